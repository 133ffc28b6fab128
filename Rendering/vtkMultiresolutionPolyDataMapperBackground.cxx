// SPDX-License-Identifier: BSD-3-Clause
// vtkMultiresolutionPolyDataMapper: background hierarchy builds. Leaves
// without a hierarchy are submitted to a vtkHierarchyBuildQueue by content
// hash and drawn in full meanwhile; finished builds are taken at the next
// UpdateObjects() and swapped in by reading the objects again.
#include "vtkMultiresolutionPolyDataMapperInternals.h"

#include "LeafContentHash.h"
#include "LeafInterimReduction.h"
#include "vtkHierarchyBuildCache.h"
#include "vtkMergeTreeFieldData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataValidator.h"
#include "vtkTOMFieldData.h"

#include <algorithm>

//------------------------------------------------------------------------------
void vtkMultiresolutionPolyDataMapper::SetBackgroundBuilds(bool on)
{
  if (on == this->BackgroundBuilds)
  {
    return;
  }
  this->BackgroundBuilds = on;
  // On: the current leaves are read again and submitted. Off: what is drawn
  // stays until the input changes (no leaf is left without its reading).
  this->Internal->ClearBackground(on);
  this->Modified();
}

void vtkMultiresolutionPolyDataMapper::SetBackgroundInterimDivisions(int divisions)
{
  divisions = divisions < 2 ? 0 : std::min(divisions, 1024);
  if (divisions != this->BackgroundInterimDivisions)
  {
    this->BackgroundInterimDivisions = divisions;
    this->Internal->Interims.clear(); // made again at the next read of pending leaves
  }
}

void vtkMultiresolutionPolyDataMapper::SetBackgroundHierarchy(int hierarchy)
{
  if (hierarchy != vtkHierarchyBuildQueue::TOTALLY_ORDERED_MESH &&
    hierarchy != vtkHierarchyBuildQueue::MERGE_TREE)
  {
    vtkErrorMacro("BackgroundHierarchy " << hierarchy
                                         << " is not TOTALLY_ORDERED_MESH (0) or MERGE_TREE (1); "
                                            "ignored.");
    return;
  }
  if (hierarchy == this->BackgroundHierarchy)
  {
    return;
  }
  this->BackgroundHierarchy = hierarchy;
  this->Internal->ClearBackground(this->BackgroundBuilds);
  this->Modified();
}

void vtkMultiresolutionPolyDataMapper::Internals::ClearBackground(bool read)
{
  if (this->Queue)
  {
    this->Queue->CancelAll();
  }
  // The objects may draw finished builds: those go at the next read.
  this->BackgroundReset = true;
  this->ForceRead = this->ForceRead || read;
}

void vtkMultiresolutionPolyDataMapper::Internals::ForgetBuilds()
{
  this->Built.clear();
  this->Interims.clear();
  this->Failed.clear();
  this->CurrentKeys.clear();
  this->PendingHierarchies = 0;
  this->BackgroundReset = false;
}

int vtkMultiresolutionPolyDataMapper::GetNumberOfPendingHierarchies() const
{
  return this->BackgroundBuilds ? this->Internal->PendingHierarchies : 0;
}

vtkIdType vtkMultiresolutionPolyDataMapper::GetNumberOfBackgroundBuilds()
{
  return this->Internal->Queue ? this->Internal->Queue->GetNumberOfBuilds() : 0;
}

vtkIdType vtkMultiresolutionPolyDataMapper::GetNumberOfBackgroundCacheHits()
{
  return this->Internal->Queue ? this->Internal->Queue->GetNumberOfStoreHits() : 0;
}

vtkHierarchyBuildQueue* vtkMultiresolutionPolyDataMapper::GetBuildQueue()
{
  Internals& in = *this->Internal;
  if (!in.Queue)
  {
    in.Queue = vtkSmartPointer<vtkHierarchyBuildQueue>::New();
    // The process's hierarchy cache (shared with vtkMultiresolutionHierarchyBuilder
    // and every other mapper): a time step or an edit shown again builds nothing.
    // Background builds use the builders' defaults: no pair contraction (0).
    vtkHierarchyBuildCache* cache = vtkHierarchyBuildCache::GetSharedInstance();
    in.Queue->SetResultStore(
      [cache](uint64_t key, vtkIdType cells, int hierarchy) {
        return cache->Find(vtkHierarchyBuildCache::Key{ key, cells, hierarchy, 0.0 });
      },
      [cache](uint64_t key, vtkIdType cells, int hierarchy, vtkPolyData* output,
        std::vector<std::string>& warnings) {
        cache->Insert(
          vtkHierarchyBuildCache::Key{ key, cells, hierarchy, 0.0 }, output, &warnings);
      });
  }
  return in.Queue;
}

void vtkMultiresolutionPolyDataMapper::WaitForHierarchies()
{
  if (!this->BackgroundBuilds)
  {
    return;
  }
  this->UpdateObjects();
  // Each round swaps in what finished; a pipeline that brings new leaves at
  // every update could go on for ever, hence the bound.
  for (int round = 0; round < 100 && this->Internal->PendingHierarchies > 0; ++round)
  {
    this->GetBuildQueue()->WaitAll();
    this->UpdateObjects();
  }
}

