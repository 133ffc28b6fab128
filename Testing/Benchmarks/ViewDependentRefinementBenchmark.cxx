// SPDX-License-Identifier: BSD-3-Clause
// ViewDependentRefinementBenchmark [mesh] [--json FILE] [--loop N] [--w2-only]
// [--w2-fixed] [--limit SECONDS] [--plain] [--repeat N] (--help: usage): on an
// orbit around the mesh (igea by default): the display triangle fraction at
// tau = 1 px, 512 x 512, the share of forced splits (fronts from scratch), what
// back-face simplification and a half-space frustum save, the incremental
// fixed-accuracy and budget update times near 100K display triangles (median,
// mean, worst), and ComputeMergeTree's time per million triangles.
//
// W2-like scenario (after the above, or alone with --w2-only; --loop 1 gives
// W2's 1.07M-triangle igea): the renderer's settings (back faces simplified,
// silhouette refinement 0.25, highlight refinement 0.5, W2's fixed light, the
// camera's six frustum planes and near distance; --plain: silhouette and
// highlight off, headlight, no frustum) at 512 px, a camera path of 3-5 degrees
// and up to 10% zoom per frame; fixed-accuracy updates at tau = 1 px, then
// budget updates at tau floor 0 with budgets moving by 5-20% per frame within
// 50-120K triangles, unbounded and with a work bound of --limit seconds
// (default 5 ms). Wall and process CPU times per update (CPU time does not
// count waiting for a core on a loaded machine); --repeat N runs each path N
// times and keeps each frame's fastest. Under callgrind (--instr-atstart=no)
// only the unbounded W2-like budget updates are instrumented, or with
// --w2-fixed (implies --w2-only) the fixed-accuracy updates.
#include "BenchmarkArguments.h"
#include "LoopSubdivision.h"
#include "MergeTreeAttributes.h"
#include "TOMBuilder.h"
#include "MeshIO.h"
#include "ViewDependentRefinement.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <map>
#include <numeric>
#include <string>
#include <vector>

#if defined(__has_include)
#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#endif
#endif
#ifndef CALLGRIND_START_INSTRUMENTATION
#define CALLGRIND_START_INSTRUMENTATION
#define CALLGRIND_STOP_INSTRUMENTATION
#endif

using namespace timecritical;

namespace
{
void PrintUsage(FILE* out, const char* program)
{
  std::fprintf(out,
    "usage: %s [MESH] [--json FILE] [--loop N] [--w2-only] [--w2-fixed] [--limit SECONDS] "
    "[--plain] [--repeat N]\n"
    "  MESH             OBJ or PLY surface (default: igea.ply of the shared data)\n"
    "  --json FILE      write the figures as JSON\n"
    "  --loop N         Loop-subdivide the mesh N times first (1: W2's igea)\n"
    "  --w2-only        only the W2-like scenario (renderer settings, camera path)\n"
    "  --w2-fixed       --w2-only; callgrind instruments the fixed-accuracy updates\n"
    "  --limit SECONDS  work bound of the bounded W2-like budget updates (default 0.005; 0: "
    "none)\n"
    "  --plain          W2-like without silhouette and highlight refinement or frustum\n"
    "  --repeat N       run each W2-like path N times; per frame the fastest (shared "
    "machines)\n"
    "  --help           this message\n",
    program);
}

/// Parses a whole argument as a number (false when it is not one).
int Run(int argc, char** argv);
}

int main(int argc, char** argv)
{
  try
  {
    return Run(argc, argv);
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "%s: %s\n", argv[0], e.what());
    return 1;
  }
}

