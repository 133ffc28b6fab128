// SPDX-License-Identifier: BSD-3-Clause
#include "vtkHierarchyBuildQueue.h"

#include "LeafHierarchyBuild.h"

#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <map>
#include <mutex>
#include <thread>
#include <unordered_set>

#ifdef __linux__
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace
{
struct Job
{
  uint64_t Key = 0;
  vtkIdType Cells = 0; // the input leaf's
  int Hierarchy = 0;
  vtkSmartPointer<vtkPolyData> Leaf;
  std::shared_ptr<std::atomic<bool>> Cancelled;
};

int DefaultThreads()
{
  const unsigned int hardware = std::thread::hardware_concurrency();
  return hardware > 0 ? static_cast<int>(hardware) : 1;
}

}

struct vtkHierarchyBuildQueue::Internals
{
  std::mutex Mutex;
  std::condition_variable WorkOrStop; // workers wait here
  std::condition_variable Changed;    // a build finished or was dropped
  std::deque<Job> Queue;
  std::map<uint64_t, std::shared_ptr<std::atomic<bool>>> Running;
  std::vector<Result> Finished;
  std::vector<std::thread> Workers;
  int Threads = DefaultThreads();
  bool Stopping = false;
  bool LowPriority = true;
  LookupFunction Lookup;
  StoreFunction Store;
  ProgressHook Hook;
  vtkIdType Builds = 0;
  vtkIdType Cancelled = 0;
  vtkIdType StoreHits = 0;

  bool Known(uint64_t key) const
  {
    if (this->Running.count(key))
    {
      return true;
    }
    auto sameKey = [key](const Job& job) { return job.Key == key; };
    auto sameResult = [key](const Result& result) { return result.Key == key; };
    return std::any_of(this->Queue.begin(), this->Queue.end(), sameKey) ||
      std::any_of(this->Finished.begin(), this->Finished.end(), sameResult);
  }

  /// Drops what `cancel` selects; the caller holds the lock.
  template <typename Predicate>
  int CancelWhere(Predicate cancel)
  {
    int count = 0;
    for (auto it = this->Queue.begin(); it != this->Queue.end();)
    {
      if (cancel(it->Key))
      {
        it = this->Queue.erase(it);
        ++count;
      }
      else
      {
        ++it;
      }
    }
    for (auto& running : this->Running)
    {
      if (cancel(running.first) && !running.second->exchange(true))
      {
        ++count;
      }
    }
    this->Finished.erase(std::remove_if(this->Finished.begin(), this->Finished.end(),
                           [&cancel](const Result& result) { return cancel(result.Key); }),
      this->Finished.end());
    this->Cancelled += count;
    this->Changed.notify_all();
    return count;
  }
};

vtkStandardNewMacro(vtkHierarchyBuildQueue);

vtkHierarchyBuildQueue::vtkHierarchyBuildQueue()
  : Internal(new Internals)
{
}

vtkHierarchyBuildQueue::~vtkHierarchyBuildQueue()
{
  this->CancelAll();
  this->StopWorkers();
}

//------------------------------------------------------------------------------
void vtkHierarchyBuildQueue::SetNumberOfThreads(int threads)
{
  threads = std::max(1, threads);
  Internals& in = *this->Internal;
  {
    std::lock_guard<std::mutex> lock(in.Mutex);
    if (threads == in.Threads)
    {
      return;
    }
  }
  this->StopWorkers();
  std::lock_guard<std::mutex> lock(in.Mutex);
  in.Threads = threads;
  if (!in.Queue.empty())
  {
    this->StartWorkers();
  }
}

void vtkHierarchyBuildQueue::StopWorkers()
{
  // Running builds finish first; queued ones wait for the next workers.
  Internals& in = *this->Internal;
  std::vector<std::thread> workers;
  {
    std::lock_guard<std::mutex> lock(in.Mutex);
    in.Stopping = true;
    workers.swap(in.Workers);
  }
  in.WorkOrStop.notify_all();
  for (auto& worker : workers)
  {
    worker.join();
  }
  std::lock_guard<std::mutex> lock(in.Mutex);
  in.Stopping = false;
}

int vtkHierarchyBuildQueue::GetNumberOfThreads()
{
  std::lock_guard<std::mutex> lock(this->Internal->Mutex);
  return this->Internal->Threads;
}

void vtkHierarchyBuildQueue::StartWorkers()
{
  // The caller holds the lock.
  Internals& in = *this->Internal;
  const size_t wanted = std::min(static_cast<size_t>(std::max(1, in.Threads)),
    in.Queue.size() + in.Running.size());
  while (in.Workers.size() < wanted)
  {
    in.Workers.emplace_back(&vtkHierarchyBuildQueue::WorkerLoop, this);
  }
}

