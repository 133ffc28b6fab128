// SPDX-License-Identifier: BSD-3-Clause
#include "ViewDependentRefinementInternals.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace timecritical
{
using vdr::None;
using vdr::Pi;

//------------------------------------------------------------------------------
void ViewDependentRefinement::PrepareView()
{
  const RefinementView& v = this->View;
  this->EyeX = v.Eye[0];
  this->EyeY = v.Eye[1];
  this->EyeZ = v.Eye[2];
  double len = std::sqrt(v.Direction[0] * v.Direction[0] + v.Direction[1] * v.Direction[1] +
    v.Direction[2] * v.Direction[2]);
  if (!(len > 0.0))
  {
    len = 1.0;
  }
  this->DirX = v.Direction[0] / len;
  this->DirY = v.Direction[1] / len;
  this->DirZ = v.Direction[2] / len;
  len = std::sqrt(v.LightDirection[0] * v.LightDirection[0] +
    v.LightDirection[1] * v.LightDirection[1] + v.LightDirection[2] * v.LightDirection[2]);
  if (!(len > 0.0))
  {
    len = 1.0;
  }
  this->LightX = v.LightDirection[0] / len;
  this->LightY = v.LightDirection[1] / len;
  this->LightZ = v.LightDirection[2] / len;
  const double height = v.ViewportHeight > 0.0 ? v.ViewportHeight : 1.0;
  if (v.Parallel)
  {
    this->PixelsPerUnit = height / (2.0 * (v.ParallelScale > 0.0 ? v.ParallelScale : 1.0));
  }
  else
  {
    const double angle = std::min(179.0, std::max(1e-3, v.ViewAngle)) * Pi / 180.0;
    this->PixelsPerUnit = height / (2.0 * std::tan(0.5 * angle));
  }
  // Bounded so that an error times it stays finite: no priority is then
  // infinity over infinity (NaN would be unwanted while a smaller error,
  // projected as 0, is wanted).
  this->PixelsPerUnit = std::min(this->PixelsPerUnit, 1e30);
  // An eye (perspective) or direction (parallel) that is not finite gives
  // no view: every node counts as culled, so the front is the coarsest.
  this->BrokenView = v.Parallel
    ? !(std::isfinite(this->DirX) && std::isfinite(this->DirY) && std::isfinite(this->DirZ))
    : !(std::isfinite(this->EyeX) && std::isfinite(this->EyeY) && std::isfinite(this->EyeZ));
  // Normalized, so that a x + b y + c z + d is a distance to compare with
  // radii; planes without a usable normal are left out.
  this->PlaneCount = 0;
  for (int i = 0; i < std::min(6, v.NumberOfFrustumPlanes); ++i)
  {
    const double* plane = v.FrustumPlanes[i];
    const double norm =
      std::sqrt(plane[0] * plane[0] + plane[1] * plane[1] + plane[2] * plane[2]);
    if (norm > 0.0 && std::isfinite(norm) && std::isfinite(plane[3]))
    {
      for (int k = 0; k < 4; ++k)
      {
        this->Planes[k][this->PlaneCount] = plane[k] / norm;
      }
      ++this->PlaneCount;
    }
  }
  for (int i = this->PlaneCount; i < 8; ++i)
  {
    for (int k = 0; k < 4; ++k)
    {
      // Unused: 0 x + 0 y + 0 z + max >= -r, never outside.
      this->Planes[k][i] = k == 3 ? std::numeric_limits<double>::max() : 0.0;
    }
  }
  // Smallest threshold factor any node can get (SurelyUnwanted()).
  const double silhouette = this->SilhouetteRefinement ? this->SilhouetteFactor : 1.0;
  const double highlight = this->HighlightRefinement ? this->HighlightFactor : 1.0;
  this->MinimumFactor =
    std::min(std::min(1.0, silhouette * highlight), std::min(silhouette, highlight));
  this->UnwantedScale = this->MinimumFactor > 0.0 && this->PixelThreshold > 0.0
    ? this->PixelsPerUnit / (this->MinimumFactor * this->PixelThreshold * (1.0 - 1e-6))
    : 0.0;

  // Sleeping candidates (Candidate::WakeAt) stay so while the eye has moved
  // less than their radius since; the odometer sums the eye's moves (at least
  // the distance between any two of its positions). Anything else that their
  // decision depends on (but the frustum and the near plane, which can only
  // make them more unwanted) wakes them all when it changes.
  const double settings[] = { this->PixelThreshold, this->PixelsPerUnit,
    v.Parallel ? 1.0 : 0.0, this->BackFaceSimplification ? 1.0 : 0.0,
    this->SilhouetteRefinement ? this->SilhouetteFactor : -1.0,
    this->HighlightRefinement ? this->HighlightFactor : -1.0, this->LightX, this->LightY,
    this->LightZ };
  static_assert(sizeof(settings) == sizeof(this->SleepSettings), "one value per setting");
  const double mx = this->EyeX - this->LastEye[0], my = this->EyeY - this->LastEye[1],
               mz = this->EyeZ - this->LastEye[2];
  const double step = std::sqrt(mx * mx + my * my + mz * mz);
  if (std::memcmp(settings, this->SleepSettings, sizeof(settings)) != 0 || !std::isfinite(step) ||
    !std::isfinite(this->Odometer + step))
  {
    this->Odometer = 0.0; // (a non-finite eye would stop it for good)
    std::memcpy(this->SleepSettings, settings, sizeof(settings));
    for (uint32_t i = 0; i < this->SplitListSize; ++i)
    {
      this->SplitList[i].WakeAt = this->SplitList[i].FactorUntil = -1.0;
    }
  }
  else
  {
    this->Odometer += step;
  }
  this->LastEye[0] = this->EyeX;
  this->LastEye[1] = this->EyeY;
  this->LastEye[2] = this->EyeZ;
}

/// Where the eye sees a node from: its bounding sphere, the unit direction d
/// from the eye to its centre (the view direction when parallel), the sine
/// and cosine of the sphere's angular radius beta (0 when parallel), the
/// distance to the centre and the projected error in pixels.
struct ViewDependentRefinement::Sight
{
  double Cx, Cy, Cz;
  double Dx, Dy, Dz;
  double SinB = 0.0, CosB = 1.0;
  double Projected;
  double Dist = 0.0;
  double Radius;
};

/// What the normal-cone tests of a node found: its threshold factor, and the
/// angles the sleep margins are measured from.
struct ViewDependentRefinement::ConeTest
{
  double CosA;         // axis . d
  double CosTB, SinTB; // of theta + beta
  double CosPsi = 0.0, CosAngle = 0.0, SinAngle = 0.0; // of the highlight test
  bool MarginSilhouetteNeeded = false;
  bool MarginHighlightNeeded = false;
  double Factor = 1.0;
};

TIMECRITICAL_ALWAYS_INLINE bool ViewDependentRefinement::Outside(const Sight& sight) const
{
  // Wholly outside a plane. Written as two plain loops so that compilers
  // vectorize them.
  const double cx = sight.Cx, cy = sight.Cy, cz = sight.Cz;
  const double r = sight.Radius;
  double distance[8];
  for (int i = 0; i < 8; ++i)
  {
    distance[i] = this->Planes[0][i] * cx + this->Planes[1][i] * cy + this->Planes[2][i] * cz +
      this->Planes[3][i] + r;
  }
  int outside = 0;
  for (int i = 0; i < 8; ++i)
  {
    outside |= distance[i] < 0.0;
  }
  return outside != 0;
}

TIMECRITICAL_ALWAYS_INLINE bool ViewDependentRefinement::SeePerspective(
  const Node& node, Sight& sight, Sleep* sleep, double& key) const
{
  // True when that decides the key (no cone test needed).
  const double cx = sight.Cx, cy = sight.Cy, cz = sight.Cz;
  const double r = sight.Radius;
  double dx = cx - this->EyeX;
  double dy = cy - this->EyeY;
  double dz = cz - this->EyeZ;
  const double dist = std::sqrt(dx * dx + dy * dy + dz * dz);
  sight.Dist = dist;
  if (!(node.Error > 0.0f) && this->PixelThreshold > 0.0)
  {
    // Key 0, unwanted as if culled. (At tau = 0 key 0 is wanted, so the
    // culling tests below decide, as for its coarser nodes.)
    if (sleep != nullptr)
    {
      sleep->Wake = std::numeric_limits<double>::infinity(); // until the settings change
    }
    key = 0.0;
    return true;
  }
  // The node's surface is at least dist - r away, and nothing nearer than
  // the near plane is drawn: project from the larger of the two, so that a
  // node around the eye gets a large but finite priority (a huge tau still
  // gives the coarsest mesh).
  const double nearPlane = this->NearPlane();
  const double projected = node.Error * this->PixelsPerUnit / std::max(dist - r, nearPlane);
  if (dist <= r)
  {
    // Eye inside the bounding sphere: every view direction, so a silhouette
    // and a highlight, never back-facing.
    const double f = (this->SilhouetteRefinement ? this->SilhouetteFactor : 1.0) *
      (this->HighlightRefinement ? this->HighlightFactor : 1.0);
    key = f > 0.0 ? projected / f : std::numeric_limits<double>::infinity();
    return true;
  }
  // cos(beta) = sqrt(dist^2 - r^2) / dist: both roots at once (a shorter
  // chain of slow operations than the root of 1 - sin^2).
  const double tangent = std::sqrt(std::max(0.0, dx * dx + dy * dy + dz * dz - r * r));
  const double inverse = 1.0 / dist;
  dx *= inverse;
  dy *= inverse;
  dz *= inverse;
  sight.Dx = dx;
  sight.Dy = dy;
  sight.Dz = dz;
  sight.SinB = r * inverse;
  sight.CosB = tangent * inverse;
  sight.Projected = projected;
  return false;
}

TIMECRITICAL_ALWAYS_INLINE bool ViewDependentRefinement::FacesAway(
  const Node& node, const Sight& sight, ConeTest& cone, Sleep* sleep) const
{
  // Angles to the view directions of the sphere: theta (cone) + beta (sphere),
  // by their cosines and sines (sum formulas instead of acos/asin/cos).
  // Sets the silhouette factor unless every normal faces away from every view
  // direction (then true, with the sleep margin of that).
  const double c = node.Cos, s = node.Sin;
  const double cosA = node.Axis[0] * sight.Dx + node.Axis[1] * sight.Dy + node.Axis[2] * sight.Dz;
  const double cosTB = c * sight.CosB - s * sight.SinB;
  const double sinTB = s * sight.CosB + c * sight.SinB;
  cone.CosA = cosA;
  cone.CosTB = cosTB;
  cone.SinTB = sinTB;
  bool silhouette = true;
  if (cosTB > 0.0 && c > -1.0) // theta + beta below 90 degrees
  {
    if (this->BackFaceSimplification && cosA > sinTB)
    {
      if (sleep != nullptr && !this->View.Parallel)
      {
        // sin(90 - (theta + beta) - alpha), alpha = angle(axis, d)
        const double margin = cosTB * cosA - sinTB * std::sqrt(std::max(0.0, 1.0 - cosA * cosA));
        sleep->Wake = this->WakeRadius(sight.Dist, sight.Radius, margin, -1.0);
      }
      return true;
    }
    silhouette = std::abs(cosA) <= sinTB;
  }
  if (this->SilhouetteRefinement && silhouette)
  {
    cone.Factor *= this->SilhouetteFactor;
  }
  cone.MarginSilhouetteNeeded = this->SilhouetteRefinement && !silhouette;
  return false;
}

TIMECRITICAL_ALWAYS_INLINE void ViewDependentRefinement::TestHighlight(
  const Node& node, const Sight& sight, ConeTest& cone) const
{
  // Reflection vectors of the light over the cone lie within 2 theta of the
  // axis's reflection R = 2 (a.L) a - L; the highlight is seen when that
  // cone, widened by beta, holds the direction to the eye (-d). theta >= 90
  // degrees (c <= 0) or 2 theta + beta >= 180: every direction.
  const double c = node.Cos, s = node.Sin;
  bool highlight = c <= 0.0;
  if (!highlight)
  {
    const double c2 = 2.0 * c * c - 1.0, s2 = 2.0 * s * c; // 2 theta < 180 degrees
    cone.CosAngle = c2 * sight.CosB - s2 * sight.SinB;
    cone.SinAngle = s2 * sight.CosB + c2 * sight.SinB;
    highlight = cone.SinAngle <= 0.0 && cone.CosAngle < 0.0;
    if (!highlight)
    {
      const double aL = node.Axis[0] * this->LightX + node.Axis[1] * this->LightY +
        node.Axis[2] * this->LightZ;
      const double dL = this->LightX * sight.Dx + this->LightY * sight.Dy + this->LightZ * sight.Dz;
      cone.CosPsi = dL - 2.0 * aL * cone.CosA; // -R.d
      highlight = cone.CosPsi >= cone.CosAngle; // -R.d >= cos(2 theta + beta)
      cone.MarginHighlightNeeded = !highlight;
    }
  }
  if (highlight)
  {
    cone.Factor *= this->HighlightFactor;
  }
}

TIMECRITICAL_ALWAYS_INLINE void ViewDependentRefinement::MeasureSleep(
  const Node& node, const Sight& sight, const ConeTest& cone, double key, Sleep& sleep) const
{
  // The factor cannot drop while the eye keeps the node off silhouettes and
  // highlights it is not on: sin(|90 - alpha| - (theta + beta)) and
  // sin(psi - (2 theta + beta)) as margins.
  const double cosA = cone.CosA;
  const double sinA = std::sqrt(std::max(0.0, 1.0 - cosA * cosA));
  const double clamped = std::max(-1.0, std::min(1.0, cone.CosPsi));
  const double marginSilhouette =
    cone.MarginSilhouetteNeeded ? std::abs(cosA) * cone.CosTB - sinA * cone.SinTB : -1.0;
  const double marginHighlight = cone.MarginHighlightNeeded
    ? std::sqrt(1.0 - clamped * clamped) * cone.CosAngle - clamped * cone.SinAngle
    : -1.0;
  sleep.FactorRadius = this->WakeRadius(sight.Dist, sight.Radius, marginSilhouette, marginHighlight);
  sleep.Factor = static_cast<float>(cone.Factor);
  if (this->PixelThreshold > 0.0 && !this->IsWanted(static_cast<float>(key)))
  {
    // Unwanted while, besides, the projected error over this factor stays
    // below tau (the near plane only lowers it).
    const double reach = node.Error * this->PixelsPerUnit /
      (cone.Factor * this->PixelThreshold * (1.0 - 1e-6));
    sleep.Wake = std::max(0.0, std::min(sight.Dist - sight.Radius - reach, sleep.FactorRadius));
  }
}

// Not inlined: every priority comes from the same machine code (no
// context-dependent contraction), so a node gets the same key from the sweep's
// copy as from Nodes.
TIMECRITICAL_NOINLINE double ViewDependentRefinement::Evaluate(const Node& node, Sleep* sleep) const
{
  if (sleep != nullptr)
  {
    *sleep = Sleep{};
  }
  Sight sight;
  sight.Cx = node.Center[0];
  sight.Cy = node.Center[1];
  sight.Cz = node.Center[2];
  sight.Radius = node.Radius;
  if (this->BrokenView || (this->PlaneCount > 0 && this->Outside(sight)))
  {
    return -1.0;
  }
  if (this->View.Parallel)
  {
    sight.Dx = this->DirX;
    sight.Dy = this->DirY;
    sight.Dz = this->DirZ;
    sight.Projected = node.Error * this->PixelsPerUnit;
  }
  else
  {
    double key = 0.0;
    if (this->SeePerspective(node, sight, sleep, key))
    {
      return key;
    }
  }
  // Sleep (see WakeRadius()): the angular margins that keep the node culled,
  // or off silhouettes and highlights.
  ConeTest cone;
  if (this->FacesAway(node, sight, cone, sleep))
  {
    return -1.0; // every normal faces away from every view direction
  }
  if (this->HighlightRefinement)
  {
    this->TestHighlight(node, sight, cone);
  }
  const double key =
    cone.Factor > 0.0 ? sight.Projected / cone.Factor : std::numeric_limits<double>::infinity();
  if (sleep != nullptr && !this->View.Parallel && cone.Factor > 0.0)
  {
    this->MeasureSleep(node, sight, cone, key, *sleep);
  }
  return key;
}

double ViewDependentRefinement::WakeRadius(
  double dist, double r, double margin0, double margin1) const
{
  // An eye move by rho <= (dist - r) / 2 turns the direction to the centre by
  // at most asin(rho / dist) <= pi/3 rho / dist (asin is convex and rho / dist
  // <= 1/2, asin(1/2) = pi/6) and widens beta = asin(r / dist)
  // by at most rho r / (x sqrt(x^2 - r^2)), x = (dist + r) / 2 (mean value
  // theorem); the sum stays below an angular margin m while it stays below
  // sin m <= m. A relative 1e-6 covers the rounding of the decision itself
  // and of a float axis that is not quite unit.
  constexpr double Slack = 1e-6;
  const double x = 0.5 * (dist + r);
  const double k = Pi / (3.0 * dist) + r / (x * std::sqrt((dist - r) * (dist + 3.0 * r) * 0.25));
  double rho = 0.5 * (dist - r);
  for (const double m : { margin0, margin1 })
  {
    if (m >= 0.0) // < 0: no margin needed
    {
      rho = std::min(rho, (m - Slack) / k);
    }
  }
  return rho > 0.0 ? rho * (1.0 - Slack) : 0.0;
}
}
