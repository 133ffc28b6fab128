// SPDX-License-Identifier: BSD-3-Clause
#include "MergeTreeAttributes.h"

#include "ScratchBlocks.h"
#include "TOMBuildOptions.h" // for MaximumCoordinateMagnitude
#include "TOMMesh.h"
#include "TOMValidator.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace timecritical
{
namespace
{
constexpr uint32_t None = std::numeric_limits<uint32_t>::max();
constexpr double Pi = 3.14159265358979323846;
// Added to every cone half-angle so that float storage and rounding stay conservative.
constexpr double ConeSlack = 1e-5;

struct Vec
{
  double X, Y, Z;
};
inline Vec Sub(const Vec& a, const Vec& b)
{
  return { a.X - b.X, a.Y - b.Y, a.Z - b.Z };
}
inline double Dot(const Vec& a, const Vec& b)
{
  return a.X * b.X + a.Y * b.Y + a.Z * b.Z;
}
inline Vec Cross(const Vec& a, const Vec& b)
{
  return { a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X };
}
inline double Norm(const Vec& a)
{
  return std::sqrt(Dot(a, a));
}

/// Normal cone: unit axis and half-angle in radians (>= Pi: the whole sphere).
struct Cone
{
  Vec Axis;
  double Angle;
};

/// Smallest cone holding both (section 4.3, Fig. 5).
Cone MergeCones(const Cone& c1, const Cone& c2)
{
  if (c1.Angle >= Pi || c2.Angle >= Pi)
  {
    return { c1.Axis, Pi };
  }
  const double phi = std::acos(std::max(-1.0, std::min(1.0, Dot(c1.Axis, c2.Axis))));
  if (phi + c2.Angle <= c1.Angle)
  {
    return c1;
  }
  if (phi + c1.Angle <= c2.Angle)
  {
    return c2;
  }
  const double angle = 0.5 * (phi + c1.Angle + c2.Angle);
  const double s = std::sin(phi);
  if (angle >= Pi || s < 1e-9)
  {
    return { c1.Axis, Pi };
  }
  // Rotate c1's axis towards c2's by the growth of c1's half-angle.
  const double alpha = angle - c1.Angle;
  const double w1 = std::sin(phi - alpha) / s;
  const double w2 = std::sin(alpha) / s;
  Vec axis = { w1 * c1.Axis.X + w2 * c2.Axis.X, w1 * c1.Axis.Y + w2 * c2.Axis.Y,
    w1 * c1.Axis.Z + w2 * c2.Axis.Z };
  const double n = Norm(axis);
  if (!(n > 0.0))
  {
    return { c1.Axis, Pi };
  }
  axis = { axis.X / n, axis.Y / n, axis.Z / n };
  return { axis, std::min(Pi, angle + ConeSlack) };
}

/// Writes a node's cone. An axis that is not a unit vector (face normals
/// that overflow or underflow on extreme coordinates) gives
/// the whole sphere, which bounds every normal, instead of a cone that lies.
void StoreCone(MergeTree& tree, uint32_t v, const Cone& cone)
{
  const double length = Norm(cone.Axis);
  const bool whole = cone.Angle >= Pi || !(std::abs(length - 1.0) < 1e-6);
  float* axis = &tree.ConeAxis[3 * size_t(v)];
  axis[0] = whole ? 0.0f : static_cast<float>(cone.Axis.X);
  axis[1] = whole ? 0.0f : static_cast<float>(cone.Axis.Y);
  axis[2] = whole ? 1.0f : static_cast<float>(cone.Axis.Z);
  tree.ConeCosine[v] = whole ? -1.0f : static_cast<float>(std::cos(cone.Angle));
}

/// Squared distance from p to triangle abc (closest-point regions).
/// ab = b - a, ac = c - a, ap = p - a (given: the caller has them).
double PointTriangleDistance2(const Vec& p, const Vec& b, const Vec& c, const Vec& ab,
  const Vec& ac, const Vec& ap)
{
  const double d1 = Dot(ab, ap), d2 = Dot(ac, ap);
  if (d1 <= 0 && d2 <= 0)
  {
    return Dot(ap, ap);
  }
  const Vec bp = Sub(p, b);
  const double d3 = Dot(ab, bp), d4 = Dot(ac, bp);
  if (d3 >= 0 && d4 <= d3)
  {
    return Dot(bp, bp);
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0)
  {
    const double v = d1 / (d1 - d3);
    const Vec q = Sub(ap, { v * ab.X, v * ab.Y, v * ab.Z });
    return Dot(q, q);
  }
  const Vec cp = Sub(p, c);
  const double d5 = Dot(ab, cp), d6 = Dot(ac, cp);
  if (d6 >= 0 && d5 <= d6)
  {
    return Dot(cp, cp);
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0)
  {
    const double w = d2 / (d2 - d6);
    const Vec q = Sub(ap, { w * ac.X, w * ac.Y, w * ac.Z });
    return Dot(q, q);
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
  {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    const Vec bc = Sub(c, b);
    const Vec q = Sub(bp, { w * bc.X, w * bc.Y, w * bc.Z });
    return Dot(q, q);
  }
  const double denom = va + vb + vc;
  if (!(std::abs(denom) > 0.0))
  {
    // Degenerate triangle: fall back on its corners (an upper bound).
    return std::min({ Dot(ap, ap), Dot(bp, bp), Dot(cp, cp) });
  }
  const double v = vb / denom, w = vc / denom;
  const Vec q = Sub(ap, { v * ab.X + w * ac.X, v * ab.Y + w * ac.Y, v * ab.Z + w * ac.Z });
  return Dot(q, q);
}

/// Barycentric weights (of a, b, c) of the point of triangle abc closest to p
/// (the closest-point regions of PointTriangleDistance2).
Vec ClosestWeights(const Vec& p, const Vec& a, const Vec& b, const Vec& c)
{
  const Vec ab = Sub(b, a), ac = Sub(c, a), ap = Sub(p, a);
  const double d1 = Dot(ab, ap), d2 = Dot(ac, ap);
  if (d1 <= 0 && d2 <= 0)
  {
    return { 1.0, 0.0, 0.0 };
  }
  const Vec bp = Sub(p, b);
  const double d3 = Dot(ab, bp), d4 = Dot(ac, bp);
  if (d3 >= 0 && d4 <= d3)
  {
    return { 0.0, 1.0, 0.0 };
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0)
  {
    const double v = d1 / (d1 - d3);
    return { 1.0 - v, v, 0.0 };
  }
  const Vec cp = Sub(p, c);
  const double d5 = Dot(ab, cp), d6 = Dot(ac, cp);
  if (d6 >= 0 && d5 <= d6)
  {
    return { 0.0, 0.0, 1.0 };
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0)
  {
    const double w = d2 / (d2 - d6);
    return { 1.0 - w, 0.0, w };
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
  {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return { 0.0, 1.0 - w, w };
  }
  const double denom = va + vb + vc;
  if (!(std::abs(denom) > 0.0))
  {
    return { 1.0, 0.0, 0.0 };
  }
  const double v = vb / denom, w = vc / denom;
  return { 1.0 - v - w, v, w };
}

/**
 * min(best2, squared distance from p to triangle abc), ap = p - a (the same
 * for a whole fan), skipping the exact
 * closest-point search when the distance to the triangle's plane (a lower
 * bound) already reaches best2, with a relative margin far above rounding so
 * the minimum is the same to the bit.
 */
inline double NearerTriangle(
  double best2, const Vec& p, const Vec& a, const Vec& b, const Vec& c, const Vec& ap)
{
  const Vec ab = Sub(b, a), ac = Sub(c, a);
  const Vec n = Cross(ab, ac);
  const double nn = Dot(n, n);
  const double h = Dot(n, ap);
  if (nn > 0.0 && h * h >= best2 * nn * (1.0 + 1e-9))
  {
    return best2;
  }
  return std::min(best2, PointTriangleDistance2(p, b, c, ab, ac, ap));
}

/// Angle in radians between unit vectors (clamped against rounding).
inline double Angle(const Vec& a, const Vec& b)
{
  return std::acos(std::max(-1.0, std::min(1.0, Dot(a, b))));
}

/// Shading state of one vertex: its own (full-resolution) normal, which the
/// renderer interpolates wherever the vertex is displayed, and the normal
/// error (radians) of the node merged into it so far.
struct alignas(16) Shade
{
  float N[3];
  float Deviation;
};
static_assert(sizeof(Shade) == 16, "four vertices per cache line");

/// The shading error as a length (see MergeTreeErrorOptions), at most
/// FLT_MAX: any weight is allowed, and a float error must stay finite.
double ShadingLength(double weight, double radius, double deviation)
{
  return std::min(weight * radius * deviation, double(std::numeric_limits<float>::max()));
}

/// Replay state of one vertex, one cache line: everything an event reads of
/// its neighbours (position, the error and depth of their last merged child,
/// the requirements pushed onto them) and of its own pair (corner list, node
/// error and radius), so that a touched vertex costs one miss.
struct alignas(64) Node
{
  double X, Y, Z;
  double Error;         ///< node error (unrounded) of the subtree merged so far
  double Radius;        ///< node radius of the subtree merged so far
  uint32_t FanStart;    ///< its fan: corners (4t + k) of its triangles, in Fans
  uint32_t FanCount;
  uint32_t Mark;        ///< last event that listed it in its row
  float ChildError;     ///< final error of the last child merged into it (0: none)
  float PushError;      ///< largest error of an event that needs this vertex's event
  /// Depth + 1 of that child (0: none) and largest depth + 1 of such an event,
  /// saturated at 65535: the stored level is clamped to 65534 anyway.
  uint16_t ChildDepth;
  uint16_t PushDepth;
};
static_assert(sizeof(Node) == 64, "one cache line per vertex");

/// One triangle of the replay: current corner ids and whether it has died.
struct alignas(16) Tri
{
  uint32_t Cur[3];
  uint32_t Dead;
};
static_assert(sizeof(Tri) == 16, "four triangles per cache line");

inline void Prefetch(const void* p)
{
#if defined(__GNUC__) || defined(__clang__)
  __builtin_prefetch(p, 1, 3);
#else
  (void)p;
#endif
}

constexpr uint32_t Succ[3] = { 1, 2, 0 };
constexpr uint32_t Pred[3] = { 2, 0, 1 };

/// Sorts a row of distinct ids (rows are short: insertion sort).
void SortRow(uint32_t* first, uint32_t* last)
{
  if (last - first > 48)
  {
    std::sort(first, last);
  }
  else
  {
    for (uint32_t* i = first + 1; i < last; ++i)
    {
      const uint32_t x = *i;
      uint32_t* j = i;
      for (; j > first && *(j - 1) > x; --j)
      {
        *j = *(j - 1);
      }
      *j = x;
    }
  }
}
}

//------------------------------------------------------------------------------
namespace
{
/// An array of trivial T: in scratch memory when given some large enough
/// (uninitialised then), else of its own (zeroed).
template <typename T>
class WorkArray
{
public:
  WorkArray(size_t n, collapse::ScratchBlocks* scratch)
    : Size(n)
  {
    this->Data = scratch ? scratch->Take<T>(n) : nullptr;
    if (!this->Data)
    {
      this->Own.resize(n);
      this->Data = this->Own.data();
    }
  }
  WorkArray(const WorkArray&) = delete;
  WorkArray& operator=(const WorkArray&) = delete;

  T& operator[](size_t i) { return this->Data[i]; }
  const T& operator[](size_t i) const { return this->Data[i]; }
  T* data() { return this->Data; }
  size_t size() const { return this->Size; }
  /// Grows to n (> size()) entries of its own, keeping the contents.
  void Grow(size_t n)
  {
    std::vector<T> grown(n);
    std::copy_n(this->Data, this->Size, grown.begin());
    this->Own.swap(grown);
    this->Data = this->Own.data();
    this->Size = n;
  }

private:
  T* Data = nullptr;
  size_t Size = 0;
  std::vector<T> Own;
};

void CheckShadingWeight(const MergeTreeErrorOptions& options)
{
  if (!(options.ShadingWeight >= 0.0) || !std::isfinite(options.ShadingWeight))
  {
    throw std::invalid_argument("ComputeMergeTree: ShadingWeight must be finite and >= 0");
  }
}

//------------------------------------------------------------------------------
/**
 * One pass over the collapse sequence, finest event first. Costs are cache
 * misses on vertices and triangles scattered by the TOM order, so the state
 * lives in one line per vertex (Node) and half a line per triangle (Tri), the
 * next events' lines are prefetched, and the monotone pass ("must be split
 * first", ViewDependentRefinement's rule) runs in the same loop: every event
 * it depends on is earlier in the replay, so its final error and depth are
 * known. The TOM must be valid and the points finite; point v of the TOM is
 * points[3 * pointIds[v]] (points[3 * v] without ids).
 */
class MergeTreeReplay
{
public:
  MergeTreeReplay(const TOMMesh& tom, const double* points, const uint32_t* pointIds,
    const MergeTreeErrorOptions& options, collapse::ScratchBlocks* scratch)
    : ShadingWeight(options.ShadingWeight)
    , Shading(options.ShadingWeight > 0.0)
    , N(tom.GetNumberOfVertices())
    , B(tom.BaseVertexCount)
    , T(tom.GetNumberOfTriangles())
    , S(tom.Substitution.data())
    , Tom(tom)
    , Nodes(N, scratch)
    // Fans of the full-resolution mesh (corners 4t + k by vertex, t
    // ascending: shifts, not divisions by 3) in one arena: an event writes
    // the new fan of u (its living corners, then v's survivors) at the end,
    // as contiguous corners whose triangles load in parallel (a linked list
    // would chain the misses). Room for 8 corners per event, a few more than
    // an event writes on ordinary meshes; grows by doubling past that.
    , Fans(3 * size_t(T) + 8 * size_t(N - B) + 64, scratch)
    , FanEnd(3 * size_t(T))
    , Cones(N, scratch)
    , Tris(T, scratch)
    , Shades(N, scratch)
    , RowStart(N, scratch)
    , Rows(Tree.Dependencies)
  {
    this->Tree.Level.assign(N, 0);
    this->Tree.Error.assign(N, 0.0f);
    this->Tree.Radius.assign(N, 0.0f);
    this->Tree.ConeAxis.assign(3 * size_t(N), 0.0f);
    this->Tree.ConeCosine.assign(N, -1.0f);
    this->Tree.DependencyOffsets.assign(size_t(N) + 1, 0);
    this->InitializeNodes(points, pointIds);
  }

  MergeTree Run(const uint16_t* levels)
  {
    this->SumFaceVectors();
    this->PlaceFans();
    this->ScatterFans();
    this->FinishLeafCones();
    // Rows in replay order (v descending), in place: turned into vertex
    // order at the end. A few per event.
    this->Rows.reserve(8 * size_t(this->N - this->B) + 64);
    for (uint32_t v = this->N; v-- > this->B;)
    {
      this->PrefetchEvent(v);
      this->ReplayEvent(v);
    }
    this->FinishRoots();
    this->OrderRows();
    this->AssignLevels(levels);
    return std::move(this->Tree);
  }

private:
  /// The triangle (u, A, B) of u's new fan nearest to v, and its squared distance.
  struct Nearest
  {
    double Distance2;
    uint32_t A, B;
  };

  Vec P(uint32_t v) const { return { this->Nodes[v].X, this->Nodes[v].Y, this->Nodes[v].Z }; }
  /// Twice the area of the triangle with corners c, times its unit normal.
  Vec FaceVector(const uint32_t* c) const
  {
    return Cross(Sub(this->P(c[1]), this->P(c[0])), Sub(this->P(c[2]), this->P(c[0])));
  }

  void InitializeNodes(const double* points, const uint32_t* pointIds)
  {
    for (uint32_t v = 0; v < this->N; ++v)
    {
      Node& n = this->Nodes[v];
      const double* p = points + 3 * size_t(pointIds ? pointIds[v] : v);
      n.X = p[0];
      n.Y = p[1];
      n.Z = p[2];
      n.Error = 0.0;
      n.Radius = 0.0;
      n.FanStart = 0;
      n.FanCount = 0;
      n.Mark = None;
      n.ChildError = 0.0f;
      n.ChildDepth = 0;
      n.PushError = 0.0f;
      n.PushDepth = 0;
    }
  }

  // Leaf cones: every original face normal around the vertex (conservative,
  // unlike the vertex normal alone); axis = area-weighted mean, the face
  // vectors summed in triangle order (by scattering them in triangle order,
  // as the fans list them), then the widest face normal from it.

  /// Counts the fans and sums the face vectors around each vertex.
  void SumFaceVectors()
  {
    for (uint32_t v = 0; v < this->N; ++v)
    {
      this->Cones[v] = { { 0.0, 0.0, 0.0 }, 1.0 }; // sum, smallest cosine
    }
    for (uint32_t t = 0; t < this->T; ++t)
    {
      const uint32_t* c = this->Tom.Triangles.data() + 3 * size_t(t);
      if (t + Ahead < this->T)
      {
        for (int k = 0; k < 3; ++k)
        {
          Prefetch(&this->Nodes[c[3 * Ahead + k]]);
          Prefetch(&this->Cones[c[3 * Ahead + k]]);
        }
      }
      const Vec a = this->FaceVector(c);
      for (int k = 0; k < 3; ++k)
      {
        ++this->Nodes[c[k]].FanCount;
        Vec& sum = this->Cones[c[k]].Axis;
        sum = { sum.X + a.X, sum.Y + a.Y, sum.Z + a.Z };
      }
    }
  }

  /// The fans' places in the arena, the leaf cones' axes and the vertex normals.
  void PlaceFans()
  {
    uint32_t fanStart = 0;
    for (uint32_t v = 0; v < this->N; ++v)
    {
      Node& n = this->Nodes[v];
      n.FanStart = fanStart;
      fanStart += n.FanCount;
      n.FanCount = 0;
      const Vec sum = this->Cones[v].Axis;
      const double len = Norm(sum);
      if (!(len > 0.0))
      {
        this->Cones[v] = { { 0.0, 0.0, 1.0 }, Pi }; // no usable face: any direction
        this->Shades[v] = { { 0.0f, 0.0f, 1.0f }, 0.0f };
        continue;
      }
      const Vec axis = { sum.X / len, sum.Y / len, sum.Z / len };
      this->Cones[v].Axis = axis;
      // The vertex normal (area-weighted, as the leaf cone's axis).
      this->Shades[v] = { { static_cast<float>(axis.X), static_cast<float>(axis.Y),
                            static_cast<float>(axis.Z) },
        0.0f };
    }
  }

  /// Fills the fans and the replay's triangles; the smallest cosine of a
  /// face normal to its leaf cone's axis, per vertex.
  void ScatterFans()
  {
    for (uint32_t t = 0; t < this->T; ++t)
    {
      const uint32_t* c = this->Tom.Triangles.data() + 3 * size_t(t);
      if (t + Ahead < this->T)
      {
        for (int k = 0; k < 3; ++k)
        {
          const Node& n = this->Nodes[c[3 * Ahead + k]];
          Prefetch(&this->Fans[n.FanStart + n.FanCount]);
          Prefetch(&this->Cones[c[3 * Ahead + k]]);
        }
      }
      if (t + 2 * Ahead < this->T)
      {
        for (int k = 0; k < 3; ++k)
        {
          Prefetch(&this->Nodes[c[6 * Ahead + k]]);
        }
      }
      Tri& r = this->Tris[t];
      for (uint32_t k = 0; k < 3; ++k)
      {
        Node& n = this->Nodes[c[k]];
        this->Fans[n.FanStart + n.FanCount++] = t << 2 | k;
        r.Cur[k] = c[k];
      }
      r.Dead = 0;
      const Vec a = this->FaceVector(c);
      const double area = Norm(a);
      if (area > 0.0) // zero-area face: no normal to bound
      {
        const Vec unit = { a.X / area, a.Y / area, a.Z / area };
        for (uint32_t k = 0; k < 3; ++k)
        {
          Cone& leaf = this->Cones[c[k]];
          if (leaf.Angle <= 1.0) // still the smallest cosine (Pi: no usable face)
          {
            leaf.Angle = std::min(leaf.Angle, Dot(leaf.Axis, unit));
          }
        }
      }
    }
  }

  /// Turns the smallest cosines into the leaf cones' half-angles.
  void FinishLeafCones()
  {
    for (uint32_t v = 0; v < this->N; ++v)
    {
      Cone& leaf = this->Cones[v];
      if (leaf.Angle <= 1.0)
      {
        const double minCos = leaf.Angle;
        leaf.Angle =
          minCos <= -1.0 ? Pi : std::acos(std::max(-1.0, std::min(1.0, minCos))) + ConeSlack;
      }
    }
  }

  /// Prefetch, one stage per event ahead: the pair's vertices, their fans,
  /// the fans' triangles, the triangles' vertices.
  void PrefetchEvent(uint32_t v)
  {
    const uint32_t base = this->B;
    const uint32_t* parent = this->S;
    if (v >= base + 4)
    {
      const uint32_t w = v - 4;
      Prefetch(&this->Nodes[w]);
      Prefetch(&this->Nodes[parent[w]]);
      Prefetch(&this->Cones[w]);
      Prefetch(&this->Cones[parent[w]]);
      if (this->Shading)
      {
        Prefetch(&this->Shades[w]);
        Prefetch(&this->Shades[parent[w]]);
      }
    }
    if (v >= base + 3)
    {
      Prefetch(&this->Fans[this->Nodes[v - 3].FanStart]);
      Prefetch(&this->Fans[this->Nodes[parent[v - 3]].FanStart]);
    }
    if (v >= base + 2)
    {
      for (const Node* n : { &this->Nodes[v - 2], &this->Nodes[parent[v - 2]] })
      {
        const uint32_t* f = this->Fans.data() + n->FanStart;
        for (uint32_t i = 0; i < n->FanCount; ++i)
        {
          Prefetch(&this->Tris[f[i] >> 2]);
        }
      }
    }
    if (v >= base + 1)
    {
      for (const Node* n : { &this->Nodes[v - 1], &this->Nodes[parent[v - 1]] })
      {
        const uint32_t* f = this->Fans.data() + n->FanStart;
        for (uint32_t i = 0; i < n->FanCount; ++i)
        {
          // The next corner's neighbour only: in a closed fan that is each
          // neighbour once (an open fan's last one may come unfetched).
          const Tri& r = this->Tris[f[i] >> 2];
          const uint32_t a = r.Cur[Succ[f[i] & 3u]];
          Prefetch(&this->Nodes[a]);
          if (this->Shading)
          {
            Prefetch(&this->Shades[a]);
          }
        }
      }
    }
  }

  /// Collapses v into u in the fans: v's triangles on the edge die, its
  /// others move to u; u's new fan is written at the end of the arena, and
  /// the neighbours of both ends make v's row. Returns the triangle of the
  /// new fan nearest to v.
  Nearest MergeFans(uint32_t v, uint32_t u, const Vec& pv, const Vec& pu, const Vec& pvu)
  {
    Node& nv = this->Nodes[v];
    Node& nu = this->Nodes[u];
    std::vector<uint32_t>& rows = this->Rows;
    Nearest near{ std::numeric_limits<double>::infinity(), None, None };
    nu.Mark = v;
    nv.Mark = v;
    auto addNeighbor = [&](uint32_t w) {
      if (this->Nodes[w].Mark != v)
      {
        this->Nodes[w].Mark = v;
        rows.push_back(w);
      }
    };
    auto consider = [&](uint32_t a, uint32_t b) {
      const double d2 = NearerTriangle(near.Distance2, pv, pu, this->P(a), this->P(b), pvu);
      if (d2 < near.Distance2)
      {
        near = { d2, a, b };
      }
    };
    if (this->FanEnd + nv.FanCount + nu.FanCount > this->Fans.size())
    {
      this->Fans.Grow(2 * (this->FanEnd + nv.FanCount + nu.FanCount));
    }
    uint32_t* out = this->Fans.data() + this->FanEnd;
    // v's corners: neighbours, the triangles dying with e_v (they hold u),
    // and the survivors, relabelled to u and moved to u's new fan.
    const uint32_t* fv = this->Fans.data() + nv.FanStart;
    for (uint32_t i = 0; i < nv.FanCount; ++i)
    {
      const uint32_t s = fv[i];
      Tri& r = this->Tris[s >> 2];
      if (r.Dead)
      {
        continue;
      }
      const uint32_t k = s & 3u;
      const uint32_t a = r.Cur[Succ[k]], b = r.Cur[Pred[k]];
      addNeighbor(a);
      addNeighbor(b);
      if (a == u || b == u)
      {
        r.Dead = 1;
      }
      else
      {
        consider(a, b);
        r.Cur[k] = u;
        *out++ = s;
      }
    }
    // u's corners: neighbours, the rest of the new fan around u; drop the dead.
    const uint32_t* fu = this->Fans.data() + nu.FanStart;
    for (uint32_t i = 0; i < nu.FanCount; ++i)
    {
      const uint32_t s = fu[i];
      const Tri& r = this->Tris[s >> 2];
      if (r.Dead)
      {
        continue;
      }
      const uint32_t k = s & 3u;
      const uint32_t a = r.Cur[Succ[k]], b = r.Cur[Pred[k]];
      addNeighbor(a);
      addNeighbor(b);
      consider(a, b);
      *out++ = s;
    }
    nu.FanStart = static_cast<uint32_t>(this->FanEnd);
    nu.FanCount = static_cast<uint32_t>(out - this->Fans.data() - this->FanEnd);
    this->FanEnd += nu.FanCount;
    nv.FanCount = 0;
    return near;
  }

  /**
   * Shading: the renderer interpolates the display vertices' own
   * (full-resolution) normals, so where v was, it now shows the normals of
   * u, a, b mixed at v's nearest point of the new fan (smooth curvature is
   * reproduced; a lost bump is not). The angle between that and v's normal
   * is the local normal error, summed over the children like the geometric
   * error: the normals shown near earlier merged vertices move with this
   * change too. Returns it as a length (see ShadingLength).
   */
  double ShadingError(uint32_t v, uint32_t u, const Vec& pv, const Vec& pu, const Nearest& near,
    double radius)
  {
    Shade& su = this->Shades[u];
    const Shade& sv = this->Shades[v];
    const Vec nuN = { su.N[0], su.N[1], su.N[2] };
    const Vec nvN = { sv.N[0], sv.N[1], sv.N[2] };
    // The angle to the shown normal, or to u's own when no triangle is
    // left: one acos.
    double localAngle = -1.0;
    if (near.A != None)
    {
      const Vec w = ClosestWeights(pv, pu, this->P(near.A), this->P(near.B));
      const Shade& sa = this->Shades[near.A];
      const Shade& sb = this->Shades[near.B];
      const Vec shown = { w.X * nuN.X + w.Y * sa.N[0] + w.Z * sb.N[0],
        w.X * nuN.Y + w.Y * sa.N[1] + w.Z * sb.N[1], w.X * nuN.Z + w.Y * sa.N[2] + w.Z * sb.N[2] };
      const double len = Norm(shown);
      if (len > 1e-12)
      {
        localAngle = Angle(nvN, { shown.X / len, shown.Y / len, shown.Z / len });
      }
    }
    if (localAngle < 0.0)
    {
      localAngle = Angle(nuN, nvN);
    }
    const double deviation =
      std::min(std::max<double>(su.Deviation, sv.Deviation) + localAngle, Pi);
    su.Deviation = static_cast<float>(deviation);
    // As a length: a normal tilted by that angle over the node's radius is
    // a tangent plane whose rim moves by about radius * angle, so its
    // projection in pixels grows with the node's projected size, as the
    // node's share of a squared image error does.
    return ShadingLength(this->ShadingWeight, radius, deviation);
  }

  /**
   * Monotone error and depth: e_v needs its previous sibling (the last child
   * merged into u), its own last child, and for each row vertex n the last
   * child merged into n; events needing e_v pushed onto it before.
   */
  void SetMonotoneError(uint32_t v, uint32_t u, size_t rowBegin, double nodeError,
    double shadingError)
  {
    Node& nv = this->Nodes[v];
    Node& nu = this->Nodes[u];
    float error = std::max(FloatNotBelow(std::max(nodeError, shadingError)), nv.PushError);
    uint32_t depth = nv.PushDepth; // saturated: see Node
    error = std::max(error, std::max(nu.ChildError, nv.ChildError));
    depth = std::max<uint32_t>(depth, std::max(nu.ChildDepth, nv.ChildDepth));
    const uint32_t* row = this->Rows.data() + rowBegin;
    const size_t rowSize = this->Rows.size() - rowBegin;
    for (size_t i = 0; i < rowSize; ++i)
    {
      const Node& n = this->Nodes[row[i]];
      error = std::max(error, n.ChildError);
      depth = std::max<uint32_t>(depth, n.ChildDepth);
    }
    for (size_t i = 0; i < rowSize; ++i)
    {
      if (row[i] >= this->B)
      {
        Node& n = this->Nodes[row[i]];
        n.PushError = std::max(n.PushError, error);
        n.PushDepth =
          static_cast<uint16_t>(std::max<uint32_t>(n.PushDepth, std::min(depth + 1, 65535u)));
      }
    }
    nu.ChildError = error;
    nu.ChildDepth = static_cast<uint16_t>(std::min(depth + 1, 65535u));
    this->Tree.Error[v] = error;
    this->Tree.Level[v] = static_cast<uint16_t>(std::min<uint32_t>(depth, 65534u));
  }

  /// The event that merges v into its parent u = S[v].
  void ReplayEvent(uint32_t v)
  {
    const uint32_t u = this->S[v];
    Node& nv = this->Nodes[v];
    Node& nu = this->Nodes[u];
    const Vec pv = { nv.X, nv.Y, nv.Z }, pu = { nu.X, nu.Y, nu.Z };
    const Vec pvu = Sub(pv, pu);
    const size_t rowBegin = this->Rows.size();
    const Nearest near = this->MergeFans(v, u, pv, pu, pvu);
    SortRow(this->Rows.data() + rowBegin, this->Rows.data() + this->Rows.size());
    this->RowStart[v] = static_cast<uint32_t>(rowBegin);

    // Geometry of the node u + v. Radius: nested spheres around the parent.
    // Error: the triangle inequality over the local surface change (distance
    // of the only moved vertex to the new fan), capped by the radius, which
    // bounds the displacement of every original point of the node.
    const double edge = Norm(pvu);
    const double radius = std::max(nu.Radius, edge + nv.Radius);
    const double local = std::isfinite(near.Distance2) ? std::sqrt(near.Distance2) : edge;
    const double nodeError = std::min(std::max(nu.Error, nv.Error) + local, radius);
    nu.Radius = radius;
    nu.Error = nodeError;
    Cone& cu = this->Cones[u];
    cu = MergeCones(cu, this->Cones[v]);

    // Skipped (no cost) without a shading weight.
    const double shadingError =
      this->Shading ? this->ShadingError(v, u, pv, pu, near, radius) : 0.0;
    this->Tree.Radius[v] = FloatNotBelow(radius);
    StoreCone(this->Tree, v, cu);
    this->SetMonotoneError(v, u, rowBegin, nodeError, shadingError);
  }

  /// Roots bound their whole tree: their own node error and every child's.
  void FinishRoots()
  {
    for (uint32_t w = 0; w < this->B; ++w)
    {
      const Node& n = this->Nodes[w];
      this->Tree.Error[w] = std::max(
        FloatNotBelow(std::max(n.Error, ShadingLength(this->ShadingWeight, n.Radius,
                                          this->Shades[w].Deviation))),
        n.ChildError);
      this->Tree.Radius[w] = FloatNotBelow(n.Radius);
      StoreCone(this->Tree, w, this->Cones[w]);
    }
  }

  /// Dependency rows in vertex order: the replay wrote them from the last
  /// vertex down, so the reversed array lists the rows in vertex order, each
  /// reversed; then each row is turned back.
  void OrderRows()
  {
    std::vector<uint32_t>& rows = this->Rows;
    std::vector<uint32_t>& offsets = this->Tree.DependencyOffsets;
    for (uint32_t v = 0; v < this->N; ++v)
    {
      const uint32_t length = v < this->B ? 0u
        : static_cast<uint32_t>(
            (v == this->B ? rows.size() : this->RowStart[v - 1]) - this->RowStart[v]);
      offsets[size_t(v) + 1] = offsets[v] + length;
    }
    std::reverse(rows.begin(), rows.end());
    for (uint32_t v = this->B; v < this->N; ++v)
    {
      std::reverse(rows.begin() + offsets[v], rows.begin() + offsets[size_t(v) + 1]);
    }
  }

  /// Levels: given, or the depth above (0 = finest) saturated to 16 bits.
  void AssignLevels(const uint16_t* levels)
  {
    MergeTree& tree = this->Tree;
    uint32_t levelCount = 0;
    for (uint32_t v = this->B; v < this->N; ++v)
    {
      const uint32_t level = levels == nullptr ? tree.Level[v] : levels[v];
      tree.Level[v] = static_cast<uint16_t>(level);
      levelCount = std::max(levelCount, level + 1);
    }
    tree.LevelCount = static_cast<uint16_t>(std::min<uint32_t>(levelCount, 65535u));
    for (uint32_t w = 0; w < this->B; ++w)
    {
      tree.Level[w] = tree.LevelCount;
    }
  }

  static constexpr uint32_t Ahead = 8; // triangles whose vertices are prefetched

  const double ShadingWeight;
  const bool Shading;
  const uint32_t N; // vertices
  const uint32_t B; // base vertices
  const uint32_t T; // triangles
  const uint32_t* const S; // the substitution
  const TOMMesh& Tom;
  MergeTree Tree;
  WorkArray<Node> Nodes;
  WorkArray<uint32_t> Fans; // the fans' corners
  size_t FanEnd;            // end of the fans written so far
  WorkArray<Cone> Cones;    // the nodes' normal cones
  WorkArray<Tri> Tris;      // current corner ids of every triangle
  WorkArray<Shade> Shades;
  WorkArray<uint32_t> RowStart; // per event, the start of its row in Rows
  std::vector<uint32_t>& Rows;  // the dependency rows, in Tree
};
}

//------------------------------------------------------------------------------
MergeTree ComputeMergeTree(const TOMMesh& tom, const double* points, const uint16_t* levels,
  const MergeTreeErrorOptions& options)
{
  CheckShadingWeight(options);
  const std::string problem = TOMValidator::Check(tom);
  if (!problem.empty())
  {
    throw std::invalid_argument("ComputeMergeTree: invalid TOM: " + problem);
  }
  const uint32_t N = tom.GetNumberOfVertices();
  if (N > 0 && points == nullptr)
  {
    throw std::invalid_argument("ComputeMergeTree: no points");
  }
  if (tom.GetNumberOfTriangles() >= (1u << 30))
  {
    throw std::invalid_argument("ComputeMergeTree: more than 2^30 triangles");
  }
  for (size_t i = 0; i < 3 * static_cast<size_t>(N); ++i)
  {
    if (!(std::abs(points[i]) <= MaximumCoordinateMagnitude))
    {
      if (!std::isfinite(points[i]))
      {
        throw std::invalid_argument(
          "ComputeMergeTree: non-finite coordinate of point " + std::to_string(i / 3));
      }
      char message[200];
      std::snprintf(message, sizeof(message),
        "ComputeMergeTree: point %zu has a coordinate of magnitude %.3g, beyond the supported "
        "%g (errors and radii are stored as float); scale the data",
        i / 3, std::abs(points[i]), MaximumCoordinateMagnitude);
      throw std::invalid_argument(message);
    }
  }
  return MergeTreeReplay(tom, points, nullptr, options, nullptr).Run(levels);
}

//------------------------------------------------------------------------------
MergeTree detail::ComputeBuiltMergeTree(const TOMMesh& tom, const double* points,
  const uint32_t* pointIds, const uint16_t* levels, const MergeTreeErrorOptions& options,
  collapse::ScratchBlocks* scratch)
{
  CheckShadingWeight(options);
  return MergeTreeReplay(tom, points, pointIds, options, scratch).Run(levels);
}
}
