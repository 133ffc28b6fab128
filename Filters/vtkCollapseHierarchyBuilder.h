// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkCollapseHierarchyBuilder
 * @brief   abstract superclass of the filters that build a hierarchy by half-edge collapse
 *
 * Holds the collapse settings and build statistics that vtkTOMBuilder and
 * vtkMergeTreeBuilder share, and hands the settings to the core
 * (timecritical::TOMBuildOptions) in one place, so that both filters accept
 * and simplify alike. Subclasses take a vtkPolyData input and build in
 * RequestData.
 *
 * @sa vtkTOMBuilder vtkMergeTreeBuilder
 */
#ifndef vtkCollapseHierarchyBuilder_h
#define vtkCollapseHierarchyBuilder_h

#include "TimeCriticalFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

namespace timecritical
{
struct TOMBuildOptions;
}

class TIMECRITICALFILTERS_EXPORT vtkCollapseHierarchyBuilder : public vtkPolyDataAlgorithm
{
public:
  vtkAbstractTypeMacro(vtkCollapseHierarchyBuilder, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Keep open boundaries in place as long as other collapses remain. Default on.
  vtkSetMacro(PreserveBoundaries, bool);
  vtkGetMacro(PreserveBoundaries, bool);
  vtkBooleanMacro(PreserveBoundaries, bool);
  ///@}

  ///@{
  /// Keep sharp edges (dihedral angle above FeatureAngle): constraint planes
  /// along them make collapses across them cost more (FeatureWeight), or lock
  /// them (LockFeatureEdges). Default on.
  vtkSetMacro(PreserveFeatureEdges, bool);
  vtkGetMacro(PreserveFeatureEdges, bool);
  vtkBooleanMacro(PreserveFeatureEdges, bool);
  ///@}

  ///@{
  /// Dihedral angle in degrees above which an edge is sharp, in [0, 180]
  /// (NaN is rejected with an error). Default 45.
  void SetFeatureAngle(double angle);
  vtkGetMacro(FeatureAngle, double);
  ///@}

  ///@{
  /**
   * Lock sharp edges like open boundaries (with PreserveFeatureEdges on):
   * their vertices only slide along them, and vertices where they turn
   * sharply (a cube's corners) stay, until no other collapse is left. Off
   * (default): sharp edges are weighted in the quadrics by FeatureWeight
   * instead, so collapses across them cost more but are not forbidden.
   * A lock suits clean CAD parts, whose sharp edges are all true creases; on
   * low-poly organic meshes a fixed FeatureAngle also flags edges of smooth
   * regions, whose locked vertices stay while the rest is over-simplified
   * (timecritical::TOMBuildOptions::LockFeatureEdges; figures in
   * docs/classes.md and docs/benchmarks/tom.md, "TOM quality").
   */
  vtkSetMacro(LockFeatureEdges, bool);
  vtkGetMacro(LockFeatureEdges, bool);
  vtkBooleanMacro(LockFeatureEdges, bool);
  ///@}

  ///@{
  /**
   * Weight of the two constraint planes along each sharp edge when sharp
   * edges are weighted, not locked (PreserveFeatureEdges on,
   * LockFeatureEdges off): moving a vertex across a sharp edge costs this
   * many times more than moving it off a face (per squared edge length,
   * like the faces' area weights). 0 leaves sharp edges to the face
   * quadrics alone; very large weights act as a lock. The default is the
   * weight that gave the lowest worst-case error on the benchmark meshes
   * (docs/classes.md; timecritical::TOMBuildOptions::FeatureWeight). Clamped to [0, 1000]
   * (1000 is the weight of the boundary constraints; for a harder hold use
   * LockFeatureEdges); NaN is rejected with an error. Default 10.
   */
  void SetFeatureWeight(double weight);
  vtkGetMacro(FeatureWeight, double);
  ///@}

  ///@{
  /// Reject collapses that rotate a triangle normal by more than this
  /// (degrees, [0, 180]; NaN is rejected with an error). Default 90.
  void SetMaximumNormalDeviation(double angle);
  vtkGetMacro(MaximumNormalDeviation, double);
  ///@}

  ///@{
  /**
   * Sliver rejection (Xia, El-Sana & Varshney eq. 3): collapses creating a
   * triangle of quality 4*sqrt(3)*area / (l0^2 + l1^2 + l2^2) below this
   * value are postponed while others remain (so that a merge tree's run-time
   * triangulations avoid slivers too). In [0, 1] (NaN is rejected with an
   * error); 0 (default) disables it.
   */
  void SetMinimumTriangleQuality(double quality);
  vtkGetMacro(MinimumTriangleQuality, double);
  ///@}

  ///@{
  /// Statistics of the last build.
  vtkGetMacro(NumberOfDroppedCells, vtkIdType);
  vtkGetMacro(NumberOfMergedPoints, vtkIdType);
  vtkGetMacro(BuildTime, double);
  ///@}

protected:
  vtkCollapseHierarchyBuilder();
  ~vtkCollapseHierarchyBuilder() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;

  /// Copies the collapse settings into the core's options, with the progress
  /// callback (timecritical::CoreProgress).
  void FillCollapseOptions(timecritical::TOMBuildOptions& options);

  bool PreserveBoundaries = true;
  bool PreserveFeatureEdges = true;
  double FeatureAngle = 45.0;
  bool LockFeatureEdges = false;
  double FeatureWeight; // the core's default (constructor)
  double MaximumNormalDeviation = 90.0;
  double MinimumTriangleQuality = 0.0;
  vtkIdType NumberOfDroppedCells = 0;
  vtkIdType NumberOfMergedPoints = 0;
  double BuildTime = 0.0;

private:
  vtkCollapseHierarchyBuilder(const vtkCollapseHierarchyBuilder&) = delete;
  void operator=(const vtkCollapseHierarchyBuilder&) = delete;
};

#endif
