// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_CollapseEngine_h
#define timecritical_CollapseEngine_h

/*
 * Internal to TimeCritical::MeshCore: the half-edge collapse engine shared
 * by TOMBuilder (greedy schedule) and MergeTreeBuilder (independent sets by
 * level), with its records. Not an API: it may change with the builders.
 * Everything lives in namespace timecritical::collapse.
 */

#include "TOMBuilder.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h> // CostLanes<DoublePair>: two costs per instruction
#endif

namespace timecritical
{
namespace collapse
{
constexpr uint32_t Invalid = std::numeric_limits<uint32_t>::max();
constexpr double Pi = 3.14159265358979323846;
// Weight of the tie-breaking "moment" term of the collapse cost (unit box units).
constexpr double EdgeLengthWeight = 1e-7;

// Triangle flag bits: bit e (e = 0..2) marks edge e, from corner e to corner
// (e + 1) % 3, as a constraint edge (boundary, feature, non-manifold or
// orientation seam); DeadFlag marks a collapsed triangle.
constexpr uint32_t DeadFlag = 8u;

/*
 * Work bounds for degenerate input. Checking or applying a collapse walks the
 * fans of both ends, and a vertex's candidates are re-evaluated (its fan
 * walked) whenever a neighbour collapses: a vertex of valence V costs O(V)
 * per collapse around it, and trying its targets one by one O(V^2) per
 * attempt, again after every change around it (a crumpled fan of 4,000
 * triangles took 20 s, 60 times the 1,000-triangle one). A vertex with more
 * than MaximumFanSize live triangles is parked: it neither collapses nor
 * takes a collapse (CheckCollapse refuses, Reevaluate blocks it without a
 * walk) until the collapses around it shrink its fan, so no collapse walks a
 * fan above twice the bound. Real meshes stay far below it (the largest fan
 * in a collapse of the shared meshes has 81 triangles; the 1,024-triangle
 * poles of a lat/long sphere shrink before they move): their output is
 * unchanged.
 */
constexpr uint32_t MaximumFanSize = 1024;
/// Largest fan of a collapse's surviving vertex whose blocked neighbours are
/// retried at once (larger: when the level ends; real meshes reach 38).
constexpr uint32_t RetryFanSize = 128;
/// Fan triangles that the search for a legal alternative target of a vertex
/// may walk before the vertex is blocked (the shared meshes use up to 8,771,
/// on fandisk).
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

/*
 * Large working arrays go on transparent huge pages where the system allows
 * it (Linux, THP in "madvise" mode or better). The build touches a few
 * hundred bytes per triangle of fresh memory and then reads it in random
 * order: with 4 KiB pages the page faults and TLB misses cost about as much
 * as the simplification itself.
 */
constexpr size_t HugePageThreshold = size_t(1) << 20;

/// Best effort: asks for huge pages on the 2 MiB-aligned interior of [p, p + bytes).
void AdviseHugePages(void* p, size_t bytes);

/// A 2 MiB-aligned anonymous mapping of at least `bytes` advised for huge pages
/// (null where the system has no such advice: use the ordinary allocator then).
void* AllocateHugePageBlock(size_t bytes);
/// Unmaps a block of AllocateHugePageBlock; false (nothing done) where it gives none.
bool FreeHugePageBlock(void* p, size_t bytes);

/// Reserves room for n elements in an (empty) vector, on huge pages if possible.
template <typename V>
void ReserveHuge(V& v, size_t n)
{
  v.reserve(n);
  AdviseHugePages(v.data(), n * sizeof(typename V::value_type));
}

/// Allocator of the large internal arrays: 2 MiB-aligned blocks advised for huge pages.
template <typename T>
struct HugePageAllocator
{
  using value_type = T;
  HugePageAllocator() = default;
  template <typename U>
  HugePageAllocator(const HugePageAllocator<U>&) // NOLINT: implicit by design
  {
  }
  T* allocate(size_t n)
  {
    if (n * sizeof(T) >= HugePageThreshold)
    {
      if (void* p = AllocateHugePageBlock(n * sizeof(T)))
      {
        return static_cast<T*>(p);
      }
    }
    return std::allocator<T>().allocate(n);
  }
  void deallocate(T* p, size_t n)
  {
    if (n * sizeof(T) >= HugePageThreshold && FreeHugePageBlock(p, n * sizeof(T)))
    {
      return;
    }
    std::allocator<T>().deallocate(p, n);
  }
  /// Default-initialises (trivial types stay uninitialised): the arrays are
  /// filled right after being sized, so zeroing them first would be wasted.
  template <typename U>
  void construct(U* p) noexcept
  {
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args)
  {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
  template <typename U>
  bool operator==(const HugePageAllocator<U>&) const
  {
    return true;
  }
  template <typename U>
  bool operator!=(const HugePageAllocator<U>&) const
  {
    return false;
  }
};

template <typename T>
using BigVector = std::vector<T, HugePageAllocator<T>>;

/**
 * Working memory handed on: the storage of arrays a step has finished with
 * (moved in, freed with this object), from which a later step takes its own
 * arrays. Fresh memory costs a page fault and the zeroing of every page
 * (MergeTreeBuilder: a tenth of the build when ComputeMergeTree's arrays
 * were fresh); reused memory costs neither.
 */
class ScratchBlocks
{
public:
  /// Takes over the storage of v, whose contents are dead.
  template <typename T>
  void Add(BigVector<T>&& v)
  {
    auto owner = std::make_shared<BigVector<T>>(std::move(v));
    const size_t bytes = owner->capacity() * sizeof(T);
    if (bytes > 0)
    {
      unsigned char* data = reinterpret_cast<unsigned char*>(owner->data());
      this->Blocks.push_back({ data, bytes, 0, std::move(owner) });
    }
  }

