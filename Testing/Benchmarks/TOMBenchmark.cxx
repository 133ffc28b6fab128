// SPDX-License-Identifier: BSD-3-Clause
/**
 * TOMBenchmark: figures of the Totally Ordered Mesh against its goals.
 *
 *  1. build speed of timecritical::TOMBuilder (full reduction) next to
 *     vtkQuadricDecimation and meshopt_simplify, both to 10% of the triangles;
 *  2. memory of a TOM against plain face-vertex form;
 *  3. traversal rate and extra vertices walked by TOMTraversal::Extract;
 *  4. quality: the dense symmetric Hausdorff distance (SurfaceDistance.h) of
 *     TOM resolutions at 50/25/10/5% of the triangles against the vertex-subset
 *     peers at the same triangle count (meshopt_simplify with options 0 and with
 *     meshopt_SimplifyLockBorder; OpenMesh's DecimaterT with ModQuadricT and
 *     ModNormalFlippingT at 90 and 60 degrees, and at 90 with ModAspectRatioT
 *     at 5) and vtkQuadricDecimation (new vertices: a reference, not a peer);
 *     per case TOM / best peer, their geometric mean and maximum, and the same
 *     ratio for the vertex-only distance;
 *  5. MergeTreeBuilder: build rate (whole and collapse part), levels, and the
 *     error of its TOM (levels of independent collapses) against the greedy
 *     TOM's at 50/25/10/5%, with the default level cost cap and, as a sweep of
 *     levels against error, other caps and none (the paper's maximal levels).
 *
 * Prints one table per section and writes everything to JSON. Missed goals
 * are reported, not failed: the exit status is nonzero only for errors
 * (unreadable input, exceptions, invalid results).
 *
 *   TOMBenchmark [--quick] [--quality-only] [--mesh NAME]... [--json FILE] [--data DIR]
 *                [--hausdorff-all]
 */
#include "BenchmarkArguments.h"
#include "BenchmarkJson.h"
#include "BenchmarkStatistics.h"
#include "BenchmarkTiming.h"
#include "LoopSubdivision.h"
#include "MachineInfo.h"
#include "MergeTreeAttributes.h"
#include "MergeTreeBuilder.h"
#include "MeshConversion.h"
#include "SurfaceDistance.h"
#include "TOMBuilder.h"
#include "TOMMesh.h"
#include "TOMTraversal.h"
#include "TOMValidator.h"
#include "MeshIO.h"

#include <meshoptimizer.h>

// OpenMesh's VectorT leaves its coordinates uninitialised by design, which
// GCC 12 reports (maybe-uninitialized) where OpenMesh's own property arrays
// grow, in code this file only instantiates.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModAspectRatioT.hh>
#include <OpenMesh/Tools/Decimater/ModNormalFlippingT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>
#pragma GCC diagnostic pop

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkFloatArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkIdTypeArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkQuadricDecimation.h>
#include <vtkSmartPointer.h>
#include <vtkVersion.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

namespace
{
using timecritical::TOMBuilder;
using timecritical::TOMBuildResult;
using timecritical::TOMMesh;
using timecritical::TOMTraversal;
using timecritical::testing::TriangleMesh;
using namespace timecritical::benchmark;

//------------------------------------------------------------------------------
// Settings

struct Settings
{
  bool Quick = false;
  std::string JsonPath = "tom-benchmark.json";
  std::string DataDirectory = TIMECRITICAL_SHARED_DATA_DIR;
  int BuildRuns = 3;               ///< median of this many runs per builder...
  double SlowRunSeconds = 10.0;    ///< ...or one run when the first takes longer
  double MinMeasureSeconds = 0.05; ///< per traversal measurement
  int TraversalMeasurements = 5;   ///< median of this many measurements
  /// Section 4 is skipped above this many triangles (igea after Loop subdivision):
  /// seven simplifiers at four resolutions and the dense sampling take minutes
  /// there. --hausdorff-all lifts the limit.
  size_t HausdorffMaxTriangles = 500000;
  /// Section 4 only (one untimed TOM build per mesh): for work on the quality.
  bool QualityOnly = false;
  /// Only the meshes of these names (all when empty).
  std::vector<std::string> MeshNames;
  /// The engine of the TOM builds (--engine greedy|passes).
  timecritical::TOMBuildEngine Engine = timecritical::TOMBuildEngine::Greedy;
  /// Only the build times of both engines and meshopt's 10% level (--build-only).
  bool BuildOnly = false;
};

/// The engine BuildTOM uses (set from Settings::Engine).
timecritical::TOMBuildEngine CurrentEngine = timecritical::TOMBuildEngine::Greedy;

const std::vector<double> TraversalResolutions = { 1.0, 0.5, 0.25, 0.1, 0.05 };
const std::vector<double> HausdorffResolutions = { 0.5, 0.25, 0.1, 0.05 };
/// Dense sampling: the simplified triangles get a sample grid of this fraction
/// of the original's mean edge length; the original its vertices, edge midpoints
/// and centroids.
constexpr double SampleSpacing = 0.5;
const std::vector<double> MergeTreeResolutions = { 0.5, 0.25, 0.1, 0.05 };
/// MergeTreeBuildOptions::LevelCostRatio of the sweep besides the default (0: no cap).
const std::vector<double> MergeTreeCostRatios = { 0.0, 1.5, 4.0 };
constexpr double ComparisonFraction = 0.1; ///< quadric and meshopt keep 10% of the triangles

//------------------------------------------------------------------------------
// Timing: every figure goes through SecondsOf().

/// Wall-clock seconds of each run and their median.
struct Timing
{
  std::vector<double> Runs;
  double Median = 0.0;
};

/// Runs `function` up to settings.BuildRuns times (once when the first run is slow).
template <class Function>
Timing TimeRuns(const Settings& settings, Function&& function)
{
  Timing timing;
  for (int run = 0; run < settings.BuildRuns; ++run)
  {
    timing.Runs.push_back(SecondsOf(function));
    if (timing.Runs.front() > settings.SlowRunSeconds)
    {
      break;
    }
  }
  timing.Median = Median(timing.Runs);
  return timing;
}

/**
 * Seconds per call of a fast `function`: the call is repeated enough times
 * that one measurement takes at least settings.MinMeasureSeconds (the
 * calibration doubles as warm-up), then the median of
 * settings.TraversalMeasurements measurements is returned.
 */
template <class Function>
double SecondsPerCall(const Settings& settings, Function&& function)
{
  uint64_t repeats = 1;
  const auto repeated = [&]() {
    for (uint64_t i = 0; i < repeats; ++i)
    {
      function();
    }
  };
  for (double elapsed = SecondsOf(repeated); elapsed < settings.MinMeasureSeconds;
       elapsed = SecondsOf(repeated))
  {
    const double scale = 1.25 * settings.MinMeasureSeconds / std::max(elapsed, 1e-7);
    repeats = static_cast<uint64_t>(
      std::ceil(static_cast<double>(repeats) * std::min(std::max(scale, 2.0), 100.0)));
  }
  std::vector<double> perCall;
  for (int i = 0; i < settings.TraversalMeasurements; ++i)
  {
    perCall.push_back(SecondsOf(repeated) / static_cast<double>(repeats));
  }
  return Median(perCall);
}

/// Million triangles per second.
double Mtris(double triangles, double seconds)
{
  return seconds > 0.0 ? triangles / seconds * 1e-6 : std::numeric_limits<double>::infinity();
}

//------------------------------------------------------------------------------
// Text formatting

__attribute__((format(printf, 1, 2))) std::string Format(const char* format, ...)
{
  char buffer[256];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buffer, sizeof(buffer), format, args);
  va_end(args);
  return buffer;
}

std::string Fixed(double value, int digits)
{
  return Format("%.*f", digits, value);
}

std::string Count(uint64_t value)
{
  return std::to_string(value);
}

/// A plain-text table: first column left aligned, the others right aligned.
class Table
{
public:
  explicit Table(std::vector<std::string> headers)
    : Rows{ std::move(headers) }
  {
  }

  void Add(std::vector<std::string> cells) { this->Rows.push_back(std::move(cells)); }

  void Print(std::ostream& os, const std::string& title) const
  {
    std::vector<size_t> widths;
    for (const auto& row : this->Rows)
    {
      widths.resize(std::max(widths.size(), row.size()), 0);
      for (size_t c = 0; c < row.size(); ++c)
      {
        widths[c] = std::max(widths[c], row[c].size());
      }
    }
    os << "\n== " << title << " ==\n";
    for (size_t r = 0; r < this->Rows.size(); ++r)
    {
      const auto& row = this->Rows[r];
      for (size_t c = 0; c < row.size(); ++c)
      {
        const std::string padding(widths[c] - row[c].size(), ' ');
        os << (c ? "  " : "") << (c ? padding + row[c] : row[c] + padding);
      }
      os << "\n";
      if (r == 0)
      {
        size_t total = 0;
        for (size_t w : widths)
        {
          total += w + 2;
        }
        os << std::string(total - 2, '-') << "\n";
      }
    }
  }

private:
  std::vector<std::vector<std::string>> Rows;
};

JsonValue ToJson(const Timing& timing)
{
  JsonValue runs = JsonValue::Array();
  for (double seconds : timing.Runs)
  {
    runs.Push(seconds);
  }
  return JsonValue::Object().Set("runs_s", std::move(runs)).Set("median_s", timing.Median);
}

//------------------------------------------------------------------------------
// Goals: each check is logged for the summary and the JSON.

struct Goal
{
  std::string Name;
  double Threshold;
  bool AtLeast; ///< met when value >= Threshold, otherwise when value <= Threshold
  std::string Unit;

  std::string Text() const
  {
    std::ostringstream os;
    os << (this->AtLeast ? ">= " : "<= ") << this->Threshold << this->Unit;
    return os.str();
  }
  bool IsMet(double value) const
  {
    return this->AtLeast ? value >= this->Threshold : value <= this->Threshold;
  }
};

