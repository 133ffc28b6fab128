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
 * vtkCollapseHierarchyBuilder, shared with vtkMergeTreeBuilder. Only this
 * builder can also join separate parts at its coarsest resolutions
 * (PairContractionDistance, off by default).
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
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Pair contraction (Garland & Heckbert's non-edge pairs; Gobbetti &
   * Bouvier's Fig. 2, right): once no edge collapse is left, a separate part
   * whose surviving vertex lies within this distance of a surviving vertex of
   * another part is substituted whole into that part, so that objects of many
   * small parts (glyphs, particles, blobs, assemblies) do not keep a few
   * vertices per part at their coarsest. A fraction of the input's
   * bounding-box diagonal in [0, 1]; 0 (default) turns it off. Every
   * resolution above the coarsest one without pairs is unchanged; the joined
   * levels are not manifold where parts meet
   * (timecritical::TOMBuildOptions::PairContractionDistance; figures in
   * docs/benchmarks/pairs.md). NaN, infinite or out-of-range values are an
   * error and leave the setting unchanged.
   */
  void SetPairContractionDistance(double distance);
  vtkGetMacro(PairContractionDistance, double);
  ///@}

  /// Separate parts substituted whole into another part by the last build.
  vtkGetMacro(NumberOfJoinedParts, vtkIdType);

protected:
  vtkTOMBuilder();
  ~vtkTOMBuilder() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double PairContractionDistance = 0.0;
  vtkIdType NumberOfJoinedParts = 0;

private:
  vtkTOMBuilder(const vtkTOMBuilder&) = delete;
  void operator=(const vtkTOMBuilder&) = delete;
};

#endif
