// SPDX-License-Identifier: BSD-3-Clause
#include "MergeTreeAttributes.h"

#include "TOMMesh.h"
#include "TOMValidator.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
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

/// Squared distance from p to triangle abc (closest-point regions).
double PointTriangleDistance2(const Vec& p, const Vec& a, const Vec& b, const Vec& c)
{
  const Vec ab = Sub(b, a), ac = Sub(c, a), ap = Sub(p, a);
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

/// Float not below x (radii and errors must stay upper bounds after storage).
float RoundUp(double x)
{
  float f = static_cast<float>(x);
  if (static_cast<double>(f) < x)
  {
    f = std::nextafter(f, std::numeric_limits<float>::infinity());
  }
  return f;
}
}

//------------------------------------------------------------------------------
MergeTree ComputeMergeTree(const TOMMesh& tom, const double* points, const uint16_t* levels)
{
  const std::string problem = TOMValidator::Check(tom);
  if (!problem.empty())
  {
    throw std::invalid_argument("ComputeMergeTree: invalid TOM: " + problem);
  }
  const uint32_t N = tom.GetNumberOfVertices();
  const uint32_t B = tom.BaseVertexCount;
  const uint32_t T = tom.GetNumberOfTriangles();
  if (N > 0 && points == nullptr)
  {
    throw std::invalid_argument("ComputeMergeTree: no points");
  }
  for (size_t i = 0; i < 3 * static_cast<size_t>(N); ++i)
  {
    if (!std::isfinite(points[i]))
    {
      throw std::invalid_argument(
        "ComputeMergeTree: non-finite coordinate of point " + std::to_string(i / 3));
    }
  }
  const uint32_t* S = tom.Substitution.data();
  auto P = [points](uint32_t v) -> Vec {
    return { points[3 * size_t(v)], points[3 * size_t(v) + 1], points[3 * size_t(v) + 2] };
  };

  MergeTree tree;
  tree.Level.assign(N, 0);
  tree.Error.assign(N, 0.0f);
  tree.Radius.assign(N, 0.0f);
  tree.ConeAxis.assign(3 * size_t(N), 0.0f);
  tree.ConeCosine.assign(N, -1.0f);
  tree.DependencyOffsets.assign(size_t(N) + 1, 0);

  // Leaf cones: every original face normal around the vertex (conservative,
  // unlike the vertex normal alone); axis = area-weighted mean.
  std::vector<Cone> cone(N, Cone{ { 0.0, 0.0, 1.0 }, 0.0 });
  std::vector<Vec> faceNormal(T);
  {
    std::vector<Vec> sum(N, Vec{ 0.0, 0.0, 0.0 });
    for (uint32_t t = 0; t < T; ++t)
    {
      const uint32_t* tri = tom.Triangles.data() + 3 * size_t(t);
      const Vec n = Cross(Sub(P(tri[1]), P(tri[0])), Sub(P(tri[2]), P(tri[0])));
      const double len = Norm(n);
      faceNormal[t] = len > 0.0 ? Vec{ n.X / len, n.Y / len, n.Z / len } : Vec{ 0.0, 0.0, 0.0 };
      for (int k = 0; k < 3; ++k)
      {
        Vec& s = sum[tri[k]];
        s = { s.X + n.X, s.Y + n.Y, s.Z + n.Z };
      }
    }
    std::vector<double> minCos(N, 1.0);
    for (uint32_t v = 0; v < N; ++v)
    {
      const double len = Norm(sum[v]);
      if (len > 0.0)
      {
        cone[v].Axis = { sum[v].X / len, sum[v].Y / len, sum[v].Z / len };
      }
      else
      {
        minCos[v] = -1.0; // no usable face: any direction
      }
    }
    for (uint32_t t = 0; t < T; ++t)
    {
      if (faceNormal[t].X == 0.0 && faceNormal[t].Y == 0.0 && faceNormal[t].Z == 0.0)
      {
        continue; // zero-area face: no normal to bound
      }
      const uint32_t* tri = tom.Triangles.data() + 3 * size_t(t);
      for (int k = 0; k < 3; ++k)
      {
        minCos[tri[k]] = std::min(minCos[tri[k]], Dot(cone[tri[k]].Axis, faceNormal[t]));
      }
    }
    for (uint32_t v = 0; v < N; ++v)
    {
      cone[v].Angle =
        minCos[v] <= -1.0 ? Pi : std::acos(std::max(-1.0, std::min(1.0, minCos[v]))) + ConeSlack;
    }
  }

  // Replay: per-vertex singly linked lists of the corners (slots 3t+k) of the
  // living triangles, and the current corner ids.
  std::vector<uint32_t> cur(tom.Triangles);
  std::vector<uint32_t> next(3 * size_t(T), None);
  std::vector<uint32_t> head(N, None);
  for (uint32_t s = 3 * T; s-- > 0;)
  {
    next[s] = head[cur[s]];
    head[cur[s]] = s;
  }
  std::vector<uint8_t> dead(T, 0);
  std::vector<uint32_t> mark(N, None);
  std::vector<double> nodeError(N, 0.0), nodeRadius(N, 0.0);
  std::vector<uint32_t> rowStart(N, 0), rowLength(N, 0);
  std::vector<uint32_t> rows;
  rows.reserve(8 * size_t(N - B) + 16);

  for (uint32_t v = N; v-- > B;)
  {
    const uint32_t u = S[v];
    const Vec pv = P(v), pu = P(u);
    mark[u] = v;
    mark[v] = v;
    rowStart[v] = static_cast<uint32_t>(rows.size());
    double local2 = std::numeric_limits<double>::infinity();
    auto addNeighbor = [&](uint32_t w) {
      if (mark[w] != v)
      {
        mark[w] = v;
        rows.push_back(w);
      }
    };
    // v's corners: neighbours, the triangles dying with e_v (they hold u),
    // and the survivors, relabelled to u and moved to u's list.
    uint32_t moved = None, movedTail = None;
    for (uint32_t s = head[v]; s != None;)
    {
      const uint32_t following = next[s];
      const uint32_t t = s / 3, k = s % 3;
      if (!dead[t])
      {
        const uint32_t a = cur[3 * t + (k + 1) % 3], b = cur[3 * t + (k + 2) % 3];
        addNeighbor(a);
        addNeighbor(b);
        if (a == u || b == u)
        {
          dead[t] = 1;
        }
        else
        {
          local2 = std::min(local2, PointTriangleDistance2(pv, pu, P(a), P(b)));
          cur[s] = u;
          next[s] = moved;
          moved = s;
          if (movedTail == None)
          {
            movedTail = s;
          }
        }
      }
      s = following;
    }
    // u's corners: neighbours, the rest of the new fan around u; drop the dead.
    uint32_t* link = &head[u];
    while (*link != None)
    {
      const uint32_t s = *link;
      const uint32_t t = s / 3, k = s % 3;
      if (dead[t])
      {
        *link = next[s];
        continue;
      }
      const uint32_t a = cur[3 * t + (k + 1) % 3], b = cur[3 * t + (k + 2) % 3];
      addNeighbor(a);
      addNeighbor(b);
      local2 = std::min(local2, PointTriangleDistance2(pv, pu, P(a), P(b)));
      link = &next[s];
    }
    if (moved != None)
    {
      next[movedTail] = head[u];
      head[u] = moved;
    }
    head[v] = None;
    rowLength[v] = static_cast<uint32_t>(rows.size()) - rowStart[v];
    std::sort(rows.begin() + rowStart[v], rows.end());

    // Geometry of the node u + v. Radius: nested spheres around the parent.
    // Error: the triangle inequality over the local surface change (distance
    // of the only moved vertex to the new fan), capped by the radius, which
    // bounds the displacement of every original point of the node.
    const double edge = Norm(Sub(pv, pu));
    const double radius = std::max(nodeRadius[u], edge + nodeRadius[v]);
    const double local = std::isfinite(local2) ? std::sqrt(local2) : edge;
    const double error = std::min(std::max(nodeError[u], nodeError[v]) + local, radius);
    nodeRadius[u] = radius;
    nodeError[u] = error;
    cone[u] = MergeCones(cone[u], cone[v]);
    tree.Error[v] = RoundUp(error);
    tree.Radius[v] = RoundUp(radius);
    tree.ConeAxis[3 * size_t(v)] = static_cast<float>(cone[u].Axis.X);
    tree.ConeAxis[3 * size_t(v) + 1] = static_cast<float>(cone[u].Axis.Y);
    tree.ConeAxis[3 * size_t(v) + 2] = static_cast<float>(cone[u].Axis.Z);
    tree.ConeCosine[v] = cone[u].Angle >= Pi ? -1.0f : static_cast<float>(std::cos(cone[u].Angle));
  }
  for (uint32_t w = 0; w < B; ++w)
  {
    tree.Error[w] = RoundUp(nodeError[w]);
    tree.Radius[w] = RoundUp(nodeRadius[w]);
    tree.ConeAxis[3 * size_t(w)] = static_cast<float>(cone[w].Axis.X);
    tree.ConeAxis[3 * size_t(w) + 1] = static_cast<float>(cone[w].Axis.Y);
    tree.ConeAxis[3 * size_t(w) + 2] = static_cast<float>(cone[w].Axis.Z);
    tree.ConeCosine[w] = cone[w].Angle >= Pi ? -1.0f : static_cast<float>(std::cos(cone[w].Angle));
  }

  // Dependency rows in vertex order.
  for (uint32_t v = 0; v < N; ++v)
  {
    tree.DependencyOffsets[size_t(v) + 1] = tree.DependencyOffsets[v] + rowLength[v];
  }
  tree.Dependencies.resize(tree.DependencyOffsets[N]);
  for (uint32_t v = B; v < N; ++v)
  {
    std::copy(rows.begin() + rowStart[v], rows.begin() + rowStart[v] + rowLength[v],
      tree.Dependencies.begin() + tree.DependencyOffsets[v]);
  }

  // Children sorted by id, to find the splits each event needs first.
  std::vector<uint32_t> childOffsets(size_t(N) + 1, 0), children(N - B);
  for (uint32_t v = B; v < N; ++v)
  {
    ++childOffsets[size_t(S[v]) + 1];
  }
  for (uint32_t v = 0; v < N; ++v)
  {
    childOffsets[size_t(v) + 1] += childOffsets[v];
  }
  {
    std::vector<uint32_t> fill(childOffsets.begin(), childOffsets.end() - 1);
    for (uint32_t v = B; v < N; ++v)
    {
      children[fill[S[v]]++] = v;
    }
  }
  auto firstChildAbove = [&](uint32_t n, uint32_t v) -> size_t {
    return static_cast<size_t>(std::upper_bound(children.begin() + childOffsets[n],
                                 children.begin() + childOffsets[size_t(n) + 1], v) -
      children.begin());
  };

  // Monotonicity and levels over "must be split first" (ViewDependentRefinement's
  // rule; requirements point to smaller ids, so one pass from the finest event
  // suffices): e_v needs its previous sibling (or e_u) and e_n of every
  // dependency n; the first child of n above v needs e_v.
  std::vector<uint32_t> depth(N, 0);
  const bool deriveLevels = levels == nullptr;
  for (uint32_t v = N; v-- > B;)
  {
    float error = tree.Error[v];
    uint32_t level = depth[v];
    const uint32_t* row = tree.Dependencies.data() + tree.DependencyOffsets[v];
    const uint32_t rowSize = tree.DependencyOffsets[size_t(v) + 1] - tree.DependencyOffsets[v];
    for (uint32_t i = 0; i < rowSize; ++i)
    {
      const size_t above = firstChildAbove(row[i], v);
      if (above < childOffsets[size_t(row[i]) + 1])
      {
        error = std::max(error, tree.Error[children[above]]);
        level = std::max(level, depth[children[above]] + 1);
      }
    }
    tree.Error[v] = error;
    depth[v] = level;
    auto push = [&](uint32_t w) {
      tree.Error[w] = std::max(tree.Error[w], error);
      depth[w] = std::max(depth[w], level + 1);
    };
    const uint32_t u = S[v];
    const size_t self = firstChildAbove(u, v) - 1; // v's own slot
    if (self > childOffsets[u])
    {
      push(children[self - 1]);
    }
    else if (u >= B)
    {
      push(u);
    }
    for (uint32_t i = 0; i < rowSize; ++i)
    {
      if (row[i] >= B)
      {
        push(row[i]);
      }
    }
  }
  for (uint32_t v = B; v < N; ++v)
  {
    if (S[v] < B) // roots bound their whole tree
    {
      tree.Error[S[v]] = std::max(tree.Error[S[v]], tree.Error[v]);
    }
  }

  // Levels: given, or the depth above (0 = finest) saturated to 16 bits.
  uint32_t levelCount = 0;
  for (uint32_t v = B; v < N; ++v)
  {
    const uint32_t level = deriveLevels ? std::min<uint32_t>(depth[v], 65534u) : levels[v];
    tree.Level[v] = static_cast<uint16_t>(level);
    levelCount = std::max(levelCount, level + 1);
  }
  tree.LevelCount = static_cast<uint16_t>(std::min<uint32_t>(levelCount, 65535u));
  for (uint32_t w = 0; w < B; ++w)
  {
    tree.Level[w] = tree.LevelCount;
  }
  return tree;
}
}
