// SPDX-License-Identifier: BSD-3-Clause
// vtkTimeCriticalRenderer's focus: where it is each frame (a fixed point, the
// screen centre or the interactor's cursor) and how an object's benefit falls
// with its distance from it (Reddy's eccentricity model or Funkhouser &
// Séquin's linear fall-off, timecritical::DegradationModel).
#include "vtkTimeCriticalRenderer.h"

#include "vtkTimeCriticalRendererInternals.h"

#include "vtkRenderWindowInteractor.h"

using namespace timecritical::rendering;

void vtkTimeCriticalRenderer::SetFocusMode(int mode)
{
  if (mode < FIXED_POINT || mode > CURSOR)
  {
    vtkErrorMacro("Unknown focus mode " << mode << "; keeping " << this->FocusMode);
    return;
  }
  if (mode != this->FocusMode)
  {
    this->FocusMode = mode;
    this->Modified();
  }
}

void vtkTimeCriticalRenderer::SetFocusFalloff(int falloff)
{
  if (falloff < FAMILY_DEFAULT || falloff > LINEAR)
  {
    vtkErrorMacro("Unknown focus fall-off " << falloff << "; keeping " << this->FocusFalloff);
    return;
  }
  if (falloff != this->FocusFalloff)
  {
    this->FocusFalloff = falloff;
    this->Modified();
  }
}

void vtkTimeCriticalRenderer::SetLinearFalloffDegrees(double degrees)
{
  if (timecritical::CheckPositiveSetting(this, "LinearFalloffDegrees", degrees) &&
    degrees != this->LinearFalloffDegrees)
  {
    this->LinearFalloffDegrees = degrees;
    this->Modified();
  }
}

void vtkTimeCriticalRenderer::UpdateFocus()
{
  this->LastFocus[0] = this->FocusPoint[0];
  this->LastFocus[1] = this->FocusPoint[1];
  if (this->FocusMode == SCREEN_CENTER)
  {
    this->LastFocus[0] = this->LastFocus[1] = 0.5;
    return;
  }
  vtkRenderWindow* window = this->GetRenderWindow();
  vtkRenderWindowInteractor* interactor = window ? window->GetInteractor() : nullptr;
  if (this->FocusMode != CURSOR || !interactor)
  {
    return;
  }
  // The event position is in window pixels (origin bottom left, as display
  // coordinates): into this viewport's normalized coordinates.
  const int* size = window->GetSize();
  const double* viewport = this->GetViewport();
  const int* event = interactor->GetEventPosition();
  const double width = (viewport[2] - viewport[0]) * size[0];
  const double height = (viewport[3] - viewport[1]) * size[1];
  if (!(width > 0.0) || !(height > 0.0))
  {
    return;
  }
  const double x = (event[0] - viewport[0] * size[0]) / width;
  const double y = (event[1] - viewport[1] * size[1]) / height;
  this->LastFocus[0] = std::min(1.0, std::max(0.0, x));
  this->LastFocus[1] = std::min(1.0, std::max(0.0, y));
}

int vtkTimeCriticalRenderer::EccentricityModel(int familyDefault) const
{
  using Model = timecritical::DegradationModel::EccentricityModel;
  switch (this->FocusFalloff)
  {
    case REDDY:
      return static_cast<int>(Model::Reddy);
    case LINEAR:
      return static_cast<int>(Model::Linear);
    default:
      return familyDefault;
  }
}
