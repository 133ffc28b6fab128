// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkTOMBuilder, vtkExtractTOMResolution and vtkTOMFieldData (and of
// vtkMergeTreeBuilder where it shares vtkTOMBuilder's input handling and settings).
#include "FilterTestSupport.h"
#include "TOMBuilder.h"
#include "TOMMesh.h"
#include "TestMeshIO.h"
#include "vtkExtractTOMResolution.h"
#include "vtkMergeTreeBuilder.h"
#include "vtkTOMBuilder.h"
#include "vtkTOMFieldData.h"

#include "vtkAppendPolyData.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkReverseSense.h"
#include "vtkSmartPointer.h"
#include "vtkTypeUInt32Array.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace
{
namespace tt = timecritical::testing;
using tt::MakeSphere;
using tt::MessageLog;
using tt::PointKey;

vtkSmartPointer<vtkPolyData> Build(vtkPolyData* input, vtkTOMBuilder* builder = nullptr)
{
  return tt::RunFilter(input, builder);
}

vtkSmartPointer<vtkPolyData> Triangle()
{
  auto data = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0, 1, 0);
  data->SetPoints(points);
  vtkNew<vtkCellArray> polys;
  polys->InsertNextCell({ 0, 1, 2 });
  data->SetPolys(polys);
  return data;
}
}

TEST(vtkTOMBuilder, SphereGivesValidTOM)
{
  auto input = MakeSphere();
  auto tom = Build(input);
  vtkNew<vtkTOMFieldData> reader;
  ASSERT_TRUE(reader->Read(tom)) << reader->GetErrorMessage();
  EXPECT_EQ(tom->GetNumberOfPoints(), input->GetNumberOfPoints());
  EXPECT_EQ(tom->GetNumberOfPolys(), input->GetNumberOfPolys());
  auto* substitution = vtkTypeUInt32Array::SafeDownCast(
    tom->GetPointData()->GetArray(vtkTOMFieldData::SubstitutionArrayName()));
  ASSERT_NE(substitution, nullptr);
  const vtkIdType base = reader->GetBaseVertexCount();
  EXPECT_GE(base, 4);
  EXPECT_LE(base, 8) << "a closed sphere should reduce to a handful of vertices";
  for (vtkIdType i = 0; i < tom->GetNumberOfPoints(); ++i)
  {
    if (i < base)
    {
      ASSERT_EQ(substitution->GetValue(i), static_cast<uint32_t>(i));
    }
    else
    {
      ASSERT_LT(substitution->GetValue(i), static_cast<uint32_t>(i));
    }
  }
  // Only the substitution is added per point: normals plus TOMSubstitution.
  EXPECT_EQ(tom->GetPointData()->GetNumberOfArrays(), input->GetPointData()->GetNumberOfArrays() + 1);
}

TEST(vtkTOMBuilder, PointAndCellDataTravelWithTheirPointsAndTriangles)
{
  auto input = MakeSphere();
  auto tom = Build(input);
  tt::ExpectDataTravelsWithPointsAndTriangles(input, tom);
}

