// SPDX-License-Identifier: BSD-3-Clause
// Private to the ViewDependentRefinement*.cxx files: the packed per-event
// records, constants shared by the hierarchy tables, the projected error, the
// front and the updates, and the small members that the per-frame loops of
// several of those files call (inline, so that splitting the class over files
// adds no call to a hot loop).
#ifndef timecritical_ViewDependentRefinementInternals_h
#define timecritical_ViewDependentRefinementInternals_h

#include "ViewDependentRefinement.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#if defined(__GNUC__)
#define TIMECRITICAL_NOINLINE __attribute__((noinline))
#define TIMECRITICAL_ALWAYS_INLINE inline __attribute__((always_inline))
#define TIMECRITICAL_PREFETCH(address) __builtin_prefetch(address)
#else
#define TIMECRITICAL_NOINLINE
#define TIMECRITICAL_ALWAYS_INLINE inline
#define TIMECRITICAL_PREFETCH(address)
#endif

namespace timecritical
{
namespace vdr
{
constexpr uint32_t None = std::numeric_limits<uint32_t>::max();
constexpr double Pi = 3.14159265358979323846;
constexpr int BucketShift = 20; // float bits: sign, exponent, 3 bits of mantissa
constexpr uint32_t Buckets = 1u << (32 - BucketShift);
inline uint32_t BucketOf(float key)
{
  uint32_t bits;
  std::memcpy(&bits, &key, sizeof(bits));
  return key >= 0.0f ? bits >> BucketShift : 0; // ordered like the keys (>= 0)
}

// Split heap: largest key on top; merge heap: smallest key on top (std heaps
// put the largest by the comparator on top). Split entries hold 2 id + 1 for a
// key, 2 id for a bound on it (lazy): at equal keys the smaller id first, and
// a vertex's bound before its key, as if all were keys.
struct SplitOrder
{
  template <typename E>
  bool operator()(const E& a, const E& b) const
  {
    return a.Key < b.Key || (a.Key == b.Key && a.Id > b.Id);
  }
};
struct MergeOrder
{
  template <typename E>
  bool operator()(const E& a, const E& b) const
  {
    return a.Key > b.Key || (a.Key == b.Key && a.Id < b.Id);
  }
};
}

/// View attributes of event e_v (or of a root), packed for the per-frame sweep
/// (40 bytes: what Priority() reads, no angles, so no trigonometry per node).
struct ViewDependentRefinement::Node
{
  float Center[3]; // parent's position
  float Radius;
  float Error;
  float Axis[3];
  float Cos; // cone half-angle theta: cosine (-1: whole sphere) and sine
  float Sin;
};

/// A split candidate: the next child of display vertex Owner, with a copy of
/// its node so that the per-frame sweep reads one sequential array.
struct ViewDependentRefinement::Candidate
{
  Node Data;
  uint32_t Id;
  uint32_t Owner;
  double WakeAt;      // surely unwanted while Odometer < WakeAt (see Evaluate())
  double FactorUntil; // its threshold factor cannot drop below Factor while Odometer < FactorUntil
  float Factor;
};

//------------------------------------------------------------------------------
// Projected error: the cheap bounds the sweeps try before Evaluate().

inline double ViewDependentRefinement::Priority(uint32_t v) const
{
  const uint32_t slot = this->Link[v].Slot;
  return slot != vdr::None ? this->Evaluate(this->Nodes[slot]) : 0.0; // a base vertex has no event
}

inline void ViewDependentRefinement::Doze(Candidate& e, const Sleep& sleep) const
{
  e.WakeAt = this->Odometer + sleep.Wake;
  e.FactorUntil = this->Odometer + sleep.FactorRadius;
  e.Factor = sleep.Factor;
}

inline double ViewDependentRefinement::KeyBound(const Node& node, float factor) const
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

inline bool ViewDependentRefinement::SurelyUnwanted(const Node& node) const
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

inline float ViewDependentRefinement::Key(uint32_t v)
{
  Links& l = this->Link[v];
  if (l.KeyFrame != this->Frame)
  {
    l.KeyFrame = this->Frame;
    l.Key = static_cast<float>(this->Priority(v));
  }
  return l.Key;
}

inline bool ViewDependentRefinement::Wanted(uint32_t v)
{
  const Links& l = this->Link[v];
  if (l.KeyFrame != this->Frame && l.Slot != vdr::None && this->SurelyUnwanted(this->Nodes[l.Slot]))
  {
    return false; // cheaper than Key() (not cached: asked about again rarely)
  }
  return this->IsWanted(this->Key(v));
}

//------------------------------------------------------------------------------
// The front: what the updates read of it.

inline uint32_t ViewDependentRefinement::NextChild(uint32_t w) const
{
  const Links& l = this->Link[w];
  const uint32_t i = l.ChildBegin + l.ActiveChildren;
  return i < l.ChildEnd ? this->Children[i] : vdr::None;
}

inline bool ViewDependentRefinement::CanMerge(uint32_t v) const
{
  // O(1): whatever needs v is counted by Split() and Merge() (Holds).
  return v >= this->B && this->Active[v] && this->Holds[v] == 0;
}

inline void ViewDependentRefinement::PrefetchOperation(uint32_t v) const
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

#endif
