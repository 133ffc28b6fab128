// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_StaticThresholdPolicy_h
#define timecritical_StaticThresholdPolicy_h

#include "ResolutionPolicy.h"

namespace timecritical
{
/**
 * Static detail elision (Funkhouser & Séquin's "Static", Gobbetti & Bouvier
 * section 2.1): a fixed pixels-per-triangle threshold k, so that an object
 * keeps about Npix / k triangles: r_i = clamp(Npix_i / (k Nmaxtri_i), rmin_i, 1).
 * Not adaptive: the frame time follows the scene.
 */
class TIMECRITICALBUDGETCORE_EXPORT StaticThresholdPolicy : public ResolutionPolicy
{
public:
  const char* GetName() const override { return "static"; }

  /// k: projected pixels per triangle (> 0).
  void SetPixelsPerTriangle(double k);
  double GetPixelsPerTriangle() const { return this->PixelsPerTriangle; }

  /// The threshold rule, shared with FeedbackPolicy. Objects without pixel or
  /// triangle data get 1.
  static void Apply(const PolicyInput& input, double pixelsPerTriangle, double* r);

protected:
  void Choose(const PolicyInput& input, double* r, PolicyResult& result) override;

private:
  double PixelsPerTriangle = 8.0;
};
}

#endif
