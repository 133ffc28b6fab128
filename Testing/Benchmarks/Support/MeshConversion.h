// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_MeshConversion_h
#define timecritical_MeshConversion_h

/**
 * The benchmarks' meshes between the test support's TriangleMesh (what the
 * VTK-free cores take) and vtkPolyData (what the filters and mappers take).
 */
#include "MeshIO.h"

#include <vtkSmartPointer.h>

class vtkPolyData;

namespace timecritical
{
namespace benchmark
{
/// Double points, the triangles in order.
vtkSmartPointer<vtkPolyData> ToPolyData(const timecritical::testing::TriangleMesh& mesh);

/// The points and triangles of a polydata of triangles only; anything else
/// (lines, strips, polygons of other sizes) throws std::runtime_error.
timecritical::testing::TriangleMesh FromPolyData(vtkPolyData* poly);

/// `input` with one smooth normal per point (no splitting: the vertices the
/// TOM orders are the mesh's own).
vtkSmartPointer<vtkPolyData> WithNormals(vtkPolyData* input);
}
}

#endif
