// SPDX-License-Identifier: BSD-3-Clause
#include "LeafHierarchyBuild.h"

#include "vtkCommand.h"
#include "vtkMergeTreeBuilder.h"
#include "vtkNew.h"
#include "vtkMergeTreeFieldData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataValidator.h"
#include "vtkTOMBuilder.h"
#include "vtkTOMFieldData.h"

#include <sstream>

namespace timecritical
{
namespace
{
/// Collects a builder's errors and warnings and forwards its progress.
class BuildObserver : public vtkCommand
{
public:
  static BuildObserver* New() { return new BuildObserver; }

  void Execute(vtkObject* caller, unsigned long event, void* callData) override
  {
    auto* builder = static_cast<vtkAlgorithm*>(caller);
    if (event == vtkCommand::ProgressEvent)
    {
      if (this->Progress && !this->Progress(builder->GetProgress()))
      {
        this->Cancelled = true;
        builder->SetAbortExecute(1);
      }
      return;
    }
    const char* text = callData ? static_cast<const char*>(callData) : "";
    this->Result->Messages.push_back({ event == vtkCommand::ErrorEvent, text });
  }

  LeafBuildResult* Result = nullptr;
  LeafBuildProgress Progress;
  bool Cancelled = false;
};

std::string PassingReason(vtkPolyData* leaf, bool& isError)
{
  // Checked here rather than by the builder, whose failure would also bring
  // an error of its executive; and vertices or lines, which a TOM cannot
  // hold, would be lost: such leaves pass as they are.
  const std::string problem = vtkPolyDataValidator::CheckBuildInput(leaf);
  if (!problem.empty())
  {
    isError = true;
    return problem + ".";
  }
  if (leaf->GetNumberOfVerts() > 0 || leaf->GetNumberOfLines() > 0)
  {
    isError = false;
    std::ostringstream text;
    text << leaf->GetNumberOfVerts() + leaf->GetNumberOfLines()
         << " vertex and line cells besides its surface: drawn in full (a hierarchy holds "
            "triangles only; extract the surface to make it multiresolution).";
    return text.str();
  }
  return std::string();
}
} // namespace

bool CarriesHierarchy(vtkPolyData* leaf, LeafHierarchy hierarchy)
{
  return leaf && vtkTOMFieldData::HasTOMArrays(leaf) &&
    (hierarchy != LeafHierarchy::MergeTree || vtkMergeTreeFieldData::HasMergeTreeArrays(leaf));
}

LeafBuildResult BuildLeafHierarchy(
  vtkPolyData* leaf, LeafHierarchy hierarchy, const LeafBuildProgress& progress)
{
  LeafBuildResult result;
  bool isError = false;
  const std::string reason = PassingReason(leaf, isError);
  if (!reason.empty())
  {
    result.Messages.push_back({ isError, reason });
    return result;
  }
  vtkSmartPointer<vtkPolyDataAlgorithm> builder;
  if (hierarchy == LeafHierarchy::MergeTree)
  {
    builder = vtkSmartPointer<vtkMergeTreeBuilder>::New();
  }
  else
  {
    builder = vtkSmartPointer<vtkTOMBuilder>::New();
  }
  vtkNew<BuildObserver> observer;
  observer->Result = &result;
  observer->Progress = progress;
  builder->AddObserver(vtkCommand::ProgressEvent, observer);
  builder->AddObserver(vtkCommand::ErrorEvent, observer);
  builder->AddObserver(vtkCommand::WarningEvent, observer);
  auto input = vtkSmartPointer<vtkPolyData>::New();
  input->ShallowCopy(leaf); // the builder's pipeline never touches the caller's leaf
  builder->SetInputData(input);
  builder->Update();
  vtkPolyData* built = builder->GetOutput();
  if (observer->Cancelled)
  {
    result.Cancelled = true;
    return result;
  }
  if (built && vtkTOMFieldData::HasTOMArrays(built))
  {
    result.Hierarchy = vtkSmartPointer<vtkPolyData>::New();
    result.Hierarchy->ShallowCopy(built);
  }
  return result;
}
} // namespace timecritical
