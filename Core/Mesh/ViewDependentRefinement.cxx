// SPDX-License-Identifier: BSD-3-Clause
#include "ViewDependentRefinementInternals.h"

#include <algorithm>
#include <cstring>

namespace timecritical
{
using vdr::None;

ViewDependentRefinement::ViewDependentRefinement() = default;
ViewDependentRefinement::~ViewDependentRefinement() = default;

//------------------------------------------------------------------------------
void ViewDependentRefinement::Reset()
{
  std::fill(this->Active.begin(), this->Active.end(), 0);
  std::fill(this->Holds.begin(), this->Holds.end(), 0);
  for (Links& l : this->Link)
  {
    l.ActiveChildren = 0;
    l.SplitPos = None;
    l.MergePos = None;
  }
  std::fill(this->DisplayPos.begin(), this->DisplayPos.end(), None);
  std::fill(this->Active.begin(), this->Active.begin() + this->B, 1);
  this->SplitListSize = 0;
  this->MergeListSize = 0;
  for (uint32_t w = 0; w < this->B; ++w)
  {
    this->RefreshSplitCandidate(w);
  }
  this->ActiveVertexCount = this->B;
  this->DisplayCount = 0;
  const uint32_t base = this->N > 0 ? this->BlockOffsets[this->B] : 0;
  for (uint32_t t = 0; t < base; ++t)
  {
    this->AddDisplay(t);
  }
  this->Statistics = RefinementStatistics{};
  this->ContinueUpdate = false;
  this->Statistics.DisplayVertices = this->ActiveVertexCount;
  this->Statistics.DisplayTriangles = this->DisplayCount;
}

void ViewDependentRefinement::SetView(const RefinementView& view)
{
  this->View = view;
}

//------------------------------------------------------------------------------
uint32_t ViewDependentRefinement::CopyTriangles(uint32_t* out, uint32_t capacity, uint32_t offset) const
{
  const uint32_t count = std::min(capacity, this->DisplayCount);
  const size_t ids = 3 * size_t(count);
  if (offset == 0)
  {
    std::memcpy(out, this->Display.data(), ids * sizeof(uint32_t));
  }
  else
  {
    for (size_t i = 0; i < ids; ++i)
    {
      out[i] = this->Display[i] + offset;
    }
  }
  return this->DisplayCount;
}
}
