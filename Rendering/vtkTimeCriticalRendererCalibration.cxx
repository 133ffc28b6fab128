// SPDX-License-Identifier: BSD-3-Clause
// vtkTimeCriticalRenderer: the start-up calibration of its cost model, and
// the scaling of the default coefficients where there is none.
#include "vtkTimeCriticalRenderer.h"

#include "vtkTimeCriticalRendererInternals.h"

using namespace timecritical::rendering;

bool vtkTimeCriticalRenderer::Calibrate()
{
  if (!this->RenderWindow)
  {
    vtkErrorMacro("Calibrate() needs a render window");
    return false;
  }
  this->Calibrated = false;
  this->Internal->CalibrationRequested = true;
  this->RenderWindow->Render();
  this->Internal->CalibrationRequested = false;
  return this->Calibrated;
}

void vtkTimeCriticalRenderer::ScaleDefaultCoefficients(double measured)
{
  // Without a calibration (it cannot run on one rank of a parallel render
  // alone, or was turned off) the model starts from defaults whose ratios
  // are plausible but whose scale may be off by an order of magnitude. A
  // still frame measures the scale: every coefficient times measured /
  // predicted, once; the budgeted frames then refine the split.
  Internals& in = *this->Internal;
  in.UsingDefaults = false;
  const double predicted = in.RawPrediction - in.RefinementEstimate;
  if (!(predicted > 0.0) || !(measured > 0.0) || !std::isfinite(measured))
  {
    return;
  }
  const double factor = std::min(100.0, std::max(0.01, measured / predicted));
  double theta[FeatureCount];
  in.Model.GetFeatureWeights(theta);
  for (double& weight : theta)
  {
    weight *= factor;
  }
  in.Model.SetFeatureWeights(theta);
  // A measurement of this machine, like a calibration: the online fit may
  // not make triangles cheaper than half of it (frames whose time does not
  // follow their triangles, as a rank's that waits for the others to
  // composite, would otherwise push the whole frame into the fixed part).
  in.SetCoefficientFloors(true);
  in.ResetCalibrator(1.0); // one frame's worth: the next frames refine it
  in.Corrector.Reset();
  in.StillCorrector.Reset();
}

//------------------------------------------------------------------------------
// Start-up calibration: renders of the current scene at several resolutions
// and three zoom factors, each timed to completion (glFinish), then a robust
// non-negative fit. Runs inside DeviceRender(), so nothing recurses into the
// window and the user sees only the final frame.
//
// Cost: the samples are sized to the target, not to the scene: a probe finds
// the per-triangle cost, then each zoom draws what the target affords and
// half, a fifth and none of it, twice each (the faster counts: scheduling
// noise only adds). About 12 targets' worth of rendering in all plus the
// first upload of the vertex data, which the first frame pays anyway; never
// more than CalibrationTimeLimit targets.

namespace
{
constexpr double CalibrationTimeLimit = 30.0; // in targets
}

