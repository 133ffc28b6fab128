// SPDX-License-Identifier: BSD-3-Clause
/**
 * A quick coarse stand-in for a polydata leaf while its hierarchy is built
 * in the background: vtkBinnedDecimation of its triangles on a grid of about
 * `divisions` bins a side (adjusted to the leaf's shape), keeping the
 * leaf's own points and point data (so the stand-in draws from the same
 * vertices) and the cell data of the triangles kept. On a 700K-triangle
 * isosurface, 64 divisions keep 4% of the triangles in under a tenth of a
 * second (docs/rendering.md). Null for leaves it does not apply to: fewer
 * than `minimumTriangles` triangles, polygons other than triangles, or
 * vertex, line or strip cells (those are drawn as they are).
 */
#ifndef LeafInterimReduction_h
#define LeafInterimReduction_h

#include "vtkSmartPointer.h" // for vtkSmartPointer
#include "vtkType.h"         // for vtkIdType

class vtkPolyData;

namespace timecritical
{
vtkSmartPointer<vtkPolyData> BuildInterimReduction(
  vtkPolyData* leaf, int divisions, vtkIdType minimumTriangles);
}

#endif
