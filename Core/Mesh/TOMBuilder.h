// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_TOMBuilder_h
#define timecritical_TOMBuilder_h

#include "TOMMesh.h"
#include "TimeCriticalMeshCoreExport.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace timecritical
{
/**
 * Largest coordinate magnitude the builders accept (TOMBuilder,
 * MergeTreeBuilder, ComputeMergeTree, and the VTK filters through
 * vtkPolyDataValidator), so that every error and radius they store as float
 * stays finite. A merge-tree radius is at most the sum of the edge lengths
 * along one substitution chain: fewer than 2^32 edges, each at most the box
 * diagonal 2 sqrt(3) 1e28, so below 1.5e38 < FLT_MAX = 3.4e38; node errors
 * are capped by radii, and TOM errors by the diagonal.
 */
constexpr double MaximumCoordinateMagnitude = 1e28;

/// Settings of TOMBuilder.
struct TOMBuildOptions
{
  /// Keep open boundaries in place (boundary vertices slide only along the boundary).
  bool PreserveBoundaries = true;
  /// Keep sharp edges (dihedral angle above FeatureAngle) in place: by
  /// weighted constraint quadrics (FeatureWeight), or locked (LockFeatureEdges).
  bool PreserveFeatureEdges = true;
  /**
   * Lock feature edges like boundaries (their vertices slide only along them,
   * with ConstraintWeight) instead of weighting them with FeatureWeight. A
   * lock suits clean CAD parts, but on low-poly organic meshes a fixed angle
   * flags edges of smooth regions (653 of 8,700 on the cow at 45 degrees),
   * whose locked vertices stay while the rest is over-simplified: 3 times
   * the peers' Hausdorff error at 10% of the cow's triangles.
   */
  bool LockFeatureEdges = false;
  /**
   * Weight of the two constraint planes along an unlocked feature edge (per
   * squared edge length, like the face planes' area weights): moving across
   * the edge costs that many times more than off a face. Of 1, 3, 10 and 30,
   * 10 gave the lowest worst case (TOMBenchmark section 4, geometric means
   * within 2%); 100 and more act as a lock on the cow.
   */
  double FeatureWeight = 10.0;
  /// Dihedral angle in degrees above which an edge counts as a feature edge.
  double FeatureAngle = 45.0;
  /// Weight of the constraint quadrics along boundaries (and locked feature edges).
  double ConstraintWeight = 1000.0;
  /// Reject collapses that rotate any surviving triangle normal by more than this (degrees).
  double MaximumNormalDeviation = 90.0;
  /**
   * Sliver rejection (Xia, El-Sana & Varshney eq. 3): reject collapses that create
   * a triangle of quality 4*sqrt(3)*area / (l0^2 + l1^2 + l2^2) below this value
   * while better collapses remain. 0 disables it.
   */
  double MinimumTriangleQuality = 0.0;
  /// Samples kept in the error curve (at most one per 256 vertices, at least 8).
  unsigned ErrorCurveSamples = 48;
  /**
   * Called now and then with the fraction done in [0,1]; returning false aborts
   * the build (TOMBuildResult::Aborted is then set and the mesh is empty).
   */
  std::function<bool(double)> Progress;
};

/// What TOMBuilder produces.
struct TOMBuildResult
{
  TOMMesh Mesh;
  /// New vertex index -> input point id (size = vertices of the TOM).
  std::vector<uint32_t> VertexOrder;
  /// New triangle index -> input triangle index.
  std::vector<uint32_t> TriangleOrder;
  /// Geometric error (world units) of the mesh with i active vertices, i in [0, N];
  /// non-increasing in i, 0 at i = N. Entries below BaseVertexCount repeat the base error.
  std::vector<float> VertexCountError;
  /// Triangle count of the mesh with i active vertices, i in [0, N].
  std::vector<uint32_t> TrianglesAtVertexCount;
  /// Input triangles dropped because two of their corners were the same point.
  size_t DroppedDegenerateTriangles = 0;
  /// Input triangles dropped because an earlier one has the same three points
  /// (in any order): what appending coincident copies gives.
  size_t DroppedDuplicateTriangles = 0;
  /// Input points used by no triangle (left out of the TOM).
  size_t UnusedPoints = 0;
  /**
   * Work of the collapses: adjacency entries (fan triangles) walked by the
   * checks, the collapses and the re-evaluations of candidates: 28 to 48 per
   * input triangle on the shared meshes, welded (44 to 90 with the cost per
   * unit area and locked features before issue 10); the fan bound
   * (collapse::MaximumFanSize) keeps it linear on degenerate input.
   */
  uint64_t FanTrianglesVisited = 0;
  bool Aborted = false;
};

/**
 * Builds a Totally Ordered Mesh by greedy half-edge collapse (vertex
 * substitution v1 -> v2, no new vertices) ordered by Garland-Heckbert quadric
 * error (per square root of area, see CollapseEngine::Cost). Collapses must
 * keep the mesh legal: link condition (no non-manifold edges or duplicate
 * triangles), no normal flips, optional sliver rejection. Boundaries carry
 * constraint quadrics and may only slide along themselves (feature edges
 * carry weighted constraint quadrics, or are locked likewise with
 * LockFeatureEdges); once no constrained collapse is left they are released so
 * that the build always reaches the coarsest mesh reachable (a few vertices per
 * connected component), keeping the order total. Degenerate input only: a
 * vertex whose fan keeps more than collapse::MaximumFanSize triangles stays
 * (the bound that keeps the build linear).
 *
 * The hot loop is hand written over flat arrays (no half-edge library): the
 * throughput goal is over 1 M input triangles per second on one core.
 */
class TIMECRITICALMESHCORE_EXPORT TOMBuilder
{
public:
  explicit TOMBuilder(TOMBuildOptions options = {});

  /**
   * points: 3 coordinates per point; triangles: 3 point ids per triangle.
   * Throws std::invalid_argument on out-of-range ids, or on coordinates of
   * used points that are not finite or exceed MaximumCoordinateMagnitude.
   * Triangles with repeated ids, and repeats of an earlier triangle's three
   * points, are dropped and counted.
   */
  TOMBuildResult Build(const double* points, size_t numberOfPoints, const uint32_t* triangles,
    size_t numberOfTriangles) const;

  const TOMBuildOptions& GetOptions() const { return this->Options; }

private:
  TOMBuildOptions Options;
};
}

#endif
