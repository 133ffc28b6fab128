// SPDX-License-Identifier: BSD-3-Clause
#include "MergeTreeBuilder.h"

#include "CollapseEngine.h"
#include "MergeTreeAttributes.h"
#include "RadixSortByKey.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>
#include <vector>

/*
 * The level schedule over the collapse engine (CollapseEngine.h), after Xia,
 * El-Sana & Varshney, section 4.1.
 *
 * A level is an independent set of half-edge collapses u -> w: no two share a
 * triangle of their regions of influence (the triangles around u or w). Two
 * regions share a triangle exactly when an end of one edge is an end of the
 * other or adjacent to one, so once u -> w is applied the vertices that later
 * collapses of the level may not use are w and its new neighbours: they are
 * "touched". Collapses are taken least error first: the level starts with
 * every vertex's cheapest collapse sorted by key; a vertex is skipped when it
 * is touched, deferred to the next level when its target is.
 *
 * Why one sort per level suffices: the engine changes the key or target only
 * of vertices of the region (w and its neighbours), which are touched and wait
 * for the next level anyway. So the key of every untouched vertex is still
 * the one it was sorted by, and the order is exactly least error first. The
 * next level's list is the touched vertices (their fresh keys, read while the
 * collapse has them in cache) plus the deferred entries, unchanged.
 *
 * When a vertex's cheapest target is illegal its cheapest legal one is taken,
 * at once when still the least error, otherwise re-queued in a small heap that
 * is merged with the sorted list. When a whole level finds nothing legal the
 * engine relaxes its constraints (as for TOMBuilder) and the level starts
 * again; the build ends when nothing is left at the last relaxation. A thin
 * level (few collapses left besides constrained vertices) releases boundary
 * and feature constraints early, which shortens the tree by a fifth; the
 * geometric checks are only relaxed once nothing is legal.
 *
 * Collapses in key order jump around the mesh: what costs is waiting on
 * memory. The sorted list shows the next collapses, so their data is fetched
 * several collapses ahead (PrefetchAhead), and once the levels are done the
 * engine's arrays are reused by ComputeMergeTree (no fresh pages to fault in).
 *
 * The cost cap (MergeTreeBuildOptions::LevelCostRatio) ends a level early,
 * once the next candidate costs too much more than where the greedy order
 * would be after as many collapses. The untried rest of the list (and the
 * re-queued alternatives) are still exact for their untouched vertices, so
 * they simply join the next level's list (the rest, sorted already, by a
 * merge). A capped level is thin by choice,
 * not because constraints hold vertices up: it does not release them.
 */

namespace timecritical
{
namespace
{
using collapse::Candidate;
using collapse::CollapseEngine;
using collapse::Invalid;
using collapse::RadixSortByKey;
using collapse::Prefetch;

/// A candidate collapse: u's key as an order-preserving integer, u and its target.
struct Entry
{
  uint32_t Key;
  uint32_t Vertex;
  uint32_t Target;
  uint32_t Unused;
};

/// Float key -> unsigned integer of the same order (negative keys included).
inline uint32_t OrderedBits(float key)
{
  uint32_t bits;
  std::memcpy(&bits, &key, sizeof(bits));
  return bits & 0x80000000u ? ~bits : bits | 0x80000000u;
}

/// The inverse of OrderedBits.
inline float KeyFromBits(uint32_t ordered)
{
  const uint32_t bits = ordered & 0x80000000u ? ordered & 0x7fffffffu : ~ordered;
  float key;
  std::memcpy(&key, &bits, sizeof(key));
  return key;
}

constexpr uint32_t NoKey = std::numeric_limits<uint32_t>::max();

/// A level that removes fewer than 1/ThinLevelDivisor of the live vertices
/// (a full one removes about 1/8) releases the constraints early.
constexpr uint32_t ThinLevelDivisor = 16;

/// Min-heap order of re-queued entries (std heaps are max-heaps).
bool LaterEntry(const Entry& a, const Entry& b)
{
  return a.Key > b.Key || (a.Key == b.Key && a.Vertex > b.Vertex);
}

/// Levels of independent collapses, least error first within a level.
class LevelSchedule
{
public:
  LevelSchedule(CollapseEngine& engine, const MergeTreeBuildOptions& options)
    : Engine(engine)
    , CostRatio(options.LevelCostRatio)
    , MinimumShare(options.LevelMinimumShare)
    , UncappedShare(options.UncappedShare)
  {
  }

  bool Run();

