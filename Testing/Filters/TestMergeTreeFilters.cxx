// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkMergeTreeBuilder, vtkMergeTreeFieldData and vtkExtractViewDependentMesh.
#include "FilterTestSupport.h"
#include "MergeTree.h"
#include "TOMMesh.h"
#include "vtkExtractViewDependentMesh.h"
#include "vtkMergeTreeBuilder.h"
#include "vtkMergeTreeFieldData.h"
#include "vtkTOMBuilder.h"
#include "vtkTOMFieldData.h"

#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkTypeUInt16Array.h"
#include "vtkTypeUInt32Array.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace
{
namespace tt = timecritical::testing;
using tt::LinesOnly;
using tt::MakeSphere;
using tt::MessageLog;
using tt::PointKey;
using Key = tt::PointKeyType;

vtkSmartPointer<vtkPolyData> BuildTree(vtkPolyData* input, vtkMergeTreeBuilder* builder = nullptr)
{
  return tt::RunFilter(input, builder);
}

// One merge tree of a sphere shared by the tests that only read it.
vtkPolyData* SphereTree()
{
  static vtkSmartPointer<vtkPolyData> tree = BuildTree(MakeSphere());
  return tree;
}

vtkSmartPointer<vtkPolyData> Copy(vtkPolyData* data)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(data);
  return copy;
}
}

// ---------------------------------------------------------------------------
// vtkMergeTreeBuilder

TEST(vtkMergeTreeBuilder, SphereGivesValidTOMAndMergeTree)
{
  auto input = MakeSphere();
  vtkNew<vtkMergeTreeBuilder> builder;
  MessageLog log(builder);
  auto out = BuildTree(input, builder);
  EXPECT_TRUE(log.Errors.empty()) << log.AllErrors();
  vtkNew<vtkMergeTreeFieldData> reader;
  ASSERT_TRUE(reader->Read(out)) << reader->GetErrorMessage();
  vtkNew<vtkTOMFieldData> tom;
  ASSERT_TRUE(tom->Read(out)) << tom->GetErrorMessage();
  EXPECT_EQ(out->GetNumberOfPoints(), input->GetNumberOfPoints());
  EXPECT_EQ(out->GetNumberOfPolys(), input->GetNumberOfPolys());
  EXPECT_EQ(reader->GetNumberOfVertices(), out->GetNumberOfPoints());
  EXPECT_GT(reader->GetLevelCount(), 1);
  EXPECT_EQ(builder->GetLevelCount(), reader->GetLevelCount());
  EXPECT_GT(reader->GetNumberOfDependencies(), 0);
  EXPECT_LE(tom->GetBaseVertexCount(), 16);
  // The exact array types of the documented layout.
  vtkPointData* pd = out->GetPointData();
  vtkFieldData* fd = out->GetFieldData();
  EXPECT_TRUE(vtkTypeUInt16Array::SafeDownCast(pd->GetArray("MergeTreeLevel")));
  EXPECT_TRUE(vtkFloatArray::SafeDownCast(pd->GetArray("MergeTreeError")));
  EXPECT_TRUE(vtkFloatArray::SafeDownCast(pd->GetArray("MergeTreeRadius")));
  ASSERT_TRUE(vtkFloatArray::SafeDownCast(pd->GetArray("MergeTreeConeAxis")));
  EXPECT_EQ(pd->GetArray("MergeTreeConeAxis")->GetNumberOfComponents(), 3);
  EXPECT_TRUE(vtkFloatArray::SafeDownCast(pd->GetArray("MergeTreeConeCosine")));
  EXPECT_TRUE(vtkTypeUInt32Array::SafeDownCast(fd->GetArray("MergeTreeDependencyOffsets")));
  EXPECT_TRUE(vtkTypeUInt32Array::SafeDownCast(fd->GetArray("MergeTreeDependencies")));
  EXPECT_TRUE(vtkTypeUInt16Array::SafeDownCast(fd->GetArray("MergeTreeLevelCount")));
  // Input arrays plus TOMSubstitution and the five merge-tree point arrays.
  EXPECT_EQ(pd->GetNumberOfArrays(), input->GetPointData()->GetNumberOfArrays() + 6);
}

TEST(vtkMergeTreeBuilder, PointAndCellDataTravelWithTheirPointsAndTriangles)
{
  tt::ExpectDataTravelsWithPointsAndTriangles(MakeSphere(), SphereTree());
}

TEST(vtkMergeTreeBuilder, EmptyInputGivesEmptyOutputQuietly)
{
  vtkNew<vtkPolyData> empty;
  vtkNew<vtkMergeTreeBuilder> builder;
  MessageLog log(builder);
  auto out = BuildTree(empty, builder);
  EXPECT_TRUE(log.Errors.empty()) << log.AllErrors();
  EXPECT_TRUE(log.Warnings.empty());
  EXPECT_EQ(out->GetNumberOfPoints(), 0);
  EXPECT_EQ(out->GetNumberOfCells(), 0);
}

TEST(vtkMergeTreeBuilder, LinesOnlyIsAnError)
{
  vtkNew<vtkMergeTreeBuilder> builder;
  MessageLog log(builder);
  auto out = BuildTree(LinesOnly(), builder);
  EXPECT_TRUE(log.ErrorContains("no surface cells")) << log.AllErrors();
  EXPECT_EQ(out->GetNumberOfCells(), 0);
}

TEST(vtkMergeTreeBuilder, NaNCoordinateIsAnError)
{
  auto input = MakeSphere(10);
  input->GetPoints()->SetPoint(5, std::numeric_limits<double>::quiet_NaN(), 0, 0);
  vtkNew<vtkMergeTreeBuilder> builder;
  MessageLog log(builder);
  auto out = BuildTree(input, builder);
  EXPECT_TRUE(log.ErrorContains("point 5 has a non-finite")) << log.AllErrors();
  EXPECT_EQ(out->GetNumberOfPoints(), 0);
}

TEST(vtkMergeTreeBuilder, HugeCoordinateIsAnError)
{
  // Beyond the limit the tree's float radii would overflow and its own
  // reader reject it; up to the limit it builds and reads back.
  auto input = MakeSphere(10);
  input->GetPoints()->SetPoint(5, 0, 3e38, 0);
  vtkNew<vtkMergeTreeBuilder> builder;
  MessageLog log(builder);
  auto out = BuildTree(input, builder);
  EXPECT_TRUE(
    log.ErrorContains("point 5 has a coordinate of magnitude 3e+38, beyond the supported"))
    << log.AllErrors();
  EXPECT_EQ(out->GetNumberOfPoints(), 0);

  auto large = MakeSphere(10);
  for (vtkIdType i = 0; i < large->GetNumberOfPoints(); ++i)
  {
    double p[3];
    large->GetPoints()->GetPoint(i, p);
    large->GetPoints()->SetPoint(i, 1.8e28 * p[0], 1.8e28 * p[1], 1.8e28 * p[2]); // radius 0.5
  }
  vtkNew<vtkMergeTreeBuilder> largeBuilder;
  MessageLog largeLog(largeBuilder);
  auto tree = BuildTree(large, largeBuilder);
  EXPECT_TRUE(largeLog.Errors.empty()) << largeLog.AllErrors();
  vtkNew<vtkMergeTreeFieldData> reader;
  EXPECT_TRUE(reader->Read(tree)) << reader->GetErrorMessage();
}

