// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_TOMBuilder_h
#define timecritical_TOMBuilder_h

#include "TOMBuildOptions.h" // for TOMBuildOptions, TOMBuildResult, MaximumCoordinateMagnitude
#include "TimeCriticalMeshCoreExport.h"

#include <cstddef>
#include <cstdint>

namespace timecritical
{
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
 * (the bound that keeps the build linear). Separate parts then join parts
 * close by (pair contraction, TOMBuildOptions::PairContractionDistance).
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
   * used points that are not finite or exceed MaximumCoordinateMagnitude,
   * and on a PairContractionDistance that is negative, NaN or infinite.
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