namespace
{
int Run(int argc, char** argv)
{
  std::string path = testing::SharedDataDirectory() + "/igea.ply";
  std::string json;
  int loops = 0;
  bool w2Only = false;
  bool w2Fixed = false;
  bool plain = false;
  int repeat = 1;
  double limit = 0.005;
  bool help = false, w2FixedFlag = false;
  benchmark::BenchmarkArguments arguments(argc, argv);
  arguments.AddFlag("--help", help);
  arguments.AddFlag("-h", help);
  arguments.AddText("--json", json);
  arguments.AddInteger("--loop", loops, 0, 4);
  arguments.AddNumber("--limit", limit, [](double x) { return x >= 0.0; });
  arguments.AddFlag("--w2-only", w2Only);
  arguments.AddFlag("--w2-fixed", w2FixedFlag);
  arguments.AddFlag("--plain", plain);
  arguments.AddInteger("--repeat", repeat, 1, 100);
  arguments.AddPositional(path);
  try
  {
    arguments.Parse();
  }
  catch (const std::runtime_error& error)
  {
    std::fprintf(stderr, "%s: %s\n", argv[0], error.what());
    PrintUsage(stderr, argv[0]);
    return 2;
  }
  if (help)
  {
    PrintUsage(stdout, argv[0]);
    return 0;
  }
  if (w2FixedFlag)
  {
    w2Only = true;
    w2Fixed = true;
  }
  testing::TriangleMesh mesh =
    testing::RemoveUnusedPoints(testing::WeldPoints(testing::LoadMesh(path)));
  mesh = benchmark::LoopSubdivide(mesh, loops);
  const TOMBuildResult r = TOMBuilder().Build(
    mesh.Points.data(), mesh.NumberOfPoints(), mesh.Triangles.data(), mesh.NumberOfTriangles());
  std::vector<double> points(3 * r.VertexOrder.size());
  double lo[3] = { 1e300, 1e300, 1e300 }, hi[3] = { -1e300, -1e300, -1e300 };
  for (size_t i = 0; i < r.VertexOrder.size(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      points[3 * i + k] = mesh.Points[3 * size_t(r.VertexOrder[i]) + k];
      lo[k] = std::min(lo[k], points[3 * i + k]);
      hi[k] = std::max(hi[k], points[3 * i + k]);
    }
  }
  double centre[3], size = 0;
  for (int k = 0; k < 3; ++k)
  {
    centre[k] = 0.5 * (lo[k] + hi[k]);
    size = std::max(size, hi[k] - lo[k]);
  }
  const auto treeStart = std::chrono::steady_clock::now();
  const MergeTree tree = ComputeMergeTree(r.Mesh, points.data(), nullptr);
  const double treeSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - treeStart).count();
  const uint32_t full = r.Mesh.GetNumberOfTriangles();
  ViewDependentRefinement vdr;
  vdr.Initialize(r.Mesh, tree, points.data());

  // Orbit at a distance where the object fills a 30-degree view.
  const double pi = 3.14159265358979323846;
  auto orbit = [&](double angle, double distanceFactor, double height) {
    RefinementView view;
    view.ViewportHeight = height;
    view.ViewAngle = 30;
    const double distance = distanceFactor * (0.5 * size / std::tan(15 * pi / 180) + 0.5 * size);
    view.Eye[0] = centre[0] + distance * std::cos(angle);
    view.Eye[1] = centre[1] + 0.3 * distance * std::sin(0.7 * angle);
    view.Eye[2] = centre[2] + distance * std::sin(angle);
    for (int k = 0; k < 3; ++k)
    {
      view.Direction[k] = centre[k] - view.Eye[k];
      view.LightDirection[k] = view.Eye[k] - centre[k];
    }
    return view;
  };

  auto median = [](std::vector<double> x) {
    std::sort(x.begin(), x.end());
    return x.empty() ? 0.0 : x[x.size() / 2];
  };

