// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkHierarchyBuildQueue: builds on workers, results taken on the
// caller's thread, cancellation (queued and running), waiting, bad input,
// the result store, thread settings.
#include "FilterTestSupport.h"
#include "vtkHierarchyBuildQueue.h"
#include "vtkMergeTreeFieldData.h"
#include "vtkTOMFieldData.h"

#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <sstream>
#include <string>
#include <condition_variable>
#include <map>
#include <mutex>
#include <thread>
#include <vector>

#ifdef __linux__
#include <dirent.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace
{
namespace tt = timecritical::testing;
using Result = vtkHierarchyBuildQueue::Result;

/// Holds builds at their start until released (a test's deterministic "slow build").
class Gate
{
public:
  void Install(vtkHierarchyBuildQueue* queue)
  {
    queue->SetProgressHook([this](uint64_t, double progress) {
      if (progress == 0.0)
      {
        std::unique_lock<std::mutex> lock(this->Mutex);
        ++this->Arrived;
        this->Changed.notify_all();
        this->Changed.wait(lock, [this] { return this->Open; });
      }
    });
  }
  void WaitForArrivals(int count)
  {
    std::unique_lock<std::mutex> lock(this->Mutex);
    this->Changed.wait(lock, [this, count] { return this->Arrived >= count; });
  }
  void Release()
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    this->Open = true;
    this->Changed.notify_all();
  }

private:
  std::mutex Mutex;
  std::condition_variable Changed;
  int Arrived = 0;
  bool Open = false;
};

std::vector<Result> TakeAll(vtkHierarchyBuildQueue* queue)
{
  std::vector<Result> results;
  queue->Take(results);
  return results;
}

TEST(HierarchyBuildQueue, BuildsTOMsAndMergeTreesOnWorkers)
{
  auto sphere = tt::MakeSphere(20);
  auto other = tt::MakeSphere(24);
  vtkNew<vtkHierarchyBuildQueue> queue;
  queue->SetNumberOfThreads(2);
  EXPECT_TRUE(queue->Submit(1, sphere, vtkHierarchyBuildQueue::TOTALLY_ORDERED_MESH));
  EXPECT_TRUE(queue->Submit(2, other, vtkHierarchyBuildQueue::MERGE_TREE));
  queue->WaitAll();
  EXPECT_EQ(queue->GetNumberOfPending(), 0);
  EXPECT_EQ(queue->GetNumberOfFinished(), 2);
  std::map<uint64_t, Result> byKey;
  for (auto& result : TakeAll(queue))
  {
    byKey[result.Key] = result;
  }
  ASSERT_EQ(byKey.size(), 2u);
  ASSERT_NE(byKey[1].Output, nullptr);
  EXPECT_TRUE(vtkTOMFieldData::HasTOMArrays(byKey[1].Output));
  EXPECT_FALSE(vtkMergeTreeFieldData::HasMergeTreeArrays(byKey[1].Output));
  EXPECT_EQ(byKey[1].Output->GetNumberOfPolys(), sphere->GetNumberOfPolys());
  ASSERT_NE(byKey[2].Output, nullptr);
  EXPECT_TRUE(vtkMergeTreeFieldData::HasMergeTreeArrays(byKey[2].Output));
  EXPECT_TRUE(byKey[1].Messages.empty());
  EXPECT_GT(byKey[1].BuildSeconds, 0.0);
  EXPECT_EQ(queue->GetNumberOfBuilds(), 2);
  EXPECT_EQ(queue->GetNumberOfFinished(), 0);
  // The caller's leaf is not touched.
  EXPECT_FALSE(vtkTOMFieldData::HasTOMArrays(sphere));
}

