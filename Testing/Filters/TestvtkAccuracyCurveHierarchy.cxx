// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkAccuracyCurveHierarchy: a scene of TOMs, a group, an LOD node
// (a TOM and a fixed coarse mesh with a stored single-point curve), an empty
// block and a plain mesh, composed in relative and absolute accuracy and
// checked pointwise against the paper's rules from the leaves' own curves;
// the LOD-node marking through .vtm and .vtpc files; and every error.
#include "AccuracyCurve.h"
#include "FilterTestSupport.h"
#include "vtkAccuracyCurveFieldData.h"
#include "vtkAccuracyCurveHierarchy.h"
#include "vtkTOMBuilder.h"

#include "vtkBoundingBox.h"
#include "vtkCompositeDataSet.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerKey.h"
#include "vtkMath.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPartitionedDataSet.h"
#include "vtkPartitionedDataSetCollection.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkXMLMultiBlockDataReader.h"
#include "vtkXMLMultiBlockDataWriter.h"
#include "vtkXMLPartitionedDataSetCollectionReader.h"
#include "vtkXMLPartitionedDataSetCollectionWriter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace
{
namespace tt = timecritical::testing;
using timecritical::AccuracyCurve;
constexpr double Inf = std::numeric_limits<double>::infinity();

/// A deep copy of `data` moved by dx along x.
vtkSmartPointer<vtkPolyData> Moved(vtkPolyData* data, double dx)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(data);
  vtkNew<vtkPoints> points;
  points->SetDataType(copy->GetPoints()->GetDataType());
  for (vtkIdType p = 0; p < copy->GetNumberOfPoints(); ++p)
  {
    double x[3];
    copy->GetPoint(p, x);
    points->InsertNextPoint(x[0] + dx, x[1], x[2]);
  }
  copy->SetPoints(points);
  return copy;
}

vtkPolyData* SphereTOM()
{
  static vtkSmartPointer<vtkPolyData> tom = tt::RunFilter<vtkTOMBuilder>(tt::MakeSphere(12), nullptr);
  return tom;
}

/// A fixed coarse mesh at x = dx with a stored single-point curve (relative accuracy 8).
vtkSmartPointer<vtkPolyData> Coarse(double dx)
{
  auto coarse = Moved(tt::MakeSphere(5), dx);
  vtkAccuracyCurveFieldData::Write(AccuracyCurve::SinglePoint(8.0,
                                     static_cast<double>(coarse->GetNumberOfPolys())),
    coarse->GetLength(), coarse);
  return coarse;
}

/**
 * Flat indices: 0 root; 1 TOM at x=0; 2 group {3 TOM at x=3, 4 TOM at x=5};
 * 5 LOD node {6 TOM at x=10, 7 coarse at x=10}; 8 empty; 9 plain sphere at x=-4.
 */
vtkSmartPointer<vtkMultiBlockDataSet> Scene(bool markInFile = true)
{
  auto root = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  root->SetBlock(0, Moved(SphereTOM(), 0.0));
  vtkNew<vtkMultiBlockDataSet> group;
  group->SetBlock(0, Moved(SphereTOM(), 3.0));
  group->SetBlock(1, Moved(SphereTOM(), 5.0));
  root->SetBlock(1, group);
  vtkNew<vtkMultiBlockDataSet> lod;
  lod->SetBlock(0, Moved(SphereTOM(), 10.0));
  lod->SetBlock(1, Coarse(10.0));
  root->SetBlock(2, lod);
  root->SetBlock(3, nullptr);
  root->SetBlock(4, Moved(tt::MakeSphere(8), -4.0));
  if (markInFile)
  {
    EXPECT_TRUE(vtkAccuracyCurveHierarchy::MarkLODNode(root, 5));
  }
  else
  {
    root->GetMetaData(2u)->Set(vtkAccuracyCurveHierarchy::LOD_NODE(), 1);
  }
  return root;
}

/// The leaf's own curve (stored or derived) and size.
AccuracyCurve LeafCurve(vtkDataObject* leaf, double& size)
{
  vtkNew<vtkAccuracyCurveFieldData> reader;
  EXPECT_TRUE(reader->ReadOrDerive(vtkPolyData::SafeDownCast(leaf))) << reader->GetErrorMessage();
  size = reader->GetSize();
  return reader->GetCurve();
}

double Diagonal(std::vector<vtkDataSet*> leaves)
{
  vtkBoundingBox box;
  for (vtkDataSet* leaf : leaves)
  {
    box.AddBounds(leaf->GetBounds());
  }
  return box.GetDiagonalLength();
}

