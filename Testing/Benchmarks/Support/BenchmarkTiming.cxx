// SPDX-License-Identifier: BSD-3-Clause
#include "BenchmarkTiming.h"

#include "W1SceneSpecification.h"

#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

namespace timecritical
{
namespace benchmark
{
double Seconds(Clock::time_point start, Clock::time_point end)
{
  return std::chrono::duration<double>(end - start).count();
}

double TimedRender(vtkRenderWindow* window)
{
  const Clock::time_point start = Clock::now();
  window->Render();
  window->WaitForCompletion();
  return Seconds(start, Clock::now());
}

void SetBackground(vtkRenderer* renderer)
{
  const auto& background = W1SceneSpecification::Get().Background;
  renderer->SetBackground(background[0], background[1], background[2]);
}
}
}
