// SPDX-License-Identifier: BSD-3-Clause
#include "ViewDependentRefinementInternals.h"

#include "MergeTree.h"
#include "TOMMesh.h"
#include "TOMTraversal.h"
#include "TOMValidator.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace timecritical
{
using vdr::None;
using vdr::Pi;

namespace
{
/// Throws std::invalid_argument when the TOM, its merge tree and the points do not fit together.
void CheckInputs(const TOMMesh& tom, const MergeTree& tree, bool hasPoints)
{
  const std::string problem = TOMValidator::Check(tom);
  if (!problem.empty())
  {
    throw std::invalid_argument("ViewDependentRefinement: invalid TOM: " + problem);
  }
  const uint32_t n = tom.GetNumberOfVertices();
  const uint32_t b = tom.BaseVertexCount;
  if (tree.GetNumberOfVertices() != n || tree.Radius.size() != n || tree.ConeCosine.size() != n ||
    tree.ConeAxis.size() != 3 * size_t(n) || tree.DependencyOffsets.size() != size_t(n) + 1 ||
    tree.DependencyOffsets[0] != 0 || tree.DependencyOffsets[n] != tree.Dependencies.size())
  {
    throw std::invalid_argument("ViewDependentRefinement: merge tree does not fit the TOM");
  }
  if (n > 0 && !hasPoints)
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
}
}

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
  CheckInputs(tom, tree, points != nullptr);
  this->N = tom.GetNumberOfVertices();
  this->B = tom.BaseVertexCount;
  this->T = tom.GetNumberOfTriangles();
  this->Parent = tom.Substitution;
  // Requirement rows: the merge tree's dependency rows (the vertices around
  // u and v just before e_v), and their transpose for the merge queue.
  this->ReqOffsets = tree.DependencyOffsets;
  this->Req = tree.Dependencies;
  this->TransposeRequirements();
  std::vector<uint32_t> childOffsets, previousSibling;
  this->BuildChildren(childOffsets, previousSibling);
  const std::vector<uint32_t> event = this->BuildBlocks(tom);
  this->BuildStars(tom, event);
  if (this->WingDependencies)
  {
    this->UseWingRequirements();
  }
  this->Nodes.assign(this->N - this->B, Node{});
  for (uint32_t slot = 0; slot < this->N - this->B; ++slot)
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
  this->BuildLinks(childOffsets);
  this->MakePrioritiesMonotone();
  this->BuildNeeds(previousSibling);
  this->AllocateUpdateState();
  this->Reset();
}

void ViewDependentRefinement::TransposeRequirements()
{
  const uint32_t n = this->N;
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
  for (uint32_t v = this->B; v < n; ++v) // ascending rows of each vertex
  {
    for (uint32_t i = this->ReqOffsets[v]; i < this->ReqOffsets[size_t(v) + 1]; ++i)
    {
      this->Rev[fill[this->Req[i]]++] = v;
    }
  }
}

void ViewDependentRefinement::BuildChildren(
  std::vector<uint32_t>& childOffsets, std::vector<uint32_t>& previousSibling)
{
  // Children of each vertex, sorted by id, and each child's previous sibling (0: none).
  const uint32_t n = this->N, b = this->B;
  childOffsets.assign(size_t(n) + 1, 0);
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
  previousSibling.assign(n, 0);
  for (uint32_t w = 0; w < n; ++w)
  {
    for (uint32_t i = childOffsets[w] + 1; i < childOffsets[size_t(w) + 1]; ++i)
    {
      previousSibling[this->Children[i]] = this->Children[i - 1];
    }
  }
}

std::vector<uint32_t> ViewDependentRefinement::BuildBlocks(const TOMMesh& tom)
{
  // Blocks: triangles appearing with each split (contiguous in a TOM).
  // Returns the event of each triangle (None: a base triangle).
  const uint32_t n = this->N, b = this->B, nt = this->T;
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
  return event;
}

void ViewDependentRefinement::BuildStars(const TOMMesh& tom, const std::vector<uint32_t>& event)
{
  // Birth corners (corners when the triangle appears, i.e. at its block's
  // split) and star slots: slot 3t+k turns from u to v at the split of v
  // exactly when v lies on the corner's substitution chain above the birth.
  const uint32_t n = this->N, b = this->B, nt = this->T;
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
}

void ViewDependentRefinement::UseWingRequirements()
{
  // Wing rows: only the third corners of e_v's own triangles (Hoppe's
  // neighbourhood of a vertex split), same closure rule as the full rows.
  const uint32_t n = this->N, b = this->B;
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
  this->TransposeRequirements();
}

void ViewDependentRefinement::BuildLinks(const std::vector<uint32_t>& childOffsets)
{
  const uint32_t n = this->N, b = this->B;
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
}

void ViewDependentRefinement::BuildNeeds(const std::vector<uint32_t>& previousSibling)
{
  // Needs: per vertex, the events of Rev[parent] between its previous sibling
  // and it, then its row; the full rows and their transpose are dropped.
  const uint32_t n = this->N, b = this->B;
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
}

void ViewDependentRefinement::AllocateUpdateState()
{
  // Everything the updates use, sized once here so that they never allocate.
  const uint32_t n = this->N, nt = this->T;
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
  this->BucketStart.assign(vdr::Buckets + 1, 0);
  this->MergeHeap.assign(4 * size_t(n) + 64, HeapEntry{});
  this->SplitLog.assign(n, 0);
  this->TradeLog.assign(n, 0);
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
}
