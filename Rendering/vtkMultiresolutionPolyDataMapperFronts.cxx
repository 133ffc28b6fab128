// SPDX-License-Identifier: BSD-3-Clause
// vtkMultiresolutionPolyDataMapper: view-dependent refinement of the leaves
// that carry a merge tree (their fronts follow the renderer's camera at every
// render) and the refinement settings, which are render state.
#include "vtkMultiresolutionPolyDataMapperInternals.h"

#include "RefinementSettingChecks.h"
#include "RefinementViewFromCamera.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLCamera.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace
{
/// Sets a refinement setting as render state: the fronts and the index buffer
/// follow it (version bump), the vertex buffers and shaders do not.
template <typename T>
void SetRenderState(T& member, T value, unsigned long& version)
{
  if (member != value)
  {
    member = value;
    ++version;
  }
}
}

void vtkMultiresolutionPolyDataMapper::SetViewDependentRefinement(bool on)
{
  SetRenderState(this->ViewDependentRefinement, on, this->Internal->ResolutionVersion);
}

void vtkMultiresolutionPolyDataMapper::SetRefinementMode(int mode)
{
  SetRenderState(this->RefinementMode, static_cast<int>(timecritical::ClampRefinementMode(mode)),
    this->Internal->ResolutionVersion);
}

void vtkMultiresolutionPolyDataMapper::SetBackFaceSimplification(bool on)
{
  SetRenderState(this->BackFaceSimplification, on, this->Internal->ResolutionVersion);
}

void vtkMultiresolutionPolyDataMapper::SetSilhouetteRefinement(bool on)
{
  SetRenderState(this->SilhouetteRefinement, on, this->Internal->ResolutionVersion);
}

void vtkMultiresolutionPolyDataMapper::SetHighlightRefinement(bool on)
{
  SetRenderState(this->HighlightRefinement, on, this->Internal->ResolutionVersion);
}

void vtkMultiresolutionPolyDataMapper::SetPixelThreshold(double tau)
{
  if (timecritical::CheckNonNegativeSetting(this, "PixelThreshold", tau))
  {
    SetRenderState(this->PixelThreshold, tau, this->Internal->ResolutionVersion);
  }
}

void vtkMultiresolutionPolyDataMapper::SetRefinementTimeLimit(double seconds)
{
  if (timecritical::CheckNonNegativeSetting(this, "RefinementTimeLimit", seconds))
  {
    SetRenderState(this->RefinementTimeLimit, seconds, this->Internal->ResolutionVersion);
  }
}

void vtkMultiresolutionPolyDataMapper::SetSilhouetteFactor(double factor)
{
  if (timecritical::CheckFactorSetting(this, "SilhouetteFactor", factor))
  {
    this->SilhouetteFactor = factor;
  }
}

void vtkMultiresolutionPolyDataMapper::SetHighlightFactor(double factor)
{
  if (timecritical::CheckFactorSetting(this, "HighlightFactor", factor))
  {
    this->HighlightFactor = factor;
  }
}

//------------------------------------------------------------------------------
static_assert(vtkMultiresolutionPolyDataMapper::BUDGET == timecritical::RefinementModeBudget &&
    vtkMultiresolutionPolyDataMapper::FIXED_ACCURACY == timecritical::RefinementModeFixedAccuracy,
  "one numbering of the refinement modes (RefinementSettings.h)");

timecritical::RefinementSettings vtkMultiresolutionPolyDataMapper::Internals::GetSettings(
  const vtkMultiresolutionPolyDataMapper& mapper)
{
  timecritical::RefinementSettings settings;
  settings.Mode = timecritical::ClampRefinementMode(mapper.RefinementMode);
  settings.PixelThreshold = mapper.PixelThreshold;
  settings.BackFaceSimplification = mapper.BackFaceSimplification;
  settings.SilhouetteRefinement = mapper.SilhouetteRefinement;
  settings.SilhouetteFactor = mapper.SilhouetteFactor;
  settings.HighlightRefinement = mapper.HighlightRefinement;
  settings.HighlightFactor = mapper.HighlightFactor;
  settings.TimeLimit = mapper.RefinementTimeLimit;
  return settings;
}