TEST(vtkMergeTreeBuilder, OutOfRangePointIdIsAnError)
{
  // Both builders share the input checks: a polygon naming a point that does
  // not exist is reported, never read.
  for (vtkIdType bad : { vtkIdType(5), vtkIdType(-1) })
  {
    auto input = vtkSmartPointer<vtkPolyData>::New();
    vtkNew<vtkPoints> points;
    for (int i = 0; i < 5; ++i)
    {
      points->InsertNextPoint(std::cos(i), std::sin(i), 0.1 * i);
    }
    input->SetPoints(points);
    vtkNew<vtkCellArray> polys;
    polys->InsertNextCell({ 0, 1, 2 });
    polys->InsertNextCell({ 0, 2, 3 });
    polys->InsertNextCell({ 0, 3, 4 });
    polys->InsertNextCell({ 0, 4, bad });
    input->SetPolys(polys);

    vtkNew<vtkMergeTreeBuilder> builder;
    MessageLog log(builder);
    auto out = BuildTree(input, builder);
    EXPECT_TRUE(log.ErrorContains("cell 3 refers to point " + std::to_string(bad)))
      << log.AllErrors();
    EXPECT_EQ(out->GetNumberOfPoints(), 0);

    vtkNew<vtkTOMBuilder> tomBuilder;
    MessageLog tomLog(tomBuilder);
    tomBuilder->SetInputData(input);
    tomBuilder->Update();
    EXPECT_TRUE(tomLog.ErrorContains("cell 3 refers to point " + std::to_string(bad)))
      << tomLog.AllErrors();
  }
}

TEST(vtkMergeTreeBuilder, QuadsAndStripsAreTriangulated)
{
  auto quads = BuildTree(tt::PlaneQuads());
  EXPECT_EQ(quads->GetNumberOfPolys(), 200);

  auto stripped = tt::PlaneStrips();
  ASSERT_GT(stripped->GetNumberOfStrips(), 0);
  auto strips = BuildTree(stripped);
  EXPECT_EQ(strips->GetNumberOfPolys(), 200);
  EXPECT_EQ(strips->GetNumberOfStrips(), 0);
  vtkNew<vtkMergeTreeFieldData> reader;
  EXPECT_TRUE(reader->Read(strips)) << reader->GetErrorMessage();
}

TEST(vtkMergeTreeBuilder, DuplicatePointsAreMergedAndDegenerateCellsDropped)
{
  vtkNew<vtkMergeTreeBuilder> builder;
  MessageLog log(builder);
  auto out = BuildTree(tt::DuplicatePointsAndDegenerateCells(), builder);
  EXPECT_TRUE(log.Errors.empty()) << log.AllErrors();
  EXPECT_GE(log.Warnings.size(), 2u);
  EXPECT_EQ(out->GetNumberOfPoints(), 4);
  EXPECT_EQ(out->GetNumberOfPolys(), 2);
  EXPECT_EQ(builder->GetNumberOfMergedPoints(), 2);
  EXPECT_EQ(builder->GetNumberOfDroppedCells(), 2);
  vtkNew<vtkMergeTreeFieldData> reader;
  EXPECT_TRUE(reader->Read(out)) << reader->GetErrorMessage();
}

TEST(vtkMergeTreeBuilder, ProgressAndAbort)
{
  auto input = MakeSphere(60);
  vtkNew<vtkMergeTreeBuilder> builder;
  std::vector<double> progress;
  vtkNew<vtkCallbackCommand> record;
  record->SetClientData(&progress);
  record->SetCallback([](vtkObject* caller, unsigned long, void* client, void*) {
    static_cast<std::vector<double>*>(client)->push_back(
      static_cast<vtkAlgorithm*>(caller)->GetProgress());
  });
  builder->AddObserver(vtkCommand::ProgressEvent, record);
  auto out = BuildTree(input, builder);
  ASSERT_GT(out->GetNumberOfPoints(), 0);
  ASSERT_GE(progress.size(), 3u);
  EXPECT_EQ(progress.back(), 1.0);
  for (size_t i = 1; i < progress.size(); ++i)
  {
    EXPECT_GE(progress[i], progress[i - 1]);
  }

  vtkNew<vtkMergeTreeBuilder> aborted;
  tt::AbortPastOneFifth(aborted);
  auto empty = BuildTree(input, aborted);
  EXPECT_EQ(empty->GetNumberOfPoints(), 0);
  EXPECT_EQ(empty->GetNumberOfCells(), 0);
}