const Goal BuildGoal{ "TOM build rate", 1.0, true, " Mtri/s" };
// The full order of the largest mesh faster than meshoptimizer's single level.
const Goal LargeBuildGoal{ "TOM build rate, igea-loop1", 2.0, true, " Mtri/s" };
const Goal MeshoptSpeedGoal{ "TOM full order speed / meshopt_simplify to 10%, igea-loop1", 1.0,
  true, "x" };
const Goal MemoryGoal{ "TOM memory overhead over face-vertex", 8.4, false, " %" };
const Goal TraversalGoal{ "traversal rate", 100.0, true, " Mtri/s" };
const Goal ChainGoal{ "extra vertices traversed", 75.0, false, " %" };
const Goal QualityMeanGoal{ "TOM / best vertex-subset peer, geometric mean", 1.0, false, "" };
const Goal QualityCaseGoal{ "TOM / best vertex-subset peer, per case", 1.5, false, "" };
const Goal MergeTreeBuildGoal{ "merge-tree build rate", 1.0, true, " Mtri/s" };
const Goal MergeTreeErrorGoal{ "merge-tree TOM error / greedy TOM's (worst of 50-5%)", 1.5,
  false, "" };
const std::vector<const Goal*> AllGoals = { &BuildGoal, &LargeBuildGoal, &MeshoptSpeedGoal,
  &MemoryGoal, &TraversalGoal, &ChainGoal,
  &QualityMeanGoal, &QualityCaseGoal, &MergeTreeBuildGoal, &MergeTreeErrorGoal };

class GoalLog
{
public:
  /// Records the check and returns the table cells: goal text and met/MISSED.
  std::vector<std::string> Check(const Goal& goal, double value, const std::string& where)
  {
    const bool met = goal.IsMet(value);
    this->Entries.push_back({ &goal, value, where, met });
    return { goal.Text(), met ? "met" : "MISSED" };
  }

  void PrintSummary(std::ostream& os) const
  {
    Table table({ "goal", "target", "met", "checks", "worst", "worst at", "status" });
    for (const Goal* goal : AllGoals)
    {
      size_t met = 0, checks = 0;
      const Entry* worst = nullptr;
      for (const Entry& entry : this->Entries)
      {
        if (entry.Which != goal)
        {
          continue;
        }
        ++checks;
        met += entry.Met;
        const bool worse = worst &&
          (goal->AtLeast ? entry.Value < worst->Value : entry.Value > worst->Value);
        worst = (!worst || worse) ? &entry : worst;
      }
      if (worst)
      {
        table.Add({ goal->Name, goal->Text(), Count(met), Count(checks), Fixed(worst->Value, 3),
          worst->Where, met == checks ? "met" : "MISSED" });
      }
    }
    table.Print(os, "Summary of goals");
  }

  JsonValue ToJson() const
  {
    JsonValue checks = JsonValue::Array();
    for (const Entry& entry : this->Entries)
    {
      checks.Push(JsonValue::Object()
                    .Set("goal", entry.Which->Name)
                    .Set("target", entry.Which->Text())
                    .Set("where", entry.Where)
                    .Set("value", entry.Value)
                    .Set("met", entry.Met));
    }
    return checks;
  }

  size_t Missed() const
  {
    return static_cast<size_t>(std::count_if(
      this->Entries.begin(), this->Entries.end(), [](const Entry& e) { return !e.Met; }));
  }

private:
  struct Entry
  {
    const Goal* Which;
    double Value;
    std::string Where;
    bool Met;
  };
  std::vector<Entry> Entries;
};

/// Throws std::runtime_error with `what` unless `condition` holds.
void Require(bool condition, const std::string& what)
{
  if (!condition)
  {
    throw std::runtime_error("invalid result: " + what);
  }
}

//------------------------------------------------------------------------------
// Meshes: TriangleMesh <-> vtkPolyData

double BoundingBoxDiagonal(const TriangleMesh& mesh)
{
  double lo[3], hi[3];
  std::fill(lo, lo + 3, std::numeric_limits<double>::infinity());
  std::fill(hi, hi + 3, -std::numeric_limits<double>::infinity());
  for (size_t i = 0; i < mesh.Points.size(); ++i)
  {
    lo[i % 3] = std::min(lo[i % 3], mesh.Points[i]);
    hi[i % 3] = std::max(hi[i % 3], mesh.Points[i]);
  }
  return std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
    (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

//------------------------------------------------------------------------------
// The meshes

/// A benchmark input: welded, without unused points.
struct InputMesh
{
  std::string Name;
  std::string Origin;
  TriangleMesh Mesh;
  vtkSmartPointer<vtkPolyData> Poly;
  double Diagonal = 0.0;
};

InputMesh MakeInput(std::string name, std::string origin, const TriangleMesh& raw)
{
  namespace tt = timecritical::testing;
  InputMesh input;
  input.Name = std::move(name);
  input.Origin = std::move(origin);
  input.Mesh = tt::RemoveUnusedPoints(tt::WeldPoints(raw));
  input.Poly = ToPolyData(input.Mesh);
  input.Diagonal = BoundingBoxDiagonal(input.Mesh);
  Require(input.Mesh.NumberOfTriangles() > 0, input.Name + " has no triangles");
  return input;
}

/**
 * A smooth organic surface with no scan behind it: the iso-surface of a sum
 * of 12 Gaussian blobs at pseudo-random places (a fixed 32-bit LCG, so the
 * same mesh everywhere), by vtkFlyingEdges3D on a 64^3 grid: about 40K
 * triangles, closed.
 */
TriangleMesh MakeBlobby()
{
  constexpr int n = 64;
  constexpr int blobs = 12;
  uint32_t state = 12345u;
  auto next = [&state]() {
    state = state * 1664525u + 1013904223u;
    return static_cast<double>(state >> 8) / double(1u << 24);
  };
  double centre[blobs][3], radius[blobs];
  for (int b = 0; b < blobs; ++b)
  {
    for (double& c : centre[b])
    {
      c = 0.3 + 0.4 * next();
    }
    radius[b] = 0.08 + 0.07 * next();
  }
  vtkNew<vtkImageData> image;
  image->SetDimensions(n, n, n);
  image->SetSpacing(1.0 / (n - 1), 1.0 / (n - 1), 1.0 / (n - 1));
  vtkNew<vtkFloatArray> field;
  field->SetName("field");
  field->SetNumberOfTuples(vtkIdType(n) * n * n);
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const double p[3] = { double(i) / (n - 1), double(j) / (n - 1), double(k) / (n - 1) };
        double sum = 0.0;
        for (int b = 0; b < blobs; ++b)
        {
          const double dx = p[0] - centre[b][0], dy = p[1] - centre[b][1],
                       dz = p[2] - centre[b][2];
          sum += std::exp(-(dx * dx + dy * dy + dz * dz) / (radius[b] * radius[b]));
        }
        field->SetValue((vtkIdType(k) * n + j) * n + i, static_cast<float>(sum));
      }
    }
  }
  image->GetPointData()->SetScalars(field);
  vtkNew<vtkFlyingEdges3D> contour;
  contour->SetInputData(image);
  contour->SetValue(0, 0.5);
  contour->ComputeNormalsOff();
  contour->ComputeGradientsOff();
  contour->ComputeScalarsOff();
  contour->Update();
  return FromPolyData(contour->GetOutput());
}

/// An input mesh to benchmark, read or made only when its turn comes.
struct MeshSource
{
  std::string Name;
  std::string Origin;
  std::function<TriangleMesh()> Read;
};

/// The shared meshes present in the data folder (the small ones only when quick),
/// and igea after one level of Loop subdivision (~1.07M triangles).
std::vector<MeshSource> SharedMeshes(const Settings& settings)
{
  namespace tt = timecritical::testing;
  std::vector<std::string> files = { "cow.obj", "spot.obj", "teapot.obj" };
  if (!settings.Quick)
  {
    files.insert(files.end(), { "homer.obj", "fandisk.obj", "stanford-bunny.obj", "igea.ply" });
  }
  std::vector<MeshSource> sources;
  for (const std::string& file : files)
  {
    const std::string path = settings.DataDirectory + "/" + file;
    if (!std::filesystem::is_regular_file(path))
    {
      std::cout << "note: " << path << " is missing, skipped\n";
      continue;
    }
    sources.push_back(
      { std::filesystem::path(file).stem().string(), path, [path] { return tt::LoadMesh(path); } });
    if (file == "igea.ply")
    {
      sources.push_back({ "igea-loop1", path + " + one level of vtkLoopSubdivisionFilter",
        [path] { return FromPolyData(LoopSubdivide(MakeInput("igea", path, tt::LoadMesh(path)).Poly, 1)); } });
    }
  }
  if (!settings.Quick && !sources.empty())
  {
    sources.push_back({ "blobby", "MakeBlobby(): iso-surface of 12 Gaussian blobs, 64^3 grid",
      [] { return MakeBlobby(); } });
  }
  return sources;
}

/// Noisy tori standing in for the shared meshes when they are absent.
std::vector<MeshSource> GeneratedMeshes(const Settings& settings)
{
  namespace tt = timecritical::testing;
  std::vector<MeshSource> sources = { { "torus-20k", "MakeTorus(160, 64, noise seed 7)",
    [] { return tt::MakeTorus(160, 64, 7); } } };
  if (!settings.Quick)
  {
    sources.push_back({ "torus-1M", "MakeTorus(1000, 540, noise seed 7)",
      [] { return tt::MakeTorus(1000, 540, 7); } });
  }
  return sources;
}

