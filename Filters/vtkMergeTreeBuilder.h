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
 * output without a message. The simplification settings and the other build
 * statistics are those of vtkCollapseHierarchyBuilder, as in vtkTOMBuilder.
 *
 * Save the output as .vtp in Binary or Ascii data mode (see docs/known-issues.md on
 * appended mode).
 *
 * @sa vtkCollapseHierarchyBuilder vtkTOMBuilder vtkMergeTreeFieldData vtkExtractViewDependentMesh
 */
#ifndef vtkMergeTreeBuilder_h
#define vtkMergeTreeBuilder_h

#include "TimeCriticalFiltersModule.h" // for export macro
#include "vtkCollapseHierarchyBuilder.h"

class TIMECRITICALFILTERS_EXPORT vtkMergeTreeBuilder : public vtkCollapseHierarchyBuilder
{
public:
  static vtkMergeTreeBuilder* New();
  vtkTypeMacro(vtkMergeTreeBuilder, vtkCollapseHierarchyBuilder);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Level cost cap (timecritical::MergeTreeBuildOptions::LevelCostRatio): a
   * level takes collapses least error first only while the next costs at
   * most this many times the greedy order's frontier, so that the merge-tree
   * TOM stays nearly as accurate as vtkTOMBuilder's for somewhat more levels
   * (figures in docs/classes.md). 0 gives the paper's maximal levels
   * (shallowest tree, far larger errors at high resolutions). Default 2, >= 0.
   */
  void SetLevelCostRatio(double ratio);
  vtkGetMacro(LevelCostRatio, double);
  ///@}

  ///@{
  /**
   * Weight of the shading error in each node's error
   * (timecritical::MergeTreeErrorOptions::ShadingWeight): lost normal
   * variation times the node's radius counts like a geometric displacement,
   * so that a 1-pixel front also keeps the shading of fine bumps, at the
   * price of more triangles (figures in docs/classes.md). 0: geometric error
   * only. Default 1, >= 0.
   */
  void SetShadingWeight(double weight);
  vtkGetMacro(ShadingWeight, double);
  ///@}

  /// Number of levels of the last build's tree.
  vtkGetMacro(LevelCount, int);

protected:
  vtkMergeTreeBuilder();
  ~vtkMergeTreeBuilder() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double LevelCostRatio; // the core's default (constructor)
  double ShadingWeight;  // the core's default (constructor)
  int LevelCount = 0;

private:
  vtkMergeTreeBuilder(const vtkMergeTreeBuilder&) = delete;
  void operator=(const vtkMergeTreeBuilder&) = delete;
};

#endif
