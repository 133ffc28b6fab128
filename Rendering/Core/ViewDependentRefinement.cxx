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
namespace
{
constexpr uint32_t None = std::numeric_limits<uint32_t>::max();
constexpr double Pi = 3.14159265358979323846;
}

/// View attributes of event e_v (or of a root), packed for the per-frame sweep.
struct ViewDependentRefinement::Node
{
  float Center[3]; // parent's position
  float Radius;
  float Error;
  float Axis[3];
  float Cos; // cone half-angle cosine, -1: whole sphere
  float Sin;
  float Theta; // half-angle, radians
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
  this->N = n;
  this->B = b;
  this->T = nt;
  this->Parent = tom.Substitution;
  this->DependencyOffsets = tree.DependencyOffsets;
  this->Dependencies = tree.Dependencies;

  this->ChildOffsets.assign(size_t(n) + 1, 0);
  this->Children.assign(n - b, 0);
  for (uint32_t v = b; v < n; ++v)
  {
    ++this->ChildOffsets[size_t(this->Parent[v]) + 1];
  }
  for (uint32_t v = 0; v < n; ++v)
  {
    this->ChildOffsets[size_t(v) + 1] += this->ChildOffsets[v];
  }
  {
    std::vector<uint32_t> fill(this->ChildOffsets.begin(), this->ChildOffsets.end() - 1);
    for (uint32_t v = b; v < n; ++v)
    {
      this->Children[fill[this->Parent[v]]++] = v;
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

  this->Nodes.assign(n, Node{});
  for (uint32_t v = 0; v < n; ++v)
  {
    Node& node = this->Nodes[v];
    const uint32_t c = v < b ? v : this->Parent[v];
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
    node.Theta = static_cast<float>(std::acos(cosine));
  }

  this->Active.assign(n, 0);
  this->ActiveChildren.assign(n, 0);
  this->Display.assign(3 * size_t(nt), 0);
  this->DisplayId.assign(nt, 0);
  this->DisplayPos.assign(nt, None);
  this->Stack.assign(n, 0);
  this->Work.assign(3 * size_t(n) + 1, 0);
  this->SplitHeap.assign(n, 0);
  this->MergeHeap.assign(n, 0);
  this->SplitPos.assign(n, None);
  this->MergePos.assign(n, None);
  this->Key.assign(n, 0.0);
  this->SplitLog.assign(n, 0);
  this->Rejected.assign(n, 0u);
  this->Reset();
}

//------------------------------------------------------------------------------
void ViewDependentRefinement::Reset()
{
  std::fill(this->Active.begin(), this->Active.end(), 0);
  std::fill(this->ActiveChildren.begin(), this->ActiveChildren.end(), 0);
  std::fill(this->DisplayPos.begin(), this->DisplayPos.end(), None);
  std::fill(this->Active.begin(), this->Active.begin() + this->B, 1);
  this->ActiveVertexCount = this->B;
  this->DisplayCount = 0;
  const uint32_t base = this->N > 0 ? this->BlockOffsets[this->B] : 0;
  for (uint32_t t = 0; t < base; ++t)
  {
    this->AddDisplay(t);
  }
  this->Statistics = RefinementStatistics{};
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
}

//------------------------------------------------------------------------------
double ViewDependentRefinement::Priority(uint32_t v) const
{
  const Node& node = this->Nodes[v];
  const double cx = node.Center[0], cy = node.Center[1], cz = node.Center[2];
  const double r = node.Radius;
  for (int i = 0; i < this->View.NumberOfFrustumPlanes && i < 6; ++i)
  {
    const double* p = this->View.FrustumPlanes[i];
    if (p[0] * cx + p[1] * cy + p[2] * cz + p[3] < -r)
    {
      return -1.0; // wholly outside
    }
  }
  double dx, dy, dz, sinB = 0.0, cosB = 1.0, projected;
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
    const double dist = std::sqrt(dx * dx + dy * dy + dz * dz);
    if (dist <= r)
    {
      // Eye inside the bounding sphere: every direction, unbounded projection.
      return node.Error > 0.0f ? std::numeric_limits<double>::infinity() : 0.0;
    }
    dx /= dist;
    dy /= dist;
    dz /= dist;
    sinB = r / dist;
    cosB = std::sqrt(1.0 - sinB * sinB);
    projected = node.Error * this->PixelsPerUnit / (dist - r);
  }
  double factor = 1.0;
  // Angles to the view directions of the sphere: theta (cone) + beta (sphere).
  const double cosA = node.Axis[0] * dx + node.Axis[1] * dy + node.Axis[2] * dz;
  const double cosTB = node.Cos * cosB - node.Sin * sinB;
  const double sinTB = node.Sin * cosB + node.Cos * sinB;
  bool silhouette = true;
  if (cosTB > 0.0 && node.Cos > -1.0f) // theta + beta below 90 degrees
  {
    if (this->BackFaceSimplification && cosA > sinTB)
    {
      return -1.0; // every normal faces away from every view direction
    }
    silhouette = std::abs(cosA) <= sinTB;
  }
  if (this->SilhouetteRefinement && silhouette)
  {
    factor *= this->SilhouetteFactor;
  }
  if (this->HighlightRefinement)
  {
    // Reflection vectors of the light over the cone lie within 2 theta of the
    // axis's reflection; the highlight is seen when that cone holds the
    // direction to the eye (-d) widened by beta.
    const double angle = 2.0 * node.Theta + std::asin(std::min(1.0, sinB));
    bool highlight = angle >= Pi || node.Cos <= -1.0f;
    if (!highlight)
    {
      const double aL = node.Axis[0] * this->LightX + node.Axis[1] * this->LightY +
        node.Axis[2] * this->LightZ;
      const double rx = 2.0 * aL * node.Axis[0] - this->LightX;
      const double ry = 2.0 * aL * node.Axis[1] - this->LightY;
      const double rz = 2.0 * aL * node.Axis[2] - this->LightZ;
      highlight = -(rx * dx + ry * dy + rz * dz) >= std::cos(angle);
    }
    if (highlight)
    {
      factor *= this->HighlightFactor;
    }
  }
  return factor > 0.0 ? projected / factor : std::numeric_limits<double>::infinity();
}

bool ViewDependentRefinement::Wanted(uint32_t v) const
{
  const double p = this->Priority(v);
  return p >= 0.0 && (p > this->PixelThreshold || this->PixelThreshold <= 0.0);
}

//------------------------------------------------------------------------------
uint32_t ViewDependentRefinement::NextChild(uint32_t w) const
{
  const uint32_t i = this->ChildOffsets[w] + this->ActiveChildren[w];
  return i < this->ChildOffsets[size_t(w) + 1] ? this->Children[i] : None;
}

uint32_t ViewDependentRefinement::LastActiveChild(uint32_t w) const
{
  return this->ActiveChildren[w] > 0
    ? this->Children[this->ChildOffsets[w] + this->ActiveChildren[w] - 1]
    : None;
}

bool ViewDependentRefinement::AliveAt(uint32_t w, uint32_t v) const
{
  // w's active children must be exactly its children collapsed after e_v
  // (smaller ids): the state w had when e_v happened.
  const uint32_t next = this->NextChild(w);
  const uint32_t last = this->LastActiveChild(w);
  return (next == None || next > v) && (last == None || last < v);
}

uint32_t ViewDependentRefinement::FirstRequirement(uint32_t v) const
{
  const uint32_t u = this->Parent[v];
  if (!this->Active[u])
  {
    return u;
  }
  const uint32_t sibling = this->NextChild(u);
  if (sibling != v)
  {
    return sibling; // an earlier-split sibling (smaller id)
  }
  for (uint32_t i = this->DependencyOffsets[v]; i < this->DependencyOffsets[size_t(v) + 1]; ++i)
  {
    const uint32_t w = this->Dependencies[i];
    if (!this->Active[w])
    {
      return w;
    }
    const uint32_t next = this->NextChild(w);
    if (next != None && next < v)
    {
      return next; // w too coarse
    }
    const uint32_t last = this->LastActiveChild(w);
    if (last != None && last > v)
    {
      return None; // w too fine: only a merge elsewhere can unblock e_v
    }
  }
  return v;
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
  this->Stack[size++] = v;
  while (size > 0)
  {
    const uint32_t x = this->Stack[size - 1];
    if (this->Active[x])
    {
      --size;
      continue;
    }
    const uint32_t r = this->FirstRequirement(x);
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
      this->Stack[size++] = r;
    }
  }
  return true;
}

