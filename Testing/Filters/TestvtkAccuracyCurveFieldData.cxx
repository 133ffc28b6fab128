// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkAccuracyCurveFieldData: the curve of a TOM from its error curve,
// of a merge tree from its node errors (a hand-set error step, checked against
// the TOM's triangle counts), the arrays surviving binary and ASCII .vtp files,
// and every way the data can fail.
#include "AccuracyCurve.h"
#include "FilterTestSupport.h"
#include "MergeTreeFilterTestSupport.h"
#include "TOMMesh.h"
#include "TOMTraversal.h"
#include "vtkAccuracyCurveFieldData.h"
#include "vtkMergeTreeFieldData.h"
#include "vtkTOMBuilder.h"
#include "vtkTOMFieldData.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLPolyDataWriter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace
{
namespace tt = timecritical::testing;
using timecritical::AccuracyCurve;
constexpr double Inf = std::numeric_limits<double>::infinity();

vtkSmartPointer<vtkPolyData> SphereTOM(int resolution = 10)
{
  return tt::RunFilter<vtkTOMBuilder>(tt::MakeSphere(resolution), nullptr);
}

std::string ReadError(vtkPolyData* data)
{
  vtkNew<vtkAccuracyCurveFieldData> curve;
  EXPECT_FALSE(curve->Read(data));
  EXPECT_EQ(curve->GetNumberOfPieces(), 0);
  EXPECT_TRUE(std::isnan(curve->GetSize()));
  return curve->GetErrorMessage();
}

bool Contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}

/// A TOM carrying its derived curve.
vtkSmartPointer<vtkPolyData> AttachedTOM()
{
  auto tom = SphereTOM();
  vtkNew<vtkAccuracyCurveFieldData> curve;
  EXPECT_TRUE(curve->Attach(tom)) << curve->GetErrorMessage();
  return tom;
}

void SetArray(vtkPolyData* data, const char* name, int components, std::vector<double> values)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->SetNumberOfComponents(components);
  for (double v : values)
  {
    array->InsertNextValue(v);
  }
  data->GetFieldData()->AddArray(array);
}
}

TEST(vtkAccuracyCurveFieldData, TOMCurveFollowsTheErrorCurve)
{
  auto tom = SphereTOM();
  vtkNew<vtkTOMFieldData> reader;
  ASSERT_TRUE(reader->Read(tom));
  const auto& samples = reader->GetMesh().ErrorCurve.GetSamples();
  ASSERT_GE(samples.size(), 3u);
  const double size = tom->GetLength();

  vtkNew<vtkAccuracyCurveFieldData> curve;
  ASSERT_TRUE(curve->Derive(tom)) << curve->GetErrorMessage();
  EXPECT_EQ(curve->GetSize(), size);
  EXPECT_EQ(curve->GetMaximumAccuracy(), Inf); // the full mesh is exact
  // The coarsest mesh is the cheapest representation, reaching size / its error.
  EXPECT_EQ(curve->GetResources(0.0), samples.front().Triangles);
  EXPECT_DOUBLE_EQ(curve->GetCurve().GetMinimumAccuracy(), size / samples.front().Error);
  // Each sample: its triangles reach size / its error (the cheapest at that error).
  for (size_t i = 0; i + 1 < samples.size(); ++i)
  {
    if (i > 0 && samples[i].Error == samples[i - 1].Error)
    {
      continue;
    }
    const double accuracy = size / samples[i].Error;
    EXPECT_NEAR(curve->GetResources(accuracy), samples[i].Triangles, 1e-6) << "sample " << i;
    EXPECT_GE(curve->GetAccuracy(samples[i].Triangles), accuracy * (1.0 - 1e-12));
  }
  // Finer than the last positive error: only the full mesh.
  const double finest = size / samples[samples.size() - 2].Error;
  EXPECT_EQ(curve->GetResources(finest * 1.01), reader->GetNumberOfTriangles());
  EXPECT_EQ(curve->GetAccuracy(reader->GetNumberOfTriangles()), Inf);
  EXPECT_TRUE(curve->GetCurve().IsNear(
    vtkAccuracyCurveFieldData::FromErrorCurve(reader->GetMesh().ErrorCurve, size)));
}

