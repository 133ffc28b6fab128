// SPDX-License-Identifier: BSD-3-Clause
#include "vtkExtractTOMResolution.h"

#include "TOMFilterSupport.h"

#include "TOMMesh.h"
#include "TOMTraversal.h"
#include "vtkTOMFieldData.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTimerLog.h"
#include "vtkTypeInt64Array.h"

#include <algorithm>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkExtractTOMResolution);

vtkExtractTOMResolution::vtkExtractTOMResolution() = default;
vtkExtractTOMResolution::~vtkExtractTOMResolution() = default;

void vtkExtractTOMResolution::SetResolution(double r)
{
  const double clamped = std::isnan(r) ? 0.0 : std::min(1.0, std::max(0.0, r));
  if (std::isnan(r))
  {
    vtkErrorMacro("Resolution must be a number in [0,1]; NaN given, using 0.");
  }
  if (clamped != this->Resolution || this->SelectionMode != BY_RESOLUTION)
  {
    this->Resolution = clamped;
    this->SelectionMode = BY_RESOLUTION;
    this->Modified();
  }
}

void vtkExtractTOMResolution::SetTargetTriangles(vtkIdType n)
{
  const vtkIdType clamped = std::max<vtkIdType>(0, n);
  if (clamped != this->TargetTriangles || this->SelectionMode != BY_TRIANGLE_COUNT)
  {
    this->TargetTriangles = clamped;
    this->SelectionMode = BY_TRIANGLE_COUNT;
    this->Modified();
  }
}

void vtkExtractTOMResolution::SetMaximumError(double e)
{
  if (std::isnan(e))
  {
    vtkErrorMacro("MaximumError must be a number; NaN ignored.");
    return;
  }
  const double clamped = std::max(0.0, e);
  if (clamped != this->MaximumError || this->SelectionMode != BY_MAXIMUM_ERROR)
  {
    this->MaximumError = clamped;
    this->SelectionMode = BY_MAXIMUM_ERROR;
    this->Modified();
  }
}