std::vector<MeshSource> ChooseMeshes(const Settings& settings)
{
  std::vector<MeshSource> sources;
  if (std::filesystem::is_directory(settings.DataDirectory))
  {
    sources = SharedMeshes(settings);
  }
  if (sources.empty())
  {
    std::cout << "note: no shared meshes in " << settings.DataDirectory
              << ": benchmarking generated meshes instead\n";
    sources = GeneratedMeshes(settings);
  }
  if (!settings.MeshNames.empty())
  {
    const std::vector<std::string>& names = settings.MeshNames;
    sources.erase(std::remove_if(sources.begin(), sources.end(),
                    [&names](const MeshSource& m) {
                      return std::find(names.begin(), names.end(), m.Name) == names.end();
                    }),
      sources.end());
    Require(!sources.empty(), "no mesh of the names given with --mesh");
  }
  return sources;
}

//------------------------------------------------------------------------------
// The simplifiers

TOMBuildResult BuildTOM(const TriangleMesh& mesh)
{
  timecritical::TOMBuildOptions options;
  options.Engine = CurrentEngine;
  return TOMBuilder(options).Build(mesh.Points.data(), mesh.NumberOfPoints(), mesh.Triangles.data(),
    mesh.NumberOfTriangles());
}

/// vtkQuadricDecimation with VTK's defaults, volume preservation off.
vtkSmartPointer<vtkPolyData> QuadricDecimate(vtkPolyData* input, double targetReduction)
{
  vtkNew<vtkQuadricDecimation> decimate;
  decimate->SetInputData(input);
  decimate->SetTargetReduction(targetReduction);
  decimate->VolumePreservationOff();
  decimate->Update();
  return decimate->GetOutput();
}

/// TargetReduction that stops vtkQuadricDecimation at `triangles` triangles (or one fewer).
double ReductionFor(size_t triangles, size_t inputTriangles)
{
  return static_cast<double>(inputTriangles - std::min(triangles, inputTriangles)) /
    static_cast<double>(inputTriangles);
}

/// Positions and indices in meshoptimizer's input form.
struct MeshoptInput
{
  std::vector<float> Positions;
  std::vector<unsigned int> Indices;
  std::vector<unsigned int> Destination;
};

MeshoptInput MakeMeshoptInput(const TriangleMesh& mesh)
{
  MeshoptInput input;
  input.Positions.assign(mesh.Points.begin(), mesh.Points.end());
  input.Indices.assign(mesh.Triangles.begin(), mesh.Triangles.end());
  input.Destination.resize(input.Indices.size());
  return input;
}

/// meshopt_simplify down to `targetTriangles`, count-bound (huge target error);
/// returns the number of triangles written to input.Destination.
size_t MeshoptSimplify(MeshoptInput& input, size_t targetTriangles, unsigned options = 0)
{
  const size_t indices = meshopt_simplify(input.Destination.data(), input.Indices.data(),
    input.Indices.size(), input.Positions.data(), input.Positions.size() / 3, 3 * sizeof(float),
    3 * targetTriangles, 1e9f, options, nullptr);
  return indices / 3;
}

/// meshopt_simplify's result as a mesh in input coordinates (unused vertices dropped).
TriangleMesh MeshoptMesh(const InputMesh& input, size_t targetTriangles, unsigned options)
{
  MeshoptInput meshopt = MakeMeshoptInput(input.Mesh);
  const size_t triangles = MeshoptSimplify(meshopt, targetTriangles, options);
  TriangleMesh mesh;
  mesh.Points = input.Mesh.Points;
  mesh.Triangles.assign(meshopt.Destination.begin(), meshopt.Destination.begin() + 3 * triangles);
  return timecritical::testing::RemoveUnusedPoints(mesh);
}

/// OpenMesh in double precision, so that its output keeps the input positions exactly.
struct OpenMeshTraits : public OpenMesh::DefaultTraits
{
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using OpenMeshMesh = OpenMesh::TriMesh_ArrayKernelT<OpenMeshTraits>;

/**
 * OpenMesh's DecimaterT down to `targetTriangles`: ModQuadricT as the
 * priority (no error bound), ModNormalFlippingT at `maximumNormalDeviation`
 * degrees, and ModAspectRatioT at `aspectRatio` unless 0. Half-edge
 * collapses, so a vertex subset like the TOM. Faces that OpenMesh's
 * half-edge structure cannot hold (those that would make a pinch vertex, as
 * on cow and teapot) are left out of its input and counted in `refused`.
 */
TriangleMesh OpenMeshDecimate(const TriangleMesh& input, size_t targetTriangles,
  double maximumNormalDeviation, float aspectRatio, size_t& refused)
{
  namespace dec = OpenMesh::Decimater;
  OpenMeshMesh mesh;
  std::vector<OpenMeshMesh::VertexHandle> handles(input.NumberOfPoints());
  for (size_t v = 0; v < handles.size(); ++v)
  {
    const double* p = &input.Points[3 * v];
    handles[v] = mesh.add_vertex(OpenMeshMesh::Point(p[0], p[1], p[2]));
  }
  for (size_t t = 0; t < input.NumberOfTriangles(); ++t)
  {
    const uint32_t* c = &input.Triangles[3 * t];
    refused += !mesh.add_face(handles[c[0]], handles[c[1]], handles[c[2]]).is_valid();
  }
  mesh.request_face_normals();
  mesh.update_face_normals();
  dec::DecimaterT<OpenMeshMesh> decimater(mesh);
  dec::ModQuadricT<OpenMeshMesh>::Handle quadric;
  dec::ModNormalFlippingT<OpenMeshMesh>::Handle flipping;
  dec::ModAspectRatioT<OpenMeshMesh>::Handle aspect;
  decimater.add(quadric);
  decimater.add(flipping);
  decimater.module(flipping).set_max_normal_deviation(maximumNormalDeviation);
  if (aspectRatio > 0.f)
  {
    decimater.add(aspect);
    decimater.module(aspect).set_aspect_ratio(aspectRatio);
  }
  Require(decimater.initialize(), "OpenMesh decimater did not initialize");
  decimater.decimate_to_faces(0, targetTriangles);
  mesh.garbage_collection();
  TriangleMesh output;
  for (const auto& v : mesh.vertices())
  {
    const OpenMeshMesh::Point& p = mesh.point(v);
    output.Points.insert(output.Points.end(), { p[0], p[1], p[2] });
  }
  for (const auto& f : mesh.faces())
  {
    for (const auto& v : mesh.fv_range(f))
    {
      output.Triangles.push_back(static_cast<uint32_t>(v.idx()));
    }
  }
  return timecritical::testing::RemoveUnusedPoints(output);
}

/// The TOM at `vertexCount` active vertices as a mesh in input coordinates
/// (unused vertices dropped).
TriangleMesh TOMAtVertexCount(
  const InputMesh& input, const TOMBuildResult& tom, const TOMTraversal& traversal, uint32_t n)
{
  TriangleMesh mesh;
  mesh.Triangles.resize(3 * static_cast<size_t>(traversal.GetNumberOfTriangles()));
  const uint32_t count = traversal.Extract(n, mesh.Triangles.data(),
    traversal.GetNumberOfTriangles());
  mesh.Triangles.resize(3 * static_cast<size_t>(count));
  mesh.Points.resize(3 * static_cast<size_t>(n));
  for (uint32_t v = 0; v < n; ++v)
  {
    const double* p = &input.Mesh.Points[3 * static_cast<size_t>(tom.VertexOrder[v])];
    std::copy(p, p + 3, &mesh.Points[3 * static_cast<size_t>(v)]);
  }
  Require(std::all_of(mesh.Triangles.begin(), mesh.Triangles.end(),
            [n](uint32_t id) { return id < n; }),
    "extracted triangle uses an inactive vertex");
  return timecritical::testing::RemoveUnusedPoints(mesh);
}

/// Symmetric Hausdorff distance (point to triangle, both directions) over the diagonal.
struct Hausdorff
{
  double OriginalToSimplified = 0.0;
  double SimplifiedToOriginal = 0.0;
  double Symmetric() const
  {
    return std::max(this->OriginalToSimplified, this->SimplifiedToOriginal);
  }
};

/// The original's side of the distances, made once per mesh.
struct QualityReference
{
  explicit QualityReference(const InputMesh& input)
    : Locator(input.Mesh.Points.data(), input.Mesh.Triangles.data(), input.Mesh.NumberOfTriangles())
  {
    const TriangleMesh& m = input.Mesh;
    // Vertices, edge midpoints and centroids of the original.
    this->Samples = timecritical::SampleSurface(
      m.Points.data(), m.NumberOfPoints(), m.Triangles.data(), m.NumberOfTriangles(), 0.0, 2);
    this->Spacing = SampleSpacing *
      timecritical::MeanEdgeLength(m.Points.data(), m.Triangles.data(), m.NumberOfTriangles());
  }
  timecritical::SurfaceLocator Locator;
  std::vector<double> Samples;
  double Spacing = 0.0;
};

/// MaximumDistance over all cores: the queries are independent and the
/// maximum does not depend on their order (a third of the quality section's
/// time on one core).
double ParallelMaximumDistance(const std::vector<double>& samples, const timecritical::SurfaceLocator& to)
{
  const size_t points = samples.size() / 3;
  const size_t threads =
    std::max<size_t>(1, std::min<size_t>(std::thread::hardware_concurrency(), points / 4096));
  std::vector<double> worst(threads, 0.0);
  std::vector<std::thread> workers;
  for (size_t k = 0; k < threads; ++k)
  {
    workers.emplace_back([&, k] {
      // Contiguous chunks keep neighbouring samples together (the hint).
      const auto first = samples.begin() + static_cast<std::ptrdiff_t>(3 * (points * k / threads));
      const auto last =
        samples.begin() + static_cast<std::ptrdiff_t>(3 * (points * (k + 1) / threads));
      worst[k] = timecritical::MaximumDistance(std::vector<double>(first, last), to);
    });
  }
  for (std::thread& worker : workers)
  {
    worker.join();
  }
  return *std::max_element(worst.begin(), worst.end());
}

/// Dense and vertex-only distances between the original and a simplification.
void RelativeHausdorff(const InputMesh& original, const QualityReference& reference,
  const TriangleMesh& simplified, Hausdorff& dense, Hausdorff& vertexOnly)
{
  namespace tc = timecritical;
  const tc::SurfaceLocator locator(
    simplified.Points.data(), simplified.Triangles.data(), simplified.NumberOfTriangles());
  const std::vector<double> samples = tc::SampleSurface(simplified.Points.data(),
    simplified.NumberOfPoints(), simplified.Triangles.data(), simplified.NumberOfTriangles(),
    reference.Spacing, 1);
  const double d = original.Diagonal;
  dense.OriginalToSimplified = ParallelMaximumDistance(reference.Samples, locator) / d;
  dense.SimplifiedToOriginal = ParallelMaximumDistance(samples, reference.Locator) / d;
  vertexOnly.OriginalToSimplified = ParallelMaximumDistance(original.Mesh.Points, locator) / d;
  vertexOnly.SimplifiedToOriginal = ParallelMaximumDistance(simplified.Points, reference.Locator) / d;
  Require(std::isfinite(dense.Symmetric()) && std::isfinite(vertexOnly.Symmetric()),
    original.Name + ": Hausdorff distance is not finite");
}

//------------------------------------------------------------------------------
// Section figures

/// 1. Build speed.
struct BuildFigures
{
  Timing Tom, Quadric, Meshopt;
  size_t QuadricTriangles = 0;
  size_t MeshoptTriangles = 0;
};

/// 2. Memory.
struct MemoryFigures
{
  uint64_t Vertices = 0, Triangles = 0, CurveSamples = 0;

