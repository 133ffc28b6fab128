// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_TOMBuildOptions_h
#define timecritical_TOMBuildOptions_h

/*
 * The settings and the result of a TOM build, shared by TOMBuilder,
 * MergeTreeBuilder and the collapse engine under both (CollapseEngine.h),
 * which therefore need not include each other.
 */

#include "TOMMesh.h"

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

/// The collapse schedules TOMBuilder can run (TOMBuildOptions::Engine).
enum class TOMBuildEngine
{
  /// The cheapest legal collapse of the whole mesh each time (an indexed heap
  /// whose keys are kept exact after every collapse).
  Greedy,
  /**
   * Passes (PassSchedule.h): the candidates are sorted once per pass and
   * taken cheapest first while no two collapses of the pass share a
   * triangle around them; the keys of the vertices around the collapses are
   * refreshed once, at the end of the pass. Fewer key updates and no heap.
   */
  Passes
};

/// Settings of TOMBuilder.
struct TOMBuildOptions
{
  /// The collapse schedule (same checks, constraints and output for both).
  TOMBuildEngine Engine = TOMBuildEngine::Greedy;
  /// Keep open boundaries in place (boundary vertices slide only along the boundary).
  bool PreserveBoundaries = true;
  /// Keep sharp edges (dihedral angle above FeatureAngle) in place: by
  /// weighted constraint quadrics (FeatureWeight), or locked (LockFeatureEdges).
  bool PreserveFeatureEdges = true;
  /**
   * Lock feature edges like boundaries (their vertices slide only along them,
   * with ConstraintWeight) instead of weighting them with FeatureWeight. A
   * lock suits clean CAD parts; on low-poly organic meshes a fixed angle also
   * flags edges of smooth regions, whose locked vertices stay while the rest
   * is over-simplified.
   */
  bool LockFeatureEdges = false;
  /**
   * Weight of the two constraint planes along an unlocked feature edge (per
   * squared edge length, like the face planes' area weights): moving across
   * the edge costs that many times more than off a face. Much larger weights
   * act as a lock.
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
  /**
   * Pair contraction (Garland & Heckbert's non-edge pairs; Gobbetti &
   * Bouvier's Fig. 2, right), TOMBuilder only: once no edge collapse is left,
   * a separate part whose surviving vertex lies within this distance of a
   * surviving vertex of another part is substituted into that vertex, whole
   * (all its vertices, cheapest by the same quadric costs first), so that
   * objects of many small parts do not keep a few vertices per part at their
   * coarsest. A fraction of the bounding-box diagonal; 0 turns it off. Every
   * finer resolution is unchanged (the joins come after every edge collapse).
   * Must be finite and >= 0 (else std::invalid_argument). MergeTreeBuilder
   * ignores it (its merge tree records edge collapses only).
   */
  double PairContractionDistance = 0.0; // off: the default is not measured yet
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
  /// Separate parts substituted whole into another part (PairContractionDistance).
  size_t JoinedParts = 0;
  /**
   * Work of the collapses: adjacency entries (fan triangles) walked by the
   * checks, the collapses and the re-evaluations of candidates, a few dozen
   * per input triangle on ordinary meshes; the fan bound
   * (collapse::MaximumFanSize) keeps it linear on degenerate input. Pair
   * contraction adds the grid entries it looks at (bounded too).
   */
  uint64_t FanTrianglesVisited = 0;
  bool Aborted = false;
};
}

#endif
