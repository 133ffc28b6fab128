// SPDX-License-Identifier: BSD-3-Clause
#include "RenderingAlgorithm.h"

namespace timecritical
{
const char* GetRenderingAlgorithmName(RenderingAlgorithm algorithm)
{
  switch (algorithm)
  {
    case RenderingAlgorithm::PerFragmentLit:
      return "per-fragment lit";
    case RenderingAlgorithm::PerVertexLit:
      return "per-vertex lit";
    case RenderingAlgorithm::Flat:
      return "flat";
    case RenderingAlgorithm::Unlit:
      return "unlit";
  }
  return "unknown";
}
}