  uint64_t FaceVertexBytes() const { return this->Vertices * (12 + 12) + this->Triangles * 12; }
  uint64_t TOMBytes() const
  {
    return this->FaceVertexBytes() + 4 * this->Vertices + 8 * this->CurveSamples;
  }
  double OverheadPercent() const
  {
    return 100.0 * static_cast<double>(this->TOMBytes() - this->FaceVertexBytes()) /
      static_cast<double>(this->FaceVertexBytes());
  }
};

/// 3. Traversal at one resolution.
struct TraversalFigures
{
  double Resolution = 0.0;
  uint32_t TargetTriangles = 0, VertexCount = 0, Triangles = 0;
  uint64_t ChainSteps = 0;
  double SecondsPerExtract = 0.0;

  double Mtris() const { return ::Mtris(this->Triangles, this->SecondsPerExtract); }
  /// Chain steps per triangle corner (the goal's definition).
  double ExtraVertexPercent() const
  {
    return this->Triangles ? 100.0 * static_cast<double>(this->ChainSteps) / (3.0 * this->Triangles)
                           : 0.0;
  }
  /// Chain steps among all vertices visited (corners + steps), for comparison; no goal.
  double ExtraOfVisitedPercent() const
  {
    const double visited = 3.0 * this->Triangles + static_cast<double>(this->ChainSteps);
    return visited > 0.0 ? 100.0 * static_cast<double>(this->ChainSteps) / visited : 0.0;
  }
};

/// 4. The simplifiers compared: the TOM first, then its vertex-subset peers,
/// then vtkQuadricDecimation (new vertex positions: a reference, not a peer).
struct Simplifier
{
  const char* Key;   ///< JSON key
  const char* Label; ///< table header
  bool Peer;         ///< a vertex-subset peer of the TOM
};
const std::vector<Simplifier> Simplifiers = { { "tom", "TOM", false },
  { "meshopt", "mo", true }, { "meshopt_lock_border", "mo-LB", true },
  { "openmesh_nf90", "OM90", true }, { "openmesh_nf60", "OM60", true },
  { "openmesh_nf90_ar5", "OM90AR5", true }, { "vtk_quadric", "vtkQD", false } };

/// a / b, 1 where both are 0.
double SafeRatio(double a, double b)
{
  if (b > 0.0)
  {
    return a / b;
  }
  return a > 0.0 ? std::numeric_limits<double>::infinity() : 1.0;
}

/// 4. Quality at one resolution, per simplifier (the order of Simplifiers).
struct QualityFigures
{
  double Resolution = 0.0;
  std::vector<size_t> Triangles;
  std::vector<Hausdorff> Dense, VertexOnly;

  /// The peer with the least error by `measure` (Dense or VertexOnly).
  size_t BestPeer(const std::vector<Hausdorff>& measure) const
  {
    size_t best = 0;
    for (size_t i = 0; i < Simplifiers.size(); ++i)
    {
      if (Simplifiers[i].Peer &&
        (best == 0 || measure[i].Symmetric() < measure[best].Symmetric()))
      {
        best = i;
      }
    }
    return best;
  }
  /// TOM / best peer, dense symmetric measure: the goal's figure.
  double Ratio() const
  {
    return SafeRatio(this->Dense[0].Symmetric(), this->Dense[this->BestPeer(this->Dense)].Symmetric());
  }
  /// The same with the vertex-only measure.
  double VertexOnlyRatio() const
  {
    return SafeRatio(this->VertexOnly[0].Symmetric(),
      this->VertexOnly[this->BestPeer(this->VertexOnly)].Symmetric());
  }
};

double GeometricMean(const std::vector<double>& values)
{
  double sum = 0.0;
  for (double v : values)
  {
    sum += std::log(v);
  }
  return values.empty() ? 0.0 : std::exp(sum / static_cast<double>(values.size()));
}

/// Error of the merge tree's TOM over the greedy TOM's (1 where both are 0).
double ErrorRatio(double mergeTree, double greedy)
{
  if (greedy > 0.0)
  {
    return mergeTree / greedy;
  }
  return mergeTree > 0.0 ? std::numeric_limits<double>::infinity() : 1.0;
}

/// 5. Merge tree: build time, levels, error (builder's estimate / diagonal) of both TOMs.
struct MergeTreeFigures
{
  /// One setting of the level cost cap: its levels and error per MergeTreeResolutions.
  struct Setting
  {
    double CostRatio = 0.0;
    unsigned Levels = 0;
    std::vector<double> Error;
  };

  Timing Build;                  ///< default options
  double AttributeSeconds = 0.0; ///< of which ComputeMergeTree (one run, timed apart)
  unsigned Levels = 0;
  double CostRatio = 0.0;                          ///< the default LevelCostRatio
  std::vector<double> MergeTreeError, GreedyError; // per MergeTreeResolutions
  std::vector<Setting> Sweep; // per MergeTreeCostRatios, one untimed build each