  /// Room for n objects of T (trivial types only, left uninitialised) from the
  /// block with the least room that holds them; null when none does.
  template <typename T>
  T* Take(size_t n)
  {
    static_assert(std::is_trivial<T>::value, "raw storage for trivial types only");
    const size_t bytes = n * sizeof(T);
    Block* best = nullptr;
    size_t bestStart = 0;
    for (Block& b : this->Blocks)
    {
      const uintptr_t base = reinterpret_cast<uintptr_t>(b.Data);
      const uintptr_t first = (base + b.Used + alignof(T) - 1) & ~uintptr_t(alignof(T) - 1);
      const size_t start = static_cast<size_t>(first - base);
      if (start <= b.Size && b.Size - start >= bytes &&
        (!best || b.Size - start < best->Size - bestStart))
      {
        best = &b;
        bestStart = start;
      }
    }
    if (!best || n == 0)
    {
      return nullptr;
    }
    best->Used = bestStart + bytes;
    T* p = reinterpret_cast<T*>(best->Data + bestStart);
    for (size_t i = 0; i < n; ++i)
    {
      ::new (static_cast<void*>(p + i)) T; // starts the objects' lifetime; no code
    }
    return p;
  }

private:
  struct Block
  {
    unsigned char* Data;
    size_t Size;
    size_t Used;
    std::shared_ptr<void> Owner;
  };
  std::vector<Block> Blocks;
};
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

struct Vec3
{
  double X, Y, Z;
};
inline Vec3 Sub(const Vec3& a, const Vec3& b)
{
  return { a.X - b.X, a.Y - b.Y, a.Z - b.Z };
}
inline Vec3 Cross(const Vec3& a, const Vec3& b)
{
  return { a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X };
}
inline double Dot(const Vec3& a, const Vec3& b)
{
  return a.X * b.X + a.Y * b.Y + a.Z * b.Z;
}
inline Vec3 TriangleNormal(const Vec3& a, const Vec3& b, const Vec3& c)
{
  return Cross(Sub(b, a), Sub(c, a));
}

/// Symmetric quadric Q(p) = p^T A p + 2 b.p + c.
struct Quadric
{
  double A00 = 0, A01 = 0, A02 = 0, A11 = 0, A12 = 0, A22 = 0;
  double B0 = 0, B1 = 0, B2 = 0, C = 0;

