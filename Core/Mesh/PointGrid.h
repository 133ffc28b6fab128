// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_PointGrid_h
#define timecritical_PointGrid_h

/*
 * Internal to TimeCritical::MeshCore: a uniform grid of points for
 * fixed-radius neighbour queries, used by the collapse engine's pair
 * contraction (CollapseEngine::JoinParts) to find close vertices without
 * comparing every pair.
 */

#include "CollapseGeometry.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace timecritical
{
namespace collapse
{
/**
 * Points sorted by the cell of a uniform grid (cells of the query radius,
 * only the occupied ones stored, as 64-bit keys), so that the points within
 * the radius of a position are found among the 27 cells around it: O(n log n)
 * to build, and a query visits only the points of those cells. Cell
 * coordinates are clamped to 2^20 per axis; clamping only merges far cells,
 * which keeps every query exact (distances are checked), only slower on
 * extreme inputs.
 */
class PointGrid
{
public:
  /// An empty grid whose queries find points within `cellSize` (> 0) of a position.
  explicit PointGrid(double cellSize = 1.0)
    : CellSize(cellSize > 0.0 ? cellSize : 1.0)
  {
  }

  /// Adds point `id` at `p` (call Build once all are added).
  void Add(uint32_t id, const Vec3& p) { this->Entries.push_back({ this->KeyOf(p, 0, 0, 0), p, id }); }

  /// Sorts the points by cell (ties: in the order added).
  void Build()
  {
    std::stable_sort(this->Entries.begin(), this->Entries.end(),
      [](const Entry& a, const Entry& b) { return a.Key < b.Key; });
  }

  size_t Size() const { return this->Entries.size(); }

  /**
   * Calls f(id, squared distance) for every point within `radius` (at most
   * the cell size) of p, cell by cell; f returns false to stop the query.
   * Returns the number of points looked at (the work of the query).
   */
  template <typename F>
  size_t ForEachWithin(const Vec3& p, double radius, F&& f) const
  {
    const double r2 = radius * radius;
    size_t visited = 0;
    for (int dx = -1; dx <= 1; ++dx)
    {
      for (int dy = -1; dy <= 1; ++dy)
      {
        for (int dz = -1; dz <= 1; ++dz)
        {
          const uint64_t key = this->KeyOf(p, dx, dy, dz);
          auto it = std::lower_bound(this->Entries.begin(), this->Entries.end(), key,
            [](const Entry& e, uint64_t k) { return e.Key < k; });
          for (; it != this->Entries.end() && it->Key == key; ++it)
          {
            ++visited;
            const Vec3 d = Sub(it->P, p);
            const double d2 = Dot(d, d);
            if (d2 < r2 && !f(it->Id, d2))
            {
              return visited;
            }
          }
        }
      }
    }
    return visited;
  }

private:
  struct Entry
  {
    uint64_t Key;
    Vec3 P;
    uint32_t Id;
  };

  static constexpr int64_t Half = int64_t(1) << 20;

  int64_t CellOf(double x, int offset) const
  {
    const double c = std::floor(x / this->CellSize);
    // Clamped before the conversion (NaN goes to the lowest cell).
    const int64_t i = c >= double(Half - 2) ? Half - 2 : (c >= double(-Half + 1) ? int64_t(c) : -Half + 1);
    return i + offset + Half; // in [0, 2^21)
  }

  uint64_t KeyOf(const Vec3& p, int dx, int dy, int dz) const
  {
    return uint64_t(this->CellOf(p.X, dx)) << 42 | uint64_t(this->CellOf(p.Y, dy)) << 21 |
      uint64_t(this->CellOf(p.Z, dz));
  }

  double CellSize;
  std::vector<Entry> Entries;
};
}
}

#endif
