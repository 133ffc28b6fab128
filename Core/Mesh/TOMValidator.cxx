// SPDX-License-Identifier: BSD-3-Clause
#include "TOMValidator.h"

#include "TOMMesh.h"
#include "TOMTraversal.h"

#include <limits>
#include <sstream>

namespace timecritical
{
namespace
{
constexpr uint64_t MaxCount = std::numeric_limits<uint32_t>::max();

template <typename... Args>
std::string Message(const Args&... args)
{
  std::ostringstream stream;
  (stream << ... << args);
  return stream.str();
}
}

//------------------------------------------------------------------------------
std::string TOMValidator::Check(const TOMMesh& mesh)
{
  // Sizes come from the vectors themselves (as 64-bit values) so that a
  // truncating uint32_t cast can never hide an oversized array.
  const uint64_t numberOfVertices = mesh.Substitution.size();
  const uint64_t numberOfIds = mesh.Triangles.size();
  if (numberOfIds % 3 != 0)
  {
    return Message("triangle array size ", numberOfIds, " is not a multiple of 3");
  }
  std::string problem = TOMValidator::Check(mesh.Substitution.data(), numberOfVertices,
    mesh.Triangles.data(), numberOfIds / 3, mesh.BaseVertexCount, mesh.BaseTriangleCount);
  if (!problem.empty())
  {
    return problem;
  }
  problem = mesh.ErrorCurve.Check(static_cast<uint32_t>(numberOfIds / 3));
  if (!problem.empty())
  {
    return "error curve: " + problem;
  }
  return {};
}

//------------------------------------------------------------------------------
std::string TOMValidator::Check(const uint32_t* substitution, uint64_t numberOfVertices,
  const uint32_t* triangles, uint64_t numberOfTriangles, uint64_t baseVertexCount,
  uint64_t baseTriangleCount)
{
  // Counts first: everything below indexes the arrays with them. (Counts that
  // fit but exceed the real arrays cannot be detected on raw pointers.)
  if (numberOfVertices > MaxCount)
  {
    return Message("number of vertices ", numberOfVertices, " does not fit in 32 bits");
  }
  if (numberOfTriangles > MaxCount)
  {
    return Message("number of triangles ", numberOfTriangles, " does not fit in 32 bits");
  }
  if (baseVertexCount > numberOfVertices)
  {
    return Message(
      "base vertex count ", baseVertexCount, " exceeds the number of vertices ", numberOfVertices);
  }
  if (baseTriangleCount > numberOfTriangles)
  {
    return Message("base triangle count ", baseTriangleCount,
      " exceeds the number of triangles ", numberOfTriangles);
  }
  if (!substitution && numberOfVertices > 0)
  {
    return Message("substitution array is null but the number of vertices is ", numberOfVertices);
  }
  if (!triangles && numberOfTriangles > 0)
  {
    return Message("triangle array is null but the number of triangles is ", numberOfTriangles);
  }
  if (numberOfVertices > 0 && baseVertexCount == 0)
  {
    // Vertex 0 would have to substitute to a lower id, which does not exist.
    return Message("base vertex count is 0 but there are ", numberOfVertices,
      " vertices: at least one vertex must remain");
  }

  // Substitutions: base vertices are fixed points, every other one points
  // strictly lower, which makes every chain finite (no cycle can close).
  for (uint64_t i = 0; i < numberOfVertices; ++i)
  {
    const uint32_t s = substitution[i];
    if (i < baseVertexCount)
    {
      if (s != i)
      {
        return Message("base vertex ", i, " substitutes to ", s,
          " (substitution[", i, "] must be ", i, " below the base vertex count ", baseVertexCount,
          ")");
      }
    }
    else if (s >= i)
    {
      return Message("substitution[", i, "] = ", s, " is not below ", i,
        ": removed vertices must substitute to a lower id (acyclic chains)");
    }
  }

  for (uint64_t t = 0; t < numberOfTriangles; ++t)
  {
    const uint32_t* tri = triangles + 3 * t;
    for (int c = 0; c < 3; ++c)
    {
      if (tri[c] >= numberOfVertices)
      {
        return Message("triangle ", t, " corner ", c, " has vertex id ", tri[c],
          " out of range (number of vertices ", numberOfVertices, ")");
      }
    }
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
    {
      return Message("triangle ", t, " (", tri[0], ", ", tri[1], ", ", tri[2],
        ") is degenerate at full resolution (repeated vertex id)");
    }
  }

  // The arrays are now safe to traverse; minimum vertex counts cost one
  // replay per triangle, O(total chain length).
  const TOMTraversal traversal(substitution, static_cast<uint32_t>(numberOfVertices), triangles,
    static_cast<uint32_t>(numberOfTriangles), static_cast<uint32_t>(baseVertexCount));
  uint32_t previous = 0;
  uint64_t alive = 0;
  for (uint64_t t = 0; t < numberOfTriangles; ++t)
  {
    const uint32_t minimum = traversal.GetMinimumVertexCount(static_cast<uint32_t>(t));
    if (minimum < previous)
    {
      return Message("triangles out of prefix order: triangle ", t, " is alive from ", minimum,
        " vertices but triangle ", t - 1, " only from ", previous);
    }
    previous = minimum;
    if (minimum <= baseVertexCount)
    {
      ++alive;
    }
  }
  if (alive != baseTriangleCount)
  {
    return Message("base triangle count ", baseTriangleCount, " differs from the ", alive,
      " triangles alive at the base vertex count ", baseVertexCount);
  }
  return {};
}
}