  // W2-like views: what vtkMultiresolutionPolyDataMapper passes for W2's
  // camera (512 x 512, so both half-angles are 15 degrees): the six frustum
  // planes and the near distance of a clipping range reset to the bounds.
  auto w2View = [&](double angle, double zoom) {
    RefinementView view = orbit(angle, zoom, 512);
    if (plain)
    {
      return view;
    }
    // W2's light outside its close-up: 70 degrees left of +z, 35 up (a fixed
    // light instead of the orbit's headlight, which would put a highlight at
    // the centre of every view).
    const double la = -70 * pi / 180, le = 35 * pi / 180;
    view.LightDirection[0] = std::sin(la) * std::cos(le);
    view.LightDirection[1] = std::sin(le);
    view.LightDirection[2] = std::cos(la) * std::cos(le);
    double d[3], right[3], up[3];
    const double* dir = view.Direction;
    const double dl = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
    for (int k = 0; k < 3; ++k)
    {
      d[k] = dir[k] / dl;
    }
    // right = d x (0, 1, 0), up = right x d
    right[0] = -d[2];
    right[1] = 0.0;
    right[2] = d[0];
    const double rl = std::sqrt(right[0] * right[0] + right[2] * right[2]);
    right[0] /= rl;
    right[2] /= rl;
    up[0] = right[1] * d[2] - right[2] * d[1];
    up[1] = right[2] * d[0] - right[0] * d[2];
    up[2] = right[0] * d[1] - right[1] * d[0];
    double nearest = 1e300, farthest = -1e300;
    for (int c = 0; c < 8; ++c)
    {
      double depth = 0.0;
      for (int k = 0; k < 3; ++k)
      {
        depth += d[k] * (((c >> k) & 1 ? hi[k] : lo[k]) - view.Eye[k]);
      }
      nearest = std::min(nearest, depth);
      farthest = std::max(farthest, depth);
    }
    farthest *= 1.01;
    nearest = std::max(0.99 * nearest, 1e-3 * farthest);
    view.NearDistance = nearest;
    const double ch = std::cos(15 * pi / 180), sh = std::sin(15 * pi / 180);
    const double sides[4][3] = { { ch * right[0], ch * right[1], ch * right[2] },
      { -ch * right[0], -ch * right[1], -ch * right[2] }, { ch * up[0], ch * up[1], ch * up[2] },
      { -ch * up[0], -ch * up[1], -ch * up[2] } };
    view.NumberOfFrustumPlanes = 6;
    for (int i = 0; i < 6; ++i)
    {
      double n[3];
      for (int k = 0; k < 3; ++k)
      {
        n[k] = i < 4 ? sides[i][k] + sh * d[k] : (i == 4 ? d[k] : -d[k]);
      }
      const double offset = i < 4 ? 0.0 : (i == 4 ? -nearest : farthest);
      for (int k = 0; k < 3; ++k)
      {
        view.FrustumPlanes[i][k] = n[k];
      }
      view.FrustumPlanes[i][3] = offset - (n[0] * view.Eye[0] + n[1] * view.Eye[1] + n[2] * view.Eye[2]);
    }
    return view;
  };
  // The renderer's and the mapper's defaults (W2 sets them explicitly).
  auto w2Settings = [&](double tau) {
    vdr.SetPixelThreshold(tau);
    vdr.SetBackFaceSimplification(true);
    vdr.SetSilhouetteRefinement(!plain);
    vdr.SetSilhouetteFactor(0.25);
    vdr.SetHighlightRefinement(!plain);
    vdr.SetHighlightFactor(0.5);
  };
  const char* w2Label = plain ? "plain" : "silhouette 0.25, highlight 0.5, frustum";

