// SPDX-License-Identifier: BSD-3-Clause
// vtkMultiresolutionPolyDataMapper: view-dependent refinement of the leaves
// that carry a merge tree (their fronts follow the renderer's camera at every
// render) and the refinement settings, which are render state.
#include "vtkMultiresolutionPolyDataMapperInternals.h"

#include "RefinementSettingChecks.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
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
  SetRenderState(this->RefinementMode, std::min(std::max(mode, static_cast<int>(BUDGET)),
    static_cast<int>(FIXED_ACCURACY)), this->Internal->ResolutionVersion);
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
namespace
{
/// World points and directions in the leaves' own coordinates (all share the actor's matrix).
struct ToObject
{
  explicit ToObject(vtkActor* act) { vtkMatrix4x4::Invert(act->GetMatrix()->GetData(), this->M); }
  void Point(const double w[3], double o[3]) const
  {
    for (int r = 0; r < 3; ++r)
    {
      o[r] = this->M[4 * r] * w[0] + this->M[4 * r + 1] * w[1] + this->M[4 * r + 2] * w[2] +
        this->M[4 * r + 3];
    }
  }
  void Direction(const double w[3], double o[3]) const
  {
    for (int r = 0; r < 3; ++r)
    {
      o[r] = this->M[4 * r] * w[0] + this->M[4 * r + 1] * w[1] + this->M[4 * r + 2] * w[2];
    }
    vtkMath::Normalize(o);
  }
  double M[16];
};

/// Eye, direction, projection and viewport of the active camera, in object coordinates.
void SetCameraView(
  vtkRenderer* ren, vtkActor* act, const ToObject& toObject, timecritical::RefinementView& view)
{
  vtkCamera* camera = ren->GetActiveCamera();
  toObject.Point(camera->GetPosition(), view.Eye);
  toObject.Direction(camera->GetDirectionOfProjection(), view.Direction);
  view.Parallel = camera->GetParallelProjection() != 0;
  int width = 0, height = 0;
  ren->GetTiledSize(&width, &height);
  view.ViewportHeight = std::max(height, 1);
  view.ViewAngle = camera->GetViewAngle();
  if (camera->GetUseHorizontalViewAngle() && width > 0 && height > 0)
  {
    // The projected error needs the vertical angle; a horizontal one spans the width.
    const double half = 0.5 * vtkMath::RadiansFromDegrees(view.ViewAngle);
    view.ViewAngle = 2.0 *
      vtkMath::DegreesFromRadians(std::atan(std::tan(half) * static_cast<double>(height) / width));
  }
  // World lengths to object lengths: the actor's uniform scale (cube root of
  // the determinant for the rare non-uniform case).
  const double scale = std::cbrt(std::abs(act->GetMatrix()->Determinant()));
  view.ParallelScale = camera->GetParallelScale() / (scale > 0.0 ? scale : 1.0);
  // Nothing nearer than the near plane is drawn: a node around the eye is
  // projected from there instead of with an unbounded error.
  view.NearDistance = camera->GetClippingRange()[0] / (scale > 0.0 ? scale : 1.0);
}

/// The frustum planes of the draw, in object coordinates.
void SetFrustumPlanes(vtkRenderer* ren, vtkActor* act, timecritical::RefinementView& view)
{
  // From the world-to-clip matrix the draw uses (cached by the camera until
  // it changes; vtkCamera::GetFrustumPlanes() would rebuild a transform
  // concatenation, allocating, at every call). vtkOpenGLCamera keeps it
  // transposed: row r of the clip matrix is column r of wcdc.
  vtkCamera* camera = ren->GetActiveCamera();
  double planes[24];
  if (auto* glCamera = vtkOpenGLCamera::SafeDownCast(camera))
  {
    vtkMatrix4x4 *wcvc = nullptr, *vcdc = nullptr, *wcdc = nullptr;
    vtkMatrix3x3* normals = nullptr;
    glCamera->GetKeyMatrices(ren, wcvc, normals, vcdc, wcdc);
    // Left, right, bottom, top, near, far: w +- x, w +- y, w +- z >= 0 inside.
    for (int i = 0; i < 6; ++i)
    {
      const int axis = i / 2;
      const double sign = i % 2 == 0 ? 1.0 : -1.0;
      for (int c = 0; c < 4; ++c)
      {
        planes[4 * i + c] = wcdc->GetElement(c, 3) + sign * wcdc->GetElement(c, axis);
      }
    }
  }
  else
  {
    camera->GetFrustumPlanes(ren->GetTiledAspectRatio(), planes);
  }
  const double* model = act->GetMatrix()->GetData();
  view.NumberOfFrustumPlanes = 6;
  for (int i = 0; i < 6; ++i)
  {
    // A plane p (world) is p M in object coordinates (the refinement
    // normalizes it).
    double* o = view.FrustumPlanes[i];
    for (int c = 0; c < 4; ++c)
    {
      o[c] = planes[4 * i] * model[c] + planes[4 * i + 1] * model[4 + c] +
        planes[4 * i + 2] * model[8 + c] + planes[4 * i + 3] * model[12 + c];
    }
  }
}

/// Towards the first switched-on light; a headlight when there is none.
void SetLightDirection(vtkRenderer* ren, const ToObject& toObject, timecritical::RefinementView& view)
{
  double toLight[3] = { -view.Direction[0], -view.Direction[1], -view.Direction[2] };
  vtkLightCollection* lights = ren->GetLights();
  vtkCollectionSimpleIterator it;
  lights->InitTraversal(it);
  while (vtkLight* light = lights->GetNextLight(it))
  {
    if (light->GetSwitch())
    {
      double position[3], focal[3], world[3];
      light->GetTransformedPosition(position);
      light->GetTransformedFocalPoint(focal);
      for (int k = 0; k < 3; ++k)
      {
        world[k] = position[k] - focal[k];
      }
      if (vtkMath::Norm(world) > 0.0)
      {
        toObject.Direction(world, toLight);
      }
      break;
    }
  }
  std::copy(toLight, toLight + 3, view.LightDirection);
}
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
    any = any || (object.Refinement && object.Resolution > 0.0);
  }
  if (!any || !this->ViewDependentRefinement)
  {
    return;
  }

  const ToObject toObject(act);
  timecritical::RefinementView view;
  SetCameraView(ren, act, toObject, view);
  SetFrustumPlanes(ren, act, view);
  SetLightDirection(ren, toObject, view);

  // The time limit is shared by the fronts drawn this render.
  int fronts = 0;
  for (const auto& object : in.Objects)
  {
    fronts += object.Refinement && object.Resolution > 0.0;
  }
  const double limit = this->RefinementTimeLimit / std::max(fronts, 1);

  bool changed = false;
  for (auto& object : in.Objects)
  {
    if (!object.Refinement || !(object.Resolution > 0.0))
    {
      continue; // culled objects keep their front for when they come back
    }
    if (in.RefineFront(object, view, *this, limit))
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
  const timecritical::RefinementView& view, const vtkMultiresolutionPolyDataMapper& settings,
  double limit)
{
  timecritical::ViewDependentRefinement& front = *object.Refinement;
  front.SetView(view);
  front.SetPixelThreshold(settings.PixelThreshold);
  front.SetBackFaceSimplification(settings.BackFaceSimplification);
  front.SetSilhouetteRefinement(settings.SilhouetteRefinement);
  front.SetSilhouetteFactor(settings.SilhouetteFactor);
  front.SetHighlightRefinement(settings.HighlightRefinement);
  front.SetHighlightFactor(settings.HighlightFactor);
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
  const timecritical::RefinementStatistics& statistics = settings.RefinementMode == FIXED_ACCURACY
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