TEST(vtkAccuracyCurveFieldData, MergeTreeCurveFromNodeErrors)
{
  // A merge tree whose nodes all have error 0 but one, w, with error 0.25: the
  // meshes with at most w vertices have error 0.25 (they lack w), the finer ones 0.
  auto tree = tt::BuildTree(tt::MakeSphere(6));
  vtkNew<vtkMergeTreeFieldData> reader;
  ASSERT_TRUE(reader->Read(tree)) << reader->GetErrorMessage();
  const auto& mesh = reader->GetMesh();
  const uint32_t n = mesh.GetNumberOfVertices();
  const uint32_t w = mesh.BaseVertexCount + (n - mesh.BaseVertexCount) / 2;
  ASSERT_LE(n - mesh.BaseVertexCount + 1, vtkAccuracyCurveFieldData::MergeTreeCurveSamples)
    << "every vertex count is a sample";
  auto* error = vtkFloatArray::SafeDownCast(
    tree->GetPointData()->GetArray(vtkMergeTreeFieldData::ErrorArrayName()));
  ASSERT_NE(error, nullptr);
  for (vtkIdType v = 0; v < error->GetNumberOfTuples(); ++v)
  {
    error->SetValue(v, v == static_cast<vtkIdType>(w) ? 0.25f : 0.f);
  }
  timecritical::TOMTraversal traversal(mesh);
  std::vector<uint32_t> scratch;
  const uint32_t coarsest = traversal.Extract(mesh.BaseVertexCount, scratch);
  const uint32_t withW = traversal.Extract(w + 1, scratch);

  vtkNew<vtkAccuracyCurveFieldData> curve;
  ASSERT_TRUE(curve->Derive(tree)) << curve->GetErrorMessage();
  const double size = tree->GetLength();
  const double a = size / 0.25;
  EXPECT_EQ(curve->GetResources(0.0), coarsest);
  EXPECT_EQ(curve->GetResources(a), coarsest);
  EXPECT_EQ(curve->GetResources(a * 1.001), withW); // the first mesh holding vertex w
  EXPECT_EQ(curve->GetResources(1e30), withW);
  EXPECT_EQ(curve->GetMaximumAccuracy(), Inf);

  // The merge tree's errors are preferred to the TOM's error curve: doubling
  // them halves every accuracy.
  auto doubled = tt::BuildTree(tt::MakeSphere(10));
  vtkNew<vtkAccuracyCurveFieldData> original;
  ASSERT_TRUE(original->Derive(doubled));
  error = vtkFloatArray::SafeDownCast(
    doubled->GetPointData()->GetArray(vtkMergeTreeFieldData::ErrorArrayName()));
  for (vtkIdType v = 0; v < error->GetNumberOfTuples(); ++v)
  {
    error->SetValue(v, 2.f * error->GetValue(v));
  }
  vtkNew<vtkAccuracyCurveFieldData> twice;
  ASSERT_TRUE(twice->Derive(doubled));
  EXPECT_TRUE(twice->GetCurve().IsNear(original->GetCurve().ScaleAccuracy(0.5)));
}

TEST(vtkAccuracyCurveFieldData, TravelsWithVtpFiles)
{
  auto tom = AttachedTOM();
  EXPECT_TRUE(vtkAccuracyCurveFieldData::HasAccuracyCurve(tom));
  vtkNew<vtkAccuracyCurveFieldData> before;
  ASSERT_TRUE(before->Read(tom)) << before->GetErrorMessage();
  EXPECT_EQ(before->GetMaximumAccuracy(), Inf);
  for (int ascii = 0; ascii < 2; ++ascii)
  {
    const std::string path = std::string(TIMECRITICAL_TEST_OUTPUT_DIR) + "/accuracy_curve_" +
      (ascii ? "ascii" : "binary") + ".vtp";
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetFileName(path.c_str());
    writer->SetInputData(tom);
    if (ascii)
    {
      writer->SetDataModeToAscii();
    }
    else
    {
      writer->SetDataModeToBinary();
    }
    ASSERT_EQ(writer->Write(), 1);
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    vtkNew<vtkAccuracyCurveFieldData> after;
    ASSERT_TRUE(after->Read(reader->GetOutput())) << after->GetErrorMessage();
    EXPECT_TRUE(after->GetCurve().IsNear(before->GetCurve(), 1e-6)) << path;
    EXPECT_EQ(after->GetMaximumAccuracy(), Inf) << path;
    EXPECT_NEAR(after->GetSize(), before->GetSize(), 1e-9) << path;
    // ReadOrDerive takes the stored curve.
    EXPECT_TRUE(after->ReadOrDerive(reader->GetOutput()));
  }
  // A stored curve wins over the derived one, whatever it says.
  auto custom = AttachedTOM();
  vtkAccuracyCurveFieldData::Write(AccuracyCurve::SinglePoint(7.0, 3.0), 2.0, custom);
  vtkNew<vtkAccuracyCurveFieldData> stored;
  ASSERT_TRUE(stored->ReadOrDerive(custom));
  EXPECT_EQ(stored->GetMaximumAccuracy(), 7.0);
  EXPECT_EQ(stored->GetSize(), 2.0);
  EXPECT_EQ(stored->GetResources(1.0), 3.0);
  // WriteTo copies the last curve.
  vtkNew<vtkPolyData> target;
  EXPECT_TRUE(stored->WriteTo(target));
  vtkNew<vtkAccuracyCurveFieldData> copied;
  ASSERT_TRUE(copied->Read(target));
  EXPECT_TRUE(copied->GetCurve().IsNear(stored->GetCurve()));
}

