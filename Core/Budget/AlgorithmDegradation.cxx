// SPDX-License-Identifier: BSD-3-Clause
#include "AlgorithmDegradation.h"

#include "ResolutionProblem.h"
#include "TupleProblem.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace timecritical
{
namespace
{
[[noreturn]] void Fail(const std::string& what)
{
  throw std::invalid_argument("AlgorithmDegradation: " + what);
}

double NonNegative(double value)
{
  return std::isfinite(value) && value > 0.0 ? value : 0.0;
}

double SampleCount(const AlgorithmDegradation::Accuracy& accuracy,
  const AlgorithmDegradation::ObjectInput& object)
{
  const double triangles = NonNegative(object.MaxTriangles);
  const double vertices =
    object.MaxVertices > 0.0 ? NonNegative(object.MaxVertices) : 0.5 * triangles;
  const double s =
    accuracy.Samples == AlgorithmDegradation::SampleKind::Triangles ? triangles : vertices;
  return std::max(1.0, s);
}
}

AlgorithmDegradation::AlgorithmDegradation(Family family)
  : Kind(family)
{
  for (std::size_t a = 0; a < RenderingAlgorithmCount; ++a)
  {
    this->Accuracies[a] = DefaultAccuracy(static_cast<RenderingAlgorithm>(a));
  }
}

std::size_t AlgorithmDegradation::Index(RenderingAlgorithm algorithm)
{
  const std::size_t a = static_cast<std::size_t>(algorithm);
  if (a >= RenderingAlgorithmCount)
  {
    Fail("unknown rendering algorithm " + std::to_string(a));
  }
  return a;
}

AlgorithmDegradation::Accuracy AlgorithmDegradation::DefaultAccuracy(RenderingAlgorithm algorithm)
{
  Accuracy accuracy;
  switch (algorithm)
  {
    case RenderingAlgorithm::PerFragmentLit:
      accuracy = { SampleKind::Vertices, 2.0, 0.25 };
      break;
    case RenderingAlgorithm::PerVertexLit:
      accuracy = { SampleKind::Vertices, 2.0, 0.5 };
      break;
    case RenderingAlgorithm::Flat:
      accuracy = { SampleKind::Triangles, 1.0, 0.5 };
      break;
    case RenderingAlgorithm::Unlit:
      accuracy = { SampleKind::Triangles, 1.0, 1.0 };
      break;
  }
  return accuracy;
}

void AlgorithmDegradation::SetAccuracy(RenderingAlgorithm algorithm, const Accuracy& accuracy)
{
  const std::size_t a = Index(algorithm);
  if (!(std::isfinite(accuracy.Exponent) && accuracy.Exponent > 0.0))
  {
    Fail(std::string("the exponent of ") + GetRenderingAlgorithmName(algorithm) + " = " +
      std::to_string(accuracy.Exponent) + " is not positive and finite");
  }
  if (!(accuracy.BaseError > 0.0 && accuracy.BaseError <= 1.0))
  {
    Fail(std::string("the base error of ") + GetRenderingAlgorithmName(algorithm) + " = " +
      std::to_string(accuracy.BaseError) + " is outside (0, 1]");
  }
  this->Accuracies[a] = accuracy;
}

const AlgorithmDegradation::Accuracy& AlgorithmDegradation::GetAccuracy(
  RenderingAlgorithm algorithm) const
{
  return this->Accuracies[Index(algorithm)];
}

void AlgorithmDegradation::SetMeasuredError(RenderingAlgorithm algorithm, double error)
{
  const std::size_t a = Index(algorithm);
  if (!(error >= 0.0 && error <= 1.0))
  {
    Fail(std::string("the measured error of ") + GetRenderingAlgorithmName(algorithm) + " = " +
      std::to_string(error) + " is outside [0, 1]");
  }
  this->Measured[a] = error;
  this->MeasuredSet[a] = true;
}

bool AlgorithmDegradation::HasMeasuredError(RenderingAlgorithm algorithm) const
{
  return this->MeasuredSet[Index(algorithm)];
}

void AlgorithmDegradation::SetGeometricAlpha(double alpha)
{
  if (!ResolutionProblem::IsValidAlpha(alpha))
  {
    Fail("the geometric alpha " + std::to_string(alpha) + " is not > -1, != 0 and finite");
  }
  this->GeometricAlpha = alpha;
}

void AlgorithmDegradation::SetBoxError(double error)
{
  if (!(error >= 0.0 && error <= 1.0))
  {
    Fail("the box error " + std::to_string(error) + " is outside [0, 1]");
  }
  this->BoxError = error;
}

double AlgorithmDegradation::FunkhouserAccuracy(
  RenderingAlgorithm algorithm, const ObjectInput& object, double r) const
{
  const Accuracy& accuracy = this->Accuracies[Index(algorithm)];
  const double samples = std::min(SampleCount(accuracy, object) * NonNegative(r),
    std::max(1.0, NonNegative(object.Pixels)));
  return 1.0 - accuracy.BaseError / std::pow(std::max(1.0, samples), accuracy.Exponent);
}

void AlgorithmDegradation::Evaluate(std::size_t n, const ObjectInput* objects,
  const RenderingAlgorithm* algorithms, std::size_t count, double* alpha, double* weight,
  double* offset, double* maxResolution, double* boxDegradation, double* dropDegradation) const
{
  if (count == 0)
  {
    Fail("the set of rendering algorithms is empty");
  }
  for (std::size_t a = 0; a < count; ++a)
  {
    const std::size_t k = Index(algorithms[a]);
    if (this->Kind == Family::Measured && !this->MeasuredSet[k])
    {
      Fail(std::string("no measured error for ") + GetRenderingAlgorithmName(algorithms[a]));
    }
    alpha[a] = this->Kind == Family::Measured ? this->GeometricAlpha : this->Accuracies[k].Exponent;
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    const ObjectInput& o = objects[i];
    const double size = NonNegative(o.Interest) * NonNegative(o.Pixels); // Size * Interest
    for (std::size_t a = 0; a < count; ++a)
    {
      const std::size_t k = i * count + a;
      const std::size_t at = Index(algorithms[a]);
      if (this->Kind == Family::Measured)
      {
        weight[k] = NonNegative(o.GeometricWeight);
        offset[k] = size * this->Measured[at];
        maxResolution[k] = 1.0;
        continue;
      }
      const Accuracy& accuracy = this->Accuracies[at];
      const double s = SampleCount(accuracy, o);
      weight[k] = accuracy.Exponent * size * accuracy.BaseError / std::pow(s, accuracy.Exponent);
      offset[k] = 0.0;
      // Samples never more than the covered pixels: no gain beyond Npix / S.
      maxResolution[k] = std::min(1.0,
        std::max(TupleProblem::TinyResolution, NonNegative(o.Pixels) / s));
    }
    if (boxDegradation)
    {
      boxDegradation[i] = size * this->BoxError;
    }
    if (dropDegradation)
    {
      dropDegradation[i] = size;
    }
  }
}
}
