// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMergeTreeFieldData.h"

#include "MergeTree.h"
#include "TOMFilterSupport.h"
#include "TOMMesh.h"
#include "vtkTOMFieldData.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkTypeUInt16Array.h"
#include "vtkTypeUInt32Array.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

struct vtkMergeTreeFieldData::Internals
{
  vtkNew<vtkTOMFieldData> TOM;
  timecritical::MergeTree Tree;
  std::string ErrorMessage;
  bool Valid = false;
};

vtkStandardNewMacro(vtkMergeTreeFieldData);

vtkMergeTreeFieldData::vtkMergeTreeFieldData()
  : Internal(new Internals)
{
}

vtkMergeTreeFieldData::~vtkMergeTreeFieldData() = default;

namespace
{
const char* const PointArrays[] = { "MergeTreeLevel", "MergeTreeError", "MergeTreeRadius",
  "MergeTreeConeAxis", "MergeTreeConeCosine" };
const char* const FieldArrays[] = { "MergeTreeDependencyOffsets", "MergeTreeDependencies",
  "MergeTreeLevelCount" };

// Largest deviation of a cone axis from unit length: the arrays are float, and
// a normalized float vector is within a few ulps of 1.
constexpr double AxisLengthTolerance = 1e-3;

enum class Kind
{
  Integer,
  Real
};

/**
 * Looks up one merge-tree array and checks its type, component count and
 * (when tuples >= 0) tuple count. Returns an empty string and sets `out`, or
 * the problem.
 */
std::string FindArray(vtkFieldData* fields, const char* where, const char* name, Kind kind,
  int components, vtkIdType tuples, const char* tuplesMeaning, vtkDataArray*& out)
{
  out = nullptr;
  vtkAbstractArray* abstract = fields->GetAbstractArray(name);
  std::ostringstream msg;
  if (!abstract)
  {
    msg << "the " << where << " array " << name << " is missing";
    return msg.str();
  }
  vtkDataArray* array = vtkDataArray::SafeDownCast(abstract);
  const char* wanted = kind == Kind::Integer ? "an integer" : "a floating-point";
  if (!array)
  {
    msg << name << " is a " << abstract->GetClassName() << "; it must be " << wanted << " array";
    return msg.str();
  }
  const bool integer = timecritical::IsIntegerType(array->GetDataType());
  const bool real = array->GetDataType() == VTK_FLOAT || array->GetDataType() == VTK_DOUBLE;
  if ((kind == Kind::Integer && !integer) || (kind == Kind::Real && !real))
  {
    msg << name << " holds " << array->GetDataTypeAsString() << " values; it must be " << wanted
        << " array";
    return msg.str();
  }
  if (array->GetNumberOfComponents() != components)
  {
    msg << name << " has " << array->GetNumberOfComponents() << " components; it must have "
        << components;
    return msg.str();
  }
  if (tuples >= 0 && array->GetNumberOfTuples() != tuples)
  {
    msg << name << " has " << array->GetNumberOfTuples() << " tuples; it must have " << tuples
        << " (" << tuplesMeaning << ")";
    return msg.str();
  }
  out = array;
  return std::string();
}

// Reads an integer value in [0, maximum]; describes the problem otherwise.
template <typename T>
std::string ToUnsigned(vtkDataArray* array, vtkIdType index, T& out)
{
  const double value = array->GetComponent(index, 0);
  if (!(value >= 0.0) || value > static_cast<double>(std::numeric_limits<T>::max()))
  {
    std::ostringstream msg;
    msg << array->GetName() << " entry " << index << " (" << value << ") is outside [0, "
        << static_cast<uint64_t>(std::numeric_limits<T>::max()) << "]";
    return msg.str();
  }
  out = static_cast<T>(value);
  return std::string();
}

// Copies a real array into floats; range and finiteness are checked by Check().
void ToFloats(vtkDataArray* array, std::vector<float>& out)
{
  const int components = array->GetNumberOfComponents();
  const vtkIdType tuples = array->GetNumberOfTuples();
  out.resize(static_cast<size_t>(tuples) * components);
  for (vtkIdType t = 0; t < tuples; ++t)
  {
    for (int c = 0; c < components; ++c)
    {
      out[static_cast<size_t>(t) * components + c] =
        static_cast<float>(array->GetComponent(t, c));
    }
  }
}

std::string SizeProblem(const char* name, size_t size, size_t expected, const char* meaning)
{
  std::ostringstream msg;
  msg << name << " has " << size << " values; it must have " << expected << " (" << meaning
      << ")";
  return msg.str();
}
}

