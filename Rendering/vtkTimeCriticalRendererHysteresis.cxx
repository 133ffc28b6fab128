// SPDX-License-Identifier: BSD-3-Clause
// vtkTimeCriticalRenderer's hysteresis (timecritical::HysteresisBand): the
// setting, the holds of a frame that drops objects (the policies' own frames
// get theirs in ResolutionPolicy::Select()), and the popping counts.
#include "vtkTimeCriticalRenderer.h"

#include "vtkTimeCriticalRendererInternals.h"

#include <stdexcept>

using namespace timecritical::rendering;

void vtkTimeCriticalRenderer::SetHysteresis(double hysteresis)
{
  try
  {
    timecritical::HysteresisBand::CheckHysteresis(hysteresis);
  }
  catch (const std::invalid_argument& e)
  {
    vtkErrorMacro("Hysteresis not changed: " << e.what());
    return;
  }
  if (this->Hysteresis != hysteresis)
  {
    this->Hysteresis = hysteresis;
    this->Modified();
  }
}

double vtkTimeCriticalRenderer::HoldDrawnObjects(double slack)
{
  Internals& in = *this->Internal;
  this->NumberOfHeldObjects = 0;
  const double alpha = in.Degradation.GetAlpha();
  if (this->Hysteresis == 0.0 || !timecritical::ResolutionProblem::IsValidAlpha(alpha))
  {
    return 0.0;
  }
  const std::size_t m = in.Visible.size();
  auto cost = [&in, m]() {
    double sum = 0.0;
    for (std::size_t k = 0; k < m; ++k)
    {
      sum += in.Chosen[k] > 0.0 ? in.MaxTime[k] * std::max(in.Chosen[k], in.MinResolution[k]) : 0.0;
    }
    return sum;
  };
  timecritical::HysteresisBand::Input band;
  band.Count = m;
  band.MaxTime = in.MaxTime.data();
  band.MinResolution = in.MinResolution.data();
  band.Previous = in.Previous.data();
  band.Alpha = alpha;
  band.Slack = std::max(0.0, slack);
  const double before = cost();
  this->NumberOfHeldObjects =
    static_cast<vtkIdType>(in.Band.Apply(band, this->Hysteresis, in.Chosen.data()));
  return cost() - before;
}

void vtkTimeCriticalRenderer::CountChanges()
{
  // Of the visible objects drawn in the last frame too (a last resolution
  // > 0), those whose resolution is not the same now.
  const Internals& in = *this->Internal;
  vtkIdType changed = 0;
  for (std::size_t k = 0; k < in.Visible.size(); ++k)
  {
    const double previous = in.Previous[k];
    if (previous > 0.0 && std::abs(in.Chosen[k] - previous) > 1e-9 * previous)
    {
      ++changed;
    }
  }
  this->NumberOfChangedObjects = changed;
}
