// SPDX-License-Identifier: BSD-3-Clause
// Tests of ActiveSetOptimizer: KKT conditions for every degradation family,
// agreement with the bisection reference, feasibility and monotone objective
// at every stop, the special cases of section 5.3.1, warm starts, and no
// allocation in steady state.
#include "AllocationCounter.h"
#include "BudgetTestUtilities.h"

#include "ActiveSetOptimizer.h"
#include "ReferenceResolutionSolver.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace
{
using timecritical::ActiveSetOptimizer;
using timecritical::ReferenceResolutionSolver;
using timecritical::ResolutionProblem;
using timecritical_test::CheckKKT;
using timecritical_test::MakeRandomProblem;
using timecritical_test::NextFrame;
using timecritical_test::RandomProblem;
using Status = ActiveSetOptimizer::Status;

const double Alphas[] = { 1.0, 2.0, -0.5, 0.5, -0.9, 3.7 };

ActiveSetOptimizer::Options Unlimited()
{
  ActiveSetOptimizer::Options options;
  options.TimeLimit = 10.0;
  return options;
}

ActiveSetOptimizer::Options PaperMethod()
{
  ActiveSetOptimizer::Options options = Unlimited();
  options.ProjectedSteps = false;
  options.BlockRelease = false;
  return options;
}

double RelativeGap(double f, double reference)
{
  return (f - reference) / std::max(1e-300, std::abs(reference));
}

/// Solve, then check feasibility, KKT (independently) and the reference.
void ExpectOptimal(const RandomProblem& problem, const ActiveSetOptimizer::Options& options,
  bool warm, std::vector<double> r, const char* what)
{
  SCOPED_TRACE(what);
  const ResolutionProblem view = problem.View();
  ActiveSetOptimizer optimizer(options);
  const ActiveSetOptimizer::Result result = optimizer.Solve(view, r.data(), warm);
  ASSERT_EQ(result.State, Status::Optimal) << ActiveSetOptimizer::GetStatusName(result.State);
  EXPECT_TRUE(result.Converged);
  EXPECT_LE(view.Cost(r.data()), view.Budget);
  EXPECT_NEAR(result.Objective, view.Objective(r.data()), 1e-9 * std::abs(result.Objective));
  EXPECT_LE(result.KKTResidual, 1e-8);
  const auto kkt = CheckKKT(view, r.data());
  EXPECT_LE(kkt.Worst(), 1e-7) << "free " << kkt.FreeDeviation << " bound " << kkt.BoundViolation
                               << " compl " << kkt.Complementarity << " primal "
                               << kkt.PrimalViolation;
  EXPECT_NEAR(result.Multiplier, kkt.Lambda, 1e-6 * kkt.Lambda);
  std::vector<double> reference(problem.Weight.size());
  const auto ref = ReferenceResolutionSolver::Solve(view, reference.data());
  EXPECT_LE(std::abs(RelativeGap(result.Objective, ref.Objective)), 1e-6);
}

TEST(ActiveSetOptimizer, KKTAndReferenceForEveryFamily)
{
  for (double alpha : Alphas)
  {
    for (unsigned seed = 1; seed <= 4; ++seed)
    {
      for (double fraction : { 0.02, 0.3, 0.9 })
      {
        RandomProblem p = MakeRandomProblem(300, alpha, seed, fraction);
        const std::string what = "alpha " + std::to_string(alpha) + " seed " +
          std::to_string(seed) + " fraction " + std::to_string(fraction);
        std::vector<double> r(p.Weight.size(), std::numeric_limits<double>::quiet_NaN());
        ExpectOptimal(p, Unlimited(), false, r, (what + " cold").c_str());
        // Warm from an unrelated point (full resolution: needs the beta reduction).
        ExpectOptimal(p, Unlimited(), true, std::vector<double>(r.size(), 1.0),
          (what + " warm from 1").c_str());
        ExpectOptimal(p, PaperMethod(), false, r, (what + " paper").c_str());
      }
    }
  }
}

TEST(ActiveSetOptimizer, PaperMethodAndAcceleratedAgree)
{
  for (double alpha : Alphas)
  {
    RandomProblem p = MakeRandomProblem(500, alpha, 7);
    const ResolutionProblem view = p.View();
    std::vector<double> a(p.Weight.size()), b(p.Weight.size());
    ActiveSetOptimizer fast(Unlimited()), paper(PaperMethod());
    const auto ra = fast.Solve(view, a.data(), false);
    const auto rb = paper.Solve(view, b.data(), false);
    ASSERT_EQ(ra.State, Status::Optimal);
    ASSERT_EQ(rb.State, Status::Optimal);
    EXPECT_LE(std::abs(RelativeGap(ra.Objective, rb.Objective)), 1e-9);
    for (std::size_t i = 0; i < a.size(); ++i)
    {
      EXPECT_NEAR(a[i], b[i], 1e-7) << i;
    }
    // The acceleration is the point: far fewer O(n) passes.
    EXPECT_LT(ra.Steps * 10, rb.Steps) << "alpha " << alpha;
  }
}

TEST(ActiveSetOptimizer, FeasibleAndMonotoneAtEveryStop)
{
  for (double alpha : { 1.0, 2.0, -0.5 })
  {
    for (int mode = 0; mode < 4; ++mode)
    {
      const bool paper = mode & 1;
      const bool warm = mode & 2;
      // Small enough for the paper's method (one bound per iteration) to finish.
      RandomProblem p = MakeRandomProblem(150, alpha, 11);
      const ResolutionProblem view = p.View();
      std::vector<double> start(p.Weight.size(), 1.0); // warm from over budget
      double previous = std::numeric_limits<double>::infinity();
      double initial = 0.0;
      bool reachedOptimum = false;
      for (long limit = 0; limit <= 1000 && !reachedOptimum; ++limit)
      {
        for (int kind = 0; kind < 2; ++kind) // stop by steps, then by iterations
        {
          ActiveSetOptimizer::Options options = paper ? PaperMethod() : Unlimited();
          if (kind == 0)
          {
            options.MaxSteps = limit;
          }
          else
          {
            options.MaxIterations = static_cast<int>(limit);
          }
          ActiveSetOptimizer optimizer(options);
          std::vector<double> r = start;
          const auto result = optimizer.Solve(view, r.data(), warm);
          SCOPED_TRACE("alpha " + std::to_string(alpha) + " mode " + std::to_string(mode) +
            " limit " + std::to_string(limit) + " kind " + std::to_string(kind));
          ASSERT_LE(view.Cost(r.data()), view.Budget);
          for (std::size_t i = 0; i < r.size(); ++i)
          {
            ASSERT_GE(r[i], p.MinResolution[i]);
            ASSERT_LE(r[i], 1.0);
          }
          const double f = view.Objective(r.data());
          EXPECT_LE(f, result.InitialObjective + 1e-12 * std::abs(f));
          if (limit == 0)
          {
            initial = result.InitialObjective;
          }
          EXPECT_EQ(result.InitialObjective, initial);
          if (kind == 0)
          {
            // More steps never make the answer worse.
            EXPECT_LE(f, previous + 1e-12 * std::abs(f));
            previous = f;
            reachedOptimum = result.State == Status::Optimal;
          }
        }
      }
      EXPECT_TRUE(reachedOptimum);
    }
  }
}

TEST(ActiveSetOptimizer, HonoursTinyTimeLimits)
{
  RandomProblem p = MakeRandomProblem(100000, 1.0, 3);
  const ResolutionProblem view = p.View();
  std::vector<double> r(p.Weight.size());
  const long fullSteps = ActiveSetOptimizer(Unlimited()).Solve(view, r.data(), false).Steps;
  ASSERT_GE(fullSteps, 1);
  for (double limit : { 0.0, 1e-9, 1e-6, 1e-4, 1e-3 })
  {
    ActiveSetOptimizer::Options options;
    options.TimeLimit = limit;
    options.ClockCheckWork = 4096;
    ActiveSetOptimizer optimizer(options);
    const auto result = optimizer.Solve(view, r.data(), false);
    SCOPED_TRACE("limit " + std::to_string(limit));
    EXPECT_TRUE(result.State == Status::TimeLimit || result.State == Status::Optimal)
      << ActiveSetOptimizer::GetStatusName(result.State);
    EXPECT_LE(view.Cost(r.data()), view.Budget);
    EXPECT_LE(result.Objective, result.InitialObjective);
    // Counted in work, not seconds (a loaded machine stretches any time): a
    // stop at the limit leaves the solve unfinished; a limit of 0, or of 1 ns,
    // which the first clock check (after 4096 object visits) finds expired,
    // stops within the first O(n) pass. (Preprocessing, one pow() per
    // object, is not interruptible.)
    if (result.State == Status::TimeLimit)
    {
      EXPECT_LT(result.Steps, fullSteps);
    }
    if (limit < 1e-6)
    {
      EXPECT_EQ(result.State, Status::TimeLimit);
      EXPECT_EQ(result.Steps, 0);
    }
  }
}

TEST(ActiveSetOptimizer, InfeasibleReturnsMinimumResolutions)
{
  RandomProblem p = MakeRandomProblem(50, 1.0, 5);
  p.Budget = 0.5 * p.CostAtMin();
  std::vector<double> r(p.Weight.size(), 0.7);
  ActiveSetOptimizer optimizer(Unlimited());
  const auto result = optimizer.Solve(p.View(), r.data(), true);
  EXPECT_EQ(result.State, Status::Infeasible);
  EXPECT_TRUE(result.Infeasible);
  EXPECT_FALSE(result.Converged);
  for (std::size_t i = 0; i < r.size(); ++i)
  {
    EXPECT_EQ(r[i], p.MinResolution[i]);
  }
  EXPECT_DOUBLE_EQ(result.Cost, p.CostAtMin());
  // NaN and negative budgets are infeasible too.
  for (double budget : { std::numeric_limits<double>::quiet_NaN(), -1.0 })
  {
    p.Budget = budget;
    EXPECT_EQ(optimizer.Solve(p.View(), r.data(), false).State, Status::Infeasible);
  }
}

TEST(ActiveSetOptimizer, UnconstrainedReturnsFullResolution)
{
  RandomProblem p = MakeRandomProblem(50, 2.0, 5);
  p.Budget = p.CostAtFull();
  std::vector<double> r(p.Weight.size(), 0.1);
  ActiveSetOptimizer optimizer(Unlimited());
  const auto result = optimizer.Solve(p.View(), r.data(), true);
  EXPECT_EQ(result.State, Status::Unconstrained);
  EXPECT_TRUE(result.Converged);
  EXPECT_EQ(result.Multiplier, 0.0);
  for (double x : r)
  {
    EXPECT_EQ(x, 1.0);
  }
}

TEST(ActiveSetOptimizer, EmptyAndSingleObject)
{
  ActiveSetOptimizer optimizer(Unlimited());
  ResolutionProblem empty;
  EXPECT_EQ(optimizer.Solve(empty, nullptr, false).State, Status::Empty);

  for (double alpha : Alphas)
  {
    const double c = 3.0, t = 0.02, lo = 0.05;
    ResolutionProblem one;
    one.Count = 1;
    one.Weight = &c;
    one.MaxTime = &t;
    one.MinResolution = &lo;
    one.Alpha = alpha;
    one.Budget = 0.008; // r = 0.4 exactly on the budget
    double r = std::numeric_limits<double>::quiet_NaN();
    const auto result = optimizer.Solve(one, &r, true);
    EXPECT_EQ(result.State, Status::Optimal);
    EXPECT_NEAR(r, 0.4, 1e-9);
    EXPECT_LE(t * r, one.Budget);
    EXPECT_NEAR(result.Multiplier, c * std::pow(0.4, -(alpha + 1.0)) / t, 1e-6 * result.Multiplier);
  }
}

TEST(ActiveSetOptimizer, LargeProblem)
{
  for (double alpha : { 1.0, -0.5 })
  {
    RandomProblem p = MakeRandomProblem(100000, alpha, 21);
    std::vector<double> r(p.Weight.size());
    ExpectOptimal(p, Unlimited(), false, r, "100000 objects");
  }
}

TEST(ActiveSetOptimizer, WarmStartReducesWork)
{
  long warmSteps = 0, coldSteps = 0;
  double warmSeconds = 0.0, coldSeconds = 0.0;
  for (unsigned seed = 1; seed <= 10; ++seed)
  {
    RandomProblem p = MakeRandomProblem(529, 1.0, seed);
    ActiveSetOptimizer optimizer(Unlimited());
    std::vector<double> previous(p.Weight.size());
    ASSERT_EQ(optimizer.Solve(p.View(), previous.data(), false).State, Status::Optimal);
    timecritical_test::Perturb(p, 0.05, seed + 100); // next frame
    std::vector<double> cold(previous.size()), warm = previous;
    const auto c = optimizer.Solve(p.View(), cold.data(), false);
    const auto w = optimizer.Solve(p.View(), warm.data(), true);
    ASSERT_EQ(c.State, Status::Optimal);
    ASSERT_EQ(w.State, Status::Optimal);
    EXPECT_LE(std::abs(RelativeGap(w.Objective, c.Objective)), 1e-9);
    // The warm start begins much closer to the optimum.
    EXPECT_LT(w.InitialObjective - w.Objective, 0.1 * (c.InitialObjective - c.Objective));
    warmSteps += w.Steps;
    coldSteps += c.Steps;
    warmSeconds += w.Seconds;
    coldSeconds += c.Seconds;
  }
  EXPECT_LT(warmSteps, coldSteps);
  RecordProperty("WarmSteps", std::to_string(warmSteps));
  RecordProperty("ColdSteps", std::to_string(coldSteps));
  std::cout << "steps warm " << warmSteps << " cold " << coldSteps << ", seconds warm "
            << warmSeconds << " cold " << coldSeconds << "\n";
}

TEST(ActiveSetOptimizer, WarmFromTheOptimumReturnsItInOneStep)
{
  // The previous frame's answer to the same problem: one pass finds the
  // multiplier in the interval around the start's, and the answer is that
  // point again.
  for (double alpha : { 1.0, 2.0, -0.5 })
  {
    RandomProblem p = MakeRandomProblem(20001, alpha, 31);
    const ResolutionProblem view = p.View();
    ActiveSetOptimizer optimizer(Unlimited());
    std::vector<double> optimum(p.Weight.size());
    ASSERT_EQ(optimizer.Solve(view, optimum.data(), false).State, Status::Optimal);
    std::vector<double> r = optimum;
    const auto warm = optimizer.Solve(view, r.data(), true);
    SCOPED_TRACE("alpha " + std::to_string(alpha));
    ASSERT_EQ(warm.State, Status::Optimal);
    EXPECT_EQ(warm.Iterations, 1);
    EXPECT_EQ(warm.Steps, 1);
    // Within the root's tolerance (phi meets the budget to 2 n eps).
    EXPECT_NEAR(warm.Objective, warm.InitialObjective, 1e-10 * std::abs(warm.Objective));
    double deviation = 0.0;
    for (std::size_t i = 0; i < r.size(); ++i)
    {
      deviation = std::max(deviation, std::abs(r[i] - optimum[i]));
    }
    EXPECT_LE(deviation, 1e-10);
  }
}

TEST(ActiveSetOptimizer, WarmAndColdAgreeOnPerturbedFrames)
{
  // The benchmark's sequence at 20,000 objects: every frame warm-started from
  // the previous frame's answer (over budget whenever the budget shrank: the
  // Beta reduction runs) reaches the cold solve's objective, and both satisfy
  // the KKT conditions checked from scratch.
  for (double alpha : { 1.0, 2.0, -0.5 })
  {
    const RandomProblem base = MakeRandomProblem(20003, alpha, 41);
    ActiveSetOptimizer warmOptimizer(Unlimited()), coldOptimizer(Unlimited());
    std::vector<double> warm(base.Weight.size()), cold(base.Weight.size());
    ASSERT_EQ(warmOptimizer.Solve(base.View(), warm.data(), false).State, Status::Optimal);
    long warmSteps = 0, coldSteps = 0;
    for (unsigned frame = 1; frame <= 8; ++frame)
    {
      const RandomProblem p = NextFrame(base, 100 * static_cast<unsigned>(alpha * 10 + 10) + frame);
      const ResolutionProblem view = p.View();
      const auto w = warmOptimizer.Solve(view, warm.data(), true);
      const auto c = coldOptimizer.Solve(view, cold.data(), false);
      SCOPED_TRACE("alpha " + std::to_string(alpha) + " frame " + std::to_string(frame));
      ASSERT_EQ(w.State, Status::Optimal);
      ASSERT_EQ(c.State, Status::Optimal);
      EXPECT_LE(std::abs(RelativeGap(w.Objective, c.Objective)), 1e-12);
      EXPECT_LE(view.Cost(warm.data()), view.Budget);
      EXPECT_LE(CheckKKT(view, warm.data()).Worst(), 1e-7);
      EXPECT_LE(w.Objective, w.InitialObjective);
      // The warm start begins much closer to the optimum.
      EXPECT_LT(w.InitialObjective - w.Objective, 0.1 * (c.InitialObjective - c.Objective));
      warmSteps += w.Steps;
      coldSteps += c.Steps;
    }
    EXPECT_LE(warmSteps, coldSteps);
  }
}

TEST(ActiveSetOptimizer, ReducedStartSpendsTheBudgetAndReportsOneObjective)
{
  // Section 5.3.1's reduction of an over-budget warm start: least valuable
  // first, the last bucket by the fraction that meets the budget. The start
  // is the same point, with the same f, whether the search then runs (which
  // reports f at the start without building it) or is not allowed to.
  for (std::size_t n : { std::size_t(1001), std::size_t(20000) })
  {
    RandomProblem p = MakeRandomProblem(n, 1.0, 51, 0.4);
    std::vector<double> previous(n);
    ActiveSetOptimizer optimizer(Unlimited());
    ASSERT_EQ(optimizer.Solve(p.View(), previous.data(), false).State, Status::Optimal);
    for (double fraction : { 0.37, 0.25, 0.05 })
    {
      p.SetBudgetFraction(fraction);
      const ResolutionProblem view = p.View();
      ActiveSetOptimizer::Options none = Unlimited();
      none.MaxIterations = 0;
      ActiveSetOptimizer start(none);
      std::vector<double> r0 = previous, r1 = previous;
      const auto s = start.Solve(view, r0.data(), true);
      const auto full = optimizer.Solve(view, r1.data(), true);
      SCOPED_TRACE("n " + std::to_string(n) + " fraction " + std::to_string(fraction));
      EXPECT_EQ(s.State, Status::IterationLimit);
      ASSERT_EQ(full.State, Status::Optimal);
      EXPECT_LE(view.Cost(r0.data()), view.Budget);
      EXPECT_GE(view.Cost(r0.data()), (1.0 - 1e-9) * view.Budget);
      EXPECT_NEAR(s.Objective, view.Objective(r0.data()), 1e-12 * std::abs(s.Objective));
      EXPECT_EQ(full.InitialObjective, s.InitialObjective);
      // Reduced, not reset: better than every object at rmin.
      std::vector<double> minimum = p.MinResolution;
      EXPECT_LT(s.Objective, view.Objective(minimum.data()));
      for (std::size_t i = 0; i < n; ++i)
      {
        ASSERT_LE(r0[i], previous[i]);
        ASSERT_GE(r0[i], p.MinResolution[i]);
      }
    }
  }
}

TEST(ActiveSetOptimizer, TimeNotBindingWhenTheRestIsAtRmin)
{
  // Objects with c = 0 stay at rmin; when the others all fit at 1 the time
  // constraint is slack (multiplier 0), though cost(1) is over the budget.
  RandomProblem p = MakeRandomProblem(1003, 1.0, 61);
  double top = 0.0;
  for (std::size_t i = 0; i < p.Weight.size(); ++i)
  {
    if (i % 3 == 0)
    {
      p.Weight[i] = 0.0;
    }
    top += p.MaxTime[i] * (i % 3 == 0 ? p.MinResolution[i] : 1.0);
  }
  p.Budget = 0.5 * (top + p.CostAtFull());
  for (bool warm : { false, true })
  {
    std::vector<double> r(p.Weight.size(), 0.5);
    ActiveSetOptimizer optimizer(Unlimited());
    const auto result = optimizer.Solve(p.View(), r.data(), warm);
    EXPECT_EQ(result.State, Status::Optimal);
    EXPECT_EQ(result.Multiplier, 0.0);
    for (std::size_t i = 0; i < r.size(); ++i)
    {
      ASSERT_EQ(r[i], i % 3 == 0 ? p.MinResolution[i] : 1.0) << i;
    }
  }
}

TEST(ActiveSetOptimizer, ExtremeExponentsStayFiniteAndFeasible)
{
  // alpha = -0.9 (gamma = 10) with weights over 60 decades: the g_i span
  // 600, past the largest kappa for some objects. Every answer is finite,
  // feasible, no worse than the start, and optimal whenever it says so.
  for (unsigned seed = 1; seed <= 6; ++seed)
  {
    RandomProblem p = MakeRandomProblem(4001, -0.9, seed, 0.5);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> decades(-30.0, 30.0);
    for (double& c : p.Weight)
    {
      c *= std::pow(10.0, decades(rng));
    }
    const ResolutionProblem view = p.View();
    for (bool warm : { false, true })
    {
      std::vector<double> r(p.Weight.size(), 0.3);
      ActiveSetOptimizer optimizer(Unlimited());
      const auto result = optimizer.Solve(view, r.data(), warm);
      SCOPED_TRACE("seed " + std::to_string(seed) + (warm ? " warm" : " cold"));
      EXPECT_TRUE(result.State == Status::Optimal || result.State == Status::IterationLimit)
        << ActiveSetOptimizer::GetStatusName(result.State);
      for (std::size_t i = 0; i < r.size(); ++i)
      {
        ASSERT_TRUE(std::isfinite(r[i]));
        ASSERT_GE(r[i], p.MinResolution[i]);
        ASSERT_LE(r[i], 1.0);
      }
      EXPECT_LE(view.Cost(r.data()), view.Budget);
      EXPECT_LE(result.Objective, result.InitialObjective + 1e-12 * std::abs(result.Objective));
      if (result.State == Status::Optimal)
      {
        EXPECT_LE(result.KKTResidual, 1e-8);
      }
    }
  }
}

TEST(ActiveSetOptimizer, WarmStartRestoresFeasibilityAndStartsNewObjectsAtMinimum)
{
  RandomProblem p = MakeRandomProblem(1000, 1.0, 9, 0.6);
  ActiveSetOptimizer optimizer(Unlimited());
  std::vector<double> r(p.Weight.size());
  ASSERT_EQ(optimizer.Solve(p.View(), r.data(), false).State, Status::Optimal);
  // Budget cut to a third and a tenth of the objects newly visible.
  p.SetBudgetFraction(0.2);
  for (std::size_t i = 0; i < r.size(); i += 10)
  {
    r[i] = std::numeric_limits<double>::quiet_NaN();
  }
  ActiveSetOptimizer::Options options = Unlimited();
  options.MaxIterations = 0; // only the start point
  ActiveSetOptimizer start(options);
  std::vector<double> r0 = r;
  const auto s = start.Solve(p.View(), r0.data(), true);
  EXPECT_EQ(s.State, Status::IterationLimit);
  EXPECT_LE(p.View().Cost(r0.data()), p.Budget);
  for (std::size_t i = 0; i < r0.size(); i += 10)
  {
    EXPECT_EQ(r0[i], p.MinResolution[i]);
  }
  // The beta reduction keeps more of the previous solution than rmin does.
  std::vector<double> minimum = p.MinResolution;
  EXPECT_LT(s.InitialObjective, p.View().Objective(minimum.data()));
  ExpectOptimal(p, Unlimited(), true, r, "after budget cut");
}

TEST(ActiveSetOptimizer, NoAllocationInSteadyState)
{
  RandomProblem p = MakeRandomProblem(2000, 1.0, 4);
  ActiveSetOptimizer optimizer(Unlimited());
  optimizer.Reserve(p.Weight.size());
  std::vector<double> r(p.Weight.size());
  optimizer.Solve(p.View(), r.data(), false);
  const std::size_t capacity = optimizer.GetCapacity();
  RandomProblem smaller = MakeRandomProblem(1500, 1.0, 5);
  const long before = static_cast<long>(timecritical::testing::GetAllocationCount());
  for (int frame = 0; frame < 20; ++frame)
  {
    timecritical_test::Perturb(p, 0.05, static_cast<unsigned>(frame));
    // Budget cuts: the warm start is over budget and gets reduced.
    p.SetBudgetFraction(frame % 3 == 0 ? 0.2 : 0.3);
    optimizer.Solve(p.View(), r.data(), true);
    optimizer.Solve(smaller.View(), r.data(), frame % 2 == 0);
  }
  const long after = static_cast<long>(timecritical::testing::GetAllocationCount());
  EXPECT_EQ(after - before, 0);
  EXPECT_EQ(optimizer.GetCapacity(), capacity);
}

TEST(ActiveSetOptimizer, SanitizesInputs)
{
  ActiveSetOptimizer optimizer(Unlimited());
  RandomProblem p = MakeRandomProblem(20, 1.0, 2);
  std::vector<double> r(p.Weight.size());
  for (double alpha : { -1.0, 0.0, -2.0, std::numeric_limits<double>::quiet_NaN() })
  {
    p.Alpha = alpha;
    EXPECT_EQ(optimizer.Solve(p.View(), r.data(), false).State, Status::InvalidInput);
    for (std::size_t i = 0; i < r.size(); ++i)
    {
      EXPECT_EQ(r[i], p.MinResolution[i]);
    }
  }
  p.Alpha = 1.0;
  p.SetBudgetFraction(0.3);
  p.Weight[0] = std::numeric_limits<double>::quiet_NaN(); // -> 0: rmin
  p.Weight[1] = 0.0;                                      // rmin
  p.MaxTime[2] = 0.0;                                     // a failed model: rmin, outside
  p.MaxTime[3] = std::numeric_limits<double>::quiet_NaN(); // invalid: rmin, outside
  p.MinResolution[4] = std::numeric_limits<double>::quiet_NaN();
  p.MinResolution[5] = 7.0; // clamped to 1
  const auto result = optimizer.Solve(p.View(), r.data(), false);
  EXPECT_EQ(result.State, Status::Optimal);
  EXPECT_EQ(result.InvalidCount, 1u);
  EXPECT_EQ(result.ZeroCostCount, 1u);
  EXPECT_EQ(r[0], p.MinResolution[0]);
  EXPECT_EQ(r[1], p.MinResolution[1]);
  EXPECT_EQ(r[2], p.MinResolution[2]);
  EXPECT_EQ(r[3], p.MinResolution[3]);
  EXPECT_GE(r[4], ResolutionProblem::TinyResolution);
  EXPECT_EQ(r[5], 1.0);
  double cost = 0.0;
  for (std::size_t i = 0; i < r.size(); ++i)
  {
    cost += i == 3 ? 0.0 : p.MaxTime[i] * r[i];
  }
  EXPECT_LE(cost, p.Budget);
  for (double x : r)
  {
    EXPECT_TRUE(std::isfinite(x));
  }
}

TEST(ActiveSetOptimizer, ZeroCostIsNeverDrawnInFull)
{
  // The soak's failure: a collapsed cost model gives objects tmax = 0, and
  // an optimizer that takes that at its word draws them in full. Whatever the
  // budget, start or method, such an object stays at rmin, unless its rmin
  // is 1 (how a caller asks for an object in full outside the budget).
  for (double fraction : { 0.0, 0.3, 2.0 })
  {
    for (double limit : { 0.0, 10.0 })
    {
      for (bool warm : { false, true })
      {
        RandomProblem p = MakeRandomProblem(40, 1.0, 8, fraction);
        for (std::size_t i = 0; i < 40; i += 4)
        {
          p.MaxTime[i] = 0.0;
          p.Weight[i] = 1e3 * p.Weight[i]; // the most valuable objects
        }
        p.MinResolution[36] = 1.0;
        ActiveSetOptimizer::Options options;
        options.TimeLimit = limit;
        ActiveSetOptimizer optimizer(options);
        std::vector<double> r(40, warm ? 1.0 : 0.5);
        const auto result = optimizer.Solve(p.View(), r.data(), warm);
        SCOPED_TRACE("fraction " + std::to_string(fraction) + " limit " + std::to_string(limit) +
          (warm ? " warm" : " cold"));
        EXPECT_EQ(result.ZeroCostCount, 10u);
        for (std::size_t i = 0; i < 36; i += 4)
        {
          EXPECT_EQ(r[i], p.MinResolution[i]) << "object " << i;
        }
        EXPECT_EQ(r[36], 1.0);
        std::vector<double> reference(40);
        ReferenceResolutionSolver::Solve(p.View(), reference.data());
        for (std::size_t i = 0; i < 40; i += 4)
        {
          EXPECT_EQ(reference[i], p.MinResolution[i]) << "reference, object " << i;
        }
      }
    }
  }
}

TEST(ActiveSetOptimizer, NoTimeGivesTheClosedFormNotTheMinimum)
{
  // t_opt = 0 with a budget for a third of the scene: no iteration, yet a
  // feasible allocation that uses the budget and is close to the optimum;
  // the paper's start point would leave every object at rmin.
  for (double alpha : Alphas)
  {
    RandomProblem p = MakeRandomProblem(529, alpha, 21, 0.33);
    const ResolutionProblem view = p.View();
    ActiveSetOptimizer::Options none;
    none.TimeLimit = 0.0;
    ActiveSetOptimizer optimizer(none);
    std::vector<double> r(529, std::numeric_limits<double>::quiet_NaN());
    const auto result = optimizer.Solve(view, r.data(), false);
    SCOPED_TRACE("alpha " + std::to_string(alpha));
    EXPECT_EQ(result.State, Status::TimeLimit);
    EXPECT_EQ(result.Iterations, 0);
    EXPECT_LE(view.Cost(r.data()), view.Budget);
    EXPECT_GE(view.Cost(r.data()), 0.9 * view.Budget);
    std::vector<double> reference(529), minimum = p.MinResolution;
    const auto ref = ReferenceResolutionSolver::Solve(view, reference.data());
    const double atMinimum = view.Objective(minimum.data());
    // Within a tenth of the way from rmin to the optimum; for alpha = -0.9
    // (gamma = 10: the g_i span a hundred orders of magnitude) the six
    // corrections do not get that close, it only beats rmin.
    EXPECT_LE(result.Objective - ref.Objective,
      (alpha > -0.9 ? 0.1 : 1.0) * (atMinimum - ref.Objective));
    // Warm: the previous frame's allocation when it is better, else the closed form.
    std::vector<double> previous = reference;
    const auto warm = optimizer.Solve(view, previous.data(), true);
    EXPECT_LE(warm.Objective, result.Objective + 1e-12 * std::abs(result.Objective));
    EXPECT_LE(view.Cost(previous.data()), view.Budget);
    std::vector<double> poor = minimum;
    const auto fromPoor = optimizer.Solve(view, poor.data(), true);
    EXPECT_NEAR(fromPoor.Objective, result.Objective, 1e-12 * std::abs(result.Objective));
  }
}

TEST(ActiveSetOptimizer, RandomizedSmallProblems)
{
  // Edge cases by the thousand: ties, zero weights, rmin = 1, tiny rmin,
  // zero tmax, random warm starts and random stop limits, both methods.
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int optimal = 0;
  for (int trial = 0; trial < 4000; ++trial)
  {
    const std::size_t n = 1 + static_cast<std::size_t>(unit(rng) * 12);
    RandomProblem p = MakeRandomProblem(n, Alphas[trial % 6], static_cast<unsigned>(trial));
    for (std::size_t i = 0; i < n; ++i)
    {
      const double dice = unit(rng);
      if (dice < 0.1)
      {
        p.Weight[i] = 0.0;
      }
      else if (dice < 0.2)
      {
        p.MinResolution[i] = 1.0;
      }
      else if (dice < 0.3)
      {
        p.MinResolution[i] = 1e-6;
      }
      else if (dice < 0.35)
      {
        p.MaxTime[i] = 0.0;
      }
      else if (dice < 0.5 && i > 0)
      {
        p.Weight[i] = p.Weight[0]; // ties
        p.MaxTime[i] = p.MaxTime[0];
        p.MinResolution[i] = p.MinResolution[0];
      }
    }
    p.SetBudgetFraction(unit(rng) * 1.2 - 0.1);
    const ResolutionProblem view = p.View();
    ActiveSetOptimizer::Options options = trial % 2 ? PaperMethod() : Unlimited();
    const bool limited = trial % 3 == 0;
    if (limited)
    {
      options.MaxSteps = static_cast<long>(unit(rng) * 6);
    }
    std::vector<double> r(n);
    const bool warm = trial % 4 < 2;
    for (double& x : r)
    {
      x = unit(rng) < 0.2 ? std::numeric_limits<double>::quiet_NaN() : unit(rng) * 1.2;
    }
    ActiveSetOptimizer optimizer(options);
    const auto result = optimizer.Solve(view, r.data(), warm);
    SCOPED_TRACE("trial " + std::to_string(trial) + " status " +
      ActiveSetOptimizer::GetStatusName(result.State));
    double cost = 0.0;
    for (std::size_t i = 0; i < n; ++i)
    {
      ASSERT_TRUE(std::isfinite(r[i]));
      const double lo = std::min(1.0, p.MinResolution[i]);
      ASSERT_GE(r[i], lo);
      ASSERT_LE(r[i], 1.0);
      cost += p.MaxTime[i] * r[i];
    }
    if (result.State == Status::Infeasible)
    {
      EXPECT_GT(p.CostAtMin(), p.Budget);
      continue;
    }
    ASSERT_LE(cost, p.Budget * (1.0 + 1e-15) + 1e-300);
    EXPECT_LE(result.Objective, result.InitialObjective + 1e-12 * std::abs(result.Objective));
    if (result.State == Status::Optimal || result.State == Status::Unconstrained)
    {
      ++optimal;
      std::vector<double> reference(n);
      const auto ref = ReferenceResolutionSolver::Solve(view, reference.data());
      EXPECT_LE(std::abs(result.Objective - ref.Objective),
        1e-6 * std::max(1.0, std::abs(ref.Objective)));
      EXPECT_LE(result.KKTResidual, 1e-7);
    }
    else
    {
      EXPECT_TRUE(limited) << "stopped early without a limit";
    }
  }
  EXPECT_GT(optimal, 2000);
}
}
