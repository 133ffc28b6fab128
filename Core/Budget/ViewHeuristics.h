// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_ViewHeuristics_h
#define timecritical_ViewHeuristics_h

#include "TimeCriticalBudgetCoreExport.h"

namespace timecritical
{
/**
 * Per-object measurements from the camera that the degradation and cost
 * models need (Gobbetti & Bouvier section 4; Funkhouser & Séquin's
 * "size", "focus" and "motion blur" factors): frustum culling, projected
 * pixel coverage, apparent velocity and eccentricity, all from an object's
 * axis-aligned bounding box, so that they cost O(1) per object.
 *
 * The matrix maps the box's coordinates to clip space (projection x view x
 * model, row-major, column vectors: clip = M (x y z 1)^T, VTK's convention
 * with z_ndc in [-1, 1]).
 */
class TIMECRITICALBUDGETCORE_EXPORT ViewHeuristics
{
public:
  struct Projection
  {
    bool Culled = false;       ///< entirely outside one frustum plane
    bool CrossesNear = false;  ///< part of the box is behind the eye: taken to cover the viewport
    double Pixels = 0.0;       ///< area of the projected box's screen rectangle, clipped to the viewport
    double MinX = 0.0, MinY = 0.0, MaxX = 0.0, MaxY = 0.0; ///< that rectangle (pixels, clipped)
    double CenterX = 0.0, CenterY = 0.0; ///< projected box centre (pixels, not clipped)
  };

  /// Viewport size in pixels (> 0).
  static Projection Project(const double matrix[16], const double bounds[6], double width,
    double height);

  /// Distance in pixels from the focus point to the projected rectangle (0 inside it).
  static double Eccentricity(const Projection& projection, double focusX, double focusY);

  /// Screen speed (pixels per second) of the projected centre between two frames dt apart.
  static double Velocity(double previousX, double previousY, double x, double y, double dt);
};
}

#endif
