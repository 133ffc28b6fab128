// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkMergeTreeBuilder
 * @brief   builds a merge tree for view-dependent refinement from a surface
 *
 * Simplifies the input by half-edge collapses grouped into levels of
 * independent sets (Xia, El-Sana & Varshney, section 4) and stores the result
 * as a Totally Ordered Mesh (see vtkTOMFieldData) that also carries the merge
 * tree: levels, node errors, bounding radii, normal cones and dependencies
 * (see vtkMergeTreeFieldData). The output renders as the full mesh, extracts
 * uniform resolutions with vtkExtractTOMResolution and view-dependent ones with
 * vtkExtractViewDependentMesh. All point and cell data travel with the
 * reordered points and triangles.
 *
 * Input handling is that of vtkTOMBuilder: coincident points are merged,
 * polygons and strips triangulated; lines, vertices and degenerate triangles
 * are dropped with a warning; out-of-range point ids, non-finite coordinates
 * and input without surface cells are errors. An empty input gives an empty
 * output without a message.
 *
 * Save the output as .vtp in Binary or Ascii data mode (see the README on
 * appended mode).
 *
 * @sa vtkTOMBuilder vtkMergeTreeFieldData vtkExtractViewDependentMesh
 */
#ifndef vtkMergeTreeBuilder_h
#define vtkMergeTreeBuilder_h

#include "TimeCriticalFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class TIMECRITICALFILTERS_EXPORT vtkMergeTreeBuilder : public vtkPolyDataAlgorithm
{
public:
  static vtkMergeTreeBuilder* New();
  vtkTypeMacro(vtkMergeTreeBuilder, vtkPolyDataAlgorithm);
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
  /// Dihedral angle in degrees above which an edge is sharp, in [0, 180]. Default 45.
  void SetFeatureAngle(double angle);
  vtkGetMacro(FeatureAngle, double);
  ///@}

  ///@{
  /**
   * Lock sharp edges like open boundaries (with PreserveFeatureEdges on);
   * off (default), weight them by FeatureWeight. As in vtkTOMBuilder, whose
   * documentation says when each suits: a lock for clean CAD parts, the
   * weights for organic meshes, where a fixed FeatureAngle also flags edges
   * of smooth regions.
   */
  vtkSetMacro(LockFeatureEdges, bool);
  vtkGetMacro(LockFeatureEdges, bool);
  vtkBooleanMacro(LockFeatureEdges, bool);
  ///@}

  ///@{
  /**
   * Weight of the two constraint planes along each sharp edge when sharp
   * edges are weighted, not locked: moving a vertex across a sharp edge
   * costs this many times more than moving it off a face (see
   * vtkTOMBuilder::SetFeatureWeight). 0 leaves sharp edges to the face
   * quadrics alone. Clamped to [0, 1000]; NaN is rejected with an error.
   * Default 10.
   */
  void SetFeatureWeight(double weight);
  vtkGetMacro(FeatureWeight, double);
  ///@}

  ///@{
  /// Reject collapses that rotate a triangle normal by more than this (degrees, [0, 180]). Default 90.
  void SetMaximumNormalDeviation(double angle);
  vtkGetMacro(MaximumNormalDeviation, double);
  ///@}

  ///@{
  /**
   * Sliver avoidance (Xia, El-Sana & Varshney eq. 3): collapses creating a
   * triangle of quality 4*sqrt(3)*area / (l0^2 + l1^2 + l2^2) below this value
   * are postponed while others remain, so that run-time triangulations avoid
   * slivers. In [0, 1]; 0 (default) disables it.
   */
  void SetMinimumTriangleQuality(double quality);
  vtkGetMacro(MinimumTriangleQuality, double);
  ///@}

  ///@{
  /**
   * Level cost cap (timecritical::MergeTreeBuildOptions::LevelCostRatio): a
   * level takes collapses least error first only while the next costs at
   * most this many times the greedy order's frontier, so that the merge-tree
   * TOM stays nearly as accurate as vtkTOMBuilder's (within about 1.3x) for
   * 10-85% more levels. 0 gives the paper's maximal levels (shallowest tree,
   * up to tens of times the error at half the triangles). Default 2, >= 0.
   */
  void SetLevelCostRatio(double ratio);
  vtkGetMacro(LevelCostRatio, double);
  ///@}

  ///@{
  /**
   * Weight of the shading error in each node's error
   * (timecritical::MergeTreeErrorOptions::ShadingWeight): lost normal
   * variation times the node's radius counts like a geometric displacement,
   * so that a 1-pixel front also keeps the shading of fine bumps (on a
   * scanned face: 45 dB instead of 36 dB against the full mesh, for 7.6%
   * instead of 2.3% of the triangles). 0: geometric error only. Default 1, >= 0.
   */
  void SetShadingWeight(double weight);
  vtkGetMacro(ShadingWeight, double);
  ///@}

  ///@{
  /// Statistics of the last build.
  vtkGetMacro(NumberOfDroppedCells, vtkIdType);
  vtkGetMacro(NumberOfMergedPoints, vtkIdType);
  vtkGetMacro(LevelCount, int);
  vtkGetMacro(BuildTime, double);
  ///@}

protected:
  vtkMergeTreeBuilder();
  ~vtkMergeTreeBuilder() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  bool PreserveBoundaries = true;
  bool PreserveFeatureEdges = true;
  double FeatureAngle = 45.0;
  bool LockFeatureEdges = false;
  double FeatureWeight; // the core's default (constructor)
  double MaximumNormalDeviation = 90.0;
  double MinimumTriangleQuality = 0.0;
  double LevelCostRatio; // the core's default (constructor)
  double ShadingWeight;  // the core's default (constructor)
  vtkIdType NumberOfDroppedCells = 0;
  vtkIdType NumberOfMergedPoints = 0;
  int LevelCount = 0;
  double BuildTime = 0.0;

private:
  vtkMergeTreeBuilder(const vtkMergeTreeBuilder&) = delete;
  void operator=(const vtkMergeTreeBuilder&) = delete;
};

#endif
