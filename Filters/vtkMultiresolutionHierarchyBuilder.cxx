// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMultiresolutionHierarchyBuilder.h"

#include "LeafHierarchyBuild.h"
#include "RefinementSettingChecks.h"
#include "vtkHierarchyBuildCache.h"

#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <functional>
#include <map>
#include <mutex>
#include <set>
#include <thread>

vtkStandardNewMacro(vtkMultiresolutionHierarchyBuilder);

namespace
{
using Key = vtkHierarchyBuildCache::Key;

/// The cells a build simplifies (0 for a leaf that is not polydata).
double SurfaceCells(vtkPolyData* leaf)
{
  return leaf ? static_cast<double>(leaf->GetNumberOfPolys() + leaf->GetNumberOfStrips()) : 0.0;
}

/**
 * Runs work(i) for every i < count on up to `threads` new threads, the next
 * index to whichever thread is free; the calling thread only waits, calling
 * poll() at least every 50 ms and whenever an item is done. With one thread
 * or one item, or when no thread can be started, the calling thread does the
 * work itself.
 */
void RunOnThreads(size_t count, unsigned int threads, const std::function<void(size_t)>& work,
  const std::function<void()>& poll)
{
  if (threads <= 1 || count <= 1)
  {
    for (size_t i = 0; i < count; ++i)
    {
      work(i);
    }
    return;
  }
  std::atomic<size_t> next{ 0 };
  std::mutex mutex;
  std::condition_variable doneChanged;
  size_t done = 0;
  auto worker = [&]() {
    for (size_t i = next++; i < count; i = next++)
    {
      work(i);
      {
        std::lock_guard<std::mutex> lock(mutex);
        ++done;
      }
      doneChanged.notify_one();
    }
  };
  std::vector<std::thread> pool;
  for (unsigned int t = 0; t < std::min<size_t>(threads, count); ++t)
  {
    try
    {
      pool.emplace_back(worker);
    }
    catch (const std::exception&) // out of threads: fewer workers
    {
      break;
    }
  }
  if (pool.empty())
  {
    worker();
  }
  std::unique_lock<std::mutex> lock(mutex);
  while (done < count)
  {
    doneChanged.wait_for(lock, std::chrono::milliseconds(50));
    lock.unlock();
    poll();
    lock.lock();
  }
  lock.unlock();
  for (std::thread& thread : pool)
  {
    thread.join();
  }
}
} // namespace

/// One polydata leaf of the input and what became of it.
struct vtkMultiresolutionHierarchyBuilder::Leaf
{
  vtkPolyData* Input = nullptr;
  unsigned int Index = 0; // composite flat index (0 for polydata)
  double Cells = 0.0;
  bool NeedsHierarchy = false;
  Key CacheKey;
  int JobIndex = -1;        // the job that gives it its hierarchy
  bool FirstOfJob = false;  // the leaf the job counts as built or loaded
  vtkSmartPointer<vtkPolyData> Output;
};

/// One content to find in the cache or build (identical leaves share one).
struct vtkMultiresolutionHierarchyBuilder::Job
{
  Key CacheKey;
  vtkPolyData* Input = nullptr;
  double Cells = 0.0;
  enum Outcomes
  {
    NONE,   // rejected by the builder or cancelled: the leaf passes
    MEMORY, // found in the cache's memory
    DISK,   // read from the cache's directory
    BUILT
  } Outcome = NONE;
  vtkSmartPointer<vtkPolyData> Output;
  std::vector<timecritical::LeafBuildMessage> Messages; // the build's
  std::vector<std::string> CacheWarnings;               // rejected or unwritable files
  std::atomic<double> Fraction{ 0.0 };                  // written by the job's thread
};

struct vtkMultiresolutionHierarchyBuilder::Internals
{
  vtkSmartPointer<vtkHierarchyBuildCache> Cache; // null: the shared one
  std::map<Key, vtkSmartPointer<vtkPolyData>> LastBuilds; // the last execution's
};

//------------------------------------------------------------------------------
vtkMultiresolutionHierarchyBuilder::vtkMultiresolutionHierarchyBuilder()
  : Internal(new Internals)
{
}

vtkMultiresolutionHierarchyBuilder::~vtkMultiresolutionHierarchyBuilder() = default;

void vtkMultiresolutionHierarchyBuilder::SetPairContractionDistance(double distance)
{
  if (timecritical::SetCheckedSetting(this,
        timecritical::CheckRange("PairContractionDistance", distance, 0.0, 1.0), distance,
        this->PairContractionDistance))
  {
    this->Modified();
  }
}

