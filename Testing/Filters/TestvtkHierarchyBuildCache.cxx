// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkHierarchyBuildCache: keys, LRU eviction under the memory limit,
// the disk cache's round trip and its rejection of bad files, settings, and
// Find/Insert from several threads at once.
#include "FilterTestSupport.h"
#include "vtkHierarchyBuildCache.h"
#include "vtkMergeTreeBuilder.h"
#include "vtkMergeTreeFieldData.h"
#include "vtkTOMBuilder.h"
#include "vtkTOMFieldData.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLPolyDataWriter.h"

#include <vtksys/SystemTools.hxx>

#include <gtest/gtest.h>

#include <unistd.h> // getpid

#include <atomic>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

namespace
{
namespace tt = timecritical::testing;
using Key = vtkHierarchyBuildCache::Key;

/// A sphere of `resolution` moved by `shift` along x: same size, other content.
vtkSmartPointer<vtkPolyData> ShiftedSphere(int resolution, double shift)
{
  auto sphere = tt::MakeSphere(resolution);
  vtkPoints* points = sphere->GetPoints();
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    p[0] += shift;
    points->SetPoint(i, p);
  }
  return sphere;
}

vtkSmartPointer<vtkPolyData> BuildTOM(vtkPolyData* input)
{
  return tt::RunFilter<vtkTOMBuilder>(input, nullptr);
}

vtkSmartPointer<vtkPolyData> BuildMergeTree(vtkPolyData* input)
{
  return tt::RunFilter<vtkMergeTreeBuilder>(input, nullptr);
}

/// A fresh directory under the test output directory.
std::string ScratchDirectory(const std::string& name)
{
  const std::string path =
    std::string(TIMECRITICAL_TEST_OUTPUT_DIR) + "/HierarchyBuildCache-" + name + "-" +
    std::to_string(::getpid()); // a folder per process: ctest runs programs side by side
  vtksys::SystemTools::RemoveADirectory(path);
  vtksys::SystemTools::MakeDirectory(path);
  return path;
}