void ExpectNear(double actual, double expected, const std::string& what)
{
  if (std::isinf(expected))
  {
    EXPECT_EQ(actual, expected) << what;
  }
  else
  {
    EXPECT_NEAR(actual, expected, 1e-9 * std::max(1.0, std::abs(expected))) << what;
  }
}

std::vector<double> Probes()
{
  std::vector<double> probes;
  for (double a = 0.0; a < 2e4; a = a * 1.13 + 0.05)
  {
    probes.push_back(a);
  }
  return probes;
}
}

TEST(vtkAccuracyCurveHierarchy, RelativeCurvesFollowThePapersRules)
{
  auto root = Scene();
  vtkNew<vtkAccuracyCurveHierarchy> hierarchy;
  ASSERT_TRUE(hierarchy->Compose(root));
  for (unsigned int index : { 0u, 1u, 2u, 3u, 4u, 5u, 6u, 7u, 9u })
  {
    EXPECT_TRUE(hierarchy->HasCurve(index)) << index;
  }
  EXPECT_FALSE(hierarchy->HasCurve(8)); // the empty block
  EXPECT_TRUE(hierarchy->GetNodeIsLOD(5));
  EXPECT_FALSE(hierarchy->GetNodeIsLOD(2));

  auto* group = vtkMultiBlockDataSet::SafeDownCast(root->GetBlock(1));
  auto* lod = vtkMultiBlockDataSet::SafeDownCast(root->GetBlock(2));
  double s3, s4, s6, s7;
  const AccuracyCurve c3 = LeafCurve(group->GetBlock(0), s3);
  const AccuracyCurve c4 = LeafCurve(group->GetBlock(1), s4);
  const AccuracyCurve c6 = LeafCurve(lod->GetBlock(0), s6);
  const AccuracyCurve c7 = LeafCurve(lod->GetBlock(1), s7);
  const double groupSize = Diagonal(
    { vtkDataSet::SafeDownCast(group->GetBlock(0)), vtkDataSet::SafeDownCast(group->GetBlock(1)) });
  const double lodSize = Diagonal(
    { vtkDataSet::SafeDownCast(lod->GetBlock(0)), vtkDataSet::SafeDownCast(lod->GetBlock(1)) });
  EXPECT_DOUBLE_EQ(hierarchy->GetNodeSize(2), groupSize);
  EXPECT_DOUBLE_EQ(hierarchy->GetNodeSize(5), lodSize);

  // The plain mesh is exact at its triangle count.
  const double plain = static_cast<double>(vtkPolyData::SafeDownCast(root->GetBlock(4))->GetNumberOfPolys());
  EXPECT_EQ(hierarchy->GetNodeResources(9, 0.0), plain);
  EXPECT_EQ(hierarchy->GetNodeResources(9, 1e12), plain);

  const double rootSize = hierarchy->GetNodeSize(0);
  for (double a : Probes())
  {
    const std::string at = " at a = " + std::to_string(a);
    // Group: members rescaled to the group's size (a d_i / D), then added.
    ExpectNear(hierarchy->GetNodeResources(2, a),
      a > hierarchy->GetCurve(2)->GetMaximumAccuracy()
        ? Inf
        : c3.GetSaturatedResources(a * s3 / groupSize) + c4.GetSaturatedResources(a * s4 / groupSize),
      "group" + at);
    // LOD node: the cheapest child that reaches the accuracy.
    const double r6 = c6.GetResources(a * s6 / lodSize);
    const double r7 = c7.GetResources(a * s7 / lodSize);
    ExpectNear(hierarchy->GetNodeResources(5, a), std::min(r6, r7), "LOD" + at);
    const int child = hierarchy->GetCheapestChild(5, a);
    EXPECT_EQ(child, r7 <= r6 ? 1 : 0) << at;
    // Root: its blocks rescaled to its size and added.
    double sum = 0.0;
    for (unsigned int block : { 1u, 2u, 5u, 9u })
    {
      sum += hierarchy->GetCurve(block)->GetSaturatedResources(
        a * hierarchy->GetNodeSize(block) / rootSize);
    }
    ExpectNear(hierarchy->GetResources(a), a > hierarchy->GetMaximumAccuracy() ? Inf : sum, "root" + at);
  }
  // Only the TOM reaches high accuracies; a group has no choice.
  EXPECT_EQ(hierarchy->GetCheapestChild(5, 1e6), 0);
  EXPECT_EQ(hierarchy->GetCheapestChild(2, 1.0), -1);
  // Quotas: the best root accuracy never overspends.
  for (double quota = hierarchy->GetMinimumResources(); quota < 5e4; quota *= 1.3)
  {
    EXPECT_LE(hierarchy->GetResources(hierarchy->GetAccuracy(quota)), quota * (1.0 + 1e-9));
  }
  EXPECT_EQ(hierarchy->GetAccuracy(hierarchy->GetMinimumResources() - 1.0), 0.0);
}

