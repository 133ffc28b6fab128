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
 * @sa vtkExtractTOMResolution vtkTOMFieldData
 */
#ifndef vtkTOMBuilder_h
#define vtkTOMBuilder_h

#include "TimeCriticalFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class TIMECRITICALFILTERS_EXPORT vtkTOMBuilder : public vtkPolyDataAlgorithm
{
public:
  static vtkTOMBuilder* New();
  vtkTypeMacro(vtkTOMBuilder, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Keep open boundaries in place as long as other collapses remain. Default on.
  vtkSetMacro(PreserveBoundaries, bool);
  vtkGetMacro(PreserveBoundaries, bool);
  vtkBooleanMacro(PreserveBoundaries, bool);
  ///@}

  ///@{
  /// Keep sharp edges: constraint quadrics along them make collapses across
  /// them cost more (timecritical::TOMBuildOptions::FeatureWeight; the core's
  /// LockFeatureEdges locks them instead, like boundaries). Default on.
  vtkSetMacro(PreserveFeatureEdges, bool);
  vtkGetMacro(PreserveFeatureEdges, bool);
  vtkBooleanMacro(PreserveFeatureEdges, bool);
  ///@}

  ///@{
  /// Dihedral angle in degrees above which an edge is sharp. Default 45.
  vtkSetClampMacro(FeatureAngle, double, 0.0, 180.0);
  vtkGetMacro(FeatureAngle, double);
  ///@}

  ///@{
  /// Reject collapses that rotate a triangle normal by more than this (degrees). Default 90.
  vtkSetClampMacro(MaximumNormalDeviation, double, 0.0, 180.0);
  vtkGetMacro(MaximumNormalDeviation, double);
  ///@}

  ///@{
  /**
   * Sliver rejection (Xia, El-Sana & Varshney eq. 3): collapses creating a
   * triangle of lower quality are postponed while others remain. 0 (default) disables it.
   */
  vtkSetClampMacro(MinimumTriangleQuality, double, 0.0, 1.0);
  vtkGetMacro(MinimumTriangleQuality, double);
  ///@}

  ///@{
  /// Statistics of the last build.
  vtkGetMacro(NumberOfDroppedCells, vtkIdType);
  vtkGetMacro(NumberOfMergedPoints, vtkIdType);
  vtkGetMacro(BuildTime, double);
  ///@}

protected:
  vtkTOMBuilder();
  ~vtkTOMBuilder() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  bool PreserveBoundaries = true;
  bool PreserveFeatureEdges = true;
  double FeatureAngle = 45.0;
  double MaximumNormalDeviation = 90.0;
  double MinimumTriangleQuality = 0.0;
  vtkIdType NumberOfDroppedCells = 0;
  vtkIdType NumberOfMergedPoints = 0;
  double BuildTime = 0.0;

private:
  vtkTOMBuilder(const vtkTOMBuilder&) = delete;
  void operator=(const vtkTOMBuilder&) = delete;
};

#endif