void vtkTimeCriticalRenderer::RunCalibration()
{
  Internals& in = *this->Internal;
  const auto calibrationStart = Clock::now();
  this->CalibrationAttempted = true;
  vtkCamera* camera = this->GetActiveCamera();
  const double savedAngle = camera->GetViewAngle();
  const double savedScale = camera->GetParallelScale();
  // With UseDesiredUpdateRate the interactive target is not known in a still
  // frame; the setting is then the yardstick (and covers faster targets).
  const double sizing = std::isfinite(in.EffectiveTarget)
    ? std::max(in.EffectiveTarget, this->TargetFrameTime)
    : this->TargetFrameTime;
  const double deadline = CalibrationTimeLimit * sizing;
  // Zooming out and in varies the objects in view and their coverage, so that
  // the fixed, per-object and fill terms can be told apart from the triangles.
  const double zooms[] = { 1.0, 0.7, 1.8 };
  const double fractions[] = { 1.0, 0.5, 0.2, 0.0 };
  constexpr std::size_t MaxSamples = 2 + 3 * 4;
  double x[MaxSamples * FeatureCount];
  double times[MaxSamples];
  std::size_t samples = 0;
  int renders = 0;

  auto visibleTriangles = [&]() {
    double total = 0.0;
    for (std::size_t o = 0; o < in.ObjectActor.size(); ++o)
    {
      total += in.Culled[o] ? 0.0 : in.MaxTriangles[o];
    }
    return total;
  };
  auto setResolution = [&](double r) {
    for (std::size_t o = 0; o < in.ObjectActor.size(); ++o)
    {
      in.Resolution[o] = in.Culled[o] ? 0.0 : std::max(r, 1e-9);
    }
    in.ApplyResolutions();
  };
  auto render = [&]() {
    const auto start = Clock::now();
    this->Superclass::DeviceRender();
    glFinish();
    ++renders;
    return Seconds(start, Clock::now());
  };
  // One sample: the faster of two renders, features from the second.
  auto sample = [&](double r) {
    setResolution(r);
    const double t = std::min(render(), render());
    this->FinishFrame();
    times[samples] = t;
    std::copy(in.Features.begin(), in.Features.end(), x + samples * FeatureCount);
    ++samples;
    return t;
  };
  auto zoomTo = [&](double zoom) {
    camera->SetViewAngle(savedAngle);
    camera->SetParallelScale(savedScale);
    camera->Zoom(zoom);
    this->MeasureObjects();
  };

  // Probe at the first zoom: the coarsest levels (after an untimed render
  // that uploads the vertex data), then a quarter of what the current
  // per-triangle cost says the target affords.
  zoomTo(zooms[0]);
  double visible = visibleTriangles();
  double triangleCost = std::max(in.Model.GetCoefficients().Triangle, 1e-12);
  if (visible > 0.0)
  {
    setResolution(0.0);
    render();
    const double coarseTime = sample(0.0);
    const double coarseTriangles = in.Features[timecritical::FrameCostModel::FeatureTriangles];
    const double probe = std::min(1.0, 0.25 * sizing / triangleCost / visible);
    const double probeTime = sample(probe);
    const double probeTriangles = in.Features[timecritical::FrameCostModel::FeatureTriangles];
    const double slope = (probeTime - coarseTime) / (probeTriangles - coarseTriangles);
    if (std::isfinite(slope) && slope > 0.0)
    {
      triangleCost = slope;
    }
  }
  for (double zoom : zooms)
  {
    if (Seconds(calibrationStart, Clock::now()) > deadline)
    {
      break;
    }
    zoomTo(zoom);
    visible = visibleTriangles();
    if (!(visible > 0.0))
    {
      continue;
    }
    // What the target affords at the measured cost, largest first: every
    // buffer grows once, in the first of its two renders.
    const double largest = std::min(1.0, sizing / triangleCost / visible);
    for (double fraction : fractions)
    {
      if (fraction == 0.0 && zoom == zooms[0])
      {
        continue; // the probe measured it
      }
      if (Seconds(calibrationStart, Clock::now()) > deadline)
      {
        break;
      }
      sample(fraction * largest);
    }
  }
  in.FramePending = false;
  camera->SetViewAngle(savedAngle);
  camera->SetParallelScale(savedScale);
  if (samples == 0)
  {
    // Nothing in view at any zoom (a script's first render comes before its
    // camera is reset, for instance): try again in a later frame.
    this->CalibrationAttempted = false;
    this->CalibrationRenders += renders;
    this->CalibrationTime = Seconds(calibrationStart, Clock::now());
    return;
  }
  // The fixed per-frame work outside DeviceRender() (swap, window events) is
  // not in these samples; online refinement adds it within a few frames.
  // The fit is bounded by the physical floors only: it is the measurement
  // the later, relative floors come from.
  const auto previousFloors = in.Model.GetMinimumCoefficients();
  in.SetCoefficientFloors(false);
  if (samples >= 3 && in.Calibrator.Calibrate(x, times, samples))
  {
    in.StoreCoefficients();
    in.SetCoefficientFloors(true);
    in.Corrector.Reset();
    in.StillCorrector.Reset();
    this->Calibrated = true;
    in.UsingDefaults = false;
  }
  else
  {
    in.ApplyFloors(previousFloors);
    vtkWarningMacro("Cost model calibration found nothing to measure; keeping the current "
                    "coefficients");
  }
  this->CalibrationRenders += renders;
  this->CalibrationTime = Seconds(calibrationStart, Clock::now());
}
