// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkMultiresolutionHierarchyBuilder: builds, reuse, pass-through, messages.
#include "FilterTestSupport.h"
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

#include <gtest/gtest.h>

#include <cmath>
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

TEST(MultiresolutionHierarchyBuilder, BuildsATOMForPolyData)
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

TEST(MultiresolutionHierarchyBuilder, ReusesBuildsOfUnchangedContent)
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

TEST(MultiresolutionHierarchyBuilder, KeepsCompositeStructureAndPassesOtherLeaves)
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

TEST(MultiresolutionHierarchyBuilder, RejectedLeafPassesWithAMessageNamingIt)
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

TEST(MultiresolutionHierarchyBuilder, ProgressRisesToOne)
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
} // namespace