TEST(vtkMergeTreeBuilder, SettingsRejectNaNAndClamp)
{
  vtkNew<vtkMergeTreeBuilder> builder;
  MessageLog log(builder);
  const vtkMTimeType before = builder->GetMTime();
  builder->SetFeatureAngle(std::numeric_limits<double>::quiet_NaN());
  builder->SetMaximumNormalDeviation(std::numeric_limits<double>::quiet_NaN());
  builder->SetMinimumTriangleQuality(std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(log.Errors.size(), 3u);
  EXPECT_TRUE(log.ErrorContains("MinimumTriangleQuality must be a number"));
  EXPECT_EQ(builder->GetMTime(), before);
  EXPECT_EQ(builder->GetFeatureAngle(), 45.0);
  EXPECT_EQ(builder->GetMaximumNormalDeviation(), 90.0);
  EXPECT_EQ(builder->GetMinimumTriangleQuality(), 0.0);
  builder->SetMinimumTriangleQuality(2.0);
  EXPECT_EQ(builder->GetMinimumTriangleQuality(), 1.0);
  EXPECT_GT(builder->GetMTime(), before);
  builder->SetFeatureAngle(-5.0);
  EXPECT_EQ(builder->GetFeatureAngle(), 0.0);
  // The feature-edge settings (forwarding: TestTOMFilters' FeatureEdgeSettingsReachTheCore).
  EXPECT_FALSE(builder->GetLockFeatureEdges());
  EXPECT_EQ(builder->GetFeatureWeight(), 10.0);
  builder->SetFeatureWeight(std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(log.Errors.size(), 4u);
  EXPECT_TRUE(log.ErrorContains("FeatureWeight must be a number in [0, 1000]; NaN ignored"));
  EXPECT_EQ(builder->GetFeatureWeight(), 10.0);
  builder->SetFeatureWeight(-2.0);
  EXPECT_EQ(builder->GetFeatureWeight(), 0.0);
  builder->SetFeatureWeight(std::numeric_limits<double>::infinity());
  EXPECT_EQ(builder->GetFeatureWeight(), 1000.0);
  builder->LockFeatureEdgesOn();
  EXPECT_TRUE(builder->GetLockFeatureEdges());
  std::ostringstream print;
  builder->Print(print);
  EXPECT_NE(print.str().find("LockFeatureEdges: 1"), std::string::npos) << print.str();
  EXPECT_NE(print.str().find("FeatureWeight: 1000"), std::string::npos) << print.str();
}

TEST(vtkMergeTreeBuilder, LevelCostRatioTradesLevelsForAccuracy)
{
  vtkNew<vtkMergeTreeBuilder> builder;
  MessageLog log(builder);
  EXPECT_EQ(builder->GetLevelCostRatio(), 2.0);
  builder->SetLevelCostRatio(std::numeric_limits<double>::quiet_NaN());
  builder->SetLevelCostRatio(-1.0);
  EXPECT_EQ(log.Errors.size(), 1u);
  EXPECT_EQ(builder->GetLevelCostRatio(), 0.0); // clamped
  // The paper's maximal levels (0) give a shallower tree than the capped default.
  auto input = MakeSphere(40);
  vtkNew<vtkMergeTreeFieldData> reader;
  ASSERT_TRUE(reader->Read(BuildTree(input, builder))) << reader->GetErrorMessage();
  const int maximalLevels = builder->GetLevelCount();
  EXPECT_EQ(reader->GetLevelCount(), maximalLevels);
  builder->SetLevelCostRatio(2.0);
  ASSERT_TRUE(reader->Read(BuildTree(input, builder))) << reader->GetErrorMessage();
  EXPECT_GT(builder->GetLevelCount(), maximalLevels);
  EXPECT_EQ(reader->GetLevelCount(), builder->GetLevelCount());
}

TEST(vtkMergeTreeBuilder, ShadingWeightRaisesErrorsOnly)
{
  vtkNew<vtkMergeTreeBuilder> builder;
  MessageLog log(builder);
  EXPECT_EQ(builder->GetShadingWeight(), 1.0);
  builder->SetShadingWeight(std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(log.Errors.size(), 1u);
  EXPECT_EQ(builder->GetShadingWeight(), 1.0);
  // Bumps much finer than the sphere: their normals vary far more than
  // their height, which only the shading term counts.
  auto input = MakeSphere(80);
  vtkPoints* points = input->GetPoints();
  for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
  {
    double x[3];
    points->GetPoint(p, x);
    const double bump = 1.0 + 0.004 * std::sin(80.0 * x[0]) * std::sin(80.0 * x[1]);
    points->SetPoint(p, bump * x[0], bump * x[1], bump * x[2]);
  }
  // (The builder's output object is reused: read each tree right after its build.)
  vtkNew<vtkMergeTreeFieldData> reader;
  builder->SetShadingWeight(0.0);
  ASSERT_TRUE(reader->Read(BuildTree(input, builder))) << reader->GetErrorMessage();
  const std::vector<float> geometricErrors = reader->GetTree().Error;
  const std::vector<uint32_t> geometricRows = reader->GetTree().Dependencies;
  builder->SetShadingWeight(1.0);
  ASSERT_TRUE(reader->Read(BuildTree(input, builder))) << reader->GetErrorMessage();
  const std::vector<float>& shadedErrors = reader->GetTree().Error;
  ASSERT_EQ(shadedErrors.size(), geometricErrors.size());
  EXPECT_EQ(reader->GetTree().Dependencies, geometricRows); // same tree
  size_t larger = 0;
  for (size_t v = 0; v < shadedErrors.size(); ++v)
  {
    EXPECT_GE(shadedErrors[v], geometricErrors[v]) << v;
    larger += shadedErrors[v] > geometricErrors[v];
  }
  EXPECT_GT(larger, 0u);
}

TEST(vtkMergeTreeBuilder, SliverAvoidanceKeepsAValidTree)
{
  auto input = MakeSphere(30);
  vtkNew<vtkMergeTreeBuilder> builder;
  builder->SetMinimumTriangleQuality(0.3);
  auto out = BuildTree(input, builder);
  vtkNew<vtkMergeTreeFieldData> reader;
  ASSERT_TRUE(reader->Read(out)) << reader->GetErrorMessage();
  EXPECT_EQ(out->GetNumberOfPolys(), input->GetNumberOfPolys());
}

TEST(vtkMergeTreeBuilder, SavedAsBinaryVTPAndReadBackLosesNothing)
{
  vtkPolyData* tree = SphereTree();
  const std::string path = std::string(TIMECRITICAL_TEST_OUTPUT_DIR) + "/sphere-merge-tree.vtp";
  vtkSmartPointer<vtkPolyData> back;
  ASSERT_NO_FATAL_FAILURE(tt::WriteAndReadBack(tree, path, back));
  vtkNew<vtkMergeTreeFieldData> before;
  vtkNew<vtkMergeTreeFieldData> after;
  ASSERT_TRUE(before->Read(tree)) << before->GetErrorMessage();
  ASSERT_TRUE(after->Read(back)) << after->GetErrorMessage();
  const timecritical::MergeTree& a = before->GetTree();
  const timecritical::MergeTree& b = after->GetTree();
  EXPECT_EQ(a.Level, b.Level);
  EXPECT_EQ(a.LevelCount, b.LevelCount);
  EXPECT_EQ(a.Error, b.Error);
  EXPECT_EQ(a.Radius, b.Radius);
  EXPECT_EQ(a.ConeAxis, b.ConeAxis);
  EXPECT_EQ(a.ConeCosine, b.ConeCosine);
  EXPECT_EQ(a.DependencyOffsets, b.DependencyOffsets);
  EXPECT_EQ(a.Dependencies, b.Dependencies);
  EXPECT_EQ(before->GetMesh().Substitution, after->GetMesh().Substitution);
  EXPECT_EQ(before->GetMesh().Triangles, after->GetMesh().Triangles);
  // Types survive too, not only values.
  for (const char* name : { "MergeTreeLevel", "MergeTreeError", "MergeTreeRadius",
         "MergeTreeConeAxis", "MergeTreeConeCosine", "TOMSubstitution" })
  {
    vtkDataArray* original = tree->GetPointData()->GetArray(name);
    vtkDataArray* reloaded = back->GetPointData()->GetArray(name);
    ASSERT_NE(reloaded, nullptr) << name;
    EXPECT_EQ(reloaded->GetDataType(), original->GetDataType()) << name;
  }
  for (const char* name :
    { "MergeTreeDependencyOffsets", "MergeTreeDependencies", "MergeTreeLevelCount" })
  {
    vtkDataArray* reloaded = back->GetFieldData()->GetArray(name);
    ASSERT_NE(reloaded, nullptr) << name;
    EXPECT_EQ(reloaded->GetDataType(), tree->GetFieldData()->GetArray(name)->GetDataType())
      << name;
  }
  for (vtkIdType i = 0; i < tree->GetNumberOfPoints(); ++i)
  {
    ASSERT_EQ(PointKey(tree, i), PointKey(back, i));
  }
  EXPECT_NE(back->GetPointData()->GetNormals(), nullptr);
  EXPECT_NE(back->GetCellData()->GetArray("InputCellId"), nullptr);
}

TEST(vtkMergeTreeBuilder, RealMeshWhenAvailable)
{
  const std::string path = std::string(TIMECRITICAL_SHARED_DATA_DIR) + "/cow.obj";
  if (!std::ifstream(path).good())
  {
    GTEST_SKIP() << path << " not found";
  }
  vtkNew<vtkOBJReader> obj;
  obj->SetFileName(path.c_str());
  vtkNew<vtkMergeTreeBuilder> builder;
  builder->SetInputConnection(obj->GetOutputPort());
  builder->Update();
  vtkNew<vtkMergeTreeFieldData> reader;
  ASSERT_TRUE(reader->Read(builder->GetOutput())) << reader->GetErrorMessage();
  EXPECT_EQ(reader->GetTOMFieldData()->GetNumberOfTriangles(), 5804);
  EXPECT_GT(reader->GetLevelCount(), 5);
}

// ---------------------------------------------------------------------------
// vtkMergeTreeFieldData

TEST(vtkMergeTreeFieldData, WriteThenReadGivesTheSameTree)
{
  // A hand-made tree on a TOM: one level, one dependency per removed vertex.
  vtkNew<vtkTOMBuilder> tomBuilder;
  tomBuilder->SetInputData(MakeSphere(12));
  tomBuilder->Update();
  vtkNew<vtkTOMFieldData> tom;
  ASSERT_TRUE(tom->Read(tomBuilder->GetOutput())) << tom->GetErrorMessage();
  const timecritical::TOMMesh& mesh = tom->GetMesh();
  const uint32_t n = mesh.GetNumberOfVertices();
  timecritical::MergeTree tree;
  tree.LevelCount = 1;
  tree.DependencyOffsets.push_back(0);
  for (uint32_t v = 0; v < n; ++v)
  {
    const bool isBase = v < mesh.BaseVertexCount;
    tree.Level.push_back(isBase ? 1 : 0);
    tree.Error.push_back(0.25f * static_cast<float>(v));
    tree.Radius.push_back(0.5f);
    tree.ConeAxis.insert(tree.ConeAxis.end(), { 0.0f, 0.0f, 1.0f });
    tree.ConeCosine.push_back(isBase ? -1.0f : 0.5f);
    if (!isBase)
    {
      tree.Dependencies.push_back(mesh.Substitution[v]);
    }
    tree.DependencyOffsets.push_back(static_cast<uint32_t>(tree.Dependencies.size()));
  }
  ASSERT_EQ(vtkMergeTreeFieldData::Check(mesh, tree), "");
  vtkNew<vtkPolyData> data;
  data->DeepCopy(tomBuilder->GetOutput());
  vtkMergeTreeFieldData::Write(mesh, tree, data);
  vtkNew<vtkMergeTreeFieldData> reader;
  ASSERT_TRUE(reader->Read(data)) << reader->GetErrorMessage();
  EXPECT_EQ(reader->GetTree().Level, tree.Level);
  EXPECT_EQ(reader->GetTree().Error, tree.Error);
  EXPECT_EQ(reader->GetTree().ConeCosine, tree.ConeCosine);
  EXPECT_EQ(reader->GetTree().Dependencies, tree.Dependencies);
  EXPECT_EQ(reader->GetNumberOfDependencies(), static_cast<vtkIdType>(n - mesh.BaseVertexCount));
  EXPECT_STREQ(reader->GetErrorMessage(), "");
}

TEST(vtkMergeTreeFieldData, PlainDataAndPlainTOMAreNotMergeTrees)
{
  vtkNew<vtkMergeTreeFieldData> reader;
  EXPECT_FALSE(reader->Read(nullptr));
  EXPECT_FALSE(reader->Read(MakeSphere(8)));
  EXPECT_NE(std::string(reader->GetErrorMessage()).find("not a merge tree"), std::string::npos)
    << reader->GetErrorMessage();
  vtkNew<vtkTOMBuilder> tomBuilder;
  tomBuilder->SetInputData(MakeSphere(8));
  tomBuilder->Update();
  EXPECT_FALSE(vtkMergeTreeFieldData::HasMergeTreeArrays(tomBuilder->GetOutput()));
  EXPECT_FALSE(reader->Read(tomBuilder->GetOutput()));
  EXPECT_NE(std::string(reader->GetErrorMessage()).find("vtkMergeTreeBuilder"), std::string::npos);
  EXPECT_EQ(reader->GetNumberOfVertices(), 0);
}

namespace
{
struct Corruption
{
  const char* What;
  std::function<void(vtkPolyData*)> Apply;
  const char* Expected; // substring of the error message
};

vtkDataArray* PointArray(vtkPolyData* data, const char* name)
{
  return data->GetPointData()->GetArray(name);
}

vtkDataArray* FieldArray(vtkPolyData* data, const char* name)
{
  return data->GetFieldData()->GetArray(name);
}

// First vertex removed by a collapse that has at least one dependency.
vtkIdType VertexWithDependencies(vtkPolyData* data)
{
  vtkDataArray* offsets = FieldArray(data, "MergeTreeDependencyOffsets");
  for (vtkIdType v = 0; v + 1 < offsets->GetNumberOfTuples(); ++v)
  {
    if (offsets->GetTuple1(v + 1) > offsets->GetTuple1(v))
    {
      return v;
    }
  }
  return -1;
}

vtkIdType BaseCount(vtkPolyData* data)
{
  return static_cast<vtkIdType>(FieldArray(data, "TOMCounts")->GetTuple1(2));
}

template <typename ArrayT>
void ReplacePointArray(vtkPolyData* data, const char* name, int components, vtkIdType tuples)
{
  vtkNew<ArrayT> array;
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(tuples);
  array->Fill(0);
  data->GetPointData()->RemoveArray(name);
  data->GetPointData()->AddArray(array);
}

std::vector<Corruption> Corruptions()
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  return {
    { "missing error array",
      [](vtkPolyData* d) { d->GetPointData()->RemoveArray("MergeTreeError"); },
      "the point-data array MergeTreeError is missing" },
    { "missing dependencies",
      [](vtkPolyData* d) { d->GetFieldData()->RemoveArray("MergeTreeDependencies"); },
      "the field-data array MergeTreeDependencies is missing" },
    { "string level array",
      [](vtkPolyData* d) {
        vtkNew<vtkStringArray> s;
        s->SetName("MergeTreeLevel");
        s->SetNumberOfValues(d->GetNumberOfPoints());
        d->GetPointData()->RemoveArray("MergeTreeLevel");
        d->GetPointData()->AddArray(s);
      },
      "MergeTreeLevel is a vtkStringArray; it must be an integer array" },
    { "integer error array",
      [](vtkPolyData* d) {
        ReplacePointArray<vtkIntArray>(d, "MergeTreeError", 1, d->GetNumberOfPoints());
      },
      "MergeTreeError holds int values; it must be a floating-point array" },
    { "float level array",
      [](vtkPolyData* d) {
        ReplacePointArray<vtkFloatArray>(d, "MergeTreeLevel", 1, d->GetNumberOfPoints());
      },
      "MergeTreeLevel holds float values; it must be an integer array" },
    { "one-component cone axis",
      [](vtkPolyData* d) {
        ReplacePointArray<vtkFloatArray>(d, "MergeTreeConeAxis", 1, d->GetNumberOfPoints());
      },
      "MergeTreeConeAxis has 1 components; it must have 3" },
    { "short radius array",
      [](vtkPolyData* d) {
        ReplacePointArray<vtkFloatArray>(d, "MergeTreeRadius", 1, d->GetNumberOfPoints() - 1);
      },
      "MergeTreeRadius has " },
    { "short offsets",
      [](vtkPolyData* d) { FieldArray(d, "MergeTreeDependencyOffsets")->SetNumberOfTuples(3); },
      "MergeTreeDependencyOffsets has 3 tuples" },
    { "two level counts",
      [](vtkPolyData* d) { FieldArray(d, "MergeTreeLevelCount")->InsertNextTuple1(1); },
      "MergeTreeLevelCount has 2 tuples" },
    { "level beyond 16 bits",
      [](vtkPolyData* d) {
        vtkNew<vtkIntArray> level;
        level->DeepCopy(PointArray(d, "MergeTreeLevel"));
        level->SetValue(4, 70000);
        d->GetPointData()->RemoveArray("MergeTreeLevel");
        d->GetPointData()->AddArray(level);
      },
      "MergeTreeLevel entry 4 (70000) is outside [0, 65535]" },
    { "removed vertex at the top level",
      [](vtkPolyData* d) {
        const vtkIdType v = BaseCount(d) + 2;
        PointArray(d, "MergeTreeLevel")
          ->SetTuple1(v, FieldArray(d, "MergeTreeLevelCount")->GetTuple1(0));
      },
      "removed points must have a level below the level count" },
    { "base vertex below the top level",
      [](vtkPolyData* d) { PointArray(d, "MergeTreeLevel")->SetTuple1(0, 0); },
      "MergeTreeLevel of base point 0 is 0" },
    { "NaN error",
      [nan](vtkPolyData* d) { PointArray(d, "MergeTreeError")->SetTuple1(7, nan); },
      "MergeTreeError of point 7 (nan) is not a finite, non-negative distance" },
    { "negative error",
      [](vtkPolyData* d) { PointArray(d, "MergeTreeError")->SetTuple1(8, -1.0); },
      "MergeTreeError of point 8 (-1)" },
    { "infinite radius",
      [inf](vtkPolyData* d) { PointArray(d, "MergeTreeRadius")->SetTuple1(9, inf); },
      "MergeTreeRadius of point 9 (inf)" },
    { "negative radius",
      [](vtkPolyData* d) { PointArray(d, "MergeTreeRadius")->SetTuple1(9, -0.5); },
      "MergeTreeRadius of point 9 (-0.5)" },
    { "cosine above 1",
      [](vtkPolyData* d) { PointArray(d, "MergeTreeConeCosine")->SetTuple1(10, 1.5); },
      "MergeTreeConeCosine of point 10 (1.5) is not a cosine in [-1, 1]" },
    { "cosine below -1",
      [](vtkPolyData* d) { PointArray(d, "MergeTreeConeCosine")->SetTuple1(10, -2.0); },
      "MergeTreeConeCosine of point 10 (-2)" },
    { "NaN cosine",
      [nan](vtkPolyData* d) { PointArray(d, "MergeTreeConeCosine")->SetTuple1(11, nan); },
      "MergeTreeConeCosine of point 11 (nan)" },
    { "NaN cone axis",
      [nan](vtkPolyData* d) { PointArray(d, "MergeTreeConeAxis")->SetComponent(12, 1, nan); },
      "MergeTreeConeAxis of point 12" },
    { "non-unit cone axis",
      [](vtkPolyData* d) {
        PointArray(d, "MergeTreeConeCosine")->SetTuple1(13, 0.5);
        PointArray(d, "MergeTreeConeAxis")->SetTuple3(13, 2.0, 0.0, 0.0);
      },
      "MergeTreeConeAxis of point 13 has length 2" },
    { "offsets not starting at 0",
      [](vtkPolyData* d) { FieldArray(d, "MergeTreeDependencyOffsets")->SetTuple1(0, 1); },
      "MergeTreeDependencyOffsets must start at 0" },
    { "offsets decreasing",
      [](vtkPolyData* d) {
        vtkDataArray* offsets = FieldArray(d, "MergeTreeDependencyOffsets");
        const vtkIdType last = offsets->GetNumberOfTuples() - 1;
        offsets->SetTuple1(last - 1, offsets->GetTuple1(last) + 5);
      },
      "decreases at entry" },
    { "negative offset",
      [](vtkPolyData* d) {
        vtkNew<vtkIntArray> offsets;
        offsets->DeepCopy(FieldArray(d, "MergeTreeDependencyOffsets"));
        offsets->SetValue(2, -3);
        d->GetFieldData()->RemoveArray("MergeTreeDependencyOffsets");
        d->GetFieldData()->AddArray(offsets);
      },
      "MergeTreeDependencyOffsets entry 2 (-3) is outside [0, 4294967295]" },
    { "offsets past the dependencies",
      [](vtkPolyData* d) {
        vtkDataArray* deps = FieldArray(d, "MergeTreeDependencies");
        deps->SetNumberOfTuples(deps->GetNumberOfTuples() - 1);
      },
      "but MergeTreeDependencies holds" },
    { "dependency out of range",
      [](vtkPolyData* d) {
        const vtkIdType v = VertexWithDependencies(d);
        const auto k =
          static_cast<vtkIdType>(FieldArray(d, "MergeTreeDependencyOffsets")->GetTuple1(v));
        FieldArray(d, "MergeTreeDependencies")->SetTuple1(k, d->GetNumberOfPoints() + 10);
      },
      "must be point ids below" },
    { "dependency on a later vertex",
      [](vtkPolyData* d) {
        const vtkIdType v = VertexWithDependencies(d);
        const auto k =
          static_cast<vtkIdType>(FieldArray(d, "MergeTreeDependencyOffsets")->GetTuple1(v));
        FieldArray(d, "MergeTreeDependencies")->SetTuple1(k, v);
      },
      "must be point ids below" },
    { "dependency rows on a base vertex",
      [](vtkPolyData* d) {
        // Shift one dependency row onto base vertex 0.
        vtkDataArray* offsets = FieldArray(d, "MergeTreeDependencyOffsets");
        const vtkIdType base = BaseCount(d);
        for (vtkIdType v = 1; v <= base; ++v)
        {
          offsets->SetTuple1(v, 1);
        }
      },
      "base point 0 has 1 dependencies" },
    { "broken TOM underneath",
      [](vtkPolyData* d) {
        PointArray(d, "TOMSubstitution")->SetTuple1(d->GetNumberOfPoints() - 1, 1e6);
      },
      "the merge tree's TOM is invalid" },
    { "missing TOM",
      [](vtkPolyData* d) { d->GetPointData()->RemoveArray("TOMSubstitution"); },
      "the merge tree's TOM is invalid: not a Totally Ordered Mesh" },
  };
}
}

TEST(vtkMergeTreeFieldData, EachCorruptionGivesAPreciseError)
{
  vtkPolyData* tree = SphereTree();
  {
    vtkNew<vtkMergeTreeFieldData> reader;
    ASSERT_TRUE(reader->Read(tree)) << reader->GetErrorMessage();
    ASSERT_GE(VertexWithDependencies(tree), BaseCount(tree));
  }
  for (const Corruption& corruption : Corruptions())
  {
    SCOPED_TRACE(corruption.What);
    auto data = Copy(tree);
    corruption.Apply(data);
    vtkNew<vtkMergeTreeFieldData> reader;
    EXPECT_FALSE(reader->Read(data));
    const std::string message = reader->GetErrorMessage();
    EXPECT_NE(message.find(corruption.Expected), std::string::npos)
      << "message: " << message << "\nexpected to contain: " << corruption.Expected;
    EXPECT_EQ(reader->GetNumberOfVertices(), 0);
    EXPECT_EQ(reader->GetLevelCount(), 0);

    // Filters reading merge trees report the same problem and give an empty output.
    vtkNew<vtkExtractViewDependentMesh> extract;
    MessageLog log(extract);
    vtkNew<vtkCamera> camera;
    extract->SetCamera(camera);
    extract->SetInputData(data);
    extract->Update();
    EXPECT_TRUE(log.ErrorContains(corruption.Expected)) << log.AllErrors();
    EXPECT_EQ(extract->GetOutput()->GetNumberOfCells(), 0);
  }
}

// ---------------------------------------------------------------------------
// vtkExtractViewDependentMesh

namespace
{
struct Topology
{
  vtkIdType Vertices = 0;
  vtkIdType Edges = 0;
  vtkIdType Faces = 0;
  bool ClosedManifold = true; // every edge in exactly two triangles, once in each direction
  bool AllPointsUsed = true;
  vtkIdType Euler() const { return this->Vertices - this->Edges + this->Faces; }
};

Topology Analyze(vtkPolyData* mesh)
{
  Topology topology;
  topology.Vertices = mesh->GetNumberOfPoints();
  topology.Faces = mesh->GetNumberOfPolys();
  std::map<std::pair<vtkIdType, vtkIdType>, int> directed;
  std::vector<bool> used(mesh->GetNumberOfPoints(), false);
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    vtkIdType size;
    const vtkIdType* ids;
    mesh->GetCellPoints(c, size, ids);
    if (size != 3)
    {
      topology.ClosedManifold = false;
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      used[ids[k]] = true;
      ++directed[{ ids[k], ids[(k + 1) % 3] }];
    }
  }
  std::set<std::pair<vtkIdType, vtkIdType>> undirected;
  for (const auto& entry : directed)
  {
    const auto& edge = entry.first;
    undirected.insert({ std::min(edge.first, edge.second), std::max(edge.first, edge.second) });
    const auto reverse = directed.find({ edge.second, edge.first });
    if (entry.second != 1 || reverse == directed.end() || reverse->second != 1)
    {
      topology.ClosedManifold = false;
    }
  }
  topology.Edges = static_cast<vtkIdType>(undirected.size());
  topology.AllPointsUsed = std::all_of(used.begin(), used.end(), [](bool u) { return u; });
  return topology;
}

void LookAt(vtkCamera* camera, double x, double y, double z)
{
  camera->SetFocalPoint(0, 0, 0);
  camera->SetPosition(x, y, z);
  camera->SetViewUp(0, 1, 0);
  if (std::abs(x) < 1e-9 && std::abs(z) < 1e-9)
  {
    camera->SetViewUp(0, 0, 1);
  }
}

vtkIdType Triangles(vtkExtractViewDependentMesh* extract)
{
  extract->Update();
  return extract->GetOutput()->GetNumberOfPolys();
}

// The sphere tree's coarsest and full triangle counts.
std::pair<vtkIdType, vtkIdType> SphereTriangleRange()
{
  vtkNew<vtkTOMFieldData> tom;
  EXPECT_TRUE(tom->Read(SphereTree()));
  return { tom->GetBaseTriangleCount(), tom->GetNumberOfTriangles() };
}
}

TEST(vtkExtractViewDependentMesh, FrontOfAClosedSurfaceIsAClosedManifold)
{
  vtkNew<vtkExtractViewDependentMesh> extract;
  MessageLog log(extract);
  extract->SetInputData(SphereTree());
  vtkNew<vtkCamera> camera;
  extract->SetCamera(camera);
  const std::array<std::array<double, 3>, 4> eyes = { { { 0, 0, 3 }, { 2, 1, 0.5 },
    { 0.2, -0.3, 0.9 }, { 0, 5, 0 } } };
  std::set<vtkIdType> counts;
  for (const auto& eye : eyes)
  {
    for (double tau : { 0.5, 2.0, 8.0 })
    {
      for (bool budget : { false, true })
      {
        SCOPED_TRACE("eye " + std::to_string(eye[0]) + " " + std::to_string(eye[1]) + " " +
          std::to_string(eye[2]) + ", tau " + std::to_string(tau) +
          (budget ? ", budget" : ", fixed accuracy"));
        LookAt(camera, eye[0], eye[1], eye[2]);
        extract->SetPixelThreshold(tau);
        extract->SetSilhouetteRefinement(tau > 1.0);
        extract->SetRefinementMode(budget ? vtkExtractViewDependentMesh::TRIANGLE_BUDGET
                                          : vtkExtractViewDependentMesh::FIXED_ACCURACY);
        extract->SetTriangleBudget(static_cast<vtkIdType>(2000 / tau));
        extract->Update();
        vtkPolyData* front = extract->GetOutput();
        const Topology topology = Analyze(front);
        EXPECT_TRUE(topology.ClosedManifold);
        EXPECT_TRUE(topology.AllPointsUsed);
        EXPECT_EQ(topology.Euler(), 2) << "V " << topology.Vertices << " E " << topology.Edges
                                       << " F " << topology.Faces;
        EXPECT_EQ(front->GetNumberOfPolys(), extract->GetNumberOfDisplayTriangles());
        EXPECT_EQ(front->GetNumberOfPoints(), extract->GetNumberOfDisplayVertices());
        counts.insert(front->GetNumberOfPolys());
      }
    }
  }
  EXPECT_TRUE(log.Errors.empty()) << log.AllErrors();
  EXPECT_GT(counts.size(), 4u) << "the fronts should differ with the view and the threshold";
}

TEST(vtkExtractViewDependentMesh, TriangleCountDecreasesWithThreshold)
{
  const auto range = SphereTriangleRange();
  vtkNew<vtkExtractViewDependentMesh> extract;
  extract->SetInputData(SphereTree());
  LookAt(extract->GetCamera(), 0, 0, 3);
  extract->BackFaceSimplificationOff();
  extract->FrustumCullingOff();
  extract->SetPixelThreshold(0.0);
  EXPECT_EQ(Triangles(extract), range.second) << "tau = 0 without culling is the full mesh";
  vtkIdType previous = range.second;
  std::vector<vtkIdType> counts;
  for (double tau : { 0.05, 0.25, 0.5, 1.0, 2.0, 4.0, 8.0, 16.0, 64.0, 1e6 })
  {
    extract->SetPixelThreshold(tau);
    const vtkIdType count = Triangles(extract);
    EXPECT_LE(count, previous) << "tau " << tau;
    previous = count;
    counts.push_back(count);
  }
  EXPECT_LT(counts[5], range.second / 2) << "4 pixels should simplify a 40x40 sphere a lot";
  EXPECT_EQ(counts.back(), range.first) << "an enormous threshold gives the coarsest mesh";
  // Going back to a small threshold refines again: the front follows the view, not its history.
  extract->SetPixelThreshold(0.5);
  EXPECT_EQ(Triangles(extract), counts[2]);
}

TEST(vtkExtractViewDependentMesh, MovingTheCameraReExecutes)
{
  vtkNew<vtkExtractViewDependentMesh> extract;
  extract->SetInputData(SphereTree());
  vtkNew<vtkCamera> camera;
  LookAt(camera, 0, 0, 40);
  extract->SetCamera(camera);
  extract->SetPixelThreshold(1.0);
  int executions = 0;
  vtkNew<vtkCallbackCommand> count;
  count->SetClientData(&executions);
  count->SetCallback(
    [](vtkObject*, unsigned long, void* client, void*) { ++*static_cast<int*>(client); });
  extract->AddObserver(vtkCommand::EndEvent, count);
  const vtkIdType far = Triangles(extract);
  EXPECT_EQ(executions, 1);
  extract->Update();
  EXPECT_EQ(executions, 1) << "nothing changed: no new execution";
  camera->SetPosition(0, 0, 2); // through the camera object, not the filter
  const vtkIdType near = Triangles(extract);
  EXPECT_EQ(executions, 2);
  EXPECT_GT(near, far) << "closer means more detail";
  extract->SetCameraPosition(0, 0, 40); // through the filter's proxy setter
  EXPECT_EQ(camera->GetPosition()[2], 40.0);
  EXPECT_EQ(Triangles(extract), far);
  EXPECT_EQ(executions, 3);
  EXPECT_GE(extract->GetNumberOfMerges(), 1);
}

TEST(vtkExtractViewDependentMesh, BackFacesAndOutsideTheFrustumStayCoarse)
{
  vtkNew<vtkExtractViewDependentMesh> extract;
  extract->SetInputData(SphereTree());
  LookAt(extract->GetCamera(), 0, 0, 3);
  extract->SetPixelThreshold(0.5);
  extract->BackFaceSimplificationOff();
  extract->FrustumCullingOff();
  const vtkIdType all = Triangles(extract);
  extract->BackFaceSimplificationOn();
  const vtkIdType front = Triangles(extract);
  EXPECT_LT(front, all);
  // Triangles facing away from the eye are larger on average.
  vtkPolyData* mesh = extract->GetOutput();
  double area[2] = { 0, 0 };
  int number[2] = { 0, 0 };
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    const vtkIdType* ids;
    vtkIdType size;
    mesh->GetCellPoints(c, size, ids);
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      mesh->GetPoint(ids[k], p[k]);
    }
    const double u[3] = { p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2] };
    const double v[3] = { p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2] };
    const double n[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
      u[0] * v[1] - u[1] * v[0] };
    const double centroidZ = (p[0][2] + p[1][2] + p[2][2]) / 3.0;
    const int back = centroidZ < -0.1 ? 1 : 0;
    if (centroidZ > 0.1 || back)
    {
      area[back] += 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      ++number[back];
    }
  }
  ASSERT_GT(number[0], 0);
  ASSERT_GT(number[1], 0);
  EXPECT_GT(area[1] / number[1], 2.0 * area[0] / number[0]);
  EXPECT_GT(number[0], number[1]);

  // Looking away from the sphere, far enough for its nodes' bounding spheres
  // to lie behind the frustum's side planes: nothing is refined.
  extract->FrustumCullingOn();
  extract->BackFaceSimplificationOff();
  LookAt(extract->GetCamera(), 0, 0, 30);
  extract->GetCamera()->SetFocalPoint(0, 0, 60);
  EXPECT_EQ(Triangles(extract), SphereTriangleRange().first);
}

