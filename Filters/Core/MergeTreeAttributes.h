// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_MergeTreeAttributes_h
#define timecritical_MergeTreeAttributes_h

#include "MergeTree.h"
#include "TimeCriticalFiltersCoreExport.h"

#include <cstdint>

namespace timecritical
{
struct TOMMesh;

/**
 * Computes the merge tree of a TOM by replaying its collapse sequence on the
 * full-resolution mesh: dependencies, errors, radii and normal cones.
 * points: 3 coordinates per TOM vertex, in TOM order. levels: one per TOM
 * vertex (level of the collapse that removed it), or null to derive levels
 * from the dependency depth. Throws std::invalid_argument on an invalid TOM.
 * Linear time, one pass over the collapses; bound by cache misses on the
 * scattered TOM order (igea after one Loop subdivision: ~0.35 s per million
 * triangles on one core, validation included); work memory about 160 bytes
 * per vertex and 50 per triangle.
 */
TIMECRITICALFILTERSCORE_EXPORT MergeTree ComputeMergeTree(
  const TOMMesh& tom, const double* points, const uint16_t* levels);
}

#endif
