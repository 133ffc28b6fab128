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

#include "TOMBuilder.h" // for MaximumCoordinateMagnitude

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
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
  return FirstPointBeyond(points, std::numeric_limits<double>::max());
}

vtkIdType vtkPolyDataValidator::FirstPointBeyond(vtkPoints* points, double limit)
{
  if (!points)
  {
    return -1;
  }
  vtkDataArray* data = points->GetData();
  const vtkIdType n = points->GetNumberOfPoints();
  // Raw pointers for the usual float and double points: no virtual call per value.
  auto scan = [n, limit](const auto* xyz) -> vtkIdType {
    for (vtkIdType i = 0; i < 3 * n; ++i)
    {
      if (!(std::abs(static_cast<double>(xyz[i])) <= limit))
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
      if (!(std::abs(data->GetComponent(i, c)) <= limit))
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

std::string vtkPolyDataValidator::CheckBuildInput(vtkPolyData* data)
{
  std::string problem = CheckPointIds(data);
  if (!problem.empty() || !data)
  {
    return problem;
  }
  // One scan for both: the first point beyond the limit, NaN and infinite included.
  const double limit = timecritical::MaximumCoordinateMagnitude;
  const vtkIdType bad = FirstPointBeyond(data->GetPoints(), limit);
  if (bad < 0)
  {
    return std::string();
  }
  double p[3];
  data->GetPoints()->GetPoint(bad, p);
  if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
  {
    return CheckCoordinates(data->GetPoints());
  }
  const double magnitude = std::max({ std::abs(p[0]), std::abs(p[1]), std::abs(p[2]) });
  char message[200];
  std::snprintf(message, sizeof(message),
    "point %lld has a coordinate of magnitude %.3g, beyond the supported %g (errors and radii "
    "are stored as float); scale the data",
    static_cast<long long>(bad), magnitude, limit);
  return message;
}
