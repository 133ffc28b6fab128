// SPDX-License-Identifier: BSD-3-Clause
#include "vtkTOMFieldData.h"

#include "TOMFilterSupport.h"
#include "TOMMesh.h"
#include "TOMValidator.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataValidator.h"
#include "vtkTypeUInt32Array.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <unordered_set>
#include <vector>

struct vtkTOMFieldData::Internals
{
  /// The objects a validation depends on, with their modification times.
  struct Stamp
  {
    const void* Objects[5] = {};
    vtkMTimeType Times[5] = {};
    bool operator==(const Stamp& other) const
    {
      return std::equal(Objects, Objects + 5, other.Objects) &&
        std::equal(Times, Times + 5, other.Times);
    }
  };
  struct StampHash
  {
    size_t operator()(const Stamp& stamp) const
    {
      size_t h = 0;
      for (int i = 0; i < 5; ++i)
      {
        h = h * 1000003u ^ std::hash<const void*>()(stamp.Objects[i]);
        h = h * 1000003u ^ std::hash<vtkMTimeType>()(stamp.Times[i]);
      }
      return h;
    }
  };
  using StampSet = std::unordered_set<Stamp, StampHash>;

  static Stamp StampOf(vtkPolyData* data, vtkDataArray* substitution, vtkDataArray* counts);

  bool WasValidated(const Stamp& stamp) const
  {
    return this->Validated.count(stamp) || this->ValidatedBefore.count(stamp);
  }

  timecritical::TOMMesh Mesh;
  std::string ErrorMessage;
  bool Valid = false;
  bool RememberValidated = false;
  StampSet Validated;       ///< validated in this reading pass
  StampSet ValidatedBefore; ///< validated in the previous one
};

vtkStandardNewMacro(vtkTOMFieldData);

vtkTOMFieldData::vtkTOMFieldData()
  : Internal(new Internals)
{
}

vtkTOMFieldData::~vtkTOMFieldData() = default;

bool vtkTOMFieldData::HasTOMArrays(vtkPolyData* data)
{
  return data && data->GetPointData()->GetAbstractArray(SubstitutionArrayName()) &&
    data->GetFieldData()->GetAbstractArray(CountsArrayName());
}

namespace
{
// Reads a non-negative integer that must fit in 32 bits.
bool ToIndex(double value, uint32_t& out)
{
  if (!(value >= 0.0) || value > std::numeric_limits<uint32_t>::max() || value != std::floor(value))
  {
    return false;
  }
  out = static_cast<uint32_t>(value);
  return true;
}
}

namespace
{
std::string CountsProblem(vtkDataArray* counts, uint32_t count[4])
{
  if (counts->GetNumberOfComponents() != 1 || counts->GetNumberOfTuples() != 4)
  {
    return "TOMCounts must hold 4 values (vertices, triangles, base vertices, base triangles)";
  }
  for (int i = 0; i < 4; ++i)
  {
    if (!ToIndex(counts->GetTuple1(i), count[i]))
    {
      std::ostringstream msg;
      msg << "TOMCounts value " << i << " (" << counts->GetTuple1(i) << ") is not a 32-bit count";
      return msg.str();
    }
  }
  return std::string();
}

std::string ReadSubstitution(vtkDataArray* substitution, std::vector<uint32_t>& out)
{
  out.resize(static_cast<size_t>(substitution->GetNumberOfTuples()));
  for (vtkIdType i = 0; i < substitution->GetNumberOfTuples(); ++i)
  {
    if (!ToIndex(substitution->GetTuple1(i), out[i]))
    {
      std::ostringstream msg;
      msg << "TOMSubstitution of point " << i << " (" << substitution->GetTuple1(i)
          << ") is not a point id";
      return msg.str();
    }
  }
  return std::string();
}

std::string ReadTriangles(vtkCellArray* polys, vtkIdType numberOfPoints, std::vector<uint32_t>& out)
{
  out.resize(3 * static_cast<size_t>(polys->GetNumberOfCells()));
  auto cells = vtk::TakeSmartPointer(polys->NewIterator());
  size_t t = 0;
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell(), ++t)
  {
    vtkIdType size;
    const vtkIdType* ids;
    cells->GetCurrentCell(size, ids);
    if (size != 3)
    {
      std::ostringstream msg;
      msg << "cell " << t << " has " << size << " points; a TOM holds triangles only";
      return msg.str();
    }
    for (int c = 0; c < 3; ++c)
    {
      if (ids[c] < 0 || ids[c] >= numberOfPoints)
      {
        std::ostringstream msg;
        msg << "triangle " << t << " refers to point " << ids[c] << ", out of range";
        return msg.str();
      }
      out[3 * t + c] = static_cast<uint32_t>(ids[c]);
    }
  }
  return std::string();
}

