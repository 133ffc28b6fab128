// SPDX-License-Identifier: BSD-3-Clause
// Pair contraction of the collapse engine (CollapseEngine::JoinParts):
// substitutions whose ends share no edge, which join separate parts
// (Gobbetti & Bouvier's Fig. 2, right; Garland & Heckbert's non-edge pairs).
#include "CollapseEngine.h"

#include "PointGrid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <queue>
#include <vector>

/*
 * When no edge collapse is left, every part (connected set of live
 * triangles) is at the coarsest the link condition allows: a closed part
 * keeps a tetrahedron or so, whatever its size. A part then joins another
 * one close by: all its vertices are substituted into one vertex w of the
 * other part, one step each, cheapest first; a triangle of the part dies
 * at the step of its second corner, so after the part's last step nothing
 * of it is left and the other part is as it was. Between the steps the
 * output has the part's remaining triangles pinched to w: the only places
 * where a manifold input gives a non-manifold mesh.
 *
 * Pairs: a vertex x of the part and a vertex w of another part closer than
 * the distance (a spatial grid over the live vertices, cells of that
 * distance: no comparison of all pairs). The cost of the join is the
 * quadric cost (CollapseEngine::Cost) of the part's merged quadric, moved to
 * w: the same measure that orders the edge collapses, over every plane the
 * part has gathered. Joins are taken cheapest first from a priority queue;
 * a join whose target has gone since (its part joined another one) is
 * looked up again, and the part that takes a join gets a fresh cost at once
 * (its quadric grew). Deterministic: ties by part and vertex ids.
 *
 * Work bounds: each part is looked up once, plus once per join that takes
 * its target away, each lookup at most JoinLookupBudget grid entries; the
 * whole phase stops after JoinWorkBudget entries per vertex (the output is
 * then coarser where it could, never invalid).
 */

namespace timecritical
{
namespace collapse
{
namespace
{
/// Grid entries one lookup of a part's best join may look at.
constexpr size_t JoinLookupBudget = 4096;
/// Grid entries the whole phase may look at, per vertex of the input.
constexpr size_t JoinWorkBudget = 64;
}

/// The live parts and their merged quadrics.
struct CollapseEngine::PartSet
{
  std::vector<uint32_t> PartOf;  // live vertex -> part (Invalid: removed)
  std::vector<uint32_t> Start;   // part -> its first entry in Members (parts + 1 entries)
  std::vector<uint32_t> Members; // the live vertices of every part, part by part
  std::vector<QuadricRecord> Quadric; // merged quadric of a part, around its first member
  std::vector<uint32_t> Version;      // changes when the part takes a join
  std::vector<uint8_t> Gone;          // joined another part
  PointGrid Grid;
  double Distance = 0.0;
  size_t WorkLeft = 0;

