// SPDX-License-Identifier: BSD-3-Clause
#include "vtkAccuracyCurveFieldData.h"

#include "AccuracyCurve.h"
#include "MergeTree.h"
#include "TOMErrorCurve.h"
#include "TOMMesh.h"
#include "TOMTraversal.h"
#include "vtkMergeTreeFieldData.h"
#include "vtkTOMFieldData.h"

#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

struct vtkAccuracyCurveFieldData::Internals
{
  timecritical::AccuracyCurve Curve;
  double Size = 0.0;
  bool Valid = false;
  std::string ErrorMessage;

  bool Fail(const std::string& message)
  {
    this->Curve = timecritical::AccuracyCurve();
    this->Size = 0.0;
    this->Valid = false;
    this->ErrorMessage = message;
    return false;
  }
  bool Succeed(timecritical::AccuracyCurve curve, double size)
  {
    this->Curve = std::move(curve);
    this->Size = size;
    this->Valid = true;
    this->ErrorMessage.clear();
    return true;
  }
};

vtkStandardNewMacro(vtkAccuracyCurveFieldData);

namespace
{
constexpr double NaN = std::numeric_limits<double>::quiet_NaN();

/// The single value of a one-value numeric field-data array, NaN when absent or malformed.
double SingleValue(vtkFieldData* fd, const char* name)
{
  vtkDataArray* array = vtkDataArray::SafeDownCast(fd->GetAbstractArray(name));
  if (!array || array->GetNumberOfComponents() != 1 || array->GetNumberOfTuples() != 1)
  {
    return NaN;
  }
  return array->GetTuple1(0);
}

void AddSingleValue(vtkFieldData* fd, const char* name, double value)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->SetNumberOfValues(1);
  array->SetValue(0, value);
  fd->AddArray(array);
}

/// Triangle count of the TOM with n active vertices, for every n (n + 1 entries).
std::vector<uint32_t> TrianglesAtVertexCount(const timecritical::TOMMesh& mesh)
{
  const uint32_t n = mesh.GetNumberOfVertices();
  std::vector<uint32_t> count(static_cast<size_t>(n) + 1, 0);
  const timecritical::TOMTraversal traversal(mesh);
  for (uint32_t t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    ++count[std::min(traversal.GetMinimumVertexCount(t), n)];
  }
  for (size_t i = 1; i < count.size(); ++i)
  {
    count[i] += count[i - 1];
  }
  return count;
}
}

//------------------------------------------------------------------------------
vtkAccuracyCurveFieldData::vtkAccuracyCurveFieldData()
  : Internal(new Internals)
{
}

vtkAccuracyCurveFieldData::~vtkAccuracyCurveFieldData() = default;

//------------------------------------------------------------------------------
bool vtkAccuracyCurveFieldData::HasAccuracyCurve(vtkDataObject* data)
{
  return data && data->GetFieldData() && data->GetFieldData()->GetAbstractArray(CurveArrayName());
}

//------------------------------------------------------------------------------
bool vtkAccuracyCurveFieldData::Read(vtkDataObject* data)
{
  Internals& in = *this->Internal;
  if (!HasAccuracyCurve(data))
  {
    return in.Fail("no accuracy curve: the field-data array AccuracyCurve is missing");
  }
  vtkFieldData* fd = data->GetFieldData();
  vtkDataArray* pieces = vtkDataArray::SafeDownCast(fd->GetAbstractArray(CurveArrayName()));
  if (!pieces || pieces->GetNumberOfComponents() != 3)
  {
    return in.Fail("AccuracyCurve must be a numeric array of (A, R, K) triples");
  }
  const double maximum = SingleValue(fd, MaximumAccuracyArrayName());
  if (std::isnan(maximum))
  {
    return in.Fail("AccuracyCurveMaximumAccuracy must be a numeric array of one value");
  }
  const double size = SingleValue(fd, SizeArrayName());
  if (!std::isfinite(size) || !(size > 0.0))
  {
    return in.Fail("AccuracyCurveSize must be a numeric array of one finite positive value");
  }
  std::vector<timecritical::AccuracyCurve::Piece> triples(
    static_cast<size_t>(pieces->GetNumberOfTuples()));
  for (vtkIdType i = 0; i < pieces->GetNumberOfTuples(); ++i)
  {
    triples[i] = { pieces->GetComponent(i, 0), pieces->GetComponent(i, 1),
      pieces->GetComponent(i, 2) };
  }
  const double end = maximum == -1.0 ? std::numeric_limits<double>::infinity() : maximum;
  try
  {
    return in.Succeed(timecritical::AccuracyCurve(std::move(triples), end), size);
  }
  catch (const std::invalid_argument& e)
  {
    return in.Fail(std::string("invalid accuracy curve: ") + e.what());
  }
}

