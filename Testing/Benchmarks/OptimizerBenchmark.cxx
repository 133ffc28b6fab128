// SPDX-License-Identifier: BSD-3-Clause
// OptimizerBenchmark: time per solve of ActiveSetOptimizer on random W1-like
// scenes of n = 100 ... 100,000 objects, cold (from rmin) and warm (from the
// previous frame's solution after a camera move), against the exact
// bisection reference and Funkhouser & Séquin's greedy; also the paper's plain
// Algorithm 1 and the quality reached within a 1 ms time limit.
//
// Times are the solving thread's CPU time (wall time on a shared machine
// counts other jobs), median over the perturbed frames; wall time is kept
// next to it. The summary gives, per n and alpha, the cold and warm medians
// and the objective's gap to the reference.
//
//   OptimizerBenchmark [--json path] [--quick] [--repeats N] [--seed S]
//                      [--sizes n,n,...] [--alphas a,a,...]
#include "BenchmarkArguments.h"
#include "BenchmarkStatistics.h"
#include "BenchmarkTiming.h"
#include "BudgetTestUtilities.h"

#include "ActiveSetOptimizer.h"
#include "GreedyLODPolicy.h"
#include "ReferenceResolutionSolver.h"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace
{
using timecritical::ActiveSetOptimizer;
using timecritical::GreedyLODPolicy;
using timecritical::ReferenceResolutionSolver;
using timecritical::ResolutionProblem;
using timecritical_test::MakeRandomProblem;
using timecritical_test::NextFrame;
using timecritical_test::RandomProblem;
using timecritical::benchmark::Clock;
using timecritical::benchmark::Median;
using timecritical::benchmark::Seconds;

/// CPU time of the calling thread (s); wall time where there is no such clock.
double ThreadSeconds()
{
#if defined(CLOCK_THREAD_CPUTIME_ID)
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
#else
  return std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
#endif
}

std::vector<double> ParseList(const std::string& text)
{
  std::vector<double> values;
  std::size_t start = 0;
  while (start < text.size())
  {
    const std::size_t end = std::min(text.find(',', start), text.size());
    values.push_back(std::atof(text.substr(start, end - start).c_str()));
    start = end + 1;
  }
  return values;
}

double Gap(double f, double reference)
{
  return (f - reference) / std::abs(reference);
}

struct Row
{
  std::size_t N = 0;
  double Alpha = 1.0;
  std::string Mode;
  double SolveMedian = 0.0, SolveMax = 0.0; ///< CPU time
  double WallMedian = 0.0;
  double Iterations = 0.0, Steps = 0.0;
  double GapReference = 0.0; ///< max over the measured solves
  double GapGreedy = 0.0;    ///< (f_greedy - f_opt) / |f_opt|, median
  double GreedyMedian = 0.0;
  double ReferenceSeconds = 0.0;
  double PaperSeconds = -1.0;   ///< plain Algorithm 1 (cold), -1 when not run
  double PaperIterations = 0.0;
  double GapAt1ms = 0.0;        ///< gap of the 1 ms time-limited solve
  bool Converged1ms = false;
  bool AllOptimal = true;
};

Row Measure(std::size_t n, double alpha, bool warm, int repeats, unsigned seed, bool paper)
{
  Row row;
  row.N = n;
  row.Alpha = alpha;
  row.Mode = warm ? "warm" : "cold";
  const RandomProblem base = MakeRandomProblem(n, alpha, seed);
  ActiveSetOptimizer::Options options;
  options.TimeLimit = 60.0; // convergence time, not a deadline
  ActiveSetOptimizer optimizer(options);
  optimizer.Reserve(n);
  GreedyLODPolicy greedy;
  std::vector<double> r(n), previous(n), reference(n), greedyR(n), greedyPrevious(n);
  std::vector<double> times, wallTimes, iterations, steps, greedyTimes, greedyGaps;

  // The previous frame's solutions (warm starts).
  optimizer.Solve(base.View(), previous.data(), false);
  {
    timecritical::PolicyInput in;
    in.Count = n;
    in.Weight = base.Weight.data();
    in.MaxTime = base.MaxTime.data();
    in.MinResolution = base.MinResolution.data();
    in.Alpha = alpha;
    in.TargetFrameTime = base.Budget;
    greedy.Select(in, greedyPrevious.data());
  }
  const int referenceCount = n >= 100000 ? 3 : (n >= 10000 ? 5 : repeats);
  for (int k = 0; k < repeats; ++k)
  {
    const RandomProblem p = NextFrame(base, seed * 1000u + static_cast<unsigned>(k) + 1u);
    const ResolutionProblem view = p.View();
    r = previous;
    const auto start = Clock::now();
    const double cpuStart = ThreadSeconds();
    const auto result = optimizer.Solve(view, r.data(), warm);
    times.push_back(ThreadSeconds() - cpuStart);
    wallTimes.push_back(Seconds(start, Clock::now()));
    iterations.push_back(result.Iterations);
    steps.push_back(static_cast<double>(result.Steps));
    row.AllOptimal = row.AllOptimal && result.State == ActiveSetOptimizer::Status::Optimal;

    timecritical::PolicyInput in;
    in.Count = n;
    in.Weight = p.Weight.data();
    in.MaxTime = p.MaxTime.data();
    in.MinResolution = p.MinResolution.data();
    in.Alpha = alpha;
    in.TargetFrameTime = p.Budget;
    in.Previous = warm ? greedyPrevious.data() : nullptr;
    const auto g = greedy.Select(in, greedyR.data());
    greedyTimes.push_back(g.Seconds);
    greedyGaps.push_back(Gap(g.Objective, result.Objective));

    if (k < referenceCount)
    {
      const auto refStart = Clock::now();
      const auto ref = ReferenceResolutionSolver::Solve(view, reference.data());
      row.ReferenceSeconds = std::max(row.ReferenceSeconds, Seconds(refStart, Clock::now()));
      row.GapReference = std::max(row.GapReference, std::abs(Gap(result.Objective, ref.Objective)));
      if (k == 0)
      {
        // Anytime quality: the same solve under a 1 ms deadline (same sized
        // optimizer, as in a renderer's steady state).
        ActiveSetOptimizer::Options limited = options;
        limited.TimeLimit = 1e-3;
        optimizer.SetOptions(limited);
        std::vector<double> q = previous;
        const auto lr = optimizer.Solve(view, q.data(), warm);
        optimizer.SetOptions(options);
        row.GapAt1ms = Gap(lr.Objective, ref.Objective);
        row.Converged1ms = lr.Converged;
      }
    }
  }
  row.SolveMedian = Median(times);
  row.WallMedian = Median(wallTimes);
  row.SolveMax = *std::max_element(times.begin(), times.end());
  row.Iterations = Median(iterations);
  row.Steps = Median(steps);
  row.GapGreedy = Median(greedyGaps);
  row.GreedyMedian = Median(greedyTimes);

  if (paper && !warm)
  {
    ActiveSetOptimizer::Options plain;
    plain.TimeLimit = 60.0;
    plain.ProjectedSteps = false;
    plain.BlockRelease = false;
    ActiveSetOptimizer method(plain);
    const RandomProblem p = NextFrame(base, seed * 1000u + 1u);
    const auto start = Clock::now();
    const auto result = method.Solve(p.View(), r.data(), false);
    row.PaperSeconds = Seconds(start, Clock::now());
    row.PaperIterations = result.Iterations;
  }
  return row;
}
}

