// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_FullResolutionPolicy_h
#define timecritical_FullResolutionPolicy_h

#include "ResolutionPolicy.h"

namespace timecritical
{
/// No detail elision: every object at full resolution (the "none" baseline).
class TIMECRITICALBUDGETCORE_EXPORT FullResolutionPolicy : public ResolutionPolicy
{
public:
  const char* GetName() const override { return "none"; }

protected:
  void Choose(const PolicyInput& input, double* r, PolicyResult& result) override;
};
}

#endif
