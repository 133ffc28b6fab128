// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_BenchmarkTiming_h
#define timecritical_BenchmarkTiming_h

/**
 * Wall-clock timing of the benchmarks and the rendering constants they share
 * (window size, view angle, background), so that every benchmark's images are
 * comparable.
 */
#include <chrono>
#include <limits>

class vtkRenderWindow;
class vtkRenderer;

namespace timecritical
{
namespace benchmark
{
using Clock = std::chrono::steady_clock;
constexpr double NaN = std::numeric_limits<double>::quiet_NaN();
constexpr int WindowSize = 512;
constexpr double ViewAngle = 40.0;

double Seconds(Clock::time_point start, Clock::time_point end);

/// Seconds one call of `function` takes.
template <class Function>
double SecondsOf(Function&& function)
{
  const Clock::time_point start = Clock::now();
  function();
  return Seconds(start, Clock::now());
}

/// Wall clock around Render() with glFinish after it: the frame is only done
/// when the rasterizer is, whatever the window does at the buffer swap.
double TimedRender(vtkRenderWindow* window);

/// The benchmarks' background colour (the W1 scene's, see W1Scene.json).
void SetBackground(vtkRenderer* renderer);
}
}

#endif
