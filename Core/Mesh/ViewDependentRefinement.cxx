// SPDX-License-Identifier: BSD-3-Clause
#include "ViewDependentRefinement.h"

#include "MergeTree.h"
#include "TOMMesh.h"
#include "TOMTraversal.h"
#include "TOMValidator.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

namespace timecritical
{
#if defined(__GNUC__)
#define TIMECRITICAL_NOINLINE __attribute__((noinline))
#define TIMECRITICAL_PREFETCH(address) __builtin_prefetch(address)
#else
#define TIMECRITICAL_NOINLINE
#define TIMECRITICAL_PREFETCH(address)
#endif

namespace
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

ViewDependentRefinement::ViewDependentRefinement() = default;
ViewDependentRefinement::~ViewDependentRefinement() = default;

//------------------------------------------------------------------------------
void ViewDependentRefinement::Initialize(
  const TOMMesh& tom, const MergeTree& tree, const float* points)
{
  this->InitializeImpl(tom, tree, points);
}

void ViewDependentRefinement::Initialize(
  const TOMMesh& tom, const MergeTree& tree, const double* points)
{
  this->InitializeImpl(tom, tree, points);
}

template <typename P>
void ViewDependentRefinement::InitializeImpl(
  const TOMMesh& tom, const MergeTree& tree, const P* points)
{
  const std::string problem = TOMValidator::Check(tom);
  if (!problem.empty())
  {
    throw std::invalid_argument("ViewDependentRefinement: invalid TOM: " + problem);
  }
  const uint32_t n = tom.GetNumberOfVertices();
  const uint32_t b = tom.BaseVertexCount;
  const uint32_t nt = tom.GetNumberOfTriangles();
  if (tree.GetNumberOfVertices() != n || tree.Radius.size() != n || tree.ConeCosine.size() != n ||
    tree.ConeAxis.size() != 3 * size_t(n) || tree.DependencyOffsets.size() != size_t(n) + 1 ||
    tree.DependencyOffsets[0] != 0 || tree.DependencyOffsets[n] != tree.Dependencies.size())
  {
    throw std::invalid_argument("ViewDependentRefinement: merge tree does not fit the TOM");
  }
  if (n > 0 && points == nullptr)
  {
    throw std::invalid_argument("ViewDependentRefinement: no points");
  }
  for (uint32_t v = 0; v < n; ++v)
  {
    if (tree.DependencyOffsets[size_t(v) + 1] < tree.DependencyOffsets[v] ||
      (v < b && tree.DependencyOffsets[size_t(v) + 1] != tree.DependencyOffsets[v]))
    {
      throw std::invalid_argument(
        "ViewDependentRefinement: bad dependency row of vertex " + std::to_string(v));
    }
    // Rows may only name vertices alive before the event (the forced-split
    // stack relies on requirements having smaller ids).
    for (uint32_t i = tree.DependencyOffsets[v]; i < tree.DependencyOffsets[size_t(v) + 1]; ++i)
    {
      if (tree.Dependencies[i] >= v || tree.Dependencies[i] == tom.Substitution[v])
      {
        throw std::invalid_argument(
          "ViewDependentRefinement: bad dependency of vertex " + std::to_string(v));
      }
    }
  }
  if (n > 0x7fffffffu)
  {
    throw std::invalid_argument("ViewDependentRefinement: more than 2^31 - 1 vertices");
  }
  this->N = n;
  this->B = b;
  this->T = nt;
  this->Parent = tom.Substitution;
  // Requirement rows: the merge tree's dependency rows (the vertices around
  // u and v just before e_v), and their transpose for the merge queue.
  this->ReqOffsets = tree.DependencyOffsets;
  this->Req = tree.Dependencies;
  this->RevOffsets.assign(size_t(n) + 1, 0);
  for (uint32_t x : this->Req)
  {
    ++this->RevOffsets[size_t(x) + 1];
  }
  for (uint32_t v = 0; v < n; ++v)
  {
    this->RevOffsets[size_t(v) + 1] += this->RevOffsets[v];
  }
  this->Rev.assign(this->Req.size(), 0);
  {
    std::vector<uint32_t> fill(this->RevOffsets.begin(), this->RevOffsets.end() - 1);
    for (uint32_t v = b; v < n; ++v) // ascending rows of each vertex
    {
      for (uint32_t i = this->ReqOffsets[v]; i < this->ReqOffsets[size_t(v) + 1]; ++i)
      {
        this->Rev[fill[this->Req[i]]++] = v;
      }
    }
  }

  std::vector<uint32_t> childOffsets(size_t(n) + 1, 0);
  this->Children.assign(n - b, 0);
  for (uint32_t v = b; v < n; ++v)
  {
    ++childOffsets[size_t(this->Parent[v]) + 1];
  }
  for (uint32_t v = 0; v < n; ++v)
  {
    childOffsets[size_t(v) + 1] += childOffsets[v];
  }
  {
    std::vector<uint32_t> fill(childOffsets.begin(), childOffsets.end() - 1);
    for (uint32_t v = b; v < n; ++v)
    {
      this->Children[fill[this->Parent[v]]++] = v;
    }
  }
  std::vector<uint32_t> previousSibling(n, 0); // 0: none
  for (uint32_t w = 0; w < n; ++w)
  {
    for (uint32_t i = childOffsets[w] + 1; i < childOffsets[size_t(w) + 1]; ++i)
    {
      previousSibling[this->Children[i]] = this->Children[i - 1];
    }
  }

  // Blocks: triangles appearing with each split (contiguous in a TOM).
  const TOMTraversal traversal(tom);
  std::vector<uint32_t> event(nt);
  this->BlockOffsets.assign(size_t(n) + 1, 0);
  for (uint32_t t = 0; t < nt; ++t)
  {
    const uint32_t mvc = traversal.GetMinimumVertexCount(t);
    event[t] = mvc <= b ? None : mvc - 1;
    if (event[t] != None)
    {
      ++this->BlockOffsets[size_t(event[t]) + 1];
    }
  }
  this->BlockOffsets[b] = tom.BaseTriangleCount;
  for (uint32_t v = b; v < n; ++v)
  {
    this->BlockOffsets[size_t(v) + 1] += this->BlockOffsets[v];
  }

  // Birth corners (corners when the triangle appears, i.e. at its block's
  // split) and star slots: slot 3t+k turns from u to v at the split of v
  // exactly when v lies on the corner's substitution chain above the birth.
  this->BirthCorners.assign(3 * size_t(nt), 0);
  this->StarOffsets.assign(size_t(n) + 1, 0);
  for (int pass = 0; pass < 2; ++pass)
  {
    std::vector<uint32_t> fill;
    if (pass == 1)
    {
      for (uint32_t v = 0; v < n; ++v)
      {
        this->StarOffsets[size_t(v) + 1] += this->StarOffsets[v];
      }
      this->StarSlots.assign(this->StarOffsets[n], 0);
      fill.assign(this->StarOffsets.begin(), this->StarOffsets.end() - 1);
    }
    for (uint32_t t = 0; t < nt; ++t)
    {
      for (uint32_t k = 0; k < 3; ++k)
      {
        uint32_t x = tom.Triangles[3 * size_t(t) + k];
        while (x >= b && (event[t] == None || x > event[t]))
        {
          if (pass == 0)
          {
            ++this->StarOffsets[size_t(x) + 1];
          }
          else
          {
            this->StarSlots[fill[x]++] = 3 * t + k;
          }
          x = this->Parent[x];
        }
        this->BirthCorners[3 * size_t(t) + k] = x;
      }
    }
  }

  if (this->WingDependencies)
  {
    // Wing rows: only the third corners of e_v's own triangles (Hoppe's
    // neighbourhood of a vertex split), same closure rule as the full rows.
    std::vector<uint32_t> off(size_t(n) + 1, 0), req;
    for (uint32_t v = 0; v < n; ++v)
    {
      const size_t first = req.size();
      if (v >= b)
      {
        for (uint32_t t = this->BlockOffsets[v]; t < this->BlockOffsets[size_t(v) + 1]; ++t)
        {
          for (int k = 0; k < 3; ++k)
          {
            const uint32_t c = this->BirthCorners[3 * size_t(t) + k];
            if (c != v && c != this->Parent[v])
            {
              req.push_back(c);
            }
          }
        }
      }
      std::sort(req.begin() + first, req.end());
      req.erase(std::unique(req.begin() + first, req.end()), req.end());
      off[size_t(v) + 1] = uint32_t(req.size());
    }
    this->ReqOffsets = off;
    this->Req = req;
    this->RevOffsets.assign(size_t(n) + 1, 0);
    for (uint32_t x : this->Req)
    {
      ++this->RevOffsets[size_t(x) + 1];
    }
    for (uint32_t v = 0; v < n; ++v)
    {
      this->RevOffsets[size_t(v) + 1] += this->RevOffsets[v];
    }
    this->Rev.assign(this->Req.size(), 0);
    std::vector<uint32_t> fill(this->RevOffsets.begin(), this->RevOffsets.end() - 1);
    for (uint32_t v = b; v < n; ++v)
    {
      for (uint32_t i = this->ReqOffsets[v]; i < this->ReqOffsets[size_t(v) + 1]; ++i)
      {
        this->Rev[fill[this->Req[i]]++] = v;
      }
    }
  }
  this->Nodes.assign(n - b, Node{});
  for (uint32_t slot = 0; slot < n - b; ++slot)
  {
    const uint32_t v = this->Children[slot];
    Node& node = this->Nodes[slot];
    const uint32_t c = this->Parent[v];
    for (int i = 0; i < 3; ++i)
    {
      node.Center[i] = static_cast<float>(points[3 * size_t(c) + i]);
      node.Axis[i] = tree.ConeAxis[3 * size_t(v) + i];
    }
    node.Radius = tree.Radius[v];
    node.Error = tree.Error[v];
    const double cosine = std::max(-1.0, std::min(1.0, static_cast<double>(tree.ConeCosine[v])));
    node.Cos = static_cast<float>(cosine);
    node.Sin = static_cast<float>(std::sqrt(std::max(0.0, 1.0 - cosine * cosine)));
  }

  this->Link.assign(n, Links{});
  for (uint32_t v = 0; v < n; ++v)
  {
    Links& l = this->Link[v];
    l.Parent = this->Parent[v];
    l.ChildBegin = childOffsets[v];
    l.ChildEnd = childOffsets[size_t(v) + 1];
    l.BlockBegin = this->BlockOffsets[v];
    l.BlockEnd = this->BlockOffsets[size_t(v) + 1];
    l.StarBegin = this->StarOffsets[v];
    l.StarEnd = this->StarOffsets[size_t(v) + 1];
    l.Slot = None;
    l.Spare = 0;
    l.KeyFrame = 0;
    l.Key = 0.0f;
  }
  for (uint32_t slot = 0; slot < n - b; ++slot)
  {
    this->Link[this->Children[slot]].Slot = slot;
  }
  this->MakePrioritiesMonotone();
  // Needs: per vertex, the events of Rev[parent] between its previous sibling
  // and it, then its row; the full rows and their transpose are dropped.
  this->Needs.clear();
  this->Needs.reserve(this->Req.size() + this->Rev.size());
  for (uint32_t v = 0; v < n; ++v)
  {
    Links& l = this->Link[v];
    l.NeedBegin = static_cast<uint32_t>(this->Needs.size());
    if (v >= b)
    {
      const uint32_t u = this->Parent[v];
      const uint32_t* begin = this->Rev.data() + this->RevOffsets[u];
      const uint32_t* end = this->Rev.data() + this->RevOffsets[size_t(u) + 1];
      // Previous sibling: the child before v in Children (0 for the first).
      const uint32_t* first = std::upper_bound(begin, end, previousSibling[v]);
      this->Needs.insert(this->Needs.end(), first, std::lower_bound(first, end, v));
      this->Needs.insert(this->Needs.end(), this->Req.begin() + this->ReqOffsets[v],
        this->Req.begin() + this->ReqOffsets[size_t(v) + 1]);
    }
    l.NeedEnd = static_cast<uint32_t>(this->Needs.size());
  }
  std::vector<uint32_t>().swap(this->Req);
  std::vector<uint32_t>().swap(this->Rev);
  std::vector<uint32_t>().swap(this->ReqOffsets);
  std::vector<uint32_t>().swap(this->RevOffsets);
  this->Active.assign(n, 0);
  this->Holds.assign(n, 0);
  this->Display.assign(3 * size_t(nt), 0);
  this->DisplayId.assign(nt, 0);
  this->DisplayPos.assign(nt, None);
  this->SplitList.assign(n, Candidate{});
  this->MergeList.assign(n, 0);
  this->Touched.assign(n, 0);
  this->Frame = 0;
  this->Stack.assign(n, 0);
  this->StackStage.assign(n, 0);
  this->StackIndex.assign(n, 0);
  this->Work.assign(3 * size_t(n) + 1, 0);
  this->MergeBits.assign(size_t(n) / 64 + 1, 0);
  // Each vertex enters a budget heap once per update, plus re-offers after
  // undone overshoots (bounded below by the capacity check).
  this->SplitHeap.assign(4 * size_t(n) + 64, HeapEntry{});
  this->Pending.assign(n, HeapEntry{});
  this->Sorted.assign(n, HeapEntry{});
  this->BucketStart.assign(Buckets + 1, 0);
  this->MergeHeap.assign(4 * size_t(n) + 64, HeapEntry{});
  this->SplitLog.assign(n, 0);
  this->TradeLog.assign(n, 0);
  this->Reset();
}

//------------------------------------------------------------------------------
/*
 * Fixed-accuracy fronts depend on the view only if a wanted event is reached
 * from the coarsest front, i.e. if the events that must be split before it
 * are wanted too: its previous sibling (same centre) and, for a first child,
 * its parent's event. The builder nests them (spheres around the parent,
 * cumulative cones, monotone errors), so priorities cannot grow along that
 * order in exact arithmetic, but float storage and rounding can make a
 * tangent child poke out by an ulp, and then a grazing frustum plane, the
 * eye or a silhouette tips the order. Here each such predecessor is widened
 * to hold its successor with a margin far above the rounding of Evaluate()
 * (relative 1e-5 of the radii, 1e-6 rad of the cones; double arithmetic
 * errs by ~1e-15 of the coordinates, and distinct float points are at least
 * ~6e-8 of them apart), which only makes the bounds more conservative. From
 * the finest event down, so each widened node is then held by its own
 * predecessor. Also sets the default near distance, which must be one for
 * all nodes for the same reason.
 */
void ViewDependentRefinement::MakePrioritiesMonotone()
{
  constexpr double RadiusMargin = 1e-5;
  constexpr double AngleMargin = 1e-6;
  auto angle = [](const Node& node) {
    return node.Cos <= -1.0f ? Pi : std::atan2(static_cast<double>(node.Sin), static_cast<double>(node.Cos));
  };
  for (uint32_t slot = this->N - this->B; slot-- > 0;)
  {
    const uint32_t v = this->Children[slot];
    const uint32_t u = this->Parent[v];
    uint32_t predecessor = None;
    if (slot > this->Link[u].ChildBegin)
    {
      predecessor = slot - 1; // previous sibling
    }
    else if (u >= this->B)
    {
      predecessor = this->Link[u].Slot; // parent's event
    }
    if (predecessor == None)
    {
      continue; // first child of a base vertex: a candidate of every front
    }
    const Node& s = this->Nodes[slot];
    Node& d = this->Nodes[predecessor];
    d.Error = std::max(d.Error, s.Error);
    double gap2 = 0.0, axisDot = 0.0, sLength2 = 0.0, dLength2 = 0.0;
    for (int i = 0; i < 3; ++i)
    {
      const double delta = static_cast<double>(s.Center[i]) - d.Center[i];
      gap2 += delta * delta;
      axisDot += static_cast<double>(s.Axis[i]) * d.Axis[i];
      sLength2 += static_cast<double>(s.Axis[i]) * s.Axis[i];
      dLength2 += static_cast<double>(d.Axis[i]) * d.Axis[i];
    }
    const double radius = (std::sqrt(gap2) + s.Radius) * (1.0 + RadiusMargin);
    if (radius > d.Radius)
    {
      d.Radius = FloatNotBelow(radius);
    }
    if (d.Cos > -1.0f)
    {
      // Angle between the axes (not quite unit as floats).
      const double lengths = std::sqrt(sLength2 * dLength2);
      const double cosine = lengths > 0.0 ? std::max(-1.0, std::min(1.0, axisDot / lengths)) : -1.0;
      const double needed = std::acos(cosine) + angle(s) + AngleMargin;
      if (needed >= Pi)
      {
        d.Cos = -1.0f; // the whole sphere of directions
        d.Sin = 0.0f;
      }
      else if (needed > angle(d))
      {
        d.Cos = static_cast<float>(std::cos(needed));
        d.Sin = static_cast<float>(std::sin(needed));
      }
    }
  }
  float largest = 0.0f;
  for (uint32_t v = 0; v < this->B; ++v)
  {
    const uint32_t slot = this->Link[v].ChildBegin;
    if (slot < this->Link[v].ChildEnd)
    {
      largest = std::max(largest, this->Nodes[slot].Radius); // a root's first event holds it all
    }
  }
  this->DefaultNear = largest > 0.0f ? 1e-3 * largest : 1e-30;
}

//------------------------------------------------------------------------------
void ViewDependentRefinement::Reset()
{
  std::fill(this->Active.begin(), this->Active.end(), 0);
  std::fill(this->Holds.begin(), this->Holds.end(), 0);
  for (Links& l : this->Link)
  {
    l.ActiveChildren = 0;
    l.SplitPos = None;
    l.MergePos = None;
  }
  std::fill(this->DisplayPos.begin(), this->DisplayPos.end(), None);
  std::fill(this->Active.begin(), this->Active.begin() + this->B, 1);
  this->SplitListSize = 0;
  this->MergeListSize = 0;
  for (uint32_t w = 0; w < this->B; ++w)
  {
    this->RefreshSplitCandidate(w);
  }
  this->ActiveVertexCount = this->B;
  this->DisplayCount = 0;
  const uint32_t base = this->N > 0 ? this->BlockOffsets[this->B] : 0;
  for (uint32_t t = 0; t < base; ++t)
  {
    this->AddDisplay(t);
  }
  this->Statistics = RefinementStatistics{};
  this->ContinueUpdate = false;
  this->Statistics.DisplayVertices = this->ActiveVertexCount;
  this->Statistics.DisplayTriangles = this->DisplayCount;
}

void ViewDependentRefinement::SetView(const RefinementView& view)
{
  this->View = view;
}

//------------------------------------------------------------------------------
void ViewDependentRefinement::PrepareView()
{
  const RefinementView& v = this->View;
  this->EyeX = v.Eye[0];
  this->EyeY = v.Eye[1];
  this->EyeZ = v.Eye[2];
  double len = std::sqrt(v.Direction[0] * v.Direction[0] + v.Direction[1] * v.Direction[1] +
    v.Direction[2] * v.Direction[2]);
  if (!(len > 0.0))
  {
    len = 1.0;
  }
  this->DirX = v.Direction[0] / len;
  this->DirY = v.Direction[1] / len;
  this->DirZ = v.Direction[2] / len;
  len = std::sqrt(v.LightDirection[0] * v.LightDirection[0] +
    v.LightDirection[1] * v.LightDirection[1] + v.LightDirection[2] * v.LightDirection[2]);
  if (!(len > 0.0))
  {
    len = 1.0;
  }
  this->LightX = v.LightDirection[0] / len;
  this->LightY = v.LightDirection[1] / len;
  this->LightZ = v.LightDirection[2] / len;
  const double height = v.ViewportHeight > 0.0 ? v.ViewportHeight : 1.0;
  if (v.Parallel)
  {
    this->PixelsPerUnit = height / (2.0 * (v.ParallelScale > 0.0 ? v.ParallelScale : 1.0));
  }
  else
  {
    const double angle = std::min(179.0, std::max(1e-3, v.ViewAngle)) * Pi / 180.0;
    this->PixelsPerUnit = height / (2.0 * std::tan(0.5 * angle));
  }
  // Bounded so that an error times it stays finite: no priority is then
  // infinity over infinity (NaN would be unwanted while a smaller error,
  // projected as 0, is wanted).
  this->PixelsPerUnit = std::min(this->PixelsPerUnit, 1e30);
  // An eye (perspective) or direction (parallel) that is not finite gives
  // no view: every node counts as culled, so the front is the coarsest.
  this->BrokenView = v.Parallel
    ? !(std::isfinite(this->DirX) && std::isfinite(this->DirY) && std::isfinite(this->DirZ))
    : !(std::isfinite(this->EyeX) && std::isfinite(this->EyeY) && std::isfinite(this->EyeZ));
  // Normalized, so that a x + b y + c z + d is a distance to compare with
  // radii; planes without a usable normal are left out.
  this->PlaneCount = 0;
  for (int i = 0; i < std::min(6, v.NumberOfFrustumPlanes); ++i)
  {
    const double* plane = v.FrustumPlanes[i];
    const double norm =
      std::sqrt(plane[0] * plane[0] + plane[1] * plane[1] + plane[2] * plane[2]);
    if (norm > 0.0 && std::isfinite(norm) && std::isfinite(plane[3]))
    {
      for (int k = 0; k < 4; ++k)
      {
        this->Planes[k][this->PlaneCount] = plane[k] / norm;
      }
      ++this->PlaneCount;
    }
  }
  for (int i = this->PlaneCount; i < 8; ++i)
  {
    for (int k = 0; k < 4; ++k)
    {
      // Unused: 0 x + 0 y + 0 z + max >= -r, never outside.
      this->Planes[k][i] = k == 3 ? std::numeric_limits<double>::max() : 0.0;
    }
  }
  // Smallest threshold factor any node can get (SurelyUnwanted()).
  const double silhouette = this->SilhouetteRefinement ? this->SilhouetteFactor : 1.0;
  const double highlight = this->HighlightRefinement ? this->HighlightFactor : 1.0;
  this->MinimumFactor =
    std::min(std::min(1.0, silhouette * highlight), std::min(silhouette, highlight));
  this->UnwantedScale = this->MinimumFactor > 0.0 && this->PixelThreshold > 0.0
    ? this->PixelsPerUnit / (this->MinimumFactor * this->PixelThreshold * (1.0 - 1e-6))
    : 0.0;

  // Sleeping candidates (Candidate::WakeAt) stay so while the eye has moved
  // less than their radius since; the odometer sums the eye's moves (at least
  // the distance between any two of its positions). Anything else that their
  // decision depends on (but the frustum and the near plane, which can only
  // make them more unwanted) wakes them all when it changes.
  const double settings[] = { this->PixelThreshold, this->PixelsPerUnit,
    v.Parallel ? 1.0 : 0.0, this->BackFaceSimplification ? 1.0 : 0.0,
    this->SilhouetteRefinement ? this->SilhouetteFactor : -1.0,
    this->HighlightRefinement ? this->HighlightFactor : -1.0, this->LightX, this->LightY,
    this->LightZ };
  static_assert(sizeof(settings) == sizeof(this->SleepSettings), "one value per setting");
  const double mx = this->EyeX - this->LastEye[0], my = this->EyeY - this->LastEye[1],
               mz = this->EyeZ - this->LastEye[2];
  const double step = std::sqrt(mx * mx + my * my + mz * mz);
  if (std::memcmp(settings, this->SleepSettings, sizeof(settings)) != 0 || !std::isfinite(step) ||
    !std::isfinite(this->Odometer + step))
  {
    this->Odometer = 0.0; // (a non-finite eye would stop it for good)
    std::memcpy(this->SleepSettings, settings, sizeof(settings));
    for (uint32_t i = 0; i < this->SplitListSize; ++i)
    {
      this->SplitList[i].WakeAt = this->SplitList[i].FactorUntil = -1.0;
    }
  }
  else
  {
    this->Odometer += step;
  }
  this->LastEye[0] = this->EyeX;
  this->LastEye[1] = this->EyeY;
  this->LastEye[2] = this->EyeZ;
}

//------------------------------------------------------------------------------
double ViewDependentRefinement::Priority(uint32_t v) const
{
  const uint32_t slot = this->Link[v].Slot;
  return slot != None ? this->Evaluate(this->Nodes[slot]) : 0.0; // a base vertex has no event
}

// Not inlined: every priority comes from the same machine code (no
// context-dependent contraction), so a node gets the same key from the sweep's
// copy as from Nodes.
TIMECRITICAL_NOINLINE double ViewDependentRefinement::Evaluate(const Node& node, Sleep* sleep) const
{
  if (sleep != nullptr)
  {
    *sleep = Sleep{};
  }
  const double cx = node.Center[0], cy = node.Center[1], cz = node.Center[2];
  const double r = node.Radius;
  if (this->BrokenView)
  {
    return -1.0;
  }
  if (this->PlaneCount > 0)
  {
    // Wholly outside a plane. Written as two plain loops so that compilers
    // vectorize them.
    double distance[8];
    for (int i = 0; i < 8; ++i)
    {
      distance[i] = this->Planes[0][i] * cx + this->Planes[1][i] * cy + this->Planes[2][i] * cz +
        this->Planes[3][i] + r;
    }
    int outside = 0;
    for (int i = 0; i < 8; ++i)
    {
      outside |= distance[i] < 0.0;
    }
    if (outside != 0)
    {
      return -1.0;
    }
  }
  double dx, dy, dz, sinB = 0.0, cosB = 1.0, projected, dist = 0.0;
  if (this->View.Parallel)
  {
    dx = this->DirX;
    dy = this->DirY;
    dz = this->DirZ;
    projected = node.Error * this->PixelsPerUnit;
  }
  else
  {
    dx = cx - this->EyeX;
    dy = cy - this->EyeY;
    dz = cz - this->EyeZ;
    dist = std::sqrt(dx * dx + dy * dy + dz * dz);
    if (!(node.Error > 0.0f) && this->PixelThreshold > 0.0)
    {
      // Key 0, unwanted as if culled. (At tau = 0 key 0 is wanted, so the
      // culling tests below decide, as for its coarser nodes.)
      if (sleep != nullptr)
      {
        sleep->Wake = std::numeric_limits<double>::infinity(); // until the settings change
      }
      return 0.0;
    }
    // The node's surface is at least dist - r away, and nothing nearer than
    // the near plane is drawn: project from the larger of the two, so that a
    // node around the eye gets a large but finite priority (a huge tau still
    // gives the coarsest mesh).
    const double nearPlane = this->NearPlane();
    projected = node.Error * this->PixelsPerUnit / std::max(dist - r, nearPlane);
    if (dist <= r)
    {
      // Eye inside the bounding sphere: every view direction, so a silhouette
      // and a highlight, never back-facing.
      const double f = (this->SilhouetteRefinement ? this->SilhouetteFactor : 1.0) *
        (this->HighlightRefinement ? this->HighlightFactor : 1.0);
      return f > 0.0 ? projected / f : std::numeric_limits<double>::infinity();
    }
    // cos(beta) = sqrt(dist^2 - r^2) / dist: both roots at once (a shorter
    // chain of slow operations than the root of 1 - sin^2).
    const double tangent = std::sqrt(std::max(0.0, dx * dx + dy * dy + dz * dz - r * r));
    const double inverse = 1.0 / dist;
    dx *= inverse;
    dy *= inverse;
    dz *= inverse;
    sinB = r * inverse;
    cosB = tangent * inverse;
  }
  // Sleep (see WakeRadius()): the angular margins that keep the node culled,
  // or off silhouettes and highlights, as sines; < 0: none needed.
  double cosPsi = 0.0, cosAngle = 0.0, sinAngle = 0.0; // of the highlight test
  bool marginHighlightNeeded = false;
  double factor = 1.0;
  // Angles to the view directions of the sphere: theta (cone) + beta (sphere),
  // by their cosines and sines (sum formulas instead of acos/asin/cos).
  const double c = node.Cos, s = node.Sin;
  const double cosA = node.Axis[0] * dx + node.Axis[1] * dy + node.Axis[2] * dz;
  const double cosTB = c * cosB - s * sinB;
  const double sinTB = s * cosB + c * sinB;
  bool silhouette = true;
  if (cosTB > 0.0 && c > -1.0) // theta + beta below 90 degrees
  {
    if (this->BackFaceSimplification && cosA > sinTB)
    {
      if (sleep != nullptr && !this->View.Parallel)
      {
        // sin(90 - (theta + beta) - alpha), alpha = angle(axis, d)
        const double margin = cosTB * cosA - sinTB * std::sqrt(std::max(0.0, 1.0 - cosA * cosA));
        sleep->Wake = this->WakeRadius(dist, r, margin, -1.0);
      }
      return -1.0; // every normal faces away from every view direction
    }
    silhouette = std::abs(cosA) <= sinTB;
  }
  if (this->SilhouetteRefinement && silhouette)
  {
    factor *= this->SilhouetteFactor;
  }
  const bool marginSilhouetteNeeded = this->SilhouetteRefinement && !silhouette;
  if (this->HighlightRefinement)
  {
    // Reflection vectors of the light over the cone lie within 2 theta of the
    // axis's reflection R = 2 (a.L) a - L; the highlight is seen when that
    // cone, widened by beta, holds the direction to the eye (-d). theta >= 90
    // degrees (c <= 0) or 2 theta + beta >= 180: every direction.
    bool highlight = c <= 0.0;
    if (!highlight)
    {
      const double c2 = 2.0 * c * c - 1.0, s2 = 2.0 * s * c; // 2 theta < 180 degrees
      cosAngle = c2 * cosB - s2 * sinB;
      sinAngle = s2 * cosB + c2 * sinB;
      highlight = sinAngle <= 0.0 && cosAngle < 0.0;
      if (!highlight)
      {
        const double aL = node.Axis[0] * this->LightX + node.Axis[1] * this->LightY +
          node.Axis[2] * this->LightZ;
        const double dL = this->LightX * dx + this->LightY * dy + this->LightZ * dz;
        cosPsi = dL - 2.0 * aL * cosA; // -R.d
        highlight = cosPsi >= cosAngle; // -R.d >= cos(2 theta + beta)
        marginHighlightNeeded = !highlight;
      }
    }
    if (highlight)
    {
      factor *= this->HighlightFactor;
    }
  }
  const double key = factor > 0.0 ? projected / factor : std::numeric_limits<double>::infinity();
  if (sleep != nullptr && !this->View.Parallel && factor > 0.0)
  {
    // The factor cannot drop while the eye keeps the node off silhouettes and
    // highlights it is not on: sin(|90 - alpha| - (theta + beta)) and
    // sin(psi - (2 theta + beta)) as margins.
    const double sinA = std::sqrt(std::max(0.0, 1.0 - cosA * cosA));
    const double clamped = std::max(-1.0, std::min(1.0, cosPsi));
    const double marginSilhouette =
      marginSilhouetteNeeded ? std::abs(cosA) * cosTB - sinA * sinTB : -1.0;
    const double marginHighlight = marginHighlightNeeded
      ? std::sqrt(1.0 - clamped * clamped) * cosAngle - clamped * sinAngle
      : -1.0;
    sleep->FactorRadius = this->WakeRadius(dist, r, marginSilhouette, marginHighlight);
    sleep->Factor = static_cast<float>(factor);
    if (this->PixelThreshold > 0.0 && !this->IsWanted(static_cast<float>(key)))
    {
      // Unwanted while, besides, the projected error over this factor stays
      // below tau (the near plane only lowers it).
      const double reach = node.Error * this->PixelsPerUnit /
        (factor * this->PixelThreshold * (1.0 - 1e-6));
      sleep->Wake = std::max(0.0, std::min(dist - r - reach, sleep->FactorRadius));
    }
  }
  return key;
}

void ViewDependentRefinement::Doze(Candidate& e, const Sleep& sleep) const
{
  e.WakeAt = this->Odometer + sleep.Wake;
  e.FactorUntil = this->Odometer + sleep.FactorRadius;
  e.Factor = sleep.Factor;
}

double ViewDependentRefinement::KeyBound(const Node& node, float factor) const
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

double ViewDependentRefinement::WakeRadius(
  double dist, double r, double margin0, double margin1) const
{
  // An eye move by rho <= (dist - r) / 2 turns the direction to the centre by
  // at most asin(rho / dist) <= pi/3 rho / dist (asin is convex and rho / dist
  // <= 1/2, asin(1/2) = pi/6) and widens beta = asin(r / dist)
  // by at most rho r / (x sqrt(x^2 - r^2)), x = (dist + r) / 2 (mean value
  // theorem); the sum stays below an angular margin m while it stays below
  // sin m <= m. A relative 1e-6 covers the rounding of the decision itself
  // and of a float axis that is not quite unit.
  constexpr double Slack = 1e-6;
  const double x = 0.5 * (dist + r);
  const double k = Pi / (3.0 * dist) + r / (x * std::sqrt((dist - r) * (dist + 3.0 * r) * 0.25));
  double rho = 0.5 * (dist - r);
  for (const double m : { margin0, margin1 })
  {
    if (m >= 0.0) // < 0: no margin needed
    {
      rho = std::min(rho, (m - Slack) / k);
    }
  }
  return rho > 0.0 ? rho * (1.0 - Slack) : 0.0;
}

bool ViewDependentRefinement::SurelyUnwanted(const Node& node) const
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

void ViewDependentRefinement::NextFrame()
{
  if (++this->Frame == 0) // stamps wrapped: clear them once every 2^32 updates
  {
    for (Links& l : this->Link)
    {
      l.KeyFrame = 0;
    }
    std::fill(this->Touched.begin(), this->Touched.end(), 0u);
    this->Frame = 1;
    this->TouchFrame = 0;
  }
}

float ViewDependentRefinement::Key(uint32_t v)
{
  Links& l = this->Link[v];
  if (l.KeyFrame != this->Frame)
  {
    l.KeyFrame = this->Frame;
    l.Key = static_cast<float>(this->Priority(v));
  }
  return l.Key;
}

bool ViewDependentRefinement::Wanted(uint32_t v)
{
  const Links& l = this->Link[v];
  if (l.KeyFrame != this->Frame && l.Slot != None && this->SurelyUnwanted(this->Nodes[l.Slot]))
  {
    return false; // cheaper than Key() (not cached: asked about again rarely)
  }
  return this->IsWanted(this->Key(v));
}


//------------------------------------------------------------------------------
uint32_t ViewDependentRefinement::NextChild(uint32_t w) const
{
  const Links& l = this->Link[w];
  const uint32_t i = l.ChildBegin + l.ActiveChildren;
  return i < l.ChildEnd ? this->Children[i] : None;
}

uint32_t ViewDependentRefinement::LastActiveChild(uint32_t w) const
{
  const Links& l = this->Link[w];
  return l.ActiveChildren > 0 ? this->Children[l.ChildBegin + l.ActiveChildren - 1] : None;
}

/*
 * Dependency rule. Vertex v needs, to be displayed: its parent u, its
 * previous sibling (children split in id order), every vertex n of its row,
 * and every event below v whose row holds u (no child of a row vertex n above
 * v, i.e. split before e_v at build time, may be displayed without v). So the front is closed under a static relation
 * "x needs y" with y < x, and:
 * - split e_v is legal iff its needs are displayed (the last condition holds
 *   by closure: such a child would need v), so forced splits never block;
 * - merge e_v is legal iff no display vertex needs v: no displayed child, v is
 *   u's last displayed child, no displayed row holds v, no row vertex has a
 *   displayed child above v (all four counted together in Holds).
 * The row vertices being displayed and not finer than at e_v makes the birth
 * corners of e_v's triangles the nearest displayed ancestors of their corners,
 * so the incremental triangles are the selectively refined mesh of the front.
 */
void ViewDependentRefinement::PrefetchOperation(uint32_t v) const
{
  // What Split(v) or Merge(v) will read at random, all reachable from v's
  // record: fetched together instead of one miss after the other.
  const Links& l = this->Link[v];
  TIMECRITICAL_PREFETCH(&this->Link[l.Parent]);
  TIMECRITICAL_PREFETCH(this->Needs.data() + l.NeedBegin);
  TIMECRITICAL_PREFETCH(this->StarSlots.data() + l.StarBegin);
  TIMECRITICAL_PREFETCH(this->DisplayPos.data() + l.BlockBegin);
  TIMECRITICAL_PREFETCH(this->BirthCorners.data() + 3 * size_t(l.BlockBegin));
  if (l.Slot != None)
  {
    TIMECRITICAL_PREFETCH(&this->Nodes[l.Slot]);
  }
  if (l.SplitPos != None)
  {
    TIMECRITICAL_PREFETCH(&this->SplitList[l.SplitPos]);
  }
}

uint32_t ViewDependentRefinement::NextRequirement(uint32_t v, uint8_t& stage, uint32_t& index) const
{
  // The front only grows during a forced split, so what was displayed stays
  // so and the scan resumes where it stopped (each row is read once).
  const uint32_t u = this->Link[v].Parent;
  switch (stage)
  {
    case 0:
      this->PrefetchOperation(v); // v is split once its needs are
      if (!this->Active[u])
      {
        return u;
      }
      stage = 1;
      [[fallthrough]];
    case 1:
    {
      const uint32_t sibling = this->NextChild(u);
      if (sibling != v)
      {
        return sibling; // an earlier-split sibling (smaller id)
      }
      // A displayed vertex that needs v (e.g. a row vertex's child above v):
      // cannot happen on a closed front; kept as a safe refusal.
      if (this->Holds[v] > 0)
      {
        return None;
      }
      // The events whose row holds u below v (those below v's previous
      // sibling are displayed already: the sibling needed them), then v's row.
      index = this->Link[v].NeedBegin;
      stage = 2;
    }
      [[fallthrough]];
    default:
      for (const uint32_t end = this->Link[v].NeedEnd; index < end; ++index)
      {
        if (!this->Active[this->Needs[index]])
        {
          // The later ones will be split too: their records are fetched
          // meanwhile (a chain of misses per forced split otherwise).
          for (uint32_t i = index + 1; i < end; ++i)
          {
            if (!this->Active[this->Needs[i]])
            {
              TIMECRITICAL_PREFETCH(&this->Link[this->Needs[i]]);
            }
          }
          return this->Needs[index];
        }
      }
      return v;
  }
}

bool ViewDependentRefinement::ForceSplit(uint32_t v)
{
  if (this->Active[v])
  {
    return true;
  }
  // Requirements have strictly smaller ids than what needs them, so the
  // stack never holds more than N entries and cannot cycle.
  uint32_t size = 0;
  auto push = [this, &size](uint32_t x) {
    this->Stack[size] = x;
    this->StackStage[size] = 0;
    ++size;
  };
  push(v);
  while (size > 0)
  {
    const uint32_t x = this->Stack[size - 1];
    if (this->Active[x])
    {
      --size;
      continue;
    }
    const uint32_t r = this->NextRequirement(x, this->StackStage[size - 1], this->StackIndex[size - 1]);
    if (r == None)
    {
      ++this->Statistics.BlockedSplits;
      return false;
    }
    if (r == x)
    {
      this->Split(x);
      if (x != v)
      {
        ++this->Statistics.ForcedSplits;
      }
      --size;
    }
    else
    {
      push(r);
    }
  }
  return true;
}

bool ViewDependentRefinement::CanMerge(uint32_t v) const
{
  // O(1): whatever needs v is counted by Split() and Merge() (Holds).
  return v >= this->B && this->Active[v] && this->Holds[v] == 0;
}

//------------------------------------------------------------------------------
void ViewDependentRefinement::AddDisplay(uint32_t t)
{
  const uint32_t p = this->DisplayCount++;
  this->DisplayPos[t] = p;
  this->DisplayId[p] = t;
  std::memcpy(&this->Display[3 * size_t(p)], &this->BirthCorners[3 * size_t(t)], 3 * sizeof(uint32_t));
}

void ViewDependentRefinement::RemoveDisplay(uint32_t t)
{
  const uint32_t p = this->DisplayPos[t];
  const uint32_t last = --this->DisplayCount;
  if (p != last)
  {
    const uint32_t moved = this->DisplayId[last];
    this->DisplayId[p] = moved;
    this->DisplayPos[moved] = p;
    std::memcpy(&this->Display[3 * size_t(p)], &this->Display[3 * size_t(last)], 3 * sizeof(uint32_t));
  }
  this->DisplayPos[t] = None;
}

void ViewDependentRefinement::RefreshSplitCandidate(uint32_t w)
{
  Links& l = this->Link[w];
  const uint32_t slot = l.ChildBegin + l.ActiveChildren; // the next child's
  const uint32_t c = this->Active[w] && slot < l.ChildEnd ? this->Children[slot] : None;
  uint32_t& p = l.SplitPos;
  if (c != None)
  {
    if (p == None)
    {
      p = this->SplitListSize++;
    }
    else if (this->SplitList[p].Id == c)
    {
      return;
    }
    Candidate& e = this->SplitList[p] = Candidate{ this->Nodes[slot], c, w, -1.0, -1.0, 0.0f };
    if (this->Mode == UpdateMode::Fixed && !this->SurelyUnwanted(e.Data))
    {
      // A new candidate of the running update: split if wanted, else it may
      // sleep from now on (the next sweeps skip it).
      Sleep sleep;
      if (this->IsWanted(static_cast<float>(this->Evaluate(e.Data, &sleep))))
      {
        this->Work[this->WorkSize++] = c;
      }
      else
      {
        this->Doze(e, sleep);
      }
    }
  }
  else if (p != None)
  {
    const uint32_t last = --this->SplitListSize;
    if (p != last)
    {
      this->SplitList[p] = this->SplitList[last];
      this->Link[this->SplitList[p].Owner].SplitPos = p;
    }
    p = None;
  }
}

void ViewDependentRefinement::RefreshMergeCandidate(uint32_t x)
{
  const bool member = this->CanMerge(x);
  uint32_t& p = this->Link[x].MergePos;
  if (member == (p != None))
  {
    return;
  }
  if (!member)
  {
    this->LeaveMergeCandidates(x);
    return;
  }
  p = this->MergeListSize++;
  this->MergeList[p] = x;
  // A vertex that becomes mergeable goes to the running update's queue
  // (only merges make vertices mergeable, always coarser ones than the merged).
  if (this->Merging)
  {
    this->MergeBits[x >> 6] |= uint64_t(1) << (x & 63);
  }
  else if (this->Mode == UpdateMode::Budget)
  {
    this->OfferMerge(x);
  }
}

void ViewDependentRefinement::LeaveMergeCandidates(uint32_t x)
{
  uint32_t& p = this->Link[x].MergePos;
  if (p != None)
  {
    const uint32_t moved = this->MergeList[--this->MergeListSize];
    this->MergeList[p] = moved;
    this->Link[moved].MergePos = p;
    p = None;
  }
}

void ViewDependentRefinement::Hold(uint32_t x)
{
  if (this->Holds[x]++ == 0)
  {
    this->LeaveMergeCandidates(x);
  }
}

void ViewDependentRefinement::Release(uint32_t x)
{
  if (--this->Holds[x] == 0)
  {
    this->RefreshMergeCandidate(x);
  }
}

void ViewDependentRefinement::Split(uint32_t v)
{
  const uint32_t u = this->Link[v].Parent;
  const uint32_t previous = this->LastActiveChild(u);
  this->Active[v] = 1;
  ++this->Link[u].ActiveChildren;
  ++this->ActiveVertexCount;
  ++this->Statistics.Splits;
  // v needs its parent, its previous sibling and its row; and u's last
  // displayed child moves from `previous` to v, so the events between them
  // whose row holds u now have a row vertex with a displayed child above them.
  this->Hold(u);
  if (previous != None)
  {
    this->Hold(previous);
  }
  const Links& l = this->Link[v];
  for (uint32_t i = l.NeedBegin; i < l.NeedEnd; ++i)
  {
    this->Hold(this->Needs[i]);
  }
  for (uint32_t t = l.BlockBegin; t < l.BlockEnd; ++t)
  {
    this->AddDisplay(t);
  }
  for (uint32_t i = l.StarBegin; i < l.StarEnd; ++i)
  {
    const uint32_t s = this->StarSlots[i];
    const uint32_t p = this->DisplayPos[s / 3];
    if (p != None)
    {
      this->Display[3 * size_t(p) + s % 3] = v;
    }
  }
  this->RefreshSplitCandidate(u);
  this->RefreshSplitCandidate(v);
  this->RefreshMergeCandidate(v); // nothing needs it yet
  if (this->Mode == UpdateMode::Budget)
  {
    this->Touched[v] = this->TouchFrame;
    this->SplitLog[this->SplitLogSize++] = v;
    this->OfferSplit(u);
    this->OfferSplit(v);
  }
}

void ViewDependentRefinement::Merge(uint32_t v)
{
  const uint32_t u = this->Link[v].Parent;
  this->Active[v] = 0;
  --this->Link[u].ActiveChildren;
  --this->ActiveVertexCount;
  ++this->Statistics.Merges;
  this->LeaveMergeCandidates(v);
  // The reverse of Split(); u's last displayed child moves back from v.
  const uint32_t last = this->LastActiveChild(u);
  this->Release(u);
  if (last != None)
  {
    this->Release(last);
  }
  const Links& l = this->Link[v];
  for (uint32_t i = l.NeedBegin; i < l.NeedEnd; ++i)
  {
    this->Release(this->Needs[i]);
  }
  for (uint32_t t = l.BlockBegin; t < l.BlockEnd; ++t)
  {
    this->RemoveDisplay(t);
  }
  for (uint32_t i = l.StarBegin; i < l.StarEnd; ++i)
  {
    const uint32_t s = this->StarSlots[i];
    const uint32_t p = this->DisplayPos[s / 3];
    if (p != None)
    {
      this->Display[3 * size_t(p) + s % 3] = u;
    }
  }
  this->RefreshSplitCandidate(u);
  this->RefreshSplitCandidate(v);
  if (this->Mode == UpdateMode::Budget)
  {
    this->Touched[v] = this->TouchFrame; // (so not offered as u's candidate again)
  }
}

//------------------------------------------------------------------------------
bool ViewDependentRefinement::OutOfTime()
{
  if (this->OperationLimit > 0 &&
    this->Statistics.Splits + this->Statistics.Merges + this->UndoneOperations >=
      this->OperationLimit)
  {
    return this->Statistics.Interrupted = true;
  }
  // The clock is read every 16 calls (a split or merge is ~0.1-1 us).
  if (this->Deadline > 0.0 && (++this->Checks & 15) == 0 &&
    std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count() >=
      this->Deadline)
  {
    return this->Statistics.Interrupted = true;
  }
  return false;
}

void ViewDependentRefinement::MergeUnwanted()
{
  // Finest first: whatever needs a vertex is finer (larger id), so it has
  // been merged or kept before the vertex is looked at, and one pass reaches
  // the fixed point. A merge only releases coarser vertices (pushed here).
  // Only what is mergeable now is queued (CanMerge() first: it is O(1) and
  // spares most priorities): whatever becomes mergeable later is released by
  // a merge here and pushed then.
  uint64_t* bits = this->MergeBits.data();
  size_t top = 0; // highest word that may hold a bit
  bool any = false;
  for (uint32_t i = 0; i < this->MergeListSize; ++i)
  {
    const uint32_t x = this->MergeList[i]; // CanMerge(x)
    if (!this->Wanted(x))
    {
      bits[x >> 6] |= uint64_t(1) << (x & 63);
      top = std::max<size_t>(top, x >> 6);
      any = true;
    }
  }
  // Merges queue the vertices they make mergeable (RefreshMergeCandidate()).
  this->Merging = true;
  for (size_t word = top; any;)
  {
    if (bits[word] == 0)
    {
      if (word == 0)
      {
        break;
      }
      --word;
      continue;
    }
    if (this->Mode == UpdateMode::None && this->Bounded && this->OutOfTime())
    {
      std::fill(bits, bits + word + 1, uint64_t(0)); // nothing stays queued
      break;
    }
    const int bit = 63 - __builtin_clzll(bits[word]);
    bits[word] &= ~(uint64_t(1) << bit);
    const uint32_t x = uint32_t(word * 64 + size_t(bit));
    if (bits[word] != 0) // the next one's record, fetched meanwhile
    {
      TIMECRITICAL_PREFETCH(&this->Link[word * 64 + size_t(63 - __builtin_clzll(bits[word]))]);
    }
    if (this->Link[x].MergePos == None)
    {
      continue; // !CanMerge(x)
    }
    this->PrefetchOperation(x); // most are merged
    if (this->Wanted(x))
    {
      continue;
    }
    this->Merge(x);
  }
  this->Merging = false;
}

const RefinementStatistics& ViewDependentRefinement::UpdateFixedAccuracy()
{
  const auto start = std::chrono::steady_clock::now();
  this->Statistics = RefinementStatistics{};
  this->ContinueUpdate = false;
  this->PrepareView();
  this->NextFrame();
  // Splits: every wanted candidate (next child of a display vertex), with
  // the splits it needs; each split offers its new candidates.
  this->Mode = UpdateMode::Fixed;
  this->WorkSize = 0;
  // The candidates (next child of each display vertex) are decided here,
  // straight from the list's node copies (a sequential read); only the wanted
  // ones are kept. The view alone decides, and only splits happen until the
  // merges, so a kept candidate stays its owner's next child until it is
  // split: at the pop, Active[c] is all there is to check. Each split offers
  // its new candidates the same way (RefreshSplitCandidate()).
  for (uint32_t i = 0; i < this->SplitListSize; ++i)
  {
    Candidate& e = this->SplitList[i];
    if (e.WakeAt > this->Odometer || this->SurelyUnwanted(e.Data) ||
      (e.FactorUntil > this->Odometer && this->PixelThreshold > 0.0 &&
        this->KeyBound(e.Data, e.Factor) <= this->PixelThreshold))
    {
      continue; // asleep, too far, or below tau with any factor it can have
    }
    Sleep sleep;
    if (this->IsWanted(static_cast<float>(this->Evaluate(e.Data, &sleep))))
    {
      this->Work[this->WorkSize++] = e.Id;
    }
    else
    {
      this->Doze(e, sleep);
    }
  }
  while (this->WorkSize > 0)
  {
    const uint32_t c = this->Work[--this->WorkSize];
    if (!this->Active[c])
    {
      this->ForceSplit(c);
    }
  }
  this->Mode = UpdateMode::None;
  this->MergeUnwanted();
  this->Statistics.DisplayVertices = this->ActiveVertexCount;
  this->Statistics.DisplayTriangles = this->DisplayCount;
  this->Statistics.Seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return this->Statistics;
}

//------------------------------------------------------------------------------
namespace
{
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

void ViewDependentRefinement::OfferSplit(uint32_t w)
{
  // w's (new) candidate, keyed from its list entry (its node is there; the
  // key is not cached: the heap entry carries it). Sub-threshold detail is
  // never bought, even when the budget allows it.
  const uint32_t p = this->Link[w].SplitPos;
  if (p == None || this->SplitSize == this->SplitHeap.size())
  {
    return;
  }
  Candidate& e = this->SplitList[p];
  if (this->Touched[e.Id] == this->TouchFrame || this->SurelyUnwanted(e.Data))
  {
    return;
  }
  Sleep sleep;
  const float key = static_cast<float>(this->Evaluate(e.Data, &sleep));
  this->Doze(e, sleep); // for the next updates
  if (this->IsWanted(key))
  {
    this->SplitHeap[this->SplitSize++] = HeapEntry{ key, (e.Id << 1) | 1 };
    std::push_heap(this->SplitHeap.data(), this->SplitHeap.data() + this->SplitSize, SplitOrder());
  }
}

void ViewDependentRefinement::SortPending(uint32_t size)
{
  // Counting sort by bucket into Sorted; afterwards BucketStart[b] is where
  // bucket b ends (and b + 1 starts).
  uint32_t* start = this->BucketStart.data();
  std::fill(start, start + Buckets + 1, 0u);
  for (uint32_t i = 0; i < size; ++i)
  {
    ++start[BucketOf(this->Pending[i].Key) + 1];
  }
  for (uint32_t b = 0; b < Buckets; ++b)
  {
    start[b + 1] += start[b];
  }
  for (uint32_t i = 0; i < size; ++i)
  {
    this->Sorted[start[BucketOf(this->Pending[i].Key)]++] = this->Pending[i];
  }
  this->PendingEnd = size;
  this->SplitFloor = std::numeric_limits<float>::infinity();
}

void ViewDependentRefinement::ReachSplitTop()
{
  // What is not taken yet, Sorted[0, PendingEnd), lies in lower buckets, so
  // below SplitFloor: the top may be popped when it is not below it.
  HeapEntry* split = this->SplitHeap.data();
  while (this->PendingEnd > 0 && (this->SplitSize == 0 || split[0].Key < this->SplitFloor))
  {
    const uint32_t bucket = BucketOf(this->Sorted[this->PendingEnd - 1].Key);
    const uint32_t first = bucket > 0 ? this->BucketStart[bucket - 1] : 0;
    const uint32_t count = this->PendingEnd - first;
    const uint32_t bits = bucket << BucketShift;
    std::memcpy(&this->SplitFloor, &bits, sizeof(bits));
    this->PendingEnd = first;
    std::memcpy(split + this->SplitSize, this->Sorted.data() + first, count * sizeof(HeapEntry));
    if (count > this->SplitSize)
    {
      this->SplitSize += count;
      std::make_heap(split, split + this->SplitSize, SplitOrder());
    }
    else
    {
      for (uint32_t i = 0; i < count; ++i)
      {
        ++this->SplitSize;
        std::push_heap(split, split + this->SplitSize, SplitOrder());
      }
    }
  }
}

void ViewDependentRefinement::OfferMerge(uint32_t v)
{
  if (v == None || this->Touched[v] == this->TouchFrame || this->MergeSize == this->MergeHeap.size() ||
    !this->CanMerge(v))
  {
    return;
  }
  this->MergeHeap[this->MergeSize++] = HeapEntry{ this->Key(v), v };
  std::push_heap(this->MergeHeap.data(), this->MergeHeap.data() + this->MergeSize, MergeOrder());
}

/*
 * Budget update: first the fixed-accuracy merges (tau is a floor: nothing
 * below it stays or is split), then dual heaps of candidate events only,
 * built by heapify: split the largest projected error while it fits, merge
 * the smallest while over the budget, and trade a smaller merge for a larger
 * split when full. Every vertex is split or merged at most once per update
 * (Touched), so the work is bounded by the candidates and the changes.
 */
const RefinementStatistics& ViewDependentRefinement::UpdateBudget(
  uint32_t triangleBudget, double timeLimitSeconds)
{
  const auto start = std::chrono::steady_clock::now();
  this->Statistics = RefinementStatistics{};
  this->UndoneOperations = 0;
  this->Checks = 0;
  this->Deadline = timeLimitSeconds > 0.0
    ? std::chrono::duration<double>(start.time_since_epoch()).count() + timeLimitSeconds
    : 0.0;
  this->Bounded = this->Deadline > 0.0 || this->OperationLimit > 0;
  this->PrepareView();
  this->NextFrame();
  // After an interrupted update the next one continues it: what that one split,
  // merged or left out stays so (otherwise calls whose bound is spent on the
  // same failed candidates would never progress).
  if (!this->ContinueUpdate || this->TouchFrame == 0)
  {
    this->TouchFrame = this->Frame;
  }
  this->Mode = UpdateMode::None;
  this->MergeUnwanted();
  auto finish = [&]() -> const RefinementStatistics& {
    this->Mode = UpdateMode::None;
    this->Bounded = false;
    this->ContinueUpdate = this->Statistics.Interrupted;
    this->Statistics.DisplayVertices = this->ActiveVertexCount;
    this->Statistics.DisplayTriangles = this->DisplayCount;
    this->Statistics.Seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return this->Statistics;
  };
  if (this->Statistics.Interrupted)
  {
    return finish();
  }

  HeapEntry* split = this->SplitHeap.data();
  HeapEntry* merge = this->MergeHeap.data();
  // The candidates' keys (or bounds) go to Pending, sorted into key buckets
  // (float bits: 8 per octave); the split heap takes a bucket only when its
  // top could be below the bucket's keys (ReachSplitTop()), so most of them
  // are never heapified.
  HeapEntry* pending = this->Pending.data();
  uint32_t pendingSize = 0;
  this->SplitSize = 0;
  for (uint32_t i = 0; i < this->SplitListSize; ++i)
  {
    Candidate& e = this->SplitList[i];
    if (e.WakeAt > this->Odometer || this->SurelyUnwanted(e.Data))
    {
      continue;
    }
    if (e.FactorUntil > this->Odometer)
    {
      // Lazy: a bound now, the key when it reaches the top (most never do).
      const double bound = this->KeyBound(e.Data, e.Factor);
      if (!(this->PixelThreshold > 0.0 && bound <= this->PixelThreshold))
      {
        pending[pendingSize++] = HeapEntry{ static_cast<float>(bound), e.Id << 1 };
      }
      continue;
    }
    Sleep sleep;
    const float key = static_cast<float>(this->Evaluate(e.Data, &sleep));
    this->Doze(e, sleep);
    if (this->IsWanted(key))
    {
      pending[pendingSize++] = HeapEntry{ key, (e.Id << 1) | 1 };
    }
  }
  this->SortPending(pendingSize);
  this->MergeSize = 0;
  for (uint32_t i = 0; i < this->MergeListSize; ++i)
  {
    const uint32_t x = this->MergeList[i]; // CanMerge(x)
    merge[this->MergeSize++] = HeapEntry{ this->Key(x), x };
  }
  std::make_heap(merge, merge + this->MergeSize, MergeOrder());

  this->Mode = UpdateMode::Budget;
  // Pops the smallest mergeable entry; None when there is none.
  auto popMerge = [&]() -> uint32_t {
    while (this->MergeSize > 0)
    {
      std::pop_heap(merge, merge + this->MergeSize, MergeOrder());
      const uint32_t m = merge[--this->MergeSize].Id;
      if (this->Touched[m] != this->TouchFrame && this->CanMerge(m))
      {
        return m;
      }
    }
    return None;
  };
  auto topMerge = [&]() -> const HeapEntry* {
    while (this->MergeSize > 0)
    {
      const uint32_t m = merge[0].Id;
      if (this->Touched[m] != this->TouchFrame && this->CanMerge(m))
      {
        return merge;
      }
      std::pop_heap(merge, merge + this->MergeSize, MergeOrder());
      --this->MergeSize;
    }
    return nullptr;
  };
  // Full and nothing worth a trade: only splits within the slack may still
  // be made; give up after this many candidates in a row that do not fit
  // (otherwise the whole split heap is popped every frame).
  constexpr uint32_t MisfitLimit = 32;
  uint32_t misfits = 0;
  // Replays the merges of a failed trade made since TradeLog[from] backwards
  // (legal: it restores the front before them) and offers them as merge
  // candidates again.
  auto undoMerges = [&](uint32_t from) {
    const uint32_t count = this->TradeLogSize - from;
    this->Mode = UpdateMode::None;
    while (this->TradeLogSize > from)
    {
      const uint32_t x = this->TradeLog[--this->TradeLogSize];
      this->Split(x);
      this->Touched[x] = 0;
    }
    this->Mode = UpdateMode::Budget;
    for (uint32_t i = from; i < from + count; ++i)
    {
      this->OfferMerge(this->TradeLog[i]);
    }
    this->Statistics.Splits -= count;
    this->Statistics.Merges -= count;
    this->UndoneOperations += 2 * count;
  };
  auto undoTrade = [&]() { undoMerges(0); };
  this->TradeLogSize = 0;
  for (;;)
  {
    if (this->Bounded && this->TradeLogSize == 0 && this->OutOfTime())
    {
      break; // every split, forced chain and merge is complete: the front is valid
    }
    if (this->DisplayCount > triangleBudget)
    {
      const uint32_t m = popMerge();
      if (m == None)
      {
        break;
      }
      this->Merge(m);
      continue;
    }
    this->ReachSplitTop();
    if (this->SplitSize == 0)
    {
      break;
    }
    const HeapEntry top = split[0];
    const uint32_t s = top.Id >> 1;
    if (this->Active[s] || this->Touched[s] == this->TouchFrame ||
      !this->Active[this->Link[s].Parent] || this->NextChild(this->Link[s].Parent) != s)
    {
      std::pop_heap(split, split + this->SplitSize, SplitOrder());
      --this->SplitSize;
      continue;
    }
    if ((top.Id & 1) == 0)
    {
      // A bound on top: its key now (no larger), back in its place if wanted.
      std::pop_heap(split, split + this->SplitSize, SplitOrder());
      --this->SplitSize;
      if (this->Wanted(s))
      {
        split[this->SplitSize++] = HeapEntry{ this->Key(s), (s << 1) | 1 };
        std::push_heap(split, split + this->SplitSize, SplitOrder());
      }
      continue;
    }
    const uint32_t cost = this->Link[s].BlockEnd - this->Link[s].BlockBegin;
    if (this->DisplayCount + cost <= triangleBudget)
    {
      std::pop_heap(split, split + this->SplitSize, SplitOrder());
      --this->SplitSize;
      this->SplitLogSize = 0;
      const uint32_t paid = this->TradeLogSize; // merges made for s before its splits
      this->ForceSplit(s);
      // The forced splits may overshoot: they are part of the price of s,
      // paid like its own triangles with merges less useful than s.
      while (this->DisplayCount > triangleBudget)
      {
        const HeapEntry* m = topMerge();
        if (m == nullptr || !(m->Key < top.Key))
        {
          break;
        }
        const uint32_t merged = popMerge();
        this->Merge(merged);
        this->TradeLog[this->TradeLogSize++] = merged;
      }
      if (this->DisplayCount <= triangleBudget)
      {
        this->TradeLogSize = 0; // the trade is made
      }
      else
      {
        // Too dear: replay everything backwards (always legal, it restores
        // the previous front; newest first) and leave s out for this update.
        undoMerges(paid);
        this->Mode = UpdateMode::None;
        const uint32_t forced = this->SplitLogSize;
        while (this->SplitLogSize > 0)
        {
          const uint32_t x = this->SplitLog[--this->SplitLogSize];
          this->Merge(x);
          this->Touched[x] = 0; // may still be split for another candidate
        }
        this->Mode = UpdateMode::Budget;
        this->Touched[s] = this->TouchFrame;
        this->Statistics.Splits -= forced;
        this->Statistics.Merges -= forced;
        this->Statistics.ForcedSplits -= forced > 0 ? forced - 1 : 0;
        this->UndoneOperations += 2 * forced;
        undoTrade();
      }
      continue;
    }
    // Full: trade the least useful merge for the most useful split.
    if (this->TradeLogSize > 0 && this->TradeFor != s)
    {
      this->TradeLogSize = 0; // cannot happen (s stays on top); keep the merges
    }
    const HeapEntry* m = topMerge();
    if (m == nullptr || !(m->Key < top.Key))
    {
      // Not worth a trade: leave s out and fill what is left with smaller
      // splits (none when nothing is left).
      if (this->TradeLogSize > 0)
      {
        undoTrade(); // s cannot be paid for with less useful merges
      }
      else if (this->DisplayCount == triangleBudget || ++misfits > MisfitLimit)
      {
        break;
      }
      std::pop_heap(split, split + this->SplitSize, SplitOrder());
      --this->SplitSize;
      this->Touched[s] = this->TouchFrame;
      continue;
    }
    // A trade is atomic: its merges are logged and undone when s is not
    // made after all, so that a failed trade does not lose detail (and
    // repeated updates settle instead of cycling).
    const uint32_t merged = popMerge();
    this->Merge(merged);
    this->TradeFor = s;
    this->TradeLog[this->TradeLogSize++] = merged;
  }
  this->TradeLogSize = 0;
  return finish();
}

//------------------------------------------------------------------------------
uint32_t ViewDependentRefinement::CopyTriangles(uint32_t* out, uint32_t capacity, uint32_t offset) const
{
  const uint32_t count = std::min(capacity, this->DisplayCount);
  const size_t ids = 3 * size_t(count);
  if (offset == 0)
  {
    std::memcpy(out, this->Display.data(), ids * sizeof(uint32_t));
  }
  else
  {
    for (size_t i = 0; i < ids; ++i)
    {
      out[i] = this->Display[i] + offset;
    }
  }
  return this->DisplayCount;
}
}