bool ViewDependentRefinement::CanMerge(uint32_t v) const
{
  if (v < this->B || !this->Active[v] || this->ActiveChildren[v] != 0 ||
    this->LastActiveChild(this->Parent[v]) != v)
  {
    return false;
  }
  for (uint32_t i = this->DependencyOffsets[v]; i < this->DependencyOffsets[size_t(v) + 1]; ++i)
  {
    const uint32_t w = this->Dependencies[i];
    if (!this->Active[w] || !this->AliveAt(w, v))
    {
      return false;
    }
  }
  return true;
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

void ViewDependentRefinement::Split(uint32_t v)
{
  const uint32_t u = this->Parent[v];
  this->Active[v] = 1;
  ++this->ActiveChildren[u];
  ++this->ActiveVertexCount;
  ++this->Statistics.Splits;
  for (uint32_t t = this->BlockOffsets[v]; t < this->BlockOffsets[size_t(v) + 1]; ++t)
  {
    this->AddDisplay(t);
  }
  for (uint32_t i = this->StarOffsets[v]; i < this->StarOffsets[size_t(v) + 1]; ++i)
  {
    const uint32_t s = this->StarSlots[i];
    const uint32_t p = this->DisplayPos[s / 3];
    if (p != None)
    {
      this->Display[3 * size_t(p) + s % 3] = v;
    }
  }
  if (this->Mode == UpdateMode::Fixed)
  {
    // New split candidates: v's next sibling and v's first child.
    this->Work[this->WorkSize++] = this->NextChild(u);
    this->Work[this->WorkSize++] = this->NextChild(v);
  }
  else if (this->Mode == UpdateMode::Budget)
  {
    this->SplitLog[this->SplitLogSize++] = v;
    this->OfferSplit(this->NextChild(u));
    this->OfferSplit(this->NextChild(v));
    this->OfferMerge(v);
  }
}

void ViewDependentRefinement::Merge(uint32_t v)
{
  const uint32_t u = this->Parent[v];
  this->Active[v] = 0;
  --this->ActiveChildren[u];
  --this->ActiveVertexCount;
  ++this->Statistics.Merges;
  for (uint32_t t = this->BlockOffsets[v]; t < this->BlockOffsets[size_t(v) + 1]; ++t)
  {
    this->RemoveDisplay(t);
  }
  for (uint32_t i = this->StarOffsets[v]; i < this->StarOffsets[size_t(v) + 1]; ++i)
  {
    const uint32_t s = this->StarSlots[i];
    const uint32_t p = this->DisplayPos[s / 3];
    if (p != None)
    {
      this->Display[3 * size_t(p) + s % 3] = u;
    }
  }
  if (this->Mode == UpdateMode::Budget)
  {
    this->OfferSplit(v);
    const uint32_t last = this->LastActiveChild(u);
    this->OfferMerge(last != None ? last : u);
    for (uint32_t i = this->DependencyOffsets[v]; i < this->DependencyOffsets[size_t(v) + 1]; ++i)
    {
      const uint32_t w = this->Dependencies[i];
      const uint32_t wl = this->LastActiveChild(w);
      this->OfferMerge(wl != None ? wl : w);
    }
  }
}

//------------------------------------------------------------------------------
const RefinementStatistics& ViewDependentRefinement::UpdateFixedAccuracy()
{
  const auto start = std::chrono::steady_clock::now();
  this->Statistics = RefinementStatistics{};
  this->PrepareView();
  this->Mode = UpdateMode::Fixed;
  // Splits: every wanted candidate (next child of a display vertex), with
  // the splits it needs; each split offers its new candidates.
  this->WorkSize = 0;
  for (uint32_t w = 0; w < this->N; ++w)
  {
    if (this->Active[w])
    {
      const uint32_t c = this->NextChild(w);
      if (c != None)
      {
        this->Work[this->WorkSize++] = c;
      }
    }
  }
  while (this->WorkSize > 0)
  {
    const uint32_t c = this->Work[--this->WorkSize];
    if (c == None || this->Active[c] || !this->Active[this->Parent[c]] ||
      this->NextChild(this->Parent[c]) != c || !this->Wanted(c))
    {
      continue;
    }
    this->ForceSplit(c);
  }
  this->Mode = UpdateMode::None;
  // Merges, finest first: the finest unwanted vertex that nothing displayed
  // needs is always mergeable, so one sweep reaches the fixed point; repeat
  // while a sweep merges anything, in case a merge unblocks a finer one.
  for (int sweep = 0; sweep < 64; ++sweep)
  {
    const uint32_t before = this->Statistics.Merges;
    for (uint32_t v = this->N; v-- > this->B;)
    {
      if (this->Active[v] && this->ActiveChildren[v] == 0 && this->CanMerge(v) && !this->Wanted(v))
      {
        this->Merge(v);
      }
    }
    if (this->Statistics.Merges == before)
    {
      break;
    }
  }
  this->Statistics.DisplayVertices = this->ActiveVertexCount;
  this->Statistics.DisplayTriangles = this->DisplayCount;
  this->Statistics.Seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return this->Statistics;
}

//------------------------------------------------------------------------------
// Indexed binary heaps over vertex ids: the split heap keeps the largest key
// on top, the merge heap the smallest.
namespace
{
template <typename Before>
void SiftUp(uint32_t* heap, uint32_t* pos, const double* key, uint32_t i, Before before)
{
  const uint32_t v = heap[i];
  while (i > 0)
  {
    const uint32_t parent = (i - 1) / 2;
    if (!before(key[v], key[heap[parent]]))
    {
      break;
    }
    heap[i] = heap[parent];
    pos[heap[i]] = i;
    i = parent;
  }
  heap[i] = v;
  pos[v] = i;
}

template <typename Before>
void SiftDown(uint32_t* heap, uint32_t* pos, const double* key, uint32_t size, uint32_t i, Before before)
{
  const uint32_t v = heap[i];
  for (;;)
  {
    uint32_t child = 2 * i + 1;
    if (child >= size)
    {
      break;
    }
    if (child + 1 < size && before(key[heap[child + 1]], key[heap[child]]))
    {
      ++child;
    }
    if (!before(key[heap[child]], key[v]))
    {
      break;
    }
    heap[i] = heap[child];
    pos[heap[i]] = i;
    i = child;
  }
  heap[i] = v;
  pos[v] = i;
}

template <typename Before>
uint32_t Pop(uint32_t* heap, uint32_t* pos, const double* key, uint32_t& size, Before before)
{
  const uint32_t top = heap[0];
  pos[top] = std::numeric_limits<uint32_t>::max();
  if (--size > 0)
  {
    heap[0] = heap[size];
    pos[heap[0]] = 0;
    SiftDown(heap, pos, key, size, 0, before);
  }
  return top;
}

inline bool Greater(double a, double b)
{
  return a > b;
}
inline bool Less(double a, double b)
{
  return a < b;
}
}

void ViewDependentRefinement::OfferSplit(uint32_t c)
{
  if (c == None || this->Active[c] || this->SplitPos[c] != None || this->Rejected[c] == this->Frame)
  {
    return;
  }
  this->Key[c] = this->Priority(c);
  this->SplitHeap[this->SplitSize] = c;
  SiftUp(this->SplitHeap.data(), this->SplitPos.data(), this->Key.data(), this->SplitSize++, Greater);
}

void ViewDependentRefinement::OfferMerge(uint32_t v)
{
  if (v == None || v < this->B || !this->Active[v] || this->MergePos[v] != None ||
    this->ActiveChildren[v] != 0 || this->LastActiveChild(this->Parent[v]) != v)
  {
    return;
  }
  this->Key[v] = this->Priority(v);
  this->MergeHeap[this->MergeSize] = v;
  SiftUp(this->MergeHeap.data(), this->MergePos.data(), this->Key.data(), this->MergeSize++, Less);
}

const RefinementStatistics& ViewDependentRefinement::UpdateBudget(uint32_t triangleBudget)
{
  const auto start = std::chrono::steady_clock::now();
  this->Statistics = RefinementStatistics{};
  this->PrepareView();
  // Fresh heaps: every key changes with the view.
  for (uint32_t i = 0; i < this->SplitSize; ++i)
  {
    this->SplitPos[this->SplitHeap[i]] = None;
  }
  for (uint32_t i = 0; i < this->MergeSize; ++i)
  {
    this->MergePos[this->MergeHeap[i]] = None;
  }
  this->SplitSize = 0;
  this->MergeSize = 0;
  if (++this->Frame == 0) // stamps wrapped: clear them once every 2^32 frames
  {
    std::fill(this->Rejected.begin(), this->Rejected.end(), 0u);
    this->Frame = 1;
  }
  this->Mode = UpdateMode::Budget;
  for (uint32_t w = 0; w < this->N; ++w)
  {
    if (this->Active[w])
    {
      this->OfferSplit(this->NextChild(w));
      this->OfferMerge(w);
    }
  }
  auto splitCandidate = [this](uint32_t c) {
    return !this->Active[c] && this->Active[this->Parent[c]] &&
      this->NextChild(this->Parent[c]) == c;
  };
  // Bounded: the trade loop below cannot cycle forever on ties.
  const uint64_t limit = 8 * uint64_t(this->N) + 1024;
  for (uint64_t iteration = 0; iteration < limit; ++iteration)
  {
    if (this->DisplayCount > triangleBudget)
    {
      if (this->MergeSize == 0)
      {
        break;
      }
      const uint32_t m = Pop(this->MergeHeap.data(), this->MergePos.data(), this->Key.data(),
        this->MergeSize, Less);
      if (this->CanMerge(m))
      {
        this->Merge(m);
      }
      continue;
    }
    if (this->SplitSize == 0)
    {
      break;
    }
    const uint32_t s = this->SplitHeap[0];
    if (!splitCandidate(s))
    {
      Pop(this->SplitHeap.data(), this->SplitPos.data(), this->Key.data(), this->SplitSize, Greater);
      continue;
    }
    const uint32_t cost = this->BlockOffsets[size_t(s) + 1] - this->BlockOffsets[s];
    if (this->DisplayCount + cost <= triangleBudget)
    {
      Pop(this->SplitHeap.data(), this->SplitPos.data(), this->Key.data(), this->SplitSize, Greater);
      this->SplitLogSize = 0;
      this->ForceSplit(s);
      if (this->DisplayCount > triangleBudget)
      {
        // The forced splits overshoot: replay them backwards (always legal,
        // it restores the previous front) and leave s out for this frame.
        this->Rejected[s] = this->Frame;
        const uint32_t forced = this->SplitLogSize;
        while (this->SplitLogSize > 0)
        {
          this->Merge(this->SplitLog[--this->SplitLogSize]);
        }
        this->Statistics.Splits -= forced;
        this->Statistics.Merges -= forced;
        this->Statistics.ForcedSplits -= forced > 0 ? forced - 1 : 0;
      }
      continue;
    }
    // Full: trade the least useful merge for the most useful split.
    if (this->MergeSize == 0)
    {
      break;
    }
    const uint32_t m = this->MergeHeap[0];
    if (!(this->Key[m] < this->Key[s]))
    {
      break;
    }
    Pop(this->MergeHeap.data(), this->MergePos.data(), this->Key.data(), this->MergeSize, Less);
    if (this->CanMerge(m))
    {
      this->Merge(m);
    }
  }
  this->Mode = UpdateMode::None;
  this->Statistics.DisplayVertices = this->ActiveVertexCount;
  this->Statistics.DisplayTriangles = this->DisplayCount;
  this->Statistics.Seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return this->Statistics;
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
