// SPDX-License-Identifier: BSD-3-Clause
#include "CollapseEngine.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <new>
#include <stdexcept>
#include <string>
#include <utility>

#if defined(__linux__)
#include <sys/mman.h>
#endif

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
 */

namespace timecritical
{
namespace collapse
{
namespace
{
constexpr size_t HugePageSize = size_t(2) << 20;

size_t RoundUp(size_t bytes)
{
  return (bytes + HugePageSize - 1) & ~(HugePageSize - 1);
}
}

//------------------------------------------------------------------------------
void AdviseHugePages(void* p, size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  if (bytes < HugePageThreshold)
  {
    return;
  }
  const uintptr_t begin = (reinterpret_cast<uintptr_t>(p) + HugePageSize - 1) & ~(HugePageSize - 1);
  const uintptr_t end = (reinterpret_cast<uintptr_t>(p) + bytes) & ~(HugePageSize - 1);
  if (end > begin)
  {
    madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
  }
#else
  (void)p;
  (void)bytes;
#endif
}

//------------------------------------------------------------------------------
void* AllocateHugePageBlock(size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  // A mapping of its own, 2 MiB aligned (trimmed from a larger one), so
  // that every 2 MiB of it can be a huge page.
  const size_t rounded = RoundUp(bytes);
  void* raw =
    mmap(nullptr, rounded + HugePageSize, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED)
  {
    throw std::bad_alloc();
  }
  const uintptr_t begin = reinterpret_cast<uintptr_t>(raw);
  const uintptr_t aligned = (begin + HugePageSize - 1) & ~(HugePageSize - 1);
  if (aligned > begin)
  {
    munmap(raw, aligned - begin);
  }
  const uintptr_t end = begin + rounded + HugePageSize;
  if (end > aligned + rounded)
  {
    munmap(reinterpret_cast<void*>(aligned + rounded), end - (aligned + rounded));
  }
  madvise(reinterpret_cast<void*>(aligned), rounded, MADV_HUGEPAGE);
  return reinterpret_cast<void*>(aligned);
#else
  (void)bytes;
  return nullptr;
#endif
}

//------------------------------------------------------------------------------
bool FreeHugePageBlock(void* p, size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  munmap(p, RoundUp(bytes));
  return true;
#else
  (void)p;
  (void)bytes;
  return false;
#endif
}

//------------------------------------------------------------------------------
uint32_t CollapseEngine::NextStampBase()
{
  if (++this->Stamp >= (1u << 29))
  {
    // Out of stamps (after half a billion checks): clear the marks once.
    for (Vertex& v : this->Vertices)
    {
      v.Mark = 0;
    }
    this->Stamp = 1;
  }
  return this->Stamp << 3;
}

//------------------------------------------------------------------------------
void CollapseEngine::ReadInput(const double* points, size_t numberOfPoints, const uint32_t* triangles,
  size_t numberOfTriangles, TOMBuildResult& result)
{
  if (numberOfPoints > 0 && !points)
  {
    throw std::invalid_argument("TOMBuilder: the point array is null but " +
      std::to_string(numberOfPoints) + " points were announced");
  }
  if (numberOfTriangles > 0 && !triangles)
  {
    throw std::invalid_argument("TOMBuilder: the triangle array is null but " +
      std::to_string(numberOfTriangles) + " triangles were announced");
  }
  // 32-bit ids everywhere, and the adjacency pool holds about 5 ids per triangle.
  if (numberOfTriangles > (std::numeric_limits<uint32_t>::max() >> 3) ||
    numberOfPoints >= std::numeric_limits<uint32_t>::max())
  {
    throw std::invalid_argument("TOMBuilder: " + std::to_string(numberOfTriangles) +
      " triangles / " + std::to_string(numberOfPoints) + " points exceed the 32-bit index limits");
  }
  this->InputTriangles = triangles;
  this->InternalIdOf.assign(numberOfPoints, Invalid);

  // Validate ids and drop triangles with repeated corners; mark used points.
  this->InputTriOf.clear();
  this->InputTriOf.reserve(numberOfTriangles);
  for (size_t t = 0; t < numberOfTriangles; ++t)
  {
    const uint32_t* c = triangles + 3 * t;
    for (int k = 0; k < 3; ++k)
    {
      if (c[k] >= numberOfPoints)
      {
        throw std::invalid_argument("TOMBuilder: triangle " + std::to_string(t) + " corner " +
          std::to_string(k) + " references point " + std::to_string(c[k]) +
          " but there are only " + std::to_string(numberOfPoints) + " points");
      }
    }
    if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2])
    {
      ++result.DroppedDegenerateTriangles;
      continue;
    }
    this->InputTriOf.push_back(static_cast<uint32_t>(t));
    this->InternalIdOf[c[0]] = this->InternalIdOf[c[1]] = this->InternalIdOf[c[2]] = 0;
  }

  // Internal ids in input order (so that survivors come out in input order).
  uint32_t n = 0;
  double lo[3] = { std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
    std::numeric_limits<double>::max() };
  double hi[3] = { -lo[0], -lo[1], -lo[2] };
  for (size_t i = 0; i < numberOfPoints; ++i)
  {
    if (this->InternalIdOf[i] == Invalid)
    {
      ++result.UnusedPoints;
      continue;
    }
    const double* p = points + 3 * i;
    for (int k = 0; k < 3; ++k)
    {
      if (!(std::abs(p[k]) <= MaximumCoordinateMagnitude))
      {
        if (!std::isfinite(p[k]))
        {
          throw std::invalid_argument("TOMBuilder: point " + std::to_string(i) +
            " (used by a triangle) has a non-finite coordinate");
        }
        char message[200];
        std::snprintf(message, sizeof(message),
          "TOMBuilder: point %zu has a coordinate of magnitude %.3g, beyond the supported %g "
          "(errors and radii are stored as float); scale the data",
          i, std::abs(p[k]), MaximumCoordinateMagnitude);
        throw std::invalid_argument(message);
      }
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
    this->InternalIdOf[i] = n++;
  }
  this->N = n;
  this->T = static_cast<uint32_t>(this->InputTriOf.size());
  if (this->N == 0)
  {
    return;
  }

  // Unit box around the origin: well-conditioned quadrics, scale-free tolerances.
  const double extent = std::max({ hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2] });
  this->Scale = extent > 0.0 && std::isfinite(extent) ? extent : 1.0;
  const double inv = 1.0 / this->Scale;
  const double center[3] = { 0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]),
    0.5 * (lo[2] + hi[2]) };
  this->InputIdOf.resize(this->N);
  this->Vertices.resize(this->N);
  for (size_t i = 0; i < numberOfPoints; ++i)
  {
    const uint32_t v = this->InternalIdOf[i];
    if (v == Invalid)
    {
      continue;
    }
    const double* p = points + 3 * i;
    this->InputIdOf[v] = static_cast<uint32_t>(i);
    Vertex& rec = this->Vertices[v];
    rec.P = { (p[0] - center[0]) * inv, (p[1] - center[1]) * inv, (p[2] - center[2]) * inv };
    rec.Target = Invalid;
    rec.Key = std::numeric_limits<float>::infinity();
    rec.Mark = 0;
    rec.Kind = KindFree;
    rec.State = 0;
  }

  this->FillTriangles();
}

