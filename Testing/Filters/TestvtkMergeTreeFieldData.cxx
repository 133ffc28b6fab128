// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkMergeTreeFieldData.
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

TEST(vtkMergeTreeFieldData, PrintSelfReportsState)
{
  vtkNew<vtkMergeTreeFieldData> reader;
  ASSERT_TRUE(reader->Read(SphereTree()));
  std::ostringstream text;
  reader->Print(text);
  for (const char* expected : { "LevelCount: ", "Valid: 1" })
  {
    EXPECT_NE(text.str().find(expected), std::string::npos) << expected;
  }
}
