// SPDX-License-Identifier: BSD-3-Clause
#include "CollapseEngine.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

/*
 * Implementation notes.
 *
 * The build is a greedy half-edge collapse (vertex substitution u -> w, the
 * paper's v1 -> v2) over flat arrays. Greedy order visits the mesh at random,
 * so what costs is the number of distinct cache lines touched per collapse
 * (and, on a fresh process, page faults): the layout is made for that.
 *
 *  - triangles: 16-byte records (3 corners + flag bits), corners rewritten in
 *    place on collapse; dead triangles are flagged, never moved;
 *  - vertices: one 64-byte record (a cache line) with everything the hot loop
 *    reads about a neighbour: position, heap key, adjacency slot, best
 *    target, scratch mark, kind, state;
 *  - vertex -> triangle adjacency: one list per vertex in a shared pool, each
 *    entry the triangle and the vertex's corner in it. Lists are compacted
 *    lazily (dead triangles are dropped whenever a list is walked); a list
 *    that outgrows its slot moves to the end of the pool, and the pool is
 *    compacted when full, so collapses do not allocate;
 *  - Garland-Heckbert quadrics (area-weighted face planes plus constraint
 *    planes along boundaries and feature edges), one cache line per vertex
 *    in single precision relative to the vertex itself;
 *  - a 4-ary indexed heap holding, per vertex, its cheapest collapse. Costs
 *    are one quadric evaluation; the legality checks (link condition, normal
 *    flips, slivers, duplicate triangles) run only when a vertex reaches the
 *    top. A cost depends only on the source's quadric and the target's
 *    position, so a collapse changes few keys, and they are kept exact;
 *  - the data of the next collapse (almost always the new top of the heap)
 *    is prefetched in stages while the current one is applied.
 *
 * When the heap runs dry the constraints are relaxed level by level (slivers,
 * then boundaries and feature edges, then the geometric checks), so that the
 * build always reaches the coarsest mesh the link condition allows.
 *
 * Coordinates are translated and scaled into a unit box first, which keeps the
 * quadrics well conditioned and makes the internal tolerances scale-free;
 * errors are scaled back to world units on output.
 *
 * This file holds the collapses (candidates, application, the adjacency
 * pool); the legality checks, the setup, the classification of the vertices
 * and the frame of the run are in CollapseEngineCheck.cxx,
 * CollapseEngineSetup.cxx, CollapseEngineClassify.cxx and
 * CollapseEngineRun.cxx.
 */