TEST(vtkAccuracyCurveFieldData, BadStoredCurves)
{
  EXPECT_TRUE(Contains(ReadError(nullptr), "missing"));
  EXPECT_TRUE(Contains(ReadError(tt::MakeSphere(6)), "missing"));
  const auto good = AttachedTOM();
  auto corrupt = [&good](const char* name, int components, std::vector<double> values) {
    auto copy = tt::Copy(good);
    SetArray(copy, name, components, std::move(values));
    return ReadError(copy);
  };
  const char* curve = vtkAccuracyCurveFieldData::CurveArrayName();
  const char* maximum = vtkAccuracyCurveFieldData::MaximumAccuracyArrayName();
  const char* size = vtkAccuracyCurveFieldData::SizeArrayName();
  EXPECT_TRUE(Contains(corrupt(curve, 2, { 1.0, 2.0 }), "(A, R, K) triples"));
  EXPECT_TRUE(Contains(corrupt(maximum, 1, {}), "one value"));
  EXPECT_TRUE(Contains(corrupt(maximum, 1, { 1.0, 2.0 }), "one value"));
  EXPECT_TRUE(Contains(corrupt(size, 1, { 0.0 }), "AccuracyCurveSize"));
  EXPECT_TRUE(Contains(corrupt(size, 1, { -1.0 }), "AccuracyCurveSize"));
  EXPECT_TRUE(Contains(corrupt(curve, 3, { 1.0, 0.0, -1.0 }), "slope"));
  EXPECT_TRUE(Contains(corrupt(curve, 3, { 2.0, 0.0, 1.0, 1.0, 0.0, 1.0 }), "not after"));
  EXPECT_TRUE(Contains(corrupt(curve, 3, { 1.0, 0.0, 10.0, 2.0, 0.0, 1.0 }), "decreases"));
  EXPECT_TRUE(Contains(corrupt(maximum, 1, { -2.0 }), "maximum accuracy"));
  auto text = tt::Copy(good);
  vtkNew<vtkStringArray> strings;
  strings->SetName(curve);
  text->GetFieldData()->AddArray(strings);
  EXPECT_TRUE(Contains(ReadError(text), "numeric"));
}

TEST(vtkAccuracyCurveFieldData, BadDerivations)
{
  vtkNew<vtkAccuracyCurveFieldData> curve;
  EXPECT_FALSE(curve->Derive(nullptr));
  EXPECT_FALSE(curve->Derive(tt::MakeSphere(6)));
  EXPECT_TRUE(Contains(curve->GetErrorMessage(), "not a multiresolution object"));
  EXPECT_FALSE(curve->Attach(tt::MakeSphere(6)));
  auto noErrorCurve = SphereTOM();
  noErrorCurve->GetFieldData()->RemoveArray(vtkTOMFieldData::ErrorCurveArrayName());
  EXPECT_FALSE(curve->Derive(noErrorCurve));
  EXPECT_TRUE(Contains(curve->GetErrorMessage(), "no error curve"));
  auto flat = SphereTOM();
  for (vtkIdType p = 0; p < flat->GetNumberOfPoints(); ++p)
  {
    flat->GetPoints()->SetPoint(p, 1.0, 2.0, 3.0);
  }
  flat->GetPoints()->Modified();
  EXPECT_FALSE(curve->Derive(flat));
  EXPECT_TRUE(Contains(curve->GetErrorMessage(), "no extent"));
  EXPECT_FALSE(curve->WriteTo(flat)); // nothing to write after a failure
  EXPECT_FALSE(vtkAccuracyCurveFieldData::HasAccuracyCurve(flat));
}

TEST(vtkAccuracyCurveFieldData, BadArgumentsGiveNaNAndAnError)
{
  auto tom = AttachedTOM();
  vtkNew<vtkAccuracyCurveFieldData> curve;
  ASSERT_TRUE(curve->Read(tom));
  tt::MessageLog log(curve);
  EXPECT_TRUE(std::isnan(curve->GetResources(std::nan(""))));
  EXPECT_TRUE(std::isnan(curve->GetAccuracy(-1.0)));
  EXPECT_EQ(log.Errors.size(), 2u);
  EXPECT_TRUE(log.ErrorContains("non-negative"));
  vtkNew<vtkAccuracyCurveFieldData> unread;
  EXPECT_TRUE(std::isnan(unread->GetResources(1.0)));
  EXPECT_EQ(unread->GetNumberOfPieces(), 0);
}
