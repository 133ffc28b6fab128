// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkPolyDataValidator: point ids out of range in each kind of cell,
// non-finite coordinates in float, double and other point arrays, and the
// builders' limit on coordinate magnitude, each with its message.
#include "FilterTestSupport.h"
#include "TOMBuilder.h"
#include "vtkPolyDataValidator.h"

#include "vtkCellArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace
{
/// Three points and one cell of each kind: vertex 0, line 1, triangle 2, strip 3.
vtkSmartPointer<vtkPolyData> OneCellOfEachKind(int pointType = VTK_FLOAT)
{
  auto data = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataType(pointType);
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0, 1, 0);
  data->SetPoints(points);
  vtkNew<vtkCellArray> verts, lines, polys, strips;
  verts->InsertNextCell({ 0 });
  lines->InsertNextCell({ 0, 1 });
  polys->InsertNextCell({ 0, 1, 2 });
  strips->InsertNextCell({ 0, 1, 2 });
  data->SetVerts(verts);
  data->SetLines(lines);
  data->SetPolys(polys);
  data->SetStrips(strips);
  return data;
}

/// `data` with cell `kind` (0 verts, 1 lines, 2 polys, 3 strips) replaced by `ids`.
void ReplaceCell(vtkPolyData* data, int kind, const std::vector<vtkIdType>& ids)
{
  vtkNew<vtkCellArray> cells;
  cells->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  switch (kind)
  {
    case 0:
      data->SetVerts(cells);
      break;
    case 1:
      data->SetLines(cells);
      break;
    case 2:
      data->SetPolys(cells);
      break;
    default:
      data->SetStrips(cells);
  }
}
}

TEST(vtkPolyDataValidator, ValidAndNullDataPass)
{
  EXPECT_EQ(vtkPolyDataValidator::Check(nullptr), "");
  EXPECT_EQ(vtkPolyDataValidator::CheckBuildInput(nullptr), "");
  EXPECT_EQ(vtkPolyDataValidator::CheckPointIds(nullptr), "");
  EXPECT_EQ(vtkPolyDataValidator::CheckCoordinates(nullptr), "");
  EXPECT_EQ(vtkPolyDataValidator::FirstNonFinitePoint(nullptr), -1);
  EXPECT_EQ(vtkPolyDataValidator::FirstPointBeyond(nullptr, 1.0), -1);
  auto data = OneCellOfEachKind();
  EXPECT_EQ(vtkPolyDataValidator::Check(data), "");
  EXPECT_EQ(vtkPolyDataValidator::CheckBuildInput(data), "");
  EXPECT_EQ(vtkPolyDataValidator::Check(timecritical::testing::MakeSphere(10)), "");
  vtkNew<vtkPolyData> empty;
  EXPECT_EQ(vtkPolyDataValidator::Check(empty), "");
  EXPECT_EQ(vtkPolyDataValidator::CheckBuildInput(empty), "");
}

TEST(vtkPolyDataValidator, OutOfRangeIdsAreNamedWithTheirCell)
{
  // Cells are numbered as vtkPolyData numbers them: vertices, lines, polygons, strips.
  const std::string expected[4] = {
    "cell 0 refers to point 3, but the data has 3 points",
    "cell 1 refers to point -5, but the data has 3 points",
    "cell 2 refers to point 7, but the data has 3 points",
    "cell 3 refers to point 3, but the data has 3 points",
  };
  const std::vector<vtkIdType> bad[4] = { { 3 }, { 0, -5 }, { 0, 7, 1 }, { 0, 1, 3 } };
  for (int kind = 0; kind < 4; ++kind)
  {
    auto data = OneCellOfEachKind();
    ReplaceCell(data, kind, bad[kind]);
    EXPECT_EQ(vtkPolyDataValidator::CheckPointIds(data), expected[kind]) << kind;
    EXPECT_EQ(vtkPolyDataValidator::Check(data), expected[kind]) << kind;
    EXPECT_EQ(vtkPolyDataValidator::CheckBuildInput(data), expected[kind]) << kind;
  }
  // Cells but no points at all.
  auto pointless = OneCellOfEachKind();
  pointless->SetPoints(nullptr);
  EXPECT_EQ(vtkPolyDataValidator::Check(pointless), "cell 0 refers to point 0, but the data has 0 points");
}

TEST(vtkPolyDataValidator, NonFiniteCoordinatesInEveryPointType)
{
  for (int type : { VTK_FLOAT, VTK_DOUBLE, VTK_INT })
  {
    auto data = OneCellOfEachKind(type);
    EXPECT_EQ(vtkPolyDataValidator::FirstNonFinitePoint(data->GetPoints()), -1) << type;
    if (type == VTK_INT)
    {
      // Integers are always finite; the generic path still finds large values.
      data->GetPoints()->SetPoint(2, 0, 100, 0);
      EXPECT_EQ(vtkPolyDataValidator::FirstPointBeyond(data->GetPoints(), 50.0), 2);
      EXPECT_EQ(vtkPolyDataValidator::FirstPointBeyond(data->GetPoints(), 100.0), -1);
      continue;
    }
    for (double bad : { std::numeric_limits<double>::quiet_NaN(),
           std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity() })
    {
      data->GetPoints()->SetPoint(1, 0, 0, bad);
      EXPECT_EQ(vtkPolyDataValidator::FirstNonFinitePoint(data->GetPoints()), 1) << type;
      EXPECT_EQ(vtkPolyDataValidator::FirstPointBeyond(data->GetPoints(), 1e300), 1) << type;
      const std::string message = "point 1 has a non-finite (NaN or infinite) coordinate";
      EXPECT_EQ(vtkPolyDataValidator::CheckCoordinates(data->GetPoints()), message) << type;
      EXPECT_EQ(vtkPolyDataValidator::Check(data), message) << type;
      EXPECT_EQ(vtkPolyDataValidator::CheckBuildInput(data), message) << type;
    }
    // Out-of-range ids are reported before coordinates.
    ReplaceCell(data, 2, { 0, 1, 9 });
    EXPECT_EQ(vtkPolyDataValidator::Check(data), "cell 2 refers to point 9, but the data has 3 points");
  }
}

TEST(vtkPolyDataValidator, BuildInputRejectsCoordinatesBeyondTheCoresLimit)
{
  const double limit = timecritical::MaximumCoordinateMagnitude;
  auto data = OneCellOfEachKind(VTK_DOUBLE);
  data->GetPoints()->SetPoint(2, 0, limit, -limit);
  EXPECT_EQ(vtkPolyDataValidator::CheckBuildInput(data), "") << "the limit itself is allowed";
  data->GetPoints()->SetPoint(2, 0, -2.2e38, 0);
  std::ostringstream limitText;
  limitText << limit;
  EXPECT_EQ(vtkPolyDataValidator::CheckBuildInput(data),
    "point 2 has a coordinate of magnitude 2.2e+38, beyond the supported " + limitText.str() +
      " (errors and radii are stored as float); scale the data");
  // Finite: Check() itself accepts it.
  EXPECT_EQ(vtkPolyDataValidator::Check(data), "");
  EXPECT_EQ(vtkPolyDataValidator::FirstNonFinitePoint(data->GetPoints()), -1);
  EXPECT_EQ(vtkPolyDataValidator::FirstPointBeyond(data->GetPoints(), limit), 2);
}

TEST(vtkPolyDataValidator, NewAndPrint)
{
  vtkNew<vtkPolyDataValidator> validator;
  std::ostringstream print;
  validator->Print(print);
  EXPECT_NE(print.str().find("vtkPolyDataValidator"), std::string::npos) << print.str();
}
