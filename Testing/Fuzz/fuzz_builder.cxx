// SPDX-License-Identifier: BSD-3-Clause
// Fuzz target: the builders on arbitrary small meshes (points and triangles
// decoded from the input, format in FuzzFormat.h: any ids, NaN and infinite
// coordinates, duplicate points and triangles, degenerate triangles) and
// arbitrary in-range settings, into TOMBuilder and/or MergeTreeBuilder.
//
// The documented contract: std::invalid_argument exactly when an id is out
// of range or a point used by a non-degenerate triangle is not finite or
// beyond MaximumCoordinateMagnitude;
// otherwise a valid TOM whose triangles are the input's (same corners in the
// same cyclic order) and, for MergeTreeBuilder, a merge tree that
// vtkMergeTreeFieldData would accept. Anything else, any sanitizer report or
// a hang is a finding.
#include "FuzzChecks.h"
#include "FuzzFormat.h"
#include "MergeTreeBuilder.h"
#include "TOMBuilder.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

using namespace timecritical;
using namespace timecritical::fuzz;

namespace
{
/// Whether the documented contract makes Build throw std::invalid_argument.
bool ExpectInvalidArgument(const MeshInput& mesh)
{
  const size_t points = mesh.NumberOfPoints();
  for (uint32_t id : mesh.Triangles)
  {
    if (id >= points)
    {
      return true;
    }
  }
  for (size_t t = 0; t < mesh.NumberOfTriangles(); ++t)
  {
    const uint32_t* c = &mesh.Triangles[3 * t];
    if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2])
    {
      continue; // dropped: its points count as unused
    }
    for (int k = 0; k < 3; ++k)
    {
      for (int i = 0; i < 3; ++i)
      {
        if (!(std::abs(mesh.Points[3 * size_t(c[k]) + i]) <= MaximumCoordinateMagnitude))
        {
          return true; // NaN, infinite or too large
        }
      }
    }
  }
  return false;
}

uint8_t TailByte(const MeshInput& mesh, size_t i)
{
  return i < mesh.Tail.size() ? mesh.Tail[i] : 0;
}

TOMBuildOptions CollapseOptions(const MeshInput& mesh, int* progressCalls, int abortAfter)
{
  TOMBuildOptions options;
  options.PreserveBoundaries = (mesh.Flags & PreserveBoundaries) != 0;
  options.PreserveFeatureEdges = (mesh.Flags & PreserveFeatureEdges) != 0;
  options.FeatureAngle = mesh.Options[0] * (180.0 / 255.0);
  options.MaximumNormalDeviation = mesh.Options[1] * (180.0 / 255.0);
  options.MinimumTriangleQuality = (mesh.Flags & SliverRejection) ? mesh.Options[2] / 255.0 : 0.0;
  options.ErrorCurveSamples = TailByte(mesh, 0);
  // Tail byte 5, bit 0: the pass engine instead of the greedy one (TOMBuilder only).
  options.Engine = (TailByte(mesh, 5) & 1) ? TOMBuildEngine::Passes : TOMBuildEngine::Greedy;
  if (abortAfter > 0)
  {
    options.Progress = [progressCalls, abortAfter](double fraction) {
      FUZZ_REQUIRE(fraction >= 0.0 && fraction <= 1.0, "progress fraction in [0, 1]");
      return ++*progressCalls < abortAfter;
    };
  }
  return options;
}

void CheckAborted(const TOMBuildResult& result)
{
  FUZZ_REQUIRE(result.Mesh.GetNumberOfVertices() == 0 && result.Mesh.GetNumberOfTriangles() == 0,
    "an aborted build leaves the mesh empty");
}
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  const MeshInput mesh = DecodeMesh(data, size);
  const bool invalid = ExpectInvalidArgument(mesh);
  // Target bits: 0 -> MergeTreeBuilder instead of TOMBuilder, 1 -> both;
  // tail byte 4: abort through the progress callback at its n-th call.
  const bool mergeTree = (mesh.Flags & TargetBit0) != 0;
  const bool both = (mesh.Flags & TargetBit1) != 0;
  const int abortAfter = TailByte(mesh, 4) % 8;

  if (!mergeTree || both)
  {
    int calls = 0;
    const TOMBuilder builder(CollapseOptions(mesh, &calls, abortAfter));
    try
    {
      const TOMBuildResult result = builder.Build(
        mesh.Points.data(), mesh.NumberOfPoints(), mesh.Triangles.data(), mesh.NumberOfTriangles());
      FUZZ_REQUIRE(!invalid, "TOMBuilder accepted out-of-range ids or bad coordinates");
      if (result.Aborted)
      {
        FUZZ_REQUIRE(abortAfter > 0, "aborted by nobody");
        CheckAborted(result);
      }
      else
      {
        CheckBuildResult(result, mesh);
      }
    }
    catch (const std::invalid_argument& e)
    {
      FUZZ_REQUIRE(invalid, std::string("TOMBuilder rejected a valid mesh: ") + e.what());
    }
  }
  if (mergeTree || both)
  {
    int calls = 0;
    MergeTreeBuildOptions options;
    options.Collapse = CollapseOptions(mesh, &calls, abortAfter);
    options.LevelCostRatio = mesh.Options[3] / 32.0;
    options.LevelMinimumShare = TailByte(mesh, 1) / 255.0;
    options.UncappedShare = TailByte(mesh, 2) / 255.0;
    options.Errors.ShadingWeight = TailByte(mesh, 3) / 64.0;
    const MergeTreeBuilder builder(options);
    try
    {
      const MergeTreeBuildResult result = builder.Build(
        mesh.Points.data(), mesh.NumberOfPoints(), mesh.Triangles.data(), mesh.NumberOfTriangles());
      FUZZ_REQUIRE(!invalid, "MergeTreeBuilder accepted out-of-range ids or bad coordinates");
      if (result.TOM.Aborted)
      {
        FUZZ_REQUIRE(abortAfter > 0, "aborted by nobody");
        CheckAborted(result.TOM);
      }
      else
      {
        CheckBuildResult(result.TOM, mesh);
        CheckMergeTree(result);
      }
    }
    catch (const std::invalid_argument& e)
    {
      FUZZ_REQUIRE(invalid, std::string("MergeTreeBuilder rejected a valid mesh: ") + e.what());
    }
  }
  return 0;
}