TEST(vtkAccuracyCurveHierarchy, AbsoluteCurvesFromAViewPoint)
{
  vtkNew<vtkMultiBlockDataSet> root;
  root->SetBlock(0, Moved(SphereTOM(), 10.0));
  root->SetBlock(1, Moved(SphereTOM(), 40.0));
  vtkNew<vtkAccuracyCurveHierarchy> hierarchy;
  hierarchy->SetAccuracyKind(vtkAccuracyCurveHierarchy::ABSOLUTE);
  ASSERT_TRUE(hierarchy->Compose(root));
  std::vector<AccuracyCurve> curves(2);
  std::vector<double> sizes(2), distances(2);
  for (unsigned int i = 0; i < 2; ++i)
  {
    auto* leaf = vtkDataSet::SafeDownCast(root->GetBlock(i));
    curves[i] = LeafCurve(leaf, sizes[i]);
    vtkBoundingBox box(leaf->GetBounds());
    double centre[3];
    box.GetCenter(centre);
    distances[i] = AccuracyCurve::NearestDistance(
      vtkMath::Norm(centre), box.GetDiagonalLength() / 2, 1e-3);
  }
  EXPECT_GT(distances[1], distances[0]);
  for (double a : Probes())
  {
    double sum = 0.0;
    for (int i = 0; i < 2; ++i)
    {
      sum += curves[i].GetSaturatedResources(
        AccuracyCurve::AbsoluteToRelative(a, sizes[i], distances[i]));
    }
    ExpectNear(hierarchy->GetResources(a), sum, "absolute root at a = " + std::to_string(a));
  }
  // From farther away the same angular accuracy costs less.
  vtkNew<vtkAccuracyCurveHierarchy> far;
  far->SetAccuracyKind(vtkAccuracyCurveHierarchy::ABSOLUTE);
  far->SetViewPoint(-100.0, 0.0, 0.0);
  ASSERT_TRUE(far->Compose(root));
  const double a = 40.0;
  EXPECT_LT(far->GetResources(a), hierarchy->GetResources(a));
  // A viewpoint inside an object counts the minimum distance: nearly only its full mesh.
  vtkNew<vtkAccuracyCurveHierarchy> inside;
  inside->SetAccuracyKind(vtkAccuracyCurveHierarchy::ABSOLUTE);
  inside->SetViewPoint(10.0, 0.0, 0.0);
  ASSERT_TRUE(inside->Compose(root));
  EXPECT_GT(inside->GetResources(a), hierarchy->GetResources(a));
}

TEST(vtkAccuracyCurveHierarchy, LODMarkSurvivesVtmFiles)
{
  auto root = Scene();
  EXPECT_TRUE(vtkAccuracyCurveHierarchy::IsLODNode(root, 5));
  EXPECT_FALSE(vtkAccuracyCurveHierarchy::IsLODNode(root, 2));
  vtkNew<vtkAccuracyCurveHierarchy> before;
  ASSERT_TRUE(before->Compose(root));
  for (bool markInFile : { true, false })
  {
    const std::string path = std::string(TIMECRITICAL_TEST_OUTPUT_DIR) + "/accuracy_curve_scene_" +
      (markInFile ? "file" : "metadata") + ".vtm";
    vtkNew<vtkXMLMultiBlockDataWriter> writer;
    writer->SetFileName(path.c_str());
    writer->SetInputData(Scene(markInFile));
    writer->SetDataModeToBinary();
    ASSERT_EQ(writer->Write(), 1);
    vtkNew<vtkXMLMultiBlockDataReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    auto* back = vtkMultiBlockDataSet::SafeDownCast(reader->GetOutput());
    ASSERT_NE(back, nullptr);
    // The metadata key does not travel in .vtm files; the root's array does.
    EXPECT_FALSE(back->GetMetaData(2u)->Has(vtkAccuracyCurveHierarchy::LOD_NODE()));
    EXPECT_EQ(vtkAccuracyCurveHierarchy::IsLODNode(back, 5), markInFile) << path;
    vtkNew<vtkAccuracyCurveHierarchy> after;
    ASSERT_TRUE(after->Compose(back));
    EXPECT_EQ(after->GetNodeIsLOD(5), markInFile);
    if (markInFile)
    {
      // The leaves' curves (the coarse mesh's stored one included) came back too.
      EXPECT_TRUE(after->GetRootCurve().IsNear(before->GetRootCurve(), 1e-9));
      EXPECT_EQ(after->GetCheapestChild(5, 0.0), before->GetCheapestChild(5, 0.0));
      EXPECT_EQ(after->GetCheapestChild(5, 1e6), 0);
    }
  }
}

