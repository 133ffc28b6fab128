// SPDX-License-Identifier: BSD-3-Clause
#include "TOMFilterSupport.h"

#include "TOMBuilder.h"

#include "vtkAlgorithm.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCleanPolyData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataValidator.h"
#include "vtkSetGet.h"
#include "vtkTriangleFilter.h"
#include "vtkTypeInt64Array.h"

#include <cmath>
#include <string>

namespace timecritical
{
SurfaceStatus PrepareSurface(vtkAlgorithm* filter, vtkPolyData* input, PreparedSurface& surface)
{
  surface = PreparedSurface();
  if (IsEmptyPiece(input))
  {
    return SurfaceStatus::Empty;
  }
  if (input->GetNumberOfPolys() == 0 && input->GetNumberOfStrips() == 0)
  {
    vtkErrorWithObjectMacro(filter,
      "The input has no surface cells (polygons or triangle strips), only "
        << input->GetNumberOfVerts() << " vertices and " << input->GetNumberOfLines()
        << " lines.");
    return SurfaceStatus::Failed;
  }
  const vtkIdType numberOfInputPoints = input->GetNumberOfPoints();
  const vtkIdType firstPoly = input->GetNumberOfVerts() + input->GetNumberOfLines();
  // VTK's cleaning filters would read out of bounds on bad point ids; the
  // cores would refuse coordinates beyond their limit.
  const std::string problem = vtkPolyDataValidator::CheckBuildInput(input);
  if (!problem.empty())
  {
    vtkErrorWithObjectMacro(filter, "Bad input: " << problem << ".");
    return SurfaceStatus::Failed;
  }
  const vtkIdType nonSurfaceCells = firstPoly;
  if (nonSurfaceCells > 0)
  {
    vtkWarningWithObjectMacro(filter,
      "Dropping " << nonSurfaceCells << " vertex and line cells: a TOM holds triangles only.");
  }

  // Copy of the input surface without verts and lines (whose cell data would
  // otherwise shift), cleaned and triangulated by VTK's own filters.
  vtkNew<vtkPolyData> polys;
  polys->SetPoints(input->GetPoints());
  polys->GetPointData()->PassData(input->GetPointData());
  polys->SetPolys(input->GetPolys());
  polys->SetStrips(input->GetStrips());
  {
    // Cell data of polys then strips, skipping verts and lines.
    vtkCellData* inCD = input->GetCellData();
    vtkCellData* outCD = polys->GetCellData();
    const vtkIdType count = input->GetNumberOfPolys() + input->GetNumberOfStrips();
    outCD->CopyAllocate(inCD, count);
    for (vtkIdType i = 0; i < count; ++i)
    {
      outCD->CopyData(inCD, firstPoly + i, i);
    }
  }

  vtkNew<vtkCleanPolyData> clean;
  clean->SetInputData(polys);
  clean->PointMergingOn();
  clean->SetTolerance(0.0);
  clean->SetAbsoluteTolerance(0.0);
  clean->ToleranceIsAbsoluteOn();
  clean->ConvertLinesToPointsOff();
  clean->ConvertPolysToLinesOn();
  clean->ConvertStripsToPolysOn();
  vtkNew<vtkTriangleFilter> triangulate;
  triangulate->SetInputConnection(clean->GetOutputPort());
  triangulate->PassVertsOff();
  triangulate->PassLinesOff();
  triangulate->Update();
  filter->UpdateProgress(0.05);

  vtkPolyData* triangles = triangulate->GetOutput();
  vtkPolyData* cleaned = clean->GetOutput();
  const vtkIdType degenerate = cleaned->GetNumberOfVerts() + cleaned->GetNumberOfLines();
  if (degenerate > 0)
  {
    // Zero-area triangles (isosurfaces have a few): nothing visible is lost,
    // so no warning; NumberOfDroppedCells counts them.
    vtkDebugWithObjectMacro(
      filter, "Dropping " << degenerate << " degenerate cells (repeated or coincident points).");
  }
  surface.NumberOfDroppedCells = nonSurfaceCells + degenerate;
  surface.NumberOfMergedPoints = numberOfInputPoints - triangles->GetNumberOfPoints();

  const vtkIdType numberOfPoints = triangles->GetNumberOfPoints();
  const vtkIdType numberOfTriangles = triangles->GetNumberOfPolys();
  if (numberOfTriangles == 0)
  {
    vtkErrorWithObjectMacro(filter, "No valid triangle is left after cleaning the input.");
    return SurfaceStatus::Failed;
  }
  if (numberOfPoints > static_cast<vtkIdType>(UINT32_MAX) / 2 ||
    numberOfTriangles > static_cast<vtkIdType>(UINT32_MAX) / 4)
  {
    vtkErrorWithObjectMacro(filter, "Too large for 32-bit TOM indices: "
        << numberOfPoints << " points, " << numberOfTriangles << " triangles.");
    return SurfaceStatus::Failed;
  }

  surface.Triangles = triangles;
  surface.Points.resize(3 * static_cast<size_t>(numberOfPoints));
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    triangles->GetPoint(i, &surface.Points[3 * static_cast<size_t>(i)]);
  }
  surface.Ids.reserve(3 * static_cast<size_t>(numberOfTriangles));
  surface.Cells.reserve(static_cast<size_t>(numberOfTriangles));
  auto cells = vtk::TakeSmartPointer(triangles->GetPolys()->NewIterator());
  vtkIdType cellId = 0;
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell(), ++cellId)
  {
    vtkIdType size;
    const vtkIdType* cell;
    cells->GetCurrentCell(size, cell);
    for (vtkIdType c = 0; c < size; ++c)
    {
      surface.Ids.push_back(static_cast<uint32_t>(cell[c]));
    }
    surface.Cells.push_back(cellId);
  }
  return SurfaceStatus::Ready;
}

