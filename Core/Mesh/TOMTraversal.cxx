// SPDX-License-Identifier: BSD-3-Clause
#include "TOMTraversal.h"

#include "TOMMesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace timecritical
{
namespace
{
/// Minimum vertex count of a triangle that is never alive (degenerate at full
/// resolution, out of range or with a corrupted chain; validated TOMs have none).
constexpr uint32_t NeverAlive = std::numeric_limits<uint32_t>::max();

/// Chain steps of triangles [begin, end), one corner at a time (cold path).
uint64_t CountSteps(const uint32_t* sub, const uint32_t* tri, uint32_t begin, uint32_t end,
  uint32_t n)
{
  uint64_t steps = 0;
  for (size_t j = 3 * static_cast<size_t>(begin); j < 3 * static_cast<size_t>(end); ++j)
  {
    for (uint32_t v = tri[j]; v >= n; v = sub[v])
    {
      ++steps;
    }
  }
  return steps;
}

/**
 * The hot loop. Maps the corners of the triangle prefix down their chains to
 * the active vertices [0, n) and stops at the first collapsed triangle; the
 * sorted triangle order guarantees all later ones are collapsed too. Triangles
 * beyond `capacity` are only counted. Chain steps are summed over the alive
 * triangles only, so the figure does not depend on where the walk stops.
 *
 * Chain lengths vary from corner to corner (0 to ~10 at coarse resolutions),
 * so a `while (v >= n)` loop per corner mispredicts its exit almost every
 * time. Instead a batch of triangles is copied out and its corners that still
 * need a step are kept in a compacted list; each round advances every listed
 * corner by one step and rebuilds the list without branches. Work is thus
 * proportional to the steps actually taken, the loads of a round are
 * independent, and only the end of each round mispredicts. At full resolution
 * the list stays empty.
 *
 * Requires n >= 1 and valid chains (sub[v] < v for v >= n), which holds for
 * any n >= BaseVertexCount of a validated TOM.
 */
uint32_t WalkPrefix(const uint32_t* sub, const uint32_t* tri, uint32_t numberOfTriangles,
  uint32_t n, uint32_t* out, uint32_t capacity, uint64_t* steps)
{
  // Large enough that the rounds (as many as the longest chain of the batch)
  // amortize their one mispredicted exit; 12 KiB of stack.
  constexpr uint32_t Batch = 512;
  uint32_t local[3 * Batch];
  uint32_t pending[3 * Batch];
  uint64_t total = 0;
  uint32_t count = 0;
  for (uint32_t t = 0; t < numberOfTriangles; t += count) // t + count <= M never wraps
  {
    count = std::min(Batch, numberOfTriangles - t);
    const uint32_t corners = 3 * count;
    const uint32_t* ids = tri + 3 * static_cast<size_t>(t);
    // Work in place in the output when the whole batch fits; slots past the
    // returned count may then hold scratch values, which the API allows.
    const bool inPlace = capacity >= count && t <= capacity - count;
    uint32_t* v = inPlace ? out + 3 * static_cast<size_t>(t) : local;

    // Copy, then list the corners that need a step (none at full resolution).
    std::copy(ids, ids + corners, v);
    uint32_t k = 0;
    for (uint32_t j = 0; j < corners; ++j)
    {
      pending[k] = j;
      k += v[j] >= n;
    }
    uint64_t batchSteps = 0;
    while (k > 0)
    {
      batchSteps += k; // one step per listed corner
      uint32_t next = 0;
      for (uint32_t i = 0; i < k; ++i)
      {
        const uint32_t j = pending[i];
        const uint32_t x = sub[v[j]];
        v[j] = x;
        pending[next] = j;
        next += x >= n;
      }
      k = next;
    }

    uint32_t alive = 0;
    for (; alive < count; ++alive)
    {
      const uint32_t a = v[3 * alive], b = v[3 * alive + 1], c = v[3 * alive + 2];
      if (a == b || b == c || a == c)
      {
        break;
      }
    }
    if (!inPlace && t < capacity)
    {
      std::copy(v, v + 3 * std::min(alive, capacity - t), out + 3 * static_cast<size_t>(t));
    }
    if (alive < count)
    {
      if (steps)
      {
        // The last batch counted only up to its first collapsed triangle;
        // at most one batch per call, so a plain walk is fine.
        *steps = total + CountSteps(sub, tri, t, t + alive, n);
      }
      return t + alive;
    }
    total += batchSteps;
  }
  if (steps)
  {
    *steps = total;
  }
  return numberOfTriangles;
}
}

//------------------------------------------------------------------------------
TOMTraversal::TOMTraversal(const TOMMesh& mesh)
  : TOMTraversal(mesh.Substitution.data(), mesh.GetNumberOfVertices(), mesh.Triangles.data(),
      mesh.GetNumberOfTriangles(), mesh.BaseVertexCount)
{
}

//------------------------------------------------------------------------------
TOMTraversal::TOMTraversal(const uint32_t* substitution, uint32_t numberOfVertices,
  const uint32_t* triangles, uint32_t numberOfTriangles, uint32_t baseVertexCount)
  : Substitution(substitution)
  , Triangles(triangles)
  , NumberOfVertices(numberOfVertices)
  , NumberOfTriangles(numberOfTriangles)
  , BaseVertexCount(std::min(baseVertexCount, numberOfVertices))
{
}

//------------------------------------------------------------------------------
uint32_t TOMTraversal::ClampVertexCount(uint32_t vertexCount) const
{
  // Below the base nothing more can be removed; above N nothing more is added.
  return std::min(std::max(vertexCount, this->BaseVertexCount), this->NumberOfVertices);
}

//------------------------------------------------------------------------------
uint32_t TOMTraversal::GetMinimumVertexCount(uint32_t t) const
{
  if (t >= this->NumberOfTriangles)
  {
    return NeverAlive;
  }
  const uint32_t* tri = this->Triangles + 3 * static_cast<size_t>(t);
  uint32_t a = tri[0];
  uint32_t b = tri[1];
  uint32_t c = tri[2];
  if (a == b || b == c || a == c)
  {
    return NeverAlive;
  }
  // Replay the removals that touch this triangle: vertices leave in decreasing
  // id order, so the next one to go is always the largest corner. The triangle
  // dies when that corner's substitute is one of the other two.
  for (;;)
  {
    if (b > a)
    {
      std::swap(a, b);
    }
    if (c > a)
    {
      std::swap(a, c);
    }
    if (a < this->BaseVertexCount)
    {
      return 0;
    }
    if (a >= this->NumberOfVertices)
    {
      return NeverAlive;
    }
    const uint32_t s = this->Substitution[a];
    if (s >= a)
    {
      return NeverAlive; // corrupted chain; guarded so this never loops
    }
    if (s == b || s == c)
    {
      return a + 1;
    }
    a = s;
  }
}

//------------------------------------------------------------------------------
uint32_t TOMTraversal::GetVertexCountForTriangles(uint32_t triangles) const
{
  if (triangles >= this->NumberOfTriangles)
  {
    return this->NumberOfVertices;
  }
  // Triangle number `triangles` (0-based) must be dead and, by the prefix
  // order, then so are all after it: the finest such mesh is the one just
  // before it appears.
  const uint32_t minimum = this->GetMinimumVertexCount(triangles);
  if (minimum == NeverAlive)
  {
    return this->NumberOfVertices;
  }
  if (minimum == 0)
  {
    return this->BaseVertexCount;
  }
  return std::max(minimum - 1, this->BaseVertexCount);
}

//------------------------------------------------------------------------------
uint32_t TOMTraversal::GetTrianglesForResolution(double r) const
{
  // NaN and r <= 0 give the coarsest request: a broken resolution must never
  // blow a frame budget.
  if (!(r > 0.0))
  {
    return 0;
  }
  if (r >= 1.0)
  {
    return this->NumberOfTriangles;
  }
  const double count = std::round(r * static_cast<double>(this->NumberOfTriangles));
  return static_cast<uint32_t>(std::min(count, static_cast<double>(this->NumberOfTriangles)));
}

//------------------------------------------------------------------------------
uint32_t TOMTraversal::CountTriangles(uint32_t vertexCount) const
{
  // First triangle whose minimum vertex count exceeds vertexCount, by binary
  // search over the sorted minimum counts (a few chain walks, no full pass).
  uint32_t lo = 0;
  uint32_t hi = this->NumberOfTriangles;
  while (lo < hi)
  {
    const uint32_t mid = lo + (hi - lo) / 2;
    if (this->GetMinimumVertexCount(mid) <= vertexCount)
    {
      lo = mid + 1;
    }
    else
    {
      hi = mid;
    }
  }
  return lo;
}

//------------------------------------------------------------------------------
uint32_t TOMTraversal::Extract(
  uint32_t vertexCount, uint32_t* out, uint32_t capacity, uint64_t* chainSteps) const
{
  const uint32_t n = this->ClampVertexCount(vertexCount);
  if (chainSteps)
  {
    *chainSteps = 0;
  }
  if (n == 0 || this->NumberOfTriangles == 0)
  {
    return 0;
  }
  return WalkPrefix(this->Substitution, this->Triangles, this->NumberOfTriangles, n, out,
    out ? capacity : 0, chainSteps);
}

//------------------------------------------------------------------------------
uint32_t TOMTraversal::Extract(
  uint32_t vertexCount, std::vector<uint32_t>& out, uint64_t* chainSteps) const
{
  const uint32_t n = this->ClampVertexCount(vertexCount);
  const size_t needed = 3 * static_cast<size_t>(this->CountTriangles(n));
  if (out.size() < needed)
  {
    out.resize(needed);
  }
  for (;;)
  {
    const uint32_t capacity = static_cast<uint32_t>(
      std::min<size_t>(out.size() / 3, std::numeric_limits<uint32_t>::max()));
    const uint32_t count = this->Extract(n, out.data(), capacity, chainSteps);
    if (count <= capacity)
    {
      return count;
    }
    // Only reached when the triangle order is not sorted (unvalidated data).
    out.resize(3 * static_cast<size_t>(count));
  }
}

//------------------------------------------------------------------------------
uint32_t TOMTraversal::GetActiveVertex(uint32_t v, uint32_t vertexCount) const
{
  if (v >= this->NumberOfVertices)
  {
    return v; // no chain to follow
  }
  const uint32_t n = this->ClampVertexCount(vertexCount);
  while (v >= n)
  {
    const uint32_t s = this->Substitution[v];
    if (s >= v)
    {
      break; // corrupted chain; guarded so this never loops
    }
    v = s;
  }
  return v;
}

//------------------------------------------------------------------------------
void TOMTraversal::Geomorph(uint32_t vertexCount, double factor, const float* attributes,
  int components, float* result) const
{
  if (this->NumberOfVertices == 0 || !attributes || !result || components <= 0)
  {
    return;
  }
  const uint32_t n = std::min(std::max(vertexCount, 1u), this->NumberOfVertices);
  const uint32_t v = n - 1;
  // sub[v] < v is already active with v vertices, so no chain walk is needed;
  // a base vertex is its own target and does not move.
  uint32_t target = v;
  if (v >= this->BaseVertexCount && this->Substitution[v] < v)
  {
    target = this->Substitution[v];
  }
  // NaN shows the true vertex; the (1-f)*a + f*b form is exact at both ends.
  const double f = std::isnan(factor) ? 1.0 : std::min(std::max(factor, 0.0), 1.0);
  const float* from = attributes + static_cast<size_t>(target) * components;
  const float* to = attributes + static_cast<size_t>(v) * components;
  for (int i = 0; i < components; ++i)
  {
    result[i] = static_cast<float>((1.0 - f) * from[i] + f * to[i]);
  }
}
}