  uint32_t Count() const { return static_cast<uint32_t>(this->Start.size()) - 1; }
  uint32_t Anchor(uint32_t part) const { return this->Members[this->Start[part]]; }
};

/// A candidate join: part `Part`, whole, into vertex `Target` of another part.
struct CollapseEngine::Join
{
  double Cost;
  uint32_t Part;
  uint32_t Target;
  uint32_t Version; // the part's version when costed
};

namespace
{
/// Priority order of joins: cheapest first, then by part and target.
struct LaterJoin
{
  template <typename J>
  bool operator()(const J& a, const J& b) const
  {
    if (a.Cost != b.Cost)
    {
      return a.Cost > b.Cost;
    }
    return a.Part != b.Part ? a.Part > b.Part : a.Target > b.Target;
  }
};
}

//------------------------------------------------------------------------------
void CollapseEngine::LabelParts(PartSet& parts) const
{
  // Union-find over the live triangles (whose corners are live vertices).
  std::vector<uint32_t> parent(this->N);
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&parent](uint32_t x) {
    while (parent[x] != x)
    {
      x = parent[x] = parent[parent[x]];
    }
    return x;
  };
  for (const Tri& tri : this->Tris)
  {
    if (!(tri.Flags & DeadFlag))
    {
      parent[find(tri.V[1])] = find(tri.V[0]);
      parent[find(tri.V[2])] = find(tri.V[0]);
    }
  }
  // Parts numbered in the order of their first vertex; members in vertex order.
  parts.PartOf.assign(this->N, Invalid);
  std::vector<uint32_t> label(this->N, Invalid);
  uint32_t count = 0;
  for (uint32_t v = 0; v < this->N; ++v)
  {
    if (this->IsRemoved(v))
    {
      continue;
    }
    uint32_t& l = label[find(v)];
    if (l == Invalid)
    {
      l = count++;
    }
    parts.PartOf[v] = l;
  }
  parts.Start.assign(count + size_t(1), 0);
  for (uint32_t v = 0; v < this->N; ++v)
  {
    if (parts.PartOf[v] != Invalid)
    {
      ++parts.Start[parts.PartOf[v] + 1];
    }
  }
  std::partial_sum(parts.Start.begin(), parts.Start.end(), parts.Start.begin());
  parts.Members.resize(parts.Start.back());
  std::vector<uint32_t> next(parts.Start.begin(), parts.Start.end() - 1);
  for (uint32_t v = 0; v < this->N; ++v)
  {
    if (parts.PartOf[v] != Invalid)
    {
      parts.Members[next[parts.PartOf[v]]++] = v;
    }
  }
}

//------------------------------------------------------------------------------
bool CollapseEngine::BestJoin(PartSet& parts, uint32_t part, Join& join)
{
  // The cheapest live vertex of another part within the distance of one of
  // this part's vertices, costed with the part's merged quadric.
  const CostLanes<double> cost(LocalQuadric(parts.Quadric[part], this->Vertices[parts.Anchor(part)].P));
  join = { std::numeric_limits<double>::infinity(), part, Invalid, parts.Version[part] };
  size_t budget = std::min(JoinLookupBudget, parts.WorkLeft);
  for (uint32_t i = parts.Start[part]; i < parts.Start[part + 1] && budget > 0; ++i)
  {
    size_t seen = 0;
    const size_t visited = parts.Grid.ForEachWithin(
      this->Vertices[parts.Members[i]].P, parts.Distance, [&](uint32_t x, double) {
        if (++seen > budget)
        {
          return false;
        }
        if (this->IsRemoved(x) || parts.PartOf[x] == part)
        {
          return true;
        }
        const Vec3& p = this->Vertices[x].P;
        const double c = cost.Cost(p.X, p.Y, p.Z);
        if (c < join.Cost || (c == join.Cost && x < join.Target))
        {
          join.Cost = c;
          join.Target = x;
        }
        return true;
      });
    budget -= std::min(budget, visited);
  }
  const size_t used = std::min(JoinLookupBudget, parts.WorkLeft) - budget;
  parts.WorkLeft -= used;
  this->Visited += used;
  return join.Target != Invalid;
}

//------------------------------------------------------------------------------
void CollapseEngine::AbsorbPart(PartSet& parts, const Join& join)
{
  // The part's vertices into the target, cheapest (by their own quadrics) first.
  const uint32_t w = join.Target;
  this->Scratch.clear();
  for (uint32_t i = parts.Start[join.Part]; i < parts.Start[join.Part + 1]; ++i)
  {
    const uint32_t m = parts.Members[i];
    this->Scratch.push_back({ this->Cost(this->QuadricOf(m), w), m });
  }
  std::sort(this->Scratch.begin(), this->Scratch.end(), [](const Candidate& a, const Candidate& b) {
    return a.Cost < b.Cost || (a.Cost == b.Cost && a.Target < b.Target);
  });
  for (const Candidate& c : this->Scratch)
  {
    this->AbsorbStep(c.Target, w);
    parts.PartOf[c.Target] = Invalid;
  }
  parts.Gone[join.Part] = 1;
  // The taker's merged quadric gathers the part's.
  const uint32_t taker = parts.PartOf[w];
  QuadricRecord& q = parts.Quadric[taker];
  LocalQuadric(parts.Quadric[join.Part], this->Vertices[parts.Anchor(join.Part)].P)
    .AddTo(q, this->Vertices[parts.Anchor(taker)].P);
  SetFaceWeight(q, q.FaceWeight + parts.Quadric[join.Part].FaceWeight);
  ++parts.Version[taker];
  ++this->JoinedParts;
}

//------------------------------------------------------------------------------
bool CollapseEngine::JoinParts()
{
  const double distance = this->Options.PairContractionDistance * this->Diagonal;
  if (!(distance > 0.0) || this->GetRemovedCount() >= this->N)
  {
    return true;
  }
  PartSet parts;
  this->LabelParts(parts);
  const uint32_t count = parts.Count();
  if (count < 2)
  {
    return true; // one part: nothing to join (and nothing else is done)
  }
  if (!this->ReportProgress(0.95))
  {
    return false;
  }
  parts.Distance = distance;
  parts.WorkLeft = JoinWorkBudget * (size_t(this->N) + 1);
  parts.Grid = PointGrid(distance);
  for (uint32_t m : parts.Members)
  {
    parts.Grid.Add(m, this->Vertices[m].P);
  }
  parts.Grid.Build();
  // Merged quadrics, around each part's first member.
  QuadricRecord empty{};
  empty.Slot = Invalid;
  parts.Quadric.assign(count, empty);
  parts.Version.assign(count, 0);
  parts.Gone.assign(count, 0);
  for (uint32_t part = 0; part < count; ++part)
  {
    QuadricRecord& q = parts.Quadric[part];
    const Vec3& anchor = this->Vertices[parts.Anchor(part)].P;
    double weight = 0.0;
    for (uint32_t i = parts.Start[part]; i < parts.Start[part + 1]; ++i)
    {
      const uint32_t m = parts.Members[i];
      LocalQuadric(this->Quadrics[m], this->Vertices[m].P).AddTo(q, anchor);
      weight += this->Quadrics[m].FaceWeight;
    }
    SetFaceWeight(q, static_cast<float>(weight));
  }

  std::priority_queue<Join, std::vector<Join>, LaterJoin> queue;
  Join join{};
  for (uint32_t part = 0; part < count; ++part)
  {
    if (this->BestJoin(parts, part, join))
    {
      queue.push(join);
    }
  }
  while (!queue.empty())
  {
    join = queue.top();
    queue.pop();
    if (parts.Gone[join.Part])
    {
      continue;
    }
    if (join.Version != parts.Version[join.Part])
    {
      continue; // costed before the part grew: its fresh join is queued already
    }
    if (this->IsRemoved(join.Target))
    {
      // Its target joined another part: the next best (never cheaper, as
      // the part's quadric and the positions are the same and targets only go).
      if (this->BestJoin(parts, join.Part, join))
      {
        queue.push(join);
      }
      continue;
    }
    const uint32_t taker = parts.PartOf[join.Target];
    this->AbsorbPart(parts, join);
    if (this->BestJoin(parts, taker, join))
    {
      queue.push(join); // the taker's quadric grew: its own join, costed again
    }
  }
  return true;
}
}
}