TEST(HierarchyBuildQueue, SameKeyIsSubmittedOnceUntilTaken)
{
  auto sphere = tt::MakeSphere(12);
  vtkNew<vtkHierarchyBuildQueue> queue;
  Gate gate;
  gate.Install(queue);
  EXPECT_TRUE(queue->Submit(7, sphere, 0));
  EXPECT_FALSE(queue->Submit(7, sphere, 0)); // queued or running
  gate.WaitForArrivals(1);
  EXPECT_TRUE(queue->IsPending(7));
  EXPECT_FALSE(queue->Submit(7, sphere, 0));
  gate.Release();
  queue->WaitAll();
  EXPECT_FALSE(queue->IsPending(7));
  EXPECT_FALSE(queue->Submit(7, sphere, 0)); // finished, not taken
  EXPECT_EQ(TakeAll(queue).size(), 1u);
  EXPECT_TRUE(queue->Submit(7, sphere, 0)); // taken: may be built again
  queue->WaitAll();
  EXPECT_EQ(queue->GetNumberOfBuilds(), 2);
}

TEST(HierarchyBuildQueue, CancelsRunningAndQueuedBuilds)
{
  auto sphere = tt::MakeSphere(16);
  vtkNew<vtkHierarchyBuildQueue> queue;
  queue->SetNumberOfThreads(1);
  Gate gate;
  gate.Install(queue);
  ASSERT_TRUE(queue->Submit(1, sphere, 0));
  ASSERT_TRUE(queue->Submit(2, sphere, 0));
  ASSERT_TRUE(queue->Submit(3, sphere, 0));
  gate.WaitForArrivals(1); // 1 runs (held), 2 and 3 wait
  EXPECT_EQ(queue->GetNumberOfPending(), 3);
  // A new input keeps only key 3: 1 (running) and 2 (queued) are cancelled.
  EXPECT_EQ(queue->CancelAllExcept({ 3 }), 2);
  EXPECT_EQ(queue->Cancel(99), 0);
  gate.Release();
  queue->WaitAll();
  const auto results = TakeAll(queue);
  ASSERT_EQ(results.size(), 1u);
  EXPECT_EQ(results[0].Key, 3u);
  EXPECT_NE(results[0].Output, nullptr);
  EXPECT_EQ(queue->GetNumberOfCancelledBuilds(), 2);
  EXPECT_EQ(queue->GetNumberOfBuilds(), 1);
}

TEST(HierarchyBuildQueue, CancelStopsARunningBuildAtItsNextProgressCheck)
{
  // A build large enough to report progress many times; the hook holds it
  // at its first report past the start until the cancellation arrived.
  auto big = tt::MakeSphere(120);
  vtkNew<vtkHierarchyBuildQueue> queue;
  std::mutex mutex;
  std::condition_variable changed;
  bool inside = false;
  bool cancelled = false;
  int reportsAfterCancel = 0;
  queue->SetProgressHook([&](uint64_t, double progress) {
    std::unique_lock<std::mutex> lock(mutex);
    if (cancelled)
    {
      ++reportsAfterCancel;
      return;
    }
    if (progress > 0.0)
    {
      inside = true;
      changed.notify_all();
      changed.wait(lock, [&] { return cancelled; });
    }
  });
  ASSERT_TRUE(queue->Submit(5, big, 0));
  {
    std::unique_lock<std::mutex> lock(mutex);
    changed.wait(lock, [&] { return inside; });
  }
  EXPECT_EQ(queue->Cancel(5), 1);
  {
    std::lock_guard<std::mutex> lock(mutex);
    cancelled = true;
    changed.notify_all();
  }
  queue->WaitAll();
  EXPECT_TRUE(TakeAll(queue).empty());
  EXPECT_EQ(queue->GetNumberOfCancelledBuilds(), 1);
  EXPECT_EQ(queue->GetNumberOfBuilds(), 0);
  // Stopped at the check right after the hook: the builder sees its abort
  // flag at its next check; the few reports left are its closing ones (a
  // whole build of this sphere reports far more).
  EXPECT_LE(reportsAfterCancel, 3);
}

