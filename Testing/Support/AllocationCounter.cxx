// SPDX-License-Identifier: BSD-3-Clause
// Counting global allocator. Every form is replaced so that new/delete pairs
// stay matched (also under AddressSanitizer); kept out of line so GCC does
// not inline malloc/free into them and flag the pairs (-Wmismatched-new-delete).
#include "AllocationCounter.h"

#include <atomic>
#include <cstdlib>
#include <new>

namespace
{
std::atomic<std::size_t> AllocationCount{ 0 };

[[gnu::noinline]] void* CountedAllocate(std::size_t size) noexcept
{
  ++AllocationCount;
  return std::malloc(size ? size : 1);
}
}

std::size_t timecritical::testing::GetAllocationCount()
{
  return AllocationCount.load();
}

[[gnu::noinline]] void* operator new(std::size_t size)
{
  if (void* p = CountedAllocate(size))
  {
    return p;
  }
  throw std::bad_alloc();
}
[[gnu::noinline]] void* operator new[](std::size_t size)
{
  return ::operator new(size);
}
[[gnu::noinline]] void* operator new(std::size_t size, const std::nothrow_t&) noexcept
{
  return CountedAllocate(size);
}
[[gnu::noinline]] void* operator new[](std::size_t size, const std::nothrow_t&) noexcept
{
  return CountedAllocate(size);
}
[[gnu::noinline]] void operator delete(void* p) noexcept
{
  std::free(p);
}
[[gnu::noinline]] void operator delete[](void* p) noexcept
{
  std::free(p);
}
[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept
{
  std::free(p);
}
[[gnu::noinline]] void operator delete[](void* p, std::size_t) noexcept
{
  std::free(p);
}
[[gnu::noinline]] void operator delete(void* p, const std::nothrow_t&) noexcept
{
  std::free(p);
}
[[gnu::noinline]] void operator delete[](void* p, const std::nothrow_t&) noexcept
{
  std::free(p);
}
