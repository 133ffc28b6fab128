// SPDX-License-Identifier: BSD-3-Clause
#include "LeafInterimReduction.h"

#include "vtkBinnedDecimation.h"
#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkPolyData.h"

namespace timecritical
{
vtkSmartPointer<vtkPolyData> BuildInterimReduction(
  vtkPolyData* leaf, int divisions, vtkIdType minimumTriangles)
{
  if (!leaf || divisions < 2 || leaf->GetNumberOfPolys() < minimumTriangles ||
    leaf->GetNumberOfVerts() > 0 || leaf->GetNumberOfLines() > 0 ||
    leaf->GetNumberOfStrips() > 0 || !leaf->GetPolys()->IsHomogeneous() ||
    leaf->GetPolys()->IsHomogeneous() != 3)
  {
    return nullptr;
  }
  vtkNew<vtkBinnedDecimation> decimation;
  auto input = vtkSmartPointer<vtkPolyData>::New();
  input->ShallowCopy(leaf); // the filter's pipeline never touches the leaf
  decimation->SetInputData(input);
  decimation->SetNumberOfDivisions(divisions, divisions, divisions);
  decimation->AutoAdjustNumberOfDivisionsOn();
  decimation->SetPointGenerationModeToUseInputPoints();
  decimation->ProducePointDataOn();
  decimation->ProduceCellDataOn();
  decimation->Update();
  vtkPolyData* reduced = decimation->GetOutput();
  if (!reduced || reduced->GetNumberOfPolys() < 1)
  {
    return nullptr;
  }
  auto interim = vtkSmartPointer<vtkPolyData>::New();
  interim->ShallowCopy(reduced);
  return interim;
}
}
