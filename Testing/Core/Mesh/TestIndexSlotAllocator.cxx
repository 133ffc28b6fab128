// SPDX-License-Identifier: BSD-3-Clause
// IndexSlotAllocator: slot sizes, fresh layouts, growth in place, moves to
// holes and to the tail, release and coalescing of holes, trimming,
// compaction, the padding limit, slots without padding, dirty-range
// coalescing, bad arguments, and no allocation after Configure().
#include "IndexSlotAllocator.h"

#include "AllocationCounter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace
{
using timecritical::IndexSlotAllocator;
using Range = IndexSlotAllocator::Range;

constexpr double NoSlack = 0.0;

/// Slots of the given full sizes laid out at `used` each (with `slack`), content recorded.
IndexSlotAllocator LaidOut(const std::vector<size_t>& full, const std::vector<size_t>& used,
  double slack, bool canPad = true)
{
  IndexSlotAllocator allocator;
  allocator.Configure(full, canPad);
  allocator.BeginLayout();
  for (size_t i = 0; i < full.size(); ++i)
  {
    allocator.AppendSlot(i, used[i], slack);
    allocator.SetUsed(i, used[i]);
  }
  return allocator;
}

void ExpectHoles(const IndexSlotAllocator& allocator, const std::vector<Range>& expected)
{
  const std::vector<Range>& holes = allocator.GetHoles();
  ASSERT_EQ(holes.size(), expected.size());
  for (size_t i = 0; i < holes.size(); ++i)
  {
    EXPECT_EQ(holes[i].Start, expected[i].Start) << "hole " << i;
    EXPECT_EQ(holes[i].Size, expected[i].Size) << "hole " << i;
  }
}

void ExpectSlot(const IndexSlotAllocator& allocator, size_t i, size_t start, size_t size, size_t used)
{
  const IndexSlotAllocator::Slot& slot = allocator.GetSlot(i);
  EXPECT_EQ(slot.Start, start) << "slot " << i;
  EXPECT_EQ(slot.Size, size) << "slot " << i;
  EXPECT_EQ(slot.Used, used) << "slot " << i;
}
}

TEST(IndexSlotAllocator, ConfigureSumsTheFullSizes)
{
  IndexSlotAllocator allocator;
  allocator.Configure({ 10, 0, 25 }, true);
  EXPECT_EQ(allocator.GetNumberOfSlots(), 3u);
  EXPECT_EQ(allocator.GetCapacity(), 35u);
  EXPECT_EQ(allocator.GetTail(), 0u);
  EXPECT_EQ(allocator.GetUsed(), 0u);
  EXPECT_TRUE(allocator.GetCanPad());
  ExpectSlot(allocator, 2, 0, 0, 0);
  EXPECT_EQ(allocator.GetSlot(2).Full, 25u);
}

TEST(IndexSlotAllocator, SlotSizeAddsSlackAndMinimumUpToFull)
{
  IndexSlotAllocator allocator;
  allocator.Configure({ 1000 }, true);
  EXPECT_EQ(allocator.SlotSizeFor(0, 1000, 0.1), 0u);
  EXPECT_EQ(allocator.SlotSizeFor(100, 1000, NoSlack), 100u);
  EXPECT_EQ(allocator.SlotSizeFor(100, 1000, 0.1), 100u + 10u + IndexSlotAllocator::MinimumSlack);
  EXPECT_EQ(allocator.SlotSizeFor(100, 105, 0.1), 105u);
  EXPECT_EQ(allocator.SlotSizeFor(100, 100, 0.1), 100u);
  allocator.Configure({ 1000 }, false);
  EXPECT_EQ(allocator.SlotSizeFor(100, 1000, 0.1), 100u); // no padding at all
}

TEST(IndexSlotAllocator, FreshLayoutPutsSlotsEndToEnd)
{
  IndexSlotAllocator allocator = LaidOut({ 100, 50, 200 }, { 40, 0, 200 }, 0.1);
  ExpectSlot(allocator, 0, 0, 40 + 4 + 8, 40);
  ExpectSlot(allocator, 1, 52, 0, 0);
  ExpectSlot(allocator, 2, 52, 200, 200);
  EXPECT_EQ(allocator.GetTail(), 252u);
  EXPECT_EQ(allocator.GetUsed(), 240u);
  EXPECT_EQ(allocator.GetNumberOfSlotted(), 2u);
  EXPECT_EQ(allocator.GetLayoutCount(), 1u);
  EXPECT_TRUE(allocator.GetHoles().empty());
}

