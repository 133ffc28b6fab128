// SPDX-License-Identifier: BSD-3-Clause
#include "SurfaceDistance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace timecritical
{
namespace
{
constexpr uint32_t LeafSize = 4;
constexpr unsigned MaximumDivisions = 256;

inline double Dot3(const double a[3], const double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// Squared distance from p to the triangle (a, b, c): the closest point by
/// the Voronoi region of p (vertex, edge or face), as in Ericson's
/// "Real-Time Collision Detection", 5.1.5.
double PointTriangleDistance2(const double p[3], const double a[3], const double b[3], const double c[3])
{
  const double ab[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double ac[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  const double ap[3] = { p[0] - a[0], p[1] - a[1], p[2] - a[2] };
  double q[3];
  auto at = [&q](const double o[3], const double d[3], double t) {
    q[0] = o[0] + t * d[0];
    q[1] = o[1] + t * d[1];
    q[2] = o[2] + t * d[2];
  };
  const double d1 = Dot3(ab, ap), d2 = Dot3(ac, ap);
  const double bp[3] = { p[0] - b[0], p[1] - b[1], p[2] - b[2] };
  const double d3 = Dot3(ab, bp), d4 = Dot3(ac, bp);
  const double cp[3] = { p[0] - c[0], p[1] - c[1], p[2] - c[2] };
  const double d5 = Dot3(ab, cp), d6 = Dot3(ac, cp);
  const double vc = d1 * d4 - d3 * d2;
  const double vb = d5 * d2 - d1 * d6;
  const double va = d3 * d6 - d5 * d4;
  if (d1 <= 0.0 && d2 <= 0.0)
  {
    at(a, ab, 0.0);
  }
  else if (d3 >= 0.0 && d4 <= d3)
  {
    at(b, ab, 0.0);
  }
  else if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
  {
    at(a, ab, d1 / (d1 - d3));
  }
  else if (d6 >= 0.0 && d5 <= d6)
  {
    at(c, ab, 0.0);
  }
  else if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
  {
    at(a, ac, d2 / (d2 - d6));
  }
  else if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
  {
    const double bc[3] = { c[0] - b[0], c[1] - b[1], c[2] - b[2] };
    at(b, bc, (d4 - d3) / ((d4 - d3) + (d5 - d6)));
  }
  else
  {
    const double sum = va + vb + vc;
    if (!(sum > 0.0))
    {
      // Degenerate triangle whose regions all failed: fall back to its corners.
      const double da[3] = { ap[0], ap[1], ap[2] };
      return std::min({ Dot3(da, da), Dot3(bp, bp), Dot3(cp, cp) });
    }
    const double v = vb / sum, w = vc / sum;
    for (int i = 0; i < 3; ++i)
    {
      q[i] = a[i] + ab[i] * v + ac[i] * w;
    }
  }
  const double d[3] = { p[0] - q[0], p[1] - q[1], p[2] - q[2] };
  return Dot3(d, d);
}

/// Squared distance from p to the box [lo, hi] (0 inside).
inline double BoxDistance2(const double p[3], const double lo[3], const double hi[3])
{
  double d2 = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    const double d = p[i] < lo[i] ? lo[i] - p[i] : (p[i] > hi[i] ? p[i] - hi[i] : 0.0);
    d2 += d * d;
  }
  return d2;
}
}

//------------------------------------------------------------------------------
SurfaceLocator::SurfaceLocator(
  const double* points, const uint32_t* triangles, size_t numberOfTriangles)
{
  std::vector<uint32_t> order(numberOfTriangles);
  std::iota(order.begin(), order.end(), 0u);
  this->Corners.resize(9 * numberOfTriangles);
  std::vector<double> centroids(3 * numberOfTriangles, 0.0);
  for (size_t t = 0; t < numberOfTriangles; ++t)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double* p = points + 3 * size_t(triangles[3 * t + c]);
      for (int i = 0; i < 3; ++i)
      {
        this->Corners[9 * t + 3 * size_t(c) + size_t(i)] = p[i];
        centroids[3 * t + size_t(i)] += p[i] / 3.0;
      }
    }
  }
  if (numberOfTriangles == 0)
  {
    return;
  }
  this->Nodes.reserve(2 * (numberOfTriangles / LeafSize + 1));
  this->Order.swap(order);
  this->BuildNode(0, static_cast<uint32_t>(numberOfTriangles), centroids);
  // Corners in tree order, so that a leaf reads one contiguous block.
  std::vector<double> sorted(this->Corners.size());
  for (size_t t = 0; t < numberOfTriangles; ++t)
  {
    std::copy_n(&this->Corners[9 * size_t(this->Order[t])], 9, &sorted[9 * t]);
  }
  this->Corners.swap(sorted);
  this->Order = std::vector<uint32_t>();
}

//------------------------------------------------------------------------------
uint32_t SurfaceLocator::BuildNode(uint32_t first, uint32_t count, std::vector<double>& centroids)
{
  const uint32_t index = static_cast<uint32_t>(this->Nodes.size());
  this->Nodes.push_back({});
  Node node{};
  double clo[3], chi[3];
  for (int i = 0; i < 3; ++i)
  {
    node.Lo[i] = clo[i] = std::numeric_limits<double>::infinity();
    node.Hi[i] = chi[i] = -std::numeric_limits<double>::infinity();
  }
  for (uint32_t k = first; k < first + count; ++k)
  {
    const size_t t = this->Order[k];
    for (size_t j = 0; j < 9; ++j)
    {
      const double x = this->Corners[9 * t + j];
      node.Lo[j % 3] = std::min(node.Lo[j % 3], x);
      node.Hi[j % 3] = std::max(node.Hi[j % 3], x);
    }
    for (size_t i = 0; i < 3; ++i)
    {
      clo[i] = std::min(clo[i], centroids[3 * t + i]);
      chi[i] = std::max(chi[i], centroids[3 * t + i]);
    }
  }
  if (count <= LeafSize)
  {
    node.First = first;
    node.Count = count;
    this->Nodes[index] = node;
    return index;
  }
  // Median split along the longest extent of the centroids.
  size_t axis = 0;
  for (size_t i = 1; i < 3; ++i)
  {
    if (chi[i] - clo[i] > chi[axis] - clo[axis])
    {
      axis = i;
    }
  }
  const uint32_t half = count / 2;
  std::nth_element(this->Order.begin() + first, this->Order.begin() + first + half,
    this->Order.begin() + first + count, [&centroids, axis](uint32_t a, uint32_t b) {
      return centroids[3 * size_t(a) + axis] < centroids[3 * size_t(b) + axis];
    });
  node.First = this->BuildNode(first, half, centroids);
  node.Right = this->BuildNode(first + half, count - half, centroids);
  node.Count = 0;
  this->Nodes[index] = node;
  return index;
}

//------------------------------------------------------------------------------
double SurfaceLocator::TriangleDistance2(uint32_t t, const double p[3]) const
{
  const double* c = &this->Corners[9 * size_t(t)];
  return PointTriangleDistance2(p, c, c + 3, c + 6);
}

//------------------------------------------------------------------------------
double SurfaceLocator::SquaredDistance(const double p[3], uint32_t& hint) const
{
  const size_t triangles = this->GetNumberOfTriangles();
  if (triangles == 0)
  {
    return std::numeric_limits<double>::infinity();
  }
  uint32_t bestSlot = hint < triangles ? hint : 0;
  double best = this->TriangleDistance2(bestSlot, p);
  // Depth-first, nearer child first; the tree is balanced (median splits),
  // so its depth is about log2(triangles / LeafSize) and 64 entries suffice.
  uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0)
  {
    const Node& node = this->Nodes[stack[--top]];
    if (BoxDistance2(p, node.Lo, node.Hi) >= best)
    {
      continue;
    }
    if (node.Count > 0)
    {
      for (uint32_t k = node.First; k < node.First + node.Count; ++k)
      {
        const double d2 = this->TriangleDistance2(k, p);
        if (d2 < best)
        {
          best = d2;
          bestSlot = k;
        }
      }
      continue;
    }
    const Node& a = this->Nodes[node.First];
    const Node& b = this->Nodes[node.Right];
    const bool aNearer = BoxDistance2(p, a.Lo, a.Hi) <= BoxDistance2(p, b.Lo, b.Hi);
    stack[top++] = aNearer ? node.Right : node.First;
    stack[top++] = aNearer ? node.First : node.Right;
  }
  hint = bestSlot;
  return best;
}

