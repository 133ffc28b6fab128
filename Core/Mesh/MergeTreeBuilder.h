// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_MergeTreeBuilder_h
#define timecritical_MergeTreeBuilder_h

#include "MergeTree.h"
#include "MergeTreeAttributes.h"
#include "TOMBuilder.h"
#include "TimeCriticalMeshCoreExport.h"

#include <cstddef>
#include <cstdint>

namespace timecritical
{
/// Settings of MergeTreeBuilder: those of the shared collapse engine, plus the level schedule.
struct MergeTreeBuildOptions
{
  /// Quadrics, boundary and feature handling, normal-flip and sliver checks, progress.
  TOMBuildOptions Collapse;

  /// How node errors are measured (shading term).
  MergeTreeErrorOptions Errors;

  /**
   * The cost cap of a level, which makes the collapse sequence follow the
   * greedy order (TOMBuilder) so that every prefix of the merge tree's TOM is
   * nearly as accurate as the greedy TOM at the same size. A maximal level
   * (the paper's) ends with collapses far costlier than the cheap ones it
   * started with, and the error of a prefix is the largest so far: 10-30x the
   * greedy TOM's at half the triangles on smooth scanned meshes. Instead a
   * level takes its candidates least error first only while the next one
   * costs at most LevelCostRatio times the greedy frontier, the key of the
   * level's candidate at the rank of the collapses taken so far (about where
   * the greedy order would be after as many), or no more than the costliest
   * collapse taken so far (that one set the error already). The rest waits
   * for the next level. Keys are mean squared distances: a ratio of 2 allows
   * about 1.4x the distance.
   *
   * The price is depth. Measured (TOMBenchmark section 5, eight meshes of
   * 5.8K-1.07M triangles), the defaults keep the error at 50/25/10/5% of the
   * triangles within 1.31x of the greedy TOM's (uncapped: up to 32x, 658x on
   * the flat CAD-like fandisk) with 1.1-1.85x the levels of maximal levels
   * (bunny 78 against 65 in the paper's Table 1, igea 85, fandisk 98). A
   * ratio of 1.5 gives at most 1.31x the error too, with 5-19% more levels;
   * 4 up to 1.6x with 5-20% fewer. 0 turns the cap off: maximal levels.
   */
  double LevelCostRatio = 2.0;
  /// A capped level still takes at least this share of its live vertices
  /// (greedily, least error first): where keys rise steeply with rank (flat
  /// regions ordered by the tiny tie-breaking term) the cap alone would make
  /// many thin levels for no error.
  double LevelMinimumShare = 0.03;
  /// The cap is lifted once at most this share of the input vertices is left:
  /// the coarsest meshes are bound by dependencies rather than by cost, and
  /// capped levels of one or two collapses would only deepen the tree.
  double UncappedShare = 0.01;
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
 * sequence, level after level, is also a TOM; the level cost cap
 * (MergeTreeBuildOptions::LevelCostRatio) keeps it nearly as accurate as
 * TOMBuilder's greedy TOM at every size.
 */
class TIMECRITICALMESHCORE_EXPORT MergeTreeBuilder
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