//------------------------------------------------------------------------------
bool vtkAccuracyCurveFieldData::Derive(vtkPolyData* data)
{
  Internals& in = *this->Internal;
  if (!data)
  {
    return in.Fail("no input data");
  }
  const double size = data->GetLength();
  const bool hasTree = vtkMergeTreeFieldData::HasMergeTreeArrays(data);
  vtkNew<vtkMergeTreeFieldData> tree;
  vtkNew<vtkTOMFieldData> tom;
  if (hasTree ? !tree->Read(data) : !tom->Read(data))
  {
    return in.Fail(std::string("not a multiresolution object: ") +
      (hasTree ? tree->GetErrorMessage() : tom->GetErrorMessage()));
  }
  if (!std::isfinite(size) || !(size > 0.0))
  {
    return in.Fail("the object has no extent (all its points coincide): no relative accuracy");
  }
  try
  {
    if (hasTree)
    {
      return in.Succeed(FromMergeTree(tree->GetMesh(), tree->GetTree(), size), size);
    }
    if (tom->GetMesh().ErrorCurve.IsEmpty())
    {
      return in.Fail("the TOM has no error curve (field-data array TOMErrorCurve)");
    }
    return in.Succeed(FromErrorCurve(tom->GetMesh().ErrorCurve, size), size);
  }
  catch (const std::invalid_argument& e)
  {
    return in.Fail(std::string("cannot derive the accuracy curve: ") + e.what());
  }
}

//------------------------------------------------------------------------------
bool vtkAccuracyCurveFieldData::ReadOrDerive(vtkPolyData* data)
{
  return HasAccuracyCurve(data) ? this->Read(data) : this->Derive(data);
}

//------------------------------------------------------------------------------
bool vtkAccuracyCurveFieldData::Attach(vtkPolyData* data)
{
  return this->Derive(data) && this->WriteTo(data);
}

//------------------------------------------------------------------------------
bool vtkAccuracyCurveFieldData::WriteTo(vtkDataObject* data) const
{
  if (!this->Internal->Valid || !data)
  {
    return false;
  }
  Write(this->Internal->Curve, this->Internal->Size, data);
  return true;
}

//------------------------------------------------------------------------------
const char* vtkAccuracyCurveFieldData::GetErrorMessage() const
{
  return this->Internal->ErrorMessage.c_str();
}

//------------------------------------------------------------------------------
int vtkAccuracyCurveFieldData::GetNumberOfPieces() const
{
  return static_cast<int>(this->Internal->Curve.GetPieces().size());
}

double vtkAccuracyCurveFieldData::GetSize() const
{
  return this->Internal->Valid ? this->Internal->Size : NaN;
}

double vtkAccuracyCurveFieldData::GetMaximumAccuracy() const
{
  return this->Internal->Valid ? this->Internal->Curve.GetMaximumAccuracy() : NaN;
}

//------------------------------------------------------------------------------
double vtkAccuracyCurveFieldData::GetResources(double relativeAccuracy) const
{
  if (!this->Internal->Valid)
  {
    return NaN;
  }
  try
  {
    return this->Internal->Curve.GetResources(relativeAccuracy);
  }
  catch (const std::invalid_argument& e)
  {
    vtkErrorMacro(<< e.what());
    return NaN;
  }
}

