// SPDX-License-Identifier: BSD-3-Clause
#include "FrameCostModel.h"

#include <algorithm>
#include <cmath>

namespace timecritical
{
namespace
{
/// Coefficients are times: anything negative or not finite is treated as 0.
double Sanitize(double value)
{
  return std::isfinite(value) && value > 0.0 ? value : 0.0;
}
}

FrameCostModel::FrameCostModel(const Coefficients& coefficients, PixelMode mode)
  : Mode(mode)
{
  this->SetCoefficients(coefficients);
}

void FrameCostModel::SetCoefficients(const Coefficients& c)
{
  const Coefficients& low = this->Minimum;
  this->Coeffs.Frame = std::max(low.Frame, Sanitize(c.Frame));
  this->Coeffs.DrawCall = std::max(low.DrawCall, Sanitize(c.DrawCall));
  this->Coeffs.Object = std::max(low.Object, Sanitize(c.Object));
  this->Coeffs.Triangle = std::max(low.Triangle, Sanitize(c.Triangle));
  this->Coeffs.Pixel = std::max(low.Pixel, Sanitize(c.Pixel));
  this->Coeffs.Margin = Sanitize(c.Margin);
}

void FrameCostModel::SetMinimumCoefficients(const Coefficients& minimum)
{
  this->Minimum.Frame = Sanitize(minimum.Frame);
  this->Minimum.DrawCall = Sanitize(minimum.DrawCall);
  this->Minimum.Object = Sanitize(minimum.Object);
  this->Minimum.Triangle = Sanitize(minimum.Triangle);
  this->Minimum.Pixel = Sanitize(minimum.Pixel);
  this->Minimum.Margin = 0.0;
  this->SetCoefficients(this->Coeffs);
}

FrameCostModel::Coefficients FrameCostModel::PhysicalMinimum()
{
  Coefficients c;
  c.Frame = 1e-5;
  c.DrawCall = 1e-7;
  c.Object = 0.0;
  c.Triangle = 1e-11;
  c.Pixel = 1e-12;
  return c;
}

double FrameCostModel::ObjectCost(double maxTriangles, double pixels, double r) const
{
  const double geometry = this->Coeffs.Triangle * r * maxTriangles;
  const double fill = this->Coeffs.Pixel * pixels;
  const double body = this->Mode == PixelMode::Overlapped ? std::max(geometry, fill) : geometry + fill;
  return this->Coeffs.Object + body;
}

double FrameCostModel::MaxTime(double maxTriangles) const
{
  return this->Coeffs.Triangle * std::max(0.0, maxTriangles);
}

double FrameCostModel::MinimumResolution(double maxTriangles, double pixels, double coarsest) const
{
  const double floor =
    std::min(1.0, std::max(TinyResolution, std::isfinite(coarsest) ? coarsest : 0.0));
  if (this->Mode == PixelMode::Additive)
  {
    return floor;
  }
  const double geometry = this->Coeffs.Triangle * maxTriangles;
  if (!(geometry > 0.0))
  {
    return 1.0; // triangles are free: nothing to gain by reducing
  }
  const double ratio = this->Coeffs.Pixel * std::max(0.0, pixels) / geometry;
  return std::min(1.0, std::max(floor, std::isfinite(ratio) ? ratio : 1.0));
}

double FrameCostModel::FixedTime(const FrameLoad& load, double totalPixels) const
{
  const Coefficients& c = this->Coeffs;
  double t = c.Frame + c.Margin + c.DrawCall * load.DrawCalls + c.Object * load.Objects +
    Sanitize(load.OtherTime);
  const double otherGeometry = c.Triangle * load.OtherTriangles;
  const double otherFill = c.Pixel * load.OtherPixels;
  if (this->Mode == PixelMode::Additive)
  {
    t += otherGeometry + otherFill + c.Pixel * totalPixels;
  }
  else
  {
    t += std::max(otherGeometry, otherFill);
  }
  return t;
}

void FrameCostModel::Evaluate(std::size_t n, const double* maxTriangles, const double* pixels,
  const double* coarsest, double* maxTime, double* minResolution) const
{
  for (std::size_t i = 0; i < n; ++i)
  {
    maxTime[i] = this->MaxTime(maxTriangles[i]);
    minResolution[i] =
      this->MinimumResolution(maxTriangles[i], pixels[i], coarsest ? coarsest[i] : 0.0);
  }
}

double FrameCostModel::PredictFrameTime(const FrameLoad& load, std::size_t n,
  const double* maxTriangles, const double* pixels, const double* r) const
{
  double totalPixels = 0.0;
  double objects = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    totalPixels += pixels[i];
    // ObjectCost() includes t_setup, which FixedTime() counts from load.Objects.
    objects += this->ObjectCost(maxTriangles[i], pixels[i], r[i]) - this->Coeffs.Object;
  }
  if (this->Mode == PixelMode::Additive)
  {
    objects -= this->Coeffs.Pixel * totalPixels; // counted once, in FixedTime()
  }
  return this->FixedTime(load, totalPixels) + objects;
}

void FrameCostModel::GetFeatures(
  const FrameLoad& load, double triangles, double pixels, double* x) const
{
  x[FeatureFrame] = 1.0;
  x[FeatureDrawCalls] = load.DrawCalls;
  x[FeatureObjects] = load.Objects;
  x[FeatureTriangles] = triangles + load.OtherTriangles;
  x[FeaturePixels] = pixels + load.OtherPixels;
}

void FrameCostModel::GetFeatureWeights(double* w) const
{
  w[FeatureFrame] = this->Coeffs.Frame;
  w[FeatureDrawCalls] = this->Coeffs.DrawCall;
  w[FeatureObjects] = this->Coeffs.Object;
  w[FeatureTriangles] = this->Coeffs.Triangle;
  w[FeaturePixels] = this->Coeffs.Pixel;
}

void FrameCostModel::SetFeatureWeights(const double* w)
{
  Coefficients c = this->Coeffs;
  c.Frame = w[FeatureFrame];
  c.DrawCall = w[FeatureDrawCalls];
  c.Object = w[FeatureObjects];
  c.Triangle = w[FeatureTriangles];
  c.Pixel = w[FeaturePixels];
  this->SetCoefficients(c);
}
}
