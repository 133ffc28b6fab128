// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkHierarchyBuildCache
 * @brief   built hierarchies kept by content across executions, time steps and edits
 *
 * Holds the leaves that vtkMultiresolutionHierarchyBuilder (and the
 * background builds of the multiresolution mapper) built, keyed by the
 * content they were built from: the leaf's content hash
 * (timecritical::HashLeafContent), its cell count, the hierarchy kind, the
 * one builder setting that can differ from the default (the TOM's pair
 * contraction distance) and FORMAT_VERSION (the file format and the other
 * builder settings). A leaf whose
 * content comes back (an animation looped, a contour value set back, a block
 * unchanged by an edit) is then found instead of built.
 *
 * In memory: many entries, the least recently used evicted first so that the
 * entries' memory (their arrays' GetActualMemorySize) stays within
 * MemoryLimit (default a quarter of the machine's physical memory).
 *
 * On disk (optional, Directory empty by default): every inserted entry is
 * also written as a binary (not appended) .vtp named by its key, to a
 * temporary name first and then renamed, so that several processes or ranks
 * may share a directory; the key and a content hash of the arrays are stored
 * in the file's field data. A file that cannot be read, is truncated, belongs
 * to another key or version, fails the content check or whose TOM and
 * merge-tree arrays fail validation (vtkTOMFieldData, vtkMergeTreeFieldData)
 * is ignored with a warning naming it: the caller builds the leaf again and
 * the next Insert overwrites the file. Files are never deleted by the cache.
 *
 * Find looks in memory first, then on disk (a disk hit is kept in memory).
 * Find and Insert may be called from any thread (one mutex; files are read
 * and written outside it). Called from a worker thread, pass a message list:
 * the warnings are then returned there instead of being emitted, so that only
 * the caller's main thread reports them. The settings (SetMemoryLimit,
 * SetDirectory) are meant for the main thread.
 *
 * GetSharedInstance() is the process-wide cache that the filter uses by
 * default, so that all representations of a ParaView process and their
 * background builds share one cap. Entries are returned and stored as
 * shallow copies: callers never share a vtkPolyData object (whose lazily
 * built cell links and bounds are not thread-safe), only its arrays, which
 * nobody may modify in place.
 *
 * @sa vtkMultiresolutionHierarchyBuilder
 */
#ifndef vtkHierarchyBuildCache_h
#define vtkHierarchyBuildCache_h

#include "TimeCriticalFiltersModule.h" // for export macro
#include "vtkObject.h"

#include <cstdint> // for uint64_t
#include <memory>  // for std::unique_ptr
#include <string>  // for std::string
#include <vector>  // for std::vector

#ifndef __VTK_WRAP__
#include "vtkSmartPointer.h" // for vtkSmartPointer
#endif

class vtkPolyData;

class TIMECRITICALFILTERS_EXPORT vtkHierarchyBuildCache : public vtkObject
{
public:
  static vtkHierarchyBuildCache* New();
  vtkTypeMacro(vtkHierarchyBuildCache, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The process-wide cache (made on first use, lives until the process ends).
  static vtkHierarchyBuildCache* GetSharedInstance();

  /**
   * The version of the stored hierarchies (file layout and builder
   * settings, bumped when either changes): part of every file's key, so
   * files of another version are foreign.
   */
  enum
  {
    FORMAT_VERSION = 1
  };

  ///@{
  /**
   * The memory the entries may hold, in bytes (>= 0; 0 keeps nothing in
   * memory). Lowering it evicts at once. A negative value is an error and
   * leaves the limit unchanged.
   */
  void SetMemoryLimit(vtkTypeInt64 bytes);
  vtkTypeInt64 GetMemoryLimit();
  ///@}

  /// A quarter of this machine's physical memory (the default limit).
  static vtkTypeInt64 GetDefaultMemoryLimit();

  ///@{
  /**
   * The on-disk cache's directory; empty or null: no disk cache (default).
   * It is made when missing. A directory that cannot be made or written is
   * an error: the disk cache is then off and SetDirectory returns false.
   */
  bool SetDirectory(const char* path);
  std::string GetDirectory();
  ///@}

  /// Forget every entry held in memory (files on disk stay).
  void Clear();

  ///@{
  /// Statistics since this cache was made (or ResetStatistics).
  vtkTypeInt64 GetNumberOfMemoryHits();
  vtkTypeInt64 GetNumberOfDiskHits();
  vtkTypeInt64 GetNumberOfMisses();        ///< Find found nothing usable
  vtkTypeInt64 GetNumberOfEvictions();     ///< entries dropped for the memory limit
  vtkTypeInt64 GetNumberOfRejectedFiles(); ///< unreadable, foreign or damaged files
  vtkTypeInt64 GetNumberOfFilesWritten();
  vtkTypeInt64 GetNumberOfEntries();       ///< entries held in memory now
  vtkTypeInt64 GetMemoryInUse();           ///< bytes those entries hold
  void ResetStatistics();
  ///@}

#ifndef __VTK_WRAP__
  /// What a build depends on.
  struct Key
  {
    uint64_t ContentHash = 0; ///< timecritical::HashLeafContent of the input leaf
    vtkIdType Cells = 0;      ///< the input leaf's cell count
    int Hierarchy = 0;        ///< vtkMultiresolutionHierarchyBuilder::Hierarchies
    /// vtkTOMBuilder::PairContractionDistance of the build (0 for merge
    /// trees, whose builder ignores it)
    double PairContractionDistance = 0.0;
    bool operator==(const Key& other) const
    {
      return this->ContentHash == other.ContentHash && this->Cells == other.Cells &&
        this->Hierarchy == other.Hierarchy &&
        this->PairContractionDistance == other.PairContractionDistance;
    }
    bool operator<(const Key& other) const;
  };

  /**
   * The key of an input leaf (hashes its content: not free, several GB/s)
   * built as `hierarchy` with that pair contraction distance (left out of
   * merge-tree keys).
   */
  static Key MakeKey(vtkPolyData* leaf, int hierarchy, double pairContractionDistance = 0.0);

  /// The key as text: the file name's stem, also stored in the file (a
  /// non-zero pair contraction distance adds its bits, so files of builds
  /// without pairs keep their names).
  static std::string KeyText(const Key& key);

  /**
   * The hierarchy built for `key` (a new shallow copy), from memory or else
   * from disk (then `fromDisk` is set when given); null when there is none.
   * Warnings (rejected files) go to `warnings` when given, else they are
   * emitted by this object.
   */
  vtkSmartPointer<vtkPolyData> Find(
    const Key& key, std::vector<std::string>* warnings = nullptr, bool* fromDisk = nullptr);

  /**
   * Keep `hierarchy` (the build for `key`; a shallow copy is stored) in
   * memory, evicting the least recently used entries beyond the memory
   * limit, and write it to the disk cache when there is one. Warnings (a file
   * that could not be written) go to `warnings` when given, else they are
   * emitted by this object.
   */
  void Insert(
    const Key& key, vtkPolyData* hierarchy, std::vector<std::string>* warnings = nullptr);

  /// The file that holds `key` in the disk cache (empty without one).
  std::string FilePath(const Key& key);
#endif

protected:
  vtkHierarchyBuildCache();
  ~vtkHierarchyBuildCache() override;

private:
  vtkHierarchyBuildCache(const vtkHierarchyBuildCache&) = delete;
  void operator=(const vtkHierarchyBuildCache&) = delete;

#ifndef __VTK_WRAP__
  void Report(const std::string& warning, std::vector<std::string>* warnings);
#endif

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
