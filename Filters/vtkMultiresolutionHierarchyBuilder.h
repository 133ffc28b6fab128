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
 * - a leaf whose points, cells and point and cell data have the content of a
 *   leaf built before (compared by a 64-bit hash of every array's values,
 *   computed at several GB/s, and the cell count) reuses that build, whether
 *   its arrays are the same objects or new ones (ParaView's geometry filter
 *   makes them anew at every execution): first the builds of this filter's
 *   last execution (its output: kept whatever the cache's limit), then its
 *   vtkHierarchyBuildCache (by default the process-wide shared one, which
 *   holds many builds under a memory limit and optionally a directory of
 *   files), then a build. Identical leaves of one execution are built once.
 * So an upstream change that leaves a leaf alone (colouring, another block)
 * costs no build, nor does a time step or contour value seen before while
 * the cache holds it.
 *
 * The leaves to build are built at once on NumberOfThreads threads (default
 * 0: one per core), each by the same serial code as alone, so the results do
 * not depend on the thread count. Only the calling thread reports progress
 * (polled about every 50 ms), checks AbortExecute (which cancels the builds
 * in progress and those not started: their leaves pass without a
 * hierarchy) and emits the messages, in leaf order, after the builds.
 *
 * Leaves that are not polydata, are empty, or have no polygons or strips
 * pass unchanged (the mapper draws them in full). So do leaves that also
 * hold vertices or lines (a hierarchy holds triangles only: nothing is
 * dropped), with a warning, and bad leaves (out-of-range point ids,
 * non-finite coordinates, see vtkPolyDataValidator), with an error naming
 * the leaf; the other leaves are built. The builders' own messages become
 * this filter's. Progress follows the triangles built.
 *
 * @sa vtkTOMBuilder vtkMergeTreeBuilder vtkHierarchyBuildCache vtkMultiresolutionPolyDataMapper
 */
#ifndef vtkMultiresolutionHierarchyBuilder_h
#define vtkMultiresolutionHierarchyBuilder_h

#include "TimeCriticalFiltersModule.h" // for export macro
#include "vtkPassInputTypeAlgorithm.h"

#include <memory> // for std::unique_ptr
#include <string> // for std::string
#include <vector> // for std::vector

class vtkHierarchyBuildCache;

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
  /**
   * vtkTOMBuilder::SetPairContractionDistance of the TOMs this filter builds
   * (a fraction of each leaf's bounding-box diagonal in [0, 1]; 0, default,
   * off): separate parts of a leaf join at its coarsest resolutions. Part of
   * the cache key (vtkHierarchyBuildCache::Key), so a changed setting never
   * reuses a build made with another. Merge trees ignore it. NaN, infinite
   * or out-of-range values are an error and leave the setting unchanged.
   */
  void SetPairContractionDistance(double distance);
  vtkGetMacro(PairContractionDistance, double);
  ///@}

  ///@{
  /**
   * Leaves of the last execution: built, reused (from the last execution,
   * the memory cache or an identical leaf), loaded from the disk cache,
   * passed as they came.
   */
  vtkGetMacro(NumberOfBuiltLeaves, vtkIdType);
  vtkGetMacro(NumberOfReusedLeaves, vtkIdType);
  vtkGetMacro(NumberOfLoadedLeaves, vtkIdType);
  vtkGetMacro(NumberOfPassedLeaves, vtkIdType);
  ///@}

  /// Leaves built since this filter was made (all executions).
  vtkGetMacro(NumberOfBuilds, vtkIdType);

  ///@{
  /**
   * Threads that build leaves at once: 0 (default) one per core, 1 builds on
   * the calling thread. A negative count is an error (unchanged).
   */
  void SetNumberOfThreads(int threads);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /**
   * The cache of builds: by default (or set to null) the process-wide
   * vtkHierarchyBuildCache::GetSharedInstance(), shared with every other
   * filter and representation of the process.
   */
  void SetCache(vtkHierarchyBuildCache* cache);
  vtkHierarchyBuildCache* GetCache();
  ///@}

  ///@{
  /**
   * The cache's memory limit in bytes and its directory (empty: no disk
   * cache), forwarded to GetCache() (which checks them): they apply to every
   * user of that cache.
   */
  void SetCacheMemoryLimit(vtkTypeInt64 bytes);
  vtkTypeInt64 GetCacheMemoryLimit();
  void SetCacheDirectory(const char* path);
  std::string GetCacheDirectory();
  ///@}

  /**
   * Forget the cached builds: this filter's last execution and the builds
   * its cache holds in memory (all of them: the shared cache's too); files
   * on disk stay. The next execution builds every leaf again (or reads it).
   */
  void ClearCache();

protected:
  vtkMultiresolutionHierarchyBuilder();
  ~vtkMultiresolutionHierarchyBuilder() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Hierarchy = TOTALLY_ORDERED_MESH;
  int NumberOfThreads = 0;
  double PairContractionDistance = 0.0;
  vtkIdType NumberOfBuiltLeaves = 0;
  vtkIdType NumberOfReusedLeaves = 0;
  vtkIdType NumberOfLoadedLeaves = 0;
  vtkIdType NumberOfPassedLeaves = 0;
  vtkIdType NumberOfBuilds = 0;

private:
  vtkMultiresolutionHierarchyBuilder(const vtkMultiresolutionHierarchyBuilder&) = delete;
  void operator=(const vtkMultiresolutionHierarchyBuilder&) = delete;

  struct Leaf;
  struct Job;
  /// The outputs of `leaves`: passed, reused, loaded or built.
  void ProcessLeaves(std::vector<Leaf>& leaves);
  /// Run the jobs (on threads when there are several), reporting progress.
  void RunJobs(std::vector<std::unique_ptr<Job>>& jobs, double doneCells, double totalCells);
  /// A leaf's messages (its build's and its cache files'), as this filter's, naming it.
  void ReportMessages(const Job& job, unsigned int leafIndex);

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
