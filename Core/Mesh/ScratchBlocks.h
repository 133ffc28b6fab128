// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_ScratchBlocks_h
#define timecritical_ScratchBlocks_h

#include "HugePageAllocator.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace timecritical
{
namespace collapse
{
/**
 * Working memory handed on: the storage of arrays a step has finished with
 * (moved in, freed with this object), from which a later step takes its own
 * arrays. Fresh memory costs a page fault and the zeroing of every page;
 * reused memory costs neither (MergeTreeBuilder hands the engine's arrays to
 * the merge-tree replay this way).
 */
class ScratchBlocks
{
public:
  /// Takes over the storage of v, whose contents are dead.
  template <typename T>
  void Add(BigVector<T>&& v)
  {
    auto owner = std::make_shared<BigVector<T>>(std::move(v));
    const size_t bytes = owner->capacity() * sizeof(T);
    if (bytes > 0)
    {
      unsigned char* data = reinterpret_cast<unsigned char*>(owner->data());
      this->Blocks.push_back({ data, bytes, 0, std::move(owner) });
    }
  }

  /// Room for n objects of T (trivial types only, left uninitialised) from the
  /// block with the least room that holds them; null when none does.
  template <typename T>
  T* Take(size_t n)
  {
    static_assert(std::is_trivial<T>::value, "raw storage for trivial types only");
    const size_t bytes = n * sizeof(T);
    Block* best = nullptr;
    size_t bestStart = 0;
    for (Block& b : this->Blocks)
    {
      const uintptr_t base = reinterpret_cast<uintptr_t>(b.Data);
      const uintptr_t first = (base + b.Used + alignof(T) - 1) & ~uintptr_t(alignof(T) - 1);
      const size_t start = static_cast<size_t>(first - base);
      if (start <= b.Size && b.Size - start >= bytes &&
        (!best || b.Size - start < best->Size - bestStart))
      {
        best = &b;
        bestStart = start;
      }
    }
    if (!best || n == 0)
    {
      return nullptr;
    }
    best->Used = bestStart + bytes;
    T* p = reinterpret_cast<T*>(best->Data + bestStart);
    for (size_t i = 0; i < n; ++i)
    {
      ::new (static_cast<void*>(p + i)) T; // starts the objects' lifetime; no code
    }
    return p;
  }

private:
  struct Block
  {
    unsigned char* Data;
    size_t Size;
    size_t Used;
    std::shared_ptr<void> Owner;
  };
  std::vector<Block> Blocks;
};
}
}

#endif
