// SPDX-License-Identifier: BSD-3-Clause
#include "RefinementViewFromCamera.h"

#include "vtkCamera.h"
#include "vtkCollection.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cmath>

namespace timecritical
{
namespace
{
/// World to object coordinates (or the identity when there is no model matrix).
class ObjectFrame
{
public:
  explicit ObjectFrame(const double* model)
    : Model(model)
  {
    if (model)
    {
      vtkMatrix4x4::Invert(model, this->ToObject);
      // World lengths to object lengths: the uniform scale (cube root of the
      // determinant for the rare non-uniform case).
      const double scale = std::cbrt(std::abs(vtkMatrix4x4::Determinant(model)));
      this->Scale = scale > 0.0 ? scale : 1.0;
    }
  }

  void Point(const double w[3], double o[3]) const
  {
    if (!this->Model)
    {
      std::copy(w, w + 3, o);
      return;
    }
    const double* m = this->ToObject;
    for (int r = 0; r < 3; ++r)
    {
      o[r] = m[4 * r] * w[0] + m[4 * r + 1] * w[1] + m[4 * r + 2] * w[2] + m[4 * r + 3];
    }
  }

  /// Transformed and normalized with a model matrix, as it is without.
  void Direction(const double w[3], double o[3]) const
  {
    if (!this->Model)
    {
      std::copy(w, w + 3, o);
      return;
    }
    const double* m = this->ToObject;
    for (int r = 0; r < 3; ++r)
    {
      o[r] = m[4 * r] * w[0] + m[4 * r + 1] * w[1] + m[4 * r + 2] * w[2];
    }
    vtkMath::Normalize(o);
  }

  double Length(double world) const { return this->Model ? world / this->Scale : world; }

  /// A plane p (world) is p M in object coordinates (the refinement normalizes it).
  void Plane(const double p[4], double o[4]) const
  {
    if (!this->Model)
    {
      std::copy(p, p + 4, o);
      return;
    }
    const double* model = this->Model;
    for (int c = 0; c < 4; ++c)
    {
      o[c] = p[0] * model[c] + p[1] * model[4 + c] + p[2] * model[8 + c] + p[3] * model[12 + c];
    }
  }

private:
  const double* Model;
  double ToObject[16] = {};
  double Scale = 1.0;
};

/// Left, right, bottom, top, near, far: w +- x, w +- y, w +- z >= 0 inside.
void WorldFrustumPlanes(vtkCamera* camera, const CameraViewOptions& options, double planes[24])
{
  if (const double* wcdc = options.OpenGLWorldToClip)
  {
    // Row r of the clip matrix is column r of wcdc.
    for (int i = 0; i < 6; ++i)
    {
      const int axis = i / 2;
      const double sign = i % 2 == 0 ? 1.0 : -1.0;
      for (int c = 0; c < 4; ++c)
      {
        planes[4 * i + c] = wcdc[4 * c + 3] + sign * wcdc[4 * c + axis];
      }
    }
    return;
  }
  const double aspect = options.AspectRatio > 0.0
    ? options.AspectRatio
    : static_cast<double>(std::max(options.ViewportWidth, 1)) /
      std::max(options.ViewportHeight, 1);
  camera->GetFrustumPlanes(aspect, planes);
}

/// The vertical view angle: a horizontal one spans the width.
double VerticalViewAngle(vtkCamera* camera, int width, int height)
{
  const double angle = camera->GetViewAngle();
  if (!camera->GetUseHorizontalViewAngle() || width <= 0 || height <= 0)
  {
    return angle;
  }
  const double half = 0.5 * vtkMath::RadiansFromDegrees(angle);
  return 2.0 *
    vtkMath::DegreesFromRadians(std::atan(std::tan(half) * static_cast<double>(height) / width));
}
}

RefinementView ComputeRefinementView(vtkCamera* camera, const CameraViewOptions& options)
{
  RefinementView view;
  const ObjectFrame frame(options.ModelMatrix);
  frame.Point(camera->GetPosition(), view.Eye);
  frame.Direction(camera->GetDirectionOfProjection(), view.Direction);
  view.Parallel = camera->GetParallelProjection() != 0;
  view.ViewportHeight = std::max(options.ViewportHeight, 1);
  view.ViewAngle = VerticalViewAngle(camera, options.ViewportWidth, options.ViewportHeight);
  view.ParallelScale = frame.Length(camera->GetParallelScale());
  if (options.UseNearClippingDistance)
  {
    // Nothing nearer than the near plane is drawn: a node around the eye is
    // projected from there instead of with an unbounded error.
    view.NearDistance = frame.Length(camera->GetClippingRange()[0]);
  }
  view.NumberOfFrustumPlanes = std::min(std::max(options.NumberOfFrustumPlanes, 0), 6);
  if (view.NumberOfFrustumPlanes > 0)
  {
    double planes[24];
    WorldFrustumPlanes(camera, options, planes);
    for (int i = 0; i < view.NumberOfFrustumPlanes; ++i)
    {
      frame.Plane(planes + 4 * i, view.FrustumPlanes[i]);
    }
  }
  if (options.LightDirection)
  {
    frame.Direction(options.LightDirection, view.LightDirection);
  }
  else
  {
    for (int k = 0; k < 3; ++k)
    {
      view.LightDirection[k] = -view.Direction[k];
    }
  }
  return view;
}

void SetViewportFromRenderer(vtkRenderer* renderer, CameraViewOptions& options)
{
  renderer->GetTiledSize(&options.ViewportWidth, &options.ViewportHeight);
  options.AspectRatio = renderer->GetTiledAspectRatio();
}

bool GetFirstLightDirection(vtkRenderer* renderer, double toLight[3])
{
  vtkLightCollection* lights = renderer->GetLights();
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
        std::copy(world, world + 3, toLight);
        return true;
      }
      return false;
    }
  }
  return false;
}
}