  /// Adds weight * (distance to the plane n.p + d = 0)^2, n of unit length.
  void AddPlane(const Vec3& n, double d, double weight)
  {
    this->A00 += weight * n.X * n.X;
    this->A01 += weight * n.X * n.Y;
    this->A02 += weight * n.X * n.Z;
    this->A11 += weight * n.Y * n.Y;
    this->A12 += weight * n.Y * n.Z;
    this->A22 += weight * n.Z * n.Z;
    this->B0 += weight * d * n.X;
    this->B1 += weight * d * n.Y;
    this->B2 += weight * d * n.Z;
    this->C += weight * d * d;
  }
  void Add(const Quadric& q)
  {
    this->A00 += q.A00;
    this->A01 += q.A01;
    this->A02 += q.A02;
    this->A11 += q.A11;
    this->A12 += q.A12;
    this->A22 += q.A22;
    this->B0 += q.B0;
    this->B1 += q.B1;
    this->B2 += q.B2;
    this->C += q.C;
  }
  double Evaluate(const Vec3& p) const
  {
    const double x = p.X, y = p.Y, z = p.Z;
    const double r = x * (this->A00 * x + 2.0 * (this->A01 * y + this->A02 * z + this->B0)) +
      y * (this->A11 * y + 2.0 * (this->A12 * z + this->B1)) + z * (this->A22 * z + 2.0 * this->B2) +
      this->C;
    return r > 0.0 ? r : 0.0; // cancellation can dip slightly below 0
  }
};

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

/**
 * The per-vertex quadric (face planes + weighted constraint planes, which
 * order the collapses), read only to compute the vertex's own candidates.
 *
 * It is stored relative to the vertex's own position p0, as
 * Q(p0 + d) = C + 2 G.d + d^T A d, which is well conditioned even in single
 * precision: d is an edge length or so, and C is the error accumulated at the
 * vertex itself. Single precision fits the record in one cache line.
 */
struct alignas(64) QuadricRecord
{
  float A00, A01, A02, A11, A12, A22;
  float G0, G1, G2;
  float C;
  float FaceWeight; // total area behind the face planes
  uint32_t Slot;    // index into the constraint records, Invalid when none
  double InverseRootWeight; // 1 / sqrt(FaceWeight), see SetFaceWeight
};
static_assert(sizeof(QuadricRecord) == 64, "one cache line per quadric");

/// Adds the symmetric matrix of m (any record with A00 ... A22) to r's, in
/// single precision: the one place where a record's matrix grows.
template <typename M>
inline void AddMatrix(QuadricRecord& r, const M& m)
{
  r.A00 = static_cast<float>(r.A00 + m.A00);
  r.A01 = static_cast<float>(r.A01 + m.A01);
  r.A02 = static_cast<float>(r.A02 + m.A02);
  r.A11 = static_cast<float>(r.A11 + m.A11);
  r.A12 = static_cast<float>(r.A12 + m.A12);
  r.A22 = static_cast<float>(r.A22 + m.A22);
}

/// Sets the face weight of r and its inverse square root, which every cost
/// evaluation reads (CollapseEngine::Cost): computed once per change, not per
/// evaluation.
inline void SetFaceWeight(QuadricRecord& r, float weight)
{
  r.FaceWeight = weight;
  r.InverseRootWeight = 1.0 / std::sqrt(double(std::max(weight, std::numeric_limits<float>::min())));
}

/// A QuadricRecord in double precision, for evaluation and merging.
struct LocalQuadric
{
  double A00, A01, A02, A11, A12, A22, G0, G1, G2, C;
  Vec3 Origin;
  double Weight;            // area behind the face planes
  double InverseRootWeight; // 1 / sqrt(Weight), see CollapseEngine::Cost

  LocalQuadric(const QuadricRecord& r, const Vec3& origin)
    : A00(r.A00)
    , A01(r.A01)
    , A02(r.A02)
    , A11(r.A11)
    , A12(r.A12)
    , A22(r.A22)
    , G0(r.G0)
    , G1(r.G1)
    , G2(r.G2)
    , C(r.C)
    , Origin(origin)
    , Weight(r.FaceWeight)
    , InverseRootWeight(r.InverseRootWeight)
  {
  }
  /// A d, for an offset d from the origin.
  Vec3 Apply(const Vec3& d) const;
  /// Q(p), at least 0.
  double Evaluate(const Vec3& p) const;
  /// Adds this quadric, re-expressed around newOrigin, to the record r (stored around newOrigin).
  void AddTo(QuadricRecord& r, const Vec3& newOrigin) const
  {
    const Vec3 d = Sub(newOrigin, this->Origin);
    const Vec3 ad = this->Apply(d);
    AddMatrix(r, *this);
    r.G0 = static_cast<float>(r.G0 + this->G0 + ad.X);
    r.G1 = static_cast<float>(r.G1 + this->G1 + ad.Y);
    r.G2 = static_cast<float>(r.G2 + this->G2 + ad.Z);
    r.C = static_cast<float>(r.C + this->Evaluate(newOrigin));
  }
};

/// KeepPositive(r): r where r > 0, else +0 (NaN included): rounding can dip
/// a quadric slightly below 0.
inline double KeepPositive(double r)
{
  return r > 0.0 ? r : 0.0;
}

#if defined(__SSE2__)
/// Two doubles in one SSE2 register, with the arithmetic CostLanes needs.
struct DoublePair
{
  __m128d V;

  DoublePair() = default;
  explicit DoublePair(double x)
    : V(_mm_set1_pd(x))
  {
  }
  DoublePair(__m128d v)
    : V(v)
  {
  }
  static DoublePair Of(double lane0, double lane1) { return _mm_set_pd(lane1, lane0); }
  double Lane0() const { return _mm_cvtsd_f64(this->V); }
  double Lane1() const { return _mm_cvtsd_f64(_mm_unpackhi_pd(this->V, this->V)); }
};
inline DoublePair operator+(DoublePair a, DoublePair b)
{
  return _mm_add_pd(a.V, b.V);
}
inline DoublePair operator-(DoublePair a, DoublePair b)
{
  return _mm_sub_pd(a.V, b.V);
}
inline DoublePair operator*(DoublePair a, DoublePair b)
{
  return _mm_mul_pd(a.V, b.V);
}
inline DoublePair KeepPositive(DoublePair r)
{
  return _mm_and_pd(r.V, _mm_cmpgt_pd(r.V, _mm_setzero_pd()));
}
#endif

/**
 * A LocalQuadric with every coefficient in a T: double, or DoublePair to
 * cost two targets at once. The formulas exist once, as templates, so both
 * take the same operations in the same order and every lane gives the scalar
 * result bit for bit: the TOM does not depend on the instruction set.
 * (Costing candidates is about a fifth of a build's instructions.)
 */
template <typename T>
struct CostLanes
{
  T A00, A01, A02, A11, A12, A22, G0, G1, G2, C, OriginX, OriginY, OriginZ;
  T InverseRootWeight, MomentWeight;

