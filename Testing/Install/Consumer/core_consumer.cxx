// SPDX-License-Identifier: BSD-3-Clause
// Uses both installed VTK-free cores: builds a TOM of a tetrahedron (mesh
// core) and evaluates a one-object resolution problem (budget core).
#include "ResolutionProblem.h"
#include "TOMBuilder.h"

#include <cstdint>
#include <iostream>

int main()
{
  const double points[] = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  const uint32_t triangles[] = { 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3 };
  const timecritical::TOMBuildResult built =
    timecritical::TOMBuilder().Build(points, 4, triangles, 4);

  const double weight = 1.0, maxTime = 0.01, minResolution = 0.1, resolution = 0.5;
  timecritical::ResolutionProblem problem;
  problem.Count = 1;
  problem.Weight = &weight;
  problem.MaxTime = &maxTime;
  problem.MinResolution = &minResolution;
  const double cost = problem.Cost(&resolution);
  std::cout << "triangles " << built.Mesh.GetNumberOfTriangles() << " cost " << cost << "\n";
  return (built.Mesh.GetNumberOfTriangles() == 4 && cost > 0.0 && cost < maxTime) ? 0 : 1;
}