std::string ReadErrorCurve(vtkPolyData* data, timecritical::TOMErrorCurve& out)
{
  vtkAbstractArray* curveArray =
    data->GetFieldData()->GetAbstractArray(vtkTOMFieldData::ErrorCurveArrayName());
  if (!curveArray)
  {
    return std::string();
  }
  vtkDataArray* curve = vtkDataArray::SafeDownCast(curveArray);
  if (!curve || curve->GetNumberOfComponents() != 2)
  {
    return "TOMErrorCurve must be a numeric array of (triangles, error) pairs";
  }
  std::vector<timecritical::TOMErrorCurve::Sample> samples(curve->GetNumberOfTuples());
  for (vtkIdType i = 0; i < curve->GetNumberOfTuples(); ++i)
  {
    if (!ToIndex(curve->GetComponent(i, 0), samples[i].Triangles))
    {
      std::ostringstream msg;
      msg << "TOMErrorCurve sample " << i << " has a bad triangle count";
      return msg.str();
    }
    samples[i].Error = static_cast<float>(curve->GetComponent(i, 1));
  }
  out = timecritical::TOMErrorCurve(std::move(samples));
  return std::string();
}

}

// What a validation depends on: the points and the TOM's arrays, each by
// address and modification time (a VTK object gets a new time when it is
// made, so an address reused by another array does not match).
vtkTOMFieldData::Internals::Stamp vtkTOMFieldData::Internals::StampOf(vtkPolyData* data, vtkDataArray* substitution,
  vtkDataArray* counts)
{
  vtkObject* parts[] = { data->GetPoints(), substitution, counts, data->GetPolys(),
    data->GetFieldData()->GetAbstractArray(vtkTOMFieldData::ErrorCurveArrayName()) };
  Stamp stamp;
  for (size_t i = 0; i < 5; ++i)
  {
    stamp.Objects[i] = parts[i];
    stamp.Times[i] = parts[i] ? parts[i]->GetMTime() : 0;
  }
  return stamp;
}

bool vtkTOMFieldData::Read(vtkPolyData* data)
{
  Internals& in = *this->Internal;
  in.Valid = false;
  in.Mesh = timecritical::TOMMesh();
  auto fail = [&in](const std::string& message) {
    in.ErrorMessage = message;
    return false;
  };

  if (!data)
  {
    return fail("no input data");
  }
  vtkDataArray* substitution = data->GetPointData()->GetArray(SubstitutionArrayName());
  vtkDataArray* counts =
    vtkDataArray::SafeDownCast(data->GetFieldData()->GetAbstractArray(CountsArrayName()));
  if (!substitution || !counts)
  {
    return fail("not a Totally Ordered Mesh: the point-data array TOMSubstitution or the field-data "
                "array TOMCounts is missing (build one with vtkTOMBuilder)");
  }
  if (substitution->GetNumberOfComponents() != 1 ||
    !timecritical::IsIntegerType(substitution->GetDataType()))
  {
    return fail("TOMSubstitution must be a single-component integer array");
  }
  uint32_t count[4];
  std::string problem = CountsProblem(counts, count);
  if (!problem.empty())
  {
    return fail(problem);
  }
  const vtkIdType numberOfPoints = data->GetNumberOfPoints();
  if (numberOfPoints != static_cast<vtkIdType>(count[0]) ||
    substitution->GetNumberOfTuples() != numberOfPoints)
  {
    std::ostringstream msg;
    msg << "TOM vertex counts disagree: TOMCounts says " << count[0] << ", the data has "
        << numberOfPoints << " points and " << substitution->GetNumberOfTuples()
        << " TOMSubstitution values";
    return fail(msg.str());
  }
  if (data->GetNumberOfVerts() || data->GetNumberOfLines() || data->GetNumberOfStrips())
  {
    return fail("a TOM holds triangles only, but the data also has vertices, lines or strips");
  }
  vtkCellArray* polys = data->GetPolys();
  if (polys->GetNumberOfCells() != static_cast<vtkIdType>(count[1]))
  {
    std::ostringstream msg;
    msg << "TOMCounts says " << count[1] << " triangles, the data has "
        << polys->GetNumberOfCells() << " polygons";
    return fail(msg.str());
  }
  const Internals::Stamp stamp = Internals::StampOf(data, substitution, counts);
  const bool validatedBefore = in.RememberValidated && in.WasValidated(stamp);
  // Coordinates are data too: a NaN or infinite point would travel into every
  // extracted mesh and into the renderer's bounds.
  if (!validatedBefore)
  {
    problem = vtkPolyDataValidator::CheckCoordinates(data->GetPoints());
  }
  timecritical::TOMMesh& mesh = in.Mesh;
  if (problem.empty())
  {
    problem = ReadSubstitution(substitution, mesh.Substitution);
  }
  if (problem.empty())
  {
    problem = ReadTriangles(polys, numberOfPoints, mesh.Triangles);
  }
  if (problem.empty())
  {
    problem = ReadErrorCurve(data, mesh.ErrorCurve);
  }
  if (!problem.empty())
  {
    mesh = timecritical::TOMMesh();
    return fail(problem);
  }
  mesh.BaseVertexCount = count[2];
  mesh.BaseTriangleCount = count[3];
  // The replay of every prefix is the costly part of a read: skipped for
  // arrays that passed it unchanged.
  if (!validatedBefore)
  {
    problem = timecritical::TOMValidator::Check(mesh);
    if (!problem.empty())
    {
      mesh = timecritical::TOMMesh();
      return fail("invalid TOM: " + problem);
    }
  }
  if (in.RememberValidated)
  {
    in.Validated.insert(stamp);
  }
  in.ErrorMessage.clear();
  in.Valid = true;
  return true;
}