  explicit CostLanes(const LocalQuadric& q)
    : A00(q.A00)
    , A01(q.A01)
    , A02(q.A02)
    , A11(q.A11)
    , A12(q.A12)
    , A22(q.A22)
    , G0(q.G0)
    , G1(q.G1)
    , G2(q.G2)
    , C(q.C)
    , OriginX(q.Origin.X)
    , OriginY(q.Origin.Y)
    , OriginZ(q.Origin.Z)
    , InverseRootWeight(q.InverseRootWeight)
    , MomentWeight(EdgeLengthWeight * q.Weight)
  {
  }
  /// A d, for the offset d from the origin.
  void Apply(T dx, T dy, T dz, T& adx, T& ady, T& adz) const
  {
    adx = this->A00 * dx + this->A01 * dy + this->A02 * dz;
    ady = this->A01 * dx + this->A11 * dy + this->A12 * dz;
    adz = this->A02 * dx + this->A12 * dy + this->A22 * dz;
  }
  /// The quadric at the offset d from its origin, at least 0.
  T Value(T dx, T dy, T dz) const
  {
    T adx, ady, adz;
    this->Apply(dx, dy, dz, adx, ady, adz);
    const T linear = this->G0 * dx + this->G1 * dy + this->G2 * dz;
    return KeepPositive(this->C + T(2.0) * linear + (dx * adx + dy * ady + dz * adz));
  }
  /// CollapseEngine::Cost of moving the origin to p (see there).
  T Cost(T x, T y, T z) const
  {
    const T dx = x - this->OriginX, dy = y - this->OriginY, dz = z - this->OriginZ;
    const T length2 = dx * dx + dy * dy + dz * dz;
    return this->Value(dx, dy, dz) * this->InverseRootWeight + this->MomentWeight * length2;
  }
};

inline Vec3 LocalQuadric::Apply(const Vec3& d) const
{
  Vec3 ad;
  CostLanes<double>(*this).Apply(d.X, d.Y, d.Z, ad.X, ad.Y, ad.Z);
  return ad;
}

inline double LocalQuadric::Evaluate(const Vec3& p) const
{
  const Vec3 d = Sub(p, this->Origin);
  return CostLanes<double>(*this).Value(d.X, d.Y, d.Z);
}

struct Candidate
{
  double Cost;
  uint32_t Target;
};

/**
 * The cheapest of the targets offered one by one (the first of equal ones,
 * as a scalar loop would keep), costed in pairs where SSE2 allows.
 */
class CheapestTarget
{
public:
  CheapestTarget(const LocalQuadric& q, const Vertex* vertices)
    : Scalar(q)
#if defined(__SSE2__)
    , Paired(q)
#endif
    , Vertices(vertices)
  {
  }
  void Offer(uint32_t x)
  {
#if defined(__SSE2__)
    if (this->Pending == Invalid)
    {
      this->Pending = x;
      return;
    }
    const Vec3& p0 = this->PositionOf(this->Pending);
    const Vec3& p1 = this->PositionOf(x);
    const DoublePair c = this->Paired.Cost(DoublePair::Of(p0.X, p1.X),
      DoublePair::Of(p0.Y, p1.Y), DoublePair::Of(p0.Z, p1.Z));
    this->Take(this->Pending, c.Lane0());
    this->Take(x, c.Lane1());
    this->Pending = Invalid;
#else
    const Vec3& p = this->PositionOf(x);
    this->Take(x, this->Scalar.Cost(p.X, p.Y, p.Z));
#endif
  }
  /// The cheapest of all offered ({+inf, Invalid} when none was).
  const Candidate& Best()
  {
    if (this->Pending != Invalid)
    {
      const Vec3& p = this->PositionOf(this->Pending);
      this->Take(this->Pending, this->Scalar.Cost(p.X, p.Y, p.Z));
      this->Pending = Invalid;
    }
    return this->Cheapest;
  }

private:
  const Vec3& PositionOf(uint32_t x) const { return this->Vertices[x].P; }
  void Take(uint32_t x, double cost)
  {
    if (cost < this->Cheapest.Cost)
    {
      this->Cheapest = { cost, x };
    }
  }

  CostLanes<double> Scalar;
#if defined(__SSE2__)
  CostLanes<DoublePair> Paired;
#endif
  const Vertex* Vertices;
  uint32_t Pending = Invalid;
  Candidate Cheapest{ std::numeric_limits<double>::infinity(), Invalid };
};

/// weight * n n^T, a plane through a record's own vertex (n of unit length),
/// computed once for all the vertices it is added to.
struct PlaneThroughOrigin
{
  double A00, A01, A02, A11, A12, A22;

