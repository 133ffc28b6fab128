// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_RefinementViewFromCamera_h
#define timecritical_RefinementViewFromCamera_h

#include "TimeCriticalFiltersModule.h" // for export macro
#include "ViewDependentRefinement.h"    // for RefinementView

class vtkCamera;
class vtkRenderer;

namespace timecritical
{
/**
 * What ComputeRefinementView() needs besides the camera. The defaults are a
 * 512 x 512 viewport, data in world coordinates, six frustum planes from the
 * camera, the near clipping distance and a headlight.
 */
struct CameraViewOptions
{
  /// Size of the viewport in pixels (a renderer's tiled size); values < 1 count as 1.
  int ViewportWidth = 512;
  int ViewportHeight = 512;
  /// Aspect ratio of the frustum planes; 0: ViewportWidth / ViewportHeight.
  double AspectRatio = 0.0;
  /**
   * Object-to-world matrix of the data, 16 values row by row (the
   * vtkMatrix4x4 layout, e.g. vtkProp3D::GetMatrix()->GetData()): the view is
   * then given in the object's coordinates. nullptr: the data is in world
   * coordinates and the camera's values are taken as they are.
   */
  const double* ModelMatrix = nullptr;
  /**
   * The world-to-clip matrix of the draw in OpenGL's layout, as
   * vtkOpenGLCamera::GetKeyMatrices() returns it (wcdc: element (c, r) is row
   * r, column c of the clip matrix). It gives the same planes as the camera
   * without vtkCamera::GetFrustumPlanes(), which allocates at every call.
   * nullptr: the planes come from vtkCamera::GetFrustumPlanes(AspectRatio).
   */
  const double* OpenGLWorldToClip = nullptr;
  /// 0 (no culling), 4 (left, right, bottom, top: the clipping range is not used) or 6.
  int NumberOfFrustumPlanes = 6;
  /// Project errors from no nearer than the camera's near clipping distance.
  bool UseNearClippingDistance = true;
  /// Towards the light in world coordinates (need not be unit); nullptr: a headlight.
  const double* LightDirection = nullptr;
};

/**
 * The view of `camera` for timecritical::ViewDependentRefinement: eye and
 * direction, projection, the vertical view angle (converted when the camera's
 * angle is horizontal), viewport height, frustum planes, near distance and
 * light direction, all in the coordinates of the data (see
 * CameraViewOptions::ModelMatrix). Lengths are divided by the model's uniform
 * scale (the cube root of its determinant). Allocates nothing when
 * OpenGLWorldToClip is given or NumberOfFrustumPlanes is 0, so that a mapper
 * may call it every frame.
 */
TIMECRITICALFILTERS_EXPORT RefinementView ComputeRefinementView(vtkCamera* camera, const CameraViewOptions& options);

/**
 * Fills `options` from `renderer`: its tiled viewport size and aspect ratio.
 * The light is left to the caller (see GetFirstLightDirection()).
 */
TIMECRITICALFILTERS_EXPORT void SetViewportFromRenderer(vtkRenderer* renderer, CameraViewOptions& options);

/**
 * The direction towards the first switched-on light of `renderer` in world
 * coordinates (position minus focal point, transformed by the light's
 * matrix). False when no light is on or the first one has no direction: the
 * caller then uses a headlight.
 */
TIMECRITICALFILTERS_EXPORT bool GetFirstLightDirection(vtkRenderer* renderer, double toLight[3]);
}

#endif
