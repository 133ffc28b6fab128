// SPDX-License-Identifier: BSD-3-Clause
// Scenes shared by the time-critical renderer's tests.
#ifndef TimeCriticalRendererTestSupport_h
#define TimeCriticalRendererTestSupport_h

#include "vtkTOMBuilder.h"

#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"

#include <cmath>

namespace timecritical
{
namespace testing
{
/// A TOM of a unit sphere of theta x phi facets with bumps (radius times
/// 1 + 0.1 sin 7x sin 5y) and unsplit normals.
inline vtkSmartPointer<vtkPolyData> MakeBumpySphereTOM(int theta, int phi)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(theta);
  sphere->SetPhiResolution(phi);
  sphere->Update();
  vtkNew<vtkPolyData> bumpy;
  bumpy->DeepCopy(sphere->GetOutput());
  vtkPoints* points = bumpy->GetPoints();
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    const double s = 1.0 + 0.1 * std::sin(7.0 * p[0]) * std::sin(5.0 * p[1]);
    points->SetPoint(i, s * p[0], s * p[1], s * p[2]);
  }
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(bumpy);
  normals->SplittingOff();
  vtkNew<vtkTOMBuilder> builder;
  builder->SetInputConnection(normals->GetOutputPort());
  builder->Update();
  return builder->GetOutput();
}
}
}

#endif
