// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkCollapseHierarchyBuilder, the superclass of vtkTOMBuilder and
// vtkMergeTreeBuilder: its collapse settings (checks, clamping, defaults of
// the core, what reaches the core) and the input handling both builders share,
// each test run on both builders.
#include "FilterTestSupport.h"
#include "TOMBuilder.h"
#include "MeshIO.h"
#include "vtkCollapseHierarchyBuilder.h"
#include "vtkMergeTreeBuilder.h"
#include "vtkTOMBuilder.h"
#include "vtkTOMFieldData.h"

#include "vtkAppendPolyData.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkReverseSense.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <type_traits>

namespace
{
namespace tt = timecritical::testing;
using tt::MakeSphere;
using tt::MessageLog;
using tt::PointKey;

/// Each typed test runs on both subclasses, named after them.
template <typename Builder>
class vtkCollapseHierarchyBuilderTest : public ::testing::Test
{
  static_assert(std::is_base_of<vtkCollapseHierarchyBuilder, Builder>::value,
    "the builders under test share vtkCollapseHierarchyBuilder");
};

struct BuilderName
{
  template <typename Builder>
  static std::string GetName(int)
  {
    return vtkSmartPointer<Builder>::New()->GetClassName();
  }
};
}

using Builders = ::testing::Types<vtkTOMBuilder, vtkMergeTreeBuilder>;
TYPED_TEST_SUITE(vtkCollapseHierarchyBuilderTest, Builders, BuilderName);

TYPED_TEST(vtkCollapseHierarchyBuilderTest, SettingsRejectNaNAndClamp)
{
  vtkNew<TypeParam> builder;
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

TYPED_TEST(vtkCollapseHierarchyBuilderTest, CoincidentCopiesAreDeduplicated)
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
  vtkNew<TypeParam> builder;
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
  EXPECT_TRUE(warned) << builder->GetClassName();
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

TYPED_TEST(vtkCollapseHierarchyBuilderTest, FeatureEdgeSettingsReachTheCore)
{
  ExpectFeatureEdgeSettingsReachTheCore<TypeParam>();
}