  // W2-like scenario: large view changes and budgets moving by thousands of
  // triangles each frame (see the file comment). Deterministic path.
  struct W2Figures
  {
    double Median = 0, Mean = 0, Worst = 0, Triangles = 0, Operations = 0, Lag = 0;
    double CpuMedian = 0, CpuMean = 0; // process CPU time: less sensitive to other load
  };
  const int w2Frames = 120;
  // Per frame the fastest of `repeat` runs (wall and CPU time apart).
  auto keepFastest = [](std::vector<double>& best, const std::vector<double>& run) {
    if (best.empty())
    {
      best = run;
    }
    for (size_t i = 0; i < best.size() && i < run.size(); ++i)
    {
      best[i] = std::min(best[i], run[i]);
    }
  };
  auto summarize = [&](W2Figures& f, const std::vector<double>& times,
                     const std::vector<double>& cpu) {
    f.Median = median(times);
    f.Mean = std::accumulate(times.begin(), times.end(), 0.0) / w2Frames;
    f.Worst = *std::max_element(times.begin(), times.end());
    f.CpuMedian = median(cpu);
    f.CpuMean = std::accumulate(cpu.begin(), cpu.end(), 0.0) / w2Frames;
  };
  // One update, its wall time (the core's own) and CPU time recorded, under
  // callgrind's instrumentation when asked.
  auto timedUpdate = [](bool instrument, std::vector<double>& times, std::vector<double>& cpu,
                       auto update) -> const RefinementStatistics& {
    if (instrument)
    {
      CALLGRIND_START_INSTRUMENTATION;
    }
    const std::clock_t clock0 = std::clock();
    const RefinementStatistics& s = update();
    const std::clock_t clock1 = std::clock();
    if (instrument)
    {
      CALLGRIND_STOP_INSTRUMENTATION;
    }
    times.push_back(s.Seconds);
    cpu.push_back(double(clock1 - clock0) / CLOCKS_PER_SEC);
    return s;
  };
  auto runW2 = [&](double timeLimit, bool instrument) {
    uint64_t state = 12345;
    auto uniform = [&state]() {
      state = state * 6364136223846793005ull + 1442695040888963407ull;
      return double(state >> 11) * (1.0 / 9007199254740992.0);
    };
    const double lowBudget = std::min(50000.0, 0.05 * full);
    const double highBudget = std::min(120000.0, 0.12 * full);
    std::vector<double> bestTimes, bestCpu;
    W2Figures f;
    for (int run = 0; run < repeat; ++run)
    {
      state = 12345;
      double angle = 0, zoom = 1.0, budget = 0.5 * (lowBudget + highBudget);
      w2Settings(0.0);
      vdr.Reset();
      vdr.SetView(w2View(angle, zoom));
      vdr.UpdateBudget(uint32_t(budget)); // warm-up: the first front
      std::vector<double> times, cpu;
      f = W2Figures{};
      for (int i = 0; i < w2Frames; ++i)
      {
        angle += (3.0 + 2.0 * uniform()) * pi / 180;
        zoom = std::min(1.6, std::max(0.5, zoom * (1.0 + 0.1 * (2 * uniform() - 1))));
        const double change = 0.05 + 0.15 * uniform();
        budget *= uniform() < 0.5 ? 1.0 - change : 1.0 + change;
        budget = std::min(highBudget, std::max(lowBudget, budget));
        vdr.SetView(w2View(angle, zoom));
        const RefinementStatistics& s = timedUpdate(instrument, times, cpu,
          [&]() -> const RefinementStatistics& {
            return vdr.UpdateBudget(uint32_t(budget), timeLimit);
          });
        f.Triangles += s.DisplayTriangles;
        f.Operations += s.Splits + s.Merges;
        f.Lag += std::abs(double(s.DisplayTriangles) - budget) / budget;
      }
      keepFastest(bestTimes, times);
      keepFastest(bestCpu, cpu);
    }
    summarize(f, bestTimes, bestCpu);
    f.Triangles /= w2Frames;
    f.Operations /= w2Frames;
    f.Lag /= w2Frames;
    std::printf("W2-like budget updates (%s, %s): %.0f display triangles, %.0f splits + merges per "
                "frame, median %.3f ms, mean %.3f ms, worst %.3f ms (CPU median %.3f ms, mean "
                "%.3f ms), mean |triangles - budget| / budget %.2f%%\n",
      w2Label,
      timeLimit > 0 ? ("limit " + std::to_string(1e3 * timeLimit) + " ms").c_str() : "unbounded",
      f.Triangles, f.Operations, 1e3 * f.Median, 1e3 * f.Mean, 1e3 * f.Worst, 1e3 * f.CpuMedian,
      1e3 * f.CpuMean, 100 * f.Lag);
    return f;
  };
  // The same path with fixed-accuracy updates at tau = 1 px (W2's front).
  auto runW2Fixed = [&](bool instrument) {
    uint64_t state = 12345;
    auto uniform = [&state]() {
      state = state * 6364136223846793005ull + 1442695040888963407ull;
      return double(state >> 11) * (1.0 / 9007199254740992.0);
    };
    std::vector<double> bestTimes, bestCpu;
    W2Figures f;
    for (int run = 0; run < repeat; ++run)
    {
      state = 12345;
      double angle = 0, zoom = 1.0;
      w2Settings(1.0);
      vdr.Reset();
      vdr.SetView(w2View(angle, zoom));
      vdr.UpdateFixedAccuracy(); // warm-up: the first front
      std::vector<double> times, cpu;
      f = W2Figures{};
      for (int i = 0; i < w2Frames; ++i)
      {
        angle += (3.0 + 2.0 * uniform()) * pi / 180;
        zoom = std::min(1.6, std::max(0.5, zoom * (1.0 + 0.1 * (2 * uniform() - 1))));
        uniform(); // the budget draws of runW2: same camera path
        uniform();
        vdr.SetView(w2View(angle, zoom));
        const RefinementStatistics& s = timedUpdate(instrument, times, cpu,
          [&]() -> const RefinementStatistics& { return vdr.UpdateFixedAccuracy(); });
        f.Triangles += s.DisplayTriangles;
        f.Operations += s.Splits + s.Merges;
      }
      keepFastest(bestTimes, times);
      keepFastest(bestCpu, cpu);
    }
    summarize(f, bestTimes, bestCpu);
    f.Triangles /= w2Frames;
    f.Operations /= w2Frames;
    std::printf("W2-like fixed-accuracy updates (tau 1 px, %s): %.0f display triangles, %.0f "
                "splits + merges per frame, median %.3f ms, mean %.3f ms, worst %.3f ms (CPU "
                "median %.3f ms, mean %.3f ms)\n",
      w2Label, f.Triangles, f.Operations, 1e3 * f.Median, 1e3 * f.Mean, 1e3 * f.Worst,
      1e3 * f.CpuMedian, 1e3 * f.CpuMean);
    return f;
  };
  // W2-like figures as JSON members (both modes write them).
  auto w2Json = [&](FILE* out, const W2Figures& fixed, const W2Figures& unbounded,
                  const W2Figures& bounded) {
    std::fprintf(out,
      "  \"w2_settings\": \"%s\",\n"
      "  \"w2_fixed_display_triangles\": %.0f,\n  \"w2_fixed_operations\": %.0f,\n"
      "  \"w2_fixed_update_ms_median\": %.4f,\n  \"w2_fixed_update_ms_mean\": %.4f,\n"
      "  \"w2_fixed_update_ms_worst\": %.4f,\n"
      "  \"w2_fixed_update_cpu_ms_median\": %.4f,\n  \"w2_fixed_update_cpu_ms_mean\": %.4f,\n"
      "  \"w2_update_ms_median\": %.4f,\n  \"w2_update_ms_mean\": %.4f,\n"
      "  \"w2_update_cpu_ms_median\": %.4f,\n  \"w2_update_cpu_ms_mean\": %.4f,\n"
      "  \"w2_update_ms_worst\": %.4f,\n  \"w2_display_triangles\": %.0f,\n"
      "  \"w2_operations\": %.0f,\n"
      "  \"w2_limit_s\": %.4f,\n  \"w2_bounded_update_ms_median\": %.4f,\n"
      "  \"w2_bounded_update_ms_mean\": %.4f,\n  \"w2_bounded_update_ms_worst\": %.4f,\n"
      "  \"w2_bounded_budget_lag\": %.4f,\n  \"w2_repeat\": %d\n}\n",
      w2Label, fixed.Triangles, fixed.Operations, 1e3 * fixed.Median, 1e3 * fixed.Mean,
      1e3 * fixed.Worst, 1e3 * fixed.CpuMedian, 1e3 * fixed.CpuMean, 1e3 * unbounded.Median,
      1e3 * unbounded.Mean, 1e3 * unbounded.CpuMedian, 1e3 * unbounded.CpuMean,
      1e3 * unbounded.Worst,
      unbounded.Triangles, unbounded.Operations, limit, 1e3 * bounded.Median, 1e3 * bounded.Mean,
      1e3 * bounded.Worst, bounded.Lag, repeat);
  };
  auto openJson = [&]() -> FILE* {
    FILE* out = std::fopen(json.c_str(), "w");
    if (out == nullptr)
    {
      std::perror(json.c_str());
    }
    return out;
  };
  if (w2Only)
  {
    std::printf("%s: %u triangles\n", path.c_str(), full);
    const W2Figures fixed = runW2Fixed(w2Fixed);
    const W2Figures unbounded = runW2(0.0, !w2Fixed);
    const W2Figures bounded = limit > 0 ? runW2(limit, false) : W2Figures{};
    if (!json.empty())
    {
      FILE* out = openJson();
      if (out == nullptr)
      {
        return 1;
      }
      std::fprintf(out, "{\n  \"mesh\": \"%s\",\n  \"triangles\": %u,\n", path.c_str(), full);
      w2Json(out, fixed, unbounded, bounded);
      std::fclose(out);
    }
    return 0;
  }

