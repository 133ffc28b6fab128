// SPDX-License-Identifier: BSD-3-Clause
// ViewDependentRefinementBenchmark [mesh] [--json FILE]: on an orbit around
// the mesh (igea by default): the display triangle fraction at tau = 1 px,
// 512 x 512, the share of forced splits (fronts from scratch), what back-face
// simplification and a half-space frustum save, the incremental
// fixed-accuracy and budget update times near 100K display triangles (median,
// mean, worst), and ComputeMergeTree's time per million triangles.
#include "MergeTreeAttributes.h"
#include "TOMBuilder.h"
#include "TestMeshIO.h"
#include "ViewDependentRefinement.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>
#include <vector>

using namespace timecritical;

int main(int argc, char** argv)
{
  std::string path = testing::SharedDataDirectory() + "/igea.ply";
  std::string json;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--json" && i + 1 < argc)
    {
      json = argv[++i];
    }
    else
    {
      path = a;
    }
  }
  testing::TriangleMesh mesh =
    testing::RemoveUnusedPoints(testing::WeldPoints(testing::LoadMesh(path)));
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
  if (!json.empty())
  {
    FILE* out = std::fopen(json.c_str(), "w");
    if (out == nullptr)
    {
      std::perror(json.c_str());
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
      "  \"budget_update_ms_mean\": %.4f,\n  \"budget_update_ms_worst\": %.4f\n}\n",
      path.c_str(), full, treeSeconds * 1e6 / full, fraction, forcedShare, backSaving,
      frustumSaving, tau, triangles / frames, 1e3 * fixedMedian, 1e3 * fixedMean,
      1e3 * fixedWorst, budget, budgetTriangles / frames, 1e3 * budgetMedian, 1e3 * budgetMean,
      1e3 * budgetWorst);
    std::fclose(out);
  }
  return 0;
}
