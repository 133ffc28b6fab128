// SPDX-License-Identifier: BSD-3-Clause
#include "LeafHierarchyBuild.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkMergeTreeBuilder.h"
#include "vtkNew.h"
#include "vtkMergeTreeFieldData.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
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

vtkSmartPointer<vtkAbstractArray> ArrayOfItsOwn(vtkAbstractArray* array)
{
  auto copy = vtk::TakeSmartPointer(array->NewInstance());
  auto* values = vtkDataArray::SafeDownCast(array);
  if (values)
  {
    vtkDataArray::SafeDownCast(copy)->ShallowCopy(values); // the values, not the caches
  }
  else
  {
    copy->DeepCopy(array); // string and variant arrays: small, and no shallow copy
  }
  return copy;
}

vtkSmartPointer<vtkCellArray> CellsOfTheirOwn(vtkCellArray* cells)
{
  auto copy = vtkSmartPointer<vtkCellArray>::New();
  if (cells)
  {
    copy->ShallowCopy(cells);
  }
  return copy;
}

/// Arrays of their own with the same names, values and active attributes;
/// input whose arrays cannot be told apart by name keeps the shared arrays.
void CopyAttributes(vtkFieldData* from, vtkFieldData* to)
{
  auto* fromAttributes = vtkDataSetAttributes::SafeDownCast(from);
  auto* toAttributes = vtkDataSetAttributes::SafeDownCast(to);
  for (int i = 0; i < from->GetNumberOfArrays(); ++i)
  {
    vtkAbstractArray* array = from->GetAbstractArray(i);
    if (!array->GetName() || to->AddArray(ArrayOfItsOwn(array)) != i)
    {
      to->ShallowCopy(from);
      return;
    }
  }
  if (!fromAttributes || !toAttributes)
  {
    return;
  }
  for (int attribute = 0; attribute < vtkDataSetAttributes::NUM_ATTRIBUTES; ++attribute)
  {
    vtkAbstractArray* active = fromAttributes->GetAbstractAttribute(attribute);
    for (int i = 0; active && i < from->GetNumberOfArrays(); ++i)
    {
      if (from->GetAbstractArray(i) == active)
      {
        toAttributes->SetActiveAttribute(i, attribute);
      }
    }
  }
}

} // namespace

vtkSmartPointer<vtkPolyData> CopyForAnotherThread(vtkPolyData* leaf)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  if (vtkPoints* points = leaf->GetPoints())
  {
    vtkNew<vtkPoints> ownPoints;
    ownPoints->SetData(vtkDataArray::SafeDownCast(ArrayOfItsOwn(points->GetData())));
    copy->SetPoints(ownPoints);
  }
  copy->SetVerts(CellsOfTheirOwn(leaf->GetVerts()));
  copy->SetLines(CellsOfTheirOwn(leaf->GetLines()));
  copy->SetPolys(CellsOfTheirOwn(leaf->GetPolys()));
  copy->SetStrips(CellsOfTheirOwn(leaf->GetStrips()));
  CopyAttributes(leaf->GetPointData(), copy->GetPointData());
  CopyAttributes(leaf->GetCellData(), copy->GetCellData());
  CopyAttributes(leaf->GetFieldData(), copy->GetFieldData());
  return copy;
}

bool CarriesHierarchy(vtkPolyData* leaf, LeafHierarchy hierarchy)
{
  return leaf && vtkTOMFieldData::HasTOMArrays(leaf) &&
    (hierarchy != LeafHierarchy::MergeTree || vtkMergeTreeFieldData::HasMergeTreeArrays(leaf));
}

LeafBuildResult BuildLeafHierarchy(vtkPolyData* leaf, LeafHierarchy hierarchy,
  const LeafBuildProgress& progress, double pairContractionDistance)
{
  LeafBuildResult result;
  if (!leaf)
  {
    result.Messages.push_back({ true, "No leaf to build." });
    return result;
  }
  vtkSmartPointer<vtkPolyData> input = CopyForAnotherThread(leaf);
  bool isError = false;
  const std::string reason = PassingReason(input, isError);
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
    auto tom = vtkSmartPointer<vtkTOMBuilder>::New();
    tom->SetPairContractionDistance(pairContractionDistance);
    builder = tom;
  }
  vtkNew<BuildObserver> observer;
  observer->Result = &result;
  observer->Progress = progress;
  builder->AddObserver(vtkCommand::ProgressEvent, observer);
  builder->AddObserver(vtkCommand::ErrorEvent, observer);
  builder->AddObserver(vtkCommand::WarningEvent, observer);
  builder->SetInputData(input); // never the caller's leaf
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
