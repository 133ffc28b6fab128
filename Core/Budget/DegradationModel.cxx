// SPDX-License-Identifier: BSD-3-Clause
#include "DegradationModel.h"

#include "ResolutionProblem.h"

#include <algorithm>
#include <cmath>

namespace timecritical
{
namespace
{
/// Negative, NaN or infinite measurements count as 0 (an object the renderer
/// could not measure gets no weight rather than poisoning the optimization).
double NonNegative(double value)
{
  return std::isfinite(value) && value > 0.0 ? value : 0.0;
}

constexpr double Pi = 3.14159265358979323846;
}

DegradationModel::DegradationModel(const Config& config)
  : Settings(config)
{
}

DegradationModel::Config DegradationModel::MakeConfig(Family family)
{
  Config config;
  config.WeightFamily = family;
  if (family == Family::YangGuKang)
  {
    // Yang et al. weigh coverage, focus (distance to the screen centre) and
    // semantics; they have no velocity term.
    config.Velocity = VelocityModel::None;
    config.Eccentricity = EccentricityModel::Linear;
  }
  return config;
}

double DegradationModel::GetAlpha(Family family)
{
  switch (family)
  {
    case Family::Hitchner:
      return 1.0;
    case Family::Funkhouser:
      return 2.0;
    case Family::GobbettiBouvier1999:
    case Family::YangGuKang:
      return -0.5;
  }
  return 1.0;
}

double DegradationModel::GetAlpha() const
{
  return GetAlpha(this->Settings.WeightFamily);
}

double DegradationModel::PixelsPerDegree(const DisplayParameters& d)
{
  const double perUnit = std::min(d.ResolutionX / d.SizeX, d.ResolutionY / d.SizeY);
  const double p = 2.0 * d.ViewingDistance * std::tan(0.5 * Pi / 180.0) * perUnit;
  return std::isfinite(p) && p > 0.0 ? p : 1.0;
}

double DegradationModel::PixelsToDegrees(double pixels) const
{
  return pixels / PixelsPerDegree(this->Display);
}

double DegradationModel::ReddyVelocityFactor(double v)
{
  if (!(v > 0.825)) // also NaN
  {
    return 1.0;
  }
  return -0.463 * std::log10(v) + 0.9615;
}

double DegradationModel::ReddyEccentricityFactor(double e)
{
  if (!(e > 5.79))
  {
    return 1.0;
  }
  const double s = 1.0 + 0.3 * e;
  return 7.49 / (s * s);
}

double DegradationModel::VelocityFactor(double v) const
{
  double w = 1.0;
  if (this->Settings.Velocity == VelocityModel::Reddy)
  {
    w = ReddyVelocityFactor(NonNegative(v));
  }
  return std::min(1.0, std::max(this->Settings.MinimumFactor, w));
}

double DegradationModel::EccentricityFactor(double e) const
{
  e = NonNegative(e);
  double w = 1.0;
  switch (this->Settings.Eccentricity)
  {
    case EccentricityModel::None:
      break;
    case EccentricityModel::Reddy:
      w = ReddyEccentricityFactor(e);
      break;
    case EccentricityModel::Linear:
      w = this->Settings.LinearFalloffDegrees > 0.0
        ? 1.0 - e / this->Settings.LinearFalloffDegrees
        : 1.0;
      break;
  }
  return std::min(1.0, std::max(this->Settings.MinimumFactor, w));
}

double DegradationModel::InterestWeight(const ObjectView& view) const
{
  return this->VelocityFactor(view.VelocityDegrees) *
    this->EccentricityFactor(view.EccentricityDegrees) * NonNegative(view.Importance);
}

double DegradationModel::ResolutionWeight(const ObjectView& view) const
{
  const double pixels = NonNegative(view.Pixels);
  const double triangles = std::max(1.0, NonNegative(view.MaxTriangles));
  switch (this->Settings.WeightFamily)
  {
    case Family::Hitchner:
      return pixels / triangles;
    case Family::Funkhouser:
      return pixels / (triangles * triangles);
    case Family::GobbettiBouvier1999:
      return pixels * std::sqrt(triangles);
    case Family::YangGuKang:
    {
      const double vertices =
        view.MaxVertices > 0.0 ? NonNegative(view.MaxVertices) : 0.5 * triangles;
      return 0.5 * pixels * std::sqrt(std::max(1.0, vertices));
    }
  }
  return 0.0;
}

double DegradationModel::Weight(const ObjectView& view) const
{
  return this->InterestWeight(view) * this->ResolutionWeight(view);
}

void DegradationModel::Evaluate(std::size_t n, const ObjectView* views, double* weights) const
{
  for (std::size_t i = 0; i < n; ++i)
  {
    weights[i] = this->Weight(views[i]);
  }
}

double DegradationModel::Degradation(const ObjectView& view, double r) const
{
  return ResolutionProblem::Term(this->Weight(view), this->GetAlpha(), r);
}
}
