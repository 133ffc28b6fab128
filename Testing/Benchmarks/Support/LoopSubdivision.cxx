// SPDX-License-Identifier: BSD-3-Clause
#include "LoopSubdivision.h"

#include "MeshConversion.h"

#include <vtkLoopSubdivisionFilter.h>
#include <vtkNew.h>
#include <vtkPolyData.h>

#include <stdexcept>

namespace timecritical
{
namespace benchmark
{
vtkSmartPointer<vtkPolyData> LoopSubdivide(vtkPolyData* input, int levels)
{
  if (levels < 0)
  {
    throw std::invalid_argument("LoopSubdivide: levels must be >= 0");
  }
  if (levels == 0)
  {
    return input;
  }
  vtkNew<vtkLoopSubdivisionFilter> loop;
  loop->SetNumberOfSubdivisions(levels);
  loop->SetInputData(input);
  loop->Update();
  vtkSmartPointer<vtkPolyData> output = loop->GetOutput();
  return output;
}

timecritical::testing::TriangleMesh LoopSubdivide(
  const timecritical::testing::TriangleMesh& mesh, int levels)
{
  if (levels == 0)
  {
    return mesh;
  }
  return FromPolyData(LoopSubdivide(ToPolyData(mesh), levels));
}
}
}
