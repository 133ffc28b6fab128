// SPDX-License-Identifier: BSD-3-Clause
#include "ViewDependentRefinementInternals.h"

#include <cstring>

namespace timecritical
{
using vdr::None;

uint32_t ViewDependentRefinement::LastActiveChild(uint32_t w) const
{
  const Links& l = this->Link[w];
  return l.ActiveChildren > 0 ? this->Children[l.ChildBegin + l.ActiveChildren - 1] : None;
}

/*
 * Dependency rule. Vertex v needs, to be displayed: its parent u, its
 * previous sibling (children split in id order), every vertex n of its row,
 * and every event below v whose row holds u (no child of a row vertex n above
 * v, i.e. split before e_v at build time, may be displayed without v). So the front is closed under a static relation
 * "x needs y" with y < x, and:
 * - split e_v is legal iff its needs are displayed (the last condition holds
 *   by closure: such a child would need v), so forced splits never block;
 * - merge e_v is legal iff no display vertex needs v: no displayed child, v is
 *   u's last displayed child, no displayed row holds v, no row vertex has a
 *   displayed child above v (all four counted together in Holds).
 * The row vertices being displayed and not finer than at e_v makes the birth
 * corners of e_v's triangles the nearest displayed ancestors of their corners,
 * so the incremental triangles are the selectively refined mesh of the front.
 */
uint32_t ViewDependentRefinement::NextRequirement(uint32_t v, uint8_t& stage, uint32_t& index) const
{
  // The front only grows during a forced split, so what was displayed stays
  // so and the scan resumes where it stopped (each row is read once).
  const uint32_t u = this->Link[v].Parent;
  switch (stage)
  {
    case 0:
      this->PrefetchOperation(v); // v is split once its needs are
      if (!this->Active[u])
      {
        return u;
      }
      stage = 1;
      [[fallthrough]];
    case 1:
    {
      const uint32_t sibling = this->NextChild(u);
      if (sibling != v)
      {
        return sibling; // an earlier-split sibling (smaller id)
      }
      // A displayed vertex that needs v (e.g. a row vertex's child above v):
      // cannot happen on a closed front; kept as a safe refusal.
      if (this->Holds[v] > 0)
      {
        return None;
      }
      // The events whose row holds u below v (those below v's previous
      // sibling are displayed already: the sibling needed them), then v's row.
      index = this->Link[v].NeedBegin;
      stage = 2;
    }
      [[fallthrough]];
    default:
      for (const uint32_t end = this->Link[v].NeedEnd; index < end; ++index)
      {
        if (!this->Active[this->Needs[index]])
        {
          // The later ones will be split too: their records are fetched
          // meanwhile (a chain of misses per forced split otherwise).
          for (uint32_t i = index + 1; i < end; ++i)
          {
            if (!this->Active[this->Needs[i]])
            {
              TIMECRITICAL_PREFETCH(&this->Link[this->Needs[i]]);
            }
          }
          return this->Needs[index];
        }
      }
      return v;
  }
}

bool ViewDependentRefinement::ForceSplit(uint32_t v)
{
  if (this->Active[v])
  {
    return true;
  }
  // Requirements have strictly smaller ids than what needs them, so the
  // stack never holds more than N entries and cannot cycle.
  uint32_t size = 0;
  auto push = [this, &size](uint32_t x) {
    this->Stack[size] = x;
    this->StackStage[size] = 0;
    ++size;
  };
  push(v);
  while (size > 0)
  {
    const uint32_t x = this->Stack[size - 1];
    if (this->Active[x])
    {
      --size;
      continue;
    }
    const uint32_t r = this->NextRequirement(x, this->StackStage[size - 1], this->StackIndex[size - 1]);
    if (r == None)
    {
      ++this->Statistics.BlockedSplits;
      return false;
    }
    if (r == x)
    {
      this->Split(x);
      if (x != v)
      {
        ++this->Statistics.ForcedSplits;
      }
      --size;
    }
    else
    {
      push(r);
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void ViewDependentRefinement::AddDisplay(uint32_t t)
{
  const uint32_t p = this->DisplayCount++;
  this->DisplayPos[t] = p;
  this->DisplayId[p] = t;
  std::memcpy(&this->Display[3 * size_t(p)], &this->BirthCorners[3 * size_t(t)], 3 * sizeof(uint32_t));
}

void ViewDependentRefinement::RemoveDisplay(uint32_t t)
{
  const uint32_t p = this->DisplayPos[t];
  const uint32_t last = --this->DisplayCount;
  if (p != last)
  {
    const uint32_t moved = this->DisplayId[last];
    this->DisplayId[p] = moved;
    this->DisplayPos[moved] = p;
    std::memcpy(&this->Display[3 * size_t(p)], &this->Display[3 * size_t(last)], 3 * sizeof(uint32_t));
  }
  this->DisplayPos[t] = None;
}

void ViewDependentRefinement::RefreshSplitCandidate(uint32_t w)
{
  Links& l = this->Link[w];
  const uint32_t slot = l.ChildBegin + l.ActiveChildren; // the next child's
  const uint32_t c = this->Active[w] && slot < l.ChildEnd ? this->Children[slot] : None;
  uint32_t& p = l.SplitPos;
  if (c != None)
  {
    if (p == None)
    {
      p = this->SplitListSize++;
    }
    else if (this->SplitList[p].Id == c)
    {
      return;
    }
    Candidate& e = this->SplitList[p] = Candidate{ this->Nodes[slot], c, w, -1.0, -1.0, 0.0f };
    if (this->Mode == UpdateMode::Fixed && !this->SurelyUnwanted(e.Data))
    {
      // A new candidate of the running update: split if wanted, else it may
      // sleep from now on (the next sweeps skip it).
      Sleep sleep;
      if (this->IsWanted(static_cast<float>(this->Evaluate(e.Data, &sleep))))
      {
        this->Work[this->WorkSize++] = c;
      }
      else
      {
        this->Doze(e, sleep);
      }
    }
  }
  else if (p != None)
  {
    const uint32_t last = --this->SplitListSize;
    if (p != last)
    {
      this->SplitList[p] = this->SplitList[last];
      this->Link[this->SplitList[p].Owner].SplitPos = p;
    }
    p = None;
  }
}

void ViewDependentRefinement::RefreshMergeCandidate(uint32_t x)
{
  const bool member = this->CanMerge(x);
  uint32_t& p = this->Link[x].MergePos;
  if (member == (p != None))
  {
    return;
  }
  if (!member)
  {
    this->LeaveMergeCandidates(x);
    return;
  }
  p = this->MergeListSize++;
  this->MergeList[p] = x;
  // A vertex that becomes mergeable goes to the running update's queue
  // (only merges make vertices mergeable, always coarser ones than the merged).
  if (this->Merging)
  {
    this->MergeBits[x >> 6] |= uint64_t(1) << (x & 63);
  }
  else if (this->Mode == UpdateMode::Budget)
  {
    this->OfferMerge(x);
  }
}

void ViewDependentRefinement::LeaveMergeCandidates(uint32_t x)
{
  uint32_t& p = this->Link[x].MergePos;
  if (p != None)
  {
    const uint32_t moved = this->MergeList[--this->MergeListSize];
    this->MergeList[p] = moved;
    this->Link[moved].MergePos = p;
    p = None;
  }
}

void ViewDependentRefinement::Hold(uint32_t x)
{
  if (this->Holds[x]++ == 0)
  {
    this->LeaveMergeCandidates(x);
  }
}

void ViewDependentRefinement::Release(uint32_t x)
{
  if (--this->Holds[x] == 0)
  {
    this->RefreshMergeCandidate(x);
  }
}

void ViewDependentRefinement::Split(uint32_t v)
{
  const uint32_t u = this->Link[v].Parent;
  const uint32_t previous = this->LastActiveChild(u);
  this->Active[v] = 1;
  ++this->Link[u].ActiveChildren;
  ++this->ActiveVertexCount;
  ++this->Statistics.Splits;
  // v needs its parent, its previous sibling and its row; and u's last
  // displayed child moves from `previous` to v, so the events between them
  // whose row holds u now have a row vertex with a displayed child above them.
  this->Hold(u);
  if (previous != None)
  {
    this->Hold(previous);
  }
  const Links& l = this->Link[v];
  for (uint32_t i = l.NeedBegin; i < l.NeedEnd; ++i)
  {
    this->Hold(this->Needs[i]);
  }
  for (uint32_t t = l.BlockBegin; t < l.BlockEnd; ++t)
  {
    this->AddDisplay(t);
  }
  for (uint32_t i = l.StarBegin; i < l.StarEnd; ++i)
  {
    const uint32_t s = this->StarSlots[i];
    const uint32_t p = this->DisplayPos[s / 3];
    if (p != None)
    {
      this->Display[3 * size_t(p) + s % 3] = v;
    }
  }
  this->RefreshSplitCandidate(u);
  this->RefreshSplitCandidate(v);
  this->RefreshMergeCandidate(v); // nothing needs it yet
  if (this->Mode == UpdateMode::Budget)
  {
    this->Touched[v] = this->TouchFrame;
    this->SplitLog[this->SplitLogSize++] = v;
    this->OfferSplit(u);
    this->OfferSplit(v);
  }
}

void ViewDependentRefinement::Merge(uint32_t v)
{
  const uint32_t u = this->Link[v].Parent;
  this->Active[v] = 0;
  --this->Link[u].ActiveChildren;
  --this->ActiveVertexCount;
  ++this->Statistics.Merges;
  this->LeaveMergeCandidates(v);
  // The reverse of Split(); u's last displayed child moves back from v.
  const uint32_t last = this->LastActiveChild(u);
  this->Release(u);
  if (last != None)
  {
    this->Release(last);
  }
  const Links& l = this->Link[v];
  for (uint32_t i = l.NeedBegin; i < l.NeedEnd; ++i)
  {
    this->Release(this->Needs[i]);
  }
  for (uint32_t t = l.BlockBegin; t < l.BlockEnd; ++t)
  {
    this->RemoveDisplay(t);
  }
  for (uint32_t i = l.StarBegin; i < l.StarEnd; ++i)
  {
    const uint32_t s = this->StarSlots[i];
    const uint32_t p = this->DisplayPos[s / 3];
    if (p != None)
    {
      this->Display[3 * size_t(p) + s % 3] = u;
    }
  }
  this->RefreshSplitCandidate(u);
  this->RefreshSplitCandidate(v);
  if (this->Mode == UpdateMode::Budget)
  {
    this->Touched[v] = this->TouchFrame; // (so not offered as u's candidate again)
  }
}
double ViewDependentRefinement::Priority(uint32_t v) const
{
  const uint32_t slot = this->Link[v].Slot;
  return slot != vdr::None ? this->Evaluate(this->Nodes[slot]) : 0.0; // a base vertex has no event
}

void ViewDependentRefinement::Doze(Candidate& e, const Sleep& sleep) const
{
  e.WakeAt = this->Odometer + sleep.Wake;
  e.FactorUntil = this->Odometer + sleep.FactorRadius;
  e.Factor = sleep.Factor;
}

double ViewDependentRefinement::KeyBound(const Node& node, float factor) const
{
  // Evaluate()'s projected error with the current eye over a factor the
  // node's cannot be below, widened by 1e-6 (rounding): >= its key.
  const double dx = node.Center[0] - this->EyeX;
  const double dy = node.Center[1] - this->EyeY;
  const double dz = node.Center[2] - this->EyeZ;
  const double dist = std::sqrt(dx * dx + dy * dy + dz * dz);
  const double r = node.Radius;
  if (!(dist > r) || !(factor > 0.0f))
  {
    return std::numeric_limits<double>::infinity();
  }
  const double nearPlane = this->NearPlane();
  return node.Error * this->PixelsPerUnit / std::max(dist - r, nearPlane) / factor * (1.0 + 1e-6);
}

bool ViewDependentRefinement::SurelyUnwanted(const Node& node) const
{
  // Wanted(v) is false when even the smallest threshold factor leaves the
  // projected error below the threshold, whatever the culling: Priority() is
  // projected / factor with projected = Error * PixelsPerUnit / max(dist - r,
  // near) (perspective). Decided without a square root, against the
  // threshold shrunk by a relative 1e-6, far more than the rounding of
  // Priority() and of its float key, so that this never contradicts Wanted().
  if (!(this->MinimumFactor > 0.0) || !(this->PixelThreshold > 0.0))
  {
    return false;
  }

  const double error = node.Error;
  if (!(error > 0.0))
  {
    return true; // priority 0 or culled
  }
  // projected / factor <= tau' <=> Error * PixelsPerUnit / (MinimumFactor tau') <= max(dist - r, near)
  const double reach = error * this->UnwantedScale;
  if (this->View.Parallel)
  {
    return reach <= 1.0;
  }
  const double r = node.Radius;
  const double nearPlane = this->NearPlane();
  if (reach <= nearPlane)
  {
    return true;
  }
  if (reach < 1e-4 * r)
  {
    return false; // dist - r would cancel too much in Priority() for this margin
  }
  const double dx = node.Center[0] - this->EyeX;
  const double dy = node.Center[1] - this->EyeY;
  const double dz = node.Center[2] - this->EyeZ;
  const double limit = reach + r; // dist >= reach + r
  return dx * dx + dy * dy + dz * dz >= limit * limit;
}

float ViewDependentRefinement::Key(uint32_t v)
{
  Links& l = this->Link[v];
  if (l.KeyFrame != this->Frame)
  {
    l.KeyFrame = this->Frame;
    l.Key = static_cast<float>(this->Priority(v));
  }
  return l.Key;
}

bool ViewDependentRefinement::Wanted(uint32_t v)
{
  const Links& l = this->Link[v];
  if (l.KeyFrame != this->Frame && l.Slot != vdr::None && this->SurelyUnwanted(this->Nodes[l.Slot]))
  {
    return false; // cheaper than Key() (not cached: asked about again rarely)
  }
  return this->IsWanted(this->Key(v));
}

uint32_t ViewDependentRefinement::NextChild(uint32_t w) const
{
  const Links& l = this->Link[w];
  const uint32_t i = l.ChildBegin + l.ActiveChildren;
  return i < l.ChildEnd ? this->Children[i] : vdr::None;
}

bool ViewDependentRefinement::CanMerge(uint32_t v) const
{
  // O(1): whatever needs v is counted by Split() and Merge() (Holds).
  return v >= this->B && this->Active[v] && this->Holds[v] == 0;
}

void ViewDependentRefinement::PrefetchOperation(uint32_t v) const
{
  // What Split(v) or Merge(v) will read at random, all reachable from v's
  // record: fetched together instead of one miss after the other.
  const Links& l = this->Link[v];
  TIMECRITICAL_PREFETCH(&this->Link[l.Parent]);
  TIMECRITICAL_PREFETCH(this->Needs.data() + l.NeedBegin);
  TIMECRITICAL_PREFETCH(this->StarSlots.data() + l.StarBegin);
  TIMECRITICAL_PREFETCH(this->DisplayPos.data() + l.BlockBegin);
  TIMECRITICAL_PREFETCH(this->BirthCorners.data() + 3 * size_t(l.BlockBegin));
  if (l.Slot != vdr::None)
  {
    TIMECRITICAL_PREFETCH(&this->Nodes[l.Slot]);
  }
  if (l.SplitPos != vdr::None)
  {
    TIMECRITICAL_PREFETCH(&this->SplitList[l.SplitPos]);
  }
}

}
