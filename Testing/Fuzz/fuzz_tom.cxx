// SPDX-License-Identifier: BSD-3-Clause
// Fuzz target: the path of TOM data read from a file. Arbitrary TOM arrays
// (substitution, triangles, counts, error curve; format in FuzzFormat.h) go
// through TOMValidator; the ones it accepts are then traversed at arbitrary
// resolutions by TOMTraversal, whose answers are checked against a plain
// reference walk, and their error curve is queried.
#include "FuzzChecks.h"
#include "FuzzFormat.h"
#include "TOMErrorCurve.h"
#include "TOMMesh.h"
#include "TOMTraversal.h"
#include "TOMValidator.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

using namespace timecritical;
using namespace timecritical::fuzz;

namespace
{
/// Vertex counts worth asking for: mostly near the mesh's range, sometimes raw.
uint32_t PickVertexCount(const TOMMesh& mesh, uint32_t a, uint32_t b)
{
  return (b & 1) ? a : a % (mesh.GetNumberOfVertices() + 2);
}

void CheckExtractCapacity(
  const TOMMesh& mesh, const TOMTraversal& traversal, uint32_t vertexCount, uint32_t capacity)
{
  const uint32_t n = ClampVertexCount(mesh, vertexCount);
  const std::vector<uint32_t> reference = ReferenceExtract(mesh, n);
  // Exactly `capacity` triangles of room, so that AddressSanitizer sees any write past it.
  std::vector<uint32_t> room(3 * size_t(capacity));
  const uint32_t count = traversal.Extract(vertexCount, room.data(), capacity);
  const std::string where =
    "at " + std::to_string(vertexCount) + " vertices into " + std::to_string(capacity);
  FUZZ_REQUIRE(count == reference.size() / 3, "triangle count " + where);
  const size_t written = 3 * size_t(std::min(count, capacity));
  FUZZ_REQUIRE(std::equal(reference.begin(), reference.begin() + written, room.begin()),
    "triangles " + where);
}

/// Number of triangles of the mesh with n vertices (reference walk).
uint32_t CountAt(const TOMMesh& mesh, uint32_t n)
{
  return static_cast<uint32_t>(ReferenceExtract(mesh, ClampVertexCount(mesh, n)).size() / 3);
}

void CheckVertexCountForTriangles(
  const TOMMesh& mesh, const TOMTraversal& traversal, uint32_t triangles)
{
  const uint32_t v = traversal.GetVertexCountForTriangles(triangles);
  const uint32_t n = mesh.GetNumberOfVertices();
  const std::string where = "for " + std::to_string(triangles) + " triangles";
  FUZZ_REQUIRE(v >= mesh.BaseVertexCount && v <= n, "vertex count in range " + where);
  // The finest mesh within the count (the coarsest one may exceed it).
  FUZZ_REQUIRE(v == mesh.BaseVertexCount || CountAt(mesh, v) <= triangles,
    "within the count " + where);
  FUZZ_REQUIRE(v == n || CountAt(mesh, v + 1) > triangles, "the finest such mesh " + where);
}

void RunQuery(const TOMMesh& mesh, const TOMTraversal& traversal, const TOMQueryInput& q)
{
  const uint32_t n = mesh.GetNumberOfVertices();
  const uint32_t t = mesh.GetNumberOfTriangles();
  switch (q.Kind)
  {
    case TOMQuery::Extract:
      CheckExtract(mesh, traversal, PickVertexCount(mesh, q.A, q.B));
      break;
    case TOMQuery::ExtractCapacity:
      CheckExtractCapacity(mesh, traversal, PickVertexCount(mesh, q.A, q.B >> 1), q.B % (t + 2));
      break;
    case TOMQuery::Resolution:
    {
      const uint32_t triangles = traversal.GetTrianglesForResolution(q.X);
      FUZZ_REQUIRE(triangles <= t, "resolution gives at most all triangles");
      FUZZ_REQUIRE(q.X > 0.0 || triangles == 0, "NaN and r <= 0 give 0 triangles");
      FUZZ_REQUIRE(!(q.X >= 1.0) || triangles == t, "r >= 1 gives all triangles");
      CheckVertexCountForTriangles(mesh, traversal, triangles);
      CheckExtract(mesh, traversal, traversal.GetVertexCountForTriangles(triangles));
      break;
    }
    case TOMQuery::ActiveVertex:
    {
      const uint32_t v = (q.B & 1) ? q.A : q.A % (n + 1);
      const uint32_t vertexCount = q.B >> 1;
      const uint32_t w = traversal.GetActiveVertex(v, vertexCount);
      if (v >= n)
      {
        FUZZ_REQUIRE(w == v, "ids out of range map to themselves");
        break;
      }
      uint32_t expected = v;
      while (expected >= ClampVertexCount(mesh, vertexCount))
      {
        expected = mesh.Substitution[expected];
      }
      FUZZ_REQUIRE(w == expected, "active vertex of " + std::to_string(v));
      break;
    }
    case TOMQuery::Geomorph:
    {
      const int components = 1 + static_cast<int>(q.B % 4);
      std::vector<float> attributes(size_t(n) * components);
      for (size_t i = 0; i < attributes.size(); ++i)
      {
        attributes[i] = static_cast<float>((i * 2654435761u) % 1000) - 500.f;
      }
      std::vector<float> result(components, 1234.5f);
      traversal.Geomorph(PickVertexCount(mesh, q.A, q.B >> 2), q.X, attributes.data(), components,
        result.data());
      for (float x : result)
      {
        if (n == 0)
        {
          break; // nothing to morph: the result is left alone
        }
        FUZZ_REQUIRE(std::isfinite(x) && std::abs(x) <= 500.f, "geomorph between two vertices");
      }
      break;
    }
    case TOMQuery::ErrorCurve:
    {
      const double e = mesh.ErrorCurve.GetErrorForTriangles(q.A);
      FUZZ_REQUIRE(std::isfinite(e) && e >= 0.0, "error of a triangle count");
      const uint32_t triangles = mesh.ErrorCurve.GetTrianglesForError(q.X);
      FUZZ_REQUIRE(triangles <= t, "triangles for an error");
      const auto& samples = mesh.ErrorCurve.GetSamples();
      if (!samples.empty() && q.X >= 0.0)
      {
        FUZZ_REQUIRE(mesh.ErrorCurve.GetErrorForTriangles(triangles) <= q.X,
          "the count found meets the error");
        FUZZ_REQUIRE(triangles <= samples.front().Triangles ||
            mesh.ErrorCurve.GetErrorForTriangles(triangles - 1) > q.X,
          "the smallest count that meets the error");
      }
      break;
    }
    case TOMQuery::VertexForTriangles:
      CheckVertexCountForTriangles(mesh, traversal, (q.B & 1) ? q.A : q.A % (t + 2));
      break;
    case TOMQuery::Count:
      break;
  }
}
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  TOMInput input = DecodeTOM(data, size);
  TOMMesh mesh;
  mesh.Substitution = input.Substitution;
  mesh.Triangles = input.Triangles;
  mesh.BaseVertexCount = input.BaseVertexCount;
  mesh.BaseTriangleCount = input.BaseTriangleCount;
  std::vector<TOMErrorCurve::Sample> samples;
  for (size_t i = 0; i < input.SampleTriangles.size(); ++i)
  {
    samples.push_back({ input.SampleTriangles[i], input.SampleErrors[i] });
  }
  mesh.ErrorCurve = TOMErrorCurve(samples);