TEST(vtkTOMBuilder, EmptyInputGivesEmptyOutputQuietly)
{
  // What a parallel reader gives the ranks without data: no message, an empty
  // output that the extraction passes on quietly too.
  vtkNew<vtkPolyData> empty;
  vtkNew<vtkTOMBuilder> builder;
  MessageLog log(builder);
  auto out = Build(empty, builder);
  EXPECT_TRUE(log.Errors.empty()) << log.AllErrors();
  EXPECT_TRUE(log.Warnings.empty());
  EXPECT_EQ(out->GetNumberOfPoints(), 0);
  EXPECT_EQ(out->GetNumberOfCells(), 0);

  vtkNew<vtkExtractTOMResolution> extract;
  MessageLog extractLog(extract);
  extract->SetInputData(out);
  extract->SetResolution(0.5);
  extract->Update();
  EXPECT_TRUE(extractLog.Errors.empty()) << extractLog.AllErrors();
  EXPECT_EQ(extract->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(extract->GetOutput()->GetNumberOfCells(), 0);
}

TEST(vtkTOMBuilder, PointsWithoutCellsAreAnError)
{
  vtkNew<vtkPolyData> cloud;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  cloud->SetPoints(points);
  vtkNew<vtkTOMBuilder> builder;
  MessageLog log(builder);
  auto out = Build(cloud, builder);
  EXPECT_TRUE(log.ErrorContains("no surface cells")) << log.AllErrors();
  EXPECT_EQ(out->GetNumberOfPoints(), 0);
}

TEST(vtkTOMBuilder, LinesOnlyIsAnError)
{
  vtkNew<vtkTOMBuilder> builder;
  MessageLog log(builder);
  auto out = Build(tt::LinesOnly(), builder);
  EXPECT_TRUE(log.ErrorContains("no surface cells"));
  EXPECT_EQ(out->GetNumberOfCells(), 0);
}

TEST(vtkTOMBuilder, NaNCoordinateIsAnError)
{
  auto input = MakeSphere(10);
  input->GetPoints()->SetPoint(5, std::numeric_limits<double>::quiet_NaN(), 0, 0);
  vtkNew<vtkTOMBuilder> builder;
  MessageLog log(builder);
  auto out = Build(input, builder);
  EXPECT_TRUE(log.ErrorContains("point 5 has a non-finite"));
  EXPECT_EQ(out->GetNumberOfPoints(), 0);
}

TEST(vtkTOMBuilder, HugeCoordinateIsAnError)
{
  // Finite, but beyond what the cores' float errors and radii hold: the
  // cores' own limit, reported at the filter's entry.
  auto input = MakeSphere(10);
  input->GetPoints()->SetPoint(5, -2.2e38, 0, 0);
  vtkNew<vtkTOMBuilder> builder;
  MessageLog log(builder);
  auto out = Build(input, builder);
  EXPECT_TRUE(log.ErrorContains(
    "point 5 has a coordinate of magnitude 2.2e+38, beyond the supported 1e+28"))
    << log.AllErrors();
  EXPECT_EQ(out->GetNumberOfPoints(), 0);
  EXPECT_EQ(out->GetNumberOfCells(), 0);
}

TEST(vtkTOMBuilder, QuadsAndStripsAreTriangulated)
{
  auto quads = Build(tt::PlaneQuads());
  EXPECT_EQ(quads->GetNumberOfPolys(), 200);

  auto stripped = tt::PlaneStrips();
  ASSERT_GT(stripped->GetNumberOfStrips(), 0);
  auto strips = Build(stripped);
  EXPECT_EQ(strips->GetNumberOfPolys(), 200);
  EXPECT_EQ(strips->GetNumberOfStrips(), 0);
  vtkNew<vtkTOMFieldData> reader;
  EXPECT_TRUE(reader->Read(strips)) << reader->GetErrorMessage();
}

TEST(vtkTOMBuilder, DuplicatePointsAreMergedAndDegenerateCellsDropped)
{
  vtkNew<vtkTOMBuilder> builder;
  MessageLog log(builder);
  auto tom = Build(tt::DuplicatePointsAndDegenerateCells(), builder);
  EXPECT_TRUE(log.Errors.empty());
  EXPECT_GE(log.Warnings.size(), 2u);
  EXPECT_EQ(tom->GetNumberOfPoints(), 4);
  EXPECT_EQ(tom->GetNumberOfPolys(), 2);
  EXPECT_EQ(builder->GetNumberOfMergedPoints(), 2);
  EXPECT_EQ(builder->GetNumberOfDroppedCells(), 2);
}

TEST(vtkTOMBuilder, CoincidentCopiesAreDeduplicated)
{
  // A careless append of coincident copies: after point merging every copy's
  // triangles repeat the first copy's (in either orientation). They are
  // dropped with one warning, so the build stays linear in the copies and the
  // output is the mesh once, with the first copy's cell data.
  auto sphere = MakeSphere(12);
  const vtkIdType triangles = sphere->GetNumberOfPolys();
  vtkNew<vtkAppendPolyData> append;
  for (int copy = 0; copy < 300; ++copy)
  {
    append->AddInputData(sphere);
  }
  // One more copy with every triangle reversed: the same point sets.
  vtkNew<vtkReverseSense> reversed;
  reversed->SetInputData(sphere);
  append->AddInputConnection(reversed->GetOutputPort());
  append->Update();
  for (bool mergeTree : { false, true })
  {
    vtkSmartPointer<vtkPolyDataAlgorithm> builder;
    if (mergeTree)
    {
      builder = vtkSmartPointer<vtkMergeTreeBuilder>::New();
    }
    else
    {
      builder = vtkSmartPointer<vtkTOMBuilder>::New();
    }
    MessageLog log(builder);
    builder->SetInputData(append->GetOutput());
    builder->Update();
    vtkPolyData* out = builder->GetOutput();
    EXPECT_TRUE(log.Errors.empty()) << log.AllErrors();
    bool warned = false;
    for (const std::string& w : log.Warnings)
    {
      warned = warned ||
        w.find("Dropping " + std::to_string(300 * triangles) + " duplicate triangles") !=
          std::string::npos;
    }
    EXPECT_TRUE(warned) << mergeTree;
    EXPECT_EQ(out->GetNumberOfPolys(), triangles);
    EXPECT_EQ(out->GetNumberOfPoints(), sphere->GetNumberOfPoints());
    vtkDataArray* cellIds = out->GetCellData()->GetArray("InputCellId");
    ASSERT_NE(cellIds, nullptr);
    std::set<double> ids;
    for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
    {
      ids.insert(cellIds->GetTuple1(c));
    }
    EXPECT_EQ(static_cast<vtkIdType>(ids.size()), triangles); // each first-copy cell once
    vtkNew<vtkTOMFieldData> reader;
    EXPECT_TRUE(reader->Read(out)) << reader->GetErrorMessage();
  }
}

TEST(vtkTOMBuilder, OneTriangle)
{
  auto tom = Build(Triangle());
  vtkNew<vtkTOMFieldData> reader;
  ASSERT_TRUE(reader->Read(tom)) << reader->GetErrorMessage();
  EXPECT_EQ(reader->GetNumberOfTriangles(), 1);
  EXPECT_EQ(reader->GetNumberOfVertices(), 3);
}

TEST(vtkTOMBuilder, NonManifoldEdgeBuilds)
{
  // Three triangles on the edge (0,1).
  vtkNew<vtkPolyData> data;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0.5, 1, 0);
  points->InsertNextPoint(0.5, -1, 0);
  points->InsertNextPoint(0.5, 0, 1);
  data->SetPoints(points);
  vtkNew<vtkCellArray> polys;
  polys->InsertNextCell({ 0, 1, 2 });
  polys->InsertNextCell({ 1, 0, 3 });
  polys->InsertNextCell({ 0, 1, 4 });
  data->SetPolys(polys);
  auto tom = Build(data);
  vtkNew<vtkTOMFieldData> reader;
  ASSERT_TRUE(reader->Read(tom)) << reader->GetErrorMessage();
  EXPECT_EQ(reader->GetNumberOfTriangles(), 3);
}

