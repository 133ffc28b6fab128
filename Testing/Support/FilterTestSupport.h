// SPDX-License-Identifier: BSD-3-Clause
// Helpers shared by the GoogleTest tests of the VTK filters (TestvtkTOMBuilder,
// TestvtkCollapseHierarchyBuilder, TestvtkMergeTreeBuilder and the others): the
// two builders take the same input checks and carry data the same way, so
// their tests use one message log, one set of input meshes and one check of
// how data travels.
#ifndef timecritical_FilterTestSupport_h
#define timecritical_FilterTestSupport_h

#include "vtkAlgorithm.h"
#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkStripper.h"
#include "vtkTriangleFilter.h"
#include "vtkVariant.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLPolyDataWriter.h"

#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace timecritical
{
namespace testing
{
/// Collects the error and warning messages an object emits.
class MessageLog
{
public:
  explicit MessageLog(vtkObject* object)
  {
    this->Callback->SetClientData(this);
    this->Callback->SetCallback([](vtkObject*, unsigned long event, void* client, void* data) {
      auto* self = static_cast<MessageLog*>(client);
      (event == vtkCommand::ErrorEvent ? self->Errors : self->Warnings)
        .emplace_back(data ? static_cast<const char*>(data) : "");
    });
    object->AddObserver(vtkCommand::ErrorEvent, this->Callback);
    object->AddObserver(vtkCommand::WarningEvent, this->Callback);
  }
  bool ErrorContains(const std::string& text) const
  {
    for (const auto& e : this->Errors)
    {
      if (e.find(text) != std::string::npos)
      {
        return true;
      }
    }
    return false;
  }
  std::string AllErrors() const
  {
    std::string all;
    for (const auto& e : this->Errors)
    {
      all += e;
    }
    return all;
  }
  std::vector<std::string> Errors;
  std::vector<std::string> Warnings;

private:
  vtkNew<vtkCallbackCommand> Callback;
};

/**
 * A closed sphere with normals (point data) and its input cell ids (cell data
 * "InputCellId"), to follow points and triangles through the reordering.
 */
inline vtkSmartPointer<vtkPolyData> MakeSphere(int resolution = 40)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(resolution);
  sphere->SetPhiResolution(resolution);
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(sphere->GetOutputPort());
  normals->SplittingOff();
  normals->Update();
  vtkSmartPointer<vtkPolyData> out = normals->GetOutput();
  vtkNew<vtkDoubleArray> cellIds;
  cellIds->SetName("InputCellId");
  for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
  {
    cellIds->InsertNextValue(static_cast<double>(c));
  }
  out->GetCellData()->AddArray(cellIds);
  return out;
}

/// Runs `filter` (a new one when null) on `input` and returns its output.
template <typename Filter>
vtkSmartPointer<vtkPolyData> RunFilter(vtkPolyData* input, Filter* filter)
{
  vtkSmartPointer<Filter> local = filter;
  if (!local)
  {
    local = vtkSmartPointer<Filter>::New();
  }
  local->SetInputData(input);
  local->Update();
  vtkSmartPointer<vtkPolyData> out = local->GetOutput();
  return out;
}

using PointKeyType = std::array<double, 3>;
inline PointKeyType PointKey(vtkPolyData* data, vtkIdType id)
{
  PointKeyType k;
  data->GetPoint(id, k.data());
  return k;
}

/// Two points and one line: no surface cells.
inline vtkSmartPointer<vtkPolyData> LinesOnly()
{
  auto lines = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  lines->SetPoints(points);
  vtkNew<vtkCellArray> cells;
  cells->InsertNextCell({ 0, 1 });
  lines->SetLines(cells);
  return lines;
}

/**
 * Two triangles sharing an edge through duplicated points (2 merged points),
 * plus a triangle that collapses to a line once the duplicates are merged,
 * plus a line cell (2 dropped cells): 4 points and 2 triangles remain.
 */
inline vtkSmartPointer<vtkPolyData> DuplicatePointsAndDegenerateCells()
{
  auto data = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0); // 0
  points->InsertNextPoint(1, 0, 0); // 1
  points->InsertNextPoint(0, 1, 0); // 2
  points->InsertNextPoint(1, 0, 0); // 3 = 1
  points->InsertNextPoint(0, 1, 0); // 4 = 2
  points->InsertNextPoint(1, 1, 0); // 5
  data->SetPoints(points);
  vtkNew<vtkCellArray> polys;
  polys->InsertNextCell({ 0, 1, 2 });
  polys->InsertNextCell({ 3, 5, 4 });
  polys->InsertNextCell({ 1, 3, 2 }); // degenerate after merging
  data->SetPolys(polys);
  vtkNew<vtkCellArray> lines;
  lines->InsertNextCell({ 0, 5 });
  data->SetLines(lines);
  return data;
}

