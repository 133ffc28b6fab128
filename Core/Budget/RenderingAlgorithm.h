// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_RenderingAlgorithm_h
#define timecritical_RenderingAlgorithm_h

#include "TimeCriticalBudgetCoreExport.h"

#include <cstddef>

namespace timecritical
{
/**
 * The rendering algorithms an object can be drawn with (Funkhouser & Séquin's
 * R of the object tuple (O, L, R)), from the most to the least accurate:
 * - PerFragmentLit: lighting per fragment (VTK's default, even for "Gouraud");
 * - PerVertexLit: lighting per vertex, colours interpolated (true Gouraud);
 * - Flat: one normal, hence one colour, per triangle;
 * - Unlit: the colour alone, no lighting.
 * The numbering is stable (statistics and resolution maps store it).
 */
enum class RenderingAlgorithm : unsigned char
{
  PerFragmentLit = 0,
  PerVertexLit = 1,
  Flat = 2,
  Unlit = 3
};

constexpr std::size_t RenderingAlgorithmCount = 4;

/// "per-fragment lit", "per-vertex lit", "flat", "unlit"; "unknown" out of range.
TIMECRITICALBUDGETCORE_EXPORT const char* GetRenderingAlgorithmName(RenderingAlgorithm algorithm);
}

#endif
