// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_MergeTreeAttributes_h
#define timecritical_MergeTreeAttributes_h

#include "MergeTree.h"
#include "TimeCriticalMeshCoreExport.h"

#include <cstdint>

namespace timecritical
{
struct TOMMesh;

/// What the merge tree's Error counts (see ComputeMergeTree).
struct MergeTreeErrorOptions
{
  /**
   * Weight of the shading error: the node's error (before the monotone pass)
   * is the larger of its geometric error and ShadingWeight * radius * normal
   * error. The normal error is estimated like the geometric one: per
   * collapse, the angle between the removed vertex's normal and the normal
   * the renderer shows at its nearest point of the new fan (the display
   * vertices' full-resolution normals, interpolated), summed over the
   * children: smooth curvature costs nearly nothing, lost bumps do, and so
   * does a crease vertex's averaged normal spread by coarse triangles over
   * flat faces (fandisk). An estimate, not a bound, like the geometric error (sampled on igea
   * prefixes, the true distance exceeds the latter at 0.3-6% of the points).
   * Weight 1: the rim of a tangent plane of the node's
   * radius tilted by that angle moves by about radius * angle, so the
   * projected error counts a lost normal variation like a geometric
   * displacement of that size; the node's share of the image's squared
   * error grows as (projected radius * angle)^2, so refining the largest
   * such term first spends triangles where they buy the most PSNR.
   * On scanned meshes the geometric error misses fine normal variation (W2,
   * igea, tau = 1 px: 36.4 dB at 2.3% of the triangles with the geometric
   * error alone, 45.0 dB at 7.6% with weight 1, +4.2 dB over the uniform TOM
   * at equal triangles). Default 1; 0: geometric error only (sharp-crease CAD
   * parts whose creases are already kept get far fewer triangles with 0).
   */
  double ShadingWeight = 1.0;
};

/**
 * Computes the merge tree of a TOM by replaying its collapse sequence on the
 * full-resolution mesh: dependencies, errors (geometric and shading, see
 * MergeTreeErrorOptions; monotone), radii and normal cones.
 * points: 3 coordinates per TOM vertex, in TOM order. levels: one per TOM
 * vertex (level of the collapse that removed it), or null to derive levels
 * from the dependency depth. Throws std::invalid_argument on an invalid TOM,
 * or on coordinates that are not finite or exceed MaximumCoordinateMagnitude
 * (TOMBuilder.h).
 * Linear time, one pass over the collapses; bound by cache misses on the
 * scattered TOM order, hidden by prefetching the next events' data (igea
 * after one Loop subdivision, one core, validation included: ~0.38 s per
 * million triangles with the default shading weight; MergeTreeBuilder's own
 * path, detail::ComputeBuiltMergeTree, ~0.30); work memory about 148 bytes
 * per vertex and 28 per triangle (MergeTreeBuilder: mostly its engine's
 * finished arrays). At most 2^30 triangles.
 */
TIMECRITICALMESHCORE_EXPORT MergeTree ComputeMergeTree(const TOMMesh& tom,
  const double* points, const uint16_t* levels, const MergeTreeErrorOptions& options = {});

namespace collapse
{
class ScratchBlocks;
}
namespace detail
{
/**
 * Internal to MeshCore: ComputeMergeTree for the TOM that MergeTreeBuilder
 * has just built (valid by construction, finite points), without validating
 * it again, its working arrays taken from scratch (the builder's finished
 * ones) where they fit. Point v of the TOM is points[3 * pointIds[v]] (the
 * builder's input and VertexOrder). Throws std::invalid_argument on an
 * invalid ShadingWeight.
 */
MergeTree ComputeBuiltMergeTree(const TOMMesh& tom, const double* points,
  const uint32_t* pointIds, const uint16_t* levels, const MergeTreeErrorOptions& options,
  collapse::ScratchBlocks* scratch);
}
}

#endif