TEST(vtkTOMBuilder, AbortLeavesEmptyOutput)
{
  auto input = MakeSphere(60);
  vtkNew<vtkTOMBuilder> builder;
  tt::AbortPastOneFifth(builder);
  auto out = Build(input, builder);
  EXPECT_EQ(out->GetNumberOfPoints(), 0);
  EXPECT_EQ(out->GetNumberOfCells(), 0);
}

TEST(vtkTOMBuilder, SavedAndReadBackLosesNothing)
{
  auto tom = Build(MakeSphere());
  const std::string path = std::string(TIMECRITICAL_TEST_OUTPUT_DIR) + "/sphere-tom.vtp";
  vtkSmartPointer<vtkPolyData> back;
  ASSERT_NO_FATAL_FAILURE(tt::WriteAndReadBack(tom, path, back));
  vtkNew<vtkTOMFieldData> before;
  vtkNew<vtkTOMFieldData> after;
  ASSERT_TRUE(before->Read(tom));
  ASSERT_TRUE(after->Read(back)) << after->GetErrorMessage();
  EXPECT_EQ(before->GetMesh().Substitution, after->GetMesh().Substitution);
  EXPECT_EQ(before->GetMesh().Triangles, after->GetMesh().Triangles);
  EXPECT_EQ(before->GetBaseTriangleCount(), after->GetBaseTriangleCount());
  const auto& a = before->GetMesh().ErrorCurve.GetSamples();
  const auto& b = after->GetMesh().ErrorCurve.GetSamples();
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i)
  {
    EXPECT_EQ(a[i].Triangles, b[i].Triangles);
    EXPECT_EQ(a[i].Error, b[i].Error);
  }
  for (vtkIdType i = 0; i < tom->GetNumberOfPoints(); ++i)
  {
    ASSERT_EQ(PointKey(tom, i), PointKey(back, i));
  }
  EXPECT_NE(back->GetPointData()->GetNormals(), nullptr);
  EXPECT_NE(back->GetCellData()->GetArray("InputCellId"), nullptr);
}