//------------------------------------------------------------------------------
double vtkAccuracyCurveFieldData::GetAccuracy(double triangleQuota) const
{
  if (!this->Internal->Valid)
  {
    return NaN;
  }
  try
  {
    return this->Internal->Curve.GetAccuracy(triangleQuota);
  }
  catch (const std::invalid_argument& e)
  {
    vtkErrorMacro(<< e.what());
    return NaN;
  }
}

//------------------------------------------------------------------------------
const timecritical::AccuracyCurve& vtkAccuracyCurveFieldData::GetCurve() const
{
  return this->Internal->Curve;
}

//------------------------------------------------------------------------------
timecritical::AccuracyCurve vtkAccuracyCurveFieldData::FromErrorCurve(
  const timecritical::TOMErrorCurve& errorCurve, double size)
{
  std::vector<timecritical::AccuracyCurve::ErrorSample> samples;
  samples.reserve(errorCurve.GetSamples().size());
  for (const auto& s : errorCurve.GetSamples())
  {
    samples.push_back({ static_cast<double>(s.Triangles), static_cast<double>(s.Error) });
  }
  return timecritical::AccuracyCurve::FromErrorSamples(samples, size);
}

//------------------------------------------------------------------------------
timecritical::AccuracyCurve vtkAccuracyCurveFieldData::FromMergeTree(
  const timecritical::TOMMesh& mesh, const timecritical::MergeTree& tree, double size)
{
  const uint32_t n = mesh.GetNumberOfVertices();
  if (tree.Error.size() != n)
  {
    throw std::invalid_argument("the merge tree has " + std::to_string(tree.Error.size()) +
      " node errors for a TOM of " + std::to_string(n) + " vertices");
  }
  // Error of the mesh with i vertices: the largest error of the vertices
  // i..n-1 it lacks (vertex ids order the collapses, the last id first).
  std::vector<float> error(static_cast<size_t>(n) + 1, 0.f);
  for (uint32_t i = n; i-- > 0;)
  {
    error[i] = std::max(error[i + 1], tree.Error[i]);
  }
  const std::vector<uint32_t> triangles = TrianglesAtVertexCount(mesh);
  const auto curve = timecritical::TOMErrorCurve::FromVertexErrors(
    error.data(), triangles.data(), n, mesh.BaseVertexCount, MergeTreeCurveSamples);
  return FromErrorCurve(curve, size);
}

//------------------------------------------------------------------------------
void vtkAccuracyCurveFieldData::Write(
  const timecritical::AccuracyCurve& curve, double size, vtkDataObject* data)
{
  vtkFieldData* fd = data->GetFieldData();
  vtkNew<vtkDoubleArray> pieces;
  pieces->SetName(CurveArrayName());
  pieces->SetNumberOfComponents(3);
  pieces->SetComponentName(0, "A");
  pieces->SetComponentName(1, "R");
  pieces->SetComponentName(2, "K");
  const auto& triples = curve.GetPieces();
  pieces->SetNumberOfTuples(static_cast<vtkIdType>(triples.size()));
  for (size_t i = 0; i < triples.size(); ++i)
  {
    const double tuple[3] = { triples[i].A, triples[i].R, triples[i].K };
    pieces->SetTypedTuple(static_cast<vtkIdType>(i), tuple);
  }
  fd->AddArray(pieces);
  const double maximum = curve.GetMaximumAccuracy();
  AddSingleValue(fd, MaximumAccuracyArrayName(), std::isinf(maximum) ? -1.0 : maximum);
  AddSingleValue(fd, SizeArrayName(), size);
}

//------------------------------------------------------------------------------
void vtkAccuracyCurveFieldData::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Valid: " << this->Internal->Valid << "\n";
  os << indent << "ErrorMessage: " << this->Internal->ErrorMessage << "\n";
  os << indent << "NumberOfPieces: " << this->GetNumberOfPieces() << "\n";
  os << indent << "Size: " << this->Internal->Size << "\n";
  os << indent << "MaximumAccuracy: " << this->GetMaximumAccuracy() << "\n";
}
