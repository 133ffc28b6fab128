// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkAccuracyCurveHierarchy
 * @brief   composes accuracy curves up the block hierarchy of a composite dataset
 *
 * Pasman & Jansen's scene graph (section 3.2) read from the data: every
 * composite node (a vtkMultiBlockDataSet block, a vtkPartitionedDataSet of a
 * vtkPartitionedDataSetCollection, ...) is a GROUP whose curve adds its
 * children's resources at equal accuracy, unless it is marked as an LOD NODE:
 * then its children are alternative representations of one object and its
 * curve is the cheapest sufficient child at each accuracy, never extending a
 * child beyond its maximum accuracy (timecritical::AccuracyCurveComposition).
 *
 * Leaves: a polydata's stored or derived curve (vtkAccuracyCurveFieldData);
 * a polydata without a hierarchy is exact (error 0) at its triangle count,
 * from accuracy 0 on; other leaves and empty ones have no curve and are
 * left out.
 *
 * Two kinds of accuracy (section 3.4):
 * - RELATIVE (default): curves relative to each node's size, the diagonal of
 *   its bounding box; a node rescales its children's curves to its own size
 *   before composing them.
 * - ABSOLUTE: one over the angular distortion seen from ViewPoint; each
 *   leaf's relative curve is converted with its nearest distance (bounding
 *   sphere, never below MinimumDistance) and nodes compose as they are.
 *
 * LOD-node marking: the integer key LOD_NODE() (1) in the block's metadata,
 * which pipelines keep (CopyStructure) but .vtm/.vtpc files drop, or the flat
 * index of the block in the root's field-data array `AccuracyCurveLODNodes`,
 * which the files keep. MarkLODNode() sets both; either one marks the block.
 *
 * Nodes are named by flat index (vtkDataObjectTreeIterator::GetCurrentFlatIndex;
 * the root is 0). A renderer asks GetAccuracy(quota) for the best accuracy of
 * the whole scene within a triangle quota and imposes it on every object
 * (section 3.3), or GetResources(accuracy) for the cost of an accuracy; an
 * LOD node's representation for an accuracy is GetCheapestChild().
 *
 * @sa vtkAccuracyCurveFieldData
 */
#ifndef vtkAccuracyCurveHierarchy_h
#define vtkAccuracyCurveHierarchy_h

#include "TimeCriticalFiltersModule.h" // for export macro
#include "vtkObject.h"

#include <memory> // for std::unique_ptr

class vtkDataObject;
class vtkDataObjectTree;
class vtkInformationIntegerKey;

namespace timecritical
{
class AccuracyCurve;
}

class TIMECRITICALFILTERS_EXPORT vtkAccuracyCurveHierarchy : public vtkObject
{
public:
  static vtkAccuracyCurveHierarchy* New();
  vtkTypeMacro(vtkAccuracyCurveHierarchy, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Block metadata key: 1 marks the block as an LOD node.
  static vtkInformationIntegerKey* LOD_NODE();

  /// Root field-data array of the flat indices of the LOD nodes (kept by .vtm/.vtpc files).
  static const char* LODNodesArrayName() { return "AccuracyCurveLODNodes"; }

  /**
   * Mark (or unmark) the composite node at `flatIndex` of `root` as an LOD
   * node, in its metadata and in the root's array. False, with an error,
   * when there is no composite node at that index.
   */
  static bool MarkLODNode(vtkDataObjectTree* root, unsigned int flatIndex, bool lod = true);

  /// True when the node at `flatIndex` is marked as an LOD node, by either mark.
  static bool IsLODNode(vtkDataObjectTree* root, unsigned int flatIndex);

  enum AccuracyKinds
  {
    RELATIVE = 0, ///< fraction of each node's size
    ABSOLUTE = 1  ///< angular, from ViewPoint
  };
  vtkSetClampMacro(AccuracyKind, int, RELATIVE, ABSOLUTE);
  vtkGetMacro(AccuracyKind, int);

  ///@{
  /// The viewpoint of ABSOLUTE curves, and the nearest distance they count (> 0, default 1e-3).
  vtkSetVector3Macro(ViewPoint, double);
  vtkGetVector3Macro(ViewPoint, double);
  vtkSetMacro(MinimumDistance, double);
  vtkGetMacro(MinimumDistance, double);
  ///@}

  /**
   * Compose the curves of `data` (a composite dataset or a single dataset).
   * False, with an error naming the block, for a leaf with a bad stored curve
   * or a bad setting; the results are then empty.
   */
  bool Compose(vtkDataObject* data);

  ///@{
  /// The root's curve after Compose (0 / +infinity / NaN as timecritical::AccuracyCurve says).
  double GetResources(double accuracy) const;
  double GetAccuracy(double quota) const;
  double GetMaximumAccuracy() const;
  double GetMinimumResources() const;
  ///@}

  ///@{
  /// Per node, by flat index: whether Compose gave it a curve, its curve's values, its size.
  bool HasCurve(unsigned int flatIndex) const;
  double GetNodeResources(unsigned int flatIndex, double accuracy) const;
  double GetNodeAccuracy(unsigned int flatIndex, double quota) const;
  double GetNodeSize(unsigned int flatIndex) const;
  bool GetNodeIsLOD(unsigned int flatIndex) const;
  ///@}

  /**
   * For an LOD node: the position among its children (0-based block index)
   * of the representation it renders for `accuracy`, the cheapest that
   * reaches it; -1 for other nodes or when no child reaches it.
   */
  int GetCheapestChild(unsigned int flatIndex, double accuracy) const;

#ifndef __VTK_WRAP__
  /// The root's curve after Compose (empty before or after a failure).
  const timecritical::AccuracyCurve& GetRootCurve() const;
  /// The curve of the node at flatIndex, null when it has none.
  const timecritical::AccuracyCurve* GetCurve(unsigned int flatIndex) const;
#endif

protected:
  vtkAccuracyCurveHierarchy();
  ~vtkAccuracyCurveHierarchy() override;

  int AccuracyKind = RELATIVE;
  double ViewPoint[3] = { 0.0, 0.0, 0.0 };
  double MinimumDistance = 1e-3;

private:
  vtkAccuracyCurveHierarchy(const vtkAccuracyCurveHierarchy&) = delete;
  void operator=(const vtkAccuracyCurveHierarchy&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
