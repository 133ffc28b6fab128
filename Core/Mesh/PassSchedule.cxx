// SPDX-License-Identifier: BSD-3-Clause
#include "PassSchedule.h"

#include "RadixSortByKey.h"

#include "CollapseEngine.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <limits>

namespace timecritical
{
namespace collapse
{
namespace
{
constexpr uint32_t NoKey = std::numeric_limits<uint32_t>::max();
/// Entries ahead of the current one whose collapse data is prefetched.
constexpr size_t Lookahead = 6;
}

//------------------------------------------------------------------------------
PassSchedule::PassSchedule(CollapseEngine& engine)
  : Engine(engine)
{
}

//------------------------------------------------------------------------------
uint32_t PassSchedule::OrderedBits(float key)
{
  uint32_t bits;
  std::memcpy(&bits, &key, sizeof(bits));
  return bits & 0x80000000u ? ~bits : bits | 0x80000000u;
}

//------------------------------------------------------------------------------
void PassSchedule::Collect()
{
  // Every live vertex with a finite key, in vertex order (the tie-break of the
  // stable sort); removed vertices leave the live list. At the start and after
  // a relaxation, which gives keys back to blocked vertices.
  const CollapseEngine& e = this->Engine;
  this->List.clear();
  size_t kept = 0;
  for (const uint32_t v : this->Live)
  {
    if (e.IsRemoved(v))
    {
      continue;
    }
    this->Live[kept++] = v;
    const float key = e.GetKey(v);
    if (key < std::numeric_limits<float>::infinity())
    {
      this->List.push_back({ OrderedBits(key), v });
    }
  }
  this->Live.resize(kept);
  RadixSortByKey(this->List, this->Buffer);
}

//------------------------------------------------------------------------------
void PassSchedule::CollectNext()
{
  // The next pass's list: the fresh entries of the touched vertices, sorted,
  // merged with the entries of the untouched ones, which are still exact and
  // in order (considered or not).
  const CollapseEngine& e = this->Engine;
  this->Fresh.clear();
  for (const uint32_t v : this->TouchedList)
  {
    const float key = e.GetKey(v);
    if (!e.IsRemoved(v) && key < std::numeric_limits<float>::infinity())
    {
      this->Fresh.push_back({ OrderedBits(key), v });
    }
  }
  RadixSortByKey(this->Fresh, this->Buffer);
  this->Buffer.clear();
  auto a = this->Fresh.cbegin();
  const auto aEnd = this->Fresh.cend();
  constexpr size_t ahead = 16; // entries whose stamps are fetched
  const size_t n = this->List.size();
  for (size_t i = 0; i < n; ++i)
  {
    if (i + ahead < n)
    {
      Prefetch(&this->Touched[this->List[i + ahead].Vertex]);
    }
    const Entry& b = this->List[i];
    if (this->IsTouched(b.Vertex))
    {
      continue; // removed, re-keyed or blocked in this pass: its fresh entry (if any) is in Fresh
    }
    for (; a != aEnd && a->Key <= b.Key; ++a)
    {
      this->Buffer.push_back(*a);
    }
    this->Buffer.push_back(b);
  }
  this->Buffer.insert(this->Buffer.end(), a, aEnd);
  this->List.swap(this->Buffer);
}

//------------------------------------------------------------------------------
void PassSchedule::PrefetchAhead(size_t position)
{
  // The engine's prefetch stages, each reading what the earlier fetched: the
  // entry `Lookahead - stage` places ahead gets stage `stage`.
  for (int stage = 0; stage < 6; ++stage)
  {
    const size_t i = position + Lookahead - static_cast<size_t>(stage);
    if (i < this->List.size() && !this->IsTouched(this->List[i].Vertex))
    {
      this->Engine.PrefetchCandidate(this->List[i].Vertex, stage); // skipped entries are not
    }
  }
}

//------------------------------------------------------------------------------
bool PassSchedule::TryCollapse(uint32_t u, uint32_t nextKey)
{
  // u is untouched, so its key and target are the ones it was sorted by.
  CollapseEngine& e = this->Engine;
  uint32_t w = e.GetTarget(u);
  if (this->IsTouched(w))
  {
    return false; // its target's region changed in this pass: next pass
  }
  if (!e.CheckCollapse(u, w))
  {
    Candidate c{};
    if (!e.FindLegalAlternative(u, w, c))
    {
      e.Block(u); // a collapse around u re-evaluates it (and touches it)
      this->Touch(u);
      return false;
    }
    e.SetTarget(u, c.Target);
    e.SetKey(u, c.Cost);
    this->Touch(u); // re-keyed: its entry is renewed
    if (this->IsTouched(c.Target) || OrderedBits(CollapseEngine::KeyOf(c.Cost)) > nextKey)
    {
      return false; // no longer the cheapest of the pass, or not independent: next pass
    }
    w = c.Target;
  }
  e.ApplyCollapse(u, w);
  this->Touch(u);
  // The region of the collapse: w and its neighbours (u's former ones among
  // them), whose keys the engine has just refreshed.
  this->Touch(w);
  e.ForEachNeighbour(w, [this](uint32_t x) { this->Touch(x); });
  return true;
}

//------------------------------------------------------------------------------
uint32_t PassSchedule::RunPass()
{
  this->NextStamp();
  const CollapseEngine& e = this->Engine;
  const size_t n = this->List.size();
  // At least one entry, so that a pass that finds something legal applies it.
  // After a pass that applied nothing (all it considered blocked, re-keyed
  // or waiting for a re-keyed target) the next one considers everything and
  // takes legal alternatives at once, so that the passes always progress.
  const size_t considered = this->Forced
    ? n
    : std::max<size_t>(1, static_cast<size_t>(PassShare * double(n)));
  uint32_t applied = 0;
  for (size_t i = 0; i < std::min(n, considered); ++i)
  {
    this->PrefetchAhead(i);
    const uint32_t u = this->List[i].Vertex;
    if (this->IsTouched(u))
    {
      continue;
    }
    if (e.IsRemoved(u))
    {
      this->Touch(u); // an orphan the engine removed (untouched): drop its entry
      continue;
    }
    // The next untouched entry's key bounds an alternative taken at once
    // (the last entry considered has no bound).
    const uint32_t nextKey =
      !this->Forced && i + 1 < std::min(n, considered) ? this->List[i + 1].Key : NoKey;
    if (this->TryCollapse(u, nextKey))
    {
      ++applied;
      if (!this->Report())
      {
        return NoKey;
      }
    }
  }
  this->Forced = applied == 0;
  this->CollectNext();
  return applied;
}

//------------------------------------------------------------------------------
void PassSchedule::NextStamp()
{
  ++this->Passes;
  if (++this->Stamp == 0)
  {
    // Out of byte stamps: clear them once every 255 passes.
    std::fill(this->Touched.begin(), this->Touched.end(), uint8_t(0));
    this->Stamp = 1;
  }
  this->TouchedList.clear();
}

//------------------------------------------------------------------------------
bool PassSchedule::Report()
{
  const CollapseEngine& e = this->Engine;
  if (e.GetRemovedCount() < this->NextReport)
  {
    return true;
  }
  this->NextReport += this->ReportEvery;
  return this->Engine.ReportProgress(
    0.05 + 0.9 * double(e.GetRemovedCount()) / double(e.GetNumberOfVertices()));
}

//------------------------------------------------------------------------------
bool PassSchedule::Run()
{
  CollapseEngine& e = this->Engine;
  const uint32_t n = e.GetNumberOfVertices();
  this->ReportEvery = std::max<size_t>(1, n / 200);
  this->NextReport = this->ReportEvery;
  this->Touched.assign(n, 0);
  this->Live.resize(n);
  for (uint32_t v = 0; v < n; ++v)
  {
    this->Live[v] = v;
  }
  // Every list holds at most one entry per vertex: reserved once, so that
  // the passes do not allocate.
  this->List.reserve(n);
  this->Fresh.reserve(n);
  this->Buffer.reserve(n);
  this->TouchedList.reserve(n);
  this->Collect();
  for (;;)
  {
    // Relaxed only once no vertex has a candidate (as the greedy schedule does
    // when its heap is empty): a pass that applied nothing has blocked or
    // re-keyed all it considered, so the passes make progress.
    if (this->List.empty())
    {
      if (!e.Relax())
      {
        return true;
      }
      this->Collect();
      this->Forced = false;
      continue;
    }
    if (this->RunPass() == NoKey)
    {
      return false;
    }
  }
}
}
}