namespace
{
// Triangles of `mesh` whose centroid lies within `degrees` of `direction` as
// seen from the origin (the sphere's centre).
int TrianglesAround(vtkPolyData* mesh, const double direction[3], double degrees)
{
  const double length = std::sqrt(
    direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
  int count = 0;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    const vtkIdType* ids;
    vtkIdType size;
    mesh->GetCellPoints(c, size, ids);
    double centroid[3] = { 0, 0, 0 };
    for (int k = 0; k < 3; ++k)
    {
      double p[3];
      mesh->GetPoint(ids[k], p);
      for (int i = 0; i < 3; ++i)
      {
        centroid[i] += p[i] / 3.0;
      }
    }
    const double norm =
      std::sqrt(centroid[0] * centroid[0] + centroid[1] * centroid[1] + centroid[2] * centroid[2]);
    const double cosine =
      (centroid[0] * direction[0] + centroid[1] * direction[1] + centroid[2] * direction[2]) /
      (norm * length);
    count += cosine >= std::cos(degrees * 3.14159265358979 / 180.0) ? 1 : 0;
  }
  return count;
}
}

TEST(vtkExtractViewDependentMesh, SilhouetteAndHighlightRefinementAddDetail)
{
  vtkNew<vtkExtractViewDependentMesh> extract;
  extract->SetInputData(SphereTree());
  LookAt(extract->GetCamera(), 0, 0, 3);
  extract->SetPixelThreshold(4.0);
  // Both on by default, as in the mapper and the renderer.
  EXPECT_TRUE(extract->GetSilhouetteRefinement());
  EXPECT_TRUE(extract->GetHighlightRefinement());
  EXPECT_EQ(extract->GetHighlightFactor(), 0.5);
  extract->SilhouetteRefinementOff();
  extract->HighlightRefinementOff();
  const vtkIdType plain = Triangles(extract);
  const double towardsEye[3] = { 0, 0, 1 };
  const int plainAtCentre = TrianglesAround(extract->GetOutput(), towardsEye, 20.0);
  extract->SilhouetteRefinementOn();
  extract->SetSilhouetteFactor(0.1);
  const vtkIdType silhouette = Triangles(extract);
  EXPECT_GT(silhouette, plain);
  extract->SilhouetteRefinementOff();

  // Light at the eye: the highlight is at the centre of the view.
  extract->HighlightRefinementOn();
  extract->SetHighlightFactor(0.1);
  extract->SetLightDirection(0, 0, 1);
  const vtkIdType highlight = Triangles(extract);
  EXPECT_GT(highlight, plain);
  const int highlightAtCentre = TrianglesAround(extract->GetOutput(), towardsEye, 20.0);
  EXPECT_GT(highlightAtCentre, plainAtCentre);
  // Light from +x: the highlight moves halfway between light and eye.
  extract->SetLightDirection(1, 0, 0);
  extract->Update();
  const double halfway[3] = { 1, 0, 1 };
  const double opposite[3] = { -1, 0, 1 };
  EXPECT_GT(TrianglesAround(extract->GetOutput(), halfway, 20.0),
    2 * TrianglesAround(extract->GetOutput(), opposite, 20.0));
}