std::function<bool(double)> CoreProgress(vtkAlgorithm* filter)
{
  return [filter](double fraction) {
    filter->UpdateProgress(0.05 + 0.9 * fraction);
    return !filter->GetAbortExecute();
  };
}

void WriteOrderedSurface(vtkAlgorithm* filter, vtkPolyData* input, PreparedSurface& surface,
  const TOMBuildResult& result, vtkPolyData* output)
{
  if (result.DroppedDegenerateTriangles > 0)
  {
    vtkWarningWithObjectMacro(
      filter, "Dropping " << result.DroppedDegenerateTriangles << " degenerate triangles.");
    surface.NumberOfDroppedCells += static_cast<vtkIdType>(result.DroppedDegenerateTriangles);
  }
  if (result.DroppedDuplicateTriangles > 0)
  {
    vtkWarningWithObjectMacro(filter, "Dropping " << result.DroppedDuplicateTriangles
                                                  << " duplicate triangles (the same three points "
                                                     "as an earlier triangle).");
    surface.NumberOfDroppedCells += static_cast<vtkIdType>(result.DroppedDuplicateTriangles);
  }
  vtkPolyData* triangles = surface.Triangles;

  // Points and point data in TOM order.
  const TOMMesh& mesh = result.Mesh;
  const vtkIdType tomPoints = mesh.GetNumberOfVertices();
  vtkNew<vtkIdList> pointOrder;
  pointOrder->SetNumberOfIds(tomPoints);
  for (vtkIdType i = 0; i < tomPoints; ++i)
  {
    pointOrder->SetId(i, result.VertexOrder[i]);
  }
  vtkNew<vtkPoints> outPoints;
  outPoints->SetDataType(triangles->GetPoints()->GetDataType());
  outPoints->SetNumberOfPoints(tomPoints);
  triangles->GetPoints()->GetPoints(pointOrder, outPoints);
  output->SetPoints(outPoints);
  vtkPointData* outPD = output->GetPointData();
  outPD->CopyAllocate(triangles->GetPointData(), tomPoints);
  outPD->CopyData(triangles->GetPointData(), pointOrder, vtkIdType(0));

  // Triangles and cell data in TOM order.
  const vtkIdType tomTriangles = mesh.GetNumberOfTriangles();
  vtkNew<vtkCellArray> polys;
  {
    vtkNew<vtkTypeInt64Array> offsets;
    vtkNew<vtkTypeInt64Array> connectivity;
    offsets->SetNumberOfValues(tomTriangles + 1);
    connectivity->SetNumberOfValues(3 * tomTriangles);
    for (vtkIdType t = 0; t <= tomTriangles; ++t)
    {
      offsets->SetValue(t, 3 * t);
    }
    for (vtkIdType i = 0; i < 3 * tomTriangles; ++i)
    {
      connectivity->SetValue(i, mesh.Triangles[i]);
    }
    polys->SetData(offsets, connectivity);
  }
  output->SetPolys(polys);
  vtkNew<vtkIdList> cellOrder;
  cellOrder->SetNumberOfIds(tomTriangles);
  for (vtkIdType t = 0; t < tomTriangles; ++t)
  {
    cellOrder->SetId(t, surface.Cells[result.TriangleOrder[t]]);
  }
  vtkCellData* outCD = output->GetCellData();
  outCD->CopyAllocate(triangles->GetCellData(), tomTriangles);
  outCD->CopyData(triangles->GetCellData(), cellOrder, vtkIdType(0));

  output->GetFieldData()->PassData(input->GetFieldData());
}

bool SetClampedSetting(vtkObject* object, const char* name, double value, double minimum,
  double maximum, double& member)
{
  if (std::isnan(value))
  {
    vtkErrorWithObjectMacro(object, << name << " must be a number in [" << minimum << ", "
                                    << maximum << "]; NaN ignored.");
    return false;
  }
  const double clamped = value < minimum ? minimum : (value > maximum ? maximum : value);
  if (clamped == member)
  {
    return false;
  }
  member = clamped;
  return true;
}

bool IsEmptyPiece(vtkPolyData* data)
{
  return !data || (data->GetNumberOfPoints() == 0 && data->GetNumberOfCells() == 0);
}

bool IsIntegerType(int type)
{
  switch (type)
  {
    case VTK_CHAR:
    case VTK_SIGNED_CHAR:
    case VTK_UNSIGNED_CHAR:
    case VTK_SHORT:
    case VTK_UNSIGNED_SHORT:
    case VTK_INT:
    case VTK_UNSIGNED_INT:
    case VTK_LONG:
    case VTK_UNSIGNED_LONG:
    case VTK_LONG_LONG:
    case VTK_UNSIGNED_LONG_LONG:
    case VTK_ID_TYPE:
      return true;
    default:
      return false;
  }
}
}
