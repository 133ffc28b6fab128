// SPDX-License-Identifier: BSD-3-Clause
// Builds a TOM with an installed TimeCritical and prints its counts.
#include "vtkExtractTOMResolution.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSphereSource.h"
#include "vtkTOMBuilder.h"

#include <iostream>

int main()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(32);
  vtkNew<vtkTOMBuilder> builder;
  builder->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkExtractTOMResolution> extract;
  extract->SetInputConnection(builder->GetOutputPort());
  extract->SetResolution(0.5);
  extract->Update();
  const vtkIdType full = builder->GetOutput()->GetNumberOfPolys();
  const vtkIdType half = extract->GetOutput()->GetNumberOfPolys();
  std::cout << "triangles " << full << " half " << half << "\n";
  return (full > 0 && half > 0 && half <= full / 2) ? 0 : 1;
}