bool vtkMergeTreeFieldData::HasMergeTreeArrays(vtkPolyData* data)
{
  if (!data)
  {
    return false;
  }
  for (const char* name : PointArrays)
  {
    if (data->GetPointData()->GetAbstractArray(name))
    {
      return true;
    }
  }
  for (const char* name : FieldArrays)
  {
    if (data->GetFieldData()->GetAbstractArray(name))
    {
      return true;
    }
  }
  return false;
}

std::string vtkMergeTreeFieldData::Check(
  const timecritical::TOMMesh& mesh, const timecritical::MergeTree& tree)
{
  const size_t n = mesh.GetNumberOfVertices();
  const uint32_t base = mesh.BaseVertexCount;
  if (tree.Level.size() != n)
  {
    return SizeProblem(LevelArrayName(), tree.Level.size(), n, "one per point");
  }
  if (tree.Error.size() != n)
  {
    return SizeProblem(ErrorArrayName(), tree.Error.size(), n, "one per point");
  }
  if (tree.Radius.size() != n)
  {
    return SizeProblem(RadiusArrayName(), tree.Radius.size(), n, "one per point");
  }
  if (tree.ConeAxis.size() != 3 * n)
  {
    return SizeProblem(ConeAxisArrayName(), tree.ConeAxis.size(), 3 * n, "three per point");
  }
  if (tree.ConeCosine.size() != n)
  {
    return SizeProblem(ConeCosineArrayName(), tree.ConeCosine.size(), n, "one per point");
  }
  if (tree.DependencyOffsets.size() != n + 1)
  {
    return SizeProblem(
      DependencyOffsetsArrayName(), tree.DependencyOffsets.size(), n + 1, "one per point, plus one");
  }

  std::ostringstream msg;
  for (size_t v = 0; v < n; ++v)
  {
    const bool isBase = v < base;
    if (isBase && tree.Level[v] != tree.LevelCount)
    {
      msg << LevelArrayName() << " of base point " << v << " is " << tree.Level[v]
          << "; base points must have the level count, " << tree.LevelCount;
      return msg.str();
    }
    if (!isBase && tree.Level[v] >= tree.LevelCount)
    {
      msg << LevelArrayName() << " of point " << v << " is " << tree.Level[v]
          << "; removed points must have a level below the level count, " << tree.LevelCount;
      return msg.str();
    }
    const float error = tree.Error[v];
    if (!std::isfinite(error) || error < 0.0f)
    {
      msg << ErrorArrayName() << " of point " << v << " (" << error
          << ") is not a finite, non-negative distance";
      return msg.str();
    }
    const float radius = tree.Radius[v];
    if (!std::isfinite(radius) || radius < 0.0f)
    {
      msg << RadiusArrayName() << " of point " << v << " (" << radius
          << ") is not a finite, non-negative distance";
      return msg.str();
    }
    const float cosine = tree.ConeCosine[v];
    if (!std::isfinite(cosine) || cosine < -1.0f || cosine > 1.0f)
    {
      msg << ConeCosineArrayName() << " of point " << v << " (" << cosine
          << ") is not a cosine in [-1, 1]";
      return msg.str();
    }
    const float* axis = &tree.ConeAxis[3 * v];
    if (!std::isfinite(axis[0]) || !std::isfinite(axis[1]) || !std::isfinite(axis[2]))
    {
      msg << ConeAxisArrayName() << " of point " << v << " (" << axis[0] << ", " << axis[1]
          << ", " << axis[2] << ") is not finite";
      return msg.str();
    }
    // A full-sphere cone (cosine -1) needs no axis; any other needs a unit one.
    const double length = std::sqrt(static_cast<double>(axis[0]) * axis[0] +
      static_cast<double>(axis[1]) * axis[1] + static_cast<double>(axis[2]) * axis[2]);
    if (cosine > -1.0f && std::abs(length - 1.0) > AxisLengthTolerance)
    {
      msg << ConeAxisArrayName() << " of point " << v << " has length " << length
          << "; a normal-cone axis must be a unit vector";
      return msg.str();
    }
  }

  const auto& offsets = tree.DependencyOffsets;
  if (offsets[0] != 0)
  {
    msg << DependencyOffsetsArrayName() << " must start at 0, not " << offsets[0];
    return msg.str();
  }
  for (size_t v = 0; v < n; ++v)
  {
    if (offsets[v + 1] < offsets[v])
    {
      msg << DependencyOffsetsArrayName() << " decreases at entry " << v + 1 << " ("
          << offsets[v] << " then " << offsets[v + 1] << "); offsets must be monotone";
      return msg.str();
    }
    if (v < base && offsets[v + 1] != offsets[v])
    {
      msg << "base point " << v << " has " << offsets[v + 1] - offsets[v]
          << " dependencies in " << DependenciesArrayName() << "; base points have none";
      return msg.str();
    }
  }
  if (offsets[n] != tree.Dependencies.size())
  {
    msg << DependencyOffsetsArrayName() << " ends at " << offsets[n] << " but "
        << DependenciesArrayName() << " holds " << tree.Dependencies.size() << " values";
    return msg.str();
  }
  for (size_t v = base; v < n; ++v)
  {
    for (uint32_t k = offsets[v]; k < offsets[v + 1]; ++k)
    {
      // Only points displayed just before the collapse of v can be its
      // dependencies, and those have lower ids (larger ids collapsed earlier).
      if (tree.Dependencies[k] >= v)
      {
        msg << DependenciesArrayName() << " entry " << k << " (dependency of point " << v
            << ") is " << tree.Dependencies[k] << "; dependencies of point " << v
            << " must be point ids below " << v;
        return msg.str();
      }
    }
  }
  return std::string();
}

