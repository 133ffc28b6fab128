// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMergeTreeBuilder.h"

#include "MergeTreeBuilder.h"
#include "TOMFilterSupport.h"
#include "vtkMergeTreeFieldData.h"

#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkTimerLog.h"

#include <exception>
#include <limits>
#include <string>

vtkStandardNewMacro(vtkMergeTreeBuilder);

vtkMergeTreeBuilder::vtkMergeTreeBuilder()
  : LevelCostRatio(timecritical::MergeTreeBuildOptions().LevelCostRatio)
  , ShadingWeight(timecritical::MergeTreeErrorOptions().ShadingWeight)
{
}
vtkMergeTreeBuilder::~vtkMergeTreeBuilder() = default;

void vtkMergeTreeBuilder::SetLevelCostRatio(double ratio)
{
  if (timecritical::SetClampedSetting(this, "LevelCostRatio", ratio, 0.0,
        std::numeric_limits<double>::max(), this->LevelCostRatio))
  {
    this->Modified();
  }
}

void vtkMergeTreeBuilder::SetShadingWeight(double weight)
{
  if (timecritical::SetClampedSetting(this, "ShadingWeight", weight, 0.0,
        std::numeric_limits<double>::max(), this->ShadingWeight))
  {
    this->Modified();
  }
}

int vtkMergeTreeBuilder::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  this->NumberOfDroppedCells = 0;
  this->NumberOfMergedPoints = 0;
  this->LevelCount = 0;
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
      // Nothing to simplify: an empty output, as VTK filters give for empty input.
      return 1;
    case timecritical::SurfaceStatus::Failed:
      return 0;
    case timecritical::SurfaceStatus::Ready:
      break;
  }
  this->NumberOfDroppedCells = surface.NumberOfDroppedCells;
  this->NumberOfMergedPoints = surface.NumberOfMergedPoints;

  timecritical::MergeTreeBuildOptions options;
  this->FillCollapseOptions(options.Collapse);
  options.LevelCostRatio = this->LevelCostRatio;
  options.Errors.ShadingWeight = this->ShadingWeight;

  timecritical::MergeTreeBuildResult result;
  try
  {
    result = timecritical::MergeTreeBuilder(options).Build(surface.Points.data(),
      surface.Points.size() / 3, surface.Ids.data(), surface.Ids.size() / 3);
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Merge tree construction failed: " << e.what());
    return 0;
  }
  if (result.TOM.Aborted)
  {
    // Aborted builds leave an empty output, as VTK filters do.
    return 1;
  }
  // Downstream filters trust what Read() accepts; never hand them a tree it would reject.
  const std::string problem = vtkMergeTreeFieldData::Check(result.TOM.Mesh, result.Tree);
  if (!problem.empty())
  {
    vtkErrorMacro("Merge tree construction produced an invalid tree: " << problem);
    return 0;
  }
  timecritical::WriteOrderedSurface(this, input, surface, result.TOM, output);
  this->NumberOfDroppedCells = surface.NumberOfDroppedCells;
  vtkMergeTreeFieldData::Write(result.TOM.Mesh, result.Tree, output);
  this->LevelCount = result.Tree.LevelCount;
  this->BuildTime = vtkTimerLog::GetUniversalTime() - start;
  this->UpdateProgress(1.0);
  return 1;
}

void vtkMergeTreeBuilder::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LevelCostRatio: " << this->LevelCostRatio << "\n";
  os << indent << "ShadingWeight: " << this->ShadingWeight << "\n";
  os << indent << "LevelCount: " << this->LevelCount << "\n";
}
