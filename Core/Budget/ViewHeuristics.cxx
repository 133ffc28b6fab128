// SPDX-License-Identifier: BSD-3-Clause
#include "ViewHeuristics.h"

#include <algorithm>
#include <cmath>

namespace timecritical
{
ViewHeuristics::Projection ViewHeuristics::Project(
  const double m[16], const double b[6], double width, double height)
{
  Projection p;
  // Outcodes per frustum plane: the box is culled when all 8 corners lie
  // outside the same plane (conservative, exact for the common cases).
  int outsideAll = 0x3f;
  bool behind = false;
  double minX = HUGE_VAL, minY = HUGE_VAL, maxX = -HUGE_VAL, maxY = -HUGE_VAL;
  for (int corner = 0; corner < 8; ++corner)
  {
    const double x = b[(corner & 1) ? 1 : 0];
    const double y = b[(corner & 2) ? 3 : 2];
    const double z = b[(corner & 4) ? 5 : 4];
    const double cx = m[0] * x + m[1] * y + m[2] * z + m[3];
    const double cy = m[4] * x + m[5] * y + m[6] * z + m[7];
    const double cz = m[8] * x + m[9] * y + m[10] * z + m[11];
    const double cw = m[12] * x + m[13] * y + m[14] * z + m[15];
    int code = 0;
    code |= cx < -cw ? 0x01 : 0;
    code |= cx > cw ? 0x02 : 0;
    code |= cy < -cw ? 0x04 : 0;
    code |= cy > cw ? 0x08 : 0;
    code |= cz < -cw ? 0x10 : 0;
    code |= cz > cw ? 0x20 : 0;
    outsideAll &= code;
    if (!(cw > 1e-12))
    {
      behind = true; // no meaningful projection for this corner
      continue;
    }
    const double sx = (cx / cw + 1.0) * 0.5 * width;
    const double sy = (cy / cw + 1.0) * 0.5 * height;
    minX = std::min(minX, sx);
    maxX = std::max(maxX, sx);
    minY = std::min(minY, sy);
    maxY = std::max(maxY, sy);
  }
  if (outsideAll != 0 || !(width > 0.0) || !(height > 0.0))
  {
    p.Culled = true;
    return p;
  }
  if (behind)
  {
    // The box surrounds the eye or crosses the eye plane: assume it fills the view.
    p.CrossesNear = true;
    p.MinX = p.MinY = 0.0;
    p.MaxX = width;
    p.MaxY = height;
    p.CenterX = 0.5 * width;
    p.CenterY = 0.5 * height;
    p.Pixels = width * height;
    return p;
  }
  p.CenterX = 0.5 * (minX + maxX);
  p.CenterY = 0.5 * (minY + maxY);
  p.MinX = std::clamp(minX, 0.0, width);
  p.MaxX = std::clamp(maxX, 0.0, width);
  p.MinY = std::clamp(minY, 0.0, height);
  p.MaxY = std::clamp(maxY, 0.0, height);
  p.Pixels = (p.MaxX - p.MinX) * (p.MaxY - p.MinY);
  return p;
}

double ViewHeuristics::Eccentricity(const Projection& p, double fx, double fy)
{
  const double dx = std::max({ p.MinX - fx, 0.0, fx - p.MaxX });
  const double dy = std::max({ p.MinY - fy, 0.0, fy - p.MaxY });
  return std::sqrt(dx * dx + dy * dy);
}

double ViewHeuristics::Velocity(double px, double py, double x, double y, double dt)
{
  if (!(dt > 0.0) || !std::isfinite(px) || !std::isfinite(py) || !std::isfinite(x) ||
    !std::isfinite(y))
  {
    return 0.0;
  }
  return std::hypot(x - px, y - py) / dt;
}
}