  /// Level of each removal step, in step order.
  const std::vector<uint16_t>& GetStepLevels() const { return this->StepLevel; }
  uint16_t GetLevelCount() const { return this->LevelCount; }

private:
  bool RunLevel(uint16_t level, uint32_t& applied, bool& capped);
  uint32_t CapFor(uint32_t applied) const;
  uint32_t Alternative(uint32_t u, uint32_t failedTarget, uint32_t cap, uint32_t& key);
  void Apply(uint32_t u, uint32_t w, uint16_t level);
  void Touch(uint32_t x);
  Entry EntryOf(uint32_t x) const;
  void PrefetchAhead();
  void ClearStamps();
  void CollectAll();
  void CollectNext();
  bool IsTouched(uint32_t v) const { return this->Touched[v] == this->Stamp; }
  uint32_t NextKey() const
  {
    uint32_t k = this->Position < this->Current.size() ? this->Current[this->Position].Key : NoKey;
    return this->Requeued.empty() ? k : std::min(k, this->Requeued.front().Key);
  }

  CollapseEngine& Engine;
  const double CostRatio;      // MergeTreeBuildOptions::LevelCostRatio
  const double MinimumShare;   // MergeTreeBuildOptions::LevelMinimumShare
  const double UncappedShare;  // MergeTreeBuildOptions::UncappedShare
  uint32_t MaxTakenKey = 0;    // costliest collapse taken so far (ordered bits)
  std::vector<Entry> Current;  // this level's candidates, by key
  size_t Position = 0;         // next one in Current
  size_t RestStart = 0;        // Current[RestStart..]: left untried by a capped level
  std::vector<Entry> Requeued; // min-heap: legal alternatives costlier than their turn
  std::vector<Entry> Next;     // fresh entries of the touched vertices
  size_t CollapseEntries = 0;  // Next's size when the touches of the latest collapse began
  std::vector<Entry> Deferred; // untouched vertices whose target is touched, and the
                               // re-queued ones a capped level left
  std::vector<Entry> Fresh;    // next level's entries besides the untried rest
  std::vector<Entry> Buffer;   // radix sort and merge
  std::vector<uint8_t> Touched; // == Stamp: touched in this level (then the engine's tag
                                // of the vertex is its entry in Next, its tag byte Stamp)
  uint8_t Stamp = 0;
  // The next untouched candidates (indices into Current), each with the
  // prefetch stage it has reached: see PrefetchAhead.
  static constexpr unsigned Lookahead = 5;
  size_t Upcoming[Lookahead] = {};
  int UpcomingStage[Lookahead] = {};
  unsigned UpcomingCount = 0;
  size_t ScanPosition = 0; // next entry of Current to consider for Upcoming
  std::vector<uint16_t> StepLevel;
  uint16_t LevelCount = 0;
  size_t ReportEvery = 1;
  size_t NextReport = 1;
};

//------------------------------------------------------------------------------
Entry LevelSchedule::EntryOf(uint32_t x) const
{
  const CollapseEngine& e = this->Engine;
  if (e.IsRemoved(x) || !(e.GetKey(x) < std::numeric_limits<float>::infinity()))
  {
    return { NoKey, Invalid, Invalid, 0 }; // removed, blocked or without a target
  }
  return { OrderedBits(e.GetKey(x)), x, e.GetTarget(x), 0 };
}

//------------------------------------------------------------------------------
void LevelSchedule::Touch(uint32_t x)
{
  // A vertex touched again may have a new key: its one entry is overwritten.
  // The stamp and the slot are kept in the vertex's own cache line, which the
  // collapse has just read (a read of the Touched array would miss); the
  // array, which the list scans read, is only written.
  uint8_t& stamp = this->Engine.TagByte(x);
  if (stamp != this->Stamp)
  {
    stamp = this->Stamp;
    this->Touched[x] = this->Stamp;
    this->Engine.Tag(x) = static_cast<uint32_t>(this->Next.size());
    this->Next.push_back(this->EntryOf(x));
  }
  else if (this->Engine.Tag(x) < this->CollapseEntries)
  {
    // Touched by an earlier collapse (an entry of this one is already fresh:
    // most neighbours come twice, once per triangle).
    this->Next[this->Engine.Tag(x)] = this->EntryOf(x);
  }
}

//------------------------------------------------------------------------------
void LevelSchedule::ClearStamps()
{
  std::fill(this->Touched.begin(), this->Touched.end(), uint8_t(0));
  for (uint32_t v = 0; v < this->Engine.GetNumberOfVertices(); ++v)
  {
    this->Engine.TagByte(v) = 0;
  }
}

//------------------------------------------------------------------------------
void LevelSchedule::CollectAll()
{
  // Every vertex with a candidate: at the start and after a relaxation, which
  // gives keys back to blocked vertices.
  CollapseEngine& e = this->Engine;
  this->Current.clear();
  for (uint32_t v = 0; v < e.GetNumberOfVertices(); ++v)
  {
    const Entry entry = this->EntryOf(v);
    if (entry.Vertex != Invalid)
    {
      this->Current.push_back(entry);
    }
  }
  RadixSortByKey(this->Current, this->Buffer);
}

//------------------------------------------------------------------------------
void LevelSchedule::CollectNext()
{
  // The fresh and deferred entries, sorted, merged with what a capped level
  // left untried (sorted already, most of the list early on).
  this->Fresh.clear();
  for (const Entry& entry : this->Next)
  {
    if (entry.Vertex != Invalid)
    {
      this->Fresh.push_back(entry);
    }
  }
  for (const Entry& entry : this->Deferred)
  {
    if (!this->IsTouched(entry.Vertex)) // else its fresh entry came from Next
    {
      this->Fresh.push_back(entry);
    }
  }
  RadixSortByKey(this->Fresh, this->Buffer);
  this->Buffer.clear();
  auto a = this->Fresh.cbegin();
  const auto aEnd = this->Fresh.cend();
  constexpr std::ptrdiff_t ahead = 16; // entries whose touched bytes are fetched
  for (auto b = this->Current.cbegin() + static_cast<std::ptrdiff_t>(this->RestStart);
       b != this->Current.cend(); ++b)
  {
    if (this->Current.cend() - b > ahead)
    {
      Prefetch(&this->Touched[b[ahead].Vertex]);
    }
    if (this->IsTouched(b->Vertex))
    {
      continue; // its fresh entry came from Next
    }
    for (; a != aEnd && a->Key <= b->Key; ++a)
    {
      this->Buffer.push_back(*a);
    }
    this->Buffer.push_back(*b);
  }
  this->Buffer.insert(this->Buffer.end(), a, aEnd);
  this->Current.swap(this->Buffer);
}

//------------------------------------------------------------------------------
uint32_t LevelSchedule::Alternative(uint32_t u, uint32_t failedTarget, uint32_t cap, uint32_t& key)
{
  // u's cheapest target is illegal: its cheapest legal one. Returns it (and
  // its key) when it is still the least error of the level and within the
  // level's cap; otherwise re-queues u, or defers it when that target is
  // touched, or blocks u when nothing is legal.
  CollapseEngine& e = this->Engine;
  Candidate c{};
  if (!e.FindLegalAlternative(u, failedTarget, c))
  {
    e.Block(u); // a collapse around u re-evaluates it (and touches it)
    return Invalid;
  }
  e.SetTarget(u, c.Target);
  key = OrderedBits(CollapseEngine::KeyOf(c.Cost));
  if (!this->IsTouched(c.Target) && key <= this->NextKey() && key <= cap)
  {
    return c.Target;
  }
  e.SetKey(u, c.Cost);
  const Entry entry{ key, u, c.Target, 0 };
  if (this->IsTouched(c.Target))
  {
    this->Deferred.push_back(entry);
  }
  else
  {
    this->Requeued.push_back(entry);
    std::push_heap(this->Requeued.begin(), this->Requeued.end(), LaterEntry);
  }
  return Invalid;
}

//------------------------------------------------------------------------------
void LevelSchedule::PrefetchAhead()
{
  // A collapse waits on chains of loads (records, lists, triangles,
  // neighbours, quadrics) that the work of one collapse cannot hide for the
  // next. The sorted list shows several collapses ahead: the k-th next
  // untouched candidate gets stage Stages[k] of its prefetch, so that each
  // stage reads what was fetched one collapse or more earlier (on igea-loop1
  // the collapses take a fifth less time than with the next one alone).
  // Candidates touched meanwhile are skipped by the level, and dropped here
  // once passed.
  static constexpr int Stages[Lookahead] = { 5, 3, 2, 1, 0 };
  static constexpr size_t TouchedAhead = 16; // entries whose touched bytes are fetched
  unsigned kept = 0;
  for (unsigned i = 0; i < this->UpcomingCount; ++i)
  {
    if (this->Upcoming[i] >= this->Position)
    {
      this->Upcoming[kept] = this->Upcoming[i];
      this->UpcomingStage[kept++] = this->UpcomingStage[i];
    }
  }
  this->UpcomingCount = kept;
  this->ScanPosition = std::max(this->ScanPosition, this->Position);
  while (this->UpcomingCount < Lookahead && this->ScanPosition < this->Current.size())
  {
    if (this->ScanPosition + TouchedAhead < this->Current.size())
    {
      const Entry& later = this->Current[this->ScanPosition + TouchedAhead];
      Prefetch(&this->Touched[later.Vertex]);
      Prefetch(&this->Touched[later.Target]);
    }
    const Entry& next = this->Current[this->ScanPosition];
    if (!this->IsTouched(next.Vertex) && !this->IsTouched(next.Target))
    {
      this->Upcoming[this->UpcomingCount] = this->ScanPosition;
      this->UpcomingStage[this->UpcomingCount++] = -1;
    }
    ++this->ScanPosition;
  }
  for (unsigned k = 0; k < this->UpcomingCount; ++k)
  {
    const Entry& entry = this->Current[this->Upcoming[k]];
    while (this->UpcomingStage[k] < Stages[k])
    {
      const int stage = ++this->UpcomingStage[k];
      this->Engine.PrefetchCandidate(entry.Vertex, stage);
      if (stage == 0)
      {
        this->Engine.PrefetchCandidate(entry.Target, 0); // its record, read from stage 1 on
      }
    }
  }
}

//------------------------------------------------------------------------------
void LevelSchedule::Apply(uint32_t u, uint32_t w, uint16_t level)
{
  CollapseEngine& e = this->Engine;
  this->PrefetchAhead();

  const uint32_t before = e.GetRemovedCount();
  e.ApplyCollapse(u, w);
  this->CollapseEntries = this->Next.size();
  // u, and vertices orphaned with it (non-manifold input only).
  for (uint32_t step = before; step < e.GetRemovedCount(); ++step)
  {
    this->StepLevel.push_back(level);
    this->Touch(e.GetRemovedVertex(step));
  }
  this->Touch(w);
  e.ForEachNeighbour(w, [this](uint32_t x) { this->Touch(x); });
}

//------------------------------------------------------------------------------
uint32_t LevelSchedule::CapFor(uint32_t applied) const
{
  // The greedy order, from the state at the start of the level, would have
  // reached about the key of the candidate at rank `applied` after as many
  // collapses: the level may go CostRatio times above it, or up to the
  // costliest collapse already taken (which costs no error).
  const size_t rank = std::min<size_t>(applied, this->Current.size() - 1);
  const double frontier = static_cast<double>(KeyFromBits(this->Current[rank].Key));
  const uint32_t cap = OrderedBits(CollapseEngine::KeyOf(this->CostRatio * frontier));
  return std::max(cap, this->MaxTakenKey);
}

//------------------------------------------------------------------------------
bool LevelSchedule::RunLevel(uint16_t level, uint32_t& applied, bool& capped)
{
  CollapseEngine& e = this->Engine;
  if (++this->Stamp == 0)
  {
    this->ClearStamps();
    this->Stamp = 1;
  }
  this->Next.clear();
  this->Deferred.clear();
  this->Position = 0;
  this->UpcomingCount = 0;
  this->ScanPosition = 0;
  this->RestStart = this->Current.size();
  applied = 0;
  capped = false;
  const uint32_t n = e.GetNumberOfVertices();
  const uint32_t live = n - e.GetRemovedCount();
  const bool useCap = this->CostRatio > 0.0 && !this->Current.empty() &&
    static_cast<double>(live) > this->UncappedShare * static_cast<double>(n);
  // The cap waits for the level's minimum share (at least one collapse, so
  // that a capped level is never empty).
  const uint32_t minimum =
    std::max<uint32_t>(1, static_cast<uint32_t>(std::ceil(this->MinimumShare * live)));
  uint32_t cap = useCap ? this->CapFor(0) : NoKey;
  for (;;)
  {
    if (applied >= minimum && this->NextKey() > cap && this->NextKey() != NoKey)
    {
      // The rest waits for the next level, unchanged (untouched vertices keep
      // their keys; touched ones have fresh entries in Next).
      capped = true;
      this->RestStart = this->Position;
      this->Deferred.insert(this->Deferred.end(), this->Requeued.begin(), this->Requeued.end());
      this->Requeued.clear();
      return true;
    }
    Entry entry;
    if (!this->Requeued.empty() &&
      (this->Position == this->Current.size() ||
        !LaterEntry(this->Requeued.front(), this->Current[this->Position])))
    {
      std::pop_heap(this->Requeued.begin(), this->Requeued.end(), LaterEntry);
      entry = this->Requeued.back();
      this->Requeued.pop_back();
    }
    else if (this->Position < this->Current.size())
    {
      entry = this->Current[this->Position++];
    }
    else
    {
      return true;
    }
    const uint32_t u = entry.Vertex;
    if (this->IsTouched(u))
    {
      continue; // its region changed: its fresh entry is in Next
    }
    if (this->IsTouched(entry.Target))
    {
      this->Deferred.push_back(entry); // u is unchanged: the same entry next level
      continue;
    }
    uint32_t w = entry.Target;
    uint32_t key = entry.Key;
    if (!e.CheckCollapse(u, w))
    {
      w = this->Alternative(u, w, applied >= minimum ? cap : NoKey, key);
      if (w == Invalid)
      {
        continue;
      }
    }
    this->Apply(u, w, level);
    ++applied;
    if (useCap)
    {
      this->MaxTakenKey = std::max(this->MaxTakenKey, key);
      cap = this->CapFor(applied);
    }
    if (e.GetRemovedCount() >= this->NextReport)
    {
      this->NextReport += this->ReportEvery;
      if (!e.ReportProgress(0.05 + 0.9 * double(e.GetRemovedCount()) / n))
      {
        return false;
      }
    }
  }
}

//------------------------------------------------------------------------------
bool LevelSchedule::Run()
{
  CollapseEngine& e = this->Engine;
  const uint32_t n = e.GetNumberOfVertices();
  // Allocated once: no list outgrows the vertex count.
  this->Current.reserve(n);
  this->Next.reserve(n);
  this->Deferred.reserve(n);
  this->Buffer.reserve(n);
  this->Fresh.reserve(n);
  this->Requeued.reserve(1024);
  this->Touched.resize(n);
  this->ClearStamps();
  this->StepLevel.reserve(n);
  this->ReportEvery = std::max<size_t>(1, n / 200);
  this->NextReport = this->ReportEvery;

  this->CollectAll();
  uint16_t level = 0;
  for (;;)
  {
    const uint32_t live = n - e.GetRemovedCount();
    uint32_t applied = 0;
    bool capped = false;
    if (!this->RunLevel(level, applied, capped))
    {
      return false;
    }
    if (applied == 0)
    {
      // Nothing legal left (every candidate blocked): relax, or done.
      if (!e.Relax())
      {
        break;
      }
      this->CollectAll();
      continue;
    }
    // Levels are 16-bit: a (pathological) mesh needing more shares the last one.
    if (level < std::numeric_limits<uint16_t>::max() - 1)
    {
      ++level;
    }
    if (!capped && applied < live / ThinLevelDivisor && e.GetRelaxation() < collapse::LevelNoConstraints)
    {
      // A thin level: the constrained vertices (boundaries, feature curves)
      // hold up the last few free ones, which would trickle down one level
      // at a time and then the released vertices another long tail of levels.
      // Releasing them now lets both tails share levels; the geometric
      // checks stay until nothing is legal.
      e.Relax();
      this->CollectAll();
      continue;
    }
    this->CollectNext();
  }
  this->LevelCount = level;
  return true;
}
}

//------------------------------------------------------------------------------
MergeTreeBuilder::MergeTreeBuilder(MergeTreeBuildOptions options)
  : Options(std::move(options))
{
}

//------------------------------------------------------------------------------
MergeTreeBuildResult MergeTreeBuilder::Build(const double* points, size_t numberOfPoints,
  const uint32_t* triangles, size_t numberOfTriangles) const
{
  MergeTreeBuildResult result;
  CollapseEngine engine(this->Options.Collapse, false);
  LevelSchedule schedule(engine, this->Options);
  result.TOM = engine.Run(
    points, numberOfPoints, triangles, numberOfTriangles, [&schedule] { return schedule.Run(); });
  if (result.TOM.Aborted)
  {
    return result;
  }

  // Per TOM vertex: the level of the collapse that removed it (TOM vertex
  // n - 1 - s was removed at step s), the level count for base vertices.
  const TOMMesh& tom = result.TOM.Mesh;
  const uint32_t n = tom.GetNumberOfVertices();
  const std::vector<uint16_t>& stepLevels = schedule.GetStepLevels();
  std::vector<uint16_t> levels(n, schedule.GetLevelCount());
  for (uint32_t step = 0; step < stepLevels.size(); ++step)
  {
    levels[n - 1 - step] = stepLevels[step];
  }
  // The engine's arrays are done with: the merge tree's working arrays reuse them.
  collapse::ScratchBlocks scratch;
  engine.ReleaseWorkingMemory(scratch);
  result.Tree = detail::ComputeBuiltMergeTree(tom, points, result.TOM.VertexOrder.data(),
    levels.data(), this->Options.Errors, &scratch);
  return result;
}
}
