// SPDX-License-Identifier: BSD-3-Clause
#include "vtkExtractViewDependentMesh.h"

#include "MergeTree.h"
#include "RefinementSettingChecks.h"
#include "RefinementSettings.h"
#include "RefinementViewFromCamera.h"
#include "TOMMesh.h"
#include "ViewDependentRefinement.h"
#include "vtkMergeTreeFieldData.h"
#include "vtkTOMFieldData.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTimerLog.h"
#include "vtkTypeInt64Array.h"
#include "vtkTypeUInt16Array.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <vector>

struct vtkExtractViewDependentMesh::Internals
{
  timecritical::ViewDependentRefinement Refinement;
  vtkNew<vtkMergeTreeFieldData> Reader;
  // The input the refinement was initialized from: its address (never
  // dereferenced) and modification time; either changing means a new input.
  const vtkPolyData* Source = nullptr;
  vtkMTimeType SourceTime = 0;
  bool Initialized = false;
  // Scratch reused between executions.
  std::vector<uint32_t> DisplayAncestor;
  std::vector<vtkIdType> OutputPoint;
};

static_assert(vtkExtractViewDependentMesh::BUDGET == timecritical::RefinementModeBudget &&
    vtkExtractViewDependentMesh::FIXED_ACCURACY == timecritical::RefinementModeFixedAccuracy,
  "one numbering of the refinement modes (RefinementSettings.h)");

vtkStandardNewMacro(vtkExtractViewDependentMesh);

vtkExtractViewDependentMesh::vtkExtractViewDependentMesh()
  : Camera(vtkSmartPointer<vtkCamera>::New())
  , Internal(new Internals)
{
}

vtkExtractViewDependentMesh::~vtkExtractViewDependentMesh() = default;

void vtkExtractViewDependentMesh::SetCamera(vtkCamera* camera)
{
  if (camera && camera == this->Camera)
  {
    return;
  }
  if (camera)
  {
    this->Camera = camera;
  }
  else
  {
    this->Camera = vtkSmartPointer<vtkCamera>::New();
  }
  this->Modified();
}

vtkCamera* vtkExtractViewDependentMesh::GetCamera()
{
  return this->Camera;
}

namespace
{
bool AllFinite(std::initializer_list<double> values)
{
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}
}

void vtkExtractViewDependentMesh::SetCameraPosition(double x, double y, double z)
{
  if (!AllFinite({ x, y, z }))
  {
    vtkErrorMacro("CameraPosition must be finite; (" << x << ", " << y << ", " << z
                                                     << ") ignored.");
    return;
  }
  this->Camera->SetPosition(x, y, z);
}

void vtkExtractViewDependentMesh::SetCameraFocalPoint(double x, double y, double z)
{
  if (!AllFinite({ x, y, z }))
  {
    vtkErrorMacro("CameraFocalPoint must be finite; (" << x << ", " << y << ", " << z
                                                       << ") ignored.");
    return;
  }
  this->Camera->SetFocalPoint(x, y, z);
}

void vtkExtractViewDependentMesh::SetCameraViewUp(double x, double y, double z)
{
  if (!AllFinite({ x, y, z }) || (x == 0.0 && y == 0.0 && z == 0.0))
  {
    vtkErrorMacro("CameraViewUp must be a finite, non-zero vector; (" << x << ", " << y << ", "
                                                                      << z << ") ignored.");
    return;
  }
  this->Camera->SetViewUp(x, y, z);
}

void vtkExtractViewDependentMesh::SetCameraViewAngle(double degrees)
{
  if (!(degrees > 0.0 && degrees < 180.0))
  {
    vtkErrorMacro("CameraViewAngle must be in (0, 180) degrees; " << degrees << " ignored.");
    return;
  }
  this->Camera->SetViewAngle(degrees);
}

void vtkExtractViewDependentMesh::SetCameraParallelProjection(bool parallel)
{
  this->Camera->SetParallelProjection(parallel);
}

void vtkExtractViewDependentMesh::SetCameraParallelScale(double scale)
{
  if (!(scale > 0.0) || !std::isfinite(scale))
  {
    vtkErrorMacro("CameraParallelScale must be a positive number; " << scale << " ignored.");
    return;
  }
  this->Camera->SetParallelScale(scale);
}

