// SPDX-License-Identifier: BSD-3-Clause
#include "vtkCollapseHierarchyBuilder.h"

#include "TOMBuilder.h"
#include "TOMFilterSupport.h"

#include "vtkInformation.h"

vtkCollapseHierarchyBuilder::vtkCollapseHierarchyBuilder()
  : FeatureWeight(timecritical::TOMBuildOptions().FeatureWeight)
{
}
vtkCollapseHierarchyBuilder::~vtkCollapseHierarchyBuilder() = default;

void vtkCollapseHierarchyBuilder::SetFeatureAngle(double angle)
{
  if (timecritical::SetClampedSetting(this, "FeatureAngle", angle, 0.0, 180.0, this->FeatureAngle))
  {
    this->Modified();
  }
}

void vtkCollapseHierarchyBuilder::SetFeatureWeight(double weight)
{
  // At most the core's weight of the boundary constraints: a heavier weight
  // would hold unlocked sharp edges harder than boundaries (past about 100 it
  // acts as a lock already: LockFeatureEdges is the setting for that), and a
  // huge one overflows the quadrics.
  const double maximum = timecritical::TOMBuildOptions().ConstraintWeight;
  if (timecritical::SetClampedSetting(
        this, "FeatureWeight", weight, 0.0, maximum, this->FeatureWeight))
  {
    this->Modified();
  }
}

void vtkCollapseHierarchyBuilder::SetMaximumNormalDeviation(double angle)
{
  if (timecritical::SetClampedSetting(
        this, "MaximumNormalDeviation", angle, 0.0, 180.0, this->MaximumNormalDeviation))
  {
    this->Modified();
  }
}

void vtkCollapseHierarchyBuilder::SetMinimumTriangleQuality(double quality)
{
  if (timecritical::SetClampedSetting(
        this, "MinimumTriangleQuality", quality, 0.0, 1.0, this->MinimumTriangleQuality))
  {
    this->Modified();
  }
}

int vtkCollapseHierarchyBuilder::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

void vtkCollapseHierarchyBuilder::FillCollapseOptions(timecritical::TOMBuildOptions& options)
{
  options.PreserveBoundaries = this->PreserveBoundaries;
  options.PreserveFeatureEdges = this->PreserveFeatureEdges;
  options.FeatureAngle = this->FeatureAngle;
  options.LockFeatureEdges = this->LockFeatureEdges;
  options.FeatureWeight = this->FeatureWeight;
  options.MaximumNormalDeviation = this->MaximumNormalDeviation;
  options.MinimumTriangleQuality = this->MinimumTriangleQuality;
  options.Progress = timecritical::CoreProgress(this);
}

void vtkCollapseHierarchyBuilder::PrintSelf(ostream& os, vtkIndent indent)
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
