// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_PassSchedule_h
#define timecritical_PassSchedule_h

/*
 * Internal to TimeCritical::MeshCore: the pass schedule of TOMBuilder
 * (TOMBuildEngine::Passes) over the collapse engine (CollapseEngine.h),
 * which it drives without a heap. Not an API.
 */

#include <cstddef>
#include <cstdint>
#include <vector>

namespace timecritical
{
namespace collapse
{
class CollapseEngine;

/**
 * Collapses in passes. A pass sorts the cheapest collapse of every live
 * vertex once (a radix sort of float keys) and takes them cheapest first,
 * skipping a collapse whose region (the triangles around its two ends)
 * meets the region of one already taken in the pass: the collapses of a pass
 * are independent, like the levels of the merge tree. The engine keeps the
 * keys exact, and it only changes keys around a collapse, which are
 * "touched" and wait for the next pass; so the untouched rest of the sorted
 * list stays in exact least-cost order, with no heap to maintain. The next
 * pass's list is that rest merged with the touched vertices' new entries
 * (only those are sorted).
 *
 * A pass considers at most a share of its list (PassShare): the collapses
 * left out of one pass by independence come back in the next while still
 * cheap, which keeps the order close to the greedy one. When a vertex's
 * cheapest target is illegal its cheapest legal one is taken when it is
 * still the cheapest of the pass and its target is untouched; otherwise it
 * waits for the next pass (or is blocked when nothing is legal); a pass
 * after one that applied nothing considers its whole list and takes legal
 * alternatives at once. Once no vertex has a candidate the engine relaxes its
 * constraints; the run ends when none is left. Deterministic: one thread,
 * equal keys in vertex order in the first list, then in the order of the
 * touches.
 */
class PassSchedule
{
public:
  explicit PassSchedule(CollapseEngine& engine);

  /// Runs every pass; false when the progress callback aborted the build.
  bool Run();

  /// Passes run (after Run).
  uint32_t GetPassCount() const { return this->Passes; }

  /// Share of a pass's sorted list it considers before the next pass starts.
  static constexpr double PassShare = 0.25;

  /// A candidate collapse: the source's key as order-preserving bits.
  struct Entry
  {
    uint32_t Key;
    uint32_t Vertex;
  };

  /// A float key as unsigned bits of the same order.
  static uint32_t OrderedBits(float key);

private:
  void Collect();
  void CollectNext();
  void NextStamp();
  /// Collapses applied (NoKey when aborted).
  uint32_t RunPass();
  bool TryCollapse(uint32_t u, uint32_t nextKey);
  /// Marks a vertex whose key, target or region changed in this pass.
  void Touch(uint32_t v)
  {
    if (this->Touched[v] != this->Stamp)
    {
      this->Touched[v] = this->Stamp;
      this->TouchedList.push_back(v);
    }
  }
  bool IsTouched(uint32_t v) const { return this->Touched[v] == this->Stamp; }
  void PrefetchAhead(size_t position);
  bool Report();

  CollapseEngine& Engine;
  std::vector<uint32_t> Live;     // vertices not yet removed (compacted each pass)
  std::vector<uint8_t> Touched;     // == Stamp: touched in this pass
  std::vector<uint32_t> TouchedList; // the vertices touched in this pass
  std::vector<Entry> List;         // this pass's candidates, cheapest first
  std::vector<Entry> Fresh;        // the touched vertices' new entries
  std::vector<Entry> Buffer;       // radix sort and merge
  uint8_t Stamp = 0;
  bool Forced = false;             // the last pass applied nothing (see RunPass)
  uint32_t Passes = 0;            // passes started (0 = none)
  size_t ReportEvery = 1;
  size_t NextReport = 1;
};
}
}

#endif
