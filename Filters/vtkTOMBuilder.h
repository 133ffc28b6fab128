// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkTOMBuilder
 * @brief   builds a Totally Ordered Mesh from a surface
 *
 * Simplifies the input by quadric-ordered half-edge collapse (vertex
 * substitution, no new vertices) and reorders points and triangles so that the
 * mesh at any resolution is a prefix of both (Gobbetti & Bouvier, section 6).
 * The output is an ordinary vtkPolyData that renders as the full mesh, plus
 * the TOM arrays described in vtkTOMFieldData. All point and cell data travel
 * with the reordered points and triangles.
 *
 * The input is cleaned first: coincident points are merged, polygons and
 * strips triangulated; lines, vertices, degenerate triangles and duplicate
 * triangles (the same three points as an earlier one) are dropped with a
 * warning. Input without surface cells, out-of-range point ids and
 * non-finite coordinates are errors (empty output). An empty input (no points,
 * no cells: a rank without data in parallel) gives an empty output without a
 * message.
 *
 * The simplification settings and build statistics are those of
 * vtkCollapseHierarchyBuilder, shared with vtkMergeTreeBuilder.
 *
 * @sa vtkCollapseHierarchyBuilder vtkExtractTOMResolution vtkTOMFieldData
 */
#ifndef vtkTOMBuilder_h
#define vtkTOMBuilder_h

#include "TimeCriticalFiltersModule.h" // for export macro
#include "vtkCollapseHierarchyBuilder.h"

class TIMECRITICALFILTERS_EXPORT vtkTOMBuilder : public vtkCollapseHierarchyBuilder
{
public:
  static vtkTOMBuilder* New();
  vtkTypeMacro(vtkTOMBuilder, vtkCollapseHierarchyBuilder);

protected:
  vtkTOMBuilder();
  ~vtkTOMBuilder() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkTOMBuilder(const vtkTOMBuilder&) = delete;
  void operator=(const vtkTOMBuilder&) = delete;
};

#endif
