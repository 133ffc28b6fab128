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

bool vtkTimeCriticalRenderer::GetCostModelMeasured() const
{
  return !this->Internal->UsingDefaults;
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
constexpr double Zooms[] = { 1.0, 0.7, 1.8 };
constexpr double Fractions[] = { 1.0, 0.5, 0.2, 0.0 };
// Steps: 0 the coarsest levels at the first zoom, 1 the probe at a quarter
// of what the target affords, then 2 + 4 z + f for zoom z and fraction f.
constexpr std::size_t StepCount = 2 + 3 * 4;
}

void vtkTimeCriticalRenderer::RunCalibration()
{
  Internals& in = *this->Internal;
  auto& run = in.Calibration;
  const auto start = Clock::now();
  run = Internals::CalibrationRun();
  this->CalibrationAttempted = true;
  // With UseDesiredUpdateRate the interactive target is not known in a still
  // frame; the setting is then the yardstick (and covers faster targets).
  run.Sizing = std::isfinite(in.EffectiveTarget)
    ? std::max(in.EffectiveTarget, this->TargetFrameTime)
    : this->TargetFrameTime;
  run.TriangleCost = std::max(in.Model.GetCoefficients().Triangle, 1e-12);
  vtkCamera* camera = this->GetActiveCamera();
  const double savedAngle = camera->GetViewAngle();
  const double savedScale = camera->GetParallelScale();
  const double deadline = CalibrationTimeLimit * run.Sizing;
  while (run.Step < StepCount && Seconds(start, Clock::now()) <= deadline)
  {
    this->CalibrationStep(savedAngle, savedScale);
  }
  camera->SetViewAngle(savedAngle);
  camera->SetParallelScale(savedScale);
  in.FramePending = false;
  this->CalibrationTime = Seconds(start, Clock::now());
  this->FinishCalibration();
}

void vtkTimeCriticalRenderer::CalibrationStep(double savedAngle, double savedScale)
{
  Internals& in = *this->Internal;
  auto& run = in.Calibration;
  const std::size_t step = run.Step++;
  const std::size_t zoom = step < 2 ? 0 : (step - 2) / 4;
  const std::size_t fraction = step < 2 ? 0 : (step - 2) % 4;
  if (step >= 2 && zoom == 0 && Fractions[fraction] == 0.0)
  {
    return; // step 0 measured it
  }
  vtkCamera* camera = this->GetActiveCamera();
  camera->SetViewAngle(savedAngle);
  camera->SetParallelScale(savedScale);
  camera->Zoom(Zooms[zoom]);
  this->MeasureObjects();
  double visible = 0.0;
  for (std::size_t o = 0; o < in.ObjectActor.size(); ++o)
  {
    visible += in.Culled[o] ? 0.0 : in.MaxTriangles[o];
  }
  if (!(visible > 0.0))
  {
    return;
  }
  if (step == 0)
  {
    this->CalibrationSample(0.0, 1, false); // uploads the vertex data
    run.CoarseTime = this->CalibrationSample(0.0, 2);
    run.CoarseTriangles = in.Features[timecritical::FrameCostModel::FeatureTriangles];
    return;
  }
  if (step == 1)
  {
    const double probe = std::min(1.0, 0.25 * run.Sizing / run.TriangleCost / visible);
    const double probeTime = this->CalibrationSample(probe, 2);
    const double probeTriangles = in.Features[timecritical::FrameCostModel::FeatureTriangles];
    const double slope = (probeTime - run.CoarseTime) / (probeTriangles - run.CoarseTriangles);
    if (std::isfinite(slope) && slope > 0.0)
    {
      run.TriangleCost = slope;
    }
    return;
  }
  // What the target affords at the measured cost, largest first: every
  // buffer grows once, in the first of its renders.
  const double largest = std::min(1.0, run.Sizing / run.TriangleCost / visible);
  this->CalibrationSample(Fractions[fraction] * largest, 2);
}

double vtkTimeCriticalRenderer::CalibrationSample(double r, int renders, bool record)
{
  // One sample: the fastest of `renders` renders, features from the last
  // (not recorded: a render that uploads the vertex data).
  Internals& in = *this->Internal;
  auto& run = in.Calibration;
  for (std::size_t o = 0; o < in.ObjectActor.size(); ++o)
  {
    in.Resolution[o] = in.Culled[o] ? 0.0 : std::max(r, 1e-9);
  }
  in.ApplyResolutions();
  double best = tcr::Infinity;
  for (int k = 0; k < renders; ++k)
  {
    const auto start = Clock::now();
    this->Superclass::DeviceRender();
    glFinish();
    ++this->CalibrationRenders;
    best = std::min(best, Seconds(start, Clock::now()));
  }
  this->FinishFrame();
  if (record && run.Samples < Internals::CalibrationRun::MaxSamples)
  {
    run.Times[run.Samples] = best;
    std::copy(in.Features.begin(), in.Features.end(), run.X + run.Samples * tcr::FeatureCount);
    ++run.Samples;
  }
  return best;
}

void vtkTimeCriticalRenderer::FinishCalibration()
{
  Internals& in = *this->Internal;
  auto& run = in.Calibration;
  if (run.Samples == 0)
  {
    // Nothing in view at any zoom (a script's first render comes before its
    // camera is reset, for instance): try again in a later frame.
    this->CalibrationAttempted = false;
    return;
  }
  // The fixed per-frame work outside DeviceRender() (swap, window events) is
  // not in these samples; online refinement adds it within a few frames.
  // The fit is bounded by the physical floors only: it is the measurement
  // the later, relative floors come from.
  const auto previousFloors = in.Model.GetMinimumCoefficients();
  in.SetCoefficientFloors(false);
  if (run.Samples >= 3 && in.Calibrator.Calibrate(run.X, run.Times, run.Samples))
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
}
