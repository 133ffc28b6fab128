// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_LoopSubdivision_h
#define timecritical_LoopSubdivision_h

/**
 * Loop subdivision of the benchmarks' inputs (W2's igea-loop1, the TOM
 * benchmark's igea-loop1 and the refinement benchmark's --loop), by
 * vtkLoopSubdivisionFilter in all of them, so that "igea after one Loop
 * subdivision" is one mesh wherever a benchmark names it.
 */
#include "MeshIO.h"

#include <vtkSmartPointer.h>

class vtkPolyData;

namespace timecritical
{
namespace benchmark
{
/// `levels` levels of Loop subdivision of a triangle polydata (levels >= 0).
vtkSmartPointer<vtkPolyData> LoopSubdivide(vtkPolyData* input, int levels);

/// The same on a TriangleMesh.
timecritical::testing::TriangleMesh LoopSubdivide(
  const timecritical::testing::TriangleMesh& mesh, int levels);
}
}

#endif