  PlaneThroughOrigin(const Vec3& n, double weight)
    : A00(weight * n.X * n.X)
    , A01(weight * n.X * n.Y)
    , A02(weight * n.X * n.Z)
    , A11(weight * n.Y * n.Y)
    , A12(weight * n.Y * n.Z)
    , A22(weight * n.Z * n.Z)
  {
  }
  void AddTo(QuadricRecord& r) const
  {
    AddMatrix(r, *this);
  }
};

/// The constraint planes alone, kept apart (few vertices have any) to report
/// a geometric error that their weights do not distort.
struct ConstraintRecord
{
  Quadric Q;
  double Weight;
};

/**
 * Min-heap of vertices keyed by their best collapse cost, with positions so
 * that keys can be changed and entries removed in O(log n). Four children per
 * node: half the depth of a binary heap, and with the storage shifted by
 * three entries each family of four 8-byte entries fills an aligned half
 * cache line.
 */
class IndexedHeap
{
public:
  struct Entry
  {
    float Key;
    uint32_t Vertex;
  };

  void Reset(size_t numberOfVertices)
  {
    this->Pos.assign(numberOfVertices, Invalid);
    this->Storage.clear();
    this->Storage.reserve(numberOfVertices + Shift);
    this->Storage.resize(Shift, Entry{ 0.f, Invalid });
    this->Count = 0;
  }
  bool Empty() const { return this->Count == 0; }
  const Entry& Top() const { return this->Storage[Shift]; }

  /// Appends without ordering; call Heapify afterwards.
  void PushUnordered(uint32_t v, float key)
  {
    this->Pos[v] = static_cast<uint32_t>(this->Count++);
    this->Storage.push_back({ key, v });
  }
  void Heapify()
  {
    for (size_t i = this->Count / Arity + 1; i-- > 0;)
    {
      if (i < this->Count)
      {
        this->SiftDown(i);
      }
    }
  }
  void Set(uint32_t v, float key)
  {
    uint32_t p = this->Pos[v];
    if (p == Invalid)
    {
      p = static_cast<uint32_t>(this->Count++);
      this->Storage.push_back({ key, v });
      this->Pos[v] = p;
      this->SiftUp(p);
      return;
    }
    Entry* d = this->Data();
    const float old = d[p].Key;
    d[p].Key = key;
    if (key < old)
    {
      this->SiftUp(p);
    }
    else if (key > old)
    {
      this->SiftDown(p);
    }
  }
  void Remove(uint32_t v)
  {
    const uint32_t p = this->Pos[v];
    if (p == Invalid)
    {
      return;
    }
    this->Pos[v] = Invalid;
    const Entry last = this->Storage.back();
    this->Storage.pop_back();
    --this->Count;
    if (p < this->Count)
    {
      Entry* d = this->Data();
      const float old = d[p].Key;
      d[p] = last;
      this->Pos[last.Vertex] = p;
      if (last.Key < old)
      {
        this->SiftUp(p);
      }
      else
      {
        this->SiftDown(p);
      }
    }
  }
  /// Smallest key among the entries other than the top (+inf when none).
  float SecondKey() const
  {
    const size_t n = std::min<size_t>(this->Count, Arity + 1);
    float k = std::numeric_limits<float>::infinity();
    for (size_t i = 1; i < n; ++i)
    {
      k = std::min(k, this->Storage[Shift + i].Key);
    }
    return k;
  }

private:
  static constexpr size_t Arity = 4;
  static constexpr size_t Shift = 3; // children of i at 4i+1.. sit at 4(i+1)+0..3 in storage

  Entry* Data() { return this->Storage.data() + Shift; }

  void SiftUp(size_t i)
  {
    Entry* d = this->Data();
    const Entry e = d[i];
    while (i > 0)
    {
      const size_t parent = (i - 1) / Arity;
      if (!(e.Key < d[parent].Key))
      {
        break;
      }
      d[i] = d[parent];
      this->Pos[d[i].Vertex] = static_cast<uint32_t>(i);
      i = parent;
    }
    d[i] = e;
    this->Pos[e.Vertex] = static_cast<uint32_t>(i);
  }
  void SiftDown(size_t i)
  {
    Entry* d = this->Data();
    const size_t n = this->Count;
    const Entry e = d[i];
    for (;;)
    {
      const size_t first = Arity * i + 1;
      if (first >= n)
      {
        break;
      }
      size_t child = first;
      if (first + Arity <= n)
      {
        // Full family (the common case): a branch-light tournament.
        const Entry* c = d + first;
        const size_t a = c[1].Key < c[0].Key ? 1 : 0;
        const size_t b = c[3].Key < c[2].Key ? 3 : 2;
        child += c[b].Key < c[a].Key ? b : a;
      }
      else
      {
        for (size_t c = first + 1; c < n; ++c)
        {
          if (d[c].Key < d[child].Key)
          {
            child = c;
          }
        }
      }
      if (!(d[child].Key < e.Key))
      {
        break;
      }
      d[i] = d[child];
      this->Pos[d[i].Vertex] = static_cast<uint32_t>(i);
      i = child;
    }
    d[i] = e;
    this->Pos[e.Vertex] = static_cast<uint32_t>(i);
  }