void vtkMultiresolutionHierarchyBuilder::SetNumberOfThreads(int threads)
{
  if (threads < 0)
  {
    vtkErrorMacro("NumberOfThreads must be >= 0 (0: one per core), not "
      << threads << "; it stays " << this->NumberOfThreads << ".");
    return;
  }
  if (threads != this->NumberOfThreads)
  {
    this->NumberOfThreads = threads; // no Modified(): the output does not depend on it
  }
}

void vtkMultiresolutionHierarchyBuilder::SetCache(vtkHierarchyBuildCache* cache)
{
  // No Modified(): the output does not depend on where builds are kept.
  this->Internal->Cache = cache;
}

vtkHierarchyBuildCache* vtkMultiresolutionHierarchyBuilder::GetCache()
{
  return this->Internal->Cache ? this->Internal->Cache.GetPointer()
                               : vtkHierarchyBuildCache::GetSharedInstance();
}

void vtkMultiresolutionHierarchyBuilder::SetCacheMemoryLimit(vtkTypeInt64 bytes)
{
  this->GetCache()->SetMemoryLimit(bytes);
}

vtkTypeInt64 vtkMultiresolutionHierarchyBuilder::GetCacheMemoryLimit()
{
  return this->GetCache()->GetMemoryLimit();
}

void vtkMultiresolutionHierarchyBuilder::SetCacheDirectory(const char* path)
{
  this->GetCache()->SetDirectory(path);
}

std::string vtkMultiresolutionHierarchyBuilder::GetCacheDirectory()
{
  return this->GetCache()->GetDirectory();
}