TEST(vtkTOMBuilder, RealMeshWhenAvailable)
{
  const std::string path = std::string(TIMECRITICAL_SHARED_DATA_DIR) + "/cow.obj";
  if (!std::ifstream(path).good())
  {
    GTEST_SKIP() << path << " not found";
  }
  vtkNew<vtkOBJReader> obj;
  obj->SetFileName(path.c_str());
  vtkNew<vtkTOMBuilder> builder;
  builder->SetInputConnection(obj->GetOutputPort());
  builder->Update();
  vtkNew<vtkTOMFieldData> reader;
  ASSERT_TRUE(reader->Read(builder->GetOutput())) << reader->GetErrorMessage();
  EXPECT_EQ(reader->GetNumberOfTriangles(), 5804);
  EXPECT_LE(reader->GetBaseVertexCount(), 16);
}

TEST(vtkTOMBuilder, SettingsRejectNaNAndClamp)
{
  vtkNew<vtkTOMBuilder> builder;
  MessageLog log(builder);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const vtkMTimeType before = builder->GetMTime();
  builder->SetFeatureAngle(nan);
  builder->SetFeatureWeight(nan);
  builder->SetMaximumNormalDeviation(nan);
  builder->SetMinimumTriangleQuality(nan);
  ASSERT_EQ(log.Errors.size(), 4u);
  EXPECT_TRUE(log.ErrorContains("FeatureWeight must be a number in [0, 1000]; NaN ignored"))
    << log.AllErrors();
  EXPECT_TRUE(log.ErrorContains("FeatureAngle must be a number"));
  EXPECT_EQ(builder->GetMTime(), before);
  // The core's defaults.
  const timecritical::TOMBuildOptions core;
  EXPECT_EQ(builder->GetFeatureAngle(), core.FeatureAngle);
  EXPECT_EQ(builder->GetFeatureWeight(), core.FeatureWeight);
  EXPECT_EQ(builder->GetLockFeatureEdges(), core.LockFeatureEdges);
  EXPECT_EQ(builder->GetMaximumNormalDeviation(), core.MaximumNormalDeviation);
  EXPECT_EQ(builder->GetMinimumTriangleQuality(), core.MinimumTriangleQuality);
  // Out of range: clamped, as vtkSetClampMacro does. The weight's upper bound
  // is the core's boundary constraint weight.
  builder->SetFeatureWeight(-1.0);
  EXPECT_EQ(builder->GetFeatureWeight(), 0.0);
  EXPECT_GT(builder->GetMTime(), before);
  builder->SetFeatureWeight(1e300);
  EXPECT_EQ(builder->GetFeatureWeight(), core.ConstraintWeight);
  builder->SetFeatureWeight(std::numeric_limits<double>::infinity());
  EXPECT_EQ(builder->GetFeatureWeight(), core.ConstraintWeight);
  builder->SetFeatureAngle(200.0);
  EXPECT_EQ(builder->GetFeatureAngle(), 180.0);
  builder->SetMinimumTriangleQuality(-1.0);
  EXPECT_EQ(builder->GetMinimumTriangleQuality(), 0.0);
  EXPECT_EQ(log.Errors.size(), 4u);
  // Setting the same value again is no modification.
  builder->SetFeatureWeight(3.0);
  builder->LockFeatureEdgesOn();
  const vtkMTimeType set = builder->GetMTime();
  builder->SetFeatureWeight(3.0);
  builder->SetLockFeatureEdges(true);
  EXPECT_EQ(builder->GetMTime(), set);
  std::ostringstream print;
  builder->Print(print);
  EXPECT_NE(print.str().find("LockFeatureEdges: 1"), std::string::npos) << print.str();
  EXPECT_NE(print.str().find("FeatureWeight: 3"), std::string::npos) << print.str();
}