TEST(IndexSlotAllocator, ContentThatFitsStaysInPlace)
{
  IndexSlotAllocator allocator = LaidOut({ 100, 100 }, { 40, 40 }, 0.1);
  const auto placement = allocator.Place(0, 50, 0.1);
  EXPECT_TRUE(placement.Placed);
  EXPECT_EQ(placement.Vacated.Size, 0u);
  EXPECT_EQ(placement.Extent, 40u); // the old content may need clearing
  allocator.SetUsed(0, 50);
  ExpectSlot(allocator, 0, 0, 52, 50);
  EXPECT_EQ(allocator.GetUsed(), 90u);
}

TEST(IndexSlotAllocator, LastSlotGrowsIntoTheTail)
{
  IndexSlotAllocator allocator = LaidOut({ 100, 100 }, { 40, 40 }, 0.1);
  const auto placement = allocator.Place(1, 80, 0.1);
  EXPECT_TRUE(placement.Placed);
  EXPECT_EQ(placement.Vacated.Size, 0u);
  EXPECT_EQ(placement.Extent, 96u); // fresh: never written in this layout
  ExpectSlot(allocator, 1, 52, 80 + 8 + 8, 40);
  EXPECT_EQ(allocator.GetTail(), 52u + 96u);
}

TEST(IndexSlotAllocator, SlotGrowsIntoTheHoleAfterIt)
{
  IndexSlotAllocator allocator = LaidOut({ 100, 100, 100 }, { 40, 40, 40 }, 0.1);
  allocator.Free(1);
  ExpectHoles(allocator, { { 52, 52 } });
  const auto placement = allocator.Place(0, 60, 0.1);
  EXPECT_TRUE(placement.Placed);
  EXPECT_EQ(placement.Vacated.Size, 0u);
  EXPECT_EQ(placement.Extent, 40u); // the hole is degenerate already
  ExpectSlot(allocator, 0, 0, 60 + 6 + 8, 40);
  ExpectHoles(allocator, { { 74, 30 } });
}

TEST(IndexSlotAllocator, OutgrownSlotMovesToTheFirstHoleThatFits)
{
  IndexSlotAllocator allocator = LaidOut({ 100, 100, 100, 100 }, { 10, 40, 10, 40 }, NoSlack);
  allocator.Free(1); // hole [10, 50)
  const auto placement = allocator.Place(2, 30, NoSlack);
  EXPECT_TRUE(placement.Placed);
  EXPECT_EQ(placement.Vacated.Start, 50u);
  EXPECT_EQ(placement.Vacated.Size, 10u);
  EXPECT_EQ(placement.Extent, 0u);
  ExpectSlot(allocator, 2, 10, 30, 0);
  // The old place merged with the hole before it, then the slot took its start.
  ExpectHoles(allocator, { { 40, 20 } });
  EXPECT_EQ(allocator.GetUsed(), 50u);
}

TEST(IndexSlotAllocator, OutgrownSlotMovesToTheTailWithoutAFittingHole)
{
  IndexSlotAllocator allocator = LaidOut({ 100, 100, 100 }, { 10, 10, 10 }, NoSlack);
  const auto placement = allocator.Place(0, 50, NoSlack);
  EXPECT_TRUE(placement.Placed);
  EXPECT_EQ(placement.Vacated.Start, 0u);
  EXPECT_EQ(placement.Vacated.Size, 10u);
  EXPECT_EQ(placement.Extent, 50u);
  ExpectSlot(allocator, 0, 30, 50, 0);
  ExpectHoles(allocator, { { 0, 10 } });
  EXPECT_EQ(allocator.GetTail(), 80u);
}

TEST(IndexSlotAllocator, NoRoomLeftFreesTheSlotAndFails)
{
  IndexSlotAllocator allocator = LaidOut({ 10, 20, 30 }, { 10, 10, 10 }, NoSlack);
  ASSERT_TRUE(allocator.Place(2, 30, NoSlack).Placed); // grows into the tail: 50 of 60
  allocator.SetUsed(2, 30);
  const auto placement = allocator.Place(1, 20, NoSlack); // no hole, no room at the tail
  EXPECT_FALSE(placement.Placed);
  EXPECT_EQ(placement.Vacated.Start, 10u);
  EXPECT_EQ(placement.Vacated.Size, 10u);
  ExpectSlot(allocator, 1, 0, 0, 0);
  ExpectHoles(allocator, { { 10, 10 } });
  EXPECT_EQ(allocator.GetUsed(), 40u);
  EXPECT_EQ(allocator.GetTail(), 50u);
}