int main(int argc, char** argv)
{
  std::string json;
  bool quick = false;
  int repeats = 21;
  unsigned seed = 1;
  std::vector<double> onlySizes, onlyAlphas;
  bool help = false;
  std::string sizesText, alphasText;
  timecritical::benchmark::BenchmarkArguments arguments(argc, argv);
  arguments.AddFlag("--help", help);
  arguments.AddText("--json", json);
  arguments.AddFlag("--quick", quick);
  arguments.AddInteger("--repeats", repeats, 1);
  arguments.AddUnsigned("--seed", seed, 0, 4294967295u);
  arguments.AddText("--sizes", sizesText);
  arguments.AddText("--alphas", alphasText);
  const char* usage = "usage: OptimizerBenchmark [--json path] [--quick] [--repeats N] [--seed S]\n"
                      "                          [--sizes n,n,...] [--alphas a,a,...]\n";
  try
  {
    arguments.Parse();
  }
  catch (const std::runtime_error& error)
  {
    std::printf("%s\n%s", error.what(), usage);
    return 2;
  }
  if (help)
  {
    std::printf("%s", usage);
    return 0;
  }
  onlySizes = ParseList(sizesText);
  onlyAlphas = ParseList(alphasText);
  std::vector<std::size_t> sizes = { 100, 529, 1000, 10000, 100000 };
  if (quick)
  {
    sizes = { 100, 529, 1000 };
    repeats = std::min(repeats, 5);
  }
  if (!onlySizes.empty())
  {
    sizes.clear();
    for (double n : onlySizes)
    {
      sizes.push_back(static_cast<std::size_t>(n));
    }
  }
  std::vector<double> alphas = { 1.0, 2.0, -0.5 };
  if (!onlyAlphas.empty())
  {
    alphas = onlyAlphas;
  }
  std::vector<Row> rows;
  std::printf("CPU time per solve (median and max over the frames), wall-time median\n");
  std::printf("%7s %5s %4s | %9s %9s %9s %5s %5s | %8s %9s | %8s %9s | %9s %6s | %9s\n", "n",
    "alpha", "mode", "cpu", "cpu-max", "wall", "iter", "steps", "gap-ref", "ref(s)", "gap-grd",
    "greedy", "gap@1ms", "conv", "paper(s)");
  for (std::size_t n : sizes)
  {
    for (double alpha : alphas)
    {
      for (bool warm : { false, true })
      {
        const Row row = Measure(n, alpha, warm, n >= 100000 ? std::min(repeats, 11) : repeats,
          seed, n <= 10000);
        rows.push_back(row);
        char paper[32] = "-";
        if (row.PaperSeconds >= 0.0)
        {
          std::snprintf(paper, sizeof(paper), "%.2e", row.PaperSeconds);
        }
        std::printf("%7zu %5.1f %4s | %7.1fus %7.1fus %7.1fus %5.0f %5.0f | %8.1e %9.2e | %8.2e %7.1fus | %9.1e %6s | %9s%s\n",
          row.N, row.Alpha, row.Mode.c_str(), row.SolveMedian * 1e6, row.SolveMax * 1e6,
          row.WallMedian * 1e6, row.Iterations, row.Steps, row.GapReference, row.ReferenceSeconds, row.GapGreedy,
          row.GreedyMedian * 1e6, row.GapAt1ms, row.Converged1ms ? "yes" : "no", paper,
          row.AllOptimal ? "" : "  (not all optimal)");
        std::fflush(stdout);
      }
    }
  }
  // Summary: cold and warm side by side (rows come in cold, warm pairs).
  std::printf("\nsummary (CPU time, median over the frames; gap: max |f - f_ref| / |f_ref|)\n");
  std::printf("%7s %5s | %10s %10s | %8s %8s\n", "n", "alpha", "cold", "warm", "gap-cold", "gap-warm");
  for (std::size_t i = 0; i + 1 < rows.size(); i += 2)
  {
    std::printf("%7zu %5.1f | %8.1fus %8.1fus | %8.1e %8.1e\n", rows[i].N, rows[i].Alpha,
      rows[i].SolveMedian * 1e6, rows[i + 1].SolveMedian * 1e6, rows[i].GapReference,
      rows[i + 1].GapReference);
  }
  if (!json.empty())
  {
    std::ofstream out(json);
    out << "{\n  \"benchmark\": \"OptimizerBenchmark\",\n  \"clock\": \"thread CPU time\",\n"
        << "  \"repeats\": " << repeats << ",\n  \"seed\": " << seed << ",\n  \"summary\": [\n";
    for (std::size_t i = 0; i + 1 < rows.size(); i += 2)
    {
      char line[512];
      std::snprintf(line, sizeof(line),
        "    {\"n\": %zu, \"alpha\": %g, \"cold_median_cpu_seconds\": %.9g, "
        "\"warm_median_cpu_seconds\": %.9g, \"cold_gap_vs_reference\": %.3g, "
        "\"warm_gap_vs_reference\": %.3g}%s\n",
        rows[i].N, rows[i].Alpha, rows[i].SolveMedian, rows[i + 1].SolveMedian,
        rows[i].GapReference, rows[i + 1].GapReference, i + 3 < rows.size() ? "," : "");
      out << line;
    }
    out << "  ],\n  \"rows\": [\n";
    for (std::size_t i = 0; i < rows.size(); ++i)
    {
      const Row& r = rows[i];
      char line[1024];
      std::snprintf(line, sizeof(line),
        "    {\"n\": %zu, \"alpha\": %g, \"mode\": \"%s\", \"median_cpu_seconds\": %.9g, "
        "\"max_cpu_seconds\": %.9g, \"median_wall_seconds\": %.9g, \"iterations\": %g, "
        "\"steps\": %g, \"all_optimal\": %s, "
        "\"gap_vs_reference\": %.3g, \"reference_seconds\": %.6g, \"gap_greedy_vs_optimizer\": %.6g, "
        "\"greedy_median_seconds\": %.9g, \"gap_at_1ms\": %.3g, \"converged_at_1ms\": %s, "
        "\"paper_method_seconds\": %s, \"paper_method_iterations\": %g}%s\n",
        r.N, r.Alpha, r.Mode.c_str(), r.SolveMedian, r.SolveMax, r.WallMedian, r.Iterations, r.Steps,
        r.AllOptimal ? "true" : "false", r.GapReference, r.ReferenceSeconds, r.GapGreedy,
        r.GreedyMedian, r.GapAt1ms, r.Converged1ms ? "true" : "false",
        r.PaperSeconds >= 0.0 ? std::to_string(r.PaperSeconds).c_str() : "null",
        r.PaperIterations, i + 1 < rows.size() ? "," : "");
      out << line;
    }
    out << "  ]\n}\n";
    std::printf("wrote %s\n", json.c_str());
  }
  return 0;
}