TEST(vtkExtractViewDependentMesh, TriangleBudget)
{
  const auto range = SphereTriangleRange();
  vtkNew<vtkExtractViewDependentMesh> extract;
  extract->SetInputData(SphereTree());
  LookAt(extract->GetCamera(), 1, 2, 3);
  extract->SetRefinementModeToTriangleBudget();
  // The threshold is a floor in budget mode: at 0 only the budget limits the front.
  extract->SetPixelThreshold(0.0);
  vtkIdType previous = 0;
  for (vtkIdType budget : { vtkIdType(0), vtkIdType(100), vtkIdType(400), vtkIdType(1000),
         vtkIdType(2000) })
  {
    extract->SetTriangleBudget(budget);
    const vtkIdType count = Triangles(extract);
    EXPECT_LE(count, std::max(budget, range.first) + 16) << "budget " << budget;
    EXPECT_GE(count, previous);
    if (budget >= 100)
    {
      EXPECT_GT(count, budget * 3 / 4) << "budget " << budget;
    }
    previous = count;
  }
  EXPECT_EQ(extract->GetRefinementMode(), vtkExtractViewDependentMesh::TRIANGLE_BUDGET);
}

TEST(vtkExtractViewDependentMesh, PointAndCellDataOfTheFront)
{
  vtkPolyData* tree = SphereTree();
  vtkNew<vtkMergeTreeFieldData> reader;
  ASSERT_TRUE(reader->Read(tree));
  vtkNew<vtkExtractViewDependentMesh> extract;
  extract->SetInputData(tree);
  LookAt(extract->GetCamera(), 0, 1, 2);
  extract->SetPixelThreshold(3.0);
  extract->GenerateLocalLevelsOn();
  extract->Update();
  vtkPolyData* front = extract->GetOutput();
  ASSERT_GT(front->GetNumberOfPolys(), 0);
  std::map<Key, vtkIdType> treeIds;
  for (vtkIdType i = 0; i < tree->GetNumberOfPoints(); ++i)
  {
    treeIds[PointKey(tree, i)] = i;
  }
  vtkDataArray* normals = front->GetPointData()->GetNormals();
  ASSERT_NE(normals, nullptr);
  for (vtkIdType i = 0; i < front->GetNumberOfPoints(); ++i)
  {
    const auto found = treeIds.find(PointKey(front, i));
    ASSERT_NE(found, treeIds.end()) << "output points are input points";
    for (int c = 0; c < 3; ++c)
    {
      ASSERT_EQ(normals->GetComponent(i, c),
        tree->GetPointData()->GetNormals()->GetComponent(found->second, c));
    }
  }
  // Each triangle carries the cell data of a TOM triangle it comes from: one
  // whose corners are the triangle's corners or merged into them.
  vtkDataArray* cellIds = front->GetCellData()->GetArray("InputCellId");
  ASSERT_NE(cellIds, nullptr);
  std::set<double> distinct;
  for (vtkIdType c = 0; c < front->GetNumberOfCells(); ++c)
  {
    distinct.insert(cellIds->GetTuple1(c));
  }
  EXPECT_EQ(static_cast<vtkIdType>(distinct.size()), front->GetNumberOfCells());
  // TOM and merge-tree arrays do not describe the front.
  for (const char* name : { "TOMSubstitution", "MergeTreeLevel", "MergeTreeError",
         "MergeTreeRadius", "MergeTreeConeAxis", "MergeTreeConeCosine" })
  {
    EXPECT_EQ(front->GetPointData()->GetAbstractArray(name), nullptr) << name;
  }
  for (const char* name : { "TOMCounts", "TOMErrorCurve", "MergeTreeDependencyOffsets",
         "MergeTreeDependencies", "MergeTreeLevelCount" })
  {
    EXPECT_EQ(front->GetFieldData()->GetAbstractArray(name), nullptr) << name;
  }
  // Local levels: within [0, LevelCount], coarser on the back.
  auto* levels = vtkTypeUInt16Array::SafeDownCast(
    front->GetCellData()->GetArray(vtkExtractViewDependentMesh::LocalLevelArrayName()));
  ASSERT_NE(levels, nullptr);
  int maximum = 0;
  for (vtkIdType c = 0; c < levels->GetNumberOfValues(); ++c)
  {
    maximum = std::max<int>(maximum, levels->GetValue(c));
  }
  EXPECT_GT(maximum, 0);
  EXPECT_LE(maximum, reader->GetLevelCount());

  // At full resolution every local level is 0.
  extract->BackFaceSimplificationOff();
  extract->FrustumCullingOff();
  extract->SetPixelThreshold(0.0);
  extract->Update();
  levels = vtkTypeUInt16Array::SafeDownCast(
    extract->GetOutput()->GetCellData()->GetArray(vtkExtractViewDependentMesh::LocalLevelArrayName()));
  ASSERT_NE(levels, nullptr);
  EXPECT_EQ(levels->GetValueRange()[1], 0);
  EXPECT_EQ(extract->GetOutput()->GetNumberOfPoints(), tree->GetNumberOfPoints());
}