std::string ReadText(const std::string& path)
{
  std::ifstream file(path.c_str(), std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
}

void WriteText(const std::string& path, const std::string& text)
{
  std::ofstream file(path.c_str(), std::ios::binary | std::ios::trunc);
  file << text;
}

/// The number of points of the cached build of `key`, or -1 when absent.
vtkIdType PointsOf(vtkHierarchyBuildCache* cache, const Key& key)
{
  auto found = cache->Find(key);
  return found ? found->GetNumberOfPoints() : -1;
}

TEST(HierarchyBuildCache, KeysFollowContentCellsAndHierarchy)
{
  auto sphere = tt::MakeSphere(12);
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(sphere);
  const Key key = vtkHierarchyBuildCache::MakeKey(sphere, 0);
  EXPECT_TRUE(key == vtkHierarchyBuildCache::MakeKey(copy, 0));
  EXPECT_FALSE(key == vtkHierarchyBuildCache::MakeKey(copy, 1));
  EXPECT_EQ(key.Cells, sphere->GetNumberOfCells());
  EXPECT_FALSE(key == vtkHierarchyBuildCache::MakeKey(ShiftedSphere(12, 1.0), 0));
  const std::string text = vtkHierarchyBuildCache::KeyText(key);
  EXPECT_EQ(text.rfind("tom-", 0), 0u) << text;
  EXPECT_NE(text.find("-" + std::to_string(key.Cells) + "-v"), std::string::npos) << text;
  EXPECT_EQ(vtkHierarchyBuildCache::KeyText(vtkHierarchyBuildCache::MakeKey(copy, 1)).rfind(
              "mergetree-", 0),
    0u);
}

TEST(HierarchyBuildCache, KeysFollowThePairContractionDistance)
{
  auto sphere = tt::MakeSphere(12);
  const Key plain = vtkHierarchyBuildCache::MakeKey(sphere, 0);
  const Key off = vtkHierarchyBuildCache::MakeKey(sphere, 0, 0.0);
  const Key on = vtkHierarchyBuildCache::MakeKey(sphere, 0, 0.05);
  const Key other = vtkHierarchyBuildCache::MakeKey(sphere, 0, 0.1);
  EXPECT_TRUE(plain == off);
  EXPECT_FALSE(on == off);
  EXPECT_FALSE(on == other);
  EXPECT_TRUE(on == vtkHierarchyBuildCache::MakeKey(sphere, 0, 0.05));
  EXPECT_EQ(on.PairContractionDistance, 0.05);
  // Ordered (the maps of builds): distinct keys compare one way only.
  EXPECT_NE(on < off, off < on);
  EXPECT_NE(on < other, other < on);
  // Files: builds without pairs keep their names; each distance has its own.
  const std::string offText = vtkHierarchyBuildCache::KeyText(off);
  const std::string onText = vtkHierarchyBuildCache::KeyText(on);
  EXPECT_EQ(offText.find("pairs"), std::string::npos) << offText;
  EXPECT_EQ(onText.rfind(offText + "-pairs", 0), 0u) << onText;
  EXPECT_NE(onText, vtkHierarchyBuildCache::KeyText(other));
  // vtkMergeTreeBuilder ignores the distance: one key for all distances.
  EXPECT_TRUE(vtkHierarchyBuildCache::MakeKey(sphere, 1, 0.05) ==
    vtkHierarchyBuildCache::MakeKey(sphere, 1));

  // A build stored for one distance is not found for another.
  vtkNew<vtkHierarchyBuildCache> cache;
  cache->Insert(on, BuildTOM(sphere));
  EXPECT_GT(PointsOf(cache, on), 0);
  EXPECT_EQ(PointsOf(cache, off), -1);
  EXPECT_EQ(PointsOf(cache, other), -1);
}

TEST(HierarchyBuildCache, EvictsTheLeastRecentlyUsedUnderTheLimit)
{
  std::vector<Key> keys;
  std::vector<vtkSmartPointer<vtkPolyData>> builds;
  for (int i = 0; i < 4; ++i)
  {
    auto sphere = ShiftedSphere(16, i);
    keys.push_back(vtkHierarchyBuildCache::MakeKey(sphere, 0));
    builds.push_back(BuildTOM(sphere));
  }
  vtkNew<vtkHierarchyBuildCache> cache;
  cache->Insert(keys[0], builds[0]);
  const vtkTypeInt64 size = cache->GetMemoryInUse(); // the same for each
  ASSERT_GT(size, 0);
  cache->SetMemoryLimit(3 * size + size / 2); // three entries
  for (int i = 1; i < 3; ++i)
  {
    cache->Insert(keys[i], builds[i]);
  }
  EXPECT_EQ(cache->GetNumberOfEntries(), 3);
  EXPECT_EQ(cache->GetMemoryInUse(), 3 * size);
  EXPECT_EQ(cache->GetNumberOfEvictions(), 0);

  // Using entry 0 makes entry 1 the least recently used: the fourth evicts it.
  EXPECT_EQ(PointsOf(cache, keys[0]), builds[0]->GetNumberOfPoints());
  cache->Insert(keys[3], builds[3]);
  EXPECT_EQ(cache->GetNumberOfEvictions(), 1);
  EXPECT_EQ(PointsOf(cache, keys[1]), -1);
  EXPECT_NE(PointsOf(cache, keys[2]), -1);
  EXPECT_NE(PointsOf(cache, keys[3]), -1);
  EXPECT_NE(PointsOf(cache, keys[0]), -1);
  EXPECT_LE(cache->GetMemoryInUse(), cache->GetMemoryLimit());
  EXPECT_EQ(cache->GetNumberOfMemoryHits(), 4);
  EXPECT_EQ(cache->GetNumberOfMisses(), 1);

  // Lowering the limit evicts at once, least recently used first (2, then 3).
  cache->SetMemoryLimit(size + size / 2);
  EXPECT_EQ(cache->GetNumberOfEntries(), 1);
  EXPECT_EQ(cache->GetNumberOfEvictions(), 3);
  EXPECT_NE(PointsOf(cache, keys[0]), -1);

  // An entry larger than the limit is not held; a limit of 0 holds nothing.
  cache->SetMemoryLimit(size / 2);
  cache->Insert(keys[1], builds[1]);
  EXPECT_EQ(cache->GetNumberOfEntries(), 0);
  EXPECT_EQ(cache->GetMemoryInUse(), 0);
  cache->SetMemoryLimit(0);
  cache->Insert(keys[1], builds[1]);
  EXPECT_EQ(PointsOf(cache, keys[1]), -1);
}

TEST(HierarchyBuildCache, FindGivesNewObjectsSharingTheArrays)
{
  auto sphere = tt::MakeSphere(12);
  const Key key = vtkHierarchyBuildCache::MakeKey(sphere, 0);
  auto build = BuildTOM(sphere);
  const int fieldArrays = build->GetFieldData()->GetNumberOfArrays();
  vtkNew<vtkHierarchyBuildCache> cache;
  const std::string directory = ScratchDirectory("Sharing");
  ASSERT_TRUE(cache->SetDirectory(directory.c_str()));
  cache->Insert(key, build);
  // Writing the file adds the key to a copy only.
  EXPECT_EQ(build->GetFieldData()->GetNumberOfArrays(), fieldArrays);
  auto first = cache->Find(key);
  auto second = cache->Find(key);
  ASSERT_TRUE(first && second);
  EXPECT_NE(first.GetPointer(), build.GetPointer());
  EXPECT_NE(first.GetPointer(), second.GetPointer());
  EXPECT_EQ(first->GetPoints()->GetData(), build->GetPoints()->GetData());
  EXPECT_EQ(first->GetFieldData()->GetNumberOfArrays(), fieldArrays);
  cache->Clear();
  EXPECT_EQ(cache->GetNumberOfEntries(), 0);
}

TEST(HierarchyBuildCache, DiskRoundTripGivesIdenticalArrays)
{
  const std::string directory = ScratchDirectory("RoundTrip");
  auto sphere = tt::MakeSphere(20);
  const Key tomKey = vtkHierarchyBuildCache::MakeKey(sphere, 0);
  const Key treeKey = vtkHierarchyBuildCache::MakeKey(sphere, 1);
  auto tom = BuildTOM(sphere);
  auto tree = BuildMergeTree(sphere);
  {
    vtkNew<vtkHierarchyBuildCache> writer;
    ASSERT_TRUE(writer->SetDirectory(directory.c_str()));
    writer->Insert(tomKey, tom);
    writer->Insert(treeKey, tree);
    EXPECT_EQ(writer->GetNumberOfFilesWritten(), 2);
    EXPECT_TRUE(vtksys::SystemTools::FileExists(writer->FilePath(tomKey), true));
  }
  vtkNew<vtkHierarchyBuildCache> reader; // another process, later
  tt::MessageLog log(reader);
  ASSERT_TRUE(reader->SetDirectory(directory.c_str()));
  bool fromDisk = false;
  auto readTOM = reader->Find(tomKey, nullptr, &fromDisk);
  EXPECT_TRUE(fromDisk);
  auto readTree = reader->Find(treeKey);
  ASSERT_TRUE(readTOM && readTree);
  tt::ExpectSameArrays(readTOM, tom);
  tt::ExpectSameArrays(readTree, tree);
  EXPECT_EQ(reader->GetNumberOfDiskHits(), 2);
  // Now in memory.
  reader->Find(tomKey, nullptr, &fromDisk);
  EXPECT_FALSE(fromDisk);
  EXPECT_EQ(reader->GetNumberOfMemoryHits(), 1);
  EXPECT_TRUE(log.Warnings.empty());
  EXPECT_TRUE(log.Errors.empty());
  // Without a directory nothing is read.
  vtkNew<vtkHierarchyBuildCache> memoryOnly;
  EXPECT_EQ(memoryOnly->Find(tomKey), nullptr);
  EXPECT_EQ(memoryOnly->FilePath(tomKey), "");
}

/// Writes `data` to `path` as the cache would not: plain binary, as given.
void WriteVTP(vtkPolyData* data, const std::string& path)
{
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(data);
  writer->SetFileName(path.c_str());
  writer->SetDataModeToBinary();
  ASSERT_EQ(writer->Write(), 1);
}

vtkSmartPointer<vtkPolyData> ReadVTP(const std::string& path)
{
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkSmartPointer<vtkPolyData> out = reader->GetOutput();
  return out;
}

/// A copy of `build` with one array replaced by a damaged deep copy.
vtkSmartPointer<vtkPolyData> Damaged(vtkPolyData* build, bool pointData, const char* name,
  vtkIdType index, double value)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->ShallowCopy(build);
  vtkFieldData* data = pointData ? copy->GetPointData() : copy->GetFieldData();
  vtkSmartPointer<vtkDataArray> array;
  array.TakeReference(data->GetArray(name)->NewInstance());
  array->DeepCopy(data->GetArray(name));
  array->SetComponent(index, 0, value);
  data->AddArray(array); // replaces the array of that name
  return copy;
}

