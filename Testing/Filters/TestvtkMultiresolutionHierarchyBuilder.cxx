// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkMultiresolutionHierarchyBuilder: builds, reuse (last execution,
// memory and disk cache), pass-through, messages, parallel builds.
#include "FilterTestSupport.h"
#include "vtkHierarchyBuildCache.h"
#include "vtkMergeTreeFieldData.h"
#include "vtkMultiresolutionHierarchyBuilder.h"
#include "vtkTOMBuilder.h"
#include "vtkTOMFieldData.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <vtksys/SystemTools.hxx>

#include <gtest/gtest.h>

#include <unistd.h> // getpid

#include <cmath>
#include <fstream>
#include <thread>
#include <string>
#include <limits>
#include <vector>

namespace
{
namespace tt = timecritical::testing;
using tt::MakeSphere;
using tt::MessageLog;

vtkPolyData* Leaf(vtkMultiBlockDataSet* data, unsigned int block)
{
  return vtkPolyData::SafeDownCast(data->GetBlock(block));
}

/// Each test starts from an empty shared cache (ctest runs each in a process
/// of its own, but the test program may run them all in one).
class MultiresolutionHierarchyBuilder : public ::testing::Test
{
protected:
  void SetUp() override { vtkHierarchyBuildCache::GetSharedInstance()->Clear(); }
};

TEST_F(MultiresolutionHierarchyBuilder, BuildsATOMForPolyData)
{
  auto sphere = MakeSphere(30);
  vtkNew<vtkMultiresolutionHierarchyBuilder> builder;
  builder->SetInputData(sphere);
  builder->Update();
  auto* out = vtkPolyData::SafeDownCast(builder->GetOutputDataObject(0));
  ASSERT_NE(out, nullptr);
  EXPECT_TRUE(vtkTOMFieldData::HasTOMArrays(out));
  EXPECT_FALSE(vtkMergeTreeFieldData::HasMergeTreeArrays(out));
  EXPECT_EQ(out->GetNumberOfPolys(), sphere->GetNumberOfPolys());
  EXPECT_EQ(builder->GetNumberOfBuiltLeaves(), 1);
  EXPECT_EQ(builder->GetNumberOfBuilds(), 1);
}

TEST_F(MultiresolutionHierarchyBuilder, ReusesBuildsOfUnchangedContent)
{
  auto sphere = MakeSphere(30);
  vtkNew<vtkMultiresolutionHierarchyBuilder> builder;
  builder->SetInputData(sphere);
  builder->Update();
  ASSERT_EQ(builder->GetNumberOfBuilds(), 1);

  // Re-executed on the same data.
  builder->Modified();
  builder->Update();
  EXPECT_EQ(builder->GetNumberOfReusedLeaves(), 1);
  EXPECT_EQ(builder->GetNumberOfBuilds(), 1);

  // New array objects of equal content (as ParaView's geometry filter makes).
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(sphere);
  builder->SetInputData(copy);
  builder->Update();
  EXPECT_EQ(builder->GetNumberOfReusedLeaves(), 1);
  EXPECT_EQ(builder->GetNumberOfBuilds(), 1);

  // A point moved in place (same array object): built again.
  double p[3];
  copy->GetPoints()->GetPoint(5, p);
  p[0] += 0.25;
  copy->GetPoints()->SetPoint(5, p);
  copy->GetPoints()->Modified();
  builder->Update();
  EXPECT_EQ(builder->GetNumberOfBuiltLeaves(), 1);
  EXPECT_EQ(builder->GetNumberOfBuilds(), 2);

  // A changed point data value is a change too (it travels with the points).
  copy->GetPointData()->GetArray(0)->SetComponent(7, 0, 0.5);
  copy->GetPointData()->GetArray(0)->Modified();
  builder->Update();
  EXPECT_EQ(builder->GetNumberOfBuilds(), 3);

  // Another hierarchy is another build.
  builder->SetHierarchy(vtkMultiresolutionHierarchyBuilder::MERGE_TREE);
  builder->Update();
  EXPECT_EQ(builder->GetNumberOfBuilds(), 4);
  EXPECT_TRUE(vtkMergeTreeFieldData::HasMergeTreeArrays(
    vtkPolyData::SafeDownCast(builder->GetOutputDataObject(0))));

  builder->ClearCache();
  builder->Update();
  EXPECT_EQ(builder->GetNumberOfBuilds(), 5);
}

TEST_F(MultiresolutionHierarchyBuilder, KeepsCompositeStructureAndPassesOtherLeaves)
{
  vtkNew<vtkMultiBlockDataSet> input;
  input->SetNumberOfBlocks(6);
  input->SetBlock(0, MakeSphere(20));
  input->SetBlock(1, MakeSphere(24));
  vtkNew<vtkUnstructuredGrid> grid;
  input->SetBlock(2, grid);
  vtkNew<vtkPolyData> empty;
  input->SetBlock(3, empty);
  // Lines only: nothing to simplify.
  vtkNew<vtkPolyData> lines;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  lines->SetPoints(points);
  vtkNew<vtkCellArray> cells;
  const vtkIdType line[2] = { 0, 1 };
  cells->InsertNextCell(2, line);
  lines->SetLines(cells);
  input->SetBlock(4, lines);
  // Already a TOM: passes as it is.
  vtkNew<vtkTOMBuilder> tom;
  tom->SetInputData(MakeSphere(16));
  tom->Update();
  input->SetBlock(5, tom->GetOutput());

  vtkNew<vtkMultiresolutionHierarchyBuilder> builder;
  builder->SetInputData(input);
  builder->Update();
  auto* out = vtkMultiBlockDataSet::SafeDownCast(builder->GetOutputDataObject(0));
  ASSERT_NE(out, nullptr);
  ASSERT_EQ(out->GetNumberOfBlocks(), 6u);
  EXPECT_TRUE(vtkTOMFieldData::HasTOMArrays(Leaf(out, 0)));
  EXPECT_TRUE(vtkTOMFieldData::HasTOMArrays(Leaf(out, 1)));
  EXPECT_EQ(out->GetBlock(2), grid.GetPointer());
  EXPECT_EQ(Leaf(out, 4), lines.GetPointer());
  EXPECT_EQ(Leaf(out, 5), tom->GetOutput());
  EXPECT_EQ(builder->GetNumberOfBuiltLeaves(), 2);
  // The grid, the empty leaf, the lines and the TOM.
  EXPECT_EQ(builder->GetNumberOfPassedLeaves(), 4);

  // A surface with lines too passes whole, with a warning.
  auto mixed = MakeSphere(14);
  mixed->SetLines(cells);
  input->SetBlock(4, mixed);
  input->Modified();
  MessageLog log(builder);
  builder->Update();
  out = vtkMultiBlockDataSet::SafeDownCast(builder->GetOutputDataObject(0));
  EXPECT_EQ(Leaf(out, 4), mixed.GetPointer());
  ASSERT_EQ(log.Warnings.size(), 1u);
  EXPECT_NE(log.Warnings[0].find("1 vertex and line cells"), std::string::npos) << log.Warnings[0];
  EXPECT_TRUE(log.Errors.empty());
  EXPECT_EQ(builder->GetNumberOfBuilds(), 2);

  // Only the changed block is built again.
  input->SetBlock(1, MakeSphere(26));
  input->Modified();
  builder->Update();
  EXPECT_EQ(builder->GetNumberOfBuiltLeaves(), 1);
  EXPECT_EQ(builder->GetNumberOfReusedLeaves(), 1);
  EXPECT_EQ(builder->GetNumberOfBuilds(), 3);
}

TEST_F(MultiresolutionHierarchyBuilder, RejectedLeafPassesWithAMessageNamingIt)
{
  vtkNew<vtkMultiBlockDataSet> input;
  input->SetNumberOfBlocks(2);
  auto bad = MakeSphere(12);
  bad->GetPoints()->SetPoint(3, std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0);
  input->SetBlock(0, bad);
  input->SetBlock(1, MakeSphere(12));

  vtkNew<vtkMultiresolutionHierarchyBuilder> builder;
  MessageLog log(builder);
  builder->SetInputData(input);
  builder->Update();
  auto* out = vtkMultiBlockDataSet::SafeDownCast(builder->GetOutputDataObject(0));
  ASSERT_NE(out, nullptr);
  EXPECT_EQ(Leaf(out, 0), bad.GetPointer());
  EXPECT_TRUE(vtkTOMFieldData::HasTOMArrays(Leaf(out, 1)));
  ASSERT_EQ(log.Errors.size(), 1u) << log.AllErrors();
  EXPECT_TRUE(log.ErrorContains("Leaf 1 (composite flat index)")) << log.AllErrors();
  EXPECT_TRUE(log.ErrorContains("finite")) << log.AllErrors();
}

TEST_F(MultiresolutionHierarchyBuilder, ProgressRisesToOne)
{
  vtkNew<vtkMultiBlockDataSet> input;
  input->SetNumberOfBlocks(3);
  for (unsigned int i = 0; i < 3; ++i)
  {
    input->SetBlock(i, MakeSphere(20 + 4 * static_cast<int>(i)));
  }
  vtkNew<vtkMultiresolutionHierarchyBuilder> builder;
  std::vector<double> progress;
  vtkNew<vtkCallbackCommand> callback;
  callback->SetClientData(&progress);
  callback->SetCallback([](vtkObject* caller, unsigned long, void* client, void*) {
    static_cast<std::vector<double>*>(client)->push_back(
      static_cast<vtkAlgorithm*>(caller)->GetProgress());
  });
  builder->AddObserver(vtkCommand::ProgressEvent, callback);
  builder->SetInputData(input);
  builder->Update();
  ASSERT_FALSE(progress.empty());
  for (size_t i = 1; i < progress.size(); ++i)
  {
    EXPECT_GE(progress[i], progress[i - 1] - 1e-12) << "at " << i;
  }
  EXPECT_DOUBLE_EQ(progress.back(), 1.0);
}

//------------------------------------------------------------------------------
// The cache across executions and the parallel builds.

/// A sphere moved by `shift` along x: the leaf of one time step.
vtkSmartPointer<vtkPolyData> Step(double shift, int resolution = 16)
{
  auto sphere = MakeSphere(resolution);
  for (vtkIdType i = 0; i < sphere->GetNumberOfPoints(); ++i)
  {
    double p[3];
    sphere->GetPoints()->GetPoint(i, p);
    p[0] += shift;
    sphere->GetPoints()->SetPoint(i, p);
  }
  return sphere;
}

vtkSmartPointer<vtkMultiBlockDataSet> Blocks(
  const std::vector<vtkSmartPointer<vtkPolyData>>& leaves)
{
  auto blocks = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  blocks->SetNumberOfBlocks(static_cast<unsigned int>(leaves.size()));
  for (size_t i = 0; i < leaves.size(); ++i)
  {
    blocks->SetBlock(static_cast<unsigned int>(i), leaves[i]);
  }
  return blocks;
}

/// Leaves of different sizes (resolutions 14 to 14 + 2 (count - 1)).
std::vector<vtkSmartPointer<vtkPolyData>> VariedLeaves(int count)
{
  std::vector<vtkSmartPointer<vtkPolyData>> leaves;
  for (int i = 0; i < count; ++i)
  {
    leaves.push_back(Step(i, 14 + 2 * i));
  }
  return leaves;
}

std::string ScratchDirectory(const std::string& name)
{
  const std::string path =
    std::string(TIMECRITICAL_TEST_OUTPUT_DIR) + "/MultiresolutionHierarchyBuilder-" + name + "-" +
    std::to_string(::getpid()); // a folder per process: ctest runs programs side by side
  vtksys::SystemTools::RemoveADirectory(path);
  return path;
}

TEST_F(MultiresolutionHierarchyBuilder, LoopingOverTimeStepsBuildsEachStepOnce)
{
  std::vector<vtkSmartPointer<vtkPolyData>> steps;
  for (int i = 0; i < 5; ++i)
  {
    steps.push_back(Step(i));
  }
  vtkHierarchyBuildCache* shared = vtkHierarchyBuildCache::GetSharedInstance();
  shared->ResetStatistics();
  vtkNew<vtkMultiresolutionHierarchyBuilder> builder;
  EXPECT_EQ(builder->GetCache(), shared);
  for (int loop = 0; loop < 2; ++loop)
  {
    for (auto& step : steps)
    {
      builder->SetInputData(step);
      builder->Update();
      EXPECT_EQ(builder->GetNumberOfBuiltLeaves() + builder->GetNumberOfReusedLeaves(), 1);
      EXPECT_EQ(builder->GetNumberOfReusedLeaves(), loop);
      EXPECT_TRUE(vtkTOMFieldData::HasTOMArrays(
        vtkPolyData::SafeDownCast(builder->GetOutputDataObject(0))));
    }
    EXPECT_EQ(builder->GetNumberOfBuilds(), 5);
  }
  EXPECT_EQ(shared->GetNumberOfMemoryHits(), 5);
  EXPECT_EQ(shared->GetNumberOfEntries(), 5);

  // Another filter (another representation) finds them too.
  vtkNew<vtkMultiresolutionHierarchyBuilder> other;
  other->SetInputData(Blocks(steps));
  other->Update();
  EXPECT_EQ(other->GetNumberOfBuilds(), 0);
  EXPECT_EQ(other->GetNumberOfReusedLeaves(), 5);
}

TEST_F(MultiresolutionHierarchyBuilder, GoingBackToAnEarlierContentBuildsNothing)
{
  vtkNew<vtkHierarchyBuildCache> cache;
  vtkNew<vtkMultiresolutionHierarchyBuilder> builder;
  builder->SetCache(cache);
  EXPECT_EQ(builder->GetCache(), cache.GetPointer());
  auto first = Step(0.0), second = Step(1.0);
  for (vtkPolyData* content : { first.GetPointer(), second.GetPointer(), first.GetPointer() })
  {
    auto copy = vtkSmartPointer<vtkPolyData>::New(); // new arrays, as ParaView makes
    copy->DeepCopy(content);
    builder->SetInputData(copy);
    builder->Update();
  }
  EXPECT_EQ(builder->GetNumberOfBuilds(), 2);
  EXPECT_EQ(builder->GetNumberOfReusedLeaves(), 1);
  EXPECT_EQ(cache->GetNumberOfMemoryHits(), 1);
  // The filter's own cache: the shared one was not used.
  EXPECT_EQ(vtkHierarchyBuildCache::GetSharedInstance()->GetNumberOfEntries(), 0);
  builder->SetCache(nullptr);
  EXPECT_EQ(builder->GetCache(), vtkHierarchyBuildCache::GetSharedInstance());
}

TEST_F(MultiresolutionHierarchyBuilder, TheMemoryLimitEvictsAndThenRebuilds)
{
  std::vector<vtkSmartPointer<vtkPolyData>> steps = { Step(0), Step(1), Step(2) };
  vtkNew<vtkHierarchyBuildCache> cache;
  vtkNew<vtkMultiresolutionHierarchyBuilder> builder;
  builder->SetCache(cache);
  builder->SetInputData(steps[0]);
  builder->Update();
  const vtkTypeInt64 size = cache->GetMemoryInUse();
  ASSERT_GT(size, 0);
  builder->SetCacheMemoryLimit(size + size / 2); // one step
  EXPECT_EQ(cache->GetMemoryLimit(), size + size / 2);
  for (int loop = 0; loop < 2; ++loop)
  {
    for (auto& step : steps)
    {
      builder->SetInputData(step);
      builder->Update();
      EXPECT_LE(cache->GetMemoryInUse(), cache->GetMemoryLimit());
    }
  }
  EXPECT_EQ(builder->GetNumberOfBuilds(), 6);
  EXPECT_GE(cache->GetNumberOfEvictions(), 4);
  builder->SetCacheMemoryLimit(100 * size);
  EXPECT_EQ(builder->GetCacheMemoryLimit(), 100 * size);
  for (int loop = 0; loop < 2; ++loop)
  {
    for (auto& step : steps)
    {
      builder->SetInputData(step);
      builder->Update();
    }
  }
  EXPECT_EQ(builder->GetNumberOfBuilds(), 8); // the two steps evicted, once
}

TEST_F(MultiresolutionHierarchyBuilder, TheDiskCacheServesANewProcess)
{
  const std::string directory = ScratchDirectory("Disk");
  auto input = Blocks(VariedLeaves(3));
  vtkNew<vtkMultiresolutionHierarchyBuilder> writer;
  vtkNew<vtkHierarchyBuildCache> writerCache;
  writer->SetCache(writerCache);
  writer->SetHierarchy(vtkMultiresolutionHierarchyBuilder::MERGE_TREE);
  writer->SetCacheDirectory(directory.c_str());
  EXPECT_EQ(writer->GetCacheDirectory(), directory);
  writer->SetInputData(input);
  writer->Update();
  EXPECT_EQ(writer->GetNumberOfBuiltLeaves(), 3);
  EXPECT_EQ(writerCache->GetNumberOfFilesWritten(), 3);

  vtkNew<vtkMultiresolutionHierarchyBuilder> reader; // as after a restart
  vtkNew<vtkHierarchyBuildCache> readerCache;
  reader->SetCache(readerCache);
  reader->SetHierarchy(vtkMultiresolutionHierarchyBuilder::MERGE_TREE);
  reader->SetCacheDirectory(directory.c_str());
  MessageLog log(reader);
  auto copy = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  copy->DeepCopy(input);
  reader->SetInputData(copy);
  reader->Update();
  EXPECT_EQ(reader->GetNumberOfBuilds(), 0);
  EXPECT_EQ(reader->GetNumberOfLoadedLeaves(), 3);
  EXPECT_TRUE(log.Warnings.empty());
  auto* built = vtkMultiBlockDataSet::SafeDownCast(writer->GetOutputDataObject(0));
  auto* loaded = vtkMultiBlockDataSet::SafeDownCast(reader->GetOutputDataObject(0));
  for (unsigned int i = 0; i < 3; ++i)
  {
    tt::ExpectSameArrays(Leaf(loaded, i), Leaf(built, i));
  }
}

TEST_F(MultiresolutionHierarchyBuilder, ACorruptedCacheFileIsRebuiltWithAWarning)
{
  const std::string directory = ScratchDirectory("Corrupted");
  auto sphere = MakeSphere(18);
  vtkNew<vtkHierarchyBuildCache> cache;
  ASSERT_TRUE(cache->SetDirectory(directory.c_str()));
  const std::string path = cache->FilePath(vtkHierarchyBuildCache::MakeKey(sphere, 0));
  {
    std::ofstream garbage(path.c_str(), std::ios::binary);
    garbage << "<?xml version=\"1.0\"?><VTKFile type=\"PolyData\"><Poly";
  }
  vtkNew<vtkMultiresolutionHierarchyBuilder> builder;
  builder->SetCache(cache);
  MessageLog log(builder);
  builder->SetInputData(sphere);
  builder->Update();
  ASSERT_EQ(log.Warnings.size(), 1u);
  EXPECT_NE(log.Warnings[0].find("Leaf 0 (composite flat index)"), std::string::npos);
  EXPECT_NE(log.Warnings[0].find(path), std::string::npos) << log.Warnings[0];
  EXPECT_TRUE(log.Errors.empty()) << log.AllErrors();
  EXPECT_EQ(builder->GetNumberOfBuiltLeaves(), 1);
  auto* out = vtkPolyData::SafeDownCast(builder->GetOutputDataObject(0));
  tt::ExpectSameArrays(out, tt::RunFilter<vtkTOMBuilder>(sphere, nullptr));

  // The file was rewritten: a new cache reads it.
  vtkNew<vtkHierarchyBuildCache> next;
  next->SetDirectory(directory.c_str());
  vtkNew<vtkMultiresolutionHierarchyBuilder> again;
  again->SetCache(next);
  again->SetInputData(sphere);
  again->Update();
  EXPECT_EQ(again->GetNumberOfLoadedLeaves(), 1);
  EXPECT_EQ(next->GetNumberOfRejectedFiles(), 0);
}

TEST_F(MultiresolutionHierarchyBuilder, ParallelBuildsEqualSerialBuildsBitForBit)
{
  auto input = Blocks(VariedLeaves(8));
  for (int hierarchy : { vtkMultiresolutionHierarchyBuilder::TOTALLY_ORDERED_MESH,
         vtkMultiresolutionHierarchyBuilder::MERGE_TREE })
  {
    vtkNew<vtkMultiresolutionHierarchyBuilder> serial, parallel;
    vtkNew<vtkHierarchyBuildCache> serialCache, parallelCache;
    serial->SetCache(serialCache);
    parallel->SetCache(parallelCache);
    serial->SetNumberOfThreads(1);
    parallel->SetNumberOfThreads(4);
    for (vtkMultiresolutionHierarchyBuilder* builder :
      { serial.GetPointer(), parallel.GetPointer() })
    {
      builder->SetHierarchy(hierarchy);
      builder->SetInputData(input);
      builder->Update();
      EXPECT_EQ(builder->GetNumberOfBuiltLeaves(), 8);
    }
    auto* a = vtkMultiBlockDataSet::SafeDownCast(serial->GetOutputDataObject(0));
    auto* b = vtkMultiBlockDataSet::SafeDownCast(parallel->GetOutputDataObject(0));
    for (unsigned int i = 0; i < 8; ++i)
    {
      SCOPED_TRACE("leaf " + std::to_string(i) + ", hierarchy " + std::to_string(hierarchy));
      tt::ExpectSameArrays(Leaf(a, i), Leaf(b, i));
    }
    // The same code as a builder of its own.
    if (hierarchy == vtkMultiresolutionHierarchyBuilder::TOTALLY_ORDERED_MESH)
    {
      tt::ExpectSameArrays(Leaf(b, 5), tt::RunFilter<vtkTOMBuilder>(Leaf(input, 5), nullptr));
    }
  }
}

TEST_F(MultiresolutionHierarchyBuilder, LeavesSharingCellArraysBuildSafelyInParallel)
{
  // As vtkTransformFilter's outputs: points of their own, one vtkCellArray
  // object for all. VTK's filters traverse a cell array through state kept in
  // the object, so each build must read it through an object of its own.
  auto base = Step(0.0, 40);
  std::vector<vtkSmartPointer<vtkPolyData>> leaves;
  for (int i = 0; i < 8; ++i)
  {
    auto leaf = Step(3.0 * i, 40);
    leaf->SetPolys(base->GetPolys());
    leaves.push_back(leaf);
  }
  auto input = Blocks(leaves);
  vtkNew<vtkMultiresolutionHierarchyBuilder> serial;
  vtkNew<vtkHierarchyBuildCache> serialCache;
  serial->SetCache(serialCache);
  serial->SetNumberOfThreads(1);
  serial->SetInputData(input);
  serial->Update();
  auto* expected = vtkMultiBlockDataSet::SafeDownCast(serial->GetOutputDataObject(0));
  for (int round = 0; round < 4; ++round)
  {
    vtkNew<vtkMultiresolutionHierarchyBuilder> parallel;
    vtkNew<vtkHierarchyBuildCache> parallelCache;
    parallel->SetCache(parallelCache);
    parallel->SetNumberOfThreads(4);
    parallel->SetInputData(input);
    parallel->Update();
    ASSERT_EQ(parallel->GetNumberOfBuiltLeaves(), 8);
    auto* built = vtkMultiBlockDataSet::SafeDownCast(parallel->GetOutputDataObject(0));
    for (unsigned int i = 0; i < 8; ++i)
    {
      SCOPED_TRACE("round " + std::to_string(round) + ", leaf " + std::to_string(i));
      tt::ExpectSameArrays(Leaf(expected, i), Leaf(built, i));
    }
  }
  // The caller's cell array is left as it was.
  EXPECT_EQ(Leaf(input, 0)->GetPolys(), base->GetPolys());
  EXPECT_EQ(base->GetPolys()->GetNumberOfCells(), Leaf(input, 7)->GetNumberOfPolys());
}

TEST_F(MultiresolutionHierarchyBuilder, IdenticalLeavesAreBuiltOnce)
{
  auto sphere = Step(0.0);
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(sphere);
  auto input = Blocks({ sphere, copy, Step(1.0) });
  vtkNew<vtkMultiresolutionHierarchyBuilder> builder;
  builder->SetNumberOfThreads(2);
  builder->SetInputData(input);
  builder->Update();
  EXPECT_EQ(builder->GetNumberOfBuiltLeaves(), 2);
  EXPECT_EQ(builder->GetNumberOfReusedLeaves(), 1);
  auto* out = vtkMultiBlockDataSet::SafeDownCast(builder->GetOutputDataObject(0));
  // Objects of their own, arrays shared.
  EXPECT_NE(Leaf(out, 0), Leaf(out, 1));
  EXPECT_EQ(Leaf(out, 0)->GetPoints()->GetData(), Leaf(out, 1)->GetPoints()->GetData());
  // Again: the last execution's builds, still one object per leaf.
  builder->Modified();
  builder->Update();
  EXPECT_EQ(builder->GetNumberOfReusedLeaves(), 3);
  out = vtkMultiBlockDataSet::SafeDownCast(builder->GetOutputDataObject(0));
  EXPECT_NE(Leaf(out, 0), Leaf(out, 1));
}

TEST_F(MultiresolutionHierarchyBuilder, ThreadsReportMessagesInLeafOrder)
{
  std::vector<vtkSmartPointer<vtkPolyData>> leaves = VariedLeaves(5);
  for (unsigned int bad : { 1u, 3u })
  {
    leaves[bad]->GetPoints()->SetPoint(2, std::numeric_limits<double>::infinity(), 0.0, 0.0);
  }
  vtkNew<vtkMultiresolutionHierarchyBuilder> builder;
  builder->SetNumberOfThreads(4);
  MessageLog log(builder);
  builder->SetInputData(Blocks(leaves));
  builder->Update();
  ASSERT_EQ(log.Errors.size(), 2u) << log.AllErrors();
  EXPECT_NE(log.Errors[0].find("Leaf 2 (composite flat index)"), std::string::npos);
  EXPECT_NE(log.Errors[1].find("Leaf 4 (composite flat index)"), std::string::npos);
  EXPECT_EQ(builder->GetNumberOfBuiltLeaves(), 3);
  EXPECT_EQ(builder->GetNumberOfPassedLeaves(), 2);
}

TEST_F(MultiresolutionHierarchyBuilder, ThreadsLeaveProgressToTheCallingThread)
{
  vtkNew<vtkMultiresolutionHierarchyBuilder> builder;
  builder->SetNumberOfThreads(3);
  struct Record
  {
    std::vector<double> Progress;
    std::vector<std::thread::id> Threads;
  } record;
  vtkNew<vtkCallbackCommand> callback;
  callback->SetClientData(&record);
  callback->SetCallback([](vtkObject* caller, unsigned long, void* client, void*) {
    auto* r = static_cast<Record*>(client);
    r->Progress.push_back(static_cast<vtkAlgorithm*>(caller)->GetProgress());
    r->Threads.push_back(std::this_thread::get_id());
  });
  builder->AddObserver(vtkCommand::ProgressEvent, callback);
  builder->SetInputData(Blocks(VariedLeaves(6)));
  builder->Update();
  ASSERT_FALSE(record.Progress.empty());
  for (size_t i = 0; i < record.Progress.size(); ++i)
  {
    EXPECT_EQ(record.Threads[i], std::this_thread::get_id());
    EXPECT_GE(record.Progress[i], i ? record.Progress[i - 1] - 1e-12 : 0.0) << "at " << i;
  }
  EXPECT_DOUBLE_EQ(record.Progress.back(), 1.0);
}

TEST_F(MultiresolutionHierarchyBuilder, AnAbortCancelsThePendingBuilds)
{
  std::vector<vtkSmartPointer<vtkPolyData>> leaves;
  for (int i = 0; i < 6; ++i)
  {
    leaves.push_back(Step(i, 60));
  }
  auto input = Blocks(leaves);
  for (int threads : { 1, 2 })
  {
    vtkNew<vtkMultiresolutionHierarchyBuilder> builder;
    vtkNew<vtkHierarchyBuildCache> cache;
    builder->SetCache(cache);
    builder->SetNumberOfThreads(threads);
    tt::AbortPastOneFifth(builder);
    builder->SetInputData(input);
    builder->Update();
    EXPECT_LT(builder->GetNumberOfBuiltLeaves(), 6) << threads << " threads";
    EXPECT_EQ(builder->GetNumberOfBuiltLeaves() + builder->GetNumberOfPassedLeaves(), 6);
    auto* out = vtkMultiBlockDataSet::SafeDownCast(builder->GetOutputDataObject(0));
    for (unsigned int i = 0; i < 6; ++i)
    {
      // A cancelled leaf passes as it came, never half built.
      EXPECT_TRUE(
        Leaf(out, i) == leaves[i].GetPointer() || vtkTOMFieldData::HasTOMArrays(Leaf(out, i)));
    }
    // Cancelled builds are not cached: without the abort every leaf is built.
    EXPECT_EQ(cache->GetNumberOfEntries(), builder->GetNumberOfBuiltLeaves());
    builder->RemoveAllObservers();
    builder->SetAbortExecute(0);
    builder->Modified();
    builder->Update();
    EXPECT_EQ(builder->GetNumberOfBuiltLeaves() + builder->GetNumberOfReusedLeaves(), 6);
  }
}

TEST_F(MultiresolutionHierarchyBuilder, PairContractionDistanceReachesTheBuildAndTheKey)
{
  // Two spheres of radius 0.5 with a gap of 0.5 (a diagonal of 2.9): joined
  // with pairs within 0.6 of it.
  auto first = MakeSphere(16);
  auto pair = vtkSmartPointer<vtkPolyData>::New();
  {
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> polys;
    for (double shift : { 0.0, 1.5 })
    {
      const vtkIdType offset = points->GetNumberOfPoints();
      for (vtkIdType p = 0; p < first->GetNumberOfPoints(); ++p)
      {
        double x[3];
        first->GetPoint(p, x);
        points->InsertNextPoint(x[0] + shift, x[1], x[2]);
      }
      for (vtkIdType c = 0; c < first->GetNumberOfCells(); ++c)
      {
        vtkIdType n = 0;
        const vtkIdType* ids = nullptr;
        first->GetCellPoints(c, n, ids);
        polys->InsertNextCell({ ids[0] + offset, ids[1] + offset, ids[2] + offset });
      }
    }
    pair->SetPoints(points);
    pair->SetPolys(polys);
  }
  auto baseVertices = [](vtkMultiresolutionHierarchyBuilder* builder) {
    vtkNew<vtkTOMFieldData> reader;
    EXPECT_TRUE(reader->Read(vtkPolyData::SafeDownCast(builder->GetOutputDataObject(0))))
      << reader->GetErrorMessage();
    return reader->GetBaseVertexCount();
  };
  vtkNew<vtkMultiresolutionHierarchyBuilder> builder;
  EXPECT_EQ(builder->GetPairContractionDistance(), 0.0);
  builder->SetInputData(pair);
  builder->Update();
  ASSERT_EQ(builder->GetNumberOfBuilds(), 1);
  EXPECT_EQ(baseVertices(builder), 8) << "a tetrahedron per sphere";

  // A changed distance is a new build (not the last execution's, not the cache's).
  builder->SetPairContractionDistance(0.6);
  builder->Update();
  EXPECT_EQ(builder->GetNumberOfBuilds(), 2);
  EXPECT_EQ(builder->GetNumberOfBuiltLeaves(), 1);
  EXPECT_EQ(baseVertices(builder), 4) << "the spheres joined";

  // Back to off: the first build, from the cache.
  builder->SetPairContractionDistance(0.0);
  builder->Update();
  EXPECT_EQ(builder->GetNumberOfBuilds(), 2);
  EXPECT_EQ(builder->GetNumberOfReusedLeaves(), 1);
  EXPECT_EQ(baseVertices(builder), 8);

  // Merge trees ignore it: one build for both distances.
  builder->SetHierarchy(vtkMultiresolutionHierarchyBuilder::MERGE_TREE);
  builder->Update();
  EXPECT_EQ(builder->GetNumberOfBuilds(), 3);
  builder->SetPairContractionDistance(0.6);
  builder->Update();
  EXPECT_EQ(builder->GetNumberOfBuilds(), 3);
  EXPECT_EQ(builder->GetNumberOfReusedLeaves(), 1);
}

TEST_F(MultiresolutionHierarchyBuilder, BadSettingsGiveClearErrors)
{
  vtkNew<vtkMultiresolutionHierarchyBuilder> builder;
  MessageLog log(builder);
  builder->SetNumberOfThreads(-2);
  ASSERT_EQ(log.Errors.size(), 1u);
  EXPECT_NE(log.Errors[0].find("NumberOfThreads must be >= 0"), std::string::npos) << log.Errors[0];
  EXPECT_EQ(builder->GetNumberOfThreads(), 0);
  builder->SetPairContractionDistance(0.5);
  for (double bad : { -1.0, 2.0, std::numeric_limits<double>::quiet_NaN() })
  {
    builder->SetPairContractionDistance(bad);
    EXPECT_EQ(builder->GetPairContractionDistance(), 0.5) << bad;
  }
  ASSERT_EQ(log.Errors.size(), 4u);
  EXPECT_NE(log.Errors[3].find("PairContractionDistance"), std::string::npos) << log.Errors[3];
  log.Errors.clear();
  // The cache's settings are checked by the cache.
  vtkNew<vtkHierarchyBuildCache> cache;
  builder->SetCache(cache);
  MessageLog cacheLog(cache);
  const vtkTypeInt64 limit = cache->GetMemoryLimit();
  builder->SetCacheMemoryLimit(-1);
  EXPECT_EQ(cacheLog.Errors.size(), 1u);
  EXPECT_EQ(builder->GetCacheMemoryLimit(), limit);
}
} // namespace