namespace timecritical
{
namespace collapse
{
//------------------------------------------------------------------------------
void CollapseEngine::CompactPool()
{
  // Rebuild the pool from the live triangles of the live vertices, in vertex
  // order, with fresh slack. Runs rarely (when the headroom is used up).
  size_t total = 0;
  for (const Vertex& rec : this->Vertices)
  {
    if (!(rec.State & RemovedBit))
    {
      total += rec.AdjCount + rec.AdjCount / 2 + 4;
    }
  }
  // Half the live size as headroom: the next compaction only comes after as
  // many entries again have been relocated, so compacting stays amortised O(1).
  BigVector<uint32_t> pool(total + total / 2 + 64);
  size_t offset = 0;
  for (Vertex& rec : this->Vertices)
  {
    const uint32_t* list = this->Pool.data() + rec.AdjStart;
    const uint32_t n = rec.AdjCount;
    rec.AdjStart = static_cast<uint32_t>(offset);
    if (rec.State & RemovedBit)
    {
      rec.AdjCount = rec.AdjCap = 0;
      continue;
    }
    uint32_t kept = 0;
    for (uint32_t i = 0; i < n; ++i)
    {
      if (!(this->Tris[list[i] >> 2].Flags & DeadFlag))
      {
        pool[offset + kept++] = list[i];
      }
    }
    rec.AdjCount = kept;
    rec.AdjCap = kept + kept / 2 + 4; // growing lists keep growing: keep their headroom
    offset += rec.AdjCap;
  }
  this->PoolUsed = offset;
  this->Pool.swap(pool);
}

//------------------------------------------------------------------------------
void CollapseEngine::EnsureCapacity(uint32_t v, uint32_t needed)
{
  if (needed <= this->Vertices[v].AdjCap)
  {
    return;
  }
  const uint32_t cap = needed + needed / 2 + 4;
  if (this->PoolUsed + cap > this->Pool.size())
  {
    this->CompactPool();
    if (needed <= this->Vertices[v].AdjCap)
    {
      return;
    }
    if (this->PoolUsed + cap > this->Pool.size())
    {
      this->Pool.resize(this->PoolUsed + cap + this->Pool.size() / 2);
    }
  }
  Vertex& rec = this->Vertices[v];
  std::copy(this->Pool.begin() + rec.AdjStart, this->Pool.begin() + rec.AdjStart + rec.AdjCount,
    this->Pool.begin() + static_cast<std::ptrdiff_t>(this->PoolUsed));
  rec.AdjStart = static_cast<uint32_t>(this->PoolUsed);
  rec.AdjCap = cap;
  this->PoolUsed += cap;
}

//------------------------------------------------------------------------------
bool CollapseEngine::BestTarget(uint32_t v, Candidate& best, bool prefetch)
{
  best.Cost = std::numeric_limits<double>::infinity();
  best.Target = Invalid;
  if (prefetch)
  {
    // Batch the cache misses: triangles first, then the neighbours.
    const Vertex& rv = this->Vertices[v];
    const uint32_t* list = this->Pool.data() + rv.AdjStart;
    for (uint32_t i = 0; i < rv.AdjCount; ++i)
    {
      Prefetch(&this->Tris[list[i] >> 2]);
    }
    for (uint32_t i = 0; i < rv.AdjCount; ++i)
    {
      const Tri& tri = this->Tris[list[i] >> 2];
      Prefetch(&this->Vertices[tri.V[Next3(list[i] & 3u)]]);
    }
  }
  CheapestTarget cheapest(this->QuadricOf(v), this->Vertices.data());
  this->ForEachAllowedTarget(v, [&cheapest](uint32_t x) { cheapest.Offer(x); });
  best = cheapest.Best();
  return best.Target != Invalid;
}

//------------------------------------------------------------------------------
const std::vector<Candidate>& CollapseEngine::GatherCandidates(uint32_t v)
{
  // All allowed targets of v, each once, cheapest first.
  this->Scratch.clear();
  const uint32_t base = this->NextStampBase();
  const LocalQuadric q = this->QuadricOf(v);
  this->ForEachAllowedTarget(v, [&](uint32_t x) {
    uint32_t& mark = this->Vertices[x].Mark;
    if ((mark & ~MarkBits) != base)
    {
      mark = base;
      this->Scratch.push_back({ this->Cost(q, x), x });
    }
  });
  std::sort(this->Scratch.begin(), this->Scratch.end(), [](const Candidate& a, const Candidate& b) {
    return a.Cost < b.Cost || (a.Cost == b.Cost && a.Target < b.Target);
  });
  return this->Scratch;
}

//------------------------------------------------------------------------------
bool CollapseEngine::FindLegalAlternative(uint32_t u, uint32_t failedTarget, Candidate& found)
{
  // Each check walks both fans: trying every target of a vertex of valence V
  // costs O(V^2), again after every change around it. Past the budget the
  // vertex waits (blocked) for its neighbourhood to change.
  const std::vector<Candidate>& candidates = this->GatherCandidates(u);
  const uint64_t limit = this->Visited + AlternativeWorkBudget;
  for (const Candidate& c : candidates)
  {
    if (this->Visited > limit)
    {
      return false;
    }
    if (c.Target != failedTarget && this->CheckCollapse(u, c.Target))
    {
      found = c;
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
void CollapseEngine::SetBest(uint32_t v, const Candidate& best)
{
  Vertex& rec = this->Vertices[v];
  rec.State &= static_cast<uint8_t>(~BlockedBit);
  rec.Target = best.Target;
  if (best.Target != Invalid)
  {
    this->HeapSet(v, best.Cost);
  }
  else
  {
    this->HeapRemove(v);
  }
}

//------------------------------------------------------------------------------
void CollapseEngine::Reevaluate(uint32_t v, bool prefetch)
{
  if (this->Parked(v))
  {
    this->Park(v);
    return;
  }
  Candidate best;
  this->BestTarget(v, best, prefetch);
  this->SetBest(v, best);
}

//------------------------------------------------------------------------------
inline void CollapseEngine::RecordStep(uint32_t u, uint32_t w)
{
  this->RemovedOrder.push_back(u);
  this->SubstituteOf[u] = w;
  this->KillStart.push_back(static_cast<uint32_t>(this->KillList.size()));
  this->HeapRemove(u);
}

//------------------------------------------------------------------------------
inline void CollapseEngine::AddToRing(uint32_t x, uint32_t u, uint32_t ringBase)
{
  Vertex& rx = this->Vertices[x];
  if (rx.Mark != ringBase)
  {
    rx.Mark = ringBase;
    this->Ring.push_back(x);
    Prefetch(&this->Quadrics[x]); // for the update of its candidates (UpdateRing)
    if ((rx.Target == u || (rx.State & BlockedBit) || rx.Kind == KindCurve) &&
      rx.LiveCount <= MaximumFanSize)
    {
      // Probably re-evaluated: its fan is fetched over this collapse.
      this->Soon.push_back(x);
      Prefetch(this->Pool.data() + rx.AdjStart);
    }
  }
}

//------------------------------------------------------------------------------
inline uint32_t CollapseEngine::MoveFanToTarget(uint32_t u, uint32_t w)
{
  // Triangles around u: those on the edge die, the others now use w (in the
  // same corner). The check just compacted u's list, so every entry is live.
  // u's neighbours are gathered on the way (the ring): their candidates change.
  Vertex& ru = this->Vertices[u];
  Vertex& rw = this->Vertices[w];
  const uint32_t ringBase = this->NextStampBase();
  this->Ring.clear();
  rw.Mark = ringBase;
  this->Soon.clear();
  this->Merges.clear();
  uint32_t* listU = this->Pool.data() + ru.AdjStart;
  const uint32_t countU = ru.AdjCount;
  this->Visited += countU + rw.AdjCount;
  uint32_t survivors = 0;
  for (uint32_t i = 0; i < countU; ++i)
  {
    const uint32_t entry = listU[i];
    const uint32_t t = entry >> 2;
    const uint32_t j = entry & 3u;
    Tri& tri = this->Tris[t];
    const uint32_t a = tri.V[Next3(j)];
    const uint32_t b = tri.V[Prev3(j)];
    if (a == w || b == w)
    {
      const uint32_t k = a == w ? Next3(j) : Prev3(j);
      const uint32_t m = 3 - j - k;
      const uint32_t x = tri.V[m];
      tri.Flags |= DeadFlag;
      this->KillList.push_back(t);
      --rw.LiveCount;
      if (--this->Vertices[x].LiveCount == 0)
      {
        this->Orphans.push_back(x);
      }
      // Edges (u, x) and (w, x) merge into one: keep a constraint flag alive.
      if (tri.Flags & ((1u << EdgeIndex(j, m)) | (1u << EdgeIndex(k, m))))
      {
        this->Merges.push_back(x);
      }
      this->AddToRing(x, u, ringBase);
      continue;
    }
    tri.V[j] = w;
    listU[survivors++] = entry;
    this->AddToRing(a, u, ringBase);
    this->AddToRing(b, u, ringBase);
  }
  rw.LiveCount += survivors;
  ru.LiveCount = 0;
  ru.AdjCount = survivors; // u keeps its list until appended (the pool may move)
  return survivors;
}

//------------------------------------------------------------------------------
inline void CollapseEngine::AppendSurvivors(uint32_t u, uint32_t w, uint32_t survivors)
{
  // w's list: drop the dead, append u's survivors.
  Vertex& ru = this->Vertices[u];
  Vertex& rw = this->Vertices[w];
  uint32_t* listW = this->Pool.data() + rw.AdjStart;
  uint32_t kept = 0;
  for (uint32_t i = 0; i < rw.AdjCount; ++i)
  {
    if (!(this->Tris[listW[i] >> 2].Flags & DeadFlag))
    {
      listW[kept++] = listW[i];
    }
  }
  rw.AdjCount = kept;
  this->EnsureCapacity(w, kept + survivors); // may move lists
  const uint32_t* listU = this->Pool.data() + ru.AdjStart;
  listW = this->Pool.data() + rw.AdjStart;
  std::copy(listU, listU + survivors, listW + kept);
  rw.AdjCount = kept + survivors;
  ru.AdjCount = 0;
}

//------------------------------------------------------------------------------
inline void CollapseEngine::KeepMergedConstraintEdges(uint32_t w)
{
  // Each wing vertex x in Merges had a constraint edge to u or w that is now
  // one edge (w, x): flag it in every triangle of w that has it.
  const Vertex& rw = this->Vertices[w];
  for (uint32_t x : this->Merges)
  {
    this->Visited += rw.AdjCount;
    const uint32_t* listW = this->Pool.data() + rw.AdjStart;
    for (uint32_t i = 0; i < rw.AdjCount; ++i)
    {
      Tri& tri = this->Tris[listW[i] >> 2];
      if (tri.Has(x))
      {
        tri.Flags |= 1u << EdgeIndex(listW[i] & 3u, tri.CornerOf(x));
      }
    }
  }
}

//------------------------------------------------------------------------------
inline void CollapseEngine::PrefetchSoonTriangles()
{
  for (uint32_t x : this->Soon)
  {
    const Vertex& rx = this->Vertices[x];
    const uint32_t* list = this->Pool.data() + rx.AdjStart;
    for (uint32_t i = 0; i < rx.AdjCount; ++i)
    {
      Prefetch(&this->Tris[list[i] >> 2]);
    }
  }
}

//------------------------------------------------------------------------------
inline void CollapseEngine::PrefetchSoonNeighbours()
{
  for (uint32_t x : this->Soon)
  {
    const Vertex& rx = this->Vertices[x];
    const uint32_t* list = this->Pool.data() + rx.AdjStart;
    for (uint32_t i = 0; i < rx.AdjCount; ++i)
    {
      const Tri& tri = this->Tris[list[i] >> 2];
      Prefetch(&this->Vertices[tri.V[Next3(list[i] & 3u)]]);
    }
  }
}

//------------------------------------------------------------------------------
inline void CollapseEngine::MergeQuadrics(uint32_t u, uint32_t w)
{
  QuadricRecord& qu = this->Quadrics[u];
  QuadricRecord& qw = this->Quadrics[w];
  LocalQuadric(qu, this->Vertices[u].P).AddTo(qw, this->Vertices[w].P);
  SetFaceWeight(qw, qw.FaceWeight + qu.FaceWeight);
  if (qu.Slot != Invalid)
  {
    if (qw.Slot == Invalid)
    {
      qw.Slot = qu.Slot; // u is gone: w takes its record over
    }
    else
    {
      this->Constraints[qw.Slot].Q.Add(this->Constraints[qu.Slot].Q);
      this->Constraints[qw.Slot].Weight += this->Constraints[qu.Slot].Weight;
    }
    qu.Slot = Invalid;
  }
}

//------------------------------------------------------------------------------
inline void CollapseEngine::RecordStepError(uint32_t w)
{
  // Reported error: the larger of the mean squared distances to the merged
  // face planes and to the merged constraint planes (their weights make the
  // ordering keep boundaries in place, but would distort a distance).
  const QuadricRecord& qw = this->Quadrics[w];
  const double total = qw.C; // the merged quadric at w itself
  double constraint = 0.0, e2c = 0.0;
  if (qw.Slot != Invalid)
  {
    const ConstraintRecord& c = this->Constraints[qw.Slot];
    constraint = c.Q.Evaluate(this->Vertices[w].P);
    e2c = c.Weight > 0.0 ? constraint / c.Weight : 0.0;
  }
  const double face = std::max(total - constraint, 0.0);
  const double e2 = std::max(qw.FaceWeight > 0.0 ? face / qw.FaceWeight : 0.0, e2c);
  // Every plane and vertex lies in the unit box, so no distance exceeds its
  // diagonal: more is rounding (a tiny face weight), which could overflow.
  this->RunningError = std::max(this->RunningError, std::sqrt(std::min(e2, 3.0)) * this->Scale);
  this->StepError.push_back(static_cast<float>(this->RunningError));
}

//------------------------------------------------------------------------------
inline void CollapseEngine::RetargetSurvivor(uint32_t w)
{
  // w: new quadric and new neighbours, so a fresh best target. Blocked
  // vertices around w are retried, since the legality of their collapses
  // may have changed; around a hub (degenerate input) only when the level
  // ends (Relax): each would come back to the hub's fan at every collapse
  // into it, O(V^2) per collapse.
  Vertex& rw = this->Vertices[w];
  this->Retry.clear();
  const bool retry = rw.LiveCount <= RetryFanSize;
  CheapestTarget cheapest(LocalQuadric(this->Quadrics[w], rw.P), this->Vertices.data());
  auto consider = [&cheapest](uint32_t x) { cheapest.Offer(x); };
  const int kind = this->EffectiveKind(w);
  this->ForEachLiveTriangle(w, [&](const Tri& tri, uint32_t j) {
    const uint32_t a = tri.V[Next3(j)];
    const uint32_t b = tri.V[Prev3(j)];
    if ((this->Vertices[a].State | this->Vertices[b].State) & BlockedBit)
    {
      if (retry)
      {
        this->Retry.push_back(a);
        this->Retry.push_back(b);
      }
      else
      {
        this->RetrySkipped = true;
      }
    }
    // The targets of ForEachAllowedTarget, in the same walk.
    if (kind == KindClosed)
    {
      consider(a);
    }
    else if (kind == KindFree)
    {
      consider(a);
      consider(b);
    }
    else if (kind == KindCurve)
    {
      if ((tri.Flags >> j) & 1u)
      {
        consider(a);
      }
      if ((tri.Flags >> Prev3(j)) & 1u)
      {
        consider(b);
      }
    }
  });
  if (this->Parked(w))
  {
    this->Park(w); // its fan grew beyond the bound
  }
  else
  {
    this->SetBest(w, cheapest.Best());
  }
}

//------------------------------------------------------------------------------
inline void CollapseEngine::UpdateRing(uint32_t u, uint32_t w)
{
  // Costs depend only on the source's quadric and the target's position, so
  // of the other vertices only u's former neighbours are affected: they
  // gained w as a target (one evaluation), and those that aimed at u lost
  // their target (a full re-evaluation). All keys stay exact, hence the order
  // exactly greedy.
  for (uint32_t x : this->Ring)
  {
    Vertex& rx = this->Vertices[x];
    if (rx.State & (RemovedBit | BlockedBit))
    {
      if (!(rx.State & RemovedBit))
      {
        this->Reevaluate(x, false);
      }
      continue;
    }
    const int kind = this->EffectiveKind(x);
    if (kind == KindFixed)
    {
      continue;
    }
    if (kind == KindCurve)
    {
      this->Reevaluate(x, false); // its targets depend on the constraint edges
      continue;
    }
    const double c = this->Cost(this->QuadricOf(x), w);
    if (static_cast<float>(c) < rx.Key)
    {
      rx.Target = w; // cheaper than its best so far: the new best
      this->HeapSet(x, c);
    }
    else if (rx.Target == u)
    {
      this->Reevaluate(x, false);
    }
  }
}

//------------------------------------------------------------------------------
inline void CollapseEngine::RetryBlocked()
{
  for (uint32_t x : this->Retry)
  {
    if ((this->Vertices[x].State & (RemovedBit | BlockedBit)) == BlockedBit)
    {
      this->Reevaluate(x);
    }
  }
}

//------------------------------------------------------------------------------
inline void CollapseEngine::RemoveOrphans(uint32_t w)
{
  // Vertices left without any triangle (only possible around non-manifold
  // configurations) disappear right away, substituted with w.
  while (!this->Orphans.empty())
  {
    const uint32_t x = this->Orphans.back();
    this->Orphans.pop_back();
    if (!this->IsRemoved(x) && x != w)
    {
      this->RemoveOrphan(x, w);
    }
  }
}

//------------------------------------------------------------------------------
void CollapseEngine::ApplyCollapse(uint32_t u, uint32_t w)
{
  this->RecordStep(u, w);
  // The next collapse most likely starts from the new top of the heap:
  // fetch its data while this one is being applied, in stages between the
  // steps. (Schedules without a heap see further ahead and prefetch
  // themselves: PrefetchCandidate.)
  const uint32_t nextTop =
    this->UseHeap && !this->Heap.Empty() ? this->Heap.Top().Vertex : Invalid;
  this->PrefetchCollapse(nextTop, 0);

  const uint32_t survivors = this->MoveFanToTarget(u, w);
  this->PrefetchCollapse(nextTop, 1);
  this->AppendSurvivors(u, w, survivors);
  Vertex& ru = this->Vertices[u];
  Vertex& rw = this->Vertices[w];
  ru.State |= RemovedBit;
  if (rw.Kind == KindClosed && ru.Kind != KindClosed)
  {
    rw.Kind = KindFree; // w may have inherited an open fan
  }
  this->KeepMergedConstraintEdges(w);

  this->PrefetchCollapse(nextTop, 2);
  this->PrefetchSoonTriangles();
  this->MergeQuadrics(u, w);
  this->RecordStepError(w);

  this->PrefetchCollapse(nextTop, 3);
  this->PrefetchSoonNeighbours();
  this->RetargetSurvivor(w);
  this->UpdateRing(u, w);
  this->RetryBlocked();
  this->PrefetchCollapse(nextTop, 4);
  this->RemoveOrphans(w);
}

//------------------------------------------------------------------------------
void CollapseEngine::AbsorbStep(uint32_t m, uint32_t w)
{
  // Substitution m -> w of a part joining another one (JoinParts): w is in
  // the other part, so no triangle has both; a triangle of the part dies
  // when its second corner goes (two corners then lead to w), as the
  // traversal finds it. m's triangles are not moved to w: all die within
  // the part's steps.
  this->RecordStep(m, w);
  Vertex& rm = this->Vertices[m];
  const uint32_t* list = this->Pool.data() + rm.AdjStart;
  this->Visited += rm.AdjCount;
  for (uint32_t i = 0; i < rm.AdjCount; ++i)
  {
    Tri& tri = this->Tris[list[i] >> 2];
    if (tri.Flags & DeadFlag)
    {
      continue;
    }
    const uint32_t j = list[i] & 3u;
    const uint32_t a = tri.V[Next3(j)];
    const uint32_t b = tri.V[Prev3(j)];
    if ((this->Vertices[a].State | this->Vertices[b].State) & RemovedBit)
    {
      tri.Flags |= DeadFlag;
      this->KillList.push_back(list[i] >> 2);
      --this->Vertices[a].LiveCount;
      --this->Vertices[b].LiveCount;
    }
  }
  rm.AdjCount = 0;
  rm.LiveCount = 0;
  rm.State |= RemovedBit;
  this->MergeQuadrics(m, w);
  this->RecordStepError(w);
}

//------------------------------------------------------------------------------
void CollapseEngine::PrefetchCollapse(uint32_t v, int stage)
{
  // A software pipeline for the next collapse, which almost always starts
  // from the new top of the heap: each stage, spread over the current
  // collapse, reads what the previous one fetched and fetches the next level
  // (vertex, adjacency lists, triangles, neighbours), for v and its target.
  if (v == Invalid)
  {
    return;
  }
  if (stage == 0)
  {
    Prefetch(&this->Vertices[v]);
    return;
  }
  const Vertex& rv = this->Vertices[v];
  const uint32_t* list = this->Pool.data() + rv.AdjStart;
  const uint32_t target = rv.Target;
  const Vertex* rt = target != Invalid ? &this->Vertices[target] : nullptr;
  // Read only by the stages after the one that fetches the target's record
  // (a parked target's fan is not fetched: the check refuses it unread).
  auto listT = [this, rt]() { return this->Pool.data() + rt->AdjStart; };
  auto fanT = [rt]() { return rt->LiveCount <= MaximumFanSize ? rt->AdjCount : 0u; };
  auto fetchTriangles = [this](const uint32_t* l, uint32_t n) {
    for (uint32_t i = 0; i < n; ++i)
    {
      Prefetch(&this->Tris[l[i] >> 2]);
    }
  };
  auto fetchNeighbours = [this](const uint32_t* l, uint32_t n) {
    for (uint32_t i = 0; i < n; ++i)
    {
      const Tri& tri = this->Tris[l[i] >> 2];
      Prefetch(&this->Vertices[tri.V[Next3(l[i] & 3u)]]);
      Prefetch(&this->Vertices[tri.V[Prev3(l[i] & 3u)]]);
    }
  };
  switch (stage)
  {
    case 1:
      Prefetch(list);
      if (rt)
      {
        Prefetch(rt);
      }
      break;
    case 2:
      fetchTriangles(list, rv.AdjCount);
      if (rt)
      {
        Prefetch(listT());
      }
      break;
    case 3:
      fetchNeighbours(list, rv.AdjCount);
      if (rt)
      {
        fetchTriangles(listT(), fanT());
      }
      break;
    case 4:
      if (rt)
      {
        fetchNeighbours(listT(), fanT());
      }
      break;
    default:
      // Only for schedules that see further ahead (PrefetchCandidate): the
      // quadrics that the collapse merges (v's, its target's) and evaluates
      // (v's neighbours', which get the target as a new candidate).
      Prefetch(&this->Quadrics[v]);
      if (rt)
      {
        Prefetch(&this->Quadrics[target]);
      }
      for (uint32_t i = 0; i < rv.AdjCount; ++i)
      {
        const Tri& tri = this->Tris[list[i] >> 2];
        Prefetch(&this->Quadrics[tri.V[Next3(list[i] & 3u)]]);
        Prefetch(&this->Quadrics[tri.V[Prev3(list[i] & 3u)]]);
      }
      break;
  }
}

//------------------------------------------------------------------------------
void CollapseEngine::RemoveOrphan(uint32_t x, uint32_t w)
{
  this->RemovedOrder.push_back(x);
  this->SubstituteOf[x] = w;
  this->KillStart.push_back(static_cast<uint32_t>(this->KillList.size()));
  this->StepError.push_back(static_cast<float>(this->RunningError));
  this->Vertices[x].State |= RemovedBit;
  this->Vertices[x].AdjCount = 0;
  this->HeapRemove(x);
}

//------------------------------------------------------------------------------
void CollapseEngine::Block(uint32_t v)
{
  this->HeapRemove(v);
  this->Vertices[v].State |= BlockedBit;
  this->BlockedList.push_back(v);
}

//------------------------------------------------------------------------------
void CollapseEngine::Park(uint32_t v)
{
  // Blocked without a walk of its fan: every collapse that shrinks the fan
  // has v in its ring, which re-evaluates blocked vertices.
  if (!(this->Vertices[v].State & BlockedBit))
  {
    this->Block(v);
  }
}

}
}
