// SPDX-License-Identifier: BSD-3-Clause
/*
 * PairContractionBenchmark: what pair contraction
 * (TOMBuildOptions::PairContractionDistance, vtkTOMBuilder's
 * PairContractionDistance) does on objects of many separate parts:
 *
 *  - "spheres": a 6 x 6 array of icospheres (radius 1, centres 2.5 apart);
 *  - "blobs": the iso-surface of a sum of 64 Gaussian blobs on a jittered
 *    4 x 4 x 4 lattice (vtkFlyingEdges3D of a sampled field), as separate
 *    closed blobs (a few may touch).
 *
 * For each object and each distance (0 = off, then fractions of the
 * bounding-box diagonal): the build time, the coarsest triangle count, the
 * parts joined, and the dense symmetric Hausdorff distance (SurfaceDistance.h,
 * as TOMBenchmark's quality section, over the diagonal) at 10%, 5% and 1% of
 * the triangles and at the coarsest level. Prints a table and writes JSON.
 *
 *   PairContractionBenchmark [--quick] [--json PATH]
 *
 * --quick: smaller objects (seconds), for the ctest smoke test, which also
 * checks that pairs lower the coarsest triangle count.
 */
#include "BenchmarkJson.h"
#include "MachineInfo.h"
#include "MeshConversion.h"
#include "MeshIO.h"
#include "SurfaceDistance.h"
#include "TOMBuilder.h"
#include "TOMTraversal.h"

#include <vtkFloatArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

