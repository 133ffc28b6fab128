// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPolyDataValidator.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <cmath>
#include <sstream>

vtkStandardNewMacro(vtkPolyDataValidator);

void vtkPolyDataValidator::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}

namespace
{
// The first out-of-range id of `cells` (numbered from firstCell), described, or "".
std::string CheckCells(vtkCellArray* cells, vtkIdType firstCell, vtkIdType numberOfPoints)
{
  if (!cells || cells->GetNumberOfCells() == 0)
  {
    return std::string();
  }
  auto it = vtk::TakeSmartPointer(cells->NewIterator());
  vtkIdType cellId = firstCell;
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++cellId)
  {
    vtkIdType size;
    const vtkIdType* ids;
    it->GetCurrentCell(size, ids);
    for (vtkIdType k = 0; k < size; ++k)
    {
      if (ids[k] < 0 || ids[k] >= numberOfPoints)
      {
        std::ostringstream msg;
        msg << "cell " << cellId << " refers to point " << ids[k] << ", but the data has "
            << numberOfPoints << " points";
        return msg.str();
      }
    }
  }
  return std::string();
}
}

std::string vtkPolyDataValidator::CheckPointIds(vtkPolyData* data)
{
  if (!data)
  {
    return std::string();
  }
  const vtkIdType n = data->GetNumberOfPoints();
  vtkIdType first = 0;
  for (vtkCellArray* cells : { data->GetVerts(), data->GetLines(), data->GetPolys(),
         data->GetStrips() })
  {
    std::string problem = CheckCells(cells, first, n);
    if (!problem.empty())
    {
      return problem;
    }
    first += cells ? cells->GetNumberOfCells() : 0;
  }
  return std::string();
}

vtkIdType vtkPolyDataValidator::FirstNonFinitePoint(vtkPoints* points)
{
  if (!points)
  {
    return -1;
  }
  vtkDataArray* data = points->GetData();
  const vtkIdType n = points->GetNumberOfPoints();
  // Raw pointers for the usual float and double points: no virtual call per value.
  auto scan = [n](const auto* xyz) -> vtkIdType {
    for (vtkIdType i = 0; i < 3 * n; ++i)
    {
      if (!std::isfinite(xyz[i]))
      {
        return i / 3;
      }
    }
    return -1;
  };
  if (auto* f = vtkFloatArray::FastDownCast(data))
  {
    return scan(f->GetPointer(0));
  }
  if (auto* d = vtkDoubleArray::FastDownCast(data))
  {
    return scan(d->GetPointer(0));
  }
  for (vtkIdType i = 0; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      if (!std::isfinite(data->GetComponent(i, c)))
      {
        return i;
      }
    }
  }
  return -1;
}

std::string vtkPolyDataValidator::CheckCoordinates(vtkPoints* points)
{
  const vtkIdType bad = FirstNonFinitePoint(points);
  if (bad < 0)
  {
    return std::string();
  }
  std::ostringstream msg;
  msg << "point " << bad << " has a non-finite (NaN or infinite) coordinate";
  return msg.str();
}

std::string vtkPolyDataValidator::Check(vtkPolyData* data)
{
  if (!data)
  {
    return std::string();
  }
  std::string problem = CheckPointIds(data);
  return problem.empty() ? CheckCoordinates(data->GetPoints()) : problem;
}
