// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_HugePageAllocator_h
#define timecritical_HugePageAllocator_h

/*
 * Internal to TimeCritical::MeshCore: the allocator of the collapse engine's
 * and the merge-tree replay's large working arrays (namespace
 * timecritical::collapse).
 */

#include <cstddef>
#include <memory>
#include <new>
#include <utility>
#include <vector>

namespace timecritical
{
namespace collapse
{
/*
 * Large working arrays go on transparent huge pages where the system allows
 * it (Linux, THP in "madvise" mode or better). The build touches a few
 * hundred bytes per triangle of fresh memory and then reads it in random
 * order: with 4 KiB pages the page faults and TLB misses would be a large
 * part of its cost.
 */
constexpr size_t HugePageThreshold = size_t(1) << 20;

/// Best effort: asks for huge pages on the 2 MiB-aligned interior of [p, p + bytes).
void AdviseHugePages(void* p, size_t bytes);

/// A 2 MiB-aligned anonymous mapping of at least `bytes` advised for huge pages
/// (null where the system has no such advice: use the ordinary allocator then).
void* AllocateHugePageBlock(size_t bytes);
/// Unmaps a block of AllocateHugePageBlock; false (nothing done) where it gives none.
bool FreeHugePageBlock(void* p, size_t bytes);

/// Reserves room for n elements in an (empty) vector, on huge pages if possible.
template <typename V>
void ReserveHuge(V& v, size_t n)
{
  v.reserve(n);
  AdviseHugePages(v.data(), n * sizeof(typename V::value_type));
}

/// Allocator of the large internal arrays: 2 MiB-aligned blocks advised for huge pages.
template <typename T>
struct HugePageAllocator
{
  using value_type = T;
  HugePageAllocator() = default;
  template <typename U>
  HugePageAllocator(const HugePageAllocator<U>&) // NOLINT: implicit by design
  {
  }
  T* allocate(size_t n)
  {
    if (n * sizeof(T) >= HugePageThreshold)
    {
      if (void* p = AllocateHugePageBlock(n * sizeof(T)))
      {
        return static_cast<T*>(p);
      }
    }
    return std::allocator<T>().allocate(n);
  }
  void deallocate(T* p, size_t n)
  {
    if (n * sizeof(T) >= HugePageThreshold && FreeHugePageBlock(p, n * sizeof(T)))
    {
      return;
    }
    std::allocator<T>().deallocate(p, n);
  }
  /// Default-initialises (trivial types stay uninitialised): the arrays are
  /// filled right after being sized, so zeroing them first would be wasted.
  template <typename U>
  void construct(U* p) noexcept
  {
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args)
  {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
  template <typename U>
  bool operator==(const HugePageAllocator<U>&) const
  {
    return true;
  }
  template <typename U>
  bool operator!=(const HugePageAllocator<U>&) const
  {
    return false;
  }
};

template <typename T>
using BigVector = std::vector<T, HugePageAllocator<T>>;
}
}

#endif