  // At tau = 1 px, 512 x 512, fronts from scratch: triangle fraction, forced
  // share, back-face and frustum savings (frustum: the half-space right of the
  // view axis through the centre; saving = 1 - half / whole).
  double fractionSum = 0, noBackSum = 0, halfSum = 0;
  uint64_t splits = 0, forced = 0;
  const int fractionViews = 16;
  vdr.SetPixelThreshold(1.0);
  for (int i = 0; i < fractionViews; ++i)
  {
    RefinementView view = orbit(2 * pi * i / fractionViews, 1.0, 512);
    vdr.SetView(view);
    vdr.SetBackFaceSimplification(true);
    vdr.Reset();
    const RefinementStatistics s = vdr.UpdateFixedAccuracy();
    fractionSum += double(s.DisplayTriangles) / full;
    splits += s.Splits;
    forced += s.ForcedSplits;
    vdr.SetBackFaceSimplification(false);
    noBackSum += double(vdr.UpdateFixedAccuracy().DisplayTriangles) / full;
    vdr.SetBackFaceSimplification(true);
    // Right of the view direction d (up = y): normal d x y.
    const double* d = view.Direction;
    double nrm[3] = { -d[2], 0.0, d[0] };
    const double len = std::sqrt(nrm[0] * nrm[0] + nrm[2] * nrm[2]);
    view.NumberOfFrustumPlanes = 1;
    view.FrustumPlanes[0][0] = nrm[0] / len;
    view.FrustumPlanes[0][1] = 0.0;
    view.FrustumPlanes[0][2] = nrm[2] / len;
    view.FrustumPlanes[0][3] = -(nrm[0] * centre[0] + nrm[2] * centre[2]) / len;
    vdr.SetView(view);
    halfSum += double(vdr.UpdateFixedAccuracy().DisplayTriangles) / full;
  }
  const double fraction = fractionSum / fractionViews;
  const double forcedShare = splits ? double(forced) / splits : 0.0;
  const double backSaving = 1.0 - fractionSum / noBackSum;
  const double frustumSaving = 1.0 - halfSum / fractionSum;
  std::printf("%s: %u triangles; ComputeMergeTree %.3f s (%.3f s per million triangles)\n",
    path.c_str(), full, treeSeconds, treeSeconds * 1e6 / full);
  std::printf("tau = 1 px at 512 x 512: %.2f%% of the full mesh, %.1f%% of splits forced, "
              "back faces save %.1f%%, a half-space frustum saves %.1f%%\n",
    100 * fraction, 100 * forcedShare, 100 * backSaving, 100 * frustumSaving);