TEST(HierarchyBuildCache, RejectsBadFilesWithAWarningNamingThem)
{
  const std::string directory = ScratchDirectory("BadFiles");
  auto sphere = tt::MakeSphere(16);
  const Key key = vtkHierarchyBuildCache::MakeKey(sphere, 0);
  const Key treeKey = vtkHierarchyBuildCache::MakeKey(sphere, 1);
  const Key otherKey = vtkHierarchyBuildCache::MakeKey(ShiftedSphere(16, 2.0), 0);
  auto tom = BuildTOM(sphere);
  auto tree = BuildMergeTree(sphere);
  vtkNew<vtkHierarchyBuildCache> writer;
  ASSERT_TRUE(writer->SetDirectory(directory.c_str()));
  writer->Insert(key, tom);
  writer->Insert(otherKey, BuildTOM(ShiftedSphere(16, 2.0)));
  const std::string path = writer->FilePath(key);
  const std::string good = ReadText(path);
  ASSERT_GT(good.size(), 1000u);

  // Each bad file, then what the reader must say about it.
  struct Case
  {
    std::string Name;
    std::function<void()> Make;
    std::string Expected;
  };
  const std::vector<Case> cases = {
    { "truncated", [&] { WriteText(path, good.substr(0, good.size() / 2)); }, "unreadable" },
    { "empty", [&] { WriteText(path, ""); }, "unreadable" },
    { "garbage", [&] { WriteText(path, std::string(5000, '\x7f') + "<?xml garbage"); },
      "unreadable" },
    { "foreign", [&] { WriteText(path, ReadText(writer->FilePath(otherKey))); }, "foreign" },
    { "edited points",
      [&] {
        writer->Insert(key, tom);
        auto data = ReadVTP(path); // key and hash kept, a point moved
        data->GetPoints()->SetPoint(0, 9.0, 9.0, 9.0);
        WriteVTP(data, path);
      },
      "content hash" },
    { "damaged TOM counts",
      [&] { writer->Insert(key, Damaged(tom, false, "TOMCounts", 1, 3.0)); }, "TOM is invalid" },
    { "damaged TOM substitution",
      [&] { writer->Insert(key, Damaged(tom, true, "TOMSubstitution", 2, 1e6)); },
      "TOM is invalid" },
  };
  for (const Case& bad : cases)
  {
    bad.Make();
    vtkNew<vtkHierarchyBuildCache> reader;
    tt::MessageLog log(reader);
    ASSERT_TRUE(reader->SetDirectory(directory.c_str()));
    EXPECT_EQ(reader->Find(key), nullptr) << bad.Name;
    ASSERT_EQ(log.Warnings.size(), 1u) << bad.Name;
    EXPECT_NE(log.Warnings[0].find(path), std::string::npos) << log.Warnings[0];
    EXPECT_NE(log.Warnings[0].find(bad.Expected), std::string::npos) << bad.Name << ": "
                                                                     << log.Warnings[0];
    EXPECT_TRUE(log.Errors.empty()) << bad.Name << ": " << log.AllErrors();
    EXPECT_EQ(reader->GetNumberOfRejectedFiles(), 1) << bad.Name;
    EXPECT_EQ(reader->GetNumberOfMisses(), 1) << bad.Name;
    // Given a list, the warning goes there instead (worker threads).
    std::vector<std::string> warnings;
    reader->Find(key, &warnings);
    EXPECT_EQ(warnings.size(), 1u) << bad.Name;
    EXPECT_EQ(log.Warnings.size(), 1u) << bad.Name;
  }

  // A damaged merge tree, then the rebuilt entry overwrites the file.
  writer->Insert(treeKey, Damaged(tree, false, "MergeTreeLevelCount", 0, 0.0));
  {
    vtkNew<vtkHierarchyBuildCache> reader;
    tt::MessageLog log(reader);
    reader->SetDirectory(directory.c_str());
    EXPECT_EQ(reader->Find(treeKey), nullptr);
    ASSERT_EQ(log.Warnings.size(), 1u);
    EXPECT_NE(log.Warnings[0].find("merge tree is invalid"), std::string::npos) << log.Warnings[0];
    reader->Insert(treeKey, tree);
  }
  vtkNew<vtkHierarchyBuildCache> reader;
  reader->SetDirectory(directory.c_str());
  auto read = reader->Find(treeKey);
  ASSERT_NE(read, nullptr);
  tt::ExpectSameArrays(read, tree);
}