//------------------------------------------------------------------------------
bool vtkHierarchyBuildQueue::Submit(uint64_t key, vtkPolyData* leaf, int hierarchy)
{
  if (!leaf)
  {
    vtkErrorMacro("Submit: no leaf.");
    return false;
  }
  if (hierarchy != TOTALLY_ORDERED_MESH && hierarchy != MERGE_TREE)
  {
    vtkErrorMacro("Submit: hierarchy " << hierarchy << " is not TOTALLY_ORDERED_MESH (0) or "
                                       << "MERGE_TREE (1).");
    return false;
  }
  Internals& in = *this->Internal;
  LookupFunction lookup;
  {
    std::lock_guard<std::mutex> lock(in.Mutex);
    if (in.Known(key))
    {
      return false;
    }
    lookup = in.Lookup;
  }
  const vtkIdType cells = leaf->GetNumberOfCells();
  vtkSmartPointer<vtkPolyData> stored = lookup ? lookup(key, cells, hierarchy) : nullptr;
  vtkSmartPointer<vtkPolyData> copy = stored ? nullptr : timecritical::CopyForAnotherThread(leaf);
  std::lock_guard<std::mutex> lock(in.Mutex);
  if (in.Known(key))
  {
    return false; // submitted meanwhile from another thread
  }
  if (stored)
  {
    Result result;
    result.Key = key;
    result.Hierarchy = hierarchy;
    result.Output = stored;
    result.FromStore = true;
    in.Finished.push_back(std::move(result));
    ++in.StoreHits;
    in.Changed.notify_all();
    return true;
  }
  Job job;
  job.Key = key;
  job.Cells = cells;
  job.Hierarchy = hierarchy;
  // The job holds the only reference, so the copy is freed on the worker that
  // read it (VTK's reference count is invisible to ThreadSanitizer; and
  // vtkSmartPointer's assignment from an rvalue copies).
  job.Leaf = copy;
  copy = nullptr;
  job.Cancelled = std::make_shared<std::atomic<bool>>(false);
  in.Queue.push_back(std::move(job));
  this->StartWorkers();
  in.WorkOrStop.notify_one();
  return true;
}

//------------------------------------------------------------------------------
namespace
{
// Linux gives each thread its own nice value: a worker at 10 gets about a
// tenth of a core's share against the drawing thread at 0 when both run.
void LowerThisThreadsPriority()
{
#ifdef __linux__
  const auto thread = static_cast<id_t>(syscall(SYS_gettid));
  setpriority(PRIO_PROCESS, thread, std::max(getpriority(PRIO_PROCESS, thread), 10));
#endif
}
}

void vtkHierarchyBuildQueue::WorkerLoop()
{
  Internals& in = *this->Internal;
  std::unique_lock<std::mutex> lock(in.Mutex);
  if (in.LowPriority)
  {
    LowerThisThreadsPriority();
  }
  for (;;)
  {
    in.WorkOrStop.wait(lock, [&in] { return in.Stopping || !in.Queue.empty(); });
    if (in.Stopping)
    {
      return;
    }
    Job job = std::move(in.Queue.front());
    in.Queue.pop_front();
    in.Running[job.Key] = job.Cancelled;
    const ProgressHook hook = in.Hook;
    lock.unlock();

    const auto start = std::chrono::steady_clock::now();
    const uint64_t key = job.Key;
    const vtkIdType cells = job.Cells;
    std::atomic<bool>& cancelled = *job.Cancelled;
    auto progress = [&hook, &cancelled, key](double value)
    {
      if (hook)
      {
        hook(key, value);
      }
      return !cancelled.load();
    };
    timecritical::LeafBuildResult built;
    if (progress(0.0))
    {
      built = timecritical::BuildLeafHierarchy(
        job.Leaf, static_cast<timecritical::LeafHierarchy>(job.Hierarchy), progress);
    }
    job.Leaf = nullptr;
    const bool stopped = cancelled.load() || built.Cancelled;
    Result result;
    result.Key = key;
    result.Hierarchy = job.Hierarchy;
    result.BuildSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!stopped)
    {
      result.Output = built.Hierarchy;
      for (auto& message : built.Messages)
      {
        result.Messages.push_back({ message.IsError, std::move(message.Text) });
      }
    }

    lock.lock();
    const StoreFunction store = in.Store;
    lock.unlock();
    if (!stopped && store && result.Output)
    {
      std::vector<std::string> warnings;
      store(key, cells, result.Hierarchy, result.Output, warnings);
      for (auto& warning : warnings)
      {
        result.Messages.push_back({ false, std::move(warning) });
      }
    }
    lock.lock();
    in.Running.erase(key);
    // A build cancelled meanwhile was counted by the cancellation.
    if (!stopped && !cancelled.load())
    {
      ++in.Builds;
      in.Finished.push_back(std::move(result));
    }
    in.Changed.notify_all();
  }
}

//------------------------------------------------------------------------------
bool vtkHierarchyBuildQueue::IsPending(uint64_t key)
{
  Internals& in = *this->Internal;
  std::lock_guard<std::mutex> lock(in.Mutex);
  return in.Running.count(key) > 0 ||
    std::any_of(in.Queue.begin(), in.Queue.end(), [key](const Job& job) { return job.Key == key; });
}

int vtkHierarchyBuildQueue::GetNumberOfPending()
{
  std::lock_guard<std::mutex> lock(this->Internal->Mutex);
  return static_cast<int>(this->Internal->Queue.size() + this->Internal->Running.size());
}