void vtkTOMFieldData::SetRememberValidated(bool remember)
{
  this->Internal->RememberValidated = remember;
  if (!remember)
  {
    this->Internal->Validated.clear();
    this->Internal->ValidatedBefore.clear();
  }
}

bool vtkTOMFieldData::GetRememberValidated() const
{
  return this->Internal->RememberValidated;
}

void vtkTOMFieldData::StartReadingPass()
{
  Internals& in = *this->Internal;
  in.ValidatedBefore.swap(in.Validated);
  in.Validated.clear();
}

void vtkTOMFieldData::ReleaseMesh()
{
  this->Internal->Mesh = timecritical::TOMMesh();
  this->Internal->Valid = false;
}

const char* vtkTOMFieldData::GetErrorMessage() const
{
  return this->Internal->ErrorMessage.c_str();
}

const timecritical::TOMMesh& vtkTOMFieldData::GetMesh() const
{
  return this->Internal->Mesh;
}

void vtkTOMFieldData::Write(const timecritical::TOMMesh& mesh, vtkPolyData* data)
{
  vtkNew<vtkTypeUInt32Array> substitution;
  substitution->SetName(SubstitutionArrayName());
  substitution->SetNumberOfValues(static_cast<vtkIdType>(mesh.Substitution.size()));
  std::copy(mesh.Substitution.begin(), mesh.Substitution.end(), substitution->GetPointer(0));
  data->GetPointData()->AddArray(substitution);

  vtkNew<vtkTypeUInt32Array> counts;
  counts->SetName(CountsArrayName());
  counts->SetNumberOfValues(4);
  counts->SetValue(0, mesh.GetNumberOfVertices());
  counts->SetValue(1, mesh.GetNumberOfTriangles());
  counts->SetValue(2, mesh.BaseVertexCount);
  counts->SetValue(3, mesh.BaseTriangleCount);
  data->GetFieldData()->AddArray(counts);

  vtkNew<vtkDoubleArray> curve;
  curve->SetName(ErrorCurveArrayName());
  curve->SetNumberOfComponents(2);
  curve->SetComponentName(0, "Triangles");
  curve->SetComponentName(1, "Error");
  const auto& samples = mesh.ErrorCurve.GetSamples();
  curve->SetNumberOfTuples(static_cast<vtkIdType>(samples.size()));
  for (size_t i = 0; i < samples.size(); ++i)
  {
    curve->SetComponent(static_cast<vtkIdType>(i), 0, samples[i].Triangles);
    curve->SetComponent(static_cast<vtkIdType>(i), 1, samples[i].Error);
  }
  data->GetFieldData()->AddArray(curve);
}

vtkIdType vtkTOMFieldData::GetNumberOfVertices() const
{
  return this->Internal->Valid ? this->Internal->Mesh.GetNumberOfVertices() : 0;
}

vtkIdType vtkTOMFieldData::GetNumberOfTriangles() const
{
  return this->Internal->Valid ? this->Internal->Mesh.GetNumberOfTriangles() : 0;
}

vtkIdType vtkTOMFieldData::GetBaseVertexCount() const
{
  return this->Internal->Valid ? this->Internal->Mesh.BaseVertexCount : 0;
}

vtkIdType vtkTOMFieldData::GetBaseTriangleCount() const
{
  return this->Internal->Valid ? this->Internal->Mesh.BaseTriangleCount : 0;
}

void vtkTOMFieldData::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Valid: " << this->Internal->Valid << "\n";
  os << indent << "ErrorMessage: " << this->Internal->ErrorMessage << "\n";
  os << indent << "NumberOfVertices: " << this->GetNumberOfVertices() << "\n";
  os << indent << "NumberOfTriangles: " << this->GetNumberOfTriangles() << "\n";
  os << indent << "BaseVertexCount: " << this->GetBaseVertexCount() << "\n";
  os << indent << "BaseTriangleCount: " << this->GetBaseTriangleCount() << "\n";
}
