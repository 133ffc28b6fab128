// SPDX-License-Identifier: BSD-3-Clause
// The legality check of a collapse (CollapseEngine::CheckCollapse): link
// condition, duplicate triangles, normal flips and slivers.
#include "CollapseEngine.h"

#include <cmath>
#include <cstdint>

namespace timecritical
{
namespace collapse
{
//------------------------------------------------------------------------------
inline void CollapseEngine::PrefetchFans(uint32_t u, uint32_t w)
{
  // Batch the memory accesses (the greedy order jumps around the mesh): all
  // triangles of both fans, then all their corners, so that the cache misses
  // overlap instead of queueing behind one another.
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

//------------------------------------------------------------------------------
inline void CollapseEngine::MarkLinkOfU(uint32_t u, uint32_t w, uint32_t base, LinkCount& link)
{
  // Neighbours of u are marked; the opposite corners of the triangles shared
  // with w are the only common neighbours allowed.
  this->ForEachLiveTriangle(u, [&](const Tri& tri, uint32_t j) {
    ++link.Triangles;
    const uint32_t a = tri.V[Next3(j)];
    const uint32_t b = tri.V[Prev3(j)];
    uint32_t& ma = this->Vertices[a].Mark;
    uint32_t& mb = this->Vertices[b].Mark;
    if ((ma & ~MarkBits) != base)
    {
      ma = base;
      ++link.Neighbours;
    }
    if ((mb & ~MarkBits) != base)
    {
      mb = base;
      ++link.Neighbours;
    }
    ma |= MarkU;
    mb |= MarkU;
    if (a == w)
    {
      mb |= MarkAllowed;
      ++link.Shared;
    }
    else if (b == w)
    {
      ma |= MarkAllowed;
      ++link.Shared;
    }
  });
}

//------------------------------------------------------------------------------
inline bool CollapseEngine::WouldDuplicate(uint32_t w, uint32_t a, uint32_t b)
{
  // (u, a, b) becomes (w, a, b): a duplicate if w already has a triangle on a and b.
  const uint32_t* listW = this->Pool.data() + this->Vertices[w].AdjStart;
  this->Visited += this->Vertices[w].AdjCount;
  for (uint32_t k = 0; k < this->Vertices[w].AdjCount; ++k)
  {
    const Tri& other = this->Tris[listW[k] >> 2];
    if (!(other.Flags & DeadFlag) && other.Has(a) && other.Has(b))
    {
      return true;
    }
  }
  return false;
}

namespace
{
/// The geometric checks of a collapse at the current relaxation level.
struct SurvivorChecks
{
  bool Normal;       // no normal may turn by more than the maximum deviation
  bool Sliver;       // no sliver may appear (or get worse)
  double CosMax;     // cosine of the maximum normal deviation
  double MinQuality; // the sliver threshold
};

/// Whether triangle (u, a, b) may become (w, a, b): not (nearly) zero area,
/// its normal not turned too far, not made a sliver.
inline bool SurvivorAcceptable(
  const Vec3& pu, const Vec3& pw, const Vec3& pa, const Vec3& pb, const SurvivorChecks& checks)
{
  const Vec3 ea = Sub(pa, pw);
  const Vec3 eb = Sub(pb, pw);
  const Vec3 nNew = Cross(ea, eb);
  const double lenNew = Dot(nNew, nNew);
  const double la = Dot(ea, ea), lb = Dot(eb, eb);
  // Reject (nearly) zero-area results: sine of the corner angle below 1e-8.
  if (!(lenNew > 1e-16 * la * lb))
  {
    return false;
  }
  const Vec3 nOld = Cross(Sub(pa, pu), Sub(pb, pu));
  const double lenOld = Dot(nOld, nOld);
  if (checks.Normal && lenOld > 0.0)
  {
    const double d = Dot(nOld, nNew);
    const double cosMax = checks.CosMax;
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
  if (checks.Sliver)
  {
    // Quality 4 sqrt(3) area / sum of squared edge lengths (Xia et al., eq. 3);
    // reject only when the collapse makes the triangle a sliver (or a worse one).
    const Vec3 ab = Sub(pa, pb);
    const double lab = Dot(ab, ab);
    const double qNew = 2.0 * std::sqrt(3.0) * std::sqrt(lenNew) / (la + lb + lab);
    if (qNew < checks.MinQuality)
    {
      const Vec3 fa = Sub(pa, pu), fb = Sub(pb, pu);
      const double qOld =
        2.0 * std::sqrt(3.0) * std::sqrt(lenOld) / (Dot(fa, fa) + Dot(fb, fb) + lab);
      if (qNew < qOld)
      {
        return false;
      }
    }
  }
  return true;
}
}

//------------------------------------------------------------------------------
inline bool CollapseEngine::SurvivorsStayValid(uint32_t u, uint32_t w, uint32_t base)
{
  // The triangles that survive around u (those on the edge die): no
  // duplicates, and at the geometric levels, acceptable geometry.
  const bool geometric = this->CurrentLevel < LevelTopologyOnly;
  SurvivorChecks checks;
  checks.Normal = geometric && this->NormalCheckEnabled;
  checks.Sliver = this->CurrentLevel == LevelAll && this->SliverCheckEnabled;
  checks.CosMax = this->CosMaxDeviation;
  checks.MinQuality = this->Options.MinimumTriangleQuality;
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
    if ((va.Mark & ~MarkU & ~MarkW) == allowed && (vb.Mark & ~MarkU & ~MarkW) == allowed &&
      this->WouldDuplicate(w, a, b))
    {
      return false;
    }
    if (geometric && !SurvivorAcceptable(pu, pw, va.P, vb.P, checks))
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
inline bool CollapseEngine::LinkOfWAllowed(uint32_t u, uint32_t w, uint32_t base, LinkCount& link)
{
  // The neighbours of w: none may be a neighbour of u off the edge (a
  // common neighbour other than the opposite corners would pinch).
  bool ok = true;
  this->ForEachLiveTriangle(w, [&](const Tri& tri, uint32_t j) {
    ++link.Triangles;
    for (uint32_t x : { tri.V[Next3(j)], tri.V[Prev3(j)] })
    {
      uint32_t& m = this->Vertices[x].Mark;
      if ((m & ~MarkBits) != base)
      {
        m = base | MarkW; // not a neighbour of u
        ++link.Neighbours;
        continue;
      }
      if (!(m & MarkW))
      {
        m |= MarkW;
        ++link.Neighbours;
      }
      if ((m & (MarkU | MarkAllowed)) == MarkU && x != u)
      {
        ok = false; // a common neighbour off the edge: the collapse would pinch
      }
    }
  });
  return ok;
}

//------------------------------------------------------------------------------
bool CollapseEngine::CheckCollapse(uint32_t u, uint32_t w)
{
  if (w == Invalid || w == u || this->IsRemoved(w) || this->Parked(u) || this->Parked(w))
  {
    return false;
  }
  const uint32_t base = this->NextStampBase();
  this->PrefetchFans(u, w);

  // Link condition, first half: the neighbours of u.
  LinkCount linkU;
  this->MarkLinkOfU(u, w, base, linkU);
  if (linkU.Shared == 0)
  {
    return false; // no longer adjacent (stale target)
  }
  // Geometry of the triangles that survive around u, and duplicates.
  if (!this->SurvivorsStayValid(u, w, base))
  {
    return false;
  }
  // Link condition, second half (after the geometry, which fails more often
  // on rough surfaces and does not need w's fan): the neighbours of w.
  LinkCount linkW;
  if (!this->LinkOfWAllowed(u, w, base, linkW))
  {
    return false;
  }
  // The collapse must leave something behind (a lone triangle, or a fan of
  // triangles all around the edge, would vanish entirely).
  const uint32_t shared = linkU.Shared;
  if (linkU.Triangles + linkW.Triangles <= 2 * shared)
  {
    return false;
  }
  // Boundary version of the link condition (a virtual vertex joined to every
  // boundary edge): two boundary vertices may only merge along a boundary
  // edge, otherwise the surface pinches. An open fan has one neighbour more
  // than triangles.
  if (linkU.Neighbours > linkU.Triangles && linkW.Neighbours > linkW.Triangles && shared != 1)
  {
    return false;
  }
  return true;
}
}
}
