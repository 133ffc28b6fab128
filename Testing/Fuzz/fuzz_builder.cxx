// SPDX-License-Identifier: BSD-3-Clause
// Fuzz target: the builders on arbitrary small meshes (points and triangles
// decoded from the input, format in FuzzFormat.h: any ids, NaN and infinite
// coordinates, duplicate points and triangles, degenerate triangles) and
// arbitrary in-range settings, into TOMBuilder and/or MergeTreeBuilder.
// TOMBuilder also joins separate parts (pair contraction) at a distance the
// input chooses (tail byte 6), and its finer levels must then be those of the
// build without pairs.
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

/**
 * Tail byte 6: TOMBuilder's PairContractionDistance: 0 off, 1..254 a
 * fraction of the diagonal up to ~4 (beyond 1 every part is in reach), 255
 * NaN (then TOMBuilder must throw std::invalid_argument).
 */
double PairDistance(const MeshInput& mesh)
{
  const uint8_t byte = TailByte(mesh, 6);
  return byte == 255 ? std::nan("") : byte / 64.0;
}

/**
 * Pair contraction only adds joins below the coarsest level without pairs:
 * every level above it is the build without pairs (same vertex at each
 * step, same triangle counts and errors), and nothing joins without pairs.
 */
void CheckPairsKeepFinerLevels(
  const TOMBuildResult& on, const MeshInput& mesh, const TOMBuildOptions& options)
{
  TOMBuildOptions offOptions = options;
  offOptions.PairContractionDistance = 0.0;
  offOptions.Progress = nullptr;
  const TOMBuildResult off = TOMBuilder(offOptions).Build(
    mesh.Points.data(), mesh.NumberOfPoints(), mesh.Triangles.data(), mesh.NumberOfTriangles());
  FUZZ_REQUIRE(off.JoinedParts == 0, "no part joins without pairs");
  const uint32_t n = off.Mesh.GetNumberOfVertices();
  FUZZ_REQUIRE(on.Mesh.GetNumberOfVertices() == n, "pairs keep every vertex");
  FUZZ_REQUIRE(on.Mesh.BaseVertexCount <= off.Mesh.BaseVertexCount, "pairs only go coarser");
  FUZZ_REQUIRE(on.JoinedParts > 0 || on.Mesh.BaseVertexCount == off.Mesh.BaseVertexCount,
    "the coarsest level moves only by joins");
  for (uint32_t i = off.Mesh.BaseVertexCount; i <= n; ++i)
  {
    FUZZ_REQUIRE(i == n || on.VertexOrder[i] == off.VertexOrder[i],
      "pairs keep the vertex order above the coarsest level without them");
    FUZZ_REQUIRE(on.TrianglesAtVertexCount[i] == off.TrianglesAtVertexCount[i] &&
        on.VertexCountError[i] == off.VertexCountError[i],
      "pairs keep the triangle counts and errors above the coarsest level without them");
  }
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
    TOMBuildOptions options = CollapseOptions(mesh, &calls, abortAfter);
    options.PairContractionDistance = PairDistance(mesh);
    const bool badDistance = std::isnan(options.PairContractionDistance);
    const TOMBuilder builder(options);
    try
    {
      const TOMBuildResult result = builder.Build(
        mesh.Points.data(), mesh.NumberOfPoints(), mesh.Triangles.data(), mesh.NumberOfTriangles());
      FUZZ_REQUIRE(!invalid, "TOMBuilder accepted out-of-range ids or bad coordinates");
      FUZZ_REQUIRE(!badDistance, "TOMBuilder accepted a NaN PairContractionDistance");
      if (result.Aborted)
      {
        FUZZ_REQUIRE(abortAfter > 0, "aborted by nobody");
        CheckAborted(result);
      }
      else
      {
        CheckBuildResult(result, mesh);
        if (options.PairContractionDistance > 0.0)
        {
          CheckPairsKeepFinerLevels(result, mesh, options);
        }
        else
        {
          FUZZ_REQUIRE(result.JoinedParts == 0, "no part joins without pairs");
        }
      }
    }
    catch (const std::invalid_argument& e)
    {
      FUZZ_REQUIRE(invalid || badDistance,
        std::string("TOMBuilder rejected a valid mesh: ") + e.what());
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