namespace
{
using timecritical::TOMBuildOptions;
using timecritical::TOMBuildResult;
using timecritical::TOMTraversal;
using timecritical::testing::TriangleMesh;
namespace bm = timecritical::benchmark;

const double Resolutions[] = { 0.10, 0.05, 0.01 };

/// rows x cols icospheres of radius 1 in the z = 0 plane, centres `spacing` apart.
TriangleMesh MakeSphereArray(int rows, int cols, double spacing, size_t subdivisions)
{
  const TriangleMesh sphere = timecritical::testing::MakeSphere(subdivisions);
  TriangleMesh out;
  for (int i = 0; i < rows * cols; ++i)
  {
    const uint32_t offset = static_cast<uint32_t>(out.NumberOfPoints());
    for (size_t p = 0; p < sphere.NumberOfPoints(); ++p)
    {
      out.Points.insert(out.Points.end(), { sphere.Points[3 * p] + spacing * (i % cols),
                                            sphere.Points[3 * p + 1] + spacing * (i / cols),
                                            sphere.Points[3 * p + 2] });
    }
    for (uint32_t id : sphere.Triangles)
    {
      out.Triangles.push_back(id + offset);
    }
  }
  return out;
}

/// The iso-surface (0.5) of a sum of 64 Gaussians of radius 0.045 to 0.06 on
/// a 4^3 lattice jittered by a fixed LCG, sampled on an n^3 grid of the unit cube.
TriangleMesh MakeBlobs(int n)
{
  uint32_t state = 2024u;
  auto next = [&state]() {
    state = state * 1664525u + 1013904223u;
    return static_cast<double>(state >> 8) / double(1u << 24);
  };
  std::vector<double> blobs; // x, y, z, r per blob
  for (int b = 0; b < 64; ++b)
  {
    const int lattice[3] = { b % 4, (b / 4) % 4, b / 16 };
    for (int c : lattice)
    {
      blobs.push_back(0.125 + 0.25 * c + 0.06 * (next() - 0.5));
    }
    blobs.push_back(0.045 + 0.015 * next());
  }
  vtkNew<vtkImageData> image;
  image->SetDimensions(n, n, n);
  const double h = 1.0 / (n - 1);
  image->SetSpacing(h, h, h);
  vtkNew<vtkFloatArray> field;
  field->SetName("field");
  field->SetNumberOfTuples(vtkIdType(n) * n * n);
  for (vtkIdType index = 0; index < vtkIdType(n) * n * n; ++index)
  {
    const double p[3] = { h * double(index % n), h * double((index / n) % n),
      h * double(index / (vtkIdType(n) * n)) };
    double sum = 0.0;
    for (size_t b = 0; b < blobs.size(); b += 4)
    {
      const double dx = p[0] - blobs[b], dy = p[1] - blobs[b + 1], dz = p[2] - blobs[b + 2];
      sum += std::exp(-(dx * dx + dy * dy + dz * dz) / (blobs[b + 3] * blobs[b + 3]));
    }
    field->SetValue(index, static_cast<float>(sum));
  }
  image->GetPointData()->SetScalars(field);
  vtkNew<vtkFlyingEdges3D> contour;
  contour->SetInputData(image);
  contour->SetValue(0, 0.5);
  contour->ComputeNormalsOff();
  contour->ComputeGradientsOff();
  contour->ComputeScalarsOff();
  contour->Update();
  return bm::FromPolyData(contour->GetOutput());
}

double Diagonal(const TriangleMesh& mesh)
{
  double lo[3] = { 1e300, 1e300, 1e300 }, hi[3] = { -1e300, -1e300, -1e300 };
  for (size_t p = 0; p < mesh.NumberOfPoints(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      lo[c] = std::min(lo[c], mesh.Points[3 * p + c]);
      hi[c] = std::max(hi[c], mesh.Points[3 * p + c]);
    }
  }
  return std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
    (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

/// The original's side of the Hausdorff distance, made once per object.
struct Reference
{
  explicit Reference(const TriangleMesh& m)
    : Mesh(m)
    , Locator(m.Points.data(), m.Triangles.data(), m.NumberOfTriangles())
    , Samples(timecritical::SampleSurface(
        m.Points.data(), m.NumberOfPoints(), m.Triangles.data(), m.NumberOfTriangles(), 0.0, 2))
    , Spacing(0.5 * timecritical::MeanEdgeLength(m.Points.data(), m.Triangles.data(),
                      m.NumberOfTriangles()))
    , Diagonal(::Diagonal(m))
  {
  }
  const TriangleMesh& Mesh;
  timecritical::SurfaceLocator Locator;
  std::vector<double> Samples;
  double Spacing;
  double Diagonal;
};

/// The TOM with `n` active vertices, in input coordinates.
TriangleMesh Level(const Reference& ref, const TOMBuildResult& tom, uint32_t n)
{
  const TOMTraversal traversal(tom.Mesh);
  TriangleMesh mesh;
  mesh.Triangles.resize(3 * size_t(traversal.GetNumberOfTriangles()));
  const uint32_t count =
    traversal.Extract(n, mesh.Triangles.data(), traversal.GetNumberOfTriangles());
  mesh.Triangles.resize(3 * size_t(count));
  for (uint32_t v = 0; v < n; ++v)
  {
    const double* p = &ref.Mesh.Points[3 * size_t(tom.VertexOrder[v])];
    mesh.Points.insert(mesh.Points.end(), p, p + 3);
  }
  return timecritical::testing::RemoveUnusedPoints(mesh);
}

/// Dense symmetric Hausdorff distance between the original and `level`, over the diagonal.
double RelativeHausdorff(const Reference& ref, const TriangleMesh& level)
{
  const timecritical::SurfaceLocator locator(
    level.Points.data(), level.Triangles.data(), level.NumberOfTriangles());
  const std::vector<double> samples = timecritical::SampleSurface(level.Points.data(),
    level.NumberOfPoints(), level.Triangles.data(), level.NumberOfTriangles(), ref.Spacing, 1);
  const double there = timecritical::MaximumDistance(ref.Samples, locator);
  const double back = timecritical::MaximumDistance(samples, ref.Locator);
  return std::max(there, back) / ref.Diagonal;
}

struct Row
{
  double Distance = 0.0;
  double BuildSeconds = 0.0;
  size_t JoinedParts = 0;
  uint32_t CoarsestTriangles = 0;
  std::vector<uint32_t> Triangles; // at Resolutions, then the coarsest
  std::vector<double> Hausdorff;
};

Row Measure(const Reference& ref, double distance)
{
  TOMBuildOptions options;
  options.PairContractionDistance = distance;
  const auto start = std::chrono::steady_clock::now();
  const TOMBuildResult tom = timecritical::TOMBuilder(options).Build(ref.Mesh.Points.data(),
    ref.Mesh.NumberOfPoints(), ref.Mesh.Triangles.data(), ref.Mesh.NumberOfTriangles());
  Row row;
  row.Distance = distance;
  row.BuildSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  row.JoinedParts = tom.JoinedParts;
  row.CoarsestTriangles = tom.Mesh.BaseTriangleCount;
  const TOMTraversal traversal(tom.Mesh);
  std::vector<uint32_t> counts;
  for (double r : Resolutions)
  {
    counts.push_back(
      traversal.GetVertexCountForTriangles(traversal.GetTrianglesForResolution(r)));
  }
  counts.push_back(tom.Mesh.BaseVertexCount);
  for (uint32_t n : counts)
  {
    const TriangleMesh level = Level(ref, tom, n);
    row.Triangles.push_back(static_cast<uint32_t>(level.NumberOfTriangles()));
    row.Hausdorff.push_back(RelativeHausdorff(ref, level));
  }
  return row;
}

void PrintTable(const std::string& name, const TriangleMesh& mesh, const std::vector<Row>& rows)
{
  std::printf("\n%s: %zu triangles, %zu points\n", name.c_str(), mesh.NumberOfTriangles(),
    mesh.NumberOfPoints());
  std::printf("%9s %9s %7s %10s | %-20s %-20s %-20s %-20s\n", "distance", "build s", "joined",
    "coarsest", "10%: tri / H", "5%: tri / H", "1%: tri / H", "coarsest: tri / H");
  for (const Row& row : rows)
  {
    std::printf("%9.3f %9.3f %7zu %10u |", row.Distance, row.BuildSeconds, row.JoinedParts,
      row.CoarsestTriangles);
    for (size_t i = 0; i < row.Triangles.size(); ++i)
    {
      std::printf(" %7u / %-10.5f", row.Triangles[i], row.Hausdorff[i]);
    }
    std::printf("\n");
  }
}

bm::JsonValue ToJson(const std::string& name, const TriangleMesh& mesh, const std::vector<Row>& rows)
{
  bm::JsonValue object = bm::JsonValue::Object();
  object.Set("name", name);
  object.Set("triangles", mesh.NumberOfTriangles());
  object.Set("points", mesh.NumberOfPoints());
  bm::JsonValue list = bm::JsonValue::Array();
  for (const Row& row : rows)
  {
    bm::JsonValue r = bm::JsonValue::Object();
    r.Set("pair_contraction_distance", row.Distance);
    r.Set("build_seconds", row.BuildSeconds);
    r.Set("joined_parts", row.JoinedParts);
    r.Set("coarsest_triangles", row.CoarsestTriangles);
    bm::JsonValue levels = bm::JsonValue::Array();
    for (size_t i = 0; i < row.Triangles.size(); ++i)
    {
      bm::JsonValue level = bm::JsonValue::Object();
      level.Set("level", i < std::size(Resolutions) ? bm::JsonValue(Resolutions[i])
                                                    : bm::JsonValue("coarsest"));
      level.Set("triangles", row.Triangles[i]);
      level.Set("hausdorff_over_diagonal", row.Hausdorff[i]);
      levels.Push(level);
    }
    r.Set("levels", levels);
    list.Push(r);
  }
  object.Set("rows", list);
  return object;
}
}

int main(int argc, char* argv[])
{
  bool quick = false;
  std::string json;
  for (int i = 1; i < argc; ++i)
  {
    if (std::strcmp(argv[i], "--quick") == 0)
    {
      quick = true;
    }
    else if (std::strcmp(argv[i], "--json") == 0 && i + 1 < argc)
    {
      json = argv[++i];
    }
    else
    {
      std::fprintf(stderr, "usage: %s [--quick] [--json PATH]\n", argv[0]);
      return 2;
    }
  }
  try
  {
    const std::vector<std::pair<std::string, TriangleMesh>> objects = {
      { "spheres", MakeSphereArray(6, 6, 2.5, quick ? 2 : 3) },
      { "blobs", MakeBlobs(quick ? 64 : 128) },
    };
    const double distances[] = { 0.0, 0.05, 0.1, 0.2 };
    bm::JsonValue root = bm::JsonValue::Object();
    root.Set("benchmark", "PairContractionBenchmark");
    root.Set("quick", quick);
    root.Set("cpu", bm::CpuModel());
    root.Set("load_average", bm::LoadAverageText());
    root.Set("date", bm::UtcNow());
    bm::JsonValue list = bm::JsonValue::Array();
    bool fewer = true;
    for (const auto& object : objects)
    {
      const Reference ref(object.second);
      std::vector<Row> rows;
      for (double d : distances)
      {
        rows.push_back(Measure(ref, d));
      }
      PrintTable(object.first, object.second, rows);
      list.Push(ToJson(object.first, object.second, rows));
      // The point of pairs: a far lower coarsest level on many parts.
      fewer = fewer && rows.back().CoarsestTriangles * 4 < rows.front().CoarsestTriangles;
    }
    root.Set("objects", list);
    if (!json.empty())
    {
      std::ofstream out(json);
      root.Write(out);
      out << "\n";
      std::printf("\nJSON: %s\n", json.c_str());
    }
    if (!fewer)
    {
      std::fprintf(stderr, "pairs did not lower the coarsest triangle count 4 times\n");
      return 1;
    }
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "PairContractionBenchmark: %s\n", e.what());
    return 1;
  }
  return 0;
}