  BigVector<Entry> Storage; // Shift unused entries, then the heap
  BigVector<uint32_t> Pos;
  size_t Count = 0;
};

/// Forwards progress to the callback; remembers a request to stop.
class ProgressReporter
{
public:
  explicit ProgressReporter(const std::function<bool(double)>& callback)
    : Callback(callback)
  {
  }
  bool Report(double fraction)
  {
    if (!this->Callback || this->Stopped)
    {
      return !this->Stopped;
    }
    if (!this->Callback(std::min(std::max(fraction, 0.0), 1.0)))
    {
      this->Stopped = true;
    }
    return !this->Stopped;
  }
  bool WasStopped() const { return this->Stopped; }

private:
  const std::function<bool(double)>& Callback;
  bool Stopped = false;
};

/**
 * The collapse engine shared by the builders: one simplification of one mesh
 * by half-edge collapses u -> w (vertex substitution, no new vertices), with
 * everything but the choice of which collapse comes next. It reads the input,
 * builds the adjacency, the quadrics and the vertex kinds (boundaries and
 * feature curves), keeps per vertex its cheapest allowed target with an exact
 * key, checks and applies collapses, relaxes the constraints on request, and
 * writes the collapse record out as a TOM. Schedules drive it: TOMBuilder
 * takes the global minimum each time (the heap), MergeTreeBuilder takes
 * independent sets level by level (no heap: keys only).
 *
 * Vertex ids inside are compact "internal" ids: the used input points,
 * numbered in input order.
 */
class CollapseEngine
{
public:
  /// useHeap: keep the vertices in an indexed heap by key (greedy schedules).
  CollapseEngine(const TOMBuildOptions& options, bool useHeap)
    : Options(options)
    , Progress(options.Progress)
    , UseHeap(useHeap)
  {
  }

  /**
   * The whole build: reads and checks the input, prepares the mesh, calls
   * schedule() to run the collapses (it returns false to abort), and writes
   * the TOM. Progress 0 after reading, 0.05 before the schedule, 1 at the
   * end; the schedule reports in between.
   */
  TOMBuildResult Run(const double* points, size_t numberOfPoints, const uint32_t* triangles,
    size_t numberOfTriangles, const std::function<bool()>& schedule);

  /// Forwards a fraction done to the progress callback; false: stop.
  bool ReportProgress(double fraction) { return this->Progress.Report(fraction); }

  // --- the state a schedule reads
  uint32_t GetNumberOfVertices() const { return this->N; }
  uint32_t GetRemovedCount() const { return static_cast<uint32_t>(this->RemovedOrder.size()); }
  /// Internal id of the vertex removed at a step (0 = first).
  uint32_t GetRemovedVertex(uint32_t step) const { return this->RemovedOrder[step]; }
  bool IsRemoved(uint32_t v) const { return this->Vertices[v].State & RemovedBit; }
  /// The cheapest allowed target of v and its key (+inf: none, or blocked).
  uint32_t GetTarget(uint32_t v) const { return this->Vertices[v].Target; }
  float GetKey(uint32_t v) const { return this->Vertices[v].Key; }
  bool HeapEmpty() const { return this->Heap.Empty(); }
  uint32_t HeapTop() const { return this->Heap.Top().Vertex; }
  /// Smallest key in the heap after the top (+inf when none).
  float HeapSecondKey() const { return this->Heap.SecondKey(); }

  // --- the operations of a schedule
  /// Whether u -> w keeps the mesh legal at the current relaxation level.
  bool CheckCollapse(uint32_t u, uint32_t w);
  /// Applies u -> w (checked first), updates quadrics and keys, records the step.
  void ApplyCollapse(uint32_t u, uint32_t w);
  /// All allowed targets of v, each once, cheapest first (valid until the next call).
  const std::vector<Candidate>& GatherCandidates(uint32_t v);
  /**
   * When u's cheapest target (failedTarget) is illegal: the cheapest legal
   * one into `found`. False when none is, or none within
   * AlternativeWorkBudget (the schedule then blocks u).
   */
  bool FindLegalAlternative(uint32_t u, uint32_t failedTarget, Candidate& found);
  /// Makes t v's target (the key is set apart, see SetKey).
  void SetTarget(uint32_t v, uint32_t t) { this->Vertices[v].Target = t; }
  /// v's key (and its place in the heap, if there is one).
  void SetKey(uint32_t v, double cost) { this->HeapSet(v, cost); }
  /// v has no legal collapse at this relaxation level until its neighbourhood
  /// changes (a collapse around it re-evaluates it) or the level changes.
  void Block(uint32_t v);
  /// Next relaxation level; false when all are used up (the build is done).
  bool Relax();
  int GetRelaxation() const { return this->CurrentLevel; }
  /// A word and a byte per vertex for the schedule, in the vertex's cache
  /// line (uninitialised).
  uint32_t& Tag(uint32_t v) { return this->Vertices[v].Tag; }
  uint8_t& TagByte(uint32_t v) { return this->Vertices[v].TagByte; }
  /// Without a heap: stage 0-5 of the prefetch of v's collapse into its
  /// target (v's record; lists; triangles; neighbours; quadrics), each stage
  /// reading what the earlier ones fetched, for schedules that see several
  /// collapses ahead and spread the stages over them.
  void PrefetchCandidate(uint32_t v, int stage) { this->PrefetchCollapse(v, stage); }

