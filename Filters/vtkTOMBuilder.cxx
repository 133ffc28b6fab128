// SPDX-License-Identifier: BSD-3-Clause
#include "vtkTOMBuilder.h"

#include "TOMBuilder.h"
#include "TOMFilterSupport.h"
#include "vtkTOMFieldData.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkTimerLog.h"

#include <exception>

vtkStandardNewMacro(vtkTOMBuilder);

vtkTOMBuilder::vtkTOMBuilder()
  : FeatureWeight(timecritical::TOMBuildOptions().FeatureWeight)
{
}
vtkTOMBuilder::~vtkTOMBuilder() = default;

void vtkTOMBuilder::SetFeatureAngle(double angle)
{
  if (timecritical::SetClampedSetting(this, "FeatureAngle", angle, 0.0, 180.0, this->FeatureAngle))
  {
    this->Modified();
  }
}

void vtkTOMBuilder::SetFeatureWeight(double weight)
{
  if (timecritical::SetClampedSetting(this, "FeatureWeight", weight, 0.0,
        timecritical::MaximumFeatureWeight, this->FeatureWeight))
  {
    this->Modified();
  }
}

void vtkTOMBuilder::SetMaximumNormalDeviation(double angle)
{
  if (timecritical::SetClampedSetting(
        this, "MaximumNormalDeviation", angle, 0.0, 180.0, this->MaximumNormalDeviation))
  {
    this->Modified();
  }
}

void vtkTOMBuilder::SetMinimumTriangleQuality(double quality)
{
  if (timecritical::SetClampedSetting(
        this, "MinimumTriangleQuality", quality, 0.0, 1.0, this->MinimumTriangleQuality))
  {
    this->Modified();
  }
}

int vtkTOMBuilder::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
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
  const double start = vtkTimerLog::GetUniversalTime();
  timecritical::PreparedSurface surface;
  switch (timecritical::PrepareSurface(this, input, surface))
  {
    case timecritical::SurfaceStatus::Empty:
      // Nothing to simplify (e.g. a rank without data in parallel): an empty
      // output, quietly, as VTK filters give for empty input.
      return 1;
    case timecritical::SurfaceStatus::Failed:
      return 0;
    case timecritical::SurfaceStatus::Ready:
      break;
  }
  this->NumberOfDroppedCells = surface.NumberOfDroppedCells;
  this->NumberOfMergedPoints = surface.NumberOfMergedPoints;

  timecritical::TOMBuildOptions options;
  timecritical::SetCollapseOptions(this, options);

  timecritical::TOMBuildResult result;
  try
  {
    result = timecritical::TOMBuilder(options).Build(surface.Points.data(),
      surface.Points.size() / 3, surface.Ids.data(), surface.Ids.size() / 3);
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
  timecritical::WriteOrderedSurface(this, input, surface, result, output);
  this->NumberOfDroppedCells = surface.NumberOfDroppedCells;
  vtkTOMFieldData::Write(result.Mesh, output);
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
  os << indent << "LockFeatureEdges: " << this->LockFeatureEdges << "\n";
  os << indent << "FeatureWeight: " << this->FeatureWeight << "\n";
  os << indent << "MaximumNormalDeviation: " << this->MaximumNormalDeviation << "\n";
  os << indent << "MinimumTriangleQuality: " << this->MinimumTriangleQuality << "\n";
  os << indent << "NumberOfDroppedCells: " << this->NumberOfDroppedCells << "\n";
  os << indent << "NumberOfMergedPoints: " << this->NumberOfMergedPoints << "\n";
  os << indent << "BuildTime: " << this->BuildTime << "\n";
}
