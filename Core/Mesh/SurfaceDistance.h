// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_SurfaceDistance_h
#define timecritical_SurfaceDistance_h

#include "TimeCriticalMeshCoreExport.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace timecritical
{
/**
 * Distances between triangle surfaces, to measure the geometric error of a
 * simplification: the dense symmetric Hausdorff distance of the TOM quality
 * benchmark and of the builders' regression tests.
 *
 * A vertex-only measure (distances from each mesh's vertices to the other
 * surface) reports no error at all from the simplified side of a vertex
 * subset, whose vertices all lie on the original: only samples inside the
 * simplified triangles see how far they cut through or float above the
 * original. Hence dense sampling on both sides.
 */
class TIMECRITICALMESHCORE_EXPORT SurfaceLocator
{
public:
  /// points: 3 coordinates per point; triangles: 3 point ids each (copied).
  SurfaceLocator(const double* points, const uint32_t* triangles, size_t numberOfTriangles);

  /**
   * Squared distance from p to the nearest triangle (+inf without triangles).
   * hint: where to start (any value, e.g. 0, the first time); on return it
   * marks the nearest triangle, so that the next query of a nearby point
   * starts with a tight bound.
   */
  double SquaredDistance(const double p[3], uint32_t& hint) const;

  size_t GetNumberOfTriangles() const { return this->Corners.size() / 9; }

private:
  struct Node
  {
    double Lo[3], Hi[3];
    uint32_t First; // leaf: first triangle (tree order); inner: left child
    uint32_t Count; // leaf: triangles (> 0); inner: 0
    uint32_t Right; // inner: right child
  };
  uint32_t BuildNode(uint32_t first, uint32_t count, std::vector<double>& centroids);
  double TriangleDistance2(uint32_t t, const double p[3]) const;

  std::vector<double> Corners; // 9 coordinates per triangle, in tree order
  std::vector<uint32_t> Order; // during the build: tree order -> input triangle
  std::vector<Node> Nodes;
};

/**
 * Points on a surface: each point used by a triangle once, plus per triangle
 * the points of its barycentric grid with k divisions per edge (corners
 * excluded), k = max(minimumDivisions, ceil(longest edge / spacing)) capped at
 * 256, and its centroid when the grid has no interior point (k < 3).
 */
TIMECRITICALMESHCORE_EXPORT std::vector<double> SampleSurface(const double* points,
  size_t numberOfPoints, const uint32_t* triangles, size_t numberOfTriangles, double spacing,
  unsigned minimumDivisions);

/// Largest distance from the samples (3 coordinates each) to the surface of `to`.
TIMECRITICALMESHCORE_EXPORT double MaximumDistance(
  const std::vector<double>& samples, const SurfaceLocator& to);

/// Mean edge length of the triangles (each edge counted once per triangle).
TIMECRITICALMESHCORE_EXPORT double MeanEdgeLength(
  const double* points, const uint32_t* triangles, size_t numberOfTriangles);
}

#endif