namespace
{
/// TestTOMBuilder's noisy cube (tt::MakeNoisyCube) as vtkPolyData.
vtkSmartPointer<vtkPolyData> NoisyCube(std::size_t n, double noise)
{
  const tt::TriangleMesh mesh = tt::MakeNoisyCube(n, noise);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.NumberOfPoints()));
  for (std::size_t i = 0; i < mesh.NumberOfPoints(); ++i)
  {
    points->SetPoint(static_cast<vtkIdType>(i), &mesh.Points[3 * i]);
  }
  vtkNew<vtkCellArray> polys;
  for (std::size_t t = 0; t < mesh.NumberOfTriangles(); ++t)
  {
    const uint32_t* v = &mesh.Triangles[3 * t];
    polys->InsertNextCell({ vtkIdType(v[0]), vtkIdType(v[1]), vtkIdType(v[2]) });
  }
  auto cube = vtkSmartPointer<vtkPolyData>::New();
  cube->SetPoints(points);
  cube->SetPolys(polys);
  return cube;
}

/// Whether two builds are the same TOM: the same points in the same order,
/// the same substitutions and the same triangles.
bool SameTOM(vtkPolyData* a, vtkPolyData* b)
{
  if (a->GetNumberOfPoints() != b->GetNumberOfPoints() ||
    a->GetNumberOfCells() != b->GetNumberOfCells())
  {
    return false;
  }
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    if (PointKey(a, i) != PointKey(b, i))
    {
      return false;
    }
  }
  vtkDataArray* sa = a->GetPointData()->GetArray("TOMSubstitution");
  vtkDataArray* sb = b->GetPointData()->GetArray("TOMSubstitution");
  if (!sa || !sb)
  {
    return false;
  }
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    if (sa->GetTuple1(i) != sb->GetTuple1(i))
    {
      return false;
    }
  }
  for (vtkIdType c = 0; c < a->GetNumberOfCells(); ++c)
  {
    vtkIdType na, nb;
    const vtkIdType* ia;
    const vtkIdType* ib;
    a->GetCellPoints(c, na, ia);
    b->GetCellPoints(c, nb, ib);
    if (na != nb || !std::equal(ia, ia + na, ib))
    {
      return false;
    }
  }
  return true;
}

/**
 * LockFeatureEdges and FeatureWeight reach the core: on a noisy cube each
 * setting changes the TOM, FeatureWeight 0 gives the TOM of unweighted
 * creases (PreserveFeatureEdges off), and a lock ignores FeatureWeight.
 */