TEST(HierarchyBuildCache, BadSettingsGiveClearErrors)
{
  vtkNew<vtkHierarchyBuildCache> cache;
  tt::MessageLog log(cache);
  EXPECT_EQ(cache->GetMemoryLimit(), vtkHierarchyBuildCache::GetDefaultMemoryLimit());
  EXPECT_GT(cache->GetMemoryLimit(), 0);
  cache->SetMemoryLimit(-5);
  ASSERT_EQ(log.Errors.size(), 1u);
  EXPECT_NE(log.Errors[0].find("MemoryLimit must be >= 0"), std::string::npos) << log.Errors[0];
  EXPECT_EQ(cache->GetMemoryLimit(), vtkHierarchyBuildCache::GetDefaultMemoryLimit());

  // A directory that cannot be made (its parent is a file): the disk cache is off.
  const std::string file = ScratchDirectory("Settings") + "/a-file";
  WriteText(file, "x");
  EXPECT_FALSE(cache->SetDirectory((file + "/cache").c_str()));
  ASSERT_EQ(log.Errors.size(), 2u);
  EXPECT_NE(log.Errors[1].find("cannot be made"), std::string::npos) << log.Errors[1];
  EXPECT_NE(log.Errors[1].find("a-file/cache"), std::string::npos) << log.Errors[1];
  EXPECT_EQ(cache->GetDirectory(), "");

  // A missing directory is made; empty or null turns the disk cache off.
  const std::string made = ScratchDirectory("Settings") + "/made/here";
  EXPECT_TRUE(cache->SetDirectory(made.c_str()));
  EXPECT_TRUE(vtksys::SystemTools::FileIsDirectory(made));
  EXPECT_EQ(cache->GetDirectory(), made);
  EXPECT_TRUE(cache->SetDirectory(""));
  EXPECT_EQ(cache->GetDirectory(), "");
  EXPECT_TRUE(cache->SetDirectory(nullptr));
  EXPECT_EQ(log.Errors.size(), 2u);
}