timecritical::RefinementView vtkMultiresolutionPolyDataMapper::Internals::ComputeView(
  vtkRenderer* ren, vtkActor* act)
{
  // The view of the draw in the leaves' own coordinates (all share the
  // actor's matrix). The planes come from the world-to-clip matrix the draw
  // uses, cached by the camera until it changes (vtkCamera::GetFrustumPlanes()
  // would allocate at every call).
  vtkCamera* camera = ren->GetActiveCamera();
  timecritical::CameraViewOptions options;
  timecritical::SetViewportFromRenderer(ren, options);
  options.ModelMatrix = act->GetMatrix()->GetData();
  if (auto* glCamera = vtkOpenGLCamera::SafeDownCast(camera))
  {
    vtkMatrix4x4 *wcvc = nullptr, *vcdc = nullptr, *wcdc = nullptr;
    vtkMatrix3x3* normals = nullptr;
    glCamera->GetKeyMatrices(ren, wcvc, normals, vcdc, wcdc);
    options.OpenGLWorldToClip = wcdc->GetData();
  }
  double toLight[3];
  if (timecritical::GetFirstLightDirection(ren, toLight))
  {
    options.LightDirection = toLight;
  }
  return timecritical::ComputeRefinementView(camera, options);
}


void vtkMultiresolutionPolyDataMapper::RefineObjects(vtkRenderer* ren, vtkActor* act)
{
  Internals& in = *this->Internal;
  this->RefinementTime = 0.0;
  bool any = false;
  for (auto& object : in.Objects)
  {
    object.Splits = object.Merges = 0;
    object.RefinementTime = 0.0;
    any = any || (object.Refinement && object.Visible && object.Resolution > 0.0);
  }
  if (!any || !this->ViewDependentRefinement)
  {
    return;
  }

  const timecritical::RefinementView view = Internals::ComputeView(ren, act);
  const timecritical::RefinementSettings settings = Internals::GetSettings(*this);

  // The time limit is shared by the fronts drawn this render.
  int fronts = 0;
  for (const auto& object : in.Objects)
  {
    fronts += object.Refinement && object.Visible && object.Resolution > 0.0;
  }
  const double limit = this->RefinementTimeLimit / std::max(fronts, 1);

  bool changed = false;
  for (auto& object : in.Objects)
  {
    if (!object.Refinement || !object.Visible || !(object.Resolution > 0.0))
    {
      continue; // culled objects keep their front for when they come back
    }
    if (in.RefineFront(object, view, settings, limit))
    {
      ++object.FrontVersion; // its slot is rewritten, the others' are not
      changed = true;
    }
    this->RefinementTime += object.RefinementTime;
  }
  if (changed)
  {
    ++in.ResolutionVersion; // the index buffer follows the fronts
  }
}

bool vtkMultiresolutionPolyDataMapper::Internals::RefineFront(Object& object,
  const timecritical::RefinementView& view, const timecritical::RefinementSettings& settings,
  double limit)
{
  timecritical::ViewDependentRefinement& front = *object.Refinement;
  front.SetView(view);
  timecritical::ApplyRefinementSettings(settings, front);
  double budget = std::min<double>(
    std::lround(object.Resolution * object.NumberOfTriangles), object.NumberOfTriangles);
  bool limited = false;
  if (limit > 0.0)
  {
    // A split or a merge changes about two triangles; until a rate is
    // measured, assume 2 us per operation.
    const double rate = object.OperationsPerSecond > 0.0 ? object.OperationsPerSecond : 5e5;
    const double step = object.StepScale * (2.0 * limit * rate + 64.0);
    const double current = front.GetNumberOfDisplayTriangles();
    const double wanted = budget;
    budget = std::min(std::max(budget, current - step), current + step);
    limited = budget != wanted;
  }
  const auto start = std::chrono::steady_clock::now();
  const timecritical::RefinementStatistics& statistics = settings.Mode == timecritical::RefinementMode::FixedAccuracy
    ? front.UpdateFixedAccuracy()
    // The step keeps the work near the limit; the core's own deadline
    // (twice the limit, at least 2 ms so that every update makes progress)
    // stops what the measured rate did not foresee.
    : front.UpdateBudget(static_cast<uint32_t>(std::max(budget, 0.0)),
        limit > 0.0 ? std::max(2.0 * limit, 2e-3) : 0.0);
  object.RefinementTime =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double operations = static_cast<double>(statistics.Splits) + statistics.Merges;
  if (operations > 0)
  {
    object.StepScale = 1.0;
  }
  else if (limited)
  {
    object.StepScale = std::min(2.0 * object.StepScale, 1e6);
  }
  if (operations >= 256 && object.RefinementTime > 0.0)
  {
    // Smoothed: one slow frame (a page fault, another process) must not
    // freeze the front.
    const double measured = operations / object.RefinementTime;
    object.OperationsPerSecond = object.OperationsPerSecond > 0.0
      ? 0.7 * object.OperationsPerSecond + 0.3 * measured
      : measured;
  }
  object.Splits = statistics.Splits;
  object.Merges = statistics.Merges;
  return statistics.Splits > 0 || statistics.Merges > 0;
}