TEST(vtkAccuracyCurveHierarchy, PartitionedDataSetCollections)
{
  vtkNew<vtkPartitionedDataSetCollection> collection;
  vtkNew<vtkPartitionedDataSet> object;
  object->SetPartition(0, Moved(SphereTOM(), 0.0));
  vtkNew<vtkPartitionedDataSet> alternatives;
  alternatives->SetPartition(0, Moved(SphereTOM(), 10.0));
  alternatives->SetPartition(1, Coarse(10.0));
  collection->SetPartitionedDataSet(0, object);
  collection->SetPartitionedDataSet(1, alternatives);
  // Flat indices: 1 {2}, 3 {4, 5}. Marked in the metadata only first.
  collection->GetMetaData(1u)->Set(vtkAccuracyCurveHierarchy::LOD_NODE(), 1);
  vtkNew<vtkAccuracyCurveHierarchy> hierarchy;
  ASSERT_TRUE(hierarchy->Compose(collection));
  EXPECT_TRUE(hierarchy->GetNodeIsLOD(3));
  EXPECT_FALSE(hierarchy->GetNodeIsLOD(1));
  EXPECT_EQ(hierarchy->GetCheapestChild(3, 1e6), 0);

  ASSERT_TRUE(vtkAccuracyCurveHierarchy::MarkLODNode(collection, 3));
  const std::string path = std::string(TIMECRITICAL_TEST_OUTPUT_DIR) + "/accuracy_curve_scene.vtpc";
  vtkNew<vtkXMLPartitionedDataSetCollectionWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(collection);
  writer->SetDataModeToBinary();
  ASSERT_EQ(writer->Write(), 1);
  vtkNew<vtkXMLPartitionedDataSetCollectionReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkNew<vtkAccuracyCurveHierarchy> back;
  ASSERT_TRUE(back->Compose(reader->GetOutputDataObject(0)));
  EXPECT_TRUE(back->GetNodeIsLOD(3));
  EXPECT_TRUE(back->GetRootCurve().IsNear(hierarchy->GetRootCurve(), 1e-9));
}

TEST(vtkAccuracyCurveHierarchy, MarkingAndUnmarking)
{
  auto root = Scene();
  tt::MessageLog log(root);
  EXPECT_FALSE(vtkAccuracyCurveHierarchy::MarkLODNode(root, 1)); // a leaf
  EXPECT_FALSE(vtkAccuracyCurveHierarchy::MarkLODNode(root, 99));
  EXPECT_EQ(log.Errors.size(), 2u);
  EXPECT_TRUE(log.ErrorContains("no composite block at flat index 99"));
  EXPECT_FALSE(vtkAccuracyCurveHierarchy::MarkLODNode(nullptr, 0));
  EXPECT_FALSE(vtkAccuracyCurveHierarchy::IsLODNode(nullptr, 0));
  ASSERT_TRUE(vtkAccuracyCurveHierarchy::MarkLODNode(root, 2));
  EXPECT_TRUE(vtkAccuracyCurveHierarchy::IsLODNode(root, 2));
  EXPECT_EQ(root->GetMetaData(1u)->Get(vtkAccuracyCurveHierarchy::LOD_NODE()), 1);
  ASSERT_TRUE(vtkAccuracyCurveHierarchy::MarkLODNode(root, 5, false));
  EXPECT_FALSE(vtkAccuracyCurveHierarchy::IsLODNode(root, 5));
  EXPECT_FALSE(root->GetMetaData(2u)->Has(vtkAccuracyCurveHierarchy::LOD_NODE()));
  auto* listed = vtkDataArray::SafeDownCast(
    root->GetFieldData()->GetAbstractArray(vtkAccuracyCurveHierarchy::LODNodesArrayName()));
  ASSERT_NE(listed, nullptr);
  ASSERT_EQ(listed->GetNumberOfTuples(), 1);
  EXPECT_EQ(listed->GetTuple1(0), 2.0);
  // The root itself can be an LOD node: its blocks are then alternatives.
  ASSERT_TRUE(vtkAccuracyCurveHierarchy::MarkLODNode(root, 0));
  vtkNew<vtkAccuracyCurveHierarchy> hierarchy;
  ASSERT_TRUE(hierarchy->Compose(root));
  EXPECT_TRUE(hierarchy->GetNodeIsLOD(0));
  EXPECT_GE(hierarchy->GetCheapestChild(0, 1.0), 0);
}

