// SPDX-License-Identifier: BSD-3-Clause
#include "HugePageAllocator.h"

#include <cstdint>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace timecritical
{
namespace collapse
{
namespace
{
constexpr size_t HugePageSize = size_t(2) << 20;

size_t RoundUp(size_t bytes)
{
  return (bytes + HugePageSize - 1) & ~(HugePageSize - 1);
}
}

//------------------------------------------------------------------------------
void AdviseHugePages(void* p, size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  if (bytes < HugePageThreshold)
  {
    return;
  }
  const uintptr_t begin = (reinterpret_cast<uintptr_t>(p) + HugePageSize - 1) & ~(HugePageSize - 1);
  const uintptr_t end = (reinterpret_cast<uintptr_t>(p) + bytes) & ~(HugePageSize - 1);
  if (end > begin)
  {
    madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
  }
#else
  (void)p;
  (void)bytes;
#endif
}

//------------------------------------------------------------------------------
void* AllocateHugePageBlock(size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  // A mapping of its own, 2 MiB aligned (trimmed from a larger one), so
  // that every 2 MiB of it can be a huge page.
  const size_t rounded = RoundUp(bytes);
  void* raw =
    mmap(nullptr, rounded + HugePageSize, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED)
  {
    throw std::bad_alloc();
  }
  const uintptr_t begin = reinterpret_cast<uintptr_t>(raw);
  const uintptr_t aligned = (begin + HugePageSize - 1) & ~(HugePageSize - 1);
  if (aligned > begin)
  {
    munmap(raw, aligned - begin);
  }
  const uintptr_t end = begin + rounded + HugePageSize;
  if (end > aligned + rounded)
  {
    munmap(reinterpret_cast<void*>(aligned + rounded), end - (aligned + rounded));
  }
  madvise(reinterpret_cast<void*>(aligned), rounded, MADV_HUGEPAGE);
  return reinterpret_cast<void*>(aligned);
#else
  (void)bytes;
  return nullptr;
#endif
}

//------------------------------------------------------------------------------
bool FreeHugePageBlock(void* p, size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  munmap(p, RoundUp(bytes));
  return true;
#else
  (void)p;
  (void)bytes;
  return false;
#endif
}
}
}