TEST(vtkExtractViewDependentMesh, ParallelProjectionAndViewport)
{
  vtkNew<vtkExtractViewDependentMesh> extract;
  extract->SetInputData(SphereTree());
  extract->SetCameraPosition(0, 0, 5);
  extract->SetCameraFocalPoint(0, 0, 0);
  extract->SetCameraViewUp(0, 1, 0);
  extract->SetCameraParallelProjection(true);
  extract->SetCameraParallelScale(0.6);
  extract->SetPixelThreshold(2.0);
  const vtkIdType small = Triangles(extract);
  extract->SetViewportSize(2048, 2048);
  const vtkIdType large = Triangles(extract);
  EXPECT_GT(large, small) << "more pixels, more detail";
  extract->SetCameraParallelScale(6.0);
  EXPECT_LT(Triangles(extract), large) << "zoomed out, less detail";
  EXPECT_TRUE(extract->GetCamera()->GetParallelProjection());
}

TEST(vtkExtractViewDependentMesh, BadSettingsAreRejected)
{
  vtkNew<vtkExtractViewDependentMesh> extract;
  MessageLog log(extract);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const vtkMTimeType before = extract->GetMTime();
  extract->SetPixelThreshold(nan);
  extract->SetSilhouetteFactor(nan);
  extract->SetHighlightFactor(nan);
  extract->SetLightDirection(nan, 0, 1);
  extract->SetLightDirection(0, 0, 0);
  extract->SetViewportSize(0, 100);
  extract->SetCameraPosition(nan, 0, 0);
  extract->SetCameraFocalPoint(0, nan, 0);
  extract->SetCameraViewUp(0, 0, 0);
  extract->SetCameraViewAngle(nan);
  extract->SetCameraViewAngle(200);
  extract->SetCameraParallelScale(-1);
  EXPECT_EQ(log.Errors.size(), 12u);
  EXPECT_TRUE(log.ErrorContains("PixelThreshold must be a number"));
  EXPECT_TRUE(log.ErrorContains("LightDirection must be a finite, non-zero vector"));
  EXPECT_TRUE(log.ErrorContains("ViewportSize must be at least 1 x 1"));
  EXPECT_EQ(extract->GetMTime(), before);
  EXPECT_EQ(extract->GetPixelThreshold(), 1.0);
  EXPECT_EQ(extract->GetViewportSize()[0], 512);
  EXPECT_EQ(extract->GetLightDirection()[2], 1.0);
  extract->SetPixelThreshold(-3.0);
  EXPECT_EQ(extract->GetPixelThreshold(), 0.0);
  extract->SetSilhouetteFactor(0.0);
  EXPECT_EQ(extract->GetSilhouetteFactor(), 0.01);
  extract->SetRefinementMode(7);
  EXPECT_EQ(extract->GetRefinementMode(), vtkExtractViewDependentMesh::TRIANGLE_BUDGET);
  // The own camera comes back after SetCamera(nullptr).
  extract->SetCamera(nullptr);
  EXPECT_NE(extract->GetCamera(), nullptr);
}

