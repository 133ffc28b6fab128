// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkHierarchyBuildQueue
 * @brief   builds the hierarchies of polydata leaves on worker threads
 *
 * Submit() queues the build of one leaf's hierarchy (a TOM, or a TOM with a
 * merge tree, as vtkMultiresolutionHierarchyBuilder builds it) under a key
 * (the leaf's content hash, timecritical::HashLeafContent, is the natural
 * one); worker threads (std::thread, NumberOfThreads of them, started on
 * demand) run timecritical::BuildLeafHierarchy; the owner takes the finished
 * results with Take() on its own thread, typically once per render, and
 * reports their messages there (TakeMessages formats them): nothing is
 * printed from a worker.
 *
 * Cancel(key), CancelAllExcept(keys) and CancelAll() drop queued builds and
 * stop running ones at their next progress check (the builders check for an
 * abort several times per second); a cancelled build produces no result.
 * WaitAll() blocks until nothing is queued or running.
 *
 * Sharing: the queue keeps its own shallow copy of each submitted leaf,
 * made on the submitting thread with its own vtkPoints object (whose cached
 * bounds the owner's thread may compute); the data arrays themselves are
 * shared and only read by the worker. A pipeline must therefore not refill
 * the same arrays in place while a build of them runs (VTK's and ParaView's
 * filters make new arrays at every execution); an owner that cannot promise
 * that must submit a deep copy.
 *
 * Store and lookup: SetResultStore() installs an optional store of finished
 * hierarchies (for example a cache shared by many queues). Submit() looks the
 * key up there first and, on a hit, finishes the entry at once without a
 * build; every successful build is stored in it from the worker thread. This
 * is the one place where finished builds are stored and looked up; the store
 * must be thread-safe.
 *
 * Thread safety: every public method may be called from any thread, but
 * results are meant to be taken by one owner thread.
 *
 * @sa vtkMultiresolutionHierarchyBuilder vtkMultiresolutionPolyDataMapper
 */
#ifndef vtkHierarchyBuildQueue_h
#define vtkHierarchyBuildQueue_h

#include "TimeCriticalFiltersModule.h" // for export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // for vtkSmartPointer

#include <cstdint>    // for uint64_t
#include <functional> // for std::function
#include <memory>     // for std::unique_ptr
#include <string>     // for std::string
#include <vector>     // for std::vector

class vtkPolyData;

class TIMECRITICALFILTERS_EXPORT vtkHierarchyBuildQueue : public vtkObject
{
public:
  static vtkHierarchyBuildQueue* New();
  vtkTypeMacro(vtkHierarchyBuildQueue, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// What a leaf's hierarchy is (as vtkMultiresolutionHierarchyBuilder::Hierarchies).
  enum Hierarchies
  {
    TOTALLY_ORDERED_MESH = 0,
    MERGE_TREE = 1
  };

  ///@{
  /**
   * Worker threads, at least 1; default: the hardware threads
   * (std::thread::hardware_concurrency(), 1 when unknown). Workers start
   * when builds are queued. Changing the count waits for the running
   * builds to finish (set it before submitting).
   */
  void SetNumberOfThreads(int threads);
  int GetNumberOfThreads();
  ///@}

  /**
   * Queue the build of `leaf`'s hierarchy under `key`. Returns false (and
   * queues nothing) when that key is already queued, running or finished
   * and not yet taken, when the leaf is null, or when the hierarchy is not
   * one of Hierarchies (with an error). A leaf that needs no build (it
   * carries the hierarchy) or that the builders reject still gets an entry:
   * its result then has no hierarchy, with the builder's message.
   */
  bool Submit(uint64_t key, vtkPolyData* leaf, int hierarchy);

  /**
   * The stored result of `key` (SetResultStore()'s lookup), counted as a
   * store hit, or null without a store or a stored result. Lets a caller
   * use a stored hierarchy at once instead of drawing a stand-in until the
   * next Take().
   */
  vtkSmartPointer<vtkPolyData> FindStored(uint64_t key, vtkIdType cells, int hierarchy);

  /// Queued or running (not finished) under key.
  bool IsPending(uint64_t key);
  /// Builds queued or running.
  int GetNumberOfPending();
  /// Results finished and not yet taken.
  int GetNumberOfFinished();

  ///@{
  /**
   * Cancel the build of `key`, or of every key not in `keep`, or all:
   * queued ones are dropped, running ones stop at their next progress
   * check; neither produces a result. Finished, untaken results of those
   * keys are dropped too. Returns how many builds were cancelled.
   */
  int Cancel(uint64_t key);
  int CancelAllExcept(const std::vector<uint64_t>& keep);
  int CancelAll();
  ///@}

  ///@{
  /**
   * Lower the workers' scheduling priority (Linux: a nice value of 10 for
   * each worker thread; elsewhere ignored). On by default: a build then takes
   * only what the thread that draws leaves, so it never slows a frame.
   * Applies to workers started after the call.
   */
  void SetLowPriorityWorkers(bool low);
  bool GetLowPriorityWorkers();
  ///@}

  /// Block until no build is queued or running (results wait to be taken).
  void WaitAll();

  /**
   * Block until the build of `key` is finished or cancelled, or `seconds`
   * passed; returns whether it is no longer pending.
   */
  bool WaitFor(uint64_t key, double seconds);

  ///@{
  /// Totals since construction: builds run to their end, builds cancelled,
  /// results found in the store (no build).
  vtkIdType GetNumberOfBuilds();
  vtkIdType GetNumberOfCancelledBuilds();
  vtkIdType GetNumberOfStoreHits();
  ///@}

#ifndef __VTK_WRAP__
  /// A finished build.
  struct Result
  {
    uint64_t Key = 0;
    int Hierarchy = TOTALLY_ORDERED_MESH;
    /// The leaf with its hierarchy; null when the leaf passes without one
    /// (Messages say why).
    vtkSmartPointer<vtkPolyData> Output;
    bool FromStore = false;
    struct Message
    {
      bool IsError = false;
      std::string Text;
    };
    std::vector<Message> Messages;
    double BuildSeconds = 0.0; ///< worker time of the build (0 from the store)
  };

  /// Move every finished result into `results` (appended); returns how many.
  size_t Take(std::vector<Result>& results);

  /**
   * Optional store of finished hierarchies (see the class comment), called
   * from the submitting thread (Lookup) and the worker threads (Store).
   * Install before the first Submit(); null functions: no store.
   */
  /// `cells`: the input leaf's cell count; the store's warnings (a file that
  /// could not be written) become warnings of the build's result.
  using LookupFunction =
    std::function<vtkSmartPointer<vtkPolyData>(uint64_t key, vtkIdType cells, int hierarchy)>;
  using StoreFunction = std::function<void(uint64_t key, vtkIdType cells, int hierarchy,
    vtkPolyData* output, std::vector<std::string>& warnings)>;
  void SetResultStore(LookupFunction lookup, StoreFunction store);

  /**
   * For tests: called on the worker thread at the start of every build and
   * at each progress report, before the cancellation check (a test can
   * block here to hold a build deterministically).
   */
  using ProgressHook = std::function<void(uint64_t key, double progress)>;
  void SetProgressHook(ProgressHook hook);
#endif

protected:
  vtkHierarchyBuildQueue();
  ~vtkHierarchyBuildQueue() override;

private:
  vtkHierarchyBuildQueue(const vtkHierarchyBuildQueue&) = delete;
  void operator=(const vtkHierarchyBuildQueue&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
  void WorkerLoop();
  void StartWorkers(); ///< with the lock held
  void StopWorkers();  ///< joins them (after their current build)
};

#endif