//------------------------------------------------------------------------------
bool vtkMultiresolutionPolyDataMapper::TakeBuiltHierarchies()
{
  Internals& in = *this->Internal;
  if (!this->BackgroundBuilds || !in.Queue || in.Queue->GetNumberOfFinished() == 0)
  {
    return false; // the usual frame: no lock held long, nothing allocated
  }
  const auto now = std::chrono::steady_clock::now();
  if (in.Queue->GetNumberOfPending() > 0 &&
    now - in.LastSwap < std::chrono::duration<double>(Internals::SwapInterval))
  {
    return false; // more builds to come: swap them in together
  }
  in.LastSwap = now;
  in.Taken.clear();
  in.Queue->Take(in.Taken);
  bool swap = false;
  for (auto& result : in.Taken)
  {
    auto current = std::find_if(in.CurrentKeys.begin(), in.CurrentKeys.end(),
      [&result](const std::pair<uint64_t, unsigned int>& key) { return key.first == result.Key; });
    if (current == in.CurrentKeys.end() || result.Hierarchy != this->BackgroundHierarchy)
    {
      continue; // its leaf is gone (finished just before the cancellation)
    }
    for (const auto& message : result.Messages)
    {
      if (message.IsError)
      {
        vtkErrorMacro("Block " << current->second << ": no hierarchy built, drawn in full: "
                               << message.Text);
      }
      else
      {
        vtkWarningMacro("Block " << current->second << ": " << message.Text);
      }
    }
    if (result.Output)
    {
      in.Built[result.Key] = result.Output;
      ++this->NumberOfSwappedHierarchies;
    }
    else
    {
      in.Failed.insert(result.Key);
    }
    swap = true;
  }
  in.Taken.clear();
  return swap;
}

//------------------------------------------------------------------------------
uint64_t vtkMultiresolutionPolyDataMapper::Internals::KeyOf(vtkPolyData* leaf)
{
  LeafFacts& facts = this->FactsOf(leaf);
  if (!facts.Hashed)
  {
    facts.Key = timecritical::HashLeafContent(leaf);
    facts.Hashed = true;
  }
  return facts.Key;
}

vtkPolyData* vtkMultiresolutionPolyDataMapper::Internals::InterimOf(
  vtkPolyData* leaf, uint64_t key, int divisions)
{
  // Made once per leaf, on this thread: a small fraction of the build's time
  // for a fraction of the full leaf's drawing time in every frame meanwhile.
  auto known = this->Interims.find(key);
  if (known == this->Interims.end())
  {
    known = this->Interims
              .emplace(key,
                timecritical::BuildInterimReduction(leaf, divisions, InterimMinimumTriangles))
              .first;
  }
  return known->second ? known->second.GetPointer() : leaf;
}

void vtkMultiresolutionPolyDataMapper::Internals::SubstituteBuiltLeaves(
  vtkMultiresolutionPolyDataMapper* self, Leaves& leaves, std::vector<char>& explained)
{
  explained.assign(leaves.size(), 0);
  std::vector<std::pair<uint64_t, unsigned int>> keys;
  const int hierarchy = self->BackgroundHierarchy;
  int pending = 0;
  for (size_t k = 0; k < leaves.size(); ++k)
  {
    vtkPolyData* leaf = leaves[k].first;
    const bool carries = vtkTOMFieldData::HasTOMArrays(leaf) &&
      (hierarchy != vtkHierarchyBuildQueue::MERGE_TREE ||
        vtkMergeTreeFieldData::HasMergeTreeArrays(leaf));
    // Empty and bad leaves are the read's to skip and report.
    if (carries || leaf->GetNumberOfPoints() < 1 || !this->FactsOf(leaf).Problem.empty())
    {
      continue;
    }
    const uint64_t key = this->KeyOf(leaf);
    keys.emplace_back(key, leaves[k].second);
    auto built = this->Built.find(key);
    if (built != this->Built.end())
    {
      leaves[k].first = built->second;
      continue;
    }
    if (vtkSmartPointer<vtkPolyData> stored =
          self->GetBuildQueue()->FindStored(key, leaf->GetNumberOfCells(), hierarchy))
    {
      this->Built[key] = stored; // built before (an earlier step or edit): no stand-in
      leaves[k].first = stored;
      continue;
    }
    explained[k] = 1;
    if (this->Failed.count(key) == 0)
    {
      self->GetBuildQueue()->Submit(key, leaf, hierarchy);
      ++pending;
      leaves[k].first = this->InterimOf(leaf, key, self->BackgroundInterimDivisions);
    }
  }
  // Builds of leaves this input no longer has are cancelled; results and
  // failures of such leaves are forgotten.
  std::vector<uint64_t> kept(keys.size());
  std::transform(keys.begin(), keys.end(), kept.begin(),
    [](const std::pair<uint64_t, unsigned int>& key) { return key.first; });
  std::sort(kept.begin(), kept.end());
  auto isKept = [&kept](uint64_t key) { return std::binary_search(kept.begin(), kept.end(), key); };
  if (this->Queue)
  {
    this->Queue->CancelAllExcept(kept);
  }
  for (auto it = this->Built.begin(); it != this->Built.end();)
  {
    it = isKept(it->first) ? std::next(it) : this->Built.erase(it);
  }
  for (auto it = this->Interims.begin(); it != this->Interims.end();)
  {
    it = isKept(it->first) && !this->Built.count(it->first) ? std::next(it) : this->Interims.erase(it);
  }
  for (auto it = this->Failed.begin(); it != this->Failed.end();)
  {
    it = isKept(*it) ? std::next(it) : this->Failed.erase(it);
  }
  this->CurrentKeys.swap(keys);
  this->PendingHierarchies = pending;
  if (pending > 0)
  {
    this->LastSwap = std::chrono::steady_clock::now();
  }
}