TEST(HierarchyBuildQueue, BadLeafFinishesWithoutHierarchyAndAnError)
{
  vtkNew<vtkPolyData> bad;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0, 1, 0);
  bad->SetPoints(points);
  vtkNew<vtkCellArray> polys;
  const vtkIdType ids[3] = { 0, 1, 7 }; // point 7 does not exist
  polys->InsertNextCell(3, ids);
  bad->SetPolys(polys);
  vtkNew<vtkHierarchyBuildQueue> queue;
  ASSERT_TRUE(queue->Submit(9, bad, 0));
  queue->WaitAll();
  const auto results = TakeAll(queue);
  ASSERT_EQ(results.size(), 1u);
  EXPECT_EQ(results[0].Output, nullptr);
  ASSERT_EQ(results[0].Messages.size(), 1u);
  EXPECT_TRUE(results[0].Messages[0].IsError);
  EXPECT_NE(results[0].Messages[0].Text.find("refers to point"), std::string::npos)
    << results[0].Messages[0].Text;
}

TEST(HierarchyBuildQueue, RejectsBadSubmissionsWithAnError)
{
  vtkNew<vtkHierarchyBuildQueue> queue;
  tt::MessageLog log(queue);
  EXPECT_FALSE(queue->Submit(1, nullptr, 0));
  EXPECT_FALSE(queue->Submit(1, tt::MakeSphere(8), 2));
  EXPECT_EQ(log.Errors.size(), 2u);
  EXPECT_EQ(queue->GetNumberOfPending(), 0);
  queue->SetNumberOfThreads(0);
  EXPECT_EQ(queue->GetNumberOfThreads(), 1);
}

TEST(HierarchyBuildQueue, StoreIsLookedUpBeforeABuildAndFilledAfter)
{
  auto sphere = tt::MakeSphere(14);
  std::mutex mutex;
  std::map<uint64_t, vtkSmartPointer<vtkPolyData>> store;
  auto lookup = [&](uint64_t key, vtkIdType, int) -> vtkSmartPointer<vtkPolyData> {
    std::lock_guard<std::mutex> lock(mutex);
    auto found = store.find(key);
    return found == store.end() ? nullptr : found->second;
  };
  auto keep = [&](uint64_t key, vtkIdType, int, vtkPolyData* output, std::vector<std::string>&) {
    std::lock_guard<std::mutex> lock(mutex);
    store[key] = output;
  };
  vtkNew<vtkHierarchyBuildQueue> first;
  first->SetResultStore(lookup, keep);
  first->Submit(11, sphere, 0);
  first->WaitAll();
  EXPECT_EQ(first->GetNumberOfBuilds(), 1);
  ASSERT_EQ(store.size(), 1u);

  vtkNew<vtkHierarchyBuildQueue> second;
  second->SetResultStore(lookup, keep);
  EXPECT_TRUE(second->Submit(11, sphere, 0));
  EXPECT_EQ(second->GetNumberOfPending(), 0); // finished at once
  const auto results = TakeAll(second);
  ASSERT_EQ(results.size(), 1u);
  EXPECT_TRUE(results[0].FromStore);
  EXPECT_EQ(results[0].Output, store[11]);
  EXPECT_EQ(second->GetNumberOfBuilds(), 0);
  EXPECT_EQ(second->GetNumberOfStoreHits(), 1);
}

TEST(HierarchyBuildQueue, FindStoredGivesTheStoredResultAndCountsIt)
{
  auto sphere = tt::MakeSphere(10);
  vtkNew<vtkHierarchyBuildQueue> queue;
  EXPECT_EQ(queue->FindStored(5, sphere->GetNumberOfCells(), 0), nullptr); // no store
  auto stored = vtkSmartPointer<vtkPolyData>::New();
  queue->SetResultStore(
    [&stored](uint64_t key, vtkIdType, int hierarchy) -> vtkSmartPointer<vtkPolyData> {
      return key == 5 && hierarchy == 0 ? stored : nullptr;
    },
    nullptr);
  EXPECT_EQ(queue->FindStored(6, sphere->GetNumberOfCells(), 0), nullptr);
  EXPECT_EQ(queue->FindStored(5, sphere->GetNumberOfCells(), 1), nullptr);
  EXPECT_EQ(queue->GetNumberOfStoreHits(), 0);
  EXPECT_EQ(queue->FindStored(5, sphere->GetNumberOfCells(), 0), stored);
  EXPECT_EQ(queue->GetNumberOfStoreHits(), 1);
  EXPECT_EQ(queue->GetNumberOfPending(), 0); // nothing queued
}

