// SPDX-License-Identifier: BSD-3-Clause
#include "AlgorithmCostModel.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace timecritical
{
namespace
{
void CheckCoefficient(double value, const char* name, RenderingAlgorithm algorithm)
{
  if (!std::isfinite(value) || value < 0.0)
  {
    throw std::invalid_argument(std::string("AlgorithmCostModel: ") + name + " coefficient of " +
      GetRenderingAlgorithmName(algorithm) + " = " + std::to_string(value) +
      " is negative or not finite");
  }
}

double NonNegative(double value)
{
  return std::isfinite(value) && value > 0.0 ? value : 0.0;
}
}

AlgorithmCostModel::AlgorithmCostModel(const FrameCostModel& model)
  : Frame(model.GetCoefficients().Frame)
  , Mode(model.GetPixelMode())
{
  const FrameCostModel::Coefficients& c = model.GetCoefficients();
  Coefficients today;
  today.DrawCall = c.DrawCall;
  today.Triangle = c.Triangle;
  today.Pixel = c.Pixel;
  this->SetAlgorithm(RenderingAlgorithm::PerFragmentLit, today);
}

void AlgorithmCostModel::SetAlgorithm(RenderingAlgorithm algorithm, const Coefficients& c)
{
  if (static_cast<std::size_t>(algorithm) >= RenderingAlgorithmCount)
  {
    throw std::invalid_argument("AlgorithmCostModel: unknown rendering algorithm " +
      std::to_string(static_cast<int>(algorithm)));
  }
  CheckCoefficient(c.DrawCall, "draw-call", algorithm);
  CheckCoefficient(c.Triangle, "triangle", algorithm);
  CheckCoefficient(c.Vertex, "vertex", algorithm);
  CheckCoefficient(c.Pixel, "pixel", algorithm);
  const int at = this->IndexOf(algorithm);
  const std::size_t index = at >= 0 ? static_cast<std::size_t>(at) : this->Count++;
  this->Algorithms[index] = algorithm;
  this->Coeffs[index] = c;
}

void AlgorithmCostModel::RemoveAlgorithm(RenderingAlgorithm algorithm)
{
  const int at = this->IndexOf(algorithm);
  if (at < 0)
  {
    return;
  }
  for (std::size_t k = static_cast<std::size_t>(at); k + 1 < this->Count; ++k)
  {
    this->Algorithms[k] = this->Algorithms[k + 1];
    this->Coeffs[k] = this->Coeffs[k + 1];
  }
  --this->Count;
}

int AlgorithmCostModel::IndexOf(RenderingAlgorithm algorithm) const
{
  for (std::size_t k = 0; k < this->Count; ++k)
  {
    if (this->Algorithms[k] == algorithm)
    {
      return static_cast<int>(k);
    }
  }
  return -1;
}

void AlgorithmCostModel::SetFrameTime(double seconds)
{
  if (!std::isfinite(seconds) || seconds < 0.0)
  {
    throw std::invalid_argument(
      "AlgorithmCostModel: frame time " + std::to_string(seconds) + " is negative or not finite");
  }
  this->Frame = seconds;
}

double AlgorithmCostModel::TupleCost(
  std::size_t index, double triangles, double vertices, double pixels) const
{
  const Coefficients& c = this->Coeffs[index];
  const double geometry =
    c.Triangle * NonNegative(triangles) + c.Vertex * NonNegative(vertices);
  const double fill = c.Pixel * NonNegative(pixels);
  return this->Mode == FrameCostModel::PixelMode::Overlapped ? std::max(geometry, fill)
                                                             : geometry + fill;
}

void AlgorithmCostModel::Evaluate(std::size_t n, const double* maxTriangles,
  const double* maxVertices, const double* pixels, const double* coarsest, double* maxTime,
  double* fixedCost, double* minResolution) const
{
  if (this->Count == 0 && n > 0)
  {
    throw std::invalid_argument("AlgorithmCostModel: the set of rendering algorithms is empty");
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    const double triangles = NonNegative(maxTriangles[i]);
    const double vertices = maxVertices ? NonNegative(maxVertices[i]) : 0.5 * triangles;
    const double floorValue = coarsest && std::isfinite(coarsest[i]) ? coarsest[i] : 0.0;
    const double floor = std::min(1.0, std::max(FrameCostModel::TinyResolution, floorValue));
    for (std::size_t a = 0; a < this->Count; ++a)
    {
      const Coefficients& c = this->Coeffs[a];
      const std::size_t k = i * this->Count + a;
      const double t = c.Triangle * triangles + c.Vertex * vertices;
      const double fill = c.Pixel * NonNegative(pixels[i]);
      maxTime[k] = t;
      if (this->Mode == FrameCostModel::PixelMode::Additive)
      {
        fixedCost[k] = fill;
        minResolution[k] = floor;
      }
      else if (fill >= t)
      {
        // Fill-bound even in full (or triangles free): the fill sets the
        // cost, which no resolution lowers (eq. 3 clamped at 1).
        fixedCost[k] = fill - t;
        minResolution[k] = 1.0;
      }
      else
      {
        fixedCost[k] = 0.0;
        minResolution[k] = std::max(floor, fill / t); // eq. 3
      }
    }
  }
}

double AlgorithmCostModel::DrawCallTime(double drawCallsPerAlgorithm) const
{
  double t = this->Frame;
  for (std::size_t a = 0; a < this->Count; ++a)
  {
    t += this->Coeffs[a].DrawCall * NonNegative(drawCallsPerAlgorithm);
  }
  return t;
}

void AlgorithmCostModel::GetFeatures(const double* drawCalls, const double* triangles,
  const double* vertices, const double* pixels, double* x) const
{
  x[0] = 1.0;
  for (std::size_t a = 0; a < this->Count; ++a)
  {
    double* xa = x + 1 + FeaturesPerAlgorithm * a;
    xa[0] = drawCalls[a];
    xa[1] = triangles[a];
    xa[2] = vertices[a];
    xa[3] = pixels[a];
  }
}

void AlgorithmCostModel::GetFeatureWeights(double* w) const
{
  w[0] = this->Frame;
  for (std::size_t a = 0; a < this->Count; ++a)
  {
    double* wa = w + 1 + FeaturesPerAlgorithm * a;
    wa[0] = this->Coeffs[a].DrawCall;
    wa[1] = this->Coeffs[a].Triangle;
    wa[2] = this->Coeffs[a].Vertex;
    wa[3] = this->Coeffs[a].Pixel;
  }
}

void AlgorithmCostModel::SetFeatureWeights(const double* w)
{
  this->Frame = NonNegative(w[0]);
  for (std::size_t a = 0; a < this->Count; ++a)
  {
    const double* wa = w + 1 + FeaturesPerAlgorithm * a;
    this->Coeffs[a].DrawCall = NonNegative(wa[0]);
    this->Coeffs[a].Triangle = NonNegative(wa[1]);
    this->Coeffs[a].Vertex = NonNegative(wa[2]);
    this->Coeffs[a].Pixel = NonNegative(wa[3]);
  }
}
}