void vtkExtractViewDependentMesh::SetViewportSize(int width, int height)
{
  if (width < 1 || height < 1)
  {
    vtkErrorMacro("ViewportSize must be at least 1 x 1 pixels; " << width << " x " << height
                                                                 << " ignored.");
    return;
  }
  if (width != this->ViewportSize[0] || height != this->ViewportSize[1])
  {
    this->ViewportSize[0] = width;
    this->ViewportSize[1] = height;
    this->Modified();
  }
}

void vtkExtractViewDependentMesh::SetPixelThreshold(double tau)
{
  if (timecritical::SetCheckedSetting(this, timecritical::CheckNonNegative("PixelThreshold", tau),
        tau, this->PixelThreshold))
  {
    this->Modified();
  }
}

void vtkExtractViewDependentMesh::SetTriangleBudget(vtkIdType budget)
{
  if (timecritical::SetCheckedSetting(this,
        timecritical::CheckTriangleBudget("TriangleBudget", budget), budget, this->TriangleBudget))
  {
    this->Modified();
  }
}

void vtkExtractViewDependentMesh::SetLegacyRefinementMode(int legacyMode)
{
  // Before the common numbering: 0 was fixed accuracy, 1 the triangle budget.
  switch (legacyMode)
  {
    case 0:
      this->SetRefinementMode(FIXED_ACCURACY);
      break;
    case 1:
      this->SetRefinementMode(BUDGET);
      break;
    default:
      vtkErrorMacro("The former RefinementMode must be 0 (fixed accuracy) or 1 (triangle budget), not "
        << legacyMode << "; ignored.");
  }
}

void vtkExtractViewDependentMesh::SetLightDirection(double x, double y, double z)
{
  if (!AllFinite({ x, y, z }) || (x == 0.0 && y == 0.0 && z == 0.0))
  {
    vtkErrorMacro("LightDirection must be a finite, non-zero vector; (" << x << ", " << y << ", "
                                                                        << z << ") ignored.");
    return;
  }
  if (x != this->LightDirection[0] || y != this->LightDirection[1] ||
    z != this->LightDirection[2])
  {
    this->LightDirection[0] = x;
    this->LightDirection[1] = y;
    this->LightDirection[2] = z;
    this->Modified();
  }
}

void vtkExtractViewDependentMesh::SetSilhouetteFactor(double factor)
{
  if (timecritical::SetCheckedSetting(this,
        timecritical::CheckFactor("SilhouetteFactor", factor), factor, this->SilhouetteFactor))
  {
    this->Modified();
  }
}

void vtkExtractViewDependentMesh::SetHighlightFactor(double factor)
{
  if (timecritical::SetCheckedSetting(this,
        timecritical::CheckFactor("HighlightFactor", factor), factor, this->HighlightFactor))
  {
    this->Modified();
  }
}

vtkMTimeType vtkExtractViewDependentMesh::GetMTime()
{
  vtkMTimeType time = this->Superclass::GetMTime();
  if (this->Camera)
  {
    time = std::max(time, this->Camera->GetMTime());
  }
  return time;
}

int vtkExtractViewDependentMesh::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkExtractViewDependentMesh::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  this->ResetStatistics();
  if (!input || !output)
  {
    vtkErrorMacro("Missing input or output polydata.");
    return 0;
  }
  const int prepared = this->PrepareRefinement(input);
  if (prepared <= 0)
  {
    return prepared == 0 ? 0 : 1;
  }
  this->UpdateFront();
  if (this->GetAbortExecute())
  {
    return 1;
  }
  vtkNew<vtkIdList> pointIds;
  const vtkIdType numberOfPoints = this->CopyDisplayVertices(input, output, pointIds);
  if (!this->CopyDisplayTriangles(input, output))
  {
    return 0;
  }
  if (this->GenerateLocalLevels)
  {
    this->AddLocalLevels(output, pointIds);
  }
  PassFieldData(input, output);
  this->NumberOfDisplayVertices = numberOfPoints;
  this->NumberOfDisplayTriangles = output->GetNumberOfPolys();
  return 1;
}

void vtkExtractViewDependentMesh::ResetStatistics()
{
  this->NumberOfDisplayVertices = 0;
  this->NumberOfDisplayTriangles = 0;
  this->NumberOfSplits = 0;
  this->NumberOfMerges = 0;
  this->NumberOfForcedSplits = 0;
  this->RefinementTime = 0.0;
}

