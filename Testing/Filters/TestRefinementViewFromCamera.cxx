// SPDX-License-Identifier: BSD-3-Clause
// Tests of ComputeRefinementView(): a vtkCamera, a viewport and an optional
// model matrix give the RefinementView the mapper and the filter refine for.
#include "RefinementViewFromCamera.h"

#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkRenderer.h"
#include "vtkTransform.h"

#include <gtest/gtest.h>

#include <cmath>

using timecritical::CameraViewOptions;
using timecritical::ComputeRefinementView;
using timecritical::RefinementView;

namespace
{
void SetUpCamera(vtkCamera* camera)
{
  camera->SetPosition(1.0, 2.0, 5.0);
  camera->SetFocalPoint(0.5, -0.25, 0.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(40.0);
  camera->SetClippingRange(0.5, 20.0);
  camera->SetParallelScale(3.0);
}

/// An object-to-world matrix: rotation, uniform scale 2, translation.
void ModelMatrix(vtkMatrix4x4* matrix)
{
  vtkNew<vtkTransform> transform;
  transform->Translate(0.5, -1.0, 2.0);
  transform->RotateWXYZ(30.0, 0.3, 1.0, 0.2);
  transform->Scale(2.0, 2.0, 2.0);
  matrix->DeepCopy(transform->GetMatrix());
}

double PlaneValue(const double plane[4], const double point[3])
{
  return plane[0] * point[0] + plane[1] * point[1] + plane[2] * point[2] + plane[3];
}
}

TEST(RefinementViewFromCamera, WorldCoordinatesTakeTheCameraAsItIs)
{
  vtkNew<vtkCamera> camera;
  SetUpCamera(camera);
  CameraViewOptions options;
  options.ViewportWidth = 800;
  options.ViewportHeight = 600;
  options.NumberOfFrustumPlanes = 4;
  options.UseNearClippingDistance = false;
  const double light[3] = { 0.0, 3.0, 4.0 };
  options.LightDirection = light;
  const RefinementView view = ComputeRefinementView(camera, options);
  for (int k = 0; k < 3; ++k)
  {
    EXPECT_EQ(view.Eye[k], camera->GetPosition()[k]);
    EXPECT_EQ(view.Direction[k], camera->GetDirectionOfProjection()[k]);
    EXPECT_EQ(view.LightDirection[k], light[k]); // not normalized: the refinement does that
  }
  EXPECT_FALSE(view.Parallel);
  EXPECT_EQ(view.ViewportHeight, 600.0);
  EXPECT_EQ(view.ViewAngle, 40.0);
  EXPECT_EQ(view.ParallelScale, 3.0);
  EXPECT_EQ(view.NearDistance, 0.0);
  ASSERT_EQ(view.NumberOfFrustumPlanes, 4);
  double planes[24];
  camera->GetFrustumPlanes(800.0 / 600.0, planes);
  for (int i = 0; i < 4; ++i)
  {
    for (int c = 0; c < 4; ++c)
    {
      EXPECT_EQ(view.FrustumPlanes[i][c], planes[4 * i + c]) << i << " " << c;
    }
  }
}

TEST(RefinementViewFromCamera, DefaultsGiveSixPlanesNearDistanceAndAHeadlight)
{
  vtkNew<vtkCamera> camera;
  SetUpCamera(camera);
  const RefinementView view = ComputeRefinementView(camera, CameraViewOptions());
  EXPECT_EQ(view.NumberOfFrustumPlanes, 6);
  EXPECT_EQ(view.NearDistance, 0.5);
  EXPECT_EQ(view.ViewportHeight, 512.0);
  for (int k = 0; k < 3; ++k)
  {
    EXPECT_EQ(view.LightDirection[k], -view.Direction[k]);
  }
  // The focal point is inside every plane; a point behind the eye is not.
  const double* focal = camera->GetFocalPoint();
  double behind[3];
  for (int k = 0; k < 3; ++k)
  {
    behind[k] = camera->GetPosition()[k] - camera->GetDirectionOfProjection()[k];
  }
  for (int i = 0; i < 6; ++i)
  {
    EXPECT_GT(PlaneValue(view.FrustumPlanes[i], focal), 0.0) << i;
  }
  EXPECT_LT(PlaneValue(view.FrustumPlanes[4], behind), 0.0);
  // No planes asked for: none.
  CameraViewOptions none;
  none.NumberOfFrustumPlanes = 0;
  EXPECT_EQ(ComputeRefinementView(camera, none).NumberOfFrustumPlanes, 0);
}

TEST(RefinementViewFromCamera, HorizontalViewAngleBecomesVertical)
{
  vtkNew<vtkCamera> camera;
  SetUpCamera(camera);
  camera->SetUseHorizontalViewAngle(true);
  CameraViewOptions options;
  options.ViewportWidth = 1000;
  options.ViewportHeight = 500;
  const RefinementView view = ComputeRefinementView(camera, options);
  const double expected = 2.0 *
    vtkMath::DegreesFromRadians(std::atan(std::tan(vtkMath::RadiansFromDegrees(20.0)) * 0.5));
  EXPECT_NEAR(view.ViewAngle, expected, 1e-12);
  EXPECT_LT(view.ViewAngle, 40.0);
  // A viewport of no size keeps the angle as it is.
  options.ViewportWidth = 0;
  EXPECT_EQ(ComputeRefinementView(camera, options).ViewAngle, 40.0);
  EXPECT_EQ(ComputeRefinementView(camera, options).ViewportHeight, 500.0);
}

TEST(RefinementViewFromCamera, ModelMatrixGivesTheViewInObjectCoordinates)
{
  vtkNew<vtkCamera> camera;
  SetUpCamera(camera);
  camera->SetParallelProjection(true);
  vtkNew<vtkMatrix4x4> model;
  ModelMatrix(model);
  vtkNew<vtkMatrix4x4> toObject;
  vtkMatrix4x4::Invert(model, toObject);
  CameraViewOptions options;
  options.ModelMatrix = model->GetData();
  const double light[3] = { 1.0, 1.0, 0.0 };
  options.LightDirection = light;
  const RefinementView view = ComputeRefinementView(camera, options);

  double eye[4] = { 0, 0, 0, 1 };
  std::copy(camera->GetPosition(), camera->GetPosition() + 3, eye);
  double expectedEye[4];
  toObject->MultiplyPoint(eye, expectedEye);
  double direction[4] = { 0, 0, 0, 0 }, lightWorld[4] = { 1.0, 1.0, 0.0, 0.0 };
  std::copy(camera->GetDirectionOfProjection(), camera->GetDirectionOfProjection() + 3, direction);
  double expectedDirection[4], expectedLight[4];
  toObject->MultiplyPoint(direction, expectedDirection);
  toObject->MultiplyPoint(lightWorld, expectedLight);
  vtkMath::Normalize(expectedDirection);
  vtkMath::Normalize(expectedLight);
  for (int k = 0; k < 3; ++k)
  {
    EXPECT_NEAR(view.Eye[k], expectedEye[k], 1e-12);
    EXPECT_NEAR(view.Direction[k], expectedDirection[k], 1e-12);
    EXPECT_NEAR(view.LightDirection[k], expectedLight[k], 1e-12);
  }
  EXPECT_TRUE(view.Parallel);
  EXPECT_NEAR(view.ParallelScale, 1.5, 1e-12); // world lengths halve in the object
  EXPECT_NEAR(view.NearDistance, 0.25, 1e-12);

  // A plane in object coordinates has the world plane's value at the world point.
  double planes[24];
  camera->GetFrustumPlanes(1.0, planes);
  const double objectPoint[4] = { 0.3, -0.7, 1.1, 1.0 };
  double worldPoint[4];
  model->MultiplyPoint(objectPoint, worldPoint);
  for (int i = 0; i < 6; ++i)
  {
    EXPECT_NEAR(PlaneValue(view.FrustumPlanes[i], objectPoint),
      PlaneValue(planes + 4 * i, worldPoint), 1e-9)
      << i;
  }
}

TEST(RefinementViewFromCamera, OpenGLWorldToClipGivesTheCameraPlanes)
{
  vtkNew<vtkCamera> camera;
  SetUpCamera(camera);
  const double aspect = 1.25;
  // vtkOpenGLCamera's wcdc: the transposed world-to-clip matrix.
  vtkNew<vtkMatrix4x4> wcdc;
  wcdc->DeepCopy(camera->GetCompositeProjectionTransformMatrix(aspect, -1, 1));
  wcdc->Transpose();
  CameraViewOptions options;
  options.AspectRatio = aspect;
  const RefinementView fromCamera = ComputeRefinementView(camera, options);
  options.OpenGLWorldToClip = wcdc->GetData();
  const RefinementView fromMatrix = ComputeRefinementView(camera, options);
  ASSERT_EQ(fromMatrix.NumberOfFrustumPlanes, 6);
  // The same planes up to scale (vtkCamera normalizes its own; the refinement
  // normalizes every plane it is given).
  for (int i = 0; i < 6; ++i)
  {
    const double matrixLength = vtkMath::Norm(fromMatrix.FrustumPlanes[i]);
    const double cameraLength = vtkMath::Norm(fromCamera.FrustumPlanes[i]);
    ASSERT_GT(matrixLength, 0.0);
    EXPECT_NEAR(cameraLength, 1.0, 1e-12);
    for (int c = 0; c < 4; ++c)
    {
      EXPECT_NEAR(fromMatrix.FrustumPlanes[i][c] / matrixLength, fromCamera.FrustumPlanes[i][c],
        1e-12)
        << i << " " << c;
    }
  }
}

TEST(RefinementViewFromCamera, FirstSwitchedOnLightGivesTheLightDirection)
{
  vtkNew<vtkRenderer> renderer;
  double toLight[3] = { 0, 0, 0 };
  EXPECT_FALSE(timecritical::GetFirstLightDirection(renderer, toLight));
  vtkNew<vtkLight> off;
  off->SetPosition(0, 0, 1);
  off->SwitchOff();
  vtkNew<vtkLight> on;
  on->SetPosition(1, 2, 3);
  on->SetFocalPoint(1, 2, 0);
  renderer->AddLight(off);
  renderer->AddLight(on);
  ASSERT_TRUE(timecritical::GetFirstLightDirection(renderer, toLight));
  EXPECT_EQ(toLight[0], 0.0);
  EXPECT_EQ(toLight[1], 0.0);
  EXPECT_EQ(toLight[2], 3.0);
  // A first light with no direction: the caller uses a headlight.
  on->SetFocalPoint(1, 2, 3);
  EXPECT_FALSE(timecritical::GetFirstLightDirection(renderer, toLight));
}
