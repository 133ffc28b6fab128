// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_TOMValidator_h
#define timecritical_TOMValidator_h

#include "TimeCriticalMeshCoreExport.h"

#include <cstdint>
#include <string>

namespace timecritical
{
struct TOMMesh;

/**
 * Checks TOM arrays before anything reads them, so that corrupted or foreign
 * data gives a precise message instead of a crash: array sizes, id ranges,
 * substitutions pointing to lower ids (which makes every chain acyclic), base
 * vertices forming a prefix, no triangle degenerate at full resolution,
 * triangles in prefix order, base counts and error curve consistent.
 */
class TIMECRITICALMESHCORE_EXPORT TOMValidator
{
public:
  /// Empty string when valid, otherwise the first problem found, naming the offending index.
  static std::string Check(const TOMMesh& mesh);

  /// Same on raw arrays (triangles: 3 ids each).
  static std::string Check(const uint32_t* substitution, uint64_t numberOfVertices,
    const uint32_t* triangles, uint64_t numberOfTriangles, uint64_t baseVertexCount,
    uint64_t baseTriangleCount);
};
}

#endif
