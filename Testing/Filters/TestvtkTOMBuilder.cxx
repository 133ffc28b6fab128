// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkTOMBuilder: the TOM it builds, its input handling and errors,
// abort, saving and reading back. The collapse settings it shares with
// vtkMergeTreeBuilder are tested in TestvtkCollapseHierarchyBuilder.cxx.
#include "FilterTestSupport.h"
#include "TOMMesh.h"
#include "vtkExtractTOMResolution.h"
#include "vtkTOMBuilder.h"
#include "vtkTOMFieldData.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkTypeUInt32Array.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>

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
  // The line is content lost: a warning. The zero-area triangle is not.
  ASSERT_EQ(log.Warnings.size(), 1u);
  EXPECT_NE(log.Warnings[0].find("vertex and line cells"), std::string::npos) << log.Warnings[0];
  EXPECT_EQ(tom->GetNumberOfPoints(), 4);
  EXPECT_EQ(tom->GetNumberOfPolys(), 2);
  EXPECT_EQ(builder->GetNumberOfMergedPoints(), 2);
  EXPECT_EQ(builder->GetNumberOfDroppedCells(), 2);
}

TEST(vtkTOMBuilder, ZeroAreaTrianglesAreDroppedWithoutAWarning)
{
  auto data = tt::DuplicatePointsAndDegenerateCells();
  data->SetLines(nullptr);
  vtkNew<vtkTOMBuilder> builder;
  MessageLog log(builder);
  auto tom = Build(data, builder);
  EXPECT_TRUE(log.Errors.empty());
  EXPECT_TRUE(log.Warnings.empty()) << log.Warnings[0];
  EXPECT_EQ(tom->GetNumberOfPolys(), 2);
  EXPECT_EQ(builder->GetNumberOfDroppedCells(), 1);
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

//------------------------------------------------------------------------------
// Pair contraction: separate parts joined at the coarsest resolutions

namespace
{
/// side x side x side closed spheres (vtkSphereSource, radius 0.5, 8 x 8
/// facets), centres `spacing` apart: separate parts, no point shared.
vtkSmartPointer<vtkPolyData> SphereField(int side, double spacing)
{
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(8);
  source->SetPhiResolution(8);
  source->Update();
  vtkPolyData* sphere = source->GetOutput();
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> polys;
  for (int i = 0; i < side * side * side; ++i)
  {
    const double centre[3] = { spacing * (i % side), spacing * ((i / side) % side),
      spacing * (i / (side * side)) };
    const vtkIdType offset = points->GetNumberOfPoints();
    for (vtkIdType p = 0; p < sphere->GetNumberOfPoints(); ++p)
    {
      double x[3];
      sphere->GetPoint(p, x);
      points->InsertNextPoint(x[0] + centre[0], x[1] + centre[1], x[2] + centre[2]);
    }
    for (vtkIdType c = 0; c < sphere->GetNumberOfCells(); ++c)
    {
      vtkIdType n = 0;
      const vtkIdType* ids = nullptr;
      sphere->GetCellPoints(c, n, ids);
      polys->InsertNextCell({ ids[0] + offset, ids[1] + offset, ids[2] + offset });
    }
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(points);
  out->SetPolys(polys);
  return out;
}

struct BuiltTOM
{
  vtkSmartPointer<vtkPolyData> Data;
  vtkIdType BaseVertices = 0;
  vtkIdType BaseTriangles = 0;
  vtkIdType JoinedParts = 0;
};

/// A TOM of `input` with that pair contraction distance, validated.
BuiltTOM BuildWithPairs(vtkPolyData* input, double distance)
{
  vtkNew<vtkTOMBuilder> builder;
  builder->SetPairContractionDistance(distance);
  BuiltTOM built;
  built.Data = Build(input, builder);
  vtkNew<vtkTOMFieldData> reader;
  EXPECT_TRUE(reader->Read(built.Data)) << reader->GetErrorMessage();
  built.BaseVertices = reader->GetBaseVertexCount();
  built.BaseTriangles = reader->GetBaseTriangleCount();
  built.JoinedParts = builder->GetNumberOfJoinedParts();
  return built;
}

/// The level of `tom` with `triangles` triangles (its points: a prefix, TOM ids).
vtkSmartPointer<vtkPolyData> LevelOf(vtkPolyData* tom, vtkIdType triangles)
{
  vtkNew<vtkExtractTOMResolution> extract;
  extract->SetTargetTriangles(triangles);
  return tt::RunFilter(tom, extract.Get());
}

/// The edges of a level used other than twice (boundary or non-manifold).
std::vector<std::pair<vtkIdType, vtkIdType>> OddEdges(vtkPolyData* level)
{
  std::map<std::pair<vtkIdType, vtkIdType>, int> uses;
  for (vtkIdType c = 0; c < level->GetNumberOfCells(); ++c)
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    level->GetCellPoints(c, n, ids);
    for (vtkIdType k = 0; k < n; ++k)
    {
      const vtkIdType a = ids[k], b = ids[(k + 1) % n];
      ++uses[{ std::min(a, b), std::max(a, b) }];
    }
  }
  std::vector<std::pair<vtkIdType, vtkIdType>> odd;
  for (const auto& entry : uses)
  {
    if (entry.second != 2)
    {
      odd.push_back(entry.first);
    }
  }
  return odd;
}
}

TEST(vtkTOMBuilder, PairContractionIsOffByDefault)
{
  vtkNew<vtkTOMBuilder> builder;
  EXPECT_EQ(builder->GetPairContractionDistance(), 0.0);
  auto field = SphereField(2, 1.5);
  const BuiltTOM byDefault = BuildWithPairs(field, 0.0);
  EXPECT_EQ(byDefault.JoinedParts, 0);
  EXPECT_EQ(byDefault.BaseTriangles, 8 * 4) << "a tetrahedron per sphere";
}

TEST(vtkTOMBuilder, PairContractionJoinsManySeparateSpheres)
{
  // 27 spheres of diameter 1, centres 1.5 apart (gaps of 0.5, a diagonal of
  // 6.9): without pairs each keeps a tetrahedron; with pairs within half
  // the diagonal they end as one part (within 0.25 of it, 1.7, two parts are
  // left: a joined part's surviving vertex may be farther from the next part).
  auto field = SphereField(3, 1.5);
  const BuiltTOM off = BuildWithPairs(field, 0.0);
  const BuiltTOM on = BuildWithPairs(field, 0.5);
  const BuiltTOM nearer = BuildWithPairs(field, 0.25);
  EXPECT_EQ(nearer.JoinedParts, 25);
  EXPECT_EQ(nearer.BaseTriangles, 8);
  EXPECT_EQ(off.BaseTriangles, 27 * 4);
  EXPECT_EQ(off.BaseVertices, 27 * 4);
  EXPECT_EQ(on.JoinedParts, 26);
  EXPECT_LE(on.BaseTriangles, 4);
  EXPECT_EQ(on.Data->GetNumberOfPolys(), field->GetNumberOfPolys());
  EXPECT_EQ(on.Data->GetNumberOfPoints(), field->GetNumberOfPoints());

  // Prefix property: each substitution goes to an earlier vertex, and every
  // level above the old coarsest one is the same as without pairs.
  auto* substitution = vtkTypeUInt32Array::SafeDownCast(
    on.Data->GetPointData()->GetArray(vtkTOMFieldData::SubstitutionArrayName()));
  ASSERT_NE(substitution, nullptr);
  for (vtkIdType i = on.BaseVertices; i < on.Data->GetNumberOfPoints(); ++i)
  {
    ASSERT_LT(substitution->GetValue(i), static_cast<uint32_t>(i)) << i;
  }
  for (vtkIdType i = off.BaseVertices; i < on.Data->GetNumberOfPoints(); ++i)
  {
    ASSERT_EQ(PointKey(on.Data, i), PointKey(off.Data, i)) << i;
  }

  // Manifold where the input was, except where parts join: at every level
  // down to the old coarsest one, no edge is used other than twice; below,
  // such an edge only ends at a vertex that parts were joined into.
  std::set<vtkIdType> targets;
  for (vtkIdType i = on.BaseVertices; i < off.BaseVertices; ++i)
  {
    targets.insert(static_cast<vtkIdType>(substitution->GetValue(i)));
  }
  const vtkIdType total = field->GetNumberOfPolys();
  for (vtkIdType triangles :
    { total, total / 2, total / 10, total / 20, off.BaseTriangles, vtkIdType(60), vtkIdType(20),
      on.BaseTriangles })
  {
    auto level = LevelOf(on.Data, triangles);
    const auto odd = OddEdges(level);
    if (level->GetNumberOfPolys() >= off.BaseTriangles)
    {
      EXPECT_TRUE(odd.empty()) << odd.size() << " odd edges at " << triangles << " triangles";
    }
    for (const auto& edge : odd)
    {
      EXPECT_TRUE(targets.count(edge.first) || targets.count(edge.second))
        << "edge " << edge.first << "-" << edge.second << " at " << triangles << " triangles";
    }
  }
}

TEST(vtkTOMBuilder, PairContractionKeepsDistantSpheresApart)
{
  // Gaps of 4 in a diagonal of 15.6: 0.05 of it (0.78) reaches no other sphere.
  auto field = SphereField(2, 4.5);
  const BuiltTOM near = BuildWithPairs(field, 0.05);
  EXPECT_EQ(near.JoinedParts, 0);
  EXPECT_EQ(near.BaseTriangles, 8 * 4);
  const BuiltTOM all = BuildWithPairs(field, 1.0);
  EXPECT_EQ(all.JoinedParts, 7);
  EXPECT_LE(all.BaseTriangles, 4);
}

TEST(vtkTOMBuilder, BadPairContractionDistanceIsAnError)
{
  vtkNew<vtkTOMBuilder> builder;
  builder->SetPairContractionDistance(0.25);
  const vtkMTimeType mtime = builder->GetMTime();
  MessageLog log(builder);
  for (double bad : { -0.1, 1.5, std::numeric_limits<double>::quiet_NaN(),
         std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity() })
  {
    builder->SetPairContractionDistance(bad);
    EXPECT_EQ(builder->GetPairContractionDistance(), 0.25) << bad;
  }
  ASSERT_EQ(log.Errors.size(), 5u);
  for (const std::string& error : log.Errors)
  {
    EXPECT_NE(error.find("PairContractionDistance"), std::string::npos) << error;
  }
  EXPECT_EQ(builder->GetMTime(), mtime) << "a rejected value must not modify the filter";
  // The ends of the range are accepted.
  builder->SetPairContractionDistance(1.0);
  EXPECT_EQ(builder->GetPairContractionDistance(), 1.0);
  builder->SetPairContractionDistance(0.0);
  EXPECT_EQ(builder->GetPairContractionDistance(), 0.0);
  EXPECT_EQ(log.Errors.size(), 5u);
}

TEST(vtkTOMBuilder, PrintSelfShowsPairContraction)
{
  vtkNew<vtkTOMBuilder> builder;
  builder->SetPairContractionDistance(0.5);
  Build(SphereField(2, 1.5), builder);
  std::ostringstream text;
  builder->Print(text);
  EXPECT_NE(text.str().find("PairContractionDistance: 0.5"), std::string::npos) << text.str();
  EXPECT_NE(text.str().find("NumberOfJoinedParts: 7"), std::string::npos) << text.str();
}
