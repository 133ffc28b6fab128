// SPDX-License-Identifier: BSD-3-Clause
// The run of the collapse engine: its frame, relaxation levels and output.
#include "CollapseEngine.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace timecritical
{
namespace collapse
{
//------------------------------------------------------------------------------
void CollapseEngine::StartLevel(int level)
{
  this->CurrentLevel = level;
  if (level == LevelNoConstraints)
  {
    // Kinds no longer restrict anything: every live vertex gets new candidates.
    for (uint32_t v = 0; v < this->N; ++v)
    {
      if (!this->IsRemoved(v))
      {
        this->Reevaluate(v);
      }
    }
  }
  else
  {
    for (uint32_t v : this->BlockedList)
    {
      if (!this->IsRemoved(v) && (this->Vertices[v].State & BlockedBit))
      {
        this->Reevaluate(v);
      }
    }
  }
  this->BlockedList.clear();
}

//------------------------------------------------------------------------------
void CollapseEngine::BeginCollapses()
{
  this->SubstituteOf.assign(this->N, Invalid);
  this->RemovedOrder.reserve(this->N);
  this->StepError.reserve(this->N);
  this->KillStart.reserve(this->N);
  this->KillList.reserve(this->T);
  this->Ring.reserve(64);
  this->Soon.reserve(64);
  this->Scratch.reserve(64);

  const double maxDeviation = this->Options.MaximumNormalDeviation;
  this->NormalCheckEnabled = maxDeviation < 180.0;
  this->CosMaxDeviation = std::cos(std::min(std::max(maxDeviation, 0.0), 180.0) * Pi / 180.0);
  this->SliverCheckEnabled = this->Options.MinimumTriangleQuality > 0.0;
  this->CurrentLevel = this->SliverCheckEnabled ? LevelAll : LevelNoSliver;
}

//------------------------------------------------------------------------------
bool CollapseEngine::Relax()
{
  if (this->CurrentLevel + 1 >= LevelEnd)
  {
    if (!this->RetrySkipped)
    {
      return false;
    }
    // Retries skipped around hubs: once more at this level. Each pass
    // re-evaluates only the vertices blocked since the last one.
    this->RetrySkipped = false;
    this->StartLevel(this->CurrentLevel);
    return true;
  }
  this->RetrySkipped = false;
  this->StartLevel(this->CurrentLevel + 1);
  return true;
}

//------------------------------------------------------------------------------
void CollapseEngine::BuildOutput(TOMBuildResult& result)
{
  const uint32_t n = this->N;
  const uint32_t removed = static_cast<uint32_t>(this->RemovedOrder.size());
  const uint32_t base = n - removed;

  // New ids: survivors first in input order, then removed vertices, the first
  // removed getting the last id.
  BigVector<uint32_t> newId(n, Invalid);
  uint32_t next = 0;
  for (size_t i = 0; i < this->InternalIdOf.size(); ++i)
  {
    const uint32_t v = this->InternalIdOf[i];
    if (v != Invalid && !this->IsRemoved(v))
    {
      newId[v] = next++; // survivors in input order
    }
  }
  for (uint32_t step = 0; step < removed; ++step)
  {
    newId[this->RemovedOrder[step]] = n - 1 - step;
  }

  TOMMesh& mesh = result.Mesh;
  mesh.BaseVertexCount = base;
  ReserveHuge(mesh.Substitution, n);
  ReserveHuge(result.VertexOrder, n);
  mesh.Substitution.resize(n);
  result.VertexOrder.resize(n);
  for (uint32_t v = 0; v < n; ++v)
  {
    const uint32_t id = newId[v];
    result.VertexOrder[id] = this->InputIdOf[v];
    mesh.Substitution[id] = this->IsRemoved(v) ? newId[this->SubstituteOf[v]] : id;
  }

  // Triangles: the base ones in input order, then the others by decreasing
  // death step (the last collapse's victims are alive from the fewest
  // vertices), in input order within a step. The rank of every triangle is
  // computed first so that the output is then written in one pass over the
  // input, in input order (reading the input in death order would jump
  // around memory).
  BigVector<uint32_t> rank(this->T);
  uint32_t written = 0;
  for (uint32_t t = 0; t < this->T; ++t)
  {
    if (!(this->Tris[t].Flags & DeadFlag))
    {
      rank[t] = written++;
    }
  }
  const uint32_t baseTriangles = written;
  ReserveHuge(result.TrianglesAtVertexCount, n + 1);
  result.TrianglesAtVertexCount.assign(n + 1, 0);
  uint32_t* alive = result.TrianglesAtVertexCount.data();
  alive[0] = baseTriangles; // turned into a running sum below
  for (uint32_t step = removed; step-- > 0;)
  {
    uint32_t* begin = this->KillList.data() + this->KillStart[step];
    uint32_t* end = step + 1 < removed ? this->KillList.data() + this->KillStart[step + 1]
                                       : this->KillList.data() + this->KillList.size();
    // Usually two triangles: an insertion sort.
    for (uint32_t* i = begin + 1; i < end; ++i)
    {
      for (uint32_t* k = i; k > begin && k[0] < k[-1]; --k)
      {
        std::swap(k[0], k[-1]);
      }
    }
    for (const uint32_t* i = begin; i < end; ++i)
    {
      rank[*i] = written++;
    }
    alive[n - step] += static_cast<uint32_t>(end - begin); // removing vertex n-1-step kills them
  }
  for (uint32_t i = 1; i <= n; ++i)
  {
    alive[i] += alive[i - 1];
  }

  mesh.BaseTriangleCount = baseTriangles;
  ReserveHuge(mesh.Triangles, 3 * static_cast<size_t>(this->T));
  ReserveHuge(result.TriangleOrder, this->T);
  mesh.Triangles.resize(3 * static_cast<size_t>(this->T));
  result.TriangleOrder.resize(this->T);
  uint32_t* out = mesh.Triangles.data();
  for (uint32_t t = 0; t < this->T; ++t)
  {
    // Original connectivity: the internal triangles were rewritten by the collapses.
    const uint32_t input = this->InputTriOf[t];
    const uint32_t r = rank[t];
    result.TriangleOrder[r] = input;
    const uint32_t* c = this->InputTriangles + 3 * static_cast<size_t>(input);
    uint32_t* o = out + 3 * static_cast<size_t>(r);
    o[0] = newId[this->InternalIdOf[c[0]]];
    o[1] = newId[this->InternalIdOf[c[1]]];
    o[2] = newId[this->InternalIdOf[c[2]]];
  }

  // Vertex count i < n is reached after n - i steps; below the base the base
  // error repeats.
  ReserveHuge(result.VertexCountError, n + 1);
  result.VertexCountError.assign(n + 1, 0.f);
  const float baseError = removed > 0 ? this->StepError[removed - 1] : 0.f;
  for (uint32_t i = 0; i < n; ++i)
  {
    result.VertexCountError[i] = i < base ? baseError : this->StepError[n - i - 1];
  }

  // The curve's 8 bytes per sample must stay small next to the one index per
  // vertex of the TOM itself: at most one sample per 256 vertices (at least 8).
  const unsigned curveSamples = std::min<unsigned>(
    this->Options.ErrorCurveSamples, std::max<unsigned>(8u, static_cast<unsigned>(n / 256)));
  mesh.ErrorCurve = TOMErrorCurve::FromVertexErrors(result.VertexCountError.data(),
    result.TrianglesAtVertexCount.data(), n, base, curveSamples);
}

//------------------------------------------------------------------------------
TOMBuildResult CollapseEngine::Run(const double* points, size_t numberOfPoints,
  const uint32_t* triangles, size_t numberOfTriangles, const std::function<bool()>& schedule)
{
  TOMBuildResult result;
  this->ReadInput(points, numberOfPoints, triangles, numberOfTriangles, result);
  auto aborted = [&result]() {
    TOMBuildResult r;
    r.DroppedDegenerateTriangles = result.DroppedDegenerateTriangles;
    r.DroppedDuplicateTriangles = result.DroppedDuplicateTriangles;
    r.UnusedPoints = result.UnusedPoints;
    r.Aborted = true;
    return r;
  };
  if (!this->Progress.Report(0.0))
  {
    return aborted();
  }
  if (this->N == 0)
  {
    // Nothing to simplify: an empty TOM (callers report it).
    result.VertexCountError.assign(1, 0.f);
    result.TrianglesAtVertexCount.assign(1, 0u);
    return this->Progress.Report(1.0) ? result : aborted();
  }
  this->BuildAdjacency();
  this->BuildFaceQuadrics();
  if (!this->ClassifyVertices())
  {
    this->DropDuplicateTriangles(result);
    this->BuildAdjacency();
    this->BuildFaceQuadrics();
    this->ClassifyVertices(); // no duplicate is left
  }

  this->BeginCollapses();
  if (!this->Progress.Report(0.05) || !schedule())
  {
    return aborted();
  }
  this->BuildOutput(result);
  result.FanTrianglesVisited = this->Visited;
  result.JoinedParts = this->JoinedParts;
  if (!this->Progress.Report(1.0))
  {
    return aborted();
  }
  return result;
}
}
}