//------------------------------------------------------------------------------
void CollapseEngine::FillTriangles()
{
  this->T = static_cast<uint32_t>(this->InputTriOf.size());
  this->Tris.resize(this->T);
  for (uint32_t t = 0; t < this->T; ++t)
  {
    const uint32_t* c = this->InputTriangles + 3 * static_cast<size_t>(this->InputTriOf[t]);
    this->Tris[t] = { { this->InternalIdOf[c[0]], this->InternalIdOf[c[1]],
                        this->InternalIdOf[c[2]] },
      0u };
  }
}

//------------------------------------------------------------------------------
void CollapseEngine::DropDuplicateTriangles(TOMBuildResult& result)
{
  // Only after the classification met a duplicate (see ClassifyVertices):
  // keeps the first of the triangles on the same three points, sorting their
  // sorted corner triples, and restarts the setup on the rest.
  struct Key
  {
    uint32_t C[3];
    uint32_t Index; // into InputTriOf
  };
  std::vector<Key> keys(this->T);
  for (uint32_t t = 0; t < this->T; ++t)
  {
    Key& k = keys[t];
    std::copy(this->Tris[t].V, this->Tris[t].V + 3, k.C);
    std::sort(k.C, k.C + 3);
    k.Index = t;
  }
  std::sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) {
    return std::lexicographical_compare(a.C, a.C + 3, b.C, b.C + 3) ||
      (std::equal(a.C, a.C + 3, b.C) && a.Index < b.Index);
  });
  std::vector<char> duplicate(this->T, 0);
  for (size_t i = 1; i < keys.size(); ++i)
  {
    if (std::equal(keys[i].C, keys[i].C + 3, keys[i - 1].C))
    {
      duplicate[keys[i].Index] = 1;
      ++result.DroppedDuplicateTriangles;
    }
  }
  uint32_t kept = 0;
  for (uint32_t t = 0; t < this->T; ++t)
  {
    if (!duplicate[t])
    {
      this->InputTriOf[kept++] = this->InputTriOf[t];
    }
  }
  this->InputTriOf.resize(kept);
  this->FillTriangles();
  // What the first classification left behind.
  for (Vertex& rec : this->Vertices)
  {
    rec.Target = Invalid;
    rec.Key = std::numeric_limits<float>::infinity();
    rec.Kind = KindFree;
    rec.State = 0;
  }
  this->Constraints.clear();
  this->BlockedList.clear();
}

//------------------------------------------------------------------------------
void CollapseEngine::BuildAdjacency()
{
  // Compressed lists with a little slack per vertex: a collapse usually grows
  // the surviving vertex's list by about two, which then fits in place.
  constexpr uint32_t slack = 3;
  for (Vertex& rec : this->Vertices)
  {
    rec.AdjCount = 0;
  }
  for (const Tri& t : this->Tris)
  {
    ++this->Vertices[t.V[0]].AdjCount;
    ++this->Vertices[t.V[1]].AdjCount;
    ++this->Vertices[t.V[2]].AdjCount;
  }
  size_t offset = 0;
  for (Vertex& rec : this->Vertices)
  {
    rec.AdjStart = static_cast<uint32_t>(offset);
    rec.AdjCap = rec.AdjCount + slack;
    rec.LiveCount = rec.AdjCount;
    offset += rec.AdjCap;
    rec.AdjCount = 0;
  }
  this->PoolUsed = offset;
  // Headroom for relocated lists; compacted when exhausted.
  this->Pool.resize(offset + offset / 8 + 64);
  for (uint32_t t = 0; t < this->T; ++t)
  {
    for (uint32_t k = 0; k < 3; ++k)
    {
      Vertex& rec = this->Vertices[this->Tris[t].V[k]];
      this->Pool[rec.AdjStart + rec.AdjCount++] = t << 2 | k;
    }
  }
}

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
void CollapseEngine::BuildFaceQuadrics()
{
  // Face planes weighted by area (Garland & Heckbert): large faces weigh more.
  // The unit normals are kept (in float, directions only) for the
  // classification of the edges.
  // Every plane passes through the corners it is added to, so in the local
  // form only A grows.
  QuadricRecord empty{};
  empty.Slot = Invalid;
  this->Quadrics.assign(this->N, empty);
  this->Normals.resize(3 * static_cast<size_t>(this->T));
  float* normal = this->Normals.data();
  for (const Tri& tri : this->Tris)
  {
    const Vec3& a = this->Vertices[tri.V[0]].P;
    const Vec3 n = TriangleNormal(a, this->Vertices[tri.V[1]].P, this->Vertices[tri.V[2]].P);
    const double len = std::sqrt(Dot(n, n));
    if (!(len > 0.0))
    {
      normal[0] = normal[1] = normal[2] = 0.f;
      normal += 3;
      continue;
    }
    const double inv = 1.0 / len;
    const Vec3 unit = { n.X * inv, n.Y * inv, n.Z * inv };
    normal[0] = static_cast<float>(unit.X);
    normal[1] = static_cast<float>(unit.Y);
    normal[2] = static_cast<float>(unit.Z);
    normal += 3;
    const double area = 0.5 * len;
    const PlaneThroughOrigin plane(unit, area);
    for (uint32_t v : tri.V)
    {
      plane.AddTo(this->Quadrics[v]);
      this->Quadrics[v].FaceWeight = static_cast<float>(this->Quadrics[v].FaceWeight + area);
    }
  }
  for (QuadricRecord& r : this->Quadrics)
  {
    SetFaceWeight(r, r.FaceWeight);
  }
}

