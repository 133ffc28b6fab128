// SPDX-License-Identifier: BSD-3-Clause
// vtkTimeCriticalRenderer's "no polygons" level (Funkhouser & Séquin): when
// even the coarsest levels of the visible objects do not fit the target, an
// interactive frame leaves the least valuable objects out, chosen by the
// policy's SelectTuples() (timecritical::TupleProblem, one algorithm, no
// bounding-box level).
#include "vtkTimeCriticalRenderer.h"

#include "vtkTimeCriticalRendererInternals.h"

#include <stdexcept>

using namespace timecritical::rendering;

bool vtkTimeCriticalRenderer::GetObjectDropped(vtkIdType object) const
{
  const auto& dropped = this->Internal->Dropped;
  return object >= 0 && static_cast<std::size_t>(object) < dropped.size() && dropped[object] != 0;
}

double vtkTimeCriticalRenderer::PrepareDropping(bool still, double correction)
{
  Internals& in = *this->Internal;
  std::fill(in.Dropped.begin(), in.Dropped.end(), 0);
  this->NumberOfDroppedObjects = 0;
  in.DrawnPixels = in.TotalPixels;
  // A model never measured on this machine (default coefficients: no
  // calibration yet, as while background builds are pending, and no still
  // frame to scale them) may overestimate several times: it would empty
  // the view. Such frames draw every visible object.
  in.DropPossible = !still && this->DropObjectsWhenOverloaded && !in.UsingDefaults &&
    (this->Policy == ACTIVE_SET || this->Policy == GREEDY_LOD);
  if (!in.DropPossible)
  {
    return 0.0;
  }
  // What an object takes whatever its resolution, and saves only when it is
  // not drawn: its setup and, where fill adds to the geometry (software
  // rasterizers), its pixels. FixedTime() counts both for every visible
  // object; a frame that drops moves them to the objects.
  const std::size_t m = in.Visible.size();
  in.ObjectFixedCost.resize(m);
  in.DropDegradation.resize(m);
  in.TupleAlgorithm.resize(m);
  const auto& c = in.Model.GetCoefficients();
  const bool additive =
    in.Model.GetPixelMode() == timecritical::FrameCostModel::PixelMode::Additive;
  double sum = 0.0;
  for (std::size_t k = 0; k < m; ++k)
  {
    const std::size_t o = in.Visible[k];
    const double cost = correction * (c.Object + (additive ? c.Pixel * in.Pixels[o] : 0.0));
    in.ObjectFixedCost[k] = cost;
    sum += cost;
    // The value: what the object loses when not drawn, Interest x Npix (the
    // benefit of Funkhouser & Séquin; AlgorithmDegradation's "not drawn").
    // With the default (Hitchner) family it is the degradation of the object
    // drawn with one triangle, so it lies above that of its coarsest level,
    // and it grows with the object's projected area.
    in.DropDegradation[k] = in.Degradation.InterestWeight(in.Views[k]) * in.Pixels[o];
  }
  return sum;
}

double vtkTimeCriticalRenderer::PlanningMargin(
  double target, double fixed, double objectFixed, bool still)
{
  // Plan for predicted + k sigma <= target; the prediction itself stays
  // unbiased. The margin never takes more than MaximumMarginShare of the time
  // the fixed part and the objects' coarsest levels leave: when noise and a
  // large fixed part meet, the objects get the best allocation of the rest
  // rather than all their coarsest levels. An overloaded frame that may drop
  // objects holds the target by dropping: its margin is a share of what the
  // fixed part leaves.
  Internals& in = *this->Internal;
  if (still || !this->OnlineCalibration)
  {
    return 0.0;
  }
  double lowest = 0.0;
  for (std::size_t k = 0; k < in.Visible.size(); ++k)
  {
    lowest += in.MaxTime[k] * in.MinResolution[k];
  }
  const double wanted =
    std::min(this->SafetyFactor * in.Corrector.GetRelativeSpread(), MaximumMargin) * target;
  double room = target - fixed - lowest;
  if (in.DropPossible && room < 0.0)
  {
    room = target - (fixed - objectFixed);
  }
  return std::min(wanted, MaximumMarginShare * std::max(0.0, room));
}

