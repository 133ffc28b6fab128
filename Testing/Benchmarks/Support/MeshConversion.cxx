// SPDX-License-Identifier: BSD-3-Clause
#include "MeshConversion.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>

#include <stdexcept>
#include <string>

namespace timecritical
{
namespace benchmark
{
using timecritical::testing::TriangleMesh;

vtkSmartPointer<vtkPolyData> ToPolyData(const TriangleMesh& mesh)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.NumberOfPoints()));
  for (size_t i = 0; i < mesh.NumberOfPoints(); ++i)
  {
    points->SetPoint(static_cast<vtkIdType>(i), &mesh.Points[3 * i]);
  }
  vtkNew<vtkIdTypeArray> offsets;
  vtkNew<vtkIdTypeArray> connectivity;
  offsets->SetNumberOfValues(static_cast<vtkIdType>(mesh.NumberOfTriangles() + 1));
  connectivity->SetNumberOfValues(static_cast<vtkIdType>(mesh.Triangles.size()));
  for (size_t t = 0; t <= mesh.NumberOfTriangles(); ++t)
  {
    offsets->SetValue(static_cast<vtkIdType>(t), static_cast<vtkIdType>(3 * t));
  }
  for (size_t i = 0; i < mesh.Triangles.size(); ++i)
  {
    connectivity->SetValue(static_cast<vtkIdType>(i), mesh.Triangles[i]);
  }
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(polys);
  return poly;
}

TriangleMesh FromPolyData(vtkPolyData* poly)
{
  if (poly->GetNumberOfStrips() != 0 || poly->GetNumberOfLines() != 0 ||
    poly->GetNumberOfVerts() != 0)
  {
    throw std::runtime_error("FromPolyData: expected a polydata of triangles only");
  }
  TriangleMesh mesh;
  mesh.Points.resize(3 * static_cast<size_t>(poly->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i)
  {
    poly->GetPoint(i, &mesh.Points[3 * static_cast<size_t>(i)]);
  }
  mesh.Triangles.reserve(3 * static_cast<size_t>(poly->GetNumberOfPolys()));
  auto cells = vtk::TakeSmartPointer(poly->GetPolys()->NewIterator());
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    vtkIdType size = 0;
    const vtkIdType* ids = nullptr;
    cells->GetCurrentCell(size, ids);
    if (size != 3)
    {
      throw std::runtime_error(
        "FromPolyData: expected triangles, got a polygon of " + std::to_string(size));
    }
    mesh.Triangles.insert(mesh.Triangles.end(), ids, ids + 3);
  }
  return mesh;
}

vtkSmartPointer<vtkPolyData> WithNormals(vtkPolyData* input)
{
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(input);
  normals->SplittingOff();
  normals->ConsistencyOn();
  normals->ComputePointNormalsOn();
  normals->ComputeCellNormalsOff();
  normals->Update();
  vtkSmartPointer<vtkPolyData> out = normals->GetOutput();
  return out;
}
}
}