int vtkExtractTOMResolution::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkExtractTOMResolution::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  this->ExtractedVertexCount = 0;
  this->ExtractedTriangleCount = 0;
  this->ExtractedError = 0.0;
  const double start = vtkTimerLog::GetUniversalTime();

  if (timecritical::IsEmptyPiece(input))
  {
    // An empty piece (parallel readers give them to ranks without data).
    this->ExtractionTime = vtkTimerLog::GetUniversalTime() - start;
    return 1;
  }
  vtkNew<vtkTOMFieldData> tom;
  if (!tom->Read(input))
  {
    vtkErrorMacro("Input is not a valid Totally Ordered Mesh: " << tom->GetErrorMessage());
    return 0;
  }
  const timecritical::TOMMesh& mesh = tom->GetMesh();
  if (mesh.GetNumberOfVertices() == 0)
  {
    // A valid TOM of nothing (all its counts 0): an empty mesh at every resolution.
    this->ExtractionTime = vtkTimerLog::GetUniversalTime() - start;
    return 1;
  }
  const timecritical::TOMTraversal traversal(mesh);

  uint32_t targetTriangles = mesh.GetNumberOfTriangles();
  switch (this->SelectionMode)
  {
    case BY_RESOLUTION:
      targetTriangles = traversal.GetTrianglesForResolution(this->Resolution);
      break;
    case BY_TRIANGLE_COUNT:
      targetTriangles = static_cast<uint32_t>(
        std::min<vtkIdType>(this->TargetTriangles, mesh.GetNumberOfTriangles()));
      break;
    case BY_MAXIMUM_ERROR:
      if (mesh.ErrorCurve.IsEmpty())
      {
        vtkWarningMacro("The TOM has no error curve; extracting the full mesh.");
      }
      else
      {
        targetTriangles = mesh.ErrorCurve.GetTrianglesForError(this->MaximumError);
      }
      break;
    default:
      break;
  }
  uint32_t vertexCount = traversal.GetVertexCountForTriangles(targetTriangles);
  if (this->SelectionMode == BY_MAXIMUM_ERROR && targetTriangles > 0 &&
    targetTriangles < mesh.GetNumberOfTriangles())
  {
    // The error bound needs at least targetTriangles triangles: take the
    // coarsest mesh in which triangle targetTriangles-1 is still alive.
    vertexCount = std::max(vertexCount, traversal.GetMinimumVertexCount(targetTriangles - 1));
  }
  std::vector<uint32_t> indices;
  const uint32_t triangleCount = traversal.Extract(vertexCount, indices);

  // Active points are a prefix of the TOM's points.
  vtkNew<vtkPoints> points;
  points->SetDataType(input->GetPoints()->GetDataType());
  points->GetData()->InsertTuples(0, vertexCount, 0, input->GetPoints()->GetData());
  output->SetPoints(points);
  vtkPointData* outPD = output->GetPointData();
  outPD->CopyFieldOff(vtkTOMFieldData::SubstitutionArrayName());
  outPD->CopyAllocate(input->GetPointData(), vertexCount);
  if (vertexCount > 0)
  {
    outPD->CopyData(input->GetPointData(), 0, vertexCount, 0);
  }

  if (this->GeomorphFactor < 1.0 && vertexCount > mesh.BaseVertexCount)
  {
    // Smooth transition: blend the last active vertex toward the vertex it
    // substitutes to once it is gone.
    const vtkIdType last = vertexCount - 1;
    const vtkIdType target = traversal.GetActiveVertex(mesh.Substitution[last], vertexCount - 1);
    double from[3], to[3], blended[3];
    input->GetPoint(target, from);
    input->GetPoint(last, to);
    for (int c = 0; c < 3; ++c)
    {
      blended[c] = from[c] + this->GeomorphFactor * (to[c] - from[c]);
    }
    points->SetPoint(last, blended);
    outPD->InterpolateEdge(input->GetPointData(), last, target, last, this->GeomorphFactor);
  }

  // Triangles of this resolution are a prefix of the input cells.
  vtkNew<vtkTypeInt64Array> offsets;
  vtkNew<vtkTypeInt64Array> connectivity;
  offsets->SetNumberOfValues(static_cast<vtkIdType>(triangleCount) + 1);
  connectivity->SetNumberOfValues(3 * static_cast<vtkIdType>(triangleCount));
  for (vtkIdType t = 0; t <= static_cast<vtkIdType>(triangleCount); ++t)
  {
    offsets->SetValue(t, 3 * t);
  }
  for (vtkIdType i = 0; i < 3 * static_cast<vtkIdType>(triangleCount); ++i)
  {
    connectivity->SetValue(i, indices[i]);
  }
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  output->SetPolys(polys);
  vtkCellData* outCD = output->GetCellData();
  outCD->CopyAllocate(input->GetCellData(), triangleCount);
  if (triangleCount > 0)
  {
    outCD->CopyData(input->GetCellData(), 0, triangleCount, 0);
  }

  // Ordinary field data passes; the TOM's own arrays describe the input only.
  output->GetFieldData()->PassData(input->GetFieldData());
  output->GetFieldData()->RemoveArray(vtkTOMFieldData::CountsArrayName());
  output->GetFieldData()->RemoveArray(vtkTOMFieldData::ErrorCurveArrayName());

  this->ExtractedVertexCount = vertexCount;
  this->ExtractedTriangleCount = triangleCount;
  this->ExtractedError =
    mesh.ErrorCurve.IsEmpty() ? 0.0 : mesh.ErrorCurve.GetErrorForTriangles(triangleCount);
  this->ExtractionTime = vtkTimerLog::GetUniversalTime() - start;
  return 1;
}

void vtkExtractTOMResolution::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SelectionMode: " << this->SelectionMode << "\n";
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "TargetTriangles: " << this->TargetTriangles << "\n";
  os << indent << "MaximumError: " << this->MaximumError << "\n";
  os << indent << "GeomorphFactor: " << this->GeomorphFactor << "\n";
  os << indent << "ExtractedVertexCount: " << this->ExtractedVertexCount << "\n";
  os << indent << "ExtractedTriangleCount: " << this->ExtractedTriangleCount << "\n";
  os << indent << "ExtractedError: " << this->ExtractedError << "\n";
}