  /// The build without ComputeMergeTree: the collapses, levels and TOM.
  double CollapseSeconds() const
  {
    return std::max(this->Build.Median - this->AttributeSeconds, 1e-9);
  }
  double WorstRatio() const
  {
    double worst = 0.0;
    for (size_t i = 0; i < this->MergeTreeError.size(); ++i)
    {
      worst = std::max(worst, ErrorRatio(this->MergeTreeError[i], this->GreedyError[i]));
    }
    return worst;
  }
};

struct MeshReport
{
  std::string Name, Origin;
  size_t Points = 0, Triangles = 0;
  double Diagonal = 0.0, LoadSeconds = 0.0;
  BuildFigures Build;
  MemoryFigures Memory;
  std::vector<TraversalFigures> Traversal;
  std::vector<QualityFigures> Quality;
  std::string QualitySkipped; ///< why section 4 did not run, empty when it did
  MergeTreeFigures MergeTree;
  bool QualityOnly = false; ///< sections 1-3 and 5 not measured
};

//------------------------------------------------------------------------------
// Section measurements

BuildFigures MeasureBuild(const Settings& settings, const InputMesh& input, TOMBuildResult& tom)
{
  BuildFigures figures;
  figures.Tom = TimeRuns(settings, [&]() { tom = BuildTOM(input.Mesh); });

  vtkSmartPointer<vtkPolyData> decimated;
  figures.Quadric = TimeRuns(
    settings, [&]() { decimated = QuadricDecimate(input.Poly, 1.0 - ComparisonFraction); });
  figures.QuadricTriangles = static_cast<size_t>(decimated->GetNumberOfPolys());

  MeshoptInput meshopt = MakeMeshoptInput(input.Mesh);
  const auto target =
    static_cast<size_t>(ComparisonFraction * static_cast<double>(input.Mesh.NumberOfTriangles()));
  figures.Meshopt =
    TimeRuns(settings, [&]() { figures.MeshoptTriangles = MeshoptSimplify(meshopt, target); });

  Require(figures.QuadricTriangles > 0 && figures.MeshoptTriangles > 0,
    input.Name + ": a reference simplifier produced no triangles");
  return figures;
}

/// Checks the TOM itself: valid arrays, every input triangle kept.
void ValidateTOM(const InputMesh& input, const TOMBuildResult& tom)
{
  Require(!tom.Aborted, input.Name + ": build aborted");
  const std::string problem = timecritical::TOMValidator::Check(tom.Mesh);
  Require(problem.empty(), input.Name + ": " + problem);
  Require(tom.Mesh.GetNumberOfVertices() + tom.UnusedPoints == input.Mesh.NumberOfPoints(),
    input.Name + ": TOM vertex count differs from the input");
  Require(tom.Mesh.GetNumberOfTriangles() + tom.DroppedDegenerateTriangles ==
      input.Mesh.NumberOfTriangles(),
    input.Name + ": TOM triangle count differs from the input");
  Require(tom.VertexOrder.size() == tom.Mesh.GetNumberOfVertices(),
    input.Name + ": VertexOrder has the wrong size");
}

MergeTreeFigures MeasureMergeTree(
  const Settings& settings, const InputMesh& input, const TOMBuildResult& greedy)
{
  const TriangleMesh& mesh = input.Mesh;
  timecritical::MergeTreeBuildResult tree;
  MergeTreeFigures figures;
  figures.Build = TimeRuns(settings, [&]() {
    tree = timecritical::MergeTreeBuilder().Build(
      mesh.Points.data(), mesh.NumberOfPoints(), mesh.Triangles.data(), mesh.NumberOfTriangles());
  });
  ValidateTOM(input, tree.TOM);
  figures.Levels = tree.Tree.LevelCount;
  figures.CostRatio = timecritical::MergeTreeBuildOptions().LevelCostRatio;
  std::vector<double> positions;
  for (uint32_t id : tree.TOM.VertexOrder)
  {
    positions.insert(positions.end(), &mesh.Points[3 * size_t(id)], &mesh.Points[3 * size_t(id)] + 3);
  }
  figures.AttributeSeconds = SecondsOf([&]() {
    timecritical::ComputeMergeTree(tree.TOM.Mesh, positions.data(), tree.Tree.Level.data());
  });
  // The error each builder reports (quadric estimate, world units) at equal triangle counts.
  auto errorAt = [&input](const TOMBuildResult& tom, double r) {
    const TOMTraversal traversal(tom.Mesh);
    const uint32_t n =
      traversal.GetVertexCountForTriangles(traversal.GetTrianglesForResolution(r));
    return tom.VertexCountError[n] / input.Diagonal;
  };
  for (double r : MergeTreeResolutions)
  {
    figures.MergeTreeError.push_back(errorAt(tree.TOM, r));
    figures.GreedyError.push_back(errorAt(greedy, r));
  }
  for (double ratio : MergeTreeCostRatios)
  {
    timecritical::MergeTreeBuildOptions options;
    options.LevelCostRatio = ratio;
    tree = timecritical::MergeTreeBuilder(options).Build(
      mesh.Points.data(), mesh.NumberOfPoints(), mesh.Triangles.data(), mesh.NumberOfTriangles());
    ValidateTOM(input, tree.TOM);
    MergeTreeFigures::Setting setting;
    setting.CostRatio = ratio;
    setting.Levels = tree.Tree.LevelCount;
    for (double r : MergeTreeResolutions)
    {
      setting.Error.push_back(errorAt(tree.TOM, r));
    }
    figures.Sweep.push_back(std::move(setting));
  }
  return figures;
}

MemoryFigures MeasureMemory(const TOMMesh& tom)
{
  MemoryFigures figures;
  figures.Vertices = tom.GetNumberOfVertices();
  figures.Triangles = tom.GetNumberOfTriangles();
  figures.CurveSamples = tom.ErrorCurve.GetSamples().size();
  return figures;
}

std::vector<TraversalFigures> MeasureTraversal(
  const Settings& settings, const std::string& name, const TOMMesh& tom)
{
  const TOMTraversal traversal(tom);
  const uint32_t capacity = traversal.GetNumberOfTriangles();
  std::vector<uint32_t> buffer(3 * static_cast<size_t>(capacity));
  std::vector<TraversalFigures> all;
  for (double r : TraversalResolutions)
  {
    TraversalFigures figures;
    figures.Resolution = r;
    figures.TargetTriangles = traversal.GetTrianglesForResolution(r);
    figures.VertexCount = traversal.GetVertexCountForTriangles(figures.TargetTriangles);
    figures.Triangles =
      traversal.Extract(figures.VertexCount, buffer.data(), capacity, &figures.ChainSteps);
    Require(figures.Triangles <= figures.TargetTriangles ||
        figures.VertexCount == tom.BaseVertexCount,
      name + ": extraction gave more triangles than asked for");
    Require(r < 1.0 || (figures.Triangles == capacity && figures.ChainSteps == 0),
      name + ": full resolution is not the input mesh");
    uint64_t sink = 0;
    figures.SecondsPerExtract = SecondsPerCall(
      settings, [&]() { sink += traversal.Extract(figures.VertexCount, buffer.data(), capacity); });
    Require(sink > 0 || figures.Triangles == 0, name + ": extraction produced nothing");
    all.push_back(figures);
  }
  return all;
}

std::vector<QualityFigures> MeasureQuality(const InputMesh& input, const TOMBuildResult& tom)
{
  const TOMTraversal traversal(tom.Mesh);
  const QualityReference reference(input);
  std::vector<QualityFigures> all;
  size_t refused = 0;
  for (double r : HausdorffResolutions)
  {
    QualityFigures figures;
    figures.Resolution = r;
    const uint32_t n =
      traversal.GetVertexCountForTriangles(traversal.GetTrianglesForResolution(r));
    const TriangleMesh tomMesh = TOMAtVertexCount(input, tom, traversal, n);
    // The peers get the TOM's triangle count.
    const size_t target = tomMesh.NumberOfTriangles();
    const TriangleMesh& m = input.Mesh;
    for (const Simplifier& simplifier : Simplifiers)
    {
      const std::string key = simplifier.Key;
      TriangleMesh simplified;
      if (key == "tom")
      {
        simplified = tomMesh;
      }
      else if (key == "meshopt")
      {
        simplified = MeshoptMesh(input, target, 0);
      }
      else if (key == "meshopt_lock_border")
      {
        simplified = MeshoptMesh(input, target, meshopt_SimplifyLockBorder);
      }
      else if (key == "openmesh_nf90")
      {
        simplified = OpenMeshDecimate(m, target, 90.0, 0.f, refused);
      }
      else if (key == "openmesh_nf60")
      {
        simplified = OpenMeshDecimate(m, target, 60.0, 0.f, refused);
      }
      else if (key == "openmesh_nf90_ar5")
      {
        simplified = OpenMeshDecimate(m, target, 90.0, 5.f, refused);
      }
      else
      {
        simplified = timecritical::testing::RemoveUnusedPoints(FromPolyData(
          QuadricDecimate(input.Poly, ReductionFor(target, m.NumberOfTriangles()))));
      }
      Require(simplified.NumberOfTriangles() > 0, input.Name + ": " + key + " gave no triangles");
      figures.Triangles.push_back(simplified.NumberOfTriangles());
      figures.Dense.emplace_back();
      figures.VertexOnly.emplace_back();
      RelativeHausdorff(input, reference, simplified, figures.Dense.back(), figures.VertexOnly.back());
    }
    all.push_back(figures);
  }
  if (refused > 0)
  {
    std::cout << "[" << input.Name << "] OpenMesh refused " << refused / (3 * all.size())
              << " input triangle(s) (pinch vertices), left out of its input" << std::endl;
  }
  return all;
}

/**
 * --build-only: both engines and meshopt's 10% level, interleaved run by run
 * (so that a change of load hits all three alike), medians printed.
 */
void CompareEngines(const Settings& settings, const InputMesh& input)
{
  using timecritical::TOMBuildEngine;
  MeshoptInput meshopt = MakeMeshoptInput(input.Mesh);
  const auto target =
    static_cast<size_t>(ComparisonFraction * static_cast<double>(input.Mesh.NumberOfTriangles()));
  std::vector<double> greedy, passes, reference;
  TOMBuildResult tom;
  const int runs = std::max(settings.BuildRuns, 5);
  for (int run = 0; run < runs; ++run)
  {
    CurrentEngine = TOMBuildEngine::Greedy;
    greedy.push_back(SecondsOf([&]() { tom = BuildTOM(input.Mesh); }));
    ValidateTOM(input, tom);
    CurrentEngine = TOMBuildEngine::Passes;
    passes.push_back(SecondsOf([&]() { tom = BuildTOM(input.Mesh); }));
    ValidateTOM(input, tom);
    reference.push_back(SecondsOf([&]() { MeshoptSimplify(meshopt, target); }));
  }
  CurrentEngine = settings.Engine;
  const double tris = static_cast<double>(input.Mesh.NumberOfTriangles()) * 1e-6;
  const double g = Median(greedy), p = Median(passes), m = Median(reference);
  std::cout << "[" << input.Name << "] medians of " << runs << " (load " << LoadAverageText()
            << "): greedy " << Fixed(g, 3) << " s (" << Fixed(tris / g, 2) << " Mtri/s, "
            << Fixed(m / g, 2) << "x meshopt), passes " << Fixed(p, 3) << " s ("
            << Fixed(tris / p, 2) << " Mtri/s, " << Fixed(m / p, 2) << "x meshopt), meshopt 10% "
            << Fixed(m, 3) << " s; passes/greedy speed " << Fixed(g / p, 2) << std::endl;
}

MeshReport MeasureMesh(const Settings& settings, const MeshSource& source)
{
  MeshReport report;
  InputMesh input;
  report.LoadSeconds =
    SecondsOf([&]() { input = MakeInput(source.Name, source.Origin, source.Read()); });
  report.Name = input.Name;
  report.Origin = input.Origin;
  report.Points = input.Mesh.NumberOfPoints();
  report.Triangles = input.Mesh.NumberOfTriangles();
  report.Diagonal = input.Diagonal;
  report.QualityOnly = settings.QualityOnly;
  std::cout << "[" << report.Name << "] " << report.Points << " points, " << report.Triangles
            << " triangles (loaded in " << Fixed(report.LoadSeconds, 2) << " s)" << std::endl;

  TOMBuildResult tom;
  if (settings.BuildOnly)
  {
    CompareEngines(settings, input);
    report.QualityOnly = true;
    report.QualitySkipped = "--build-only";
    return report;
  }
  if (settings.QualityOnly && report.Triangles > settings.HausdorffMaxTriangles)
  {
    report.QualitySkipped = "more than " + Count(settings.HausdorffMaxTriangles) + " triangles";
    return report;
  }
  if (settings.QualityOnly)
  {
    tom = BuildTOM(input.Mesh);
    ValidateTOM(input, tom);
  }
  else
  {
    report.Build = MeasureBuild(settings, input, tom);
    ValidateTOM(input, tom);
    report.Memory = MeasureMemory(tom.Mesh);
    report.MergeTree = MeasureMergeTree(settings, input, tom);
    report.Traversal = MeasureTraversal(settings, report.Name, tom.Mesh);
  }

  if (report.Triangles <= settings.HausdorffMaxTriangles)
  {
    const double seconds =
      SecondsOf([&]() { report.Quality = MeasureQuality(input, tom); });
    std::cout << "[" << report.Name << "] simplifiers and Hausdorff distances in "
              << Fixed(seconds, 1) << " s" << std::endl;
  }
  else
  {
    report.QualitySkipped = "more than " + Count(settings.HausdorffMaxTriangles) +
      " triangles: seven simplifiers at four resolutions take minutes here "
      "(run with --hausdorff-all to include it)";
  }
  return report;
}

//------------------------------------------------------------------------------
// Section tables and JSON

void PrintBuild(const std::vector<MeshReport>& reports, GoalLog& goals)
{
  Table table({ "mesh", "tris", "TOM s", "TOM Mtri/s", "quadric s", "quadric Mtri/s",
    "TOM speedup", "meshopt s", "meshopt Mtri/s", "TOM speedup", "runs", "goal", "status" });
  for (const MeshReport& m : reports)
  {
    const BuildFigures& b = m.Build;
    const double t = static_cast<double>(m.Triangles);
    std::vector<std::string> row = { m.Name, Count(m.Triangles), Fixed(b.Tom.Median, 4),
      Fixed(Mtris(t, b.Tom.Median), 3), Fixed(b.Quadric.Median, 4),
      Fixed(Mtris(t, b.Quadric.Median), 3), Fixed(b.Quadric.Median / b.Tom.Median, 2) + "x",
      Fixed(b.Meshopt.Median, 4), Fixed(Mtris(t, b.Meshopt.Median), 3),
      Fixed(b.Meshopt.Median / b.Tom.Median, 2) + "x",
      Count(b.Tom.Runs.size()) + "/" + Count(b.Quadric.Runs.size()) + "/" +
        Count(b.Meshopt.Runs.size()) };
    for (auto& cell : goals.Check(BuildGoal, Mtris(t, b.Tom.Median), m.Name))
    {
      row.push_back(std::move(cell));
    }
    table.Add(std::move(row));
  }
  table.Print(std::cout,
    "1. Build: TOM (full reduction) vs vtkQuadricDecimation and meshopt_simplify to 10% "
    "(median wall-clock s; speedup = their time / ours)");

  // The goals on the largest mesh (absent without the shared data).
  Table large({ "mesh", "measure", "value", "goal", "status" });
  bool found = false;
  for (const MeshReport& m : reports)
  {
    if (m.Name != "igea-loop1")
    {
      continue;
    }
    const BuildFigures& b = m.Build;
    const double rate = Mtris(static_cast<double>(m.Triangles), b.Tom.Median);
    const double speed = b.Meshopt.Median / b.Tom.Median;
    std::vector<std::string> rateRow = { m.Name, "TOM Mtri/s", Fixed(rate, 3) };
    for (auto& cell : goals.Check(LargeBuildGoal, rate, m.Name))
    {
      rateRow.push_back(std::move(cell));
    }
    large.Add(std::move(rateRow));
    std::vector<std::string> speedRow = { m.Name, "meshopt s / TOM s", Fixed(speed, 2) };
    for (auto& cell : goals.Check(MeshoptSpeedGoal, speed, m.Name))
    {
      speedRow.push_back(std::move(cell));
    }
    large.Add(std::move(speedRow));
    found = true;
  }
  if (found)
  {
    large.Print(std::cout,
      "1b. Build speed on the largest mesh (issue 10): the full TOM order against "
      "meshopt_simplify's single 10% level, same run");
  }
}

void PrintMergeTree(const std::vector<MeshReport>& reports, GoalLog& goals)
{
  std::vector<std::string> header = { "mesh", "tris", "MT s", "attributes s", "MT Mtri/s",
    "collapse Mtri/s", "TOM Mtri/s", "levels", "goal", "status" };
  for (double r : MergeTreeResolutions)
  {
    header.push_back("err/diag MT:TOM r=" + Fixed(r, 2));
  }
  header.insert(header.end(), { "worst MT/TOM", "goal", "status" });
  Table table(header);
  for (const MeshReport& m : reports)
  {
    const MergeTreeFigures& f = m.MergeTree;
    const double t = static_cast<double>(m.Triangles);
    std::vector<std::string> row = { m.Name, Count(m.Triangles), Fixed(f.Build.Median, 4),
      Fixed(f.AttributeSeconds, 4), Fixed(Mtris(t, f.Build.Median), 3),
      Fixed(Mtris(t, f.CollapseSeconds()), 3), Fixed(Mtris(t, m.Build.Tom.Median), 3),
      Count(f.Levels) };
    for (auto& cell : goals.Check(MergeTreeBuildGoal, Mtris(t, f.Build.Median), m.Name))
    {
      row.push_back(std::move(cell));
    }
    for (size_t i = 0; i < MergeTreeResolutions.size(); ++i)
    {
      row.push_back(Format("%.2e:%.2e", f.MergeTreeError[i], f.GreedyError[i]));
    }
    row.push_back(Fixed(f.WorstRatio(), 2) + "x");
    for (auto& cell : goals.Check(MergeTreeErrorGoal, f.WorstRatio(), m.Name))
    {
      row.push_back(std::move(cell));
    }
    table.Add(std::move(row));
  }
  table.Print(std::cout,
    "5. Merge tree (levels of independent collapses, default cost cap) vs greedy TOM: build "
    "(attributes = ComputeMergeTree, included; collapse = the rest), levels, error each reports "
    "(quadric estimate / diagonal) at r = fraction of triangles");

  // Levels against error: the cap trades depth for accuracy.
  std::vector<std::string> sweepHeader = { "mesh", "LevelCostRatio", "levels" };
  for (double r : MergeTreeResolutions)
  {
    sweepHeader.push_back("MT/TOM r=" + Fixed(r, 2));
  }
  Table sweep(sweepHeader);
  for (const MeshReport& m : reports)
  {
    const MergeTreeFigures& f = m.MergeTree;
    auto addRow = [&](const std::string& label, unsigned levels, const std::vector<double>& error) {
      std::vector<std::string> row = { m.Name, label, Count(levels) };
      for (size_t i = 0; i < MergeTreeResolutions.size(); ++i)
      {
        row.push_back(Fixed(ErrorRatio(error[i], f.GreedyError[i]), 2) + "x");
      }
      sweep.Add(std::move(row));
    };
    addRow(Fixed(f.CostRatio, 1) + " (default)", f.Levels, f.MergeTreeError);
    for (const MergeTreeFigures::Setting& setting : f.Sweep)
    {
      addRow(setting.CostRatio > 0.0 ? Fixed(setting.CostRatio, 1) : "0 (maximal levels)",
        setting.Levels, setting.Error);
    }
  }
  sweep.Print(std::cout,
    "5b. Merge tree: levels against error (merge-tree TOM's / greedy TOM's) per level cost cap "
    "(MergeTreeBuildOptions::LevelCostRatio; one build each)");
}

void PrintMemory(const std::vector<MeshReport>& reports, GoalLog& goals)
{
  Table table({ "mesh", "vertices", "triangles", "curve samples", "face-vertex B", "TOM B",
    "overhead %", "of which subst. %", "goal", "status" });
  for (const MeshReport& m : reports)
  {
    const MemoryFigures& f = m.Memory;
    const double substitution =
      100.0 * 4.0 * static_cast<double>(f.Vertices) / static_cast<double>(f.FaceVertexBytes());
    std::vector<std::string> row = { m.Name, Count(f.Vertices), Count(f.Triangles),
      Count(f.CurveSamples), Count(f.FaceVertexBytes()), Count(f.TOMBytes()),
      Fixed(f.OverheadPercent(), 3), Fixed(substitution, 3) };
    for (auto& cell : goals.Check(MemoryGoal, f.OverheadPercent(), m.Name))
    {
      row.push_back(std::move(cell));
    }
    table.Add(std::move(row));
  }
  table.Print(std::cout,
    "2. Memory: face-vertex = V*(12+12) + T*12; TOM = that + 4*V + 8 per error-curve sample");
}

void PrintTraversal(const std::vector<MeshReport>& reports, GoalLog& goals)
{
  Table table({ "mesh", "r", "target tris", "vertices", "tris", "us/extract", "Mtri/s", "goal",
    "status", "extra vertices %", "goal", "status", "extra/visited %" });
  for (const MeshReport& m : reports)
  {
    for (const TraversalFigures& f : m.Traversal)
    {
      const std::string where = m.Name + " r=" + Fixed(f.Resolution, 2);
      std::vector<std::string> row = { m.Name, Fixed(f.Resolution, 2), Count(f.TargetTriangles),
        Count(f.VertexCount), Count(f.Triangles), Fixed(f.SecondsPerExtract * 1e6, 2),
        Fixed(f.Mtris(), 1) };
      for (auto& cell : goals.Check(TraversalGoal, f.Mtris(), where))
      {
        row.push_back(std::move(cell));
      }
      row.push_back(Fixed(f.ExtraVertexPercent(), 2));
      for (auto& cell : goals.Check(ChainGoal, f.ExtraVertexPercent(), where))
      {
        row.push_back(std::move(cell));
      }
      row.push_back(Fixed(f.ExtraOfVisitedPercent(), 2));
      table.Add(std::move(row));
    }
  }
  table.Print(std::cout,
    "3. Traversal: TOMTraversal::Extract, one core, median per call; extra vertices = chain "
    "steps / (3 * triangles); extra/visited = chain steps / (3 * triangles + chain steps)");
}

void PrintQuality(const std::vector<MeshReport>& reports, GoalLog& goals)
{
  std::vector<std::string> headers = { "mesh", "r", "TOM tris" };
  for (const Simplifier& simplifier : Simplifiers)
  {
    headers.push_back(simplifier.Label);
  }
  headers.insert(headers.end(), { "best peer", "TOM/best", "vertex-only", "goal", "status" });
  Table table(headers);
  std::vector<std::string> notes;
  std::vector<double> ratios, vertexRatios;
  for (const MeshReport& m : reports)
  {
    if (!m.QualitySkipped.empty())
    {
      notes.push_back(m.Name + ": skipped, " + m.QualitySkipped);
    }
    for (const QualityFigures& f : m.Quality)
    {
      std::vector<std::string> row = { m.Name, Fixed(f.Resolution, 2), Count(f.Triangles[0]) };
      for (const Hausdorff& h : f.Dense)
      {
        row.push_back(Format("%.2e", h.Symmetric()));
      }
      row.push_back(Simplifiers[f.BestPeer(f.Dense)].Label);
      row.push_back(Fixed(f.Ratio(), 2));
      row.push_back(Fixed(f.VertexOnlyRatio(), 2));
      for (auto& cell :
        goals.Check(QualityCaseGoal, f.Ratio(), m.Name + " r=" + Fixed(f.Resolution, 2)))
      {
        row.push_back(std::move(cell));
      }
      table.Add(std::move(row));
      ratios.push_back(f.Ratio());
      vertexRatios.push_back(f.VertexOnlyRatio());
      const auto peerTriangles = f.Triangles[f.BestPeer(f.Dense)];
      if (peerTriangles > f.Triangles[0])
      {
        notes.push_back(m.Name + " r=" + Fixed(f.Resolution, 2) + ": the best peer stopped at " +
          Count(peerTriangles) + " triangles, above the TOM's " + Count(f.Triangles[0]));
      }
    }
  }
  table.Print(std::cout,
    "4. Quality: dense symmetric Hausdorff distance / bounding-box diagonal at the TOM's "
    "triangle count; TOM/best = TOM over the best vertex-subset peer (mo, mo-LB, OM*); "
    "vertex-only: the same ratio measured from the vertices only; vtkQD: reference");
  if (!ratios.empty())
  {
    const double mean = GeometricMean(ratios);
    const double worst = *std::max_element(ratios.begin(), ratios.end());
    Table summary({ "measure", "cases", "geometric mean", "max", "cases > 1.5", "goal", "status" });
    std::vector<std::string> row = { "dense", Count(ratios.size()), Fixed(mean, 3),
      Fixed(worst, 2),
      Count(std::count_if(ratios.begin(), ratios.end(), [](double r) { return r > 1.5; })) };
    for (auto& cell : goals.Check(QualityMeanGoal, mean, "all cases"))
    {
      row.push_back(std::move(cell));
    }
    summary.Add(std::move(row));
    summary.Add({ "vertex-only", Count(vertexRatios.size()), Fixed(GeometricMean(vertexRatios), 3),
      Fixed(*std::max_element(vertexRatios.begin(), vertexRatios.end()), 2),
      Count(std::count_if(
        vertexRatios.begin(), vertexRatios.end(), [](double r) { return r > 1.5; })),
      "", "" });
    summary.Print(std::cout, "4. Quality summary: TOM / best vertex-subset peer");
  }
  for (const std::string& note : notes)
  {
    std::cout << "note: " << note << "\n";
  }
}

JsonValue ToJson(const Hausdorff& h)
{
  return JsonValue::Object()
    .Set("original_to_simplified", h.OriginalToSimplified)
    .Set("simplified_to_original", h.SimplifiedToOriginal)
    .Set("symmetric", h.Symmetric());
}

JsonValue MergeTreeJson(const MeshReport& m)
{
  const MergeTreeFigures& f = m.MergeTree;
  JsonValue errors = JsonValue::Array();
  for (size_t i = 0; i < MergeTreeResolutions.size(); ++i)
  {
    errors.Push(JsonValue::Object()
                  .Set("resolution", MergeTreeResolutions[i])
                  .Set("merge_tree_error_over_diagonal", f.MergeTreeError[i])
                  .Set("greedy_error_over_diagonal", f.GreedyError[i])
                  .Set("ratio_to_greedy", ErrorRatio(f.MergeTreeError[i], f.GreedyError[i])));
  }
  JsonValue sweep = JsonValue::Array();
  for (const MergeTreeFigures::Setting& setting : f.Sweep)
  {
    JsonValue settingErrors = JsonValue::Array();
    for (size_t i = 0; i < MergeTreeResolutions.size(); ++i)
    {
      settingErrors.Push(JsonValue::Object()
                           .Set("resolution", MergeTreeResolutions[i])
                           .Set("merge_tree_error_over_diagonal", setting.Error[i])
                           .Set("ratio_to_greedy", ErrorRatio(setting.Error[i], f.GreedyError[i])));
    }
    sweep.Push(JsonValue::Object()
                 .Set("level_cost_ratio", setting.CostRatio)
                 .Set("levels", setting.Levels)
                 .Set("errors", std::move(settingErrors)));
  }
  const double t = static_cast<double>(m.Triangles);
  return ToJson(f.Build)
    .Set("mtris_per_s", Mtris(t, f.Build.Median))
    .Set("attributes_s", f.AttributeSeconds)
    .Set("collapse_mtris_per_s", Mtris(t, f.CollapseSeconds()))
    .Set("level_cost_ratio", f.CostRatio)
    .Set("levels", f.Levels)
    .Set("worst_ratio_to_greedy", f.WorstRatio())
    .Set("errors", std::move(errors))
    .Set("sweep", std::move(sweep));
}

JsonValue ToJson(const MeshReport& m)
{
  const double t = static_cast<double>(m.Triangles);
  const BuildFigures& b = m.Build;
  JsonValue build = JsonValue::Object()
                 .Set("tom", ToJson(b.Tom).Set("mtris_per_s", Mtris(t, b.Tom.Median)))
                 .Set("quadric_10pct", ToJson(b.Quadric)
                                         .Set("mtris_per_s", Mtris(t, b.Quadric.Median))
                                         .Set("output_triangles", b.QuadricTriangles))
                 .Set("meshopt_10pct", ToJson(b.Meshopt)
                                         .Set("mtris_per_s", Mtris(t, b.Meshopt.Median))
                                         .Set("output_triangles", b.MeshoptTriangles))
                 .Set("speedup_vs_quadric", b.Quadric.Median / b.Tom.Median)
                 .Set("speedup_vs_meshopt", b.Meshopt.Median / b.Tom.Median);
  const MemoryFigures& f = m.Memory;
  JsonValue memory = JsonValue::Object()
                  .Set("vertices", f.Vertices)
                  .Set("triangles", f.Triangles)
                  .Set("error_curve_samples", f.CurveSamples)
                  .Set("face_vertex_bytes", f.FaceVertexBytes())
                  .Set("tom_bytes", f.TOMBytes())
                  .Set("overhead_percent", f.OverheadPercent());
  JsonValue traversal = JsonValue::Array();
  for (const TraversalFigures& tr : m.Traversal)
  {
    traversal.Push(JsonValue::Object()
                     .Set("resolution", tr.Resolution)
                     .Set("target_triangles", tr.TargetTriangles)
                     .Set("vertex_count", tr.VertexCount)
                     .Set("triangles", tr.Triangles)
                     .Set("median_s_per_extract", tr.SecondsPerExtract)
                     .Set("mtris_per_s", tr.Mtris())
                     .Set("chain_steps", tr.ChainSteps)
                     .Set("extra_vertex_percent", tr.ExtraVertexPercent())
                     .Set("extra_of_visited_percent", tr.ExtraOfVisitedPercent()));
  }
  JsonValue quality = JsonValue::Array();
  for (const QualityFigures& q : m.Quality)
  {
    JsonValue simplifiers = JsonValue::Object();
    for (size_t i = 0; i < Simplifiers.size(); ++i)
    {
      simplifiers.Set(Simplifiers[i].Key,
        JsonValue::Object()
          .Set("triangles", q.Triangles[i])
          .Set("vertex_subset_peer", Simplifiers[i].Peer)
          .Set("dense_relative_hausdorff", ToJson(q.Dense[i]))
          .Set("vertex_only_relative_hausdorff", ToJson(q.VertexOnly[i])));
    }
    quality.Push(JsonValue::Object()
                   .Set("resolution", q.Resolution)
                   .Set("simplifiers", std::move(simplifiers))
                   .Set("best_peer", Simplifiers[q.BestPeer(q.Dense)].Key)
                   .Set("ratio_tom_over_best_peer", q.Ratio())
                   .Set("best_peer_vertex_only", Simplifiers[q.BestPeer(q.VertexOnly)].Key)
                   .Set("ratio_tom_over_best_peer_vertex_only", q.VertexOnlyRatio())
                   .Set("ratio_tom_over_vtk_quadric",
                     SafeRatio(q.Dense[0].Symmetric(), q.Dense.back().Symmetric())));
  }
  return JsonValue::Object()
    .Set("name", m.Name)
    .Set("origin", m.Origin)
    .Set("points", m.Points)
    .Set("triangles", m.Triangles)
    .Set("bounding_box_diagonal", m.Diagonal)
    .Set("load_s", m.LoadSeconds)
    .Set("build", m.QualityOnly ? JsonValue() : std::move(build))
    .Set("memory", m.QualityOnly ? JsonValue() : std::move(memory))
    .Set("traversal", m.QualityOnly ? JsonValue() : std::move(traversal))
    .Set("hausdorff", std::move(quality))
    .Set("hausdorff_skipped", m.QualitySkipped.empty() ? JsonValue() : JsonValue(m.QualitySkipped))
    .Set("merge_tree", m.QualityOnly ? JsonValue() : MergeTreeJson(m));
}

/// Medians over the meshes of the headline figures.
JsonValue Medians(const std::vector<MeshReport>& reports)
{
  std::vector<double> build, quadric, meshopt, memory, rate, chain, ratio, vertexRatio;
  for (const MeshReport& m : reports)
  {
    for (const QualityFigures& q : m.Quality)
    {
      ratio.push_back(q.Ratio());
      vertexRatio.push_back(q.VertexOnlyRatio());
    }
    if (m.QualityOnly)
    {
      continue;
    }
    const double t = static_cast<double>(m.Triangles);
    build.push_back(Mtris(t, m.Build.Tom.Median));
    quadric.push_back(Mtris(t, m.Build.Quadric.Median));
    meshopt.push_back(Mtris(t, m.Build.Meshopt.Median));
    memory.push_back(m.Memory.OverheadPercent());
    for (const TraversalFigures& f : m.Traversal)
    {
      rate.push_back(f.Mtris());
      chain.push_back(f.ExtraVertexPercent());
    }
  }
  const auto maximum = [](const std::vector<double>& v) {
    return v.empty() ? JsonValue() : JsonValue(*std::max_element(v.begin(), v.end()));
  };
  return JsonValue::Object()
    .Set("tom_build_mtris_per_s", Median(build))
    .Set("quadric_10pct_mtris_per_s", Median(quadric))
    .Set("meshopt_10pct_mtris_per_s", Median(meshopt))
    .Set("memory_overhead_percent", Median(memory))
    .Set("traversal_mtris_per_s", Median(rate))
    .Set("extra_vertex_percent", Median(chain))
    .Set("quality_ratio_geometric_mean", ratio.empty() ? JsonValue() : JsonValue(GeometricMean(ratio)))
    .Set("quality_ratio_max", maximum(ratio))
    .Set("quality_ratio_vertex_only_geometric_mean",
      vertexRatio.empty() ? JsonValue() : JsonValue(GeometricMean(vertexRatio)))
    .Set("quality_ratio_vertex_only_max", maximum(vertexRatio));
}

//------------------------------------------------------------------------------
// Machine and run information

JsonValue MachineInfo()
{
  return JsonValue::Object()
    .Set("cpu_model", CpuModel())
    .Set("hardware_threads", std::thread::hardware_concurrency())
    .Set("load_average_at_start", LoadAverageText())
    .Set("date_utc", UtcNow())
    .Set("compiler", __VERSION__)
#ifdef NDEBUG
    .Set("assertions", false)
#else
    .Set("assertions", true)
#endif
    .Set("vtk_version", vtkVersion::GetVTKVersion())
    .Set("meshoptimizer_version", MESHOPTIMIZER_VERSION);
}

JsonValue SettingsInfo(const Settings& s)
{
  JsonValue goals = JsonValue::Object();
  for (const Goal* goal : AllGoals)
  {
    goals.Set(goal->Name, goal->Text());
  }
  return JsonValue::Object()
    .Set("quick", s.Quick)
    .Set("data_directory", s.DataDirectory)
    .Set("build_runs", s.BuildRuns)
    .Set("hausdorff_max_triangles", s.HausdorffMaxTriangles)
    .Set("single_run_above_s", s.SlowRunSeconds)
    .Set("traversal_min_measurement_s", s.MinMeasureSeconds)
    .Set("traversal_measurements", s.TraversalMeasurements)
    .Set("comparison_fraction", ComparisonFraction)
    .Set("quadric_settings", "VTK defaults, TargetReduction 0.9, VolumePreservation off")
    .Set("meshopt_settings", "meshopt_simplify, target 10% of indices, target_error 1e9, options 0")
    .Set("quality_only", s.QualityOnly)
    .Set("quality_resolutions", [] {
      JsonValue r = JsonValue::Array();
      for (double x : HausdorffResolutions)
      {
        r.Push(x);
      }
      return r;
    }())
    .Set("quality_measure",
      "dense symmetric Hausdorff / bounding-box diagonal: original's vertices, edge midpoints and "
      "centroids against the simplified triangles; simplified's vertices and barycentric grids of "
      "spacing " + Fixed(SampleSpacing, 2) + " x the original's mean edge length against the "
      "original triangles (SurfaceDistance.h); peers at the TOM's triangle count: meshopt_simplify "
      "(target_error 1e9, options 0 and meshopt_SimplifyLockBorder), OpenMesh DecimaterT with "
      "ModQuadricT + ModNormalFlippingT 90 / 60 degrees / 90 + ModAspectRatioT 5")
    .Set("goals", std::move(goals));
}

//------------------------------------------------------------------------------
// Command line

void PrintUsage(std::ostream& os)
{
  os << "usage: TOMBenchmark [--quick] [--quality-only] [--mesh NAME]... [--json FILE] [--data DIR]\n"
        "                    [--hausdorff-all] [--engine greedy|passes] [--build-only]\n"
        "  --quick          small meshes only, shorter measurements (smoke test)\n"
        "  --quality-only   section 4 only (quality against the peers)\n"
        "  --mesh NAME      only this mesh (repeatable): cow, spot, ..., igea-loop1, blobby\n"
        "  --json FILE      where to write the figures (default tom-benchmark.json)\n"
        "  --data DIR       folder of the shared meshes\n"
        "                   (default " TIMECRITICAL_SHARED_DATA_DIR ")\n"
        "  --hausdorff-all  Hausdorff distances also for meshes over 500k triangles (minutes)\n"
        "  --engine NAME    the TOM builds' engine (TOMBuildOptions::Engine): greedy (default)\n"
        "                   or passes\n"
        "  --build-only     only the build times of both engines and meshopt's 10% level\n";
}

enum class Parsed
{
  Run,
  Help,
  Error
};

Parsed ParseArguments(int argc, char* argv[], Settings& settings)
{
  bool help = false, hausdorffAll = false;
  BenchmarkArguments arguments(argc, argv);
  arguments.AddFlag("--help", help);
  arguments.AddFlag("-h", help);
  arguments.AddFlag("--quick", settings.Quick);
  arguments.AddFlag("--quality-only", settings.QualityOnly);
  arguments.AddRepeatedText("--mesh", settings.MeshNames);
  arguments.AddText("--json", settings.JsonPath);
  arguments.AddText("--data", settings.DataDirectory);
  arguments.AddFlag("--hausdorff-all", hausdorffAll);
  arguments.AddFlag("--build-only", settings.BuildOnly);
  std::string engine = "greedy";
  arguments.AddText("--engine", engine);
  try
  {
    arguments.Parse();
  }
  catch (const std::runtime_error& error)
  {
    std::cerr << error.what() << "\n";
    PrintUsage(std::cerr);
    return Parsed::Error;
  }
  if (help)
  {
    PrintUsage(std::cout);
    return Parsed::Help;
  }
  if (engine != "greedy" && engine != "passes")
  {
    std::cerr << "--engine must be greedy or passes\n";
    PrintUsage(std::cerr);
    return Parsed::Error;
  }
  settings.Engine = engine == "passes" ? timecritical::TOMBuildEngine::Passes
                                       : timecritical::TOMBuildEngine::Greedy;
  CurrentEngine = settings.Engine;
  settings.QualityOnly = settings.QualityOnly || settings.BuildOnly;
  if (settings.Quick)
  {
    settings.MinMeasureSeconds = 0.02;
  }
  if (hausdorffAll)
  {
    settings.HausdorffMaxTriangles = std::numeric_limits<size_t>::max();
  }
  return Parsed::Run;
}

int Run(const Settings& settings)
{
  omerr().disable(); // refused faces are counted instead (OpenMeshDecimate)
  std::cout << "TOMBenchmark on " << CpuModel() << " (" << std::thread::hardware_concurrency()
            << " threads, load average " << LoadAverageText() << "), " << UtcNow()
            << (settings.Quick ? " (quick)" : "") << std::endl;
  const JsonValue machine = MachineInfo();
  std::vector<MeshReport> reports;
  const double total = SecondsOf([&]() {
    for (const MeshSource& source : ChooseMeshes(settings))
    {
      reports.push_back(MeasureMesh(settings, source));
    }
  });

  GoalLog goals;
  if (!settings.QualityOnly)
  {
    PrintBuild(reports, goals);
    PrintMemory(reports, goals);
    PrintTraversal(reports, goals);
  }
  PrintQuality(reports, goals);
  if (!settings.QualityOnly)
  {
    PrintMergeTree(reports, goals);
  }
  goals.PrintSummary(std::cout);

  JsonValue meshes = JsonValue::Array();
  for (const MeshReport& report : reports)
  {
    meshes.Push(ToJson(report));
  }
  const JsonValue document = JsonValue::Object()
                          .Set("benchmark", "TOMBenchmark")
                          .Set("machine", machine)
                          .Set("load_average_at_end", LoadAverageText())
                          .Set("settings", SettingsInfo(settings))
                          .Set("total_s", total)
                          .Set("meshes", std::move(meshes))
                          .Set("medians_over_meshes", Medians(reports))
                          .Set("goal_checks", goals.ToJson())
                          .Set("goals_missed", goals.Missed());
  std::ofstream out(settings.JsonPath);
  document.Write(out);
  out << "\n";
  out.close();
  if (!out)
  {
    std::cerr << "error: cannot write " << settings.JsonPath << "\n";
    return 1;
  }
  std::cout << "\n" << goals.Missed() << " goal check(s) missed; " << reports.size()
            << " mesh(es) in " << Fixed(total, 1) << " s; figures written to " << settings.JsonPath
            << std::endl;
  return 0;
}
}

int main(int argc, char* argv[])
{
  Settings settings;
  switch (ParseArguments(argc, argv, settings))
  {
    case Parsed::Help:
      return 0;
    case Parsed::Error:
      return 2;
    case Parsed::Run:
      break;
  }
  try
  {
    return Run(settings);
  }
  catch (const std::exception& e)
  {
    std::cerr << "error: " << e.what() << std::endl;
    return 1;
  }
}
