// SPDX-License-Identifier: BSD-3-Clause
// A small owning scene for the policy tests: per-object arrays plus a
// PolicyInput view, and a simulated renderer (the "plant") whose frame time
// follows the cost model with a fixed part and some noise.
#ifndef timecritical_PolicyTestScene_h
#define timecritical_PolicyTestScene_h

#include "BudgetTestUtilities.h"
#include "ResolutionPolicy.h"

#include <random>
#include <vector>

namespace timecritical_test
{
struct PolicyScene
{
  RandomProblem Problem;
  std::vector<double> Previous;
  double FixedTime = 0.02;
  double Target = 0.1;

  PolicyScene(std::size_t n, double alpha, unsigned seed, double budgetFraction = 0.3)
    : Problem(MakeRandomProblem(n, alpha, seed, budgetFraction))
  {
    this->Target = this->FixedTime + this->Problem.Budget;
  }

  timecritical::PolicyInput Input(bool withPrevious = false, double lastFrameTime = -1.0) const
  {
    timecritical::PolicyInput in;
    in.Count = this->Problem.Weight.size();
    in.Weight = this->Problem.Weight.data();
    in.MaxTime = this->Problem.MaxTime.data();
    in.MinResolution = this->Problem.MinResolution.data();
    in.Pixels = this->Problem.Pixels.data();
    in.MaxTriangles = this->Problem.Triangles.data();
    in.Previous = withPrevious && !this->Previous.empty() ? this->Previous.data() : nullptr;
    in.Alpha = this->Problem.Alpha;
    in.TargetFrameTime = this->Target;
    in.FixedTime = this->FixedTime;
    if (lastFrameTime > 0.0)
    {
      in.LastFrameTime = lastFrameTime;
    }
    return in;
  }

  /// "Measured" time of rendering r: the cost model's prediction times (1 + noise).
  double Render(const std::vector<double>& r, std::mt19937_64& rng, double noise = 0.01) const
  {
    std::normal_distribution<double> n(0.0, noise);
    return (this->FixedTime + this->Problem.View().EffectiveCost(r.data())) * (1.0 + n(rng));
  }
};
}

#endif