/// A 10x10 plane of quads (200 triangles once triangulated).
inline vtkSmartPointer<vtkPolyData> PlaneQuads()
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(10, 10);
  plane->Update();
  vtkSmartPointer<vtkPolyData> out = plane->GetOutput();
  return out;
}

/// The same plane as triangle strips.
inline vtkSmartPointer<vtkPolyData> PlaneStrips()
{
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(PlaneQuads());
  vtkNew<vtkStripper> stripper;
  stripper->SetInputConnection(triangles->GetOutputPort());
  stripper->Update();
  vtkSmartPointer<vtkPolyData> out = stripper->GetOutput();
  return out;
}

/// Sets AbortExecute on `filter` once its progress passes 0.2.
inline void AbortPastOneFifth(vtkAlgorithm* filter)
{
  vtkNew<vtkCallbackCommand> abort;
  abort->SetCallback([](vtkObject* caller, unsigned long, void*, void*) {
    auto* algorithm = static_cast<vtkAlgorithm*>(caller);
    if (algorithm->GetProgress() > 0.2)
    {
      algorithm->SetAbortExecute(1);
    }
  });
  filter->AddObserver(vtkCommand::ProgressEvent, abort);
}

/// Same type, shape, name and values (bytes of numeric arrays, else text).
inline void ExpectSameArray(vtkAbstractArray* a, vtkAbstractArray* b, const std::string& what)
{
  ASSERT_TRUE(a && b) << what;
  EXPECT_STREQ(a->GetName(), b->GetName()) << what;
  ASSERT_EQ(a->GetDataType(), b->GetDataType()) << what;
  ASSERT_EQ(a->GetNumberOfComponents(), b->GetNumberOfComponents()) << what;
  ASSERT_EQ(a->GetNumberOfTuples(), b->GetNumberOfTuples()) << what;
  auto* da = vtkDataArray::SafeDownCast(a);
  auto* db = vtkDataArray::SafeDownCast(b);
  if (da && db && da->HasStandardMemoryLayout() && db->HasStandardMemoryLayout())
  {
    const size_t bytes =
      static_cast<size_t>(da->GetNumberOfValues()) * static_cast<size_t>(da->GetDataTypeSize());
    EXPECT_EQ(bytes == 0 ? 0 : std::memcmp(da->GetVoidPointer(0), db->GetVoidPointer(0), bytes), 0)
      << what;
    return;
  }
  for (vtkIdType i = 0; i < a->GetNumberOfValues(); ++i)
  {
    ASSERT_EQ(a->GetVariantValue(i).ToString(), b->GetVariantValue(i).ToString()) << what;
  }
}

