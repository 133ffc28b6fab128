// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkMultiresolutionHierarchyBuilder
 * @brief   gives every surface leaf the hierarchy the time-critical renderer draws, built once
 *
 * For each polydata leaf of its input (a vtkPolyData or any composite
 * dataset) the output holds that leaf as vtkTOMBuilder (Hierarchy
 * TOTALLY_ORDERED_MESH, default) or vtkMergeTreeBuilder (MERGE_TREE: a TOM
 * that also carries a merge tree for view-dependent refinement) makes it, so
 * that vtkMultiresolutionPolyDataMapper can draw it at any resolution. The
 * composite structure is kept.
 *
 * Builds are the expensive part (build times in docs/paraview.md), so this
 * filter never builds a leaf twice for the same content:
 * - a leaf that already carries the requested hierarchy (the output of one of
 *   those builders, read from a file) passes unchanged;
 * - across executions, a leaf whose points, cells and point and cell data
 *   have the content of the leaf it built last time at the same composite
 *   index (compared by a 64-bit hash of every array's values, computed at
 *   several GB/s) reuses that build, whether its arrays are the same objects
 *   or new ones (ParaView's geometry filter makes them anew at every
 *   execution).
 * So an upstream change that leaves a leaf alone (colouring, another
 * block) costs no build. The cache holds the last execution's leaves only.
 *
 * Leaves that are not polydata, are empty, or have no polygons or strips
 * pass unchanged (the mapper draws them in full). So do leaves that also
 * hold vertices or lines (a hierarchy holds triangles only: nothing is
 * dropped), with a warning, and bad leaves (out-of-range point ids,
 * non-finite coordinates, see vtkPolyDataValidator), with an error naming
 * the leaf; the other leaves are built. The builders' own messages become
 * this filter's. Progress follows the triangles built.
 *
 * @sa vtkTOMBuilder vtkMergeTreeBuilder vtkMultiresolutionPolyDataMapper
 */
#ifndef vtkMultiresolutionHierarchyBuilder_h
#define vtkMultiresolutionHierarchyBuilder_h

#include "TimeCriticalFiltersModule.h" // for export macro
#include "vtkPassInputTypeAlgorithm.h"
#include "vtkSmartPointer.h" // for vtkSmartPointer

class vtkPolyData;
namespace timecritical
{
struct LeafBuildResult;
}

#include <map>    // for std::map
#include <memory> // for std::unique_ptr

class TIMECRITICALFILTERS_EXPORT vtkMultiresolutionHierarchyBuilder
  : public vtkPassInputTypeAlgorithm
{
public:
  static vtkMultiresolutionHierarchyBuilder* New();
  vtkTypeMacro(vtkMultiresolutionHierarchyBuilder, vtkPassInputTypeAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Hierarchies
  {
    TOTALLY_ORDERED_MESH = 0, ///< uniform resolutions (vtkTOMBuilder)
    MERGE_TREE = 1            ///< also view-dependent fronts (vtkMergeTreeBuilder)
  };
  vtkSetClampMacro(Hierarchy, int, TOTALLY_ORDERED_MESH, MERGE_TREE);
  vtkGetMacro(Hierarchy, int);

  ///@{
  /// Leaves of the last execution: built, reused from the previous execution, passed as they came.
  vtkGetMacro(NumberOfBuiltLeaves, vtkIdType);
  vtkGetMacro(NumberOfReusedLeaves, vtkIdType);
  vtkGetMacro(NumberOfPassedLeaves, vtkIdType);
  ///@}

  /// Leaves built since this filter was made (all executions).
  vtkGetMacro(NumberOfBuilds, vtkIdType);

  /// Forget the cached builds (the next execution builds every leaf again).
  void ClearCache();

protected:
  vtkMultiresolutionHierarchyBuilder();
  ~vtkMultiresolutionHierarchyBuilder() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Hierarchy = TOTALLY_ORDERED_MESH;
  vtkIdType NumberOfBuiltLeaves = 0;
  vtkIdType NumberOfReusedLeaves = 0;
  vtkIdType NumberOfPassedLeaves = 0;
  vtkIdType NumberOfBuilds = 0;

private:
  vtkMultiresolutionHierarchyBuilder(const vtkMultiresolutionHierarchyBuilder&) = delete;
  void operator=(const vtkMultiresolutionHierarchyBuilder&) = delete;

  struct CacheEntry;
  /// One polydata leaf's output: passed, reused from the last execution, or built.
  vtkSmartPointer<vtkPolyData> ProcessLeaf(vtkPolyData* data, unsigned int index,
    std::map<unsigned int, CacheEntry>& cache, double totalCells, double& doneCells);

  /// Build the hierarchy of one leaf (the leaf itself when the builder rejects it).
  vtkSmartPointer<vtkPolyData> Build(
    vtkPolyData* leaf, unsigned int leafIndex, double progressBase, double progressSpan);

  /// A build's errors and warnings, as this filter's, naming the leaf.
  void ReportMessages(const timecritical::LeafBuildResult& built, unsigned int leafIndex);

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