TEST(vtkAccuracyCurveHierarchy, SingleDataSets)
{
  vtkNew<vtkAccuracyCurveHierarchy> hierarchy;
  ASSERT_TRUE(hierarchy->Compose(SphereTOM()));
  double size;
  const AccuracyCurve own = LeafCurve(SphereTOM(), size);
  EXPECT_TRUE(hierarchy->GetRootCurve().IsNear(own));
  EXPECT_EQ(hierarchy->GetNodeSize(0), size);
  EXPECT_EQ(hierarchy->GetCheapestChild(0, 1.0), -1);
  vtkNew<vtkPolyData> empty;
  ASSERT_TRUE(hierarchy->Compose(empty));
  EXPECT_FALSE(hierarchy->HasCurve(0));
  EXPECT_TRUE(hierarchy->GetRootCurve().IsEmpty());
}

TEST(vtkAccuracyCurveHierarchy, Errors)
{
  vtkNew<vtkAccuracyCurveHierarchy> hierarchy;
  tt::MessageLog log(hierarchy);
  EXPECT_FALSE(hierarchy->Compose(nullptr));
  EXPECT_TRUE(log.ErrorContains("no input data"));

  // A leaf with a bad stored curve: the error names its block; nothing is kept.
  ASSERT_TRUE(hierarchy->Compose(Scene()));
  auto bad = Scene();
  auto* leaf = vtkMultiBlockDataSet::SafeDownCast(bad->GetBlock(1))->GetBlock(1);
  vtkNew<vtkFloatArray> size;
  size->SetName(vtkAccuracyCurveFieldData::SizeArrayName());
  size->InsertNextValue(-1.f);
  vtkAccuracyCurveFieldData::Write(AccuracyCurve::SinglePoint(1.0, 1.0), 1.0, leaf);
  leaf->GetFieldData()->AddArray(size);
  EXPECT_FALSE(hierarchy->Compose(bad));
  EXPECT_TRUE(log.ErrorContains("block 4: AccuracyCurveSize")) << log.AllErrors();
  EXPECT_FALSE(hierarchy->HasCurve(0));
  EXPECT_TRUE(std::isnan(hierarchy->GetResources(1.0)));

  // A malformed list of LOD nodes.
  auto badList = Scene();
  vtkNew<vtkFloatArray> list;
  list->SetName(vtkAccuracyCurveHierarchy::LODNodesArrayName());
  list->InsertNextValue(1.5f);
  badList->GetFieldData()->AddArray(list);
  EXPECT_FALSE(hierarchy->Compose(badList));
  EXPECT_TRUE(log.ErrorContains("not a flat index"));
  EXPECT_TRUE(vtkAccuracyCurveHierarchy::IsLODNode(badList, 5)); // the metadata key still marks it
  // MarkLODNode replaces it.
  EXPECT_TRUE(vtkAccuracyCurveHierarchy::MarkLODNode(badList, 5));
  EXPECT_TRUE(hierarchy->Compose(badList));

  // Bad settings and arguments.
  hierarchy->SetMinimumDistance(0.0);
  EXPECT_FALSE(hierarchy->Compose(Scene()));
  EXPECT_TRUE(log.ErrorContains("MinimumDistance"));
  hierarchy->SetMinimumDistance(1e-3);
  hierarchy->SetViewPoint(std::nan(""), 0.0, 0.0);
  EXPECT_FALSE(hierarchy->Compose(Scene()));
  hierarchy->SetViewPoint(0.0, 0.0, 0.0);
  ASSERT_TRUE(hierarchy->Compose(Scene()));
  const size_t errors = log.Errors.size();
  EXPECT_TRUE(std::isnan(hierarchy->GetResources(-1.0)));
  EXPECT_EQ(hierarchy->GetCheapestChild(5, std::nan("")), -1);
  EXPECT_EQ(log.Errors.size(), errors + 2);
  EXPECT_TRUE(std::isnan(hierarchy->GetNodeResources(42, 1.0))); // no such node
}