int vtkExtractViewDependentMesh::PrepareRefinement(vtkPolyData* input)
{
  Internals& in = *this->Internal;
  if (input->GetNumberOfPoints() == 0 && !vtkMergeTreeFieldData::HasMergeTreeArrays(input))
  {
    // Empty input (say, an aborted build upstream): empty output, no message.
    in.Initialized = false;
    return -1;
  }
  // Read and validate the input only when it is a new one; the refinement
  // keeps its front otherwise, so a camera move is an incremental update.
  if (in.Initialized && in.Source == input && in.SourceTime == input->GetMTime())
  {
    return 1;
  }
  in.Initialized = false;
  if (!in.Reader->Read(input))
  {
    vtkErrorMacro("Input is not a valid merge tree: " << in.Reader->GetErrorMessage());
    return 0;
  }
  if (!input->GetPoints() || input->GetNumberOfPoints() == 0)
  {
    // A valid but empty tree: nothing to refine.
    return -1;
  }
  if (!this->InitializeRefinement(input))
  {
    return 0;
  }
  in.Source = input;
  in.SourceTime = input->GetMTime();
  in.Initialized = true;
  return 1;
}

bool vtkExtractViewDependentMesh::InitializeRefinement(vtkPolyData* input)
{
  Internals& in = *this->Internal;
  try
  {
    vtkDataArray* coordinates = input->GetPoints()->GetData();
    if (auto* floats = vtkFloatArray::SafeDownCast(coordinates))
    {
      in.Refinement.Initialize(in.Reader->GetMesh(), in.Reader->GetTree(), floats->GetPointer(0));
    }
    else if (auto* doubles = vtkDoubleArray::SafeDownCast(coordinates))
    {
      in.Refinement.Initialize(in.Reader->GetMesh(), in.Reader->GetTree(), doubles->GetPointer(0));
    }
    else
    {
      std::vector<double> copy(3 * static_cast<size_t>(input->GetNumberOfPoints()));
      for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
      {
        input->GetPoint(i, &copy[3 * static_cast<size_t>(i)]);
      }
      in.Refinement.Initialize(in.Reader->GetMesh(), in.Reader->GetTree(), copy.data());
    }
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("The merge tree cannot be refined: " << e.what());
    return false;
  }
  return true;
}

void vtkExtractViewDependentMesh::UpdateFront()
{
  // The view, in the data's (world) coordinates. Left, right, bottom and top
  // planes only: the clipping range of a camera handed to a filter is rarely
  // fitted to the data.
  timecritical::CameraViewOptions options;
  options.ViewportWidth = this->ViewportSize[0];
  options.ViewportHeight = this->ViewportSize[1];
  options.NumberOfFrustumPlanes = this->FrustumCulling ? 4 : 0;
  options.UseNearClippingDistance = false;
  options.LightDirection = this->LightDirection;

  timecritical::RefinementSettings settings;
  settings.Mode = timecritical::ClampRefinementMode(this->RefinementMode);
  settings.PixelThreshold = this->PixelThreshold;
  settings.BackFaceSimplification = this->BackFaceSimplification;
  settings.SilhouetteRefinement = this->SilhouetteRefinement;
  settings.SilhouetteFactor = this->SilhouetteFactor;
  settings.HighlightRefinement = this->HighlightRefinement;
  settings.HighlightFactor = this->HighlightFactor;
  settings.TriangleBudget = this->TriangleBudget;

  timecritical::ViewDependentRefinement& refinement = this->Internal->Refinement;
  refinement.SetView(timecritical::ComputeRefinementView(this->Camera, options));
  timecritical::ApplyRefinementSettings(settings, refinement);
  const timecritical::RefinementStatistics& statistics =
    settings.Mode == timecritical::RefinementMode::Budget
    ? refinement.UpdateBudget(static_cast<uint32_t>(settings.TriangleBudget))
    : refinement.UpdateFixedAccuracy();
  this->NumberOfSplits = statistics.Splits;
  this->NumberOfMerges = statistics.Merges;
  this->NumberOfForcedSplits = statistics.ForcedSplits;
  this->RefinementTime = statistics.Seconds;
}

