// SPDX-License-Identifier: BSD-3-Clause
// Helpers shared by the GoogleTest tests that render (TestvtkMultiresolutionPolyDataMapper,
// TestvtkMultiresolutionPolyDataMapperFronts, TestvtkTimeCriticalRenderer, TestvtkTOMPolyDataMapper):
// the X server workaround, the bumpy test surface, event counting and reading
// back the window, so that the tests render and compare the same way.
#ifndef timecritical_RenderTestSupport_h
#define timecritical_RenderTestSupport_h

#include "vtkCallbackCommand.h"
#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>

namespace timecritical
{
namespace testing
{
/**
 * Xvfb resets when its last client disconnects, and a window opened during
 * the reset fails ("bad X server connection"): one window stays open for the
 * whole run, as each test opens and closes its own. Register it with
 * ::testing::AddGlobalTestEnvironment(new KeepDisplayOpen).
 */
class KeepDisplayOpen : public ::testing::Environment
{
public:
  void SetUp() override
  {
    this->Window = vtkSmartPointer<vtkRenderWindow>::New();
    this->Window->SetOffScreenRendering(1);
    this->Window->SetSize(1, 1);
    vtkNew<vtkRenderer> renderer;
    this->Window->AddRenderer(renderer);
    this->Window->Render();
  }
  void TearDown() override { this->Window = nullptr; }

private:
  vtkSmartPointer<vtkRenderWindow> Window;
};

/**
 * A deterministic closed bumpy sphere with point normals, a point array
 * "Height" (z) and a cell array "Patch" (five values), so that every
 * resolution and front shows and both kinds of scalars can be told apart.
 */
inline vtkSmartPointer<vtkPolyData> MakeBumpySurface(
  double radius, int theta, int phi, double cx, double cy, double cz, double frequency)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(radius);
  sphere->SetThetaResolution(theta);
  sphere->SetPhiResolution(phi);
  sphere->Update();
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->DeepCopy(sphere->GetOutput());
  data->GetPointData()->Initialize();
  vtkPoints* points = data->GetPoints();
  vtkNew<vtkFloatArray> height;
  height->SetName("Height");
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    const double bump = 1.0 +
      0.08 * std::sin(frequency * p[0] / radius) * std::sin(7.0 * p[1] / radius) *
        std::cos(5.0 * p[2] / radius);
    points->SetPoint(i, cx + p[0] * bump, cy + p[1] * bump, cz + p[2] * bump);
    height->InsertNextValue(static_cast<float>(p[2] / radius));
  }
  data->GetPointData()->AddArray(height);
  vtkNew<vtkIntArray> patch;
  patch->SetName("Patch");
  for (vtkIdType c = 0; c < data->GetNumberOfCells(); ++c)
  {
    patch->InsertNextValue(static_cast<int>((c * 7) % 5));
  }
  data->GetCellData()->AddArray(patch);
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(data);
  normals->SplittingOff();
  normals->Update();
  vtkSmartPointer<vtkPolyData> out = normals->GetOutput();
  return out;
}

/// Counts the events of one kind an object emits, and keeps the last message.
struct EventCounter
{
  EventCounter(vtkObject* object, unsigned long event)
  {
    this->Command->SetClientData(this);
    this->Command->SetCallback(
      [](vtkObject*, unsigned long, void* self, void* data)
      {
        auto* counter = static_cast<EventCounter*>(self);
        ++counter->Count;
        counter->Last = data ? static_cast<const char*>(data) : "";
      });
    object->AddObserver(event, this->Command);
  }
  int Count = 0;
  std::string Last;
  vtkNew<vtkCallbackCommand> Command;
};

/**
 * Writes the back buffer of `window` to a PNG file; `rerender` lets the grab
 * render the window first (vtkWindowToImageFilter's ShouldRerender).
 */
inline void WriteWindowPNG(vtkRenderWindow* window, const std::string& path, bool rerender)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->SetShouldRerender(rerender);
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  writer->SetFileName(path.c_str());
  writer->Write();
}

/// Pixels of the last render of `window` that differ from the background (0.1, 0.1, 0.15).
inline int CountForegroundPixels(vtkRenderWindow* window)
{
  vtkNew<vtkUnsignedCharArray> pixels;
  const int* size = window->GetSize();
  window->GetPixelData(0, 0, size[0] - 1, size[1] - 1, 0, pixels);
  int count = 0;
  for (vtkIdType i = 0; i < pixels->GetNumberOfTuples(); ++i)
  {
    const unsigned char* p = pixels->GetPointer(3 * i);
    count += std::abs(p[0] - 26) + std::abs(p[1] - 26) + std::abs(p[2] - 38) > 6;
  }
  return count;
}
}
}

#endif
