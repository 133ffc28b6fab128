// SPDX-License-Identifier: BSD-3-Clause
// Private to the ViewDependentRefinement*.cxx files: the packed per-event
// records, constants shared by the hierarchy tables, the projected error, the
// front and the updates. The small members the per-frame loops call
// (Priority, Key, Wanted, KeyBound, SurelyUnwanted, Doze, CanMerge, NextChild,
// PrefetchOperation) are ordinary out-of-line functions of
// ViewDependentRefinementFront.cxx: inlined into every loop they made the
// fixed-accuracy update slower, with fewer instructions.
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







//------------------------------------------------------------------------------
// The front: what the updates read of it.



}

#endif
