// SPDX-License-Identifier: BSD-3-Clause
#include "ViewDependentRefinementInternals.h"

#include <algorithm>
#include <chrono>

namespace timecritical
{
using vdr::None;

void ViewDependentRefinement::NextFrame()
{
  if (++this->Frame == 0) // stamps wrapped: clear them once every 2^32 updates
  {
    for (Links& l : this->Link)
    {
      l.KeyFrame = 0;
    }
    std::fill(this->Touched.begin(), this->Touched.end(), 0u);
    this->Frame = 1;
    this->TouchFrame = 0;
  }
}

void ViewDependentRefinement::MergeUnwanted()
{
  // Finest first: whatever needs a vertex is finer (larger id), so it has
  // been merged or kept before the vertex is looked at, and one pass reaches
  // the fixed point. A merge only releases coarser vertices (pushed here).
  // Only what is mergeable now is queued (CanMerge() first: it is O(1) and
  // spares most priorities): whatever becomes mergeable later is released by
  // a merge here and pushed then.
  uint64_t* bits = this->MergeBits.data();
  size_t top = 0; // highest word that may hold a bit
  bool any = false;
  for (uint32_t i = 0; i < this->MergeListSize; ++i)
  {
    const uint32_t x = this->MergeList[i]; // CanMerge(x)
    if (!this->Wanted(x))
    {
      bits[x >> 6] |= uint64_t(1) << (x & 63);
      top = std::max<size_t>(top, x >> 6);
      any = true;
    }
  }
  // Merges queue the vertices they make mergeable (RefreshMergeCandidate()).
  this->Merging = true;
  for (size_t word = top; any;)
  {
    if (bits[word] == 0)
    {
      if (word == 0)
      {
        break;
      }
      --word;
      continue;
    }
    if (this->Mode == UpdateMode::None && this->Bounded && this->OutOfTime())
    {
      std::fill(bits, bits + word + 1, uint64_t(0)); // nothing stays queued
      break;
    }
    const int bit = 63 - __builtin_clzll(bits[word]);
    bits[word] &= ~(uint64_t(1) << bit);
    const uint32_t x = uint32_t(word * 64 + size_t(bit));
    if (bits[word] != 0) // the next one's record, fetched meanwhile
    {
      TIMECRITICAL_PREFETCH(&this->Link[word * 64 + size_t(63 - __builtin_clzll(bits[word]))]);
    }
    if (this->Link[x].MergePos == None)
    {
      continue; // !CanMerge(x)
    }
    this->PrefetchOperation(x); // most are merged
    if (this->Wanted(x))
    {
      continue;
    }
    this->Merge(x);
  }
  this->Merging = false;
}

const RefinementStatistics& ViewDependentRefinement::UpdateFixedAccuracy()
{
  const auto start = std::chrono::steady_clock::now();
  this->Statistics = RefinementStatistics{};
  this->ContinueUpdate = false;
  this->PrepareView();
  this->NextFrame();
  // Splits: every wanted candidate (next child of a display vertex), with
  // the splits it needs; each split offers its new candidates.
  this->Mode = UpdateMode::Fixed;
  this->WorkSize = 0;
  // The candidates (next child of each display vertex) are decided here,
  // straight from the list's node copies (a sequential read); only the wanted
  // ones are kept. The view alone decides, and only splits happen until the
  // merges, so a kept candidate stays its owner's next child until it is
  // split: at the pop, Active[c] is all there is to check. Each split offers
  // its new candidates the same way (RefreshSplitCandidate()).
  for (uint32_t i = 0; i < this->SplitListSize; ++i)
  {
    Candidate& e = this->SplitList[i];
    if (e.WakeAt > this->Odometer || this->SurelyUnwanted(e.Data) ||
      (e.FactorUntil > this->Odometer && this->PixelThreshold > 0.0 &&
        this->KeyBound(e.Data, e.Factor) <= this->PixelThreshold))
    {
      continue; // asleep, too far, or below tau with any factor it can have
    }
    Sleep sleep;
    if (this->IsWanted(static_cast<float>(this->Evaluate(e.Data, &sleep))))
    {
      this->Work[this->WorkSize++] = e.Id;
    }
    else
    {
      this->Doze(e, sleep);
    }
  }
  while (this->WorkSize > 0)
  {
    const uint32_t c = this->Work[--this->WorkSize];
    if (!this->Active[c])
    {
      this->ForceSplit(c);
    }
  }
  this->Mode = UpdateMode::None;
  this->MergeUnwanted();
  this->Statistics.DisplayVertices = this->ActiveVertexCount;
  this->Statistics.DisplayTriangles = this->DisplayCount;
  this->Statistics.Seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return this->Statistics;
}
}