/// Two polydata hold the same points, cells and point, cell and field arrays, bit for bit.
inline void ExpectSameArrays(vtkPolyData* a, vtkPolyData* b)
{
  ASSERT_TRUE(a && b);
  ExpectSameArray(a->GetPoints()->GetData(), b->GetPoints()->GetData(), "points");
  vtkCellArray* cells[4][2] = { { a->GetVerts(), b->GetVerts() }, { a->GetLines(), b->GetLines() },
    { a->GetPolys(), b->GetPolys() }, { a->GetStrips(), b->GetStrips() } };
  for (auto& pair : cells)
  {
    ASSERT_EQ(pair[0]->GetNumberOfCells(), pair[1]->GetNumberOfCells());
    if (pair[0]->GetNumberOfCells() > 0)
    {
      ExpectSameArray(pair[0]->GetOffsetsArray(), pair[1]->GetOffsetsArray(), "offsets");
      ExpectSameArray(
        pair[0]->GetConnectivityArray(), pair[1]->GetConnectivityArray(), "connectivity");
    }
  }
  vtkFieldData* attributes[3][2] = { { a->GetPointData(), b->GetPointData() },
    { a->GetCellData(), b->GetCellData() }, { a->GetFieldData(), b->GetFieldData() } };
  for (auto& pair : attributes)
  {
    ASSERT_EQ(pair[0]->GetNumberOfArrays(), pair[1]->GetNumberOfArrays());
    for (int i = 0; i < pair[0]->GetNumberOfArrays(); ++i)
    {
      vtkAbstractArray* array = pair[0]->GetAbstractArray(i);
      ExpectSameArray(array, pair[1]->GetAbstractArray(array->GetName()),
        std::string("array ") + (array->GetName() ? array->GetName() : "?"));
    }
  }
}

/**
 * Checks that every output point carries the normal of the input point at the
 * same place, and every output triangle the "InputCellId" of the input
 * triangle with the same corners in the same order (MakeSphere's arrays).
 */
inline void ExpectDataTravelsWithPointsAndTriangles(vtkPolyData* input, vtkPolyData* out)
{
  ASSERT_EQ(out->GetNumberOfPoints(), input->GetNumberOfPoints());
  std::map<PointKeyType, vtkIdType> inputIds;
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    inputIds[PointKey(input, i)] = i;
  }
  vtkDataArray* inNormals = input->GetPointData()->GetNormals();
  vtkDataArray* outNormals = out->GetPointData()->GetNormals();
  ASSERT_NE(outNormals, nullptr);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    auto found = inputIds.find(PointKey(out, i));
    ASSERT_NE(found, inputIds.end());
    for (int c = 0; c < 3; ++c)
    {
      ASSERT_EQ(outNormals->GetComponent(i, c), inNormals->GetComponent(found->second, c));
    }
  }
  vtkDataArray* cellIds = out->GetCellData()->GetArray("InputCellId");
  ASSERT_NE(cellIds, nullptr);
  std::vector<bool> seen(input->GetNumberOfCells(), false);
  for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
  {
    const auto inCell = static_cast<vtkIdType>(cellIds->GetTuple1(c));
    ASSERT_FALSE(seen[inCell]);
    seen[inCell] = true;
    vtkIdType nOut, nIn;
    const vtkIdType* outIds;
    const vtkIdType* inIds;
    out->GetCellPoints(c, nOut, outIds);
    input->GetCellPoints(inCell, nIn, inIds);
    ASSERT_EQ(nOut, 3);
    ASSERT_EQ(nIn, 3);
    for (int k = 0; k < 3; ++k)
    {
      ASSERT_EQ(PointKey(out, outIds[k]), PointKey(input, inIds[k])) << "winding must be kept";
    }
  }
}

/**
 * Writes `data` to `path` as a .vtp file and reads it back into `back`.
 * Inline binary: Debian 12's VTK 9.2 cannot read back appended-mode files
 * with its patched expat (a platform bug, see docs/known-issues.md).
 */
inline void WriteAndReadBack(
  vtkPolyData* data, const std::string& path, vtkSmartPointer<vtkPolyData>& back)
{
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(data);
  writer->SetDataModeToBinary();
  ASSERT_EQ(writer->Write(), 1);
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  back = reader->GetOutput();
}
}
}

#endif