//------------------------------------------------------------------------------
std::vector<double> SampleSurface(const double* points, size_t numberOfPoints,
  const uint32_t* triangles, size_t numberOfTriangles, double spacing, unsigned minimumDivisions)
{
  std::vector<double> samples;
  std::vector<bool> used(numberOfPoints, false);
  for (size_t i = 0; i < 3 * numberOfTriangles; ++i)
  {
    used[triangles[i]] = true;
  }
  for (size_t v = 0; v < numberOfPoints; ++v)
  {
    if (used[v])
    {
      samples.insert(samples.end(), points + 3 * v, points + 3 * v + 3);
    }
  }
  for (size_t t = 0; t < numberOfTriangles; ++t)
  {
    const double* a = points + 3 * size_t(triangles[3 * t]);
    const double* b = points + 3 * size_t(triangles[3 * t + 1]);
    const double* c = points + 3 * size_t(triangles[3 * t + 2]);
    double longest = 0.0;
    for (const auto& e : { std::make_pair(a, b), std::make_pair(b, c), std::make_pair(c, a) })
    {
      const double d[3] = { e.second[0] - e.first[0], e.second[1] - e.first[1],
        e.second[2] - e.first[2] };
      longest = std::max(longest, std::sqrt(Dot3(d, d)));
    }
    unsigned k = std::max(minimumDivisions, 1u);
    if (spacing > 0.0 && longest / spacing > k)
    {
      k = static_cast<unsigned>(std::min(std::ceil(longest / spacing), double(MaximumDivisions)));
    }
    for (unsigned i = 0; i <= k; ++i)
    {
      for (unsigned j = 0; i + j <= k; ++j)
      {
        if ((i == 0 && j == 0) || i == k || j == k)
        {
          continue; // a corner
        }
        const double u = double(i) / k, v = double(j) / k;
        for (int x = 0; x < 3; ++x)
        {
          samples.push_back(a[x] + u * (b[x] - a[x]) + v * (c[x] - a[x]));
        }
      }
    }
    if (k < 3)
    {
      for (int x = 0; x < 3; ++x)
      {
        samples.push_back((a[x] + b[x] + c[x]) / 3.0);
      }
    }
  }
  return samples;
}

//------------------------------------------------------------------------------
double MaximumDistance(const std::vector<double>& samples, const SurfaceLocator& to)
{
  double worst = 0.0;
  uint32_t hint = 0;
  for (size_t i = 0; i + 2 < samples.size(); i += 3)
  {
    worst = std::max(worst, to.SquaredDistance(&samples[i], hint));
  }
  return std::sqrt(worst);
}

//------------------------------------------------------------------------------
double MeanEdgeLength(const double* points, const uint32_t* triangles, size_t numberOfTriangles)
{
  double sum = 0.0;
  for (size_t t = 0; t < numberOfTriangles; ++t)
  {
    for (size_t c = 0; c < 3; ++c)
    {
      const double* p = points + 3 * size_t(triangles[3 * t + c]);
      const double* q = points + 3 * size_t(triangles[3 * t + (c + 1) % 3]);
      const double d[3] = { q[0] - p[0], q[1] - p[1], q[2] - p[2] };
      sum += std::sqrt(Dot3(d, d));
    }
  }
  return numberOfTriangles > 0 ? sum / (3.0 * double(numberOfTriangles)) : 0.0;
}
}
