// SPDX-License-Identifier: BSD-3-Clause
// The classification of the vertices of the collapse engine (kinds,
// constraint edges) and their first candidates.
#include "CollapseEngine.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace timecritical
{
namespace collapse
{
//------------------------------------------------------------------------------
bool CollapseEngine::SharpTurn(uint32_t v, uint32_t a, uint32_t b) const
{
  // The curve a -> v -> b turns by more than the feature angle: v is a corner
  // of the boundary or feature line (a corner of a square hole, a kink of a
  // crease) and stays, like the ends and junctions of such lines.
  const Vec3& p = this->Vertices[v].P;
  const Vec3 da = Sub(this->Vertices[a].P, p);
  const Vec3 db = Sub(this->Vertices[b].P, p);
  const double c = std::cos(this->Options.FeatureAngle * Pi / 180.0);
  return Dot(da, db) > -c * std::sqrt(Dot(da, da) * Dot(db, db));
}

//------------------------------------------------------------------------------
bool CollapseEngine::ClassifyClosedFan(uint32_t v, float cosFeature)
{
  // Fast path for the common case, a small closed fan with consistent
  // orientation: the triangle after triangle i around v is the one whose
  // previous corner is i's next corner. Anything else goes the general way.
  constexpr uint32_t maxFan = 16;
  const Vertex& rec = this->Vertices[v];
  const uint32_t count = rec.AdjCount;
  if (count < 3 || count > maxFan)
  {
    return false;
  }
  const uint32_t* list = this->Pool.data() + rec.AdjStart;
  uint32_t next[maxFan], prev[maxFan], corner[maxFan], twin[maxFan];
  for (uint32_t i = 0; i < count; ++i)
  {
    const Tri& tri = this->Tris[list[i] >> 2];
    const uint32_t j = list[i] & 3u;
    corner[i] = j;
    next[i] = tri.V[Next3(j)];
    prev[i] = tri.V[Prev3(j)];
  }
  // Walk around v, from each triangle to the first one whose previous corner
  // is its next corner. Coming back to the start after visiting every
  // triangle makes that map a single cycle, hence one by one: each edge has
  // exactly one triangle on each side, consistently oriented, in one piece.
  uint32_t c = 0;
  for (uint32_t steps = 0; steps < count; ++steps)
  {
    uint32_t l = 0;
    while (l < count && prev[l] != next[c])
    {
      ++l;
    }
    if (l == count || (l == 0) != (steps + 1 == count))
    {
      return false;
    }
    twin[c] = l;
    c = l;
  }

  const TOMBuildOptions& o = this->Options;
  uint32_t constrained = 0;
  uint32_t ends[2] = { Invalid, Invalid };
  for (uint32_t i = 0; i < count; ++i)
  {
    // Edge (v, next[i]) between triangle i (its edge corner[i]) and twin[i].
    const uint32_t t0 = list[i] >> 2, t1 = list[twin[i]] >> 2;
    const uint32_t e0 = corner[i], e1 = Prev3(corner[twin[i]]);
    if (next[i] > v && o.PreserveFeatureEdges)
    {
      const float* a = this->Normals.data() + 3 * static_cast<size_t>(t0);
      const float* b = this->Normals.data() + 3 * static_cast<size_t>(t1);
      const float d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
      const bool degenerate =
        (a[0] == 0.f && a[1] == 0.f && a[2] == 0.f) || (b[0] == 0.f && b[1] == 0.f && b[2] == 0.f);
      if (!degenerate && d < cosFeature)
      {
        const double w = o.LockFeatureEdges ? o.ConstraintWeight : o.FeatureWeight;
        this->AddConstraintPlane(v, next[i], Vec3{ a[0], a[1], a[2] }, w);
        this->AddConstraintPlane(v, next[i], Vec3{ b[0], b[1], b[2] }, w);
        if (o.LockFeatureEdges)
        {
          this->Tris[t0].Flags |= 1u << e0;
          this->Tris[t1].Flags |= 1u << e1;
        }
      }
    }
    if (((this->Tris[t0].Flags >> e0) | (this->Tris[t1].Flags >> e1)) & 1u)
    {
      ends[constrained++ & 1u] = next[i];
    }
  }
  this->Vertices[v].Kind = constrained == 0
    ? KindClosed
    : (constrained == 2 && !this->SharpTurn(v, ends[0], ends[1]) ? KindCurve : KindFixed);
  return true;
}

//------------------------------------------------------------------------------
inline Vec3 CollapseEngine::NormalOf(uint32_t t) const
{
  const float* n = this->Normals.data() + 3 * static_cast<size_t>(t);
  return Vec3{ n[0], n[1], n[2] };
}

//------------------------------------------------------------------------------
inline void CollapseEngine::ClassifyFanEdge(
  uint32_t v, const FanGroups& fan, const FanGroups::Group& group, const EdgeRules& rules)
{
  // Edge (v, group.X), classified once, from its lower end; the flags it
  // sets are seen by the higher end later.
  const TOMBuildOptions& o = this->Options;
  const uint32_t x = group.X;
  const uint32_t n = group.Next + group.Prev;
  bool constraint = false;
  const FanGroups::Spoke& s0 = fan.FirstSpoke(group);
  if (n == 1)
  {
    this->AddConstraintPlane(v, x, this->NormalOf(s0.Tri), rules.BoundaryWeight);
    constraint = o.PreserveBoundaries;
  }
  else if (n == 2 && group.Next == 1)
  {
    // Manifold, consistently oriented edge: a feature if the dihedral is sharp.
    uint32_t t1 = s0.Tri;
    fan.ForEachSpoke(group, [&](const FanGroups::Spoke& s) {
      if (s.Tri != s0.Tri)
      {
        t1 = s.Tri;
      }
    });
    const Vec3 n0 = this->NormalOf(s0.Tri);
    const Vec3 n1 = this->NormalOf(t1);
    if (o.PreserveFeatureEdges && Dot(n0, n0) > 0.0 && Dot(n1, n1) > 0.0 &&
      Dot(n0, n1) < rules.CosFeature)
    {
      const double w = o.LockFeatureEdges ? o.ConstraintWeight : o.FeatureWeight;
      this->AddConstraintPlane(v, x, n0, w);
      this->AddConstraintPlane(v, x, n1, w);
      constraint = o.LockFeatureEdges;
    }
  }
  else
  {
    // Non-manifold edge or orientation seam: kept until constraints are released.
    constraint = true;
  }
  if (constraint)
  {
    fan.ForEachSpoke(
      group, [this](const FanGroups::Spoke& s) { this->Tris[s.Tri].Flags |= 1u << s.Edge; });
  }
}

//------------------------------------------------------------------------------
bool CollapseEngine::ClassifyGeneralFan(uint32_t v, FanGroups& fan, const EdgeRules& rules)
{
  // Any fan: open, large, irregular or non-manifold. False when two of its
  // triangles have the same three points (see ClassifyVertices).
  Vertex& rec = this->Vertices[v];
  fan.Build(this->Pool.data() + rec.AdjStart, rec.AdjCount, this->Tris.data());
  if (fan.HasDuplicateTriangle())
  {
    return false;
  }
  bool closed = true;
  uint32_t constrained = 0;
  uint32_t ends[2] = { Invalid, Invalid };
  for (const FanGroups::Group& group : fan.GetGroups())
  {
    if (group.Next != 1 || group.Prev != 1)
    {
      closed = false;
    }
    if (group.X > v)
    {
      this->ClassifyFanEdge(v, fan, group, rules);
    }
    bool flagged = false;
    fan.ForEachSpoke(group, [&](const FanGroups::Spoke& s) {
      flagged |= ((this->Tris[s.Tri].Flags >> s.Edge) & 1u) != 0;
    });
    if (flagged)
    {
      ends[constrained++ & 1u] = group.X;
    }
  }
  const uint32_t pieces = fan.CountPieces();

  uint8_t kind = KindFree;
  if (pieces > 1)
  {
    kind = KindFixed; // pinch vertex: several fans meet here
  }
  else if (constrained == 2 && !this->SharpTurn(v, ends[0], ends[1]))
  {
    kind = KindCurve;
  }
  else if (constrained > 0)
  {
    kind = KindFixed; // end, junction or sharp corner of constraint curves
  }
  else if (closed)
  {
    kind = KindClosed;
  }
  rec.Kind = kind;
  return true;
}

//------------------------------------------------------------------------------
bool CollapseEngine::ClassifyVertices()
{
  if (this->UseHeap)
  {
    this->Heap.Reset(this->N);
  }
  this->Constraints.reserve(this->N / 16 + 16); // boundaries and creases: a minority, usually
  const TOMBuildOptions& o = this->Options;
  EdgeRules rules;
  rules.CosFeature = static_cast<float>(std::cos(o.FeatureAngle * Pi / 180.0));
  rules.BoundaryWeight = o.PreserveBoundaries ? o.ConstraintWeight : 1.0;
  FanGroups fan;
  for (uint32_t v = 0; v < this->N; ++v)
  {
    // Duplicate triangles (the same three points) share an edge and its
    // third corner. None touches a vertex of the fast path (its walk around
    // the fan needs distinct neighbours), so every one is met by the general
    // path: the setup starts again without them (Run).
    if (!this->ClassifyClosedFan(v, rules.CosFeature) &&
      !this->ClassifyGeneralFan(v, fan, rules))
    {
      return false;
    }
    this->SeedCandidate(v);
  }
  if (this->UseHeap)
  {
    this->Heap.Heapify();
  }
  this->Normals = BigVector<float>(); // no longer needed
  return true;
}

//------------------------------------------------------------------------------
void CollapseEngine::SeedCandidate(uint32_t v)
{
  // Called by the classification as soon as v's kind, constraint edges and
  // quadric are final (edges are classified from their lower end), while
  // its fan is still in cache.
  if (this->Parked(v))
  {
    this->Park(v);
    return;
  }
  Candidate best;
  if (this->BestTarget(v, best, false))
  {
    this->Vertices[v].Target = best.Target;
    this->Vertices[v].Key = KeyOf(best.Cost);
    if (this->UseHeap)
    {
      this->Heap.PushUnordered(v, this->Vertices[v].Key);
    }
  }
}

}
}