TEST(IndexSlotAllocator, ReleasedRangesCoalesceAndShortenTheTail)
{
  IndexSlotAllocator allocator = LaidOut({ 10, 10, 10, 10, 10 }, { 10, 10, 10, 10, 10 }, NoSlack);
  allocator.Free(1);
  allocator.Free(3);
  ExpectHoles(allocator, { { 10, 10 }, { 30, 10 } });
  allocator.Free(2); // merges with both neighbours
  ExpectHoles(allocator, { { 10, 30 } });
  EXPECT_EQ(allocator.GetTail(), 50u);
  allocator.Free(4); // the hole reaches the tail: the tail moves down instead
  EXPECT_TRUE(allocator.GetHoles().empty());
  EXPECT_EQ(allocator.GetTail(), 10u);
  EXPECT_EQ(allocator.GetUsed(), 10u);
  EXPECT_EQ(allocator.GetNumberOfSlotted(), 1u);
}

TEST(IndexSlotAllocator, EmptyContentFreesTheSlot)
{
  IndexSlotAllocator allocator = LaidOut({ 10, 10 }, { 10, 10 }, NoSlack);
  const auto placement = allocator.Place(0, 0, NoSlack);
  EXPECT_TRUE(placement.Placed);
  EXPECT_EQ(placement.Vacated.Start, 0u);
  EXPECT_EQ(placement.Vacated.Size, 10u);
  ExpectSlot(allocator, 0, 0, 0, 0);
  ExpectHoles(allocator, { { 0, 10 } });
}

TEST(IndexSlotAllocator, TrimReturnsTheEndOfAFarTooLargeSlot)
{
  IndexSlotAllocator allocator = LaidOut({ 1000, 10 }, { 500, 10 }, NoSlack);
  allocator.SetUsed(0, 300);
  allocator.Trim(0, NoSlack); // 500 is not above 2 x 300
  ExpectSlot(allocator, 0, 0, 500, 300);
  allocator.SetUsed(0, 200);
  allocator.Trim(0, NoSlack);
  ExpectSlot(allocator, 0, 0, 200, 200);
  ExpectHoles(allocator, { { 200, 300 } });
}

TEST(IndexSlotAllocator, CompactionMovesSlotsDownInBufferOrder)
{
  IndexSlotAllocator allocator = LaidOut({ 100, 100, 100, 100 }, { 20, 20, 20, 20 }, 0.5);
  // Slots of 38: [0, 38) [38, 76) [76, 114) [114, 152).
  allocator.Free(1);
  ASSERT_TRUE(allocator.Place(0, 60, 0.5).Placed); // moves to the tail
  allocator.SetUsed(0, 60);
  allocator.SetUsed(2, 5);
  const size_t before = allocator.GetLayoutCount();
  const auto& moves = allocator.Compact(0.5);
  EXPECT_EQ(allocator.GetLayoutCount(), before + 1);
  // Buffer order: slot 2, slot 3, slot 0; slot 2 trimmed to 5 + 2 + 8.
  ASSERT_EQ(moves.size(), 3u);
  EXPECT_EQ(moves[0].SlotIndex, 2u);
  EXPECT_EQ(moves[0].To, 0u);
  EXPECT_EQ(moves[0].Size, 15u);
  EXPECT_EQ(moves[0].Used, 5u);
  EXPECT_EQ(moves[1].SlotIndex, 3u);
  EXPECT_EQ(moves[1].To, 15u);
  EXPECT_EQ(moves[2].SlotIndex, 0u);
  EXPECT_EQ(moves[2].To, 15u + 38u);
  for (const auto& move : moves)
  {
    EXPECT_LE(move.To, move.From);
  }
  ExpectSlot(allocator, 0, 53, 98, 60);
  EXPECT_TRUE(allocator.GetHoles().empty());
  EXPECT_EQ(allocator.GetTail(), 53u + 98u);
}

TEST(IndexSlotAllocator, PaddingLimitIsTwiceAFreshLayoutsPadding)
{
  IndexSlotAllocator allocator = LaidOut({ 1000, 1000, 1000 }, { 100, 0, 300 }, 0.1);
  EXPECT_EQ(allocator.PaddingLimit(0.1), 2u * (40u + 2u * IndexSlotAllocator::MinimumSlack));
  EXPECT_EQ(allocator.PaddingLimit(NoSlack), 0u);
}

