// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_CollapseRecords_h
#define timecritical_CollapseRecords_h

/*
 * Internal to TimeCritical::MeshCore: the records of the collapse engine
 * (triangle, vertex, candidate), their bits, and the bounds on its work.
 */

#include "CollapseGeometry.h"

#include <cstdint>
#include <limits>

namespace timecritical
{
namespace collapse
{
constexpr uint32_t Invalid = std::numeric_limits<uint32_t>::max();

// Triangle flag bits: bit e (e = 0..2) marks edge e, from corner e to corner
// (e + 1) % 3, as a constraint edge (boundary, feature, non-manifold or
// orientation seam); DeadFlag marks a collapsed triangle.
constexpr uint32_t DeadFlag = 8u;

/*
 * Work bounds for degenerate input. Checking or applying a collapse walks the
 * fans of both ends, and a vertex's candidates are re-evaluated (its fan
 * walked) whenever a neighbour collapses: a vertex of valence V costs O(V)
 * per collapse around it, and trying its targets one by one O(V^2) per
 * attempt, again after every change around it: quadratic time on a crumpled
 * fan of thousands of triangles. A vertex with more
 * than MaximumFanSize live triangles is parked: it neither collapses nor
 * takes a collapse (CheckCollapse refuses, Reevaluate blocks it without a
 * walk) until the collapses around it shrink its fan, so no collapse walks a
 * fan above twice the bound. Real meshes stay far below it (the poles of a
 * lat/long sphere shrink before they move), so their output does not depend
 * on it.
 */
constexpr uint32_t MaximumFanSize = 1024;
/// Largest fan of a collapse's surviving vertex whose blocked neighbours are
/// retried at once (larger: when the level ends); real meshes stay below it.
constexpr uint32_t RetryFanSize = 128;
/// Fan triangles that the search for a legal alternative target of a vertex
/// may walk before the vertex is blocked (real meshes stay below it).
constexpr uint64_t AlternativeWorkBudget = 16 * uint64_t(MaximumFanSize);

// Relaxation levels, tried in order whenever no legal collapse is left.
enum Level : int
{
  LevelAll = 0,           // every check, slivers included
  LevelNoSliver = 1,      // sliver rejection off
  LevelNoConstraints = 2, // boundaries, feature edges and pinch vertices released
  LevelTopologyOnly = 3,  // only the link condition (no geometric checks)
  LevelEnd = 4
};

// Vertex kinds, which restrict where a vertex may go while constraints hold.
enum Kind : uint8_t
{
  KindClosed = 0, // interior vertex with one closed, consistently oriented fan
  KindFree = 1,   // unconstrained, but its fan is open or irregular
  KindCurve = 2,  // on a boundary / feature curve: slides along it only
  KindFixed = 3   // curve corner or end, or non-manifold (pinch) vertex: stays
};

// Vertex state bits.
constexpr uint8_t RemovedBit = 1;
constexpr uint8_t BlockedBit = 2; // no legal collapse at this level until its neighbourhood changes

// Scratch marks: (stamp << 3) | bits, so that a fresh stamp clears them all.
constexpr uint32_t MarkU = 1;       // neighbour of u
constexpr uint32_t MarkAllowed = 2; // opposite corner of a triangle on the edge (u, w)
constexpr uint32_t MarkW = 4;       // neighbour of w
constexpr uint32_t MarkBits = 7;


/// Hint that p will be read soon (the greedy order visits the mesh at random).
inline void Prefetch(const void* p)
{
#if defined(__GNUC__) || defined(__clang__)
  __builtin_prefetch(p);
#else
  (void)p;
#endif
}

inline uint32_t Next3(uint32_t i)
{
  return i == 2 ? 0 : i + 1;
}
inline uint32_t Prev3(uint32_t i)
{
  return i == 0 ? 2 : i - 1;
}

/// A triangle: its corners (rewritten by the collapses) and flag bits (see DeadFlag).
struct Tri
{
  uint32_t V[3];
  uint32_t Flags;

  uint32_t CornerOf(uint32_t v) const { return this->V[0] == v ? 0 : (this->V[1] == v ? 1 : 2); }
  bool Has(uint32_t v) const { return this->V[0] == v || this->V[1] == v || this->V[2] == v; }
};

/// Index of the edge joining corners p and q of a triangle.
inline uint32_t EdgeIndex(uint32_t p, uint32_t q)
{
  return Next3(p) == q ? p : q;
}


/// The hot per-vertex record: one cache line.
struct alignas(64) Vertex
{
  Vec3 P;        // position in the unit box
  float Key;     // key in the heap (+inf when not in it)
  uint32_t Tag; // the schedule's own word about the vertex (the engine never reads it)
  uint32_t AdjStart;
  uint32_t AdjCount; // entries in the list (dead triangles possibly included)
  uint32_t AdjCap;
  uint32_t Target;    // cheapest allowed neighbour to collapse into (Invalid: none)
  uint32_t Mark;      // scratch, see MarkU etc.
  uint32_t LiveCount; // live triangles around the vertex
  uint8_t Kind;
  uint8_t State;
  uint8_t TagByte; // the schedule's own byte (the engine never reads it)
};
static_assert(sizeof(Vertex) == 64, "one cache line per vertex");

/// A target of a collapse and its cost.
struct Candidate
{
  double Cost;
  uint32_t Target;
};
}
}

#endif