  // Find tau giving about 100K display triangles at 1024 px, then orbit.
  const double targetTriangles = std::min(100000.0, 0.5 * full);
  double tau = 1.0;
  for (int i = 0; i < 40; ++i)
  {
    vdr.SetView(orbit(0, 1.0, 1024));
    vdr.SetPixelThreshold(tau);
    const double t = vdr.UpdateFixedAccuracy().DisplayTriangles;
    if (std::abs(t - targetTriangles) < 0.05 * targetTriangles)
    {
      break;
    }
    tau *= std::pow(std::max(t, 1.0) / targetTriangles, 0.7);
  }
  const int frames = 360;
  std::vector<double> fixedTimes, budgetTimes;
  double triangles = 0, budgetTriangles = 0;
  uint64_t work = 0;
  for (int i = 0; i < frames; ++i)
  {
    vdr.SetView(orbit(2 * pi * i / frames, 1.0 + 0.2 * std::sin(i * 0.05), 1024));
    const RefinementStatistics& s = vdr.UpdateFixedAccuracy();
    fixedTimes.push_back(s.Seconds);
    triangles += s.DisplayTriangles;
    work += s.Splits + s.Merges;
  }
  const double fixedMedian = median(fixedTimes);
  const double fixedMean = std::accumulate(fixedTimes.begin(), fixedTimes.end(), 0.0) / frames;
  const double fixedWorst = *std::max_element(fixedTimes.begin(), fixedTimes.end());
  std::printf("fixed accuracy, tau %.3f px, 1 degree per frame: %.0f display triangles, "
              "median %.3f ms, mean %.3f ms, worst %.3f ms per frame, %.0f splits + merges per "
              "frame\n",
    tau, triangles / frames, 1e3 * fixedMedian, 1e3 * fixedMean, 1e3 * fixedWorst,
    double(work) / frames);
  // Budget mode at the same tau (a floor) and a cap below what tau alone gives.
  const uint32_t budget = uint32_t(0.9 * triangles / frames);
  for (int i = 0; i < frames; ++i)
  {
    vdr.SetView(orbit(2 * pi * i / frames, 1.0, 1024));
    const RefinementStatistics& s = vdr.UpdateBudget(budget);
    budgetTimes.push_back(s.Seconds);
    budgetTriangles += s.DisplayTriangles;
  }
  const double budgetMedian = median(budgetTimes);
  const double budgetMean = std::accumulate(budgetTimes.begin(), budgetTimes.end(), 0.0) / frames;
  const double budgetWorst = *std::max_element(budgetTimes.begin(), budgetTimes.end());
  std::printf("budget %u (tau %.3f px floor): %.0f display triangles, median %.3f ms, mean %.3f "
              "ms, worst %.3f ms per frame\n",
    budget, tau, budgetTriangles / frames, 1e3 * budgetMedian, 1e3 * budgetMean,
    1e3 * budgetWorst);
  const W2Figures w2FixedFigures = runW2Fixed(false);
  const W2Figures w2 = runW2(0.0, false);
  const W2Figures w2Bounded = limit > 0 ? runW2(limit, false) : W2Figures{};
  if (!json.empty())
  {
    FILE* out = openJson();
    if (out == nullptr)
    {
      return 1;
    }
    std::fprintf(out,
      "{\n  \"mesh\": \"%s\",\n  \"triangles\": %u,\n"
      "  \"compute_merge_tree_s_per_mtri\": %.4f,\n"
      "  \"tau1_fraction\": %.5f,\n  \"forced_split_share\": %.4f,\n"
      "  \"backface_saving\": %.4f,\n  \"frustum_half_saving\": %.4f,\n"
      "  \"fixed_tau\": %.5f,\n  \"fixed_display_triangles\": %.0f,\n"
      "  \"fixed_update_ms_median\": %.4f,\n  \"fixed_update_ms_mean\": %.4f,\n"
      "  \"fixed_update_ms_worst\": %.4f,\n  \"budget\": %u,\n"
      "  \"budget_display_triangles\": %.0f,\n  \"budget_update_ms_median\": %.4f,\n"
      "  \"budget_update_ms_mean\": %.4f,\n  \"budget_update_ms_worst\": %.4f,\n",
      path.c_str(), full, treeSeconds * 1e6 / full, fraction, forcedShare, backSaving,
      frustumSaving, tau, triangles / frames, 1e3 * fixedMedian, 1e3 * fixedMean,
      1e3 * fixedWorst, budget, budgetTriangles / frames, 1e3 * budgetMedian, 1e3 * budgetMean,
      1e3 * budgetWorst);
    w2Json(out, w2FixedFigures, w2, w2Bounded);
    std::fclose(out);
  }
  return 0;
}
}
