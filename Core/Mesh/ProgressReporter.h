// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_ProgressReporter_h
#define timecritical_ProgressReporter_h

#include <algorithm>
#include <functional>

namespace timecritical
{
namespace collapse
{
/// Forwards progress to the callback; remembers a request to stop.
class ProgressReporter
{
public:
  explicit ProgressReporter(const std::function<bool(double)>& callback)
    : Callback(callback)
  {
  }
  bool Report(double fraction)
  {
    if (!this->Callback || this->Stopped)
    {
      return !this->Stopped;
    }
    if (!this->Callback(std::min(std::max(fraction, 0.0), 1.0)))
    {
      this->Stopped = true;
    }
    return !this->Stopped;
  }
  bool WasStopped() const { return this->Stopped; }

private:
  const std::function<bool(double)>& Callback;
  bool Stopped = false;
};
}
}

#endif