vtkIdType vtkExtractViewDependentMesh::CopyDisplayVertices(
  vtkPolyData* input, vtkPolyData* output, vtkIdList* pointIds)
{
  // Display vertices, in TOM order, become the output points.
  Internals& in = *this->Internal;
  const timecritical::ViewDependentRefinement& refinement = in.Refinement;
  const uint32_t n = in.Reader->GetMesh().GetNumberOfVertices();
  in.OutputPoint.assign(n, -1);
  pointIds->Allocate(refinement.GetNumberOfDisplayVertices());
  for (uint32_t v = 0; v < n; ++v)
  {
    if (refinement.IsDisplayVertex(v))
    {
      in.OutputPoint[v] = pointIds->InsertNextId(v);
    }
  }
  const vtkIdType numberOfPoints = pointIds->GetNumberOfIds();
  vtkNew<vtkPoints> points;
  points->SetDataType(input->GetPoints()->GetDataType());
  points->SetNumberOfPoints(numberOfPoints);
  input->GetPoints()->GetPoints(pointIds, points);
  output->SetPoints(points);
  vtkPointData* outPD = output->GetPointData();
  // The TOM and merge-tree arrays describe the input only.
  for (const char* name : { vtkTOMFieldData::SubstitutionArrayName(),
         vtkMergeTreeFieldData::LevelArrayName(), vtkMergeTreeFieldData::ErrorArrayName(),
         vtkMergeTreeFieldData::RadiusArrayName(), vtkMergeTreeFieldData::ConeAxisArrayName(),
         vtkMergeTreeFieldData::ConeCosineArrayName() })
  {
    outPD->CopyFieldOff(name);
  }
  outPD->CopyAllocate(input->GetPointData(), numberOfPoints);
  outPD->CopyData(input->GetPointData(), pointIds, vtkIdType(0));
  return numberOfPoints;
}

bool vtkExtractViewDependentMesh::CopyDisplayTriangles(vtkPolyData* input, vtkPolyData* output)
{
  // Each display triangle is a TOM triangle whose corners, moved up the merge
  // tree to their display ancestors, are distinct: the front replays the
  // build's collapses exactly. Going through the TOM triangles gives each
  // display triangle its source triangle, hence its cell data.
  Internals& in = *this->Internal;
  const timecritical::ViewDependentRefinement& refinement = in.Refinement;
  const timecritical::TOMMesh& mesh = in.Reader->GetMesh();
  const uint32_t n = mesh.GetNumberOfVertices();
  std::vector<uint32_t>& ancestor = in.DisplayAncestor;
  ancestor.resize(n);
  for (uint32_t v = 0; v < n; ++v)
  {
    // Parents have lower ids, so theirs is already known.
    ancestor[v] = refinement.IsDisplayVertex(v) ? v : ancestor[mesh.Substitution[v]];
  }
  const uint32_t expected = refinement.GetNumberOfDisplayTriangles();
  vtkNew<vtkTypeInt64Array> connectivity;
  connectivity->Allocate(3 * static_cast<vtkIdType>(expected));
  vtkNew<vtkIdList> cellIds;
  cellIds->Allocate(expected);
  const uint32_t numberOfTriangles = mesh.GetNumberOfTriangles();
  for (uint32_t t = 0; t < numberOfTriangles; ++t)
  {
    const uint32_t a = ancestor[mesh.Triangles[3 * t]];
    const uint32_t b = ancestor[mesh.Triangles[3 * t + 1]];
    const uint32_t c = ancestor[mesh.Triangles[3 * t + 2]];
    if (a != b && b != c && a != c)
    {
      connectivity->InsertNextValue(in.OutputPoint[a]);
      connectivity->InsertNextValue(in.OutputPoint[b]);
      connectivity->InsertNextValue(in.OutputPoint[c]);
      cellIds->InsertNextId(t);
    }
  }
  const vtkIdType displayTriangles = cellIds->GetNumberOfIds();
  if (displayTriangles != static_cast<vtkIdType>(expected))
  {
    vtkErrorMacro("Internal error: the refinement reports "
      << expected << " display triangles, its display vertices give " << displayTriangles << ".");
    output->Initialize();
    return false;
  }
  vtkNew<vtkTypeInt64Array> offsets;
  offsets->SetNumberOfValues(displayTriangles + 1);
  for (vtkIdType t = 0; t <= displayTriangles; ++t)
  {
    offsets->SetValue(t, 3 * t);
  }
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  output->SetPolys(polys);
  vtkCellData* outCD = output->GetCellData();
  outCD->CopyAllocate(input->GetCellData(), displayTriangles);
  outCD->CopyData(input->GetCellData(), cellIds, vtkIdType(0));
  return true;
}