template <typename Builder>
void ExpectFeatureEdgeSettingsReachTheCore()
{
  const auto cube = NoisyCube(8, 0.6 / 8);
  auto build = [&cube](void (*configure)(Builder*)) {
    vtkNew<Builder> builder;
    MessageLog log(builder);
    configure(builder);
    builder->SetInputData(cube);
    builder->Update();
    EXPECT_TRUE(log.Errors.empty()) << log.AllErrors();
    vtkSmartPointer<vtkPolyData> out = builder->GetOutput();
    EXPECT_EQ(out->GetNumberOfPolys(), cube->GetNumberOfPolys());
    return out;
  };
  const auto weighted = build([](Builder*) {});
  const auto unweighted = build([](Builder* b) { b->SetFeatureWeight(0.0); });
  const auto light = build([](Builder* b) { b->SetFeatureWeight(1.0); });
  const auto plain = build([](Builder* b) { b->PreserveFeatureEdgesOff(); });
  const auto locked = build([](Builder* b) { b->LockFeatureEdgesOn(); });
  const auto lockedUnweighted = build([](Builder* b) {
    b->LockFeatureEdgesOn();
    b->SetFeatureWeight(0.0);
  });
  EXPECT_FALSE(SameTOM(weighted, unweighted)) << "FeatureWeight 0 not forwarded";
  EXPECT_FALSE(SameTOM(weighted, light)) << "FeatureWeight 1 not forwarded";
  EXPECT_FALSE(SameTOM(light, unweighted));
  EXPECT_TRUE(SameTOM(unweighted, plain)) << "weight 0 should leave creases to the face quadrics";
  EXPECT_FALSE(SameTOM(weighted, locked)) << "LockFeatureEdges not forwarded";
  EXPECT_FALSE(SameTOM(plain, locked));
  EXPECT_TRUE(SameTOM(locked, lockedUnweighted)) << "a lock does not use FeatureWeight";
}
}

TEST(vtkTOMBuilder, FeatureEdgeSettingsReachTheCore)
{
  ExpectFeatureEdgeSettingsReachTheCore<vtkTOMBuilder>();
}

TEST(vtkMergeTreeBuilder, FeatureEdgeSettingsReachTheCore)
{
  ExpectFeatureEdgeSettingsReachTheCore<vtkMergeTreeBuilder>();
}

namespace
{
vtkSmartPointer<vtkPolyData> Extract(vtkPolyData* tom, vtkExtractTOMResolution* filter)
{
  filter->SetInputData(tom);
  filter->Update();
  vtkSmartPointer<vtkPolyData> out = filter->GetOutput();
  return out;
}
}

TEST(vtkExtractTOMResolution, ResolutionsArePrefixes)
{
  auto tom = Build(MakeSphere());
  const vtkIdType full = tom->GetNumberOfPolys();
  vtkIdType previousVertices = 0;
  for (double r : { 0.05, 0.1, 0.25, 0.5, 1.0 })
  {
    vtkNew<vtkExtractTOMResolution> extract;
    extract->SetResolution(r);
    auto out = Extract(tom, extract);
    const vtkIdType target = static_cast<vtkIdType>(std::lround(r * static_cast<double>(full)));
    EXPECT_LE(out->GetNumberOfPolys(), std::max<vtkIdType>(target, 8)) << "r = " << r;
    EXPECT_GE(out->GetNumberOfPolys(), target - 4) << "r = " << r;
    EXPECT_GT(out->GetNumberOfPoints(), previousVertices);
    previousVertices = out->GetNumberOfPoints();
    EXPECT_EQ(out->GetNumberOfPolys(), extract->GetExtractedTriangleCount());
    EXPECT_EQ(out->GetPointData()->GetArray(vtkTOMFieldData::SubstitutionArrayName()), nullptr);
    EXPECT_NE(out->GetPointData()->GetNormals(), nullptr);
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    {
      ASSERT_EQ(PointKey(out, i), PointKey(tom, i));
    }
    // Cell data is the prefix of the TOM's.
    vtkDataArray* inIds = tom->GetCellData()->GetArray("InputCellId");
    vtkDataArray* outIds = out->GetCellData()->GetArray("InputCellId");
    ASSERT_NE(outIds, nullptr);
    for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
    {
      ASSERT_EQ(outIds->GetTuple1(c), inIds->GetTuple1(c));
    }
  }
  EXPECT_EQ(previousVertices, tom->GetNumberOfPoints());
}

