// SPDX-License-Identifier: BSD-3-Clause
/**
 * Builds the hierarchy of one polydata leaf (vtkTOMBuilder or
 * vtkMergeTreeBuilder with default settings, except the TOM's pair
 * contraction distance), on whatever thread calls it:
 * the leaf is only read (through VTK objects of the build's own, sharing its
 * values, so that builds may share a leaf's objects across threads), every
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

/**
 * The leaf with VTK objects of its own around the caller's values (points,
 * cell arrays, data arrays; string arrays are copied). VTK's filters keep
 * state in the objects they read (a cell array's traversal position, an
 * array's cached range, the points' bounds), and leaves often share them
 * (vtkTransformFilter's outputs share one cell array): a leaf read on another
 * thread must be read through such a copy. leaf must not be null.
 */
vtkSmartPointer<vtkPolyData> CopyForAnotherThread(vtkPolyData* leaf);

/// True when the leaf already carries the hierarchy (TOM arrays; for
/// MergeTree also merge-tree arrays), so it needs no build.
bool CarriesHierarchy(vtkPolyData* leaf, LeafHierarchy hierarchy);

/// `pairContractionDistance`: vtkTOMBuilder::SetPairContractionDistance (a
/// TotallyOrderedMesh only; vtkMergeTreeBuilder has no such setting).
LeafBuildResult BuildLeafHierarchy(vtkPolyData* leaf, LeafHierarchy hierarchy,
  const LeafBuildProgress& progress = nullptr, double pairContractionDistance = 0.0);
}

#endif