void vtkMultiresolutionHierarchyBuilder::ClearCache()
{
  this->Internal->LastBuilds.clear();
  this->GetCache()->Clear();
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkMultiresolutionHierarchyBuilder::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  vtkDataObject* output = vtkDataObject::GetData(outputVector, 0);
  this->NumberOfBuiltLeaves = this->NumberOfReusedLeaves = this->NumberOfPassedLeaves = 0;
  this->NumberOfLoadedLeaves = 0;
  if (!input || !output)
  {
    return 1;
  }
  std::vector<Leaf> leaves;
  auto* compositeInput = vtkCompositeDataSet::SafeDownCast(input);
  auto* compositeOutput = vtkCompositeDataSet::SafeDownCast(output);
  if (compositeInput && compositeOutput)
  {
    compositeOutput->CopyStructure(compositeInput);
    vtkSmartPointer<vtkCompositeDataIterator> iterator;
    iterator.TakeReference(compositeInput->NewIterator());
    iterator->SkipEmptyNodesOn();
    for (iterator->InitTraversal(); !iterator->IsDoneWithTraversal(); iterator->GoToNextItem())
    {
      if (auto* poly = vtkPolyData::SafeDownCast(iterator->GetCurrentDataObject()))
      {
        leaves.emplace_back();
        leaves.back().Input = poly;
        leaves.back().Index = iterator->GetCurrentFlatIndex();
      }
    }
    this->ProcessLeaves(leaves);
    size_t next = 0; // the leaves in the same traversal order
    for (iterator->InitTraversal(); !iterator->IsDoneWithTraversal(); iterator->GoToNextItem())
    {
      vtkDataObject* leaf = iterator->GetCurrentDataObject();
      if (vtkPolyData::SafeDownCast(leaf))
      {
        compositeOutput->SetDataSet(iterator, leaves[next++].Output);
      }
      else
      {
        compositeOutput->SetDataSet(iterator, leaf);
        ++this->NumberOfPassedLeaves;
      }
    }
  }
  else if (auto* poly = vtkPolyData::SafeDownCast(input))
  {
    leaves.emplace_back();
    leaves.back().Input = poly;
    this->ProcessLeaves(leaves);
    output->ShallowCopy(leaves.back().Output);
  }
  else
  {
    output->ShallowCopy(input);
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkMultiresolutionHierarchyBuilder::ProcessLeaves(std::vector<Leaf>& leaves)
{
  const auto hierarchy = this->Hierarchy == MERGE_TREE
    ? timecritical::LeafHierarchy::MergeTree
    : timecritical::LeafHierarchy::TotallyOrderedMesh;
  std::vector<size_t> toHash;
  double totalCells = 0.0;
  for (size_t i = 0; i < leaves.size(); ++i)
  {
    Leaf& leaf = leaves[i];
    leaf.Cells = SurfaceCells(leaf.Input);
    totalCells += leaf.Cells;
    leaf.Output = leaf.Input;
    leaf.NeedsHierarchy =
      leaf.Cells > 0.0 && !timecritical::CarriesHierarchy(leaf.Input, hierarchy);
    if (leaf.NeedsHierarchy)
    {
      toHash.push_back(i);
    }
  }
  // Hashing reads every array once: on all threads too.
  const unsigned int cores = std::max(1u, std::thread::hardware_concurrency());
  const unsigned int threads =
    this->NumberOfThreads > 0 ? static_cast<unsigned int>(this->NumberOfThreads) : cores;
  RunOnThreads(
    toHash.size(), threads,
    [&](size_t i) {
      Leaf& leaf = leaves[toHash[i]];
      leaf.CacheKey = vtkHierarchyBuildCache::MakeKey(
        leaf.Input, this->Hierarchy, this->PairContractionDistance);
    },
    [] {});

  // The last execution's builds, then one job per content.
  std::vector<std::unique_ptr<Job>> jobs;
  std::map<Key, int> jobOfKey;
  std::map<Key, vtkSmartPointer<vtkPolyData>> builds;
  double doneCells = 0.0;
  for (Leaf& leaf : leaves)
  {
    if (!leaf.NeedsHierarchy)
    {
      doneCells += leaf.Cells;
      continue;
    }
    auto last = this->Internal->LastBuilds.find(leaf.CacheKey);
    if (last != this->Internal->LastBuilds.end())
    {
      leaf.Output = last->second;
      builds[leaf.CacheKey] = last->second;
      doneCells += leaf.Cells;
      continue;
    }
    auto known = jobOfKey.emplace(leaf.CacheKey, static_cast<int>(jobs.size()));
    leaf.JobIndex = known.first->second;
    leaf.FirstOfJob = known.second;
    if (known.second)
    {
      jobs.emplace_back(new Job);
      jobs.back()->CacheKey = leaf.CacheKey;
      jobs.back()->Input = leaf.Input;
      jobs.back()->Cells = leaf.Cells;
    }
    else
    {
      doneCells += leaf.Cells;
    }
  }
  this->RunJobs(jobs, doneCells, totalCells);

  // Outputs, counts and messages, in leaf order. Identical leaves get
  // objects of their own (sharing the arrays).
  std::set<vtkPolyData*> given;
  auto give = [&given](Leaf& leaf, vtkPolyData* output) {
    leaf.Output = output;
    if (!given.insert(output).second)
    {
      leaf.Output = vtkSmartPointer<vtkPolyData>::New();
      leaf.Output->ShallowCopy(output);
    }
  };
  for (Leaf& leaf : leaves)
  {
    if (!leaf.NeedsHierarchy)
    {
      ++this->NumberOfPassedLeaves;
      continue;
    }
    if (leaf.JobIndex < 0)
    {
      give(leaf, leaf.Output);
      ++this->NumberOfReusedLeaves;
      continue;
    }
    const Job& job = *jobs[static_cast<size_t>(leaf.JobIndex)];
    this->ReportMessages(job, leaf.Index);
    if (!job.Output)
    {
      ++this->NumberOfPassedLeaves; // the messages said why (or the build was cancelled)
      continue;
    }
    give(leaf, job.Output);
    builds[leaf.CacheKey] = job.Output;
    if (!leaf.FirstOfJob || job.Outcome == Job::MEMORY)
    {
      ++this->NumberOfReusedLeaves;
    }
    else if (job.Outcome == Job::DISK)
    {
      ++this->NumberOfLoadedLeaves;
    }
    else
    {
      ++this->NumberOfBuiltLeaves;
      ++this->NumberOfBuilds;
    }
  }
  this->Internal->LastBuilds.swap(builds);
  this->UpdateProgress(1.0);
}

//------------------------------------------------------------------------------
void vtkMultiresolutionHierarchyBuilder::RunJobs(
  std::vector<std::unique_ptr<Job>>& jobs, double doneCells, double totalCells)
{
  vtkHierarchyBuildCache* cache = this->GetCache();
  const auto hierarchy = this->Hierarchy == MERGE_TREE
    ? timecritical::LeafHierarchy::MergeTree
    : timecritical::LeafHierarchy::TotallyOrderedMesh;
  std::atomic<bool> cancel{ false };
  // One job: find it in the cache, else build it (the same serial code on any thread).
  auto run = [&](Job& job, const timecritical::LeafBuildProgress& progress) {
    if (cancel)
    {
      return;
    }
    try
    {
      bool fromDisk = false;
      job.Output = cache->Find(job.CacheKey, &job.CacheWarnings, &fromDisk);
      if (job.Output)
      {
        job.Outcome = fromDisk ? Job::DISK : Job::MEMORY;
        return;
      }
      timecritical::LeafBuildResult built =
        timecritical::BuildLeafHierarchy(
          job.Input, hierarchy, progress, job.CacheKey.PairContractionDistance);
      job.Messages = std::move(built.Messages);
      if (built.Hierarchy)
      {
        job.Output = built.Hierarchy;
        job.Outcome = Job::BUILT;
        cache->Insert(job.CacheKey, job.Output, &job.CacheWarnings);
      }
    }
    catch (const std::exception& error) // out of memory: the leaf passes
    {
      job.Output = nullptr;
      job.Outcome = Job::NONE;
      job.Messages.push_back({ true, std::string("its build failed: ") + error.what() });
    }
  };
  const double scale = totalCells > 0.0 ? 1.0 / totalCells : 0.0;
  const unsigned int cores = std::max(1u, std::thread::hardware_concurrency());
  const unsigned int threads =
    this->NumberOfThreads > 0 ? static_cast<unsigned int>(this->NumberOfThreads) : cores;
  if (threads <= 1 || jobs.size() <= 1)
  {
    // On this thread: progress and abort checks straight from the build.
    for (auto& job : jobs)
    {
      const double base = doneCells;
      run(*job, [this, base, &job, scale, &cancel](double fraction) {
        this->UpdateProgress((base + fraction * job->Cells) * scale);
        cancel = cancel || this->AbortExecute;
        return !cancel;
      });
      doneCells += job->Cells;
      this->UpdateProgress(doneCells * scale);
    }
    return;
  }
  // On worker threads: they write their progress, this thread reports it.
  double reported = doneCells * scale;
  RunOnThreads(
    jobs.size(), threads,
    [&](size_t i) {
      Job& job = *jobs[i];
      run(job, [&job, &cancel](double fraction) {
        job.Fraction = fraction;
        return !cancel;
      });
      job.Fraction = 1.0;
    },
    [&]() {
      double cells = doneCells;
      for (const auto& job : jobs)
      {
        cells += std::min(1.0, std::max(0.0, job->Fraction.load())) * job->Cells;
      }
      reported = std::max(reported, cells * scale);
      this->UpdateProgress(reported);
      cancel = cancel || this->AbortExecute;
    });
}

void vtkMultiresolutionHierarchyBuilder::ReportMessages(const Job& job, unsigned int leafIndex)
{
  // The builders' messages become this filter's, with the leaf they concern.
  for (const timecritical::LeafBuildMessage& message : job.Messages)
  {
    if (message.IsError)
    {
      vtkErrorMacro("Leaf " << leafIndex << " (composite flat index) passes without a "
                            << "hierarchy: " << message.Text);
    }
    else
    {
      vtkWarningMacro("Leaf " << leafIndex << " (composite flat index): " << message.Text);
    }
  }
  for (const std::string& warning : job.CacheWarnings)
  {
    vtkWarningMacro("Leaf " << leafIndex << " (composite flat index): " << warning);
  }
}

//------------------------------------------------------------------------------
void vtkMultiresolutionHierarchyBuilder::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Hierarchy: "
     << (this->Hierarchy == MERGE_TREE ? "MERGE_TREE" : "TOTALLY_ORDERED_MESH") << "\n";
  os << indent << "PairContractionDistance: " << this->PairContractionDistance << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "NumberOfBuiltLeaves: " << this->NumberOfBuiltLeaves << "\n";
  os << indent << "NumberOfReusedLeaves: " << this->NumberOfReusedLeaves << "\n";
  os << indent << "NumberOfLoadedLeaves: " << this->NumberOfLoadedLeaves << "\n";
  os << indent << "NumberOfPassedLeaves: " << this->NumberOfPassedLeaves << "\n";
  os << indent << "NumberOfBuilds: " << this->NumberOfBuilds << "\n";
  os << indent << "LastExecutionBuilds: " << this->Internal->LastBuilds.size() << "\n";
  os << indent << "Cache: " << this->GetCache() << "\n";
}
