// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_IndexedHeap_h
#define timecritical_IndexedHeap_h

#include "HugePageAllocator.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>

namespace timecritical
{
namespace collapse
{
/**
 * Min-heap of vertices keyed by their best collapse cost, with positions so
 * that keys can be changed and entries removed in O(log n). Four children per
 * node: half the depth of a binary heap, and with the storage shifted by
 * three entries each family of four 8-byte entries fills an aligned half
 * cache line.
 */
class IndexedHeap
{
public:
  struct Entry
  {
    float Key;
    uint32_t Vertex;
  };

  void Reset(size_t numberOfVertices)
  {
    this->Pos.assign(numberOfVertices, NotInHeap);
    this->Storage.clear();
    this->Storage.reserve(numberOfVertices + Shift);
    this->Storage.resize(Shift, Entry{ 0.f, NotInHeap });
    this->Count = 0;
  }
  bool Empty() const { return this->Count == 0; }
  const Entry& Top() const { return this->Storage[Shift]; }

  /// Appends without ordering; call Heapify afterwards.
  void PushUnordered(uint32_t v, float key)
  {
    this->Pos[v] = static_cast<uint32_t>(this->Count++);
    this->Storage.push_back({ key, v });
  }
  void Heapify()
  {
    for (size_t i = this->Count / Arity + 1; i-- > 0;)
    {
      if (i < this->Count)
      {
        this->SiftDown(i);
      }
    }
  }
  void Set(uint32_t v, float key)
  {
    uint32_t p = this->Pos[v];
    if (p == NotInHeap)
    {
      p = static_cast<uint32_t>(this->Count++);
      this->Storage.push_back({ key, v });
      this->Pos[v] = p;
      this->SiftUp(p);
      return;
    }
    Entry* d = this->Data();
    const float old = d[p].Key;
    d[p].Key = key;
    if (key < old)
    {
      this->SiftUp(p);
    }
    else if (key > old)
    {
      this->SiftDown(p);
    }
  }
  void Remove(uint32_t v)
  {
    const uint32_t p = this->Pos[v];
    if (p == NotInHeap)
    {
      return;
    }
    this->Pos[v] = NotInHeap;
    const Entry last = this->Storage.back();
    this->Storage.pop_back();
    --this->Count;
    if (p < this->Count)
    {
      Entry* d = this->Data();
      const float old = d[p].Key;
      d[p] = last;
      this->Pos[last.Vertex] = p;
      if (last.Key < old)
      {
        this->SiftUp(p);
      }
      else
      {
        this->SiftDown(p);
      }
    }
  }
  /// Smallest key among the entries other than the top (+inf when none).
  float SecondKey() const
  {
    const size_t n = std::min<size_t>(this->Count, Arity + 1);
    float k = std::numeric_limits<float>::infinity();
    for (size_t i = 1; i < n; ++i)
    {
      k = std::min(k, this->Storage[Shift + i].Key);
    }
    return k;
  }

private:
  static constexpr uint32_t NotInHeap = std::numeric_limits<uint32_t>::max();
  static constexpr size_t Arity = 4;
  static constexpr size_t Shift = 3; // children of i at 4i+1.. sit at 4(i+1)+0..3 in storage

  Entry* Data() { return this->Storage.data() + Shift; }

  void SiftUp(size_t i)
  {
    Entry* d = this->Data();
    const Entry e = d[i];
    while (i > 0)
    {
      const size_t parent = (i - 1) / Arity;
      if (!(e.Key < d[parent].Key))
      {
        break;
      }
      d[i] = d[parent];
      this->Pos[d[i].Vertex] = static_cast<uint32_t>(i);
      i = parent;
    }
    d[i] = e;
    this->Pos[e.Vertex] = static_cast<uint32_t>(i);
  }
  void SiftDown(size_t i)
  {
    Entry* d = this->Data();
    const size_t n = this->Count;
    const Entry e = d[i];
    for (;;)
    {
      const size_t first = Arity * i + 1;
      if (first >= n)
      {
        break;
      }
      size_t child = first;
      if (first + Arity <= n)
      {
        // Full family (the common case): a branch-light tournament.
        const Entry* c = d + first;
        const size_t a = c[1].Key < c[0].Key ? 1 : 0;
        const size_t b = c[3].Key < c[2].Key ? 3 : 2;
        child += c[b].Key < c[a].Key ? b : a;
      }
      else
      {
        for (size_t c = first + 1; c < n; ++c)
        {
          if (d[c].Key < d[child].Key)
          {
            child = c;
          }
        }
      }
      if (!(d[child].Key < e.Key))
      {
        break;
      }
      d[i] = d[child];
      this->Pos[d[i].Vertex] = static_cast<uint32_t>(i);
      i = child;
    }
    d[i] = e;
    this->Pos[e.Vertex] = static_cast<uint32_t>(i);
  }

  BigVector<Entry> Storage; // Shift unused entries, then the heap
  BigVector<uint32_t> Pos;
  size_t Count = 0;
};
}
}

#endif
