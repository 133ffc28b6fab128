// SPDX-License-Identifier: BSD-3-Clause
#include "vtkTOMBuilder.h"

#include "TOMBuilder.h"
#include "vtkTOMFieldData.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCleanPolyData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTimerLog.h"
#include "vtkTriangleFilter.h"
#include "vtkTypeInt64Array.h"

#include <cmath>
#include <exception>
#include <vector>

vtkStandardNewMacro(vtkTOMBuilder);

vtkTOMBuilder::vtkTOMBuilder() = default;
vtkTOMBuilder::~vtkTOMBuilder() = default;

int vtkTOMBuilder::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

namespace
{
// Id of the first point with a NaN or infinite coordinate, or -1.
vtkIdType FirstNonFinitePoint(vtkPoints* points)
{
  vtkDataArray* data = points->GetData();
  const vtkIdType n = points->GetNumberOfPoints();
  for (vtkIdType i = 0; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      if (!std::isfinite(data->GetComponent(i, c)))
      {
        return i;
      }
    }
  }
  return -1;
}
}

int vtkTOMBuilder::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  this->NumberOfDroppedCells = 0;
  this->NumberOfMergedPoints = 0;
  this->BuildTime = 0.0;
  if (!input || !output)
  {
    vtkErrorMacro("Missing input or output polydata.");
    return 0;
  }
  if (input->GetNumberOfPoints() == 0 || input->GetNumberOfCells() == 0)
  {
    vtkErrorMacro("Empty input: a TOM needs a surface with points and triangles.");
    return 0;
  }
  if (input->GetNumberOfPolys() == 0 && input->GetNumberOfStrips() == 0)
  {
    vtkErrorMacro("The input has no surface cells (polygons or triangle strips), only "
      << input->GetNumberOfVerts() << " vertices and " << input->GetNumberOfLines()
      << " lines.");
    return 0;
  }
  const vtkIdType badPoint = FirstNonFinitePoint(input->GetPoints());
  if (badPoint >= 0)
  {
    vtkErrorMacro("Point " << badPoint << " has a non-finite (NaN or infinite) coordinate.");
    return 0;
  }
  const vtkIdType nonSurfaceCells = input->GetNumberOfVerts() + input->GetNumberOfLines();
  if (nonSurfaceCells > 0)
  {
    vtkWarningMacro("Dropping " << nonSurfaceCells
                                << " vertex and line cells: a TOM holds triangles only.");
  }

  const double start = vtkTimerLog::GetUniversalTime();

  // Copy of the input surface without verts and lines (whose cell data would
  // otherwise shift), cleaned and triangulated by VTK's own filters.
  vtkNew<vtkPolyData> surface;
  surface->SetPoints(input->GetPoints());
  surface->GetPointData()->PassData(input->GetPointData());
  surface->SetPolys(input->GetPolys());
  surface->SetStrips(input->GetStrips());
  {
    // Cell data of polys then strips, skipping verts and lines.
    vtkCellData* inCD = input->GetCellData();
    vtkCellData* outCD = surface->GetCellData();
    const vtkIdType firstPoly = input->GetNumberOfVerts() + input->GetNumberOfLines();
    const vtkIdType count = input->GetNumberOfPolys() + input->GetNumberOfStrips();
    outCD->CopyAllocate(inCD, count);
    for (vtkIdType i = 0; i < count; ++i)
    {
      outCD->CopyData(inCD, firstPoly + i, i);
    }
  }

  vtkNew<vtkCleanPolyData> clean;
  clean->SetInputData(surface);
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
  this->UpdateProgress(0.05);

  vtkPolyData* triangles = triangulate->GetOutput();
  vtkPolyData* cleaned = clean->GetOutput();
  const vtkIdType degenerate = cleaned->GetNumberOfVerts() + cleaned->GetNumberOfLines();
  if (degenerate > 0)
  {
    vtkWarningMacro("Dropping " << degenerate
                                << " degenerate cells (repeated or coincident points).");
  }
  this->NumberOfDroppedCells = nonSurfaceCells + degenerate;
  this->NumberOfMergedPoints = input->GetNumberOfPoints() - triangles->GetNumberOfPoints();

  const vtkIdType numberOfPoints = triangles->GetNumberOfPoints();
  const vtkIdType numberOfTriangles = triangles->GetNumberOfPolys();
  if (numberOfTriangles == 0)
  {
    vtkErrorMacro("No valid triangle is left after cleaning the input.");
    return 0;
  }
  if (numberOfPoints > static_cast<vtkIdType>(UINT32_MAX) / 2 ||
    numberOfTriangles > static_cast<vtkIdType>(UINT32_MAX) / 4)
  {
    vtkErrorMacro("Too large for 32-bit TOM indices: " << numberOfPoints << " points, "
                                                       << numberOfTriangles << " triangles.");
    return 0;
  }

  std::vector<double> points(3 * static_cast<size_t>(numberOfPoints));
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    triangles->GetPoint(i, &points[3 * static_cast<size_t>(i)]);
  }
  std::vector<uint32_t> ids;
  ids.reserve(3 * static_cast<size_t>(numberOfTriangles));
  {
    auto cells = vtk::TakeSmartPointer(triangles->GetPolys()->NewIterator());
    for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
    {
      vtkIdType size;
      const vtkIdType* cell;
      cells->GetCurrentCell(size, cell);
      for (vtkIdType c = 0; c < size; ++c)
      {
        ids.push_back(static_cast<uint32_t>(cell[c]));
      }
    }
  }

  timecritical::TOMBuildOptions options;
  options.PreserveBoundaries = this->PreserveBoundaries;
  options.PreserveFeatureEdges = this->PreserveFeatureEdges;
  options.FeatureAngle = this->FeatureAngle;
  options.MaximumNormalDeviation = this->MaximumNormalDeviation;
  options.MinimumTriangleQuality = this->MinimumTriangleQuality;
  options.Progress = [this](double fraction) {
    this->UpdateProgress(0.05 + 0.9 * fraction);
    return !this->GetAbortExecute();
  };

  timecritical::TOMBuildResult result;
  try
  {
    result = timecritical::TOMBuilder(options).Build(
      points.data(), static_cast<size_t>(numberOfPoints), ids.data(), ids.size() / 3);
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("TOM construction failed: " << e.what());
    return 0;
  }
  if (result.Aborted)
  {
    // Aborted builds leave an empty output, as VTK filters do.
    return 1;
  }
  if (result.DroppedDegenerateTriangles > 0)
  {
    vtkWarningMacro("Dropping " << result.DroppedDegenerateTriangles << " degenerate triangles.");
    this->NumberOfDroppedCells += static_cast<vtkIdType>(result.DroppedDegenerateTriangles);
  }

  // Points and point data in TOM order.
  const timecritical::TOMMesh& mesh = result.Mesh;
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
    cellOrder->SetId(t, result.TriangleOrder[t]);
  }
  vtkCellData* outCD = output->GetCellData();
  outCD->CopyAllocate(triangles->GetCellData(), tomTriangles);
  outCD->CopyData(triangles->GetCellData(), cellOrder, vtkIdType(0));

  output->GetFieldData()->PassData(input->GetFieldData());
  vtkTOMFieldData::Write(mesh, output);
  this->BuildTime = vtkTimerLog::GetUniversalTime() - start;
  this->UpdateProgress(1.0);
  return 1;
}

void vtkTOMBuilder::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "PreserveBoundaries: " << this->PreserveBoundaries << "\n";
  os << indent << "PreserveFeatureEdges: " << this->PreserveFeatureEdges << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "MaximumNormalDeviation: " << this->MaximumNormalDeviation << "\n";
  os << indent << "MinimumTriangleQuality: " << this->MinimumTriangleQuality << "\n";
  os << indent << "NumberOfDroppedCells: " << this->NumberOfDroppedCells << "\n";
  os << indent << "NumberOfMergedPoints: " << this->NumberOfMergedPoints << "\n";
  os << indent << "BuildTime: " << this->BuildTime << "\n";
}