//------------------------------------------------------------------------------
void CollapseEngine::AddConstraintPlane(uint32_t a, uint32_t b, const Vec3& faceNormal, double weight)
{
  // A plane through edge (a, b), perpendicular to the face: moving an end of
  // the edge across the curve costs, sliding along it does not.
  const Vec3 e = Sub(this->Vertices[b].P, this->Vertices[a].P);
  Vec3 m = Cross(e, faceNormal);
  const double mlen = std::sqrt(Dot(m, m));
  if (!(mlen > 0.0) || !(weight > 0.0))
  {
    return;
  }
  m = { m.X / mlen, m.Y / mlen, m.Z / mlen };
  const double w = weight * Dot(e, e);
  Quadric q;
  q.AddPlane(m, -Dot(m, this->Vertices[a].P), w);
  const PlaneThroughOrigin plane(m, w);
  for (uint32_t v : { a, b })
  {
    QuadricRecord& rec = this->Quadrics[v];
    plane.AddTo(rec);
    if (rec.Slot == Invalid)
    {
      rec.Slot = static_cast<uint32_t>(this->Constraints.size());
      this->Constraints.push_back({ Quadric(), 0.0 });
    }
    this->Constraints[rec.Slot].Q.Add(q);
    this->Constraints[rec.Slot].Weight += w;
  }
}

//------------------------------------------------------------------------------
bool CollapseEngine::SharpTurn(uint32_t v, uint32_t a, uint32_t b) const
{
  // The curve a -> v -> b turns by more than the feature angle: v is a corner
  // of the boundary or feature line (a corner of a square hole, a kink of a
  // crease) and stays, like the ends and junctions of such lines.
  const Vec3& p = this->Vertices[v].P;
  const Vec3 da = Sub(this->Vertices[a].P, p);
  const Vec3 db = Sub(this->Vertices[b].P, p);
  const double c = std::cos(this->Options.FeatureAngle * Pi / 180.0);
  return Dot(da, db) > -c * std::sqrt(Dot(da, da) * Dot(db, db));
}

//------------------------------------------------------------------------------
bool CollapseEngine::ClassifyClosedFan(uint32_t v, float cosFeature)
{
  // Fast path for the common case, a small closed fan with consistent
  // orientation: the triangle after triangle i around v is the one whose
  // previous corner is i's next corner. Anything else goes the general way.
  constexpr uint32_t maxFan = 16;
  const Vertex& rec = this->Vertices[v];
  const uint32_t count = rec.AdjCount;
  if (count < 3 || count > maxFan)
  {
    return false;
  }
  const uint32_t* list = this->Pool.data() + rec.AdjStart;
  uint32_t next[maxFan], prev[maxFan], corner[maxFan], twin[maxFan];
  for (uint32_t i = 0; i < count; ++i)
  {
    const Tri& tri = this->Tris[list[i] >> 2];
    const uint32_t j = list[i] & 3u;
    corner[i] = j;
    next[i] = tri.V[Next3(j)];
    prev[i] = tri.V[Prev3(j)];
  }
  // Walk around v, from each triangle to the first one whose previous corner
  // is its next corner. Coming back to the start after visiting every
  // triangle makes that map a single cycle, hence one by one: each edge has
  // exactly one triangle on each side, consistently oriented, in one piece.
  uint32_t c = 0;
  for (uint32_t steps = 0; steps < count; ++steps)
  {
    uint32_t l = 0;
    while (l < count && prev[l] != next[c])
    {
      ++l;
    }
    if (l == count || (l == 0) != (steps + 1 == count))
    {
      return false;
    }
    twin[c] = l;
    c = l;
  }

  const TOMBuildOptions& o = this->Options;
  uint32_t constrained = 0;
  uint32_t ends[2] = { Invalid, Invalid };
  for (uint32_t i = 0; i < count; ++i)
  {
    // Edge (v, next[i]) between triangle i (its edge corner[i]) and twin[i].
    const uint32_t t0 = list[i] >> 2, t1 = list[twin[i]] >> 2;
    const uint32_t e0 = corner[i], e1 = Prev3(corner[twin[i]]);
    if (next[i] > v && o.PreserveFeatureEdges)
    {
      const float* a = this->Normals.data() + 3 * static_cast<size_t>(t0);
      const float* b = this->Normals.data() + 3 * static_cast<size_t>(t1);
      const float d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
      const bool degenerate =
        (a[0] == 0.f && a[1] == 0.f && a[2] == 0.f) || (b[0] == 0.f && b[1] == 0.f && b[2] == 0.f);
      if (!degenerate && d < cosFeature)
      {
        const double w = o.LockFeatureEdges ? o.ConstraintWeight : o.FeatureWeight;
        this->AddConstraintPlane(v, next[i], Vec3{ a[0], a[1], a[2] }, w);
        this->AddConstraintPlane(v, next[i], Vec3{ b[0], b[1], b[2] }, w);
        if (o.LockFeatureEdges)
        {
          this->Tris[t0].Flags |= 1u << e0;
          this->Tris[t1].Flags |= 1u << e1;
        }
      }
    }
    if (((this->Tris[t0].Flags >> e0) | (this->Tris[t1].Flags >> e1)) & 1u)
    {
      ends[constrained++ & 1u] = next[i];
    }
  }
  this->Vertices[v].Kind = constrained == 0
    ? KindClosed
    : (constrained == 2 && !this->SharpTurn(v, ends[0], ends[1]) ? KindCurve : KindFixed);
  return true;
}

