// SPDX-License-Identifier: BSD-3-Clause
// ViewDependentRefinementBenchmark [mesh]: incremental fixed-accuracy update
// time per frame near 100K display triangles on an orbit, and the display
// triangle fraction at tau = 1 px, 512 x 512, against the full mesh.
#include "MergeTreeAttributes.h"
#include "TOMBuilder.h"
#include "TestMeshIO.h"
#include "ViewDependentRefinement.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace timecritical;

int main(int argc, char** argv)
{
  const std::string path =
    argc > 1 ? argv[1] : testing::SharedDataDirectory() + "/igea.ply";
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
  const MergeTree tree = ComputeMergeTree(r.Mesh, points.data(), nullptr);
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

  // Triangle fraction at tau = 1 px, 512 x 512 (back faces simplified).
  double fractionSum = 0;
  const int fractionViews = 16;
  for (int i = 0; i < fractionViews; ++i)
  {
    vdr.SetView(orbit(2 * pi * i / fractionViews, 1.0, 512));
    vdr.SetPixelThreshold(1.0);
    fractionSum += double(vdr.UpdateFixedAccuracy().DisplayTriangles) / full;
  }
  std::printf("%s: %u triangles; tau = 1 px at 512 x 512: %.1f%% of the full mesh on average\n",
    path.c_str(), full, 100 * fractionSum / fractionViews);

  // Find tau giving about 100K display triangles at 1024 px, then orbit.
  const double targetTriangles = std::min(100000.0, 0.5 * full);
  double tau = 1.0;
  for (int i = 0; i < 30; ++i)
  {
    vdr.SetView(orbit(0, 1.0, 1024));
    vdr.SetPixelThreshold(tau);
    const double t = vdr.UpdateFixedAccuracy().DisplayTriangles;
    if (std::abs(t - targetTriangles) < 0.05 * targetTriangles)
    {
      break;
    }
    tau *= std::pow(t / targetTriangles, 0.7);
  }
  const int frames = 360;
  double total = 0, worst = 0, triangles = 0;
  uint64_t work = 0;
  for (int i = 0; i < frames; ++i)
  {
    vdr.SetView(orbit(2 * pi * i / frames, 1.0 + 0.2 * std::sin(i * 0.05), 1024));
    const RefinementStatistics& s = vdr.UpdateFixedAccuracy();
    total += s.Seconds;
    worst = std::max(worst, s.Seconds);
    triangles += s.DisplayTriangles;
    work += s.Splits + s.Merges;
  }
  std::printf("fixed accuracy, tau %.3f px, 1 degree per frame: %.0f display triangles, "
              "%.3f ms per frame (worst %.3f ms), %.0f splits + merges per frame\n",
    tau, triangles / frames, 1e3 * total / frames, 1e3 * worst, double(work) / frames);
  total = worst = 0;
  for (int i = 0; i < frames; ++i)
  {
    vdr.SetView(orbit(2 * pi * i / frames, 1.0, 1024));
    const RefinementStatistics& s = vdr.UpdateBudget(uint32_t(targetTriangles));
    total += s.Seconds;
    worst = std::max(worst, s.Seconds);
  }
  std::printf("budget %u: %.3f ms per frame (worst %.3f ms)\n", uint32_t(targetTriangles),
    1e3 * total / frames, 1e3 * worst);
  return 0;
}
