// SPDX-License-Identifier: BSD-3-Clause
#include "vtkTOMBuilder.h"

#include "RefinementSettingChecks.h"
#include "TOMBuilder.h"
#include "TOMFilterSupport.h"
#include "vtkTOMFieldData.h"

#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkTimerLog.h"

#include <exception>

vtkStandardNewMacro(vtkTOMBuilder);

vtkTOMBuilder::vtkTOMBuilder() = default;
vtkTOMBuilder::~vtkTOMBuilder() = default;

void vtkTOMBuilder::SetPairContractionDistance(double distance)
{
  // Not clamped: a negative distance or one beyond the diagonal is a mistake
  // (1 already reaches every part).
  if (timecritical::SetCheckedSetting(this,
        timecritical::CheckRange("PairContractionDistance", distance, 0.0, 1.0), distance,
        this->PairContractionDistance))
  {
    this->Modified();
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
  this->NumberOfJoinedParts = 0;
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
  this->FillCollapseOptions(options);
  options.PairContractionDistance = this->PairContractionDistance;

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
  this->NumberOfJoinedParts = static_cast<vtkIdType>(result.JoinedParts);
  this->BuildTime = vtkTimerLog::GetUniversalTime() - start;
  this->UpdateProgress(1.0);
  return 1;
}

void vtkTOMBuilder::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "PairContractionDistance: " << this->PairContractionDistance << "\n";
  os << indent << "NumberOfJoinedParts: " << this->NumberOfJoinedParts << "\n";
}
