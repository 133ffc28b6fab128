// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_IndexSlotAllocator_h
#define timecritical_IndexSlotAllocator_h

#include "TimeCriticalMeshCoreExport.h"

#include <cstddef>
#include <vector>

namespace timecritical
{
/**
 * Lays out one slot per object in a buffer of primitives (an index buffer
 * that many objects share, each drawn at its own resolution) and keeps the
 * layout as the objects' sizes change.
 *
 * Slot i holds up to Full(i) primitives: [Start, Start + Used) are the
 * object's, [Start + Used, Start + Size) are padding, room to grow in place.
 * The capacity is the sum of the full sizes, so a layout of every slot at
 * its full size always fits. Freed ranges below the tail are holes, kept
 * sorted and merged; a hole that reaches the tail shortens it instead.
 *
 * The allocator only does the bookkeeping: the caller writes the primitives
 * (and makes vacated and padding ranges degenerate). Padding a slot needs
 * primitives that draw nothing; without them (CanPad false, as for points)
 * every slot fits its content exactly and any change of size fails, so that
 * the caller lays the buffer out again.
 *
 * After Configure() nothing allocates: holes, slot order and moves use
 * capacity reserved there (at most one hole more than there are slots).
 * Bad arguments (slot index out of range, a size above the slot's full size,
 * negative or NaN slack) throw std::invalid_argument or std::out_of_range.
 */
class TIMECRITICALMESHCORE_EXPORT IndexSlotAllocator
{
public:
  /// Primitives [Start, Start + Size).
  struct Range
  {
    std::size_t Start = 0;
    std::size_t Size = 0;
  };

  struct Slot
  {
    std::size_t Start = 0;
    std::size_t Size = 0; ///< 0: no slot
    std::size_t Used = 0; ///< primitives of the object; the rest of Size is padding
    std::size_t Full = 0; ///< the object's size at full resolution: no slot needs more
  };

  /// What Place() did with a slot.
  struct Placement
  {
    bool Placed = false; ///< false: no room (compact or lay out again)
    /// The primitives the slot held where it was before it moved: to be made degenerate.
    Range Vacated;
    /// How much of the slot may hold other than degenerate primitives (its
    /// old content, or primitives never written in this layout).
    std::size_t Extent = 0;
  };

  /// A slot moved down by Compact(): its first Size primitives (the content
  /// and the padding kept) go from From to To.
  struct Move
  {
    std::size_t SlotIndex = 0;
    std::size_t From = 0;
    std::size_t To = 0;
    std::size_t Size = 0;
    std::size_t Used = 0;
  };

  /// Padding every slot gets on top of the slack's share, so that small
  /// objects can change by a few primitives in place.
  static constexpr std::size_t MinimumSlack = 8;

  /**
   * One empty slot per entry of fullSizes, with that full size; capacity is
   * their sum. Reserves everything later calls need (the only call that allocates).
   */
  void Configure(const std::vector<std::size_t>& fullSizes, bool canPad);

  /// Slot size for `used` primitives: used plus slack * used + MinimumSlack, at most full.
  std::size_t SlotSizeFor(std::size_t used, std::size_t full, double slack) const;

  ///@{
  /**
   * A fresh layout: BeginLayout() empties the buffer, then AppendSlot() puts
   * each slot in turn at the tail, sized for `used` primitives (Used stays 0
   * until SetUsed()). Returns the slot.
   */
  void BeginLayout();
  const Slot& AppendSlot(std::size_t index, std::size_t used, double slack);
  ///@}

  /// Records that slot `index` now holds `used` primitives (at most its size).
  void SetUsed(std::size_t index, std::size_t used);

  /**
   * Makes slot `index` fit `used` primitives: as it is when it is large
   * enough, else grown into the hole or tail right after it, else moved to
   * the first hole that fits or to the tail. Used is left to SetUsed().
   * A slot of no primitives is freed. Without padding, a slot whose size
   * is not `used` is not placed.
   */
  Placement Place(std::size_t index, std::size_t used, double slack);

  /// Gives slot `index` back (its content counts as unused from now on).
  void Free(std::size_t index);

  /// Returns the end of slot `index` when it exceeds twice the size its content needs.
  void Trim(std::size_t index, double slack);

  /**
   * Moves every slot down over the holes, in buffer order, trimmed to the
   * size a fresh layout gives it (never larger than now). Returns the moves,
   * in the order they must be applied (each To below or at its From).
   */
  const std::vector<Move>& Compact(double slack);

  /// Twice the padding a fresh layout leaves (0 without slack).
  std::size_t PaddingLimit(double slack) const;

  /// Sorts and merges ranges closer than `gap` (in place, no allocation), clipped to [0, end).
  static void CoalesceRanges(std::vector<Range>& ranges, std::size_t end, std::size_t gap);

  const Slot& GetSlot(std::size_t index) const;
  std::size_t GetNumberOfSlots() const { return this->Slots.size(); }
  std::size_t GetCapacity() const { return this->Capacity; }
  bool GetCanPad() const { return this->CanPad; }
  /// Primitives drawn: slots, padding and holes.
  std::size_t GetTail() const { return this->Tail; }
  /// Primitives of the objects; the other Tail - Used are degenerate.
  std::size_t GetUsed() const { return this->Used; }
  std::size_t GetNumberOfSlotted() const { return this->Slotted; }
  const std::vector<Range>& GetHoles() const { return this->Holes; }
  /// Fresh layouts and compactions so far.
  std::size_t GetLayoutCount() const { return this->LayoutCount; }

private:
  Slot& CheckedSlot(std::size_t index);
  static void CheckSlack(double slack);
  bool Allocate(std::size_t size, std::size_t& start, bool& fresh);
  void Release(std::size_t start, std::size_t size);
  bool GrowInPlace(Slot& slot, std::size_t size, bool& fresh);

  std::vector<Slot> Slots;
  std::vector<Range> Holes; // free ranges below Tail, sorted and merged
  std::vector<std::size_t> Order; // slots by position (Compact)
  std::vector<Move> Moves;
  std::size_t Capacity = 0;
  std::size_t Tail = 0;
  std::size_t Used = 0;
  std::size_t Slotted = 0; // slots of a non-zero size
  std::size_t LayoutCount = 0;
  bool CanPad = true;
};
}

#endif