TEST(HierarchyBuildCache, SharedInstanceIsOnePerProcess)
{
  vtkHierarchyBuildCache* shared = vtkHierarchyBuildCache::GetSharedInstance();
  ASSERT_NE(shared, nullptr);
  EXPECT_EQ(shared, vtkHierarchyBuildCache::GetSharedInstance());
  EXPECT_EQ(shared->GetMemoryLimit(), vtkHierarchyBuildCache::GetDefaultMemoryLimit());
}

TEST(HierarchyBuildCache, ConcurrentFindAndInsert)
{
  // 8 contents, room for about 4 in memory, a shared directory: 6 threads
  // find and insert at once. Every find gives nothing or the right build.
  constexpr int contents = 8;
  std::vector<Key> keys;
  std::vector<vtkSmartPointer<vtkPolyData>> builds;
  for (int i = 0; i < contents; ++i)
  {
    auto sphere = ShiftedSphere(10 + i, i);
    keys.push_back(vtkHierarchyBuildCache::MakeKey(sphere, 0));
    builds.push_back(BuildTOM(sphere));
  }
  vtkNew<vtkHierarchyBuildCache> cache;
  cache->Insert(keys[4], builds[4]);
  cache->SetMemoryLimit(4 * cache->GetMemoryInUse());
  cache->Clear();
  ASSERT_TRUE(cache->SetDirectory(ScratchDirectory("Concurrent").c_str()));
  std::atomic<int> wrong{ 0 }, finds{ 0 }, warnings{ 0 };
  std::vector<std::thread> threads;
  for (int t = 0; t < 6; ++t)
  {
    threads.emplace_back([&, t]() {
      std::vector<std::string> messages;
      for (int round = 0; round < 24; ++round)
      {
        const int i = (round * 5 + t * 3) % contents;
        auto found = cache->Find(keys[i], &messages);
        ++finds;
        if (!found)
        {
          cache->Insert(keys[i], builds[i], &messages);
        }
        else if (found->GetNumberOfPoints() != builds[i]->GetNumberOfPoints() ||
          found->GetNumberOfPolys() != builds[i]->GetNumberOfPolys())
        {
          ++wrong;
        }
      }
      warnings += static_cast<int>(messages.size());
    });
  }
  for (auto& thread : threads)
  {
    thread.join();
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_EQ(warnings, 0);
  EXPECT_EQ(cache->GetNumberOfMemoryHits() + cache->GetNumberOfDiskHits() +
      cache->GetNumberOfMisses(),
    finds.load());
  EXPECT_LE(cache->GetMemoryInUse(), cache->GetMemoryLimit());
  // Every file written at once by several threads is whole.
  vtkNew<vtkHierarchyBuildCache> reader;
  reader->SetDirectory(cache->GetDirectory().c_str());
  for (int i = 0; i < contents; ++i)
  {
    auto read = reader->Find(keys[i]);
    ASSERT_NE(read, nullptr) << i;
    tt::ExpectSameArrays(read, builds[i]);
  }
}
} // namespace