TEST(vtkExtractViewDependentMesh, EmptyAndForeignInput)
{
  vtkNew<vtkExtractViewDependentMesh> extract;
  MessageLog log(extract);
  vtkNew<vtkPolyData> empty;
  extract->SetInputData(empty);
  extract->Update();
  EXPECT_TRUE(log.Errors.empty()) << log.AllErrors();
  EXPECT_EQ(extract->GetOutput()->GetNumberOfPoints(), 0);

  extract->SetInputData(MakeSphere(8));
  extract->Update();
  EXPECT_TRUE(log.ErrorContains("Input is not a valid merge tree: not a merge tree"))
    << log.AllErrors();
  EXPECT_EQ(extract->GetOutput()->GetNumberOfPoints(), 0);

  // Merge-tree arrays on no points at all: an empty tree, whether valid or not, is no crash.
  vtkNew<vtkPolyData> emptyTree;
  vtkMergeTreeFieldData::Write(timecritical::TOMMesh(), timecritical::MergeTree(), emptyTree);
  extract->SetInputData(emptyTree);
  extract->Update();
  EXPECT_EQ(extract->GetOutput()->GetNumberOfPoints(), 0);

  // A valid tree afterwards works again.
  log.Errors.clear();
  extract->SetInputData(SphereTree());
  extract->Update();
  EXPECT_TRUE(log.Errors.empty()) << log.AllErrors();
  EXPECT_GT(extract->GetOutput()->GetNumberOfPolys(), 0);
}