void vtkExtractViewDependentMesh::AddLocalLevels(vtkPolyData* output, vtkIdList* pointIds)
{
  // How coarse the front is at a display vertex: one more than the highest
  // level of its hidden children (the splits it still has to make), 0 when
  // all its children are displayed.
  const Internals& in = *this->Internal;
  const timecritical::ViewDependentRefinement& refinement = in.Refinement;
  const timecritical::TOMMesh& mesh = in.Reader->GetMesh();
  const timecritical::MergeTree& tree = in.Reader->GetTree();
  const uint32_t n = mesh.GetNumberOfVertices();
  std::vector<uint16_t> vertexLevel(n, 0);
  for (uint32_t v = n; v-- > mesh.BaseVertexCount;)
  {
    const uint32_t parent = mesh.Substitution[v];
    if (!refinement.IsDisplayVertex(v) && refinement.IsDisplayVertex(parent))
    {
      vertexLevel[parent] = std::max(vertexLevel[parent], static_cast<uint16_t>(tree.Level[v] + 1));
    }
  }
  vtkCellArray* polys = output->GetPolys();
  const vtkIdType displayTriangles = polys->GetNumberOfCells();
  vtkNew<vtkTypeUInt16Array> levels;
  levels->SetName(LocalLevelArrayName());
  levels->SetNumberOfValues(displayTriangles);
  vtkTypeInt64Array* connectivity = polys->GetConnectivityArray64();
  for (vtkIdType t = 0; t < displayTriangles; ++t)
  {
    uint16_t level = 0;
    for (int k = 0; k < 3; ++k)
    {
      const vtkIdType point = pointIds->GetId(connectivity->GetValue(3 * t + k));
      level = std::max(level, vertexLevel[point]);
    }
    levels->SetValue(t, level);
  }
  output->GetCellData()->AddArray(levels);
}

void vtkExtractViewDependentMesh::PassFieldData(vtkPolyData* input, vtkPolyData* output)
{
  // Ordinary field data passes; the TOM's and merge tree's describe the input only.
  vtkFieldData* outFD = output->GetFieldData();
  outFD->PassData(input->GetFieldData());
  for (const char* name : { vtkTOMFieldData::CountsArrayName(),
         vtkTOMFieldData::ErrorCurveArrayName(), vtkMergeTreeFieldData::DependencyOffsetsArrayName(),
         vtkMergeTreeFieldData::DependenciesArrayName(),
         vtkMergeTreeFieldData::LevelCountArrayName() })
  {
    outFD->RemoveArray(name);
  }
}

void vtkExtractViewDependentMesh::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Camera: " << this->Camera.GetPointer() << "\n";
  os << indent << "ViewportSize: " << this->ViewportSize[0] << " x " << this->ViewportSize[1]
     << "\n";
  os << indent << "PixelThreshold: " << this->PixelThreshold << "\n";
  os << indent << "LightDirection: (" << this->LightDirection[0] << ", " << this->LightDirection[1]
     << ", " << this->LightDirection[2] << ")\n";
  os << indent << "BackFaceSimplification: " << this->BackFaceSimplification << "\n";
  os << indent << "FrustumCulling: " << this->FrustumCulling << "\n";
  os << indent << "SilhouetteRefinement: " << this->SilhouetteRefinement << "\n";
  os << indent << "SilhouetteFactor: " << this->SilhouetteFactor << "\n";
  os << indent << "HighlightRefinement: " << this->HighlightRefinement << "\n";
  os << indent << "HighlightFactor: " << this->HighlightFactor << "\n";
  os << indent << "RefinementMode: "
     << timecritical::RefinementModeName(timecritical::ClampRefinementMode(this->RefinementMode))
     << "\n";
  os << indent << "TriangleBudget: " << this->TriangleBudget << "\n";
  os << indent << "GenerateLocalLevels: " << this->GenerateLocalLevels << "\n";
  os << indent << "NumberOfDisplayVertices: " << this->NumberOfDisplayVertices << "\n";
  os << indent << "NumberOfDisplayTriangles: " << this->NumberOfDisplayTriangles << "\n";
  os << indent << "NumberOfSplits: " << this->NumberOfSplits << "\n";
  os << indent << "NumberOfMerges: " << this->NumberOfMerges << "\n";
  os << indent << "NumberOfForcedSplits: " << this->NumberOfForcedSplits << "\n";
  os << indent << "RefinementTime: " << this->RefinementTime << "\n";
}
