// SPDX-License-Identifier: BSD-3-Clause
#include "TOMBuilder.h"

#include "CollapseEngine.h"
#include "PassSchedule.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

/*
 * The greedy schedule over the collapse engine (CollapseEngine.h): always the
 * cheapest legal collapse of the whole mesh, from an indexed heap whose keys
 * the engine keeps exact; when the heap runs dry the engine relaxes the
 * constraints one level, until none is left. TOMBuildEngine::Passes runs the
 * pass schedule (PassSchedule.h) over the same engine instead.
 */

namespace timecritical
{
namespace
{
using collapse::Candidate;
using collapse::CollapseEngine;

/// The greedy order: the top of the heap, or its cheapest legal alternative.
class GreedySchedule
{
public:
  explicit GreedySchedule(CollapseEngine& engine)
    : Engine(engine)
  {
  }

  bool Run();

private:
  bool TryAlternatives(uint32_t u, uint32_t failedTarget);

  CollapseEngine& Engine;
};

//------------------------------------------------------------------------------
bool GreedySchedule::TryAlternatives(uint32_t u, uint32_t failedTarget)
{
  // The cheapest target of u is illegal: take the cheapest legal one, which
  // may no longer be the global minimum, hence the re-queue.
  CollapseEngine& e = this->Engine;
  Candidate c{};
  if (!e.FindLegalAlternative(u, failedTarget, c))
  {
    // Nothing legal at this level: wait for the neighbourhood to change.
    e.Block(u);
    return false;
  }
  e.SetTarget(u, c.Target);
  if (CollapseEngine::KeyOf(c.Cost) <= e.HeapSecondKey())
  {
    return true; // still the cheapest collapse overall: do it now
  }
  e.SetKey(u, c.Cost);
  return false;
}

//------------------------------------------------------------------------------
bool GreedySchedule::Run()
{
  CollapseEngine& e = this->Engine;
  const uint32_t n = e.GetNumberOfVertices();
  // About 200 progress reports over the collapses.
  const size_t reportEvery = std::max<size_t>(1, n / 200);
  size_t nextReport = reportEvery;
  for (;;)
  {
    while (!e.HeapEmpty())
    {
      const uint32_t u = e.HeapTop();
      uint32_t w = e.GetTarget(u);
      if (!e.CheckCollapse(u, w))
      {
        if (!this->TryAlternatives(u, w))
        {
          continue;
        }
        w = e.GetTarget(u);
      }
      e.ApplyCollapse(u, w);
      if (e.GetRemovedCount() >= nextReport)
      {
        nextReport += reportEvery;
        if (!e.ReportProgress(0.05 + 0.9 * double(e.GetRemovedCount()) / n))
        {
          return false;
        }
      }
    }
    if (!e.Relax())
    {
      return true;
    }
  }
}
}

//------------------------------------------------------------------------------
TOMBuilder::TOMBuilder(TOMBuildOptions options)
  : Options(std::move(options))
{
}

//------------------------------------------------------------------------------
TOMBuildResult TOMBuilder::Build(const double* points, size_t numberOfPoints,
  const uint32_t* triangles, size_t numberOfTriangles) const
{
  const double pairDistance = this->Options.PairContractionDistance;
  if (!(pairDistance >= 0.0) || !std::isfinite(pairDistance))
  {
    char message[200];
    std::snprintf(message, sizeof(message),
      "TOMBuilder: PairContractionDistance must be a finite number >= 0 (a fraction of the "
      "bounding-box diagonal, 0 = off), not %g",
      pairDistance);
    throw std::invalid_argument(message);
  }
  // Either schedule, then the pair contractions (which join separate parts
  // once no edge collapse is left).
  if (this->Options.Engine == TOMBuildEngine::Passes)
  {
    CollapseEngine engine(this->Options, false); // the passes need no heap
    collapse::PassSchedule schedule(engine);
    return engine.Run(points, numberOfPoints, triangles, numberOfTriangles,
      [&schedule, &engine] { return schedule.Run() && engine.JoinParts(); });
  }
  CollapseEngine engine(this->Options, true);
  GreedySchedule schedule(engine);
  return engine.Run(points, numberOfPoints, triangles, numberOfTriangles,
    [&schedule, &engine] { return schedule.Run() && engine.JoinParts(); });
}
}