int vtkHierarchyBuildQueue::GetNumberOfFinished()
{
  std::lock_guard<std::mutex> lock(this->Internal->Mutex);
  return static_cast<int>(this->Internal->Finished.size());
}

int vtkHierarchyBuildQueue::Cancel(uint64_t key)
{
  std::lock_guard<std::mutex> lock(this->Internal->Mutex);
  return this->Internal->CancelWhere([key](uint64_t other) { return other == key; });
}

int vtkHierarchyBuildQueue::CancelAllExcept(const std::vector<uint64_t>& keep)
{
  const std::unordered_set<uint64_t> kept(keep.begin(), keep.end());
  std::lock_guard<std::mutex> lock(this->Internal->Mutex);
  return this->Internal->CancelWhere([&kept](uint64_t key) { return kept.count(key) == 0; });
}

int vtkHierarchyBuildQueue::CancelAll()
{
  std::lock_guard<std::mutex> lock(this->Internal->Mutex);
  return this->Internal->CancelWhere([](uint64_t) { return true; });
}

void vtkHierarchyBuildQueue::WaitAll()
{
  Internals& in = *this->Internal;
  std::unique_lock<std::mutex> lock(in.Mutex);
  in.Changed.wait(lock, [&in] { return in.Queue.empty() && in.Running.empty(); });
}

bool vtkHierarchyBuildQueue::WaitFor(uint64_t key, double seconds)
{
  Internals& in = *this->Internal;
  std::unique_lock<std::mutex> lock(in.Mutex);
  auto done = [&in, key]
  {
    return in.Running.count(key) == 0 &&
      std::none_of(in.Queue.begin(), in.Queue.end(), [key](const Job& job) { return job.Key == key; });
  };
  return in.Changed.wait_for(lock, std::chrono::duration<double>(std::max(0.0, seconds)), done);
}

size_t vtkHierarchyBuildQueue::Take(std::vector<Result>& results)
{
  Internals& in = *this->Internal;
  std::lock_guard<std::mutex> lock(in.Mutex);
  const size_t count = in.Finished.size();
  for (auto& result : in.Finished)
  {
    results.push_back(std::move(result));
  }
  in.Finished.clear();
  return count;
}

void vtkHierarchyBuildQueue::SetResultStore(LookupFunction lookup, StoreFunction store)
{
  std::lock_guard<std::mutex> lock(this->Internal->Mutex);
  this->Internal->Lookup = std::move(lookup);
  this->Internal->Store = std::move(store);
}

void vtkHierarchyBuildQueue::SetProgressHook(ProgressHook hook)
{
  std::lock_guard<std::mutex> lock(this->Internal->Mutex);
  this->Internal->Hook = std::move(hook);
}

vtkIdType vtkHierarchyBuildQueue::GetNumberOfBuilds()
{
  std::lock_guard<std::mutex> lock(this->Internal->Mutex);
  return this->Internal->Builds;
}

vtkIdType vtkHierarchyBuildQueue::GetNumberOfCancelledBuilds()
{
  std::lock_guard<std::mutex> lock(this->Internal->Mutex);
  return this->Internal->Cancelled;
}

vtkSmartPointer<vtkPolyData> vtkHierarchyBuildQueue::FindStored(
  uint64_t key, vtkIdType cells, int hierarchy)
{
  Internals& in = *this->Internal;
  LookupFunction lookup;
  {
    std::lock_guard<std::mutex> lock(in.Mutex);
    lookup = in.Lookup;
  }
  vtkSmartPointer<vtkPolyData> stored = lookup ? lookup(key, cells, hierarchy) : nullptr;
  if (stored)
  {
    std::lock_guard<std::mutex> lock(in.Mutex);
    ++in.StoreHits;
  }
  return stored;
}

void vtkHierarchyBuildQueue::SetLowPriorityWorkers(bool low)
{
  std::lock_guard<std::mutex> lock(this->Internal->Mutex);
  this->Internal->LowPriority = low;
}

bool vtkHierarchyBuildQueue::GetLowPriorityWorkers()
{
  std::lock_guard<std::mutex> lock(this->Internal->Mutex);
  return this->Internal->LowPriority;
}

vtkIdType vtkHierarchyBuildQueue::GetNumberOfStoreHits()
{
  std::lock_guard<std::mutex> lock(this->Internal->Mutex);
  return this->Internal->StoreHits;
}

//------------------------------------------------------------------------------
void vtkHierarchyBuildQueue::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  std::lock_guard<std::mutex> lock(this->Internal->Mutex);
  const Internals& in = *this->Internal;
  os << indent << "NumberOfThreads: " << in.Threads << "\n";
  os << indent << "LowPriorityWorkers: " << (in.LowPriority ? "On" : "Off") << "\n";
  os << indent << "Queued: " << in.Queue.size() << ", running: " << in.Running.size()
     << ", finished: " << in.Finished.size() << "\n";
  os << indent << "Builds: " << in.Builds << ", cancelled: " << in.Cancelled
     << ", store hits: " << in.StoreHits << "\n";
}
