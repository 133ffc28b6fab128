// SPDX-License-Identifier: BSD-3-Clause
/**
 * Builds the hierarchy of one polydata leaf (vtkTOMBuilder or
 * vtkMergeTreeBuilder with default settings), on whatever thread calls it:
 * the leaf is only read (shallow copied into the builder's own input), every
 * message of the builder is collected rather than printed, and progress and
 * cancellation go through the caller's callback. The callers
 * (vtkMultiresolutionHierarchyBuilder, and builds run on worker threads)
 * report the messages on their own thread.
 *
 * A leaf the builders cannot take passes without a hierarchy, with an error
 * (bad input, see vtkPolyDataValidator) or a warning (vertex or line cells
 * besides the surface, which a hierarchy cannot hold: nothing is dropped).
 */
#ifndef LeafHierarchyBuild_h
#define LeafHierarchyBuild_h

#include "vtkSmartPointer.h" // for vtkSmartPointer

#include <functional> // for std::function
#include <string>     // for std::string
#include <vector>     // for std::vector

class vtkPolyData;

namespace timecritical
{
/// What a leaf's hierarchy is: vtkMultiresolutionHierarchyBuilder::Hierarchies.
enum class LeafHierarchy
{
  TotallyOrderedMesh = 0,
  MergeTree = 1
};

struct LeafBuildMessage
{
  bool IsError = false; // an error (the leaf passes without a hierarchy) or a warning
  std::string Text;
};

struct LeafBuildResult
{
  /// The leaf with its hierarchy; null when the leaf passes without one
  /// (the messages say why) or the build was cancelled.
  vtkSmartPointer<vtkPolyData> Hierarchy;
  bool Cancelled = false;
  std::vector<LeafBuildMessage> Messages;
};

/**
 * Progress callback: called with the build's progress in [0, 1]; returning
 * false cancels the build (Cancelled is then set and Hierarchy is null).
 */
using LeafBuildProgress = std::function<bool(double)>;

/// True when the leaf already carries the hierarchy (TOM arrays; for
/// MergeTree also merge-tree arrays), so it needs no build.
bool CarriesHierarchy(vtkPolyData* leaf, LeafHierarchy hierarchy);

LeafBuildResult BuildLeafHierarchy(
  vtkPolyData* leaf, LeafHierarchy hierarchy, const LeafBuildProgress& progress = nullptr);
}

#endif