bool vtkMergeTreeFieldData::Read(vtkPolyData* data)
{
  Internals& in = *this->Internal;
  in.Valid = false;
  in.Tree = timecritical::MergeTree();
  auto fail = [&in](const std::string& message) {
    in.ErrorMessage = message;
    return false;
  };

  if (!data)
  {
    return fail("no input data");
  }
  if (!HasMergeTreeArrays(data))
  {
    return fail("not a merge tree: the merge-tree arrays (MergeTreeLevel, MergeTreeError, ...) "
                "are missing (build one with vtkMergeTreeBuilder)");
  }
  if (!in.TOM->Read(data))
  {
    return fail(std::string("the merge tree's TOM is invalid: ") + in.TOM->GetErrorMessage());
  }
  const timecritical::TOMMesh& mesh = in.TOM->GetMesh();
  const vtkIdType n = mesh.GetNumberOfVertices();
  vtkPointData* pd = data->GetPointData();
  vtkFieldData* fd = data->GetFieldData();

  vtkDataArray* level;
  vtkDataArray* error;
  vtkDataArray* radius;
  vtkDataArray* axis;
  vtkDataArray* cosine;
  vtkDataArray* offsets;
  vtkDataArray* dependencies;
  vtkDataArray* levelCount;
  struct Wanted
  {
    vtkFieldData* Fields;
    const char* Where;
    const char* Name;
    Kind Type;
    int Components;
    vtkIdType Tuples;
    const char* TuplesMeaning;
    vtkDataArray** Out;
  };
  const Wanted wanted[] = {
    { pd, "point-data", LevelArrayName(), Kind::Integer, 1, n, "one per point", &level },
    { pd, "point-data", ErrorArrayName(), Kind::Real, 1, n, "one per point", &error },
    { pd, "point-data", RadiusArrayName(), Kind::Real, 1, n, "one per point", &radius },
    { pd, "point-data", ConeAxisArrayName(), Kind::Real, 3, n, "one per point", &axis },
    { pd, "point-data", ConeCosineArrayName(), Kind::Real, 1, n, "one per point", &cosine },
    { fd, "field-data", DependencyOffsetsArrayName(), Kind::Integer, 1, n + 1,
      "one per point, plus one", &offsets },
    { fd, "field-data", DependenciesArrayName(), Kind::Integer, 1, -1, "", &dependencies },
    { fd, "field-data", LevelCountArrayName(), Kind::Integer, 1, 1, "the number of levels",
      &levelCount },
  };
  std::string problem;
  for (const Wanted& w : wanted)
  {
    problem = FindArray(
      w.Fields, w.Where, w.Name, w.Type, w.Components, w.Tuples, w.TuplesMeaning, *w.Out);
    if (!problem.empty())
    {
      return fail("invalid merge tree: " + problem);
    }
  }

  timecritical::MergeTree& tree = in.Tree;
  if (!(problem = ToUnsigned(levelCount, 0, tree.LevelCount)).empty())
  {
    return fail("invalid merge tree: " + problem);
  }
  tree.Level.resize(static_cast<size_t>(n));
  for (vtkIdType v = 0; v < n; ++v)
  {
    if (!(problem = ToUnsigned(level, v, tree.Level[v])).empty())
    {
      return fail("invalid merge tree: " + problem);
    }
  }
  tree.DependencyOffsets.resize(static_cast<size_t>(n) + 1);
  for (vtkIdType v = 0; v <= n; ++v)
  {
    if (!(problem = ToUnsigned(offsets, v, tree.DependencyOffsets[v])).empty())
    {
      return fail("invalid merge tree: " + problem);
    }
  }
  const vtkIdType numberOfDependencies = dependencies->GetNumberOfTuples();
  tree.Dependencies.resize(static_cast<size_t>(numberOfDependencies));
  for (vtkIdType k = 0; k < numberOfDependencies; ++k)
  {
    if (!(problem = ToUnsigned(dependencies, k, tree.Dependencies[k])).empty())
    {
      return fail("invalid merge tree: " + problem);
    }
  }
  ToFloats(error, tree.Error);
  ToFloats(radius, tree.Radius);
  ToFloats(axis, tree.ConeAxis);
  ToFloats(cosine, tree.ConeCosine);

  problem = Check(mesh, tree);
  if (!problem.empty())
  {
    return fail("invalid merge tree: " + problem);
  }
  in.ErrorMessage.clear();
  in.Valid = true;
  return true;
}

