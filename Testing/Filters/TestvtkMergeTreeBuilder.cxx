// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkMergeTreeBuilder.
#include "FilterTestSupport.h"
#include "MergeTreeFilterTestSupport.h"
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
using tt::BuildTree;
using tt::Copy;
using tt::LinesOnly;
using tt::MakeSphere;
using tt::MessageLog;
using tt::PointKey;
using tt::SphereTree;
using Key = tt::PointKeyType;
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
  EXPECT_EQ(log.Warnings.size(), 1u); // the line; the zero-area triangle is silent
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
  // The feature-edge settings (forwarding: TestvtkCollapseHierarchyBuilder's FeatureEdgeSettingsReachTheCore).
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

TEST(vtkMergeTreeBuilder, PrintSelfReportsSettings)
{
  vtkNew<vtkMergeTreeBuilder> builder;
  std::ostringstream text;
  builder->Print(text);
  for (const char* expected : { "MinimumTriangleQuality: 0", "LockFeatureEdges: 0",
         "FeatureWeight: 10" })
  {
    EXPECT_NE(text.str().find(expected), std::string::npos) << expected;
  }
}
