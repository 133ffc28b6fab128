// SPDX-License-Identifier: BSD-3-Clause
// The setup of the collapse engine: input, adjacency, face and constraint quadrics.
#include "CollapseEngine.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace timecritical
{
namespace collapse
{
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
  this->Diagonal = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                     (hi[2] - lo[2]) * (hi[2] - lo[2])) *
    inv;
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

}
}
