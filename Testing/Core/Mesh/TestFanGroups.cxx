// SPDX-License-Identifier: BSD-3-Clause
// FanGroups: the fan of a vertex grouped by neighbour, against hand-built
// fans: closed, with a boundary, with a non-manifold edge, with a repeated
// triangle, and pinched (two fans through one vertex); small fans (linear
// search) and large ones (sorting) alike.

#include "FanGroups.h"

#include <gtest/gtest.h>

#include <map>
#include <vector>

namespace
{
using namespace timecritical::collapse;

constexpr uint32_t V = 0; // the vertex whose fan is grouped

/// The triangles and the adjacency entries (triangle << 2 | corner of V) of a fan.
struct Fan
{
  std::vector<Tri> Tris;
  std::vector<uint32_t> Entries;

  void Add(uint32_t a, uint32_t b, uint32_t c)
  {
    const uint32_t t = static_cast<uint32_t>(this->Tris.size());
    this->Tris.push_back({ { a, b, c }, 0 });
    this->Entries.push_back(t << 2 | this->Tris.back().CornerOf(V));
  }
  void Group(FanGroups& groups) const
  {
    groups.Build(this->Entries.data(), static_cast<uint32_t>(this->Entries.size()), this->Tris.data());
  }
};

/// A closed fan around V over the neighbours first .. first + n - 1.
void AddClosedFan(Fan& fan, uint32_t first, uint32_t n)
{
  for (uint32_t i = 0; i < n; ++i)
  {
    fan.Add(V, first + i, first + (i + 1) % n);
  }
}

/// (Next, Prev) counts of each neighbour's group.
std::map<uint32_t, std::pair<uint32_t, uint32_t>> CountsByNeighbour(const FanGroups& groups)
{
  std::map<uint32_t, std::pair<uint32_t, uint32_t>> counts;
  for (const FanGroups::Group& group : groups.GetGroups())
  {
    EXPECT_EQ(counts.count(group.X), 0u) << "one group per neighbour";
    counts[group.X] = { group.Next, group.Prev };
  }
  return counts;
}

TEST(FanGroups, ClosedFanHasTwoSpokesPerNeighbour)
{
  Fan fan;
  AddClosedFan(fan, 1, 5);
  FanGroups groups;
  fan.Group(groups);
  const auto counts = CountsByNeighbour(groups);
  ASSERT_EQ(counts.size(), 5u);
  for (uint32_t x = 1; x <= 5; ++x)
  {
    EXPECT_EQ(counts.at(x), std::make_pair(1u, 1u)) << x;
  }
  EXPECT_FALSE(groups.HasDuplicateTriangle());
  EXPECT_EQ(groups.CountPieces(), 1u);
}

TEST(FanGroups, SpokesKnowTheirTriangleAndEdge)
{
  Fan fan;
  fan.Add(3, V, 4); // V at corner 1: 4 follows V (edge 1), 3 precedes it (edge 0)
  FanGroups groups;
  fan.Group(groups);
  ASSERT_EQ(groups.GetGroups().size(), 2u);
  for (const FanGroups::Group& group : groups.GetGroups())
  {
    const FanGroups::Spoke& spoke = groups.FirstSpoke(group);
    EXPECT_EQ(spoke.X, group.X);
    EXPECT_EQ(spoke.Tri, 0u);
    if (group.X == 4)
    {
      EXPECT_EQ(spoke.Prev, 0u);
      EXPECT_EQ(spoke.Edge, 1u);
      EXPECT_EQ(group.Next, 1u);
      EXPECT_EQ(group.Prev, 0u);
    }
    else
    {
      EXPECT_EQ(group.X, 3u);
      EXPECT_EQ(spoke.Prev, 1u);
      EXPECT_EQ(spoke.Edge, 0u);
      EXPECT_EQ(group.Next, 0u);
      EXPECT_EQ(group.Prev, 1u);
    }
  }
}

TEST(FanGroups, OpenFanHasTwoBoundaryNeighbours)
{
  Fan fan;
  fan.Add(V, 1, 2);
  fan.Add(V, 2, 3);
  fan.Add(V, 3, 4);
  FanGroups groups;
  fan.Group(groups);
  const auto counts = CountsByNeighbour(groups);
  ASSERT_EQ(counts.size(), 4u);
  EXPECT_EQ(counts.at(1), std::make_pair(1u, 0u)); // boundary edge (V, 1)
  EXPECT_EQ(counts.at(2), std::make_pair(1u, 1u));
  EXPECT_EQ(counts.at(3), std::make_pair(1u, 1u));
  EXPECT_EQ(counts.at(4), std::make_pair(0u, 1u)); // boundary edge (4, V)
  EXPECT_FALSE(groups.HasDuplicateTriangle());
  EXPECT_EQ(groups.CountPieces(), 1u);
}

TEST(FanGroups, NonManifoldEdgeGroupsItsThreeTriangles)
{
  Fan fan;
  AddClosedFan(fan, 1, 4);
  fan.Add(V, 1, 9); // a fin on the edge (V, 1)
  FanGroups groups;
  fan.Group(groups);
  const auto counts = CountsByNeighbour(groups);
  EXPECT_EQ(counts.at(1), std::make_pair(2u, 1u));
  EXPECT_EQ(counts.at(9), std::make_pair(0u, 1u));
  std::vector<uint32_t> triangles;
  for (const FanGroups::Group& group : groups.GetGroups())
  {
    if (group.X == 1)
    {
      groups.ForEachSpoke(group, [&triangles](const FanGroups::Spoke& spoke) { triangles.push_back(spoke.Tri); });
    }
  }
  EXPECT_EQ(triangles, (std::vector<uint32_t>{ 0, 3, 4 }));
  EXPECT_FALSE(groups.HasDuplicateTriangle());
  EXPECT_EQ(groups.CountPieces(), 1u);
}

TEST(FanGroups, RepeatedTriangleIsFound)
{
  Fan fan;
  AddClosedFan(fan, 1, 4);
  fan.Add(V, 2, 1); // the points of triangle (V, 1, 2) again, the other way round
  FanGroups groups;
  fan.Group(groups);
  EXPECT_TRUE(groups.HasDuplicateTriangle());
}

TEST(FanGroups, PinchedVertexHasTwoPieces)
{
  Fan fan;
  AddClosedFan(fan, 1, 3);
  AddClosedFan(fan, 10, 4);
  FanGroups groups;
  fan.Group(groups);
  EXPECT_EQ(groups.GetGroups().size(), 7u);
  EXPECT_EQ(groups.CountPieces(), 2u);
}

TEST(FanGroups, LargeFansAreGroupedTheSameWay)
{
  Fan fan;
  AddClosedFan(fan, 1, 40);
  AddClosedFan(fan, 100, 30); // 70 triangles: above the linear-search limit
  FanGroups groups;
  fan.Group(groups);
  const auto counts = CountsByNeighbour(groups);
  ASSERT_EQ(counts.size(), 70u);
  for (const auto& entry : counts)
  {
    EXPECT_EQ(entry.second, std::make_pair(1u, 1u)) << entry.first;
  }
  EXPECT_FALSE(groups.HasDuplicateTriangle());
  EXPECT_EQ(groups.CountPieces(), 2u);

  Fan repeated = fan;
  for (uint32_t i = 0; i < 60; ++i)
  {
    repeated.Add(V, 1, 200 + i); // 61 triangles on the edge (V, 1): sorted duplicate search
  }
  repeated.Add(V, 1, 230);
  repeated.Group(groups); // the arrays are reused from one fan to the next
  EXPECT_TRUE(groups.HasDuplicateTriangle());
}

TEST(FanGroups, ReusedForASmallerFan)
{
  Fan large;
  AddClosedFan(large, 1, 60);
  FanGroups groups;
  large.Group(groups);
  Fan small;
  small.Add(V, 1, 2);
  small.Group(groups);
  const auto counts = CountsByNeighbour(groups);
  ASSERT_EQ(counts.size(), 2u);
  EXPECT_EQ(groups.CountPieces(), 1u);
}
}