TEST(vtkExtractTOMResolution, TargetTrianglesAndMaximumError)
{
  auto tom = Build(MakeSphere());
  vtkNew<vtkExtractTOMResolution> extract;
  extract->SetTargetTriangles(500);
  auto out = Extract(tom, extract);
  EXPECT_LE(out->GetNumberOfPolys(), 500);
  EXPECT_GE(out->GetNumberOfPolys(), 496);
  EXPECT_EQ(extract->GetSelectionMode(), vtkExtractTOMResolution::BY_TRIANGLE_COUNT);

  vtkIdType previous = -1;
  for (double e : { 1.0, 0.1, 0.01, 0.001, 0.0 })
  {
    extract->SetMaximumError(e);
    out = Extract(tom, extract);
    EXPECT_GE(out->GetNumberOfPolys(), previous) << "smaller error must not give fewer triangles";
    EXPECT_LE(extract->GetExtractedError(), e + 1e-6);
    previous = out->GetNumberOfPolys();
  }
  EXPECT_EQ(previous, tom->GetNumberOfPolys());
}

TEST(vtkExtractTOMResolution, GeomorphMovesTheLastVertex)
{
  auto tom = Build(MakeSphere());
  vtkNew<vtkExtractTOMResolution> extract;
  extract->SetResolution(0.5);
  extract->SetGeomorphFactor(1.0);
  auto rest = vtkSmartPointer<vtkPolyData>::New();
  rest->DeepCopy(Extract(tom, extract));
  extract->SetGeomorphFactor(0.0);
  auto morphed = Extract(tom, extract);
  const vtkIdType last = morphed->GetNumberOfPoints() - 1;
  ASSERT_EQ(rest->GetNumberOfPoints(), morphed->GetNumberOfPoints());
  EXPECT_NE(PointKey(rest, last), PointKey(morphed, last));
  // At factor 0 the last vertex sits on another active vertex.
  bool onAnother = false;
  for (vtkIdType i = 0; i < last; ++i)
  {
    onAnother = onAnother || PointKey(morphed, i) == PointKey(morphed, last);
  }
  EXPECT_TRUE(onAnother);
  for (vtkIdType i = 0; i < last; ++i)
  {
    ASSERT_EQ(PointKey(rest, i), PointKey(morphed, i));
  }
}

TEST(vtkExtractTOMResolution, NonTOMInputIsAnError)
{
  vtkNew<vtkExtractTOMResolution> extract;
  MessageLog log(extract);
  auto out = Extract(MakeSphere(), extract);
  EXPECT_TRUE(log.ErrorContains("TOMSubstitution"));
  EXPECT_EQ(out->GetNumberOfPoints(), 0);
}

TEST(vtkExtractTOMResolution, CorruptedTOMIsAnError)
{
  auto tom = Build(MakeSphere());
  // A substitution pointing to a later vertex would make chains cyclic.
  auto corrupted = vtkSmartPointer<vtkPolyData>::New();
  corrupted->DeepCopy(tom);
  auto* substitution = vtkTypeUInt32Array::SafeDownCast(
    corrupted->GetPointData()->GetArray(vtkTOMFieldData::SubstitutionArrayName()));
  const vtkIdType n = corrupted->GetNumberOfPoints();
  substitution->SetValue(n - 2, static_cast<uint32_t>(n - 1));
  vtkNew<vtkExtractTOMResolution> extract;
  MessageLog log(extract);
  auto out = Extract(corrupted, extract);
  ASSERT_FALSE(log.Errors.empty());
  EXPECT_TRUE(log.ErrorContains("invalid TOM")) << log.Errors[0];
  EXPECT_EQ(out->GetNumberOfPoints(), 0);

  // Counts that disagree with the data.
  corrupted->DeepCopy(tom);
  auto* counts = vtkDataArray::SafeDownCast(
    corrupted->GetFieldData()->GetAbstractArray(vtkTOMFieldData::CountsArrayName()));
  counts->SetTuple1(1, counts->GetTuple1(1) + 1);
  vtkNew<vtkExtractTOMResolution> extract2;
  MessageLog log2(extract2);
  Extract(corrupted, extract2);
  EXPECT_TRUE(log2.ErrorContains("triangles")) << (log2.Errors.empty() ? "" : log2.Errors[0]);

  // Triangles out of prefix order: swap the first and the last triangle.
  corrupted->DeepCopy(tom);
  vtkNew<vtkIdList> first, last;
  corrupted->GetCellPoints(0, first);
  corrupted->GetCellPoints(corrupted->GetNumberOfCells() - 1, last);
  corrupted->ReplaceCell(0, 3, last->GetPointer(0));
  corrupted->ReplaceCell(corrupted->GetNumberOfCells() - 1, 3, first->GetPointer(0));
  vtkNew<vtkExtractTOMResolution> extract3;
  MessageLog log3(extract3);
  Extract(corrupted, extract3);
  EXPECT_TRUE(log3.ErrorContains("invalid TOM"));
}