  /// Calls f(x) for each neighbour x of v (twice for most), v's list compacted.
  template <typename F>
  void ForEachNeighbour(uint32_t v, F&& f)
  {
    this->ForEachLiveTriangle(v, [&f](const Tri& tri, uint32_t j) {
      f(tri.V[Next3(j)]);
      f(tri.V[Prev3(j)]);
    });
  }

  /// After Run: hands the working arrays (records, quadrics, triangles,
  /// adjacency) over to blocks for reuse. Nothing may be asked of the engine after.
  void ReleaseWorkingMemory(ScratchBlocks& blocks)
  {
    blocks.Add(std::move(this->Vertices));
    blocks.Add(std::move(this->Quadrics));
    blocks.Add(std::move(this->Tris));
    blocks.Add(std::move(this->Pool));
  }

  /// Heap keys are floats, clamped so that +inf can mean "not in the heap".
  static float KeyOf(double cost)
  {
    return static_cast<float>(std::min(cost, double(std::numeric_limits<float>::max())));
  }

private:
  // --- setup
  void ReadInput(const double* points, size_t numberOfPoints, const uint32_t* triangles,
    size_t numberOfTriangles, TOMBuildResult& result);
  void FillTriangles();
  void DropDuplicateTriangles(TOMBuildResult& result);
  void BuildAdjacency();
  void BuildFaceQuadrics();
  bool ClassifyVertices();
  bool ClassifyClosedFan(uint32_t v, float cosFeature);
  bool SharpTurn(uint32_t v, uint32_t a, uint32_t b) const;
  void AddConstraintPlane(uint32_t a, uint32_t b, const Vec3& faceNormal, double weight);
  void SeedCandidate(uint32_t v);
  void BeginCollapses();

  // --- collapses
  void RemoveOrphan(uint32_t x, uint32_t w);
  void PrefetchCollapse(uint32_t v, int stage);
  /// New best target of v; prefetch false where the collapse that calls it
  /// fetched v's fan already (its "soon" neighbours).
  void Reevaluate(uint32_t v, bool prefetch = true);
  /// Whether v's fan is beyond MaximumFanSize (then it is parked, see there).
  bool Parked(uint32_t v) const { return this->Vertices[v].LiveCount > MaximumFanSize; }
  void Park(uint32_t v);
  void SetBest(uint32_t v, const Candidate& best);
  void StartLevel(int level);
  uint32_t NextStampBase();

  void HeapSet(uint32_t v, double cost)
  {
    this->Vertices[v].Key = KeyOf(cost);
    if (this->UseHeap)
    {
      this->Heap.Set(v, this->Vertices[v].Key);
    }
  }
  void HeapRemove(uint32_t v)
  {
    this->Vertices[v].Key = std::numeric_limits<float>::infinity();
    if (this->UseHeap)
    {
      this->Heap.Remove(v);
    }
  }

  /// Walks v's adjacency list, drops dead triangles from it and calls
  /// f(triangle, corner of v) for each live one.
  template <typename F>
  void ForEachLiveTriangle(uint32_t v, F&& f)
  {
    Vertex& rec = this->Vertices[v];
    uint32_t* list = this->Pool.data() + rec.AdjStart;
    const uint32_t n = rec.AdjCount;
    this->Visited += n;
    uint32_t kept = 0;
    for (uint32_t i = 0; i < n; ++i)
    {
      const uint32_t entry = list[i];
      const Tri& tri = this->Tris[entry >> 2];
      if (tri.Flags & DeadFlag)
      {
        continue;
      }
      list[kept++] = entry;
      f(tri, entry & 3u);
    }
    rec.AdjCount = kept;
  }

  /**
   * Calls consider(x) for every neighbour x that v may collapse into under
   * the kind rules of the current level (a neighbour may come twice).
   */
  template <typename F>
  void ForEachAllowedTarget(uint32_t v, F&& consider)
  {
    const int kind = this->EffectiveKind(v);
    if (kind == KindFixed)
    {
      return;
    }
    this->ForEachLiveTriangle(v, [&](const Tri& tri, uint32_t j) {
      if (kind == KindClosed)
      {
        // In a closed, consistently oriented fan each neighbour follows v once.
        consider(tri.V[Next3(j)]);
      }
      else if (kind == KindFree)
      {
        consider(tri.V[Next3(j)]);
        consider(tri.V[Prev3(j)]);
      }
      else
      {
        // A curve vertex only slides along its constraint edges.
        if ((tri.Flags >> j) & 1u)
        {
          consider(tri.V[Next3(j)]);
        }
        if ((tri.Flags >> Prev3(j)) & 1u)
        {
          consider(tri.V[Prev3(j)]);
        }
      }
    });
  }

