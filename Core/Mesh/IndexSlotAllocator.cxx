// SPDX-License-Identifier: BSD-3-Clause
#include "IndexSlotAllocator.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <string>

namespace timecritical
{
namespace
{
auto ByStart()
{
  return [](const IndexSlotAllocator::Range& range, std::size_t value)
  { return range.Start < value; };
}
}

void IndexSlotAllocator::Configure(const std::vector<std::size_t>& fullSizes, bool canPad)
{
  this->Slots.assign(fullSizes.size(), Slot());
  this->Capacity = 0;
  for (std::size_t i = 0; i < fullSizes.size(); ++i)
  {
    this->Slots[i].Full = fullSizes[i];
    this->Capacity += fullSizes[i];
  }
  this->CanPad = canPad;
  this->Holes.clear();
  this->Tail = 0;
  this->Used = 0;
  this->Slotted = 0;
  // Holes stay sorted and merged: at most one more than there are slots,
  // plus one that Release() inserts before merging.
  this->Holes.reserve(fullSizes.size() + 2);
  this->Order.reserve(fullSizes.size());
  this->Moves.reserve(fullSizes.size());
}

void IndexSlotAllocator::CheckSlack(double slack)
{
  if (!(slack >= 0.0))
  {
    throw std::invalid_argument("IndexSlotAllocator: slack must be >= 0, got " +
      std::to_string(slack));
  }
}

IndexSlotAllocator::Slot& IndexSlotAllocator::CheckedSlot(std::size_t index)
{
  if (index >= this->Slots.size())
  {
    throw std::out_of_range("IndexSlotAllocator: slot " + std::to_string(index) +
      " out of range [0, " + std::to_string(this->Slots.size()) + ")");
  }
  return this->Slots[index];
}

const IndexSlotAllocator::Slot& IndexSlotAllocator::GetSlot(std::size_t index) const
{
  return const_cast<IndexSlotAllocator*>(this)->CheckedSlot(index);
}

std::size_t IndexSlotAllocator::SlotSizeFor(std::size_t used, std::size_t full, double slack) const
{
  CheckSlack(slack);
  if (used == 0 || !this->CanPad)
  {
    return used;
  }
  const std::size_t extra =
    slack > 0.0 ? static_cast<std::size_t>(slack * static_cast<double>(used)) + MinimumSlack : 0;
  return std::max(used, std::min(full, used + extra));
}

void IndexSlotAllocator::BeginLayout()
{
  this->Holes.clear();
  this->Tail = 0;
  this->Used = 0;
  this->Slotted = 0;
  ++this->LayoutCount;
}

const IndexSlotAllocator::Slot& IndexSlotAllocator::AppendSlot(
  std::size_t index, std::size_t used, double slack)
{
  Slot& slot = this->CheckedSlot(index);
  if (used > slot.Full)
  {
    throw std::invalid_argument("IndexSlotAllocator: " + std::to_string(used) +
      " primitives exceed the full size " + std::to_string(slot.Full) + " of slot " +
      std::to_string(index));
  }
  const std::size_t size = this->SlotSizeFor(used, slot.Full, slack);
  if (this->Tail + size > this->Capacity)
  {
    throw std::logic_error("IndexSlotAllocator: slot appended twice in one layout");
  }
  slot.Start = this->Tail;
  slot.Size = size;
  slot.Used = 0;
  this->Slotted += size > 0 ? 1 : 0;
  this->Tail += size;
  return slot;
}

void IndexSlotAllocator::SetUsed(std::size_t index, std::size_t used)
{
  Slot& slot = this->CheckedSlot(index);
  if (used > slot.Size)
  {
    throw std::invalid_argument("IndexSlotAllocator: " + std::to_string(used) +
      " primitives exceed the size " + std::to_string(slot.Size) + " of slot " +
      std::to_string(index));
  }
  this->Used = this->Used - slot.Used + used;
  slot.Used = used;
}

IndexSlotAllocator::Placement IndexSlotAllocator::Place(
  std::size_t index, std::size_t used, double slack)
{
  Slot& slot = this->CheckedSlot(index);
  if (used > slot.Full)
  {
    throw std::invalid_argument("IndexSlotAllocator: " + std::to_string(used) +
      " primitives exceed the full size " + std::to_string(slot.Full) + " of slot " +
      std::to_string(index));
  }
  CheckSlack(slack);
  Placement placement;
  if (!this->CanPad && used != slot.Size)
  {
    return placement; // no degenerate primitive (nor hole): every slot fits exactly
  }
  if (used == 0)
  {
    placement.Vacated = Range{ slot.Start, slot.Used };
    this->Free(index);
    placement.Placed = true;
    return placement;
  }
  placement.Extent = slot.Used;
  if (used > slot.Size)
  {
    const std::size_t size = this->SlotSizeFor(used, slot.Full, slack);
    bool fresh = false;
    if (!this->GrowInPlace(slot, size, fresh))
    {
      placement.Vacated = Range{ slot.Start, slot.Used };
      this->Free(index);
      std::size_t start = 0;
      if (!this->Allocate(size, start, fresh))
      {
        return placement;
      }
      slot.Start = start;
      slot.Size = size;
      ++this->Slotted;
      placement.Extent = 0;
    }
    if (fresh)
    {
      placement.Extent = size;
    }
  }
  placement.Placed = true;
  return placement;
}

void IndexSlotAllocator::Free(std::size_t index)
{
  Slot& slot = this->CheckedSlot(index);
  this->Used -= slot.Used;
  slot.Used = 0;
  this->Release(slot.Start, slot.Size);
  this->Slotted -= slot.Size > 0 ? 1 : 0;
  slot.Start = 0;
  slot.Size = 0;
}

void IndexSlotAllocator::Trim(std::size_t index, double slack)
{
  Slot& slot = this->CheckedSlot(index);
  const std::size_t size = this->SlotSizeFor(slot.Used, slot.Full, slack);
  if (slot.Size > 2 * size)
  {
    // The end is degenerate already.
    this->Release(slot.Start + size, slot.Size - size);
    slot.Size = size;
  }
}

bool IndexSlotAllocator::Allocate(std::size_t size, std::size_t& start, bool& fresh)
{
  // First fit among the holes (degenerate already), else past the end.
  for (auto hole = this->Holes.begin(); hole != this->Holes.end(); ++hole)
  {
    if (hole->Size >= size)
    {
      start = hole->Start;
      hole->Start += size;
      hole->Size -= size;
      if (hole->Size == 0)
      {
        this->Holes.erase(hole);
      }
      fresh = false;
      return true;
    }
  }
  if (this->Tail + size > this->Capacity)
  {
    return false;
  }
  start = this->Tail;
  this->Tail += size;
  fresh = true; // never written in this layout
  return true;
}

void IndexSlotAllocator::Release(std::size_t start, std::size_t size)
{
  if (size == 0)
  {
    return;
  }
  auto hole = std::lower_bound(this->Holes.begin(), this->Holes.end(), start, ByStart());
  if (hole != this->Holes.begin() && std::prev(hole)->Start + std::prev(hole)->Size == start)
  {
    --hole;
    hole->Size += size;
  }
  else
  {
    hole = this->Holes.insert(hole, Range{ start, size });
  }
  const auto next = std::next(hole);
  if (next != this->Holes.end() && hole->Start + hole->Size == next->Start)
  {
    hole->Size += next->Size;
    hole = std::prev(this->Holes.erase(next));
  }
  if (hole->Start + hole->Size == this->Tail)
  {
    // A hole at the end is simply not drawn.
    this->Tail = hole->Start;
    this->Holes.erase(hole);
  }
}

bool IndexSlotAllocator::GrowInPlace(Slot& slot, std::size_t size, bool& fresh)
{
  const std::size_t end = slot.Start + slot.Size;
  const std::size_t extra = size - slot.Size;
  if (slot.Size == 0)
  {
    return false;
  }
  if (end == this->Tail)
  {
    if (slot.Start + size > this->Capacity)
    {
      return false;
    }
    this->Tail = slot.Start + size;
    slot.Size = size;
    fresh = true;
    return true;
  }
  auto hole = std::lower_bound(this->Holes.begin(), this->Holes.end(), end, ByStart());
  if (hole == this->Holes.end() || hole->Start != end || hole->Size < extra)
  {
    return false;
  }
  hole->Start += extra;
  hole->Size -= extra;
  if (hole->Size == 0)
  {
    this->Holes.erase(hole);
  }
  slot.Size = size;
  fresh = false;
  return true;
}

const std::vector<IndexSlotAllocator::Move>& IndexSlotAllocator::Compact(double slack)
{
  CheckSlack(slack);
  this->Order.clear();
  for (std::size_t i = 0; i < this->Slots.size(); ++i)
  {
    if (this->Slots[i].Size > 0)
    {
      this->Order.push_back(i); // capacity reserved by Configure
    }
  }
  std::sort(this->Order.begin(), this->Order.end(), [this](std::size_t a, std::size_t b)
    { return this->Slots[a].Start < this->Slots[b].Start; });
  this->Moves.clear();
  std::size_t tail = 0;
  for (const std::size_t i : this->Order)
  {
    Slot& slot = this->Slots[i];
    // Never larger than now, so that every slot moves down (or stays).
    const std::size_t size = std::min(slot.Size, this->SlotSizeFor(slot.Used, slot.Full, slack));
    if (slot.Start != tail)
    {
      this->Moves.push_back(Move{ i, slot.Start, tail, size, slot.Used });
    }
    slot.Start = tail;
    slot.Size = size;
    tail += size;
  }
  this->Holes.clear();
  this->Tail = tail;
  ++this->LayoutCount;
  return this->Moves;
}

std::size_t IndexSlotAllocator::PaddingLimit(double slack) const
{
  CheckSlack(slack);
  return slack > 0.0
    ? 2 * (static_cast<std::size_t>(slack * static_cast<double>(this->Used)) +
            MinimumSlack * this->Slotted)
    : 0;
}

void IndexSlotAllocator::CoalesceRanges(
  std::vector<Range>& ranges, std::size_t end, std::size_t gap)
{
  std::sort(ranges.begin(), ranges.end(),
    [](const Range& a, const Range& b) { return a.Start < b.Start; });
  std::size_t kept = 0;
  for (const Range& range : ranges)
  {
    const std::size_t stop = std::min(range.Start + range.Size, end);
    if (range.Start >= stop)
    {
      continue;
    }
    if (kept > 0 && range.Start <= ranges[kept - 1].Start + ranges[kept - 1].Size + gap)
    {
      Range& last = ranges[kept - 1];
      last.Size = std::max(last.Start + last.Size, stop) - last.Start;
    }
    else
    {
      ranges[kept++] = Range{ range.Start, stop - range.Start };
    }
  }
  ranges.resize(kept); // shrinking: no allocation
}
}