TEST(vtkExtractTOMResolution, NonFiniteCoordinatesAreAnError)
{
  // Coordinates are checked like the arrays: NaN or infinite points would
  // otherwise come out of every extraction.
  auto tom = Build(MakeSphere());
  for (double bad : { std::numeric_limits<double>::quiet_NaN(),
         -std::numeric_limits<double>::infinity() })
  {
    auto corrupted = vtkSmartPointer<vtkPolyData>::New();
    corrupted->DeepCopy(tom);
    corrupted->GetPoints()->SetPoint(7, 0.0, bad, 0.0);
    vtkNew<vtkExtractTOMResolution> extract;
    MessageLog log(extract);
    auto out = Extract(corrupted, extract);
    EXPECT_TRUE(log.ErrorContains("point 7 has a non-finite")) << log.AllErrors();
    EXPECT_EQ(out->GetNumberOfPoints(), 0);
    EXPECT_EQ(out->GetNumberOfCells(), 0);
  }
}

TEST(vtkExtractTOMResolution, TOMOfNoPointsGivesEmptyOutput)
{
  // Counts 0, 0, 0, 0 and empty arrays but no vtkPoints: a valid TOM of
  // nothing, which once dereferenced the missing points.
  vtkNew<vtkPolyData> nothing;
  vtkNew<vtkTypeUInt32Array> substitution;
  substitution->SetName(vtkTOMFieldData::SubstitutionArrayName());
  nothing->GetPointData()->AddArray(substitution);
  vtkNew<vtkTypeUInt32Array> counts;
  counts->SetName(vtkTOMFieldData::CountsArrayName());
  counts->SetNumberOfValues(4);
  counts->FillValue(0);
  nothing->GetFieldData()->AddArray(counts);
  for (int mode = 0; mode < 3; ++mode)
  {
    vtkNew<vtkExtractTOMResolution> extract;
    MessageLog log(extract);
    if (mode == 0)
    {
      extract->SetResolution(0.5);
    }
    else if (mode == 1)
    {
      extract->SetTargetTriangles(10);
    }
    else
    {
      extract->SetMaximumError(0.1);
    }
    extract->SetInputData(nothing);
    extract->Update();
    EXPECT_TRUE(log.Errors.empty()) << log.AllErrors();
    EXPECT_EQ(extract->GetOutput()->GetNumberOfPoints(), 0);
    EXPECT_EQ(extract->GetOutput()->GetNumberOfCells(), 0);
    EXPECT_EQ(extract->GetExtractedTriangleCount(), 0);
  }
}

TEST(vtkExtractTOMResolution, NaNResolutionIsReported)
{
  vtkNew<vtkExtractTOMResolution> extract;
  MessageLog log(extract);
  extract->SetResolution(std::numeric_limits<double>::quiet_NaN());
  EXPECT_TRUE(log.ErrorContains("NaN"));
  EXPECT_EQ(extract->GetResolution(), 0.0);
}