  bool BestTarget(uint32_t v, Candidate& best, bool prefetch = true);
  int EffectiveKind(uint32_t v) const
  {
    return this->CurrentLevel >= LevelNoConstraints ? static_cast<int>(KindFree)
                                                    : this->Vertices[v].Kind;
  }
  /**
   * Cost of collapsing the vertex with quadric q into `target`: the increase
   * of the quadric error, Q(p) = the area-weighted squared distances of the
   * target from the planes the vertex has accumulated (constraint planes
   * included with their weights), divided by the square root of that area A:
   * the mean squared distance Q/A times the linear size sqrt(A) of the
   * region. Q alone (Garland-Heckbert) favours small triangles whatever their
   * deviation; Q/A follows distances only, and lets large, already simplified
   * regions keep collapsing while their mean stays low, however far their
   * worst parts move. Measured with the dense Hausdorff distance against the
   * vertex-subset peers (TOMBenchmark section 4: geometric mean of TOM / best
   * peer over eight meshes and four resolutions), exponents 0.35 and 0.8 of
   * A did worse than 0.5, and 0 and 1 worse still.
   * The cost depends only on the source's quadric and the
   * target's position, so it does not change when the target absorbs other
   * vertices: a collapse changes few keys, which are all kept exact.
   *
   * A small "moment" term, area already gathered at the vertex times the
   * squared length of the move, breaks the ties of flat regions, where every
   * collapse is free: without it a vertex can roll along a row, dragging an
   * ever longer fan that every collapse walks (quadratic time), or swallow
   * a whole plane. Its weight is small enough to only decide where
   * collapses are (nearly) free.
   */
  double Cost(const LocalQuadric& q, uint32_t target) const
  {
    const Vec3& p = this->Vertices[target].P;
    return CostLanes<double>(q).Cost(p.X, p.Y, p.Z);
  }
  LocalQuadric QuadricOf(uint32_t v) const
  {
    return LocalQuadric(this->Quadrics[v], this->Vertices[v].P);
  }

  void EnsureCapacity(uint32_t v, uint32_t needed);
  void CompactPool();

  void BuildOutput(TOMBuildResult& result);

  const TOMBuildOptions& Options;
  ProgressReporter Progress;

  // Input bookkeeping.
  const uint32_t* InputTriangles = nullptr;
  BigVector<uint32_t> InputIdOf;    // internal vertex -> input point id
  BigVector<uint32_t> InternalIdOf; // input point id -> internal vertex (Invalid if unused)
  BigVector<uint32_t> InputTriOf;   // internal triangle -> input triangle index
  double Scale = 1.0;

  uint32_t N = 0; // vertices
  uint32_t T = 0; // triangles

  BigVector<Tri> Tris;
  BigVector<Vertex> Vertices;
  BigVector<QuadricRecord> Quadrics;
  BigVector<float> Normals; // unit face normals, during the setup only
  BigVector<ConstraintRecord> Constraints; // one per vertex touched by a constraint plane

  BigVector<uint32_t> Pool;
  size_t PoolUsed = 0;

  IndexedHeap Heap;
  const bool UseHeap;
  int CurrentLevel = LevelAll;
  double CosMaxDeviation = 0.0;
  bool NormalCheckEnabled = true;
  bool SliverCheckEnabled = false;

  uint32_t Stamp = 0;
  uint64_t Visited = 0; // TOMBuildResult::FanTrianglesVisited
  std::vector<Candidate> Scratch;
  std::vector<uint32_t> Ring;  // u's neighbours during a collapse
  std::vector<uint32_t> Soon;  // those of them probably re-evaluated
  std::vector<uint32_t> Retry; // blocked vertices around w during a collapse
  bool RetrySkipped = false;   // some around a hub (RetryFanSize) since the level started
  std::vector<uint32_t> Orphans;
  std::vector<uint32_t> BlockedList;
  std::vector<uint32_t> Merges; // wing vertices whose merged edge keeps a constraint flag

  // The collapse record.
  BigVector<uint32_t> RemovedOrder; // internal id of the vertex removed at each step
  BigVector<uint32_t> SubstituteOf; // internal id -> internal id it was substituted with
  BigVector<float> StepError;       // running max of the geometric error, per step
  BigVector<uint32_t> KillList;     // triangles in the order they died
  BigVector<uint32_t> KillStart;    // per step, first index into KillList
  double RunningError = 0.0;
};
}
}

#endif