const char* vtkMergeTreeFieldData::GetErrorMessage() const
{
  return this->Internal->ErrorMessage.c_str();
}

vtkTOMFieldData* vtkMergeTreeFieldData::GetTOMFieldData() const
{
  return this->Internal->TOM;
}

const timecritical::MergeTree& vtkMergeTreeFieldData::GetTree() const
{
  return this->Internal->Tree;
}

const timecritical::TOMMesh& vtkMergeTreeFieldData::GetMesh() const
{
  return this->Internal->TOM->GetMesh();
}

namespace
{
template <typename ArrayT, typename T>
void AddArray(vtkFieldData* fields, const char* name, int components, const std::vector<T>& values)
{
  vtkNew<ArrayT> array;
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(static_cast<vtkIdType>(values.size() / components));
  std::copy(values.begin(), values.end(), array->GetPointer(0));
  fields->AddArray(array);
}
}

void vtkMergeTreeFieldData::Write(
  const timecritical::TOMMesh& mesh, const timecritical::MergeTree& tree, vtkPolyData* data)
{
  vtkTOMFieldData::Write(mesh, data);
  vtkPointData* pd = data->GetPointData();
  AddArray<vtkTypeUInt16Array>(pd, LevelArrayName(), 1, tree.Level);
  AddArray<vtkFloatArray>(pd, ErrorArrayName(), 1, tree.Error);
  AddArray<vtkFloatArray>(pd, RadiusArrayName(), 1, tree.Radius);
  AddArray<vtkFloatArray>(pd, ConeAxisArrayName(), 3, tree.ConeAxis);
  AddArray<vtkFloatArray>(pd, ConeCosineArrayName(), 1, tree.ConeCosine);
  vtkFieldData* fd = data->GetFieldData();
  AddArray<vtkTypeUInt32Array>(fd, DependencyOffsetsArrayName(), 1, tree.DependencyOffsets);
  AddArray<vtkTypeUInt32Array>(fd, DependenciesArrayName(), 1, tree.Dependencies);
  AddArray<vtkTypeUInt16Array>(fd, LevelCountArrayName(), 1, std::vector<uint16_t>{ tree.LevelCount });
}

vtkIdType vtkMergeTreeFieldData::GetNumberOfVertices() const
{
  return this->Internal->Valid ? this->Internal->Tree.GetNumberOfVertices() : 0;
}

int vtkMergeTreeFieldData::GetLevelCount() const
{
  return this->Internal->Valid ? this->Internal->Tree.LevelCount : 0;
}

vtkIdType vtkMergeTreeFieldData::GetNumberOfDependencies() const
{
  return this->Internal->Valid ? static_cast<vtkIdType>(this->Internal->Tree.Dependencies.size())
                               : 0;
}

void vtkMergeTreeFieldData::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Valid: " << this->Internal->Valid << "\n";
  os << indent << "ErrorMessage: " << this->Internal->ErrorMessage << "\n";
  os << indent << "NumberOfVertices: " << this->GetNumberOfVertices() << "\n";
  os << indent << "LevelCount: " << this->GetLevelCount() << "\n";
  os << indent << "NumberOfDependencies: " << this->GetNumberOfDependencies() << "\n";
  os << indent << "TOMFieldData:\n";
  this->Internal->TOM->PrintSelf(os, indent.GetNextIndent());
}
