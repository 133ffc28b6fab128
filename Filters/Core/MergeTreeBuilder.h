// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_MergeTreeBuilder_h
#define timecritical_MergeTreeBuilder_h

#include "MergeTree.h"
#include "TOMBuilder.h"
#include "TimeCriticalFiltersCoreExport.h"

#include <cstddef>
#include <cstdint>

namespace timecritical
{
/// Settings of MergeTreeBuilder: those of the shared collapse engine, plus the level schedule.
struct MergeTreeBuildOptions
{
  /// Quadrics, boundary and feature handling, normal-flip and sliver checks, progress.
  TOMBuildOptions Collapse;
};

/// What MergeTreeBuilder produces: a valid TOM (points and triangles ordered by
/// the collapse sequence) and the merge tree of the same vertices.
struct MergeTreeBuildResult
{
  TOMBuildResult TOM;
  MergeTree Tree;
};

/**
 * Builds a merge tree (Xia, El-Sana & Varshney, section 4): half-edge collapses
 * grouped into levels of independent sets (regions of influence disjoint),
 * least error first within a level, so that the tree is balanced. The collapse
 * sequence, level after level, is also a TOM.
 */
class TIMECRITICALFILTERSCORE_EXPORT MergeTreeBuilder
{
public:
  explicit MergeTreeBuilder(MergeTreeBuildOptions options = {});

  /// Same input contract and errors as TOMBuilder::Build.
  MergeTreeBuildResult Build(const double* points, size_t numberOfPoints, const uint32_t* triangles,
    size_t numberOfTriangles) const;

  const MergeTreeBuildOptions& GetOptions() const { return this->Options; }

private:
  MergeTreeBuildOptions Options;
};
}

#endif