  // The raw-array form and the mesh form agree; the mesh form adds the curve.
  const std::string raw = TOMValidator::Check(input.Substitution.data(),
    input.Substitution.size(), input.Triangles.data(), input.Triangles.size() / 3,
    input.BaseVertexCount, input.BaseTriangleCount);
  const std::string problem = TOMValidator::Check(mesh);
  if (!raw.empty())
  {
    FUZZ_REQUIRE(problem == raw, "both forms report the array problem");
    return 0;
  }
  FUZZ_REQUIRE(problem.empty() == mesh.ErrorCurve.Check(mesh.GetNumberOfTriangles()).empty(),
    "the mesh form adds only the error curve's check");
  if (!problem.empty())
  {
    return 0;
  }

  const TOMTraversal traversal(mesh);
  FUZZ_REQUIRE(traversal.GetNumberOfVertices() == mesh.GetNumberOfVertices() &&
      traversal.GetNumberOfTriangles() == mesh.GetNumberOfTriangles(),
    "traversal sizes");
  // The coarsest and the full mesh always, then the input's queries.
  CheckExtract(mesh, traversal, 0);
  CheckExtract(mesh, traversal, mesh.GetNumberOfVertices());
  const size_t queries = std::min<size_t>(input.Queries.size(), 32);
  for (size_t i = 0; i < queries; ++i)
  {
    RunQuery(mesh, traversal, input.Queries[i]);
  }
  return 0;
}