//------------------------------------------------------------------------------
bool CollapseEngine::ClassifyVertices()
{
  if (this->UseHeap)
  {
    this->Heap.Reset(this->N);
  }
  this->Constraints.reserve(this->N / 16 + 16); // boundaries and creases: a minority, usually
  const TOMBuildOptions& o = this->Options;
  const float cosFeature = static_cast<float>(std::cos(o.FeatureAngle * Pi / 180.0));
  const double boundaryWeight = o.PreserveBoundaries ? o.ConstraintWeight : 1.0;
  auto normalOf = [this](uint32_t t) {
    const float* n = this->Normals.data() + 3 * static_cast<size_t>(t);
    return Vec3{ n[0], n[1], n[2] };
  };

  // Around each vertex v: one "spoke" per (triangle, neighbour), grouped by
  // neighbour so that each edge (v, x) sees all its triangles. Small fans are
  // grouped by linear search, large ones by sorting; either way the work stays
  // local to the fan.
  struct Spoke
  {
    uint32_t X;    // neighbour
    uint32_t Tri;  // triangle
    uint32_t Edge; // index of edge (v, X) in that triangle
    uint32_t Prev; // 1 when X precedes v in the triangle (edge X -> v)
  };
  struct Group
  {
    uint32_t X;
    uint32_t Next, Prev; // spokes with X following / preceding v
    uint32_t First;      // first spoke of the group (in `members` once bucketed)
    uint32_t Parent;     // union-find over the groups: pieces of the fan
  };
  std::vector<Spoke> spokes;
  std::vector<uint32_t> groupOf; // spoke -> group
  std::vector<Group> groups;
  std::vector<uint32_t> order;
  std::vector<uint32_t> members; // spokes bucketed by group
  auto find = [&groups](uint32_t g) {
    while (groups[g].Parent != g)
    {
      groups[g].Parent = groups[groups[g].Parent].Parent;
      g = groups[g].Parent;
    }
    return g;
  };
  constexpr uint32_t linearSearchLimit = 48;

  for (uint32_t v = 0; v < this->N; ++v)
  {
    Vertex& rec = this->Vertices[v];
    const uint32_t* list = this->Pool.data() + rec.AdjStart;
    const uint32_t count = rec.AdjCount;
    if (this->ClassifyClosedFan(v, cosFeature))
    {
      this->SeedCandidate(v);
      continue;
    }
    spokes.resize(2 * static_cast<size_t>(count));
    groupOf.resize(spokes.size());
    groups.clear();
    for (uint32_t i = 0; i < count; ++i)
    {
      const uint32_t t = list[i] >> 2;
      const uint32_t j = list[i] & 3u;
      const Tri& tri = this->Tris[t];
      spokes[2 * i] = { tri.V[Next3(j)], t, j, 0 };
      spokes[2 * i + 1] = { tri.V[Prev3(j)], t, Prev3(j), 1 };
    }
    auto addToGroup = [&](size_t k, uint32_t g) {
      groupOf[k] = g;
      if (spokes[k].Prev)
      {
        ++groups[g].Prev;
      }
      else
      {
        ++groups[g].Next;
      }
    };
    if (count <= linearSearchLimit)
    {
      for (size_t k = 0; k < spokes.size(); ++k)
      {
        const uint32_t x = spokes[k].X;
        uint32_t g = 0;
        const uint32_t numberOfGroups = static_cast<uint32_t>(groups.size());
        while (g < numberOfGroups && groups[g].X != x)
        {
          ++g;
        }
        if (g == numberOfGroups)
        {
          groups.push_back({ x, 0, 0, static_cast<uint32_t>(k), g });
        }
        addToGroup(k, g);
      }
    }
    else
    {
      order.resize(spokes.size());
      for (uint32_t k = 0; k < order.size(); ++k)
      {
        order[k] = k;
      }
      std::sort(order.begin(), order.end(), [&spokes](uint32_t a, uint32_t b) {
        return spokes[a].X < spokes[b].X || (spokes[a].X == spokes[b].X && a < b);
      });
      for (size_t r = 0; r < order.size(); ++r)
      {
        const uint32_t k = order[r];
        if (r == 0 || spokes[order[r - 1]].X != spokes[k].X)
        {
          const uint32_t g = static_cast<uint32_t>(groups.size());
          groups.push_back({ spokes[k].X, 0, 0, k, g });
        }
        addToGroup(k, static_cast<uint32_t>(groups.size() - 1));
      }
    }

    // Bucket the spokes by group (counting sort) so each edge finds its triangles directly.
    {
      uint32_t offset = 0;
      for (Group& group : groups)
      {
        group.First = offset;
        offset += group.Next + group.Prev;
      }
      members.resize(spokes.size());
      for (uint32_t k = 0; k < spokes.size(); ++k)
      {
        members[groups[groupOf[k]].First++] = k;
      }
      for (Group& group : groups)
      {
        group.First -= group.Next + group.Prev;
      }
    }

    // Duplicate triangles (the same three points) share an edge and its third
    // corner. None touches a vertex of the fast path (its walk around the fan
    // needs distinct neighbours), so every one is met here: the setup starts
    // again without them (Run). Usually two triangles per edge: one compare.
    for (const Group& group : groups)
    {
      const uint32_t n = group.Next + group.Prev;
      const uint32_t* m = members.data() + group.First;
      if (n > linearSearchLimit)
      {
        order.resize(n);
        for (uint32_t k = 0; k < n; ++k)
        {
          order[k] = spokes[m[k] ^ 1u].X; // the third corner (the sibling spoke's neighbour)
        }
        std::sort(order.begin(), order.end());
        if (std::adjacent_find(order.begin(), order.end()) != order.end())
        {
          return false;
        }
        continue;
      }
      for (uint32_t a = 1; a < n; ++a)
      {
        for (uint32_t b = 0; b < a; ++b)
        {
          if (spokes[m[a] ^ 1u].X == spokes[m[b] ^ 1u].X)
          {
            return false;
          }
        }
      }
    }

    // Each edge is classified once, from its lower end; the flags it sets
    // are seen by the higher end later.
    bool closed = true;
    uint32_t constrained = 0;
    uint32_t ends[2] = { Invalid, Invalid };
    for (uint32_t g = 0; g < groups.size(); ++g)
    {
      const Group& group = groups[g];
      const uint32_t x = group.X;
      const uint32_t n = group.Next + group.Prev;
      if (group.Next != 1 || group.Prev != 1)
      {
        closed = false;
      }
      // The spokes of this group (few: usually two).
      auto forEachSpoke = [&](auto&& f) {
        for (uint32_t k = group.First; k < group.First + n; ++k)
        {
          f(spokes[members[k]]);
        }
      };
      if (x > v)
      {
        bool constraint = false;
        const Spoke& s0 = spokes[members[group.First]];
        if (n == 1)
        {
          this->AddConstraintPlane(v, x, normalOf(s0.Tri), boundaryWeight);
          constraint = o.PreserveBoundaries;
        }
        else if (n == 2 && group.Next == 1)
        {
          // Manifold, consistently oriented edge: a feature if the dihedral is sharp.
          uint32_t t1 = s0.Tri;
          forEachSpoke([&](const Spoke& s) {
            if (s.Tri != s0.Tri)
            {
              t1 = s.Tri;
            }
          });
          const Vec3 n0 = normalOf(s0.Tri);
          const Vec3 n1 = normalOf(t1);
          if (o.PreserveFeatureEdges && Dot(n0, n0) > 0.0 && Dot(n1, n1) > 0.0 &&
            Dot(n0, n1) < cosFeature)
          {
            const double w = o.LockFeatureEdges ? o.ConstraintWeight : o.FeatureWeight;
            this->AddConstraintPlane(v, x, n0, w);
            this->AddConstraintPlane(v, x, n1, w);
            constraint = o.LockFeatureEdges;
          }
        }
        else
        {
          // Non-manifold edge or orientation seam: kept until constraints are released.
          constraint = true;
        }
        if (constraint)
        {
          forEachSpoke([this](const Spoke& s) { this->Tris[s.Tri].Flags |= 1u << s.Edge; });
        }
      }
      bool flagged = false;
      forEachSpoke([&](const Spoke& s) { flagged |= ((this->Tris[s.Tri].Flags >> s.Edge) & 1u) != 0; });
      if (flagged)
      {
        ends[constrained++ & 1u] = x;
      }
    }

    // Pieces of the fan: the link graph has an edge per triangle.
    uint32_t pieces = static_cast<uint32_t>(groups.size());
    for (uint32_t i = 0; i < count; ++i)
    {
      const uint32_t ra = find(groupOf[2 * i]);
      const uint32_t rb = find(groupOf[2 * i + 1]);
      if (ra != rb)
      {
        groups[ra].Parent = rb;
        --pieces;
      }
    }

    uint8_t kind = KindFree;
    if (pieces > 1)
    {
      kind = KindFixed; // pinch vertex: several fans meet here
    }
    else if (constrained == 2 && !this->SharpTurn(v, ends[0], ends[1]))
    {
      kind = KindCurve;
    }
    else if (constrained > 0)
    {
      kind = KindFixed; // end, junction or sharp corner of constraint curves
    }
    else if (closed)
    {
      kind = KindClosed;
    }
    rec.Kind = kind;
    this->SeedCandidate(v);
  }
  if (this->UseHeap)
  {
    this->Heap.Heapify();
  }
  this->Normals = BigVector<float>(); // no longer needed
  return true;
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
void CollapseEngine::SeedCandidate(uint32_t v)
{
  // Called by the classification as soon as v's kind, constraint edges and
  // quadric are final (edges are classified from their lower end), while
  // its fan is still in cache.
  if (this->Parked(v))
  {
    this->Park(v);
    return;
  }
  Candidate best;
  if (this->BestTarget(v, best, false))
  {
    this->Vertices[v].Target = best.Target;
    this->Vertices[v].Key = KeyOf(best.Cost);
    if (this->UseHeap)
    {
      this->Heap.PushUnordered(v, this->Vertices[v].Key);
    }
  }
}

//------------------------------------------------------------------------------
bool CollapseEngine::CheckCollapse(uint32_t u, uint32_t w)
{
  if (w == Invalid || w == u || this->IsRemoved(w) || this->Parked(u) || this->Parked(w))
  {
    return false;
  }
  const uint32_t base = this->NextStampBase();

  // Batch the memory accesses (the greedy order jumps around the mesh): all
  // triangles of both fans, then all their corners, so that the cache misses
  // overlap instead of queueing behind one another.
  {
    const Vertex& ru = this->Vertices[u];
    const Vertex& rw = this->Vertices[w];
    const uint32_t* lu = this->Pool.data() + ru.AdjStart;
    const uint32_t* lw = this->Pool.data() + rw.AdjStart;
    this->Visited += ru.AdjCount + rw.AdjCount;
    for (uint32_t i = 0; i < ru.AdjCount; ++i)
    {
      Prefetch(&this->Tris[lu[i] >> 2]);
    }
    for (uint32_t i = 0; i < rw.AdjCount; ++i)
    {
      Prefetch(&this->Tris[lw[i] >> 2]);
    }
    for (uint32_t i = 0; i < ru.AdjCount; ++i)
    {
      const Tri& tri = this->Tris[lu[i] >> 2];
      const uint32_t j = lu[i] & 3u;
      Prefetch(&this->Vertices[tri.V[Next3(j)]]);
      Prefetch(&this->Vertices[tri.V[Prev3(j)]]);
    }
    for (uint32_t i = 0; i < rw.AdjCount; ++i)
    {
      const Tri& tri = this->Tris[lw[i] >> 2];
      const uint32_t j = lw[i] & 3u;
      Prefetch(&this->Vertices[tri.V[Next3(j)]]);
      Prefetch(&this->Vertices[tri.V[Prev3(j)]]);
    }
  }

  // Link condition. Neighbours of u are marked; the opposite corners of the
  // triangles shared with w are the only common neighbours allowed.
  uint32_t trisU = 0, distinctU = 0, shared = 0;
  this->ForEachLiveTriangle(u, [&](const Tri& tri, uint32_t j) {
    ++trisU;
    const uint32_t a = tri.V[Next3(j)];
    const uint32_t b = tri.V[Prev3(j)];
    uint32_t& ma = this->Vertices[a].Mark;
    uint32_t& mb = this->Vertices[b].Mark;
    if ((ma & ~MarkBits) != base)
    {
      ma = base;
      ++distinctU;
    }
    if ((mb & ~MarkBits) != base)
    {
      mb = base;
      ++distinctU;
    }
    ma |= MarkU;
    mb |= MarkU;
    if (a == w)
    {
      mb |= MarkAllowed;
      ++shared;
    }
    else if (b == w)
    {
      ma |= MarkAllowed;
      ++shared;
    }
  });
  if (shared == 0)
  {
    return false; // no longer adjacent (stale target)
  }

  // Geometry of the triangles that survive around u, and duplicates.
  const bool geometric = this->CurrentLevel < LevelTopologyOnly;
  const bool normalCheck = geometric && this->NormalCheckEnabled;
  const bool sliverCheck = this->CurrentLevel == LevelAll && this->SliverCheckEnabled;
  const double cosMax = this->CosMaxDeviation;
  const double minQuality = this->Options.MinimumTriangleQuality;
  const Vec3 pu = this->Vertices[u].P;
  const Vec3 pw = this->Vertices[w].P;
  const uint32_t* listU = this->Pool.data() + this->Vertices[u].AdjStart;
  const uint32_t countU = this->Vertices[u].AdjCount;
  const uint32_t allowed = base | MarkAllowed;
  for (uint32_t i = 0; i < countU; ++i)
  {
    const Tri& tri = this->Tris[listU[i] >> 2];
    const uint32_t j = listU[i] & 3u;
    const uint32_t a = tri.V[Next3(j)];
    const uint32_t b = tri.V[Prev3(j)];
    if (a == w || b == w)
    {
      continue; // dies
    }
    const Vertex& va = this->Vertices[a];
    const Vertex& vb = this->Vertices[b];
    if ((va.Mark & ~MarkU & ~MarkW) == allowed && (vb.Mark & ~MarkU & ~MarkW) == allowed)
    {
      // (u, a, b) becomes (w, a, b): a duplicate if w already has a triangle on a and b.
      const uint32_t* listW = this->Pool.data() + this->Vertices[w].AdjStart;
      this->Visited += this->Vertices[w].AdjCount;
      for (uint32_t k = 0; k < this->Vertices[w].AdjCount; ++k)
      {
        const Tri& other = this->Tris[listW[k] >> 2];
        if (!(other.Flags & DeadFlag) && other.Has(a) && other.Has(b))
        {
          return false;
        }
      }
    }
    if (!geometric)
    {
      continue;
    }
    const Vec3 ea = Sub(va.P, pw);
    const Vec3 eb = Sub(vb.P, pw);
    const Vec3 nNew = Cross(ea, eb);
    const double lenNew = Dot(nNew, nNew);
    const double la = Dot(ea, ea), lb = Dot(eb, eb);
    // Reject (nearly) zero-area results: sine of the corner angle below 1e-8.
    if (!(lenNew > 1e-16 * la * lb))
    {
      return false;
    }
    const Vec3 nOld = Cross(Sub(va.P, pu), Sub(vb.P, pu));
    const double lenOld = Dot(nOld, nOld);
    if (normalCheck && lenOld > 0.0)
    {
      const double d = Dot(nOld, nNew);
      if (cosMax >= 0.0)
      {
        if (!(d > 0.0) || d * d < cosMax * cosMax * lenOld * lenNew)
        {
          return false;
        }
      }
      else if (d < cosMax * std::sqrt(lenOld * lenNew))
      {
        return false;
      }
    }
    if (sliverCheck)
    {
      // Quality 4 sqrt(3) area / sum of squared edge lengths (Xia et al., eq. 3);
      // reject only when the collapse makes the triangle a sliver (or a worse one).
      const Vec3 ab = Sub(va.P, vb.P);
      const double lab = Dot(ab, ab);
      const double qNew = 2.0 * std::sqrt(3.0) * std::sqrt(lenNew) / (la + lb + lab);
      if (qNew < minQuality)
      {
        const Vec3 fa = Sub(va.P, pu), fb = Sub(vb.P, pu);
        const double qOld =
          2.0 * std::sqrt(3.0) * std::sqrt(lenOld) / (Dot(fa, fa) + Dot(fb, fb) + lab);
        if (qNew < qOld)
        {
          return false;
        }
      }
    }
  }

  // Link condition, second half (after the geometry, which fails more often
  // on rough surfaces and does not need w's fan): the neighbours of w.
  uint32_t trisW = 0, distinctW = 0;
  bool ok = true;
  this->ForEachLiveTriangle(w, [&](const Tri& tri, uint32_t j) {
    ++trisW;
    for (uint32_t x : { tri.V[Next3(j)], tri.V[Prev3(j)] })
    {
      uint32_t& m = this->Vertices[x].Mark;
      if ((m & ~MarkBits) != base)
      {
        m = base | MarkW; // not a neighbour of u
        ++distinctW;
        continue;
      }
      if (!(m & MarkW))
      {
        m |= MarkW;
        ++distinctW;
      }
      if ((m & (MarkU | MarkAllowed)) == MarkU && x != u)
      {
        ok = false; // a common neighbour off the edge: the collapse would pinch
      }
    }
  });
  if (!ok)
  {
    return false;
  }
  // The collapse must leave something behind (a lone triangle, or a fan of
  // triangles all around the edge, would vanish entirely).
  if (trisU + trisW <= 2 * shared)
  {
    return false;
  }
  // Boundary version of the link condition (a virtual vertex joined to every
  // boundary edge): two boundary vertices may only merge along a boundary
  // edge, otherwise the surface pinches. An open fan has one neighbour more
  // than triangles.
  if (distinctU > trisU && distinctW > trisW && shared != 1)
  {
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void CollapseEngine::ApplyCollapse(uint32_t u, uint32_t w)
{
  Vertex& ru = this->Vertices[u];
  Vertex& rw = this->Vertices[w];
  this->RemovedOrder.push_back(u);
  this->SubstituteOf[u] = w;
  this->KillStart.push_back(static_cast<uint32_t>(this->KillList.size()));
  this->HeapRemove(u);
  // The next collapse most likely starts from the new top of the heap:
  // fetch its data while this one is being applied. (Schedules without a
  // heap see further ahead and prefetch themselves: PrefetchCandidate.)
  const uint32_t nextTop =
    this->UseHeap && !this->Heap.Empty() ? this->Heap.Top().Vertex : Invalid;
  this->PrefetchCollapse(nextTop, 0);

  // Triangles around u: those on the edge die, the others now use w (in the
  // same corner). The check just compacted u's list, so every entry is live.
  // u's neighbours are gathered on the way: their candidates change.
  const uint32_t ringBase = this->NextStampBase();
  this->Ring.clear();
  rw.Mark = ringBase;
  this->Soon.clear();
  auto addToRing = [&](uint32_t x) {
    Vertex& rx = this->Vertices[x];
    if (rx.Mark != ringBase)
    {
      rx.Mark = ringBase;
      this->Ring.push_back(x);
      Prefetch(&this->Quadrics[x]); // for the update of its candidates below
      if ((rx.Target == u || (rx.State & BlockedBit) || rx.Kind == KindCurve) &&
        rx.LiveCount <= MaximumFanSize)
      {
        // Probably re-evaluated below: its fan is fetched over this collapse.
        this->Soon.push_back(x);
        Prefetch(this->Pool.data() + rx.AdjStart);
      }
    }
  };
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
      addToRing(x);
      continue;
    }
    tri.V[j] = w;
    listU[survivors++] = entry;
    addToRing(a);
    addToRing(b);
  }
  rw.LiveCount += survivors;
  ru.LiveCount = 0;
  ru.AdjCount = survivors; // u keeps its list until appended (the pool may move)
  this->PrefetchCollapse(nextTop, 1);

  // w's list: drop the dead, append u's survivors.
  {
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
    listU = this->Pool.data() + ru.AdjStart;
    listW = this->Pool.data() + rw.AdjStart;
    std::copy(listU, listU + survivors, listW + kept);
    rw.AdjCount = kept + survivors;
    ru.AdjCount = 0;
  }
  ru.State |= RemovedBit;
  if (rw.Kind == KindClosed && ru.Kind != KindClosed)
  {
    rw.Kind = KindFree; // w may have inherited an open fan
  }
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

  this->PrefetchCollapse(nextTop, 2);
  for (uint32_t x : this->Soon)
  {
    const Vertex& rx = this->Vertices[x];
    const uint32_t* list = this->Pool.data() + rx.AdjStart;
    for (uint32_t i = 0; i < rx.AdjCount; ++i)
    {
      Prefetch(&this->Tris[list[i] >> 2]);
    }
  }

  // Quadrics and the error of this step.
  QuadricRecord& qu = this->Quadrics[u];
  QuadricRecord& qw = this->Quadrics[w];
  LocalQuadric(qu, ru.P).AddTo(qw, rw.P);
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
  {
    // Reported error: the larger of the mean squared distances to the merged
    // face planes and to the merged constraint planes (their weights make the
    // ordering keep boundaries in place, but would distort a distance).
    const double total = qw.C; // the merged quadric at w itself
    double constraint = 0.0, e2c = 0.0;
    if (qw.Slot != Invalid)
    {
      const ConstraintRecord& c = this->Constraints[qw.Slot];
      constraint = c.Q.Evaluate(rw.P);
      e2c = c.Weight > 0.0 ? constraint / c.Weight : 0.0;
    }
    const double face = std::max(total - constraint, 0.0);
    const double e2 = std::max(qw.FaceWeight > 0.0 ? face / qw.FaceWeight : 0.0, e2c);
    // Every plane and vertex lies in the unit box, so no distance exceeds its
    // diagonal: more is rounding (a tiny face weight), which could overflow.
    this->RunningError =
      std::max(this->RunningError, std::sqrt(std::min(e2, 3.0)) * this->Scale);
    this->StepError.push_back(static_cast<float>(this->RunningError));
  }

  this->PrefetchCollapse(nextTop, 3);
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

  // w: new quadric and new neighbours, so a fresh best target. Blocked
  // vertices around w are retried, since the legality of their collapses
  // may have changed; around a hub (degenerate input) only when the level
  // ends (Relax): each would come back to the hub's fan at every collapse
  // into it, O(V^2) per collapse (most of the work on a crumpled fan).
  this->Retry.clear();
  const bool retry = rw.LiveCount <= RetryFanSize;
  {
    CheapestTarget cheapest(LocalQuadric(qw, rw.P), this->Vertices.data());
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
  for (uint32_t x : this->Retry)
  {
    if ((this->Vertices[x].State & (RemovedBit | BlockedBit)) == BlockedBit)
    {
      this->Reevaluate(x);
    }
  }
  this->PrefetchCollapse(nextTop, 4);

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
void CollapseEngine::StartLevel(int level)
{
  this->CurrentLevel = level;
  if (level == LevelNoConstraints)
  {
    // Kinds no longer restrict anything: every live vertex gets new candidates.
    for (uint32_t v = 0; v < this->N; ++v)
    {
      if (!this->IsRemoved(v))
      {
        this->Reevaluate(v);
      }
    }
  }
  else
  {
    for (uint32_t v : this->BlockedList)
    {
      if (!this->IsRemoved(v) && (this->Vertices[v].State & BlockedBit))
      {
        this->Reevaluate(v);
      }
    }
  }
  this->BlockedList.clear();
}

//------------------------------------------------------------------------------
void CollapseEngine::BeginCollapses()
{
  this->SubstituteOf.assign(this->N, Invalid);
  this->RemovedOrder.reserve(this->N);
  this->StepError.reserve(this->N);
  this->KillStart.reserve(this->N);
  this->KillList.reserve(this->T);
  this->Ring.reserve(64);
  this->Soon.reserve(64);
  this->Scratch.reserve(64);

  const double maxDeviation = this->Options.MaximumNormalDeviation;
  this->NormalCheckEnabled = maxDeviation < 180.0;
  this->CosMaxDeviation = std::cos(std::min(std::max(maxDeviation, 0.0), 180.0) * Pi / 180.0);
  this->SliverCheckEnabled = this->Options.MinimumTriangleQuality > 0.0;
  this->CurrentLevel = this->SliverCheckEnabled ? LevelAll : LevelNoSliver;
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

//------------------------------------------------------------------------------
bool CollapseEngine::Relax()
{
  if (this->CurrentLevel + 1 >= LevelEnd)
  {
    if (!this->RetrySkipped)
    {
      return false;
    }
    // Retries skipped around hubs: once more at this level. Each pass
    // re-evaluates only the vertices blocked since the last one.
    this->RetrySkipped = false;
    this->StartLevel(this->CurrentLevel);
    return true;
  }
  this->RetrySkipped = false;
  this->StartLevel(this->CurrentLevel + 1);
  return true;
}

//------------------------------------------------------------------------------
void CollapseEngine::BuildOutput(TOMBuildResult& result)
{
  const uint32_t n = this->N;
  const uint32_t removed = static_cast<uint32_t>(this->RemovedOrder.size());
  const uint32_t base = n - removed;

  // New ids: survivors first in input order, then removed vertices, the first
  // removed getting the last id.
  BigVector<uint32_t> newId(n, Invalid);
  uint32_t next = 0;
  for (size_t i = 0; i < this->InternalIdOf.size(); ++i)
  {
    const uint32_t v = this->InternalIdOf[i];
    if (v != Invalid && !this->IsRemoved(v))
    {
      newId[v] = next++; // survivors in input order
    }
  }
  for (uint32_t step = 0; step < removed; ++step)
  {
    newId[this->RemovedOrder[step]] = n - 1 - step;
  }

  TOMMesh& mesh = result.Mesh;
  mesh.BaseVertexCount = base;
  ReserveHuge(mesh.Substitution, n);
  ReserveHuge(result.VertexOrder, n);
  mesh.Substitution.resize(n);
  result.VertexOrder.resize(n);
  for (uint32_t v = 0; v < n; ++v)
  {
    const uint32_t id = newId[v];
    result.VertexOrder[id] = this->InputIdOf[v];
    mesh.Substitution[id] = this->IsRemoved(v) ? newId[this->SubstituteOf[v]] : id;
  }

  // Triangles: the base ones in input order, then the others by decreasing
  // death step (the last collapse's victims are alive from the fewest
  // vertices), in input order within a step. The rank of every triangle is
  // computed first so that the output is then written in one pass over the
  // input, in input order (reading the input in death order would jump
  // around memory).
  BigVector<uint32_t> rank(this->T);
  uint32_t written = 0;
  for (uint32_t t = 0; t < this->T; ++t)
  {
    if (!(this->Tris[t].Flags & DeadFlag))
    {
      rank[t] = written++;
    }
  }
  const uint32_t baseTriangles = written;
  ReserveHuge(result.TrianglesAtVertexCount, n + 1);
  result.TrianglesAtVertexCount.assign(n + 1, 0);
  uint32_t* alive = result.TrianglesAtVertexCount.data();
  alive[0] = baseTriangles; // turned into a running sum below
  for (uint32_t step = removed; step-- > 0;)
  {
    uint32_t* begin = this->KillList.data() + this->KillStart[step];
    uint32_t* end = step + 1 < removed ? this->KillList.data() + this->KillStart[step + 1]
                                       : this->KillList.data() + this->KillList.size();
    // Usually two triangles: an insertion sort.
    for (uint32_t* i = begin + 1; i < end; ++i)
    {
      for (uint32_t* k = i; k > begin && k[0] < k[-1]; --k)
      {
        std::swap(k[0], k[-1]);
      }
    }
    for (const uint32_t* i = begin; i < end; ++i)
    {
      rank[*i] = written++;
    }
    alive[n - step] += static_cast<uint32_t>(end - begin); // removing vertex n-1-step kills them
  }
  for (uint32_t i = 1; i <= n; ++i)
  {
    alive[i] += alive[i - 1];
  }

  mesh.BaseTriangleCount = baseTriangles;
  ReserveHuge(mesh.Triangles, 3 * static_cast<size_t>(this->T));
  ReserveHuge(result.TriangleOrder, this->T);
  mesh.Triangles.resize(3 * static_cast<size_t>(this->T));
  result.TriangleOrder.resize(this->T);
  uint32_t* out = mesh.Triangles.data();
  for (uint32_t t = 0; t < this->T; ++t)
  {
    // Original connectivity: the internal triangles were rewritten by the collapses.
    const uint32_t input = this->InputTriOf[t];
    const uint32_t r = rank[t];
    result.TriangleOrder[r] = input;
    const uint32_t* c = this->InputTriangles + 3 * static_cast<size_t>(input);
    uint32_t* o = out + 3 * static_cast<size_t>(r);
    o[0] = newId[this->InternalIdOf[c[0]]];
    o[1] = newId[this->InternalIdOf[c[1]]];
    o[2] = newId[this->InternalIdOf[c[2]]];
  }

  // Vertex count i < n is reached after n - i steps; below the base the base
  // error repeats.
  ReserveHuge(result.VertexCountError, n + 1);
  result.VertexCountError.assign(n + 1, 0.f);
  const float baseError = removed > 0 ? this->StepError[removed - 1] : 0.f;
  for (uint32_t i = 0; i < n; ++i)
  {
    result.VertexCountError[i] = i < base ? baseError : this->StepError[n - i - 1];
  }

  // The curve's 8 bytes per sample must stay small next to the one index per
  // vertex of the TOM itself: at most one sample per 256 vertices (at least 8).
  const unsigned curveSamples = std::min<unsigned>(
    this->Options.ErrorCurveSamples, std::max<unsigned>(8u, static_cast<unsigned>(n / 256)));
  mesh.ErrorCurve = TOMErrorCurve::FromVertexErrors(result.VertexCountError.data(),
    result.TrianglesAtVertexCount.data(), n, base, curveSamples);
}

//------------------------------------------------------------------------------
TOMBuildResult CollapseEngine::Run(const double* points, size_t numberOfPoints,
  const uint32_t* triangles, size_t numberOfTriangles, const std::function<bool()>& schedule)
{
  TOMBuildResult result;
  this->ReadInput(points, numberOfPoints, triangles, numberOfTriangles, result);
  auto aborted = [&result]() {
    TOMBuildResult r;
    r.DroppedDegenerateTriangles = result.DroppedDegenerateTriangles;
    r.DroppedDuplicateTriangles = result.DroppedDuplicateTriangles;
    r.UnusedPoints = result.UnusedPoints;
    r.Aborted = true;
    return r;
  };
  if (!this->Progress.Report(0.0))
  {
    return aborted();
  }
  if (this->N == 0)
  {
    // Nothing to simplify: an empty TOM (callers report it).
    result.VertexCountError.assign(1, 0.f);
    result.TrianglesAtVertexCount.assign(1, 0u);
    return this->Progress.Report(1.0) ? result : aborted();
  }
  this->BuildAdjacency();
  this->BuildFaceQuadrics();
  if (!this->ClassifyVertices())
  {
    this->DropDuplicateTriangles(result);
    this->BuildAdjacency();
    this->BuildFaceQuadrics();
    this->ClassifyVertices(); // no duplicate is left
  }

  this->BeginCollapses();
  if (!this->Progress.Report(0.05) || !schedule())
  {
    return aborted();
  }
  this->BuildOutput(result);
  result.FanTrianglesVisited = this->Visited;
  if (!this->Progress.Report(1.0))
  {
    return aborted();
  }
  return result;
}
}
}