#ifdef __linux__
/// Nice values of this process's threads other than the calling one.
std::vector<int> OtherThreadsNiceValues()
{
  std::vector<int> values;
  const std::string self = std::to_string(static_cast<long>(syscall(SYS_gettid)));
  DIR* tasks = opendir("/proc/self/task");
  for (dirent* entry = tasks ? readdir(tasks) : nullptr; entry; entry = readdir(tasks))
  {
    const std::string name = entry->d_name;
    if (name == "." || name == ".." || name == self)
    {
      continue;
    }
    std::ifstream stat("/proc/self/task/" + name + "/stat");
    std::string line;
    std::getline(stat, line);
    // Fields after the command's closing parenthesis; the nice value is field 19.
    std::istringstream fields(line.substr(line.rfind(')') + 2));
    std::string field;
    for (int i = 3; i <= 19 && fields >> field; ++i)
    {
      if (i == 19)
      {
        values.push_back(std::stoi(field));
      }
    }
  }
  if (tasks)
  {
    closedir(tasks);
  }
  return values;
}

int WorkersNiceValueWhileBuilding(bool low)
{
  vtkNew<vtkHierarchyBuildQueue> queue;
  queue->SetNumberOfThreads(1);
  queue->SetLowPriorityWorkers(low);
  EXPECT_EQ(queue->GetLowPriorityWorkers(), low);
  Gate gate;
  gate.Install(queue);
  auto sphere = tt::MakeSphere(10);
  queue->Submit(1, sphere, 0);
  gate.WaitForArrivals(1);
  int highest = -100;
  for (int value : OtherThreadsNiceValues())
  {
    highest = std::max(highest, value);
  }
  gate.Release();
  queue->WaitAll();
  return highest;
}

TEST(HierarchyBuildQueue, WorkersRunAtLowPriorityUnlessAskedNotTo)
{
  const int ours = getpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)));
  EXPECT_GE(WorkersNiceValueWhileBuilding(true), std::max(ours, 10));
  EXPECT_EQ(WorkersNiceValueWhileBuilding(false), ours);
}
#endif

TEST(HierarchyBuildQueue, ManySubmittersAndCancellersAtOnce)
{
  // For ThreadSanitizer: submissions, cancellations, polls and takes from
  // several threads while workers build.
  auto sphere = tt::MakeSphere(10);
  vtkNew<vtkHierarchyBuildQueue> queue;
  queue->SetNumberOfThreads(3);
  std::vector<std::thread> threads;
  for (int t = 0; t < 3; ++t)
  {
    threads.emplace_back([&queue, &sphere, t] {
      for (uint64_t k = 0; k < 8; ++k)
      {
        const uint64_t key = 100 * static_cast<uint64_t>(t) + k;
        queue->Submit(key, sphere, static_cast<int>(k % 2));
        if (k % 3 == 0)
        {
          queue->Cancel(key);
        }
        queue->GetNumberOfPending();
      }
    });
  }
  std::vector<Result> results;
  for (auto& thread : threads)
  {
    thread.join();
  }
  queue->WaitAll();
  queue->Take(results);
  // A result cancelled after its build finished counts as a build, not taken.
  EXPECT_LE(static_cast<vtkIdType>(results.size()), queue->GetNumberOfBuilds());
  EXPECT_EQ(queue->GetNumberOfBuilds() + queue->GetNumberOfCancelledBuilds(), 24);
  for (const auto& result : results)
  {
    EXPECT_NE(result.Output, nullptr);
  }
}

TEST(HierarchyBuildQueue, DestructionCancelsAndJoins)
{
  auto sphere = tt::MakeSphere(60);
  auto queue = vtkSmartPointer<vtkHierarchyBuildQueue>::New();
  for (uint64_t k = 0; k < 4; ++k)
  {
    queue->Submit(k, sphere, 0);
  }
  const auto start = std::chrono::steady_clock::now();
  queue = nullptr; // must not hang nor leave threads behind
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10.0);
}
}
