// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_FanGroups_h
#define timecritical_FanGroups_h

/*
 * Internal to TimeCritical::MeshCore: the fan of one vertex grouped by
 * neighbour, for the classification of the collapse engine's vertices where
 * the fan is not a small closed one (CollapseEngine::ClassifyVertices).
 */

#include "CollapseRecords.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace timecritical
{
namespace collapse
{
/**
 * Around a vertex v: one "spoke" per (triangle, neighbour), grouped by
 * neighbour so that each edge (v, x) sees all its triangles. Small fans are
 * grouped by linear search, large ones by sorting; either way the work stays
 * local to the fan. The arrays are kept from one fan to the next.
 */
class FanGroups
{
public:
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
    uint32_t First;      // first spoke of the group (in the bucketed order)
    uint32_t Parent;     // union-find over the groups: pieces of the fan
  };

  /// Groups the fan of count triangles, given as adjacency entries (triangle << 2 | corner of v).
  void Build(const uint32_t* list, uint32_t count, const Tri* tris)
  {
    this->Count = count;
    this->Spokes.resize(2 * static_cast<size_t>(count));
    this->GroupOf.resize(this->Spokes.size());
    this->Groups.clear();
    for (uint32_t i = 0; i < count; ++i)
    {
      const uint32_t t = list[i] >> 2;
      const uint32_t j = list[i] & 3u;
      const Tri& tri = tris[t];
      this->Spokes[2 * i] = { tri.V[Next3(j)], t, j, 0 };
      this->Spokes[2 * i + 1] = { tri.V[Prev3(j)], t, Prev3(j), 1 };
    }
    if (count <= LinearSearchLimit)
    {
      this->GroupByLinearSearch();
    }
    else
    {
      this->GroupBySorting();
    }
    this->Bucket();
  }

  /// Whether two triangles of the fan have the same three points (then they
  /// share an edge and its third corner). Usually two triangles per edge: one compare.
  bool HasDuplicateTriangle()
  {
    for (const Group& group : this->Groups)
    {
      const uint32_t n = group.Next + group.Prev;
      const uint32_t* m = this->Members.data() + group.First;
      if (n > LinearSearchLimit)
      {
        this->Order.resize(n);
        for (uint32_t k = 0; k < n; ++k)
        {
          this->Order[k] = this->Spokes[m[k] ^ 1u].X; // the third corner (the sibling spoke's neighbour)
        }
        std::sort(this->Order.begin(), this->Order.end());
        if (std::adjacent_find(this->Order.begin(), this->Order.end()) != this->Order.end())
        {
          return true;
        }
        continue;
      }
      for (uint32_t a = 1; a < n; ++a)
      {
        for (uint32_t b = 0; b < a; ++b)
        {
          if (this->Spokes[m[a] ^ 1u].X == this->Spokes[m[b] ^ 1u].X)
          {
            return true;
          }
        }
      }
    }
    return false;
  }

  /// Pieces of the fan (1: one fan; more: a pinch vertex). The link graph
  /// has an edge per triangle, between the groups of its two spokes. Once per Build.
  uint32_t CountPieces()
  {
    uint32_t pieces = static_cast<uint32_t>(this->Groups.size());
    for (uint32_t i = 0; i < this->Count; ++i)
    {
      const uint32_t ra = this->Find(this->GroupOf[2 * i]);
      const uint32_t rb = this->Find(this->GroupOf[2 * i + 1]);
      if (ra != rb)
      {
        this->Groups[ra].Parent = rb;
        --pieces;
      }
    }
    return pieces;
  }

  const std::vector<Group>& GetGroups() const { return this->Groups; }

  /// Calls f(spoke) for each spoke of the group (few: usually two).
  template <typename F>
  void ForEachSpoke(const Group& group, F&& f) const
  {
    const uint32_t n = group.Next + group.Prev;
    for (uint32_t k = group.First; k < group.First + n; ++k)
    {
      f(this->Spokes[this->Members[k]]);
    }
  }
  /// The first spoke of the group.
  const Spoke& FirstSpoke(const Group& group) const
  {
    return this->Spokes[this->Members[group.First]];
  }

private:
  static constexpr uint32_t LinearSearchLimit = 48;

  void AddToGroup(size_t k, uint32_t g)
  {
    this->GroupOf[k] = g;
    if (this->Spokes[k].Prev)
    {
      ++this->Groups[g].Prev;
    }
    else
    {
      ++this->Groups[g].Next;
    }
  }
  void GroupByLinearSearch()
  {
    for (size_t k = 0; k < this->Spokes.size(); ++k)
    {
      const uint32_t x = this->Spokes[k].X;
      uint32_t g = 0;
      const uint32_t numberOfGroups = static_cast<uint32_t>(this->Groups.size());
      while (g < numberOfGroups && this->Groups[g].X != x)
      {
        ++g;
      }
      if (g == numberOfGroups)
      {
        this->Groups.push_back({ x, 0, 0, static_cast<uint32_t>(k), g });
      }
      this->AddToGroup(k, g);
    }
  }
  void GroupBySorting()
  {
    std::vector<uint32_t>& order = this->Order;
    const std::vector<Spoke>& spokes = this->Spokes;
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
        const uint32_t g = static_cast<uint32_t>(this->Groups.size());
        this->Groups.push_back({ spokes[k].X, 0, 0, k, g });
      }
      this->AddToGroup(k, static_cast<uint32_t>(this->Groups.size() - 1));
    }
  }
  /// Buckets the spokes by group (counting sort), so each edge finds its triangles directly.
  void Bucket()
  {
    uint32_t offset = 0;
    for (Group& group : this->Groups)
    {
      group.First = offset;
      offset += group.Next + group.Prev;
    }
    this->Members.resize(this->Spokes.size());
    for (uint32_t k = 0; k < this->Spokes.size(); ++k)
    {
      this->Members[this->Groups[this->GroupOf[k]].First++] = k;
    }
    for (Group& group : this->Groups)
    {
      group.First -= group.Next + group.Prev;
    }
  }
  uint32_t Find(uint32_t g)
  {
    while (this->Groups[g].Parent != g)
    {
      this->Groups[g].Parent = this->Groups[this->Groups[g].Parent].Parent;
      g = this->Groups[g].Parent;
    }
    return g;
  }

  uint32_t Count = 0;              // triangles of the fan
  std::vector<Spoke> Spokes;       // two per triangle
  std::vector<uint32_t> GroupOf;   // spoke -> group
  std::vector<Group> Groups;
  std::vector<uint32_t> Order;     // scratch of the sorts
  std::vector<uint32_t> Members;   // spokes bucketed by group
};
}
}

#endif
