// SPDX-License-Identifier: BSD-3-Clause
#include "ViewDependentRefinementInternals.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <limits>

namespace timecritical
{
using vdr::Buckets;
using vdr::BucketOf;
using vdr::BucketShift;
using vdr::MergeOrder;
using vdr::None;
using vdr::SplitOrder;

namespace
{
// Full and nothing worth a trade: only splits within the slack may still be
// made; give up after this many candidates in a row that do not fit
// (otherwise the whole split heap is popped every frame).
constexpr uint32_t MisfitLimit = 32;
}

//------------------------------------------------------------------------------
bool ViewDependentRefinement::OutOfTime()
{
  if (this->OperationLimit > 0 &&
    this->Statistics.Splits + this->Statistics.Merges + this->UndoneOperations >=
      this->OperationLimit)
  {
    return this->Statistics.Interrupted = true;
  }
  // The clock is read every 16 calls: the overrun is a few operations at most.
  if (this->Deadline > 0.0 && (++this->Checks & 15) == 0 &&
    std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count() >=
      this->Deadline)
  {
    return this->Statistics.Interrupted = true;
  }
  return false;
}

void ViewDependentRefinement::OfferSplit(uint32_t w)
{
  // w's (new) candidate, keyed from its list entry (its node is there; the
  // key is not cached: the heap entry carries it). Sub-threshold detail is
  // never bought, even when the budget allows it.
  const uint32_t p = this->Link[w].SplitPos;
  if (p == None || this->SplitSize == this->SplitHeap.size())
  {
    return;
  }
  Candidate& e = this->SplitList[p];
  if (this->Touched[e.Id] == this->TouchFrame || this->SurelyUnwanted(e.Data))
  {
    return;
  }
  Sleep sleep;
  const float key = static_cast<float>(this->Evaluate(e.Data, &sleep));
  this->Doze(e, sleep); // for the next updates
  if (this->IsWanted(key))
  {
    this->SplitHeap[this->SplitSize++] = HeapEntry{ key, (e.Id << 1) | 1 };
    std::push_heap(this->SplitHeap.data(), this->SplitHeap.data() + this->SplitSize, SplitOrder());
  }
}

void ViewDependentRefinement::SortPending(uint32_t size)
{
  // Counting sort by bucket into Sorted; afterwards BucketStart[b] is where
  // bucket b ends (and b + 1 starts).
  uint32_t* start = this->BucketStart.data();
  std::fill(start, start + Buckets + 1, 0u);
  for (uint32_t i = 0; i < size; ++i)
  {
    ++start[BucketOf(this->Pending[i].Key) + 1];
  }
  for (uint32_t b = 0; b < Buckets; ++b)
  {
    start[b + 1] += start[b];
  }
  for (uint32_t i = 0; i < size; ++i)
  {
    this->Sorted[start[BucketOf(this->Pending[i].Key)]++] = this->Pending[i];
  }
  this->PendingEnd = size;
  this->SplitFloor = std::numeric_limits<float>::infinity();
}

void ViewDependentRefinement::ReachSplitTop()
{
  // What is not taken yet, Sorted[0, PendingEnd), lies in lower buckets, so
  // below SplitFloor: the top may be popped when it is not below it.
  HeapEntry* split = this->SplitHeap.data();
  while (this->PendingEnd > 0 && (this->SplitSize == 0 || split[0].Key < this->SplitFloor))
  {
    const uint32_t bucket = BucketOf(this->Sorted[this->PendingEnd - 1].Key);
    const uint32_t first = bucket > 0 ? this->BucketStart[bucket - 1] : 0;
    const uint32_t count = this->PendingEnd - first;
    const uint32_t bits = bucket << BucketShift;
    std::memcpy(&this->SplitFloor, &bits, sizeof(bits));
    this->PendingEnd = first;
    std::memcpy(split + this->SplitSize, this->Sorted.data() + first, count * sizeof(HeapEntry));
    if (count > this->SplitSize)
    {
      this->SplitSize += count;
      std::make_heap(split, split + this->SplitSize, SplitOrder());
    }
    else
    {
      for (uint32_t i = 0; i < count; ++i)
      {
        ++this->SplitSize;
        std::push_heap(split, split + this->SplitSize, SplitOrder());
      }
    }
  }
}

void ViewDependentRefinement::OfferMerge(uint32_t v)
{
  if (v == None || this->Touched[v] == this->TouchFrame || this->MergeSize == this->MergeHeap.size() ||
    !this->CanMerge(v))
  {
    return;
  }
  this->MergeHeap[this->MergeSize++] = HeapEntry{ this->Key(v), v };
  std::push_heap(this->MergeHeap.data(), this->MergeHeap.data() + this->MergeSize, MergeOrder());
}

/*
 * Budget update: first the fixed-accuracy merges (tau is a floor: nothing
 * below it stays or is split), then dual heaps of candidate events only,
 * built by heapify: split the largest projected error while it fits, merge
 * the smallest while over the budget, and trade a smaller merge for a larger
 * split when full. Every vertex is split or merged at most once per update
 * (Touched), so the work is bounded by the candidates and the changes.
 */
const RefinementStatistics& ViewDependentRefinement::UpdateBudget(
  uint32_t triangleBudget, double timeLimitSeconds)
{
  const auto start = std::chrono::steady_clock::now();
  this->Statistics = RefinementStatistics{};
  this->UndoneOperations = 0;
  this->Checks = 0;
  this->Deadline = timeLimitSeconds > 0.0
    ? std::chrono::duration<double>(start.time_since_epoch()).count() + timeLimitSeconds
    : 0.0;
  this->Bounded = this->Deadline > 0.0 || this->OperationLimit > 0;
  this->PrepareView();
  this->NextFrame();
  // After an interrupted update the next one continues it: what that one split,
  // merged or left out stays so (otherwise calls whose bound is spent on the
  // same failed candidates would never progress).
  if (!this->ContinueUpdate || this->TouchFrame == 0)
  {
    this->TouchFrame = this->Frame;
  }
  this->Mode = UpdateMode::None;
  this->MergeUnwanted();
  if (!this->Statistics.Interrupted)
  {
    this->QueueBudgetCandidates();
    this->SpendBudget(triangleBudget);
  }
  this->Mode = UpdateMode::None;
  this->Bounded = false;
  this->ContinueUpdate = this->Statistics.Interrupted;
  this->Statistics.DisplayVertices = this->ActiveVertexCount;
  this->Statistics.DisplayTriangles = this->DisplayCount;
  this->Statistics.Seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return this->Statistics;
}

void ViewDependentRefinement::QueueBudgetCandidates()
{
  // The candidates' keys (or bounds) go to Pending, sorted into key buckets
  // (float bits: 8 per octave); the split heap takes a bucket only when its
  // top could be below the bucket's keys (ReachSplitTop()), so most of them
  // are never heapified.
  HeapEntry* pending = this->Pending.data();
  uint32_t pendingSize = 0;
  this->SplitSize = 0;
  for (uint32_t i = 0; i < this->SplitListSize; ++i)
  {
    Candidate& e = this->SplitList[i];
    if (e.WakeAt > this->Odometer || this->SurelyUnwanted(e.Data))
    {
      continue;
    }
    if (e.FactorUntil > this->Odometer)
    {
      // Lazy: a bound now, the key when it reaches the top (most never do).
      const double bound = this->KeyBound(e.Data, e.Factor);
      if (!(this->PixelThreshold > 0.0 && bound <= this->PixelThreshold))
      {
        pending[pendingSize++] = HeapEntry{ static_cast<float>(bound), e.Id << 1 };
      }
      continue;
    }
    Sleep sleep;
    const float key = static_cast<float>(this->Evaluate(e.Data, &sleep));
    this->Doze(e, sleep);
    if (this->IsWanted(key))
    {
      pending[pendingSize++] = HeapEntry{ key, (e.Id << 1) | 1 };
    }
  }
  this->SortPending(pendingSize);
  HeapEntry* merge = this->MergeHeap.data();
  this->MergeSize = 0;
  for (uint32_t i = 0; i < this->MergeListSize; ++i)
  {
    const uint32_t x = this->MergeList[i]; // CanMerge(x)
    merge[this->MergeSize++] = HeapEntry{ this->Key(x), x };
  }
  std::make_heap(merge, merge + this->MergeSize, MergeOrder());
}

uint32_t ViewDependentRefinement::PopMerge()
{
  // The smallest mergeable entry; None when there is none.
  HeapEntry* merge = this->MergeHeap.data();
  while (this->MergeSize > 0)
  {
    std::pop_heap(merge, merge + this->MergeSize, MergeOrder());
    const uint32_t m = merge[--this->MergeSize].Id;
    if (this->Touched[m] != this->TouchFrame && this->CanMerge(m))
    {
      return m;
    }
  }
  return None;
}

const ViewDependentRefinement::HeapEntry* ViewDependentRefinement::TopMerge()
{
  HeapEntry* merge = this->MergeHeap.data();
  while (this->MergeSize > 0)
  {
    const uint32_t m = merge[0].Id;
    if (this->Touched[m] != this->TouchFrame && this->CanMerge(m))
    {
      return merge;
    }
    std::pop_heap(merge, merge + this->MergeSize, MergeOrder());
    --this->MergeSize;
  }
  return nullptr;
}

void ViewDependentRefinement::PopSplit()
{
  std::pop_heap(this->SplitHeap.data(), this->SplitHeap.data() + this->SplitSize, SplitOrder());
  --this->SplitSize;
}

void ViewDependentRefinement::UndoMerges(uint32_t from)
{
  // Replays the merges of a failed trade made since TradeLog[from] backwards
  // (legal: it restores the front before them) and offers them as merge
  // candidates again.
  const uint32_t count = this->TradeLogSize - from;
  this->Mode = UpdateMode::None;
  while (this->TradeLogSize > from)
  {
    const uint32_t x = this->TradeLog[--this->TradeLogSize];
    this->Split(x);
    this->Touched[x] = 0;
  }
  this->Mode = UpdateMode::Budget;
  for (uint32_t i = from; i < from + count; ++i)
  {
    this->OfferMerge(this->TradeLog[i]);
  }
  this->Statistics.Splits -= count;
  this->Statistics.Merges -= count;
  this->UndoneOperations += 2 * count;
}

void ViewDependentRefinement::SpendBudget(uint32_t triangleBudget)
{
  this->Mode = UpdateMode::Budget;
  uint32_t misfits = 0; // candidates in a row that did not fit (MisfitLimit)
  this->TradeLogSize = 0;
  for (;;)
  {
    if (this->Bounded && this->TradeLogSize == 0 && this->OutOfTime())
    {
      break; // every split, forced chain and merge is complete: the front is valid
    }
    if (this->DisplayCount > triangleBudget)
    {
      const uint32_t m = this->PopMerge();
      if (m == None)
      {
        break;
      }
      this->Merge(m);
      continue;
    }
    this->ReachSplitTop();
    if (this->SplitSize == 0)
    {
      break;
    }
    const HeapEntry top = this->SplitHeap[0];
    const uint32_t s = top.Id >> 1;
    if (this->Active[s] || this->Touched[s] == this->TouchFrame ||
      !this->Active[this->Link[s].Parent] || this->NextChild(this->Link[s].Parent) != s)
    {
      this->PopSplit();
      continue;
    }
    if ((top.Id & 1) == 0)
    {
      // A bound on top: its key now (no larger), back in its place if wanted.
      this->PopSplit();
      if (this->Wanted(s))
      {
        HeapEntry* split = this->SplitHeap.data();
        split[this->SplitSize++] = HeapEntry{ this->Key(s), (s << 1) | 1 };
        std::push_heap(split, split + this->SplitSize, SplitOrder());
      }
      continue;
    }
    const uint32_t cost = this->Link[s].BlockEnd - this->Link[s].BlockBegin;
    if (this->DisplayCount + cost <= triangleBudget)
    {
      this->PopSplit();
      this->SplitPaidFor(top, triangleBudget);
      continue;
    }
    if (!this->TradeForSplit(top, triangleBudget, misfits))
    {
      break;
    }
  }
  this->TradeLogSize = 0;
}

void ViewDependentRefinement::SplitPaidFor(const HeapEntry& top, uint32_t triangleBudget)
{
  // Split s, whose own triangles fit, with the splits it forces.
  const uint32_t s = top.Id >> 1;
  this->SplitLogSize = 0;
  const uint32_t paid = this->TradeLogSize; // merges made for s before its splits
  this->ForceSplit(s);
  // The forced splits may overshoot: they are part of the price of s,
  // paid like its own triangles with merges less useful than s.
  while (this->DisplayCount > triangleBudget)
  {
    const HeapEntry* m = this->TopMerge();
    if (m == nullptr || !(m->Key < top.Key))
    {
      break;
    }
    const uint32_t merged = this->PopMerge();
    this->Merge(merged);
    this->TradeLog[this->TradeLogSize++] = merged;
  }
  if (this->DisplayCount <= triangleBudget)
  {
    this->TradeLogSize = 0; // the trade is made
    return;
  }
  // Too dear: replay everything backwards (always legal, it restores
  // the previous front; newest first) and leave s out for this update.
  this->UndoMerges(paid);
  this->Mode = UpdateMode::None;
  const uint32_t forced = this->SplitLogSize;
  while (this->SplitLogSize > 0)
  {
    const uint32_t x = this->SplitLog[--this->SplitLogSize];
    this->Merge(x);
    this->Touched[x] = 0; // may still be split for another candidate
  }
  this->Mode = UpdateMode::Budget;
  this->Touched[s] = this->TouchFrame;
  this->Statistics.Splits -= forced;
  this->Statistics.Merges -= forced;
  this->Statistics.ForcedSplits -= forced > 0 ? forced - 1 : 0;
  this->UndoneOperations += 2 * forced;
  this->UndoMerges(0); // the whole trade
}

bool ViewDependentRefinement::TradeForSplit(
  const HeapEntry& top, uint32_t triangleBudget, uint32_t& misfits)
{
  // Full: trade the least useful merge for the most useful split. False:
  // nothing more fits.
  const uint32_t s = top.Id >> 1;
  if (this->TradeLogSize > 0 && this->TradeFor != s)
  {
    this->TradeLogSize = 0; // cannot happen (s stays on top); keep the merges
  }
  const HeapEntry* m = this->TopMerge();
  if (m == nullptr || !(m->Key < top.Key))
  {
    // Not worth a trade: leave s out and fill what is left with smaller
    // splits (none when nothing is left).
    if (this->TradeLogSize > 0)
    {
      this->UndoMerges(0); // s cannot be paid for with less useful merges
    }
    else if (this->DisplayCount == triangleBudget || ++misfits > MisfitLimit)
    {
      return false;
    }
    this->PopSplit();
    this->Touched[s] = this->TouchFrame;
    return true;
  }
  // A trade is atomic: its merges are logged and undone when s is not
  // made after all, so that a failed trade does not lose detail (and
  // repeated updates settle instead of cycling).
  const uint32_t merged = this->PopMerge();
  this->Merge(merged);
  this->TradeFor = s;
  this->TradeLog[this->TradeLogSize++] = merged;
  return true;
}
}
