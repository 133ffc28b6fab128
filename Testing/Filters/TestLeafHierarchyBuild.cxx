// SPDX-License-Identifier: BSD-3-Clause
// The per-thread copy of a leaf (CopyForAnotherThread) and the one-leaf build.
#include "FilterTestSupport.h"
#include "LeafHierarchyBuild.h"

#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"
#include "vtkTOMFieldData.h"

#include <gtest/gtest.h>

namespace
{
namespace tt = timecritical::testing;

vtkSmartPointer<vtkFloatArray> Values(const char* name, vtkIdType count)
{
  auto array = vtkSmartPointer<vtkFloatArray>::New();
  if (name)
  {
    array->SetName(name);
  }
  array->SetNumberOfTuples(count);
  for (vtkIdType i = 0; i < count; ++i)
  {
    array->SetValue(i, static_cast<float>(i));
  }
  return array;
}
} // namespace

TEST(LeafHierarchyBuild, CopyForAnotherThreadHasObjectsOfItsOwnAroundTheSameValues)
{
  auto leaf = tt::MakeSphere(12);
  leaf->GetPointData()->SetScalars(Values("height", leaf->GetNumberOfPoints()));
  vtkNew<vtkStringArray> label;
  label->SetName("label");
  label->InsertNextValue("leaf");
  leaf->GetFieldData()->AddArray(label);

  auto copy = timecritical::CopyForAnotherThread(leaf);
  ASSERT_NE(copy, nullptr);
  EXPECT_NE(copy->GetPoints(), leaf->GetPoints());
  EXPECT_NE(copy->GetPoints()->GetData(), leaf->GetPoints()->GetData());
  EXPECT_EQ(copy->GetPoints()->GetData()->GetVoidPointer(0),
    leaf->GetPoints()->GetData()->GetVoidPointer(0)); // values shared, not copied
  EXPECT_NE(copy->GetPolys(), leaf->GetPolys());
  EXPECT_EQ(copy->GetPolys()->GetConnectivityArray(), leaf->GetPolys()->GetConnectivityArray());
  EXPECT_EQ(copy->GetNumberOfPolys(), leaf->GetNumberOfPolys());
  // Arrays of their own, still the active scalars and normals.
  ASSERT_NE(copy->GetPointData()->GetScalars(), nullptr);
  EXPECT_NE(copy->GetPointData()->GetScalars(), leaf->GetPointData()->GetScalars());
  EXPECT_STREQ(copy->GetPointData()->GetScalars()->GetName(), "height");
  EXPECT_EQ(copy->GetPointData()->GetScalars()->GetVoidPointer(0),
    leaf->GetPointData()->GetScalars()->GetVoidPointer(0));
  ASSERT_NE(leaf->GetPointData()->GetNormals(), nullptr);
  ASSERT_NE(copy->GetPointData()->GetNormals(), nullptr);
  EXPECT_STREQ(copy->GetPointData()->GetNormals()->GetName(),
    leaf->GetPointData()->GetNormals()->GetName());
  auto* copiedLabel = vtkStringArray::SafeDownCast(copy->GetFieldData()->GetAbstractArray("label"));
  ASSERT_NE(copiedLabel, nullptr);
  EXPECT_NE(copiedLabel, label.GetPointer());
  EXPECT_EQ(copiedLabel->GetValue(0), "leaf");
}

TEST(LeafHierarchyBuild, CopyForAnotherThreadKeepsArraysThatNamesCannotTellApart)
{
  auto leaf = tt::MakeSphere(12);
  const int before = leaf->GetPointData()->GetNumberOfArrays();
  leaf->GetPointData()->AddArray(Values(nullptr, leaf->GetNumberOfPoints()));
  leaf->GetPointData()->AddArray(Values(nullptr, leaf->GetNumberOfPoints()));
  ASSERT_EQ(leaf->GetPointData()->GetNumberOfArrays(), before + 2);

  auto copy = timecritical::CopyForAnotherThread(leaf);
  ASSERT_EQ(copy->GetPointData()->GetNumberOfArrays(), before + 2);
  for (int i = 0; i < before + 2; ++i)
  {
    EXPECT_EQ(copy->GetPointData()->GetAbstractArray(i), leaf->GetPointData()->GetAbstractArray(i));
  }
}

TEST(LeafHierarchyBuild, BuildsFromTheCopyAndLeavesTheLeafAlone)
{
  auto leaf = tt::MakeSphere(16);
  const vtkMTimeType polysTime = leaf->GetPolys()->GetMTime();
  const vtkMTimeType pointsTime = leaf->GetPoints()->GetMTime();
  auto result =
    timecritical::BuildLeafHierarchy(leaf, timecritical::LeafHierarchy::TotallyOrderedMesh);
  ASSERT_NE(result.Hierarchy, nullptr);
  EXPECT_TRUE(vtkTOMFieldData::HasTOMArrays(result.Hierarchy));
  EXPECT_FALSE(vtkTOMFieldData::HasTOMArrays(leaf));
  EXPECT_EQ(leaf->GetPolys()->GetMTime(), polysTime);
  EXPECT_EQ(leaf->GetPoints()->GetMTime(), pointsTime);
  EXPECT_TRUE(result.Messages.empty());
}

TEST(LeafHierarchyBuild, NoLeafGivesAnErrorMessage)
{
  auto result = timecritical::BuildLeafHierarchy(nullptr, timecritical::LeafHierarchy::MergeTree);
  EXPECT_EQ(result.Hierarchy, nullptr);
  ASSERT_EQ(result.Messages.size(), 1u);
  EXPECT_TRUE(result.Messages[0].IsError);
}