TEST(vtkExtractViewDependentMesh, RealMeshWhenAvailable)
{
  const std::string cow = std::string(TIMECRITICAL_SHARED_DATA_DIR) + "/cow.obj";
  if (!std::ifstream(cow).good())
  {
    GTEST_SKIP() << cow << " not found";
  }
  vtkNew<vtkOBJReader> obj;
  obj->SetFileName(cow.c_str());
  vtkNew<vtkMergeTreeBuilder> builder;
  builder->SetInputConnection(obj->GetOutputPort());
  vtkNew<vtkExtractViewDependentMesh> extract;
  extract->SetInputConnection(builder->GetOutputPort());
  builder->Update();
  double bounds[6];
  builder->GetOutput()->GetBounds(bounds);
  const double center[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  const double size = bounds[1] - bounds[0] + bounds[3] - bounds[2] + bounds[5] - bounds[4];
  extract->SetCameraFocalPoint(center[0], center[1], center[2]);
  extract->SetCameraPosition(center[0], center[1], center[2] + 2 * size);
  extract->SetPixelThreshold(1.0);
  const Topology full = Analyze(builder->GetOutput());
  extract->Update();
  const Topology front = Analyze(extract->GetOutput());
  EXPECT_EQ(front.Euler(), full.Euler());
  EXPECT_EQ(front.ClosedManifold, full.ClosedManifold);
  EXPECT_LT(front.Faces, full.Faces);
  EXPECT_GT(front.Faces, 0);
}

TEST(MergeTreeClasses, PrintSelfReportsSettingsAndState)
{
  vtkNew<vtkMergeTreeBuilder> builder;
  vtkNew<vtkMergeTreeFieldData> reader;
  vtkNew<vtkExtractViewDependentMesh> extract;
  ASSERT_TRUE(reader->Read(SphereTree()));
  std::ostringstream text;
  builder->Print(text);
  reader->Print(text);
  extract->Print(text);
  for (const char* expected : { "MinimumTriangleQuality: 0", "LockFeatureEdges: 0",
         "FeatureWeight: 10", "LevelCount: ", "Valid: 1",
         "PixelThreshold: 1", "RefinementMode: FIXED_ACCURACY", "ViewportSize: 512 x 512" })
  {
    EXPECT_NE(text.str().find(expected), std::string::npos) << expected;
  }
}