TEST(IndexSlotAllocator, WithoutPaddingSlotsFitExactly)
{
  IndexSlotAllocator allocator = LaidOut({ 100, 100 }, { 40, 40 }, 0.1, false);
  ExpectSlot(allocator, 0, 0, 40, 40);
  EXPECT_FALSE(allocator.Place(0, 39, 0.1).Placed);
  EXPECT_FALSE(allocator.Place(0, 0, 0.1).Placed);
  ExpectSlot(allocator, 0, 0, 40, 40); // untouched
  const auto same = allocator.Place(0, 40, 0.1);
  EXPECT_TRUE(same.Placed);
  EXPECT_EQ(same.Extent, 40u);
}

TEST(IndexSlotAllocator, CoalesceRangesSortsMergesAndClips)
{
  std::vector<Range> ranges = { { 500, 10 }, { 0, 10 }, { 15, 5 }, { 900, 200 }, { 1000, 5 },
    { 40, 0 } };
  IndexSlotAllocator::CoalesceRanges(ranges, 1000, 8);
  ASSERT_EQ(ranges.size(), 3u);
  EXPECT_EQ(ranges[0].Start, 0u); // [0, 10) and [15, 20): 5 apart
  EXPECT_EQ(ranges[0].Size, 20u);
  EXPECT_EQ(ranges[1].Start, 500u);
  EXPECT_EQ(ranges[1].Size, 10u);
  EXPECT_EQ(ranges[2].Start, 900u); // clipped; [1000, 1005) dropped
  EXPECT_EQ(ranges[2].Size, 100u);
}

TEST(IndexSlotAllocator, BadArgumentsThrow)
{
  IndexSlotAllocator allocator = LaidOut({ 10, 10 }, { 5, 5 }, NoSlack);
  EXPECT_THROW(allocator.GetSlot(2), std::out_of_range);
  EXPECT_THROW(allocator.Place(2, 1, NoSlack), std::out_of_range);
  EXPECT_THROW(allocator.Free(7), std::out_of_range);
  EXPECT_THROW(allocator.Place(0, 11, NoSlack), std::invalid_argument);
  EXPECT_THROW(allocator.Place(0, 6, -0.1), std::invalid_argument);
  EXPECT_THROW(allocator.Place(0, 6, std::numeric_limits<double>::quiet_NaN()),
    std::invalid_argument);
  EXPECT_THROW(allocator.SetUsed(0, 6), std::invalid_argument); // above its size
  EXPECT_THROW(allocator.Compact(-1.0), std::invalid_argument);
  allocator.BeginLayout();
  EXPECT_THROW(allocator.AppendSlot(0, 11, NoSlack), std::invalid_argument);
  allocator.AppendSlot(0, 10, NoSlack);
  allocator.AppendSlot(1, 10, NoSlack);
  EXPECT_THROW(allocator.AppendSlot(1, 10, NoSlack), std::logic_error);
}

TEST(IndexSlotAllocator, NothingAllocatesAfterConfigure)
{
  const size_t count = 64;
  std::vector<size_t> full(count);
  for (size_t i = 0; i < count; ++i)
  {
    full[i] = 50 + 7 * i;
  }
  IndexSlotAllocator allocator;
  allocator.Configure(full, true);
  std::vector<Range> dirty;
  dirty.reserve(4 * count);
  const size_t before = timecritical::testing::GetAllocationCount();
  for (int round = 0; round < 3; ++round)
  {
    allocator.BeginLayout();
    for (size_t i = 0; i < count; ++i)
    {
      const auto& slot = allocator.AppendSlot(i, full[i] / 4, 0.1);
      allocator.SetUsed(i, full[i] / 4);
      dirty.push_back(Range{ slot.Start, slot.Size });
    }
    for (size_t step = 0; step < 8 * count; ++step)
    {
      const size_t i = (step * 37) % count;
      const size_t used = (step * 13 + i) % (full[i] + 1);
      const auto placement = allocator.Place(i, used, 0.1);
      if (!placement.Placed)
      {
        allocator.Compact(0.1);
        continue;
      }
      if (used > 0)
      {
        allocator.SetUsed(i, used);
        allocator.Trim(i, 0.1);
      }
      if (allocator.GetTail() - allocator.GetUsed() > allocator.PaddingLimit(0.1))
      {
        allocator.Compact(0.1);
      }
      dirty.push_back(Range{ allocator.GetSlot(i).Start, used });
      IndexSlotAllocator::CoalesceRanges(dirty, allocator.GetTail(), 16);
      if (dirty.size() > 2 * count)
      {
        dirty.clear(); // uploaded
      }
    }
  }
  EXPECT_EQ(timecritical::testing::GetAllocationCount(), before);
  EXPECT_LE(allocator.GetHoles().size(), count + 1);
}
