// SPDX-License-Identifier: BSD-3-Clause
// Helpers shared by the tests of vtkMergeTreeBuilder, vtkMergeTreeFieldData
// and vtkExtractViewDependentMesh.
#ifndef timecritical_MergeTreeFilterTestSupport_h
#define timecritical_MergeTreeFilterTestSupport_h

#include "FilterTestSupport.h"
#include "vtkMergeTreeBuilder.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

namespace timecritical
{
namespace testing
{
/// The merge tree `builder` (a default one when null) makes of `input`.
inline vtkSmartPointer<vtkPolyData> BuildTree(
  vtkPolyData* input, vtkMergeTreeBuilder* builder = nullptr)
{
  return RunFilter(input, builder);
}

/// One merge tree of a sphere shared by the tests that only read it.
inline vtkPolyData* SphereTree()
{
  static vtkSmartPointer<vtkPolyData> tree = BuildTree(MakeSphere());
  return tree;
}

/// A deep copy of `data`.
inline vtkSmartPointer<vtkPolyData> Copy(vtkPolyData* data)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(data);
  return copy;
}
}
}

#endif