namespace
{
/// When every object is dropped, draws the most valuable at its cheapest tuple.
void KeepTheMostValuable(const timecritical::TupleProblem& problem, int* algorithms, double* r,
  timecritical::TupleProblem::Solution& solution)
{
  const std::size_t m = problem.Count;
  std::size_t best = m;
  for (std::size_t k = 0; k < m; ++k)
  {
    if (algorithms[k] != timecritical::TupleProblem::NotDrawn)
    {
      return; // something is drawn
    }
    if (best == m || problem.DropDegradation[k] > problem.DropDegradation[best])
    {
      best = k;
    }
  }
  if (best == m)
  {
    return;
  }
  const int algorithm = problem.CheapestAlgorithm(best);
  algorithms[best] = algorithm;
  r[best] = problem.Lo(best, static_cast<std::size_t>(algorithm));
  solution.Cost += problem.Cost(best, algorithm, r[best]);
  solution.Objective +=
    problem.Degradation(best, algorithm, r[best]) - problem.DropDegradation[best];
  solution.Dropped -= 1;
}
}

bool vtkTimeCriticalRenderer::ChooseWithDropping(double target, double fixed, double objectFixed)
{
  Internals& in = *this->Internal;
  const std::size_t m = in.Visible.size();
  if (!in.DropPossible || m == 0)
  {
    return false;
  }
  const double alpha = in.Degradation.GetAlpha();
  timecritical::TupleProblem problem;
  problem.Count = m;
  problem.AlgorithmCount = 1;
  problem.Alpha = &alpha;
  problem.Weight = in.Weight.data();
  problem.MaxTime = in.MaxTime.data();
  problem.FixedCost = in.ObjectFixedCost.data();
  problem.MinResolution = in.MinResolution.data();
  problem.DropDegradation = in.DropDegradation.data();
  problem.AllowDrop = true;
  // What users expect of a view: the largest, most valuable objects are the
  // last to go (with value ~ area and fill cost ~ area, benefit per cost alone
  // would drop large objects as readily as small ones).
  problem.StrictValueOrder = true;
  const double base = fixed - objectFixed; // the frame's time without its objects
  problem.Budget = target - base;
  // When the frame's fixed part alone reaches the target, no choice of
  // objects holds it: dropping them all would empty the view for nothing,
  // so they are drawn at their coarsest levels, as without dropping.
  if (!(problem.Budget > 0.0) || !problem.NeedsDropping())
  {
    return false;
  }
  const auto start = Clock::now();
  timecritical::TupleProblem::Solution solution;
  try
  {
    solution = this->Policy == GREEDY_LOD
      ? in.Greedy.SelectTuples(problem, in.TupleAlgorithm.data(), in.Chosen.data())
      : in.ActiveSet.SelectTuples(problem, in.TupleAlgorithm.data(), in.Chosen.data());
  }
  catch (const std::invalid_argument& e)
  {
    vtkErrorMacro("Cannot choose the objects to drop: " << e.what());
    return false;
  }
  // Dropping never empties the view: an empty frame tells the user nothing,
  // an over-budget one at least shows the most valuable object (a single
  // object whose coarsest level exceeds the target, a large stand-in while
  // its hierarchy builds).
  KeepTheMostValuable(problem, in.TupleAlgorithm.data(), in.Chosen.data(), solution);
  vtkIdType dropped = 0;
  for (std::size_t k = 0; k < m; ++k)
  {
    if (in.TupleAlgorithm[k] == timecritical::TupleProblem::NotDrawn)
    {
      const std::size_t o = in.Visible[k];
      in.Chosen[k] = 0.0; // the mapper leaves the object out, as a culled one
      in.Dropped[o] = 1;
      in.DrawnPixels -= in.Pixels[o];
      ++dropped;
    }
  }
  this->NumberOfDroppedObjects = dropped;
  const double held = this->HoldDrawnObjects(problem.Budget - solution.Cost);
  timecritical::PolicyResult& result = in.DropResult;
  result = timecritical::PolicyResult();
  result.Seconds = Seconds(start, Clock::now());
  result.PredictedFrameTime = base + solution.Cost + held;
  result.Objective = solution.Objective;
  result.Iterations = solution.Iterations;
  result.Converged = true;
  result.OverBudget = result.PredictedFrameTime > target * (1.0 + 1e-9);
  result.Held = static_cast<std::size_t>(this->NumberOfHeldObjects);
  return true;
}
