// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkMergeTreeFieldData
 * @brief   reads and writes the merge-tree arrays of a Totally Ordered Mesh
 *
 * A merge tree (Xia, El-Sana & Varshney; timecritical::MergeTree) travels on
 * the vtkPolyData of a valid TOM (see vtkTOMFieldData), so the same dataset
 * serves uniform prefix extraction and view-dependent refinement:
 *
 * point data, one tuple per TOM vertex:
 *  - `MergeTreeLevel` (uint16): level of the collapse that removed the vertex,
 *    LevelCount for base vertices;
 *  - `MergeTreeError` (float): geometric error of the node, world units, >= 0;
 *  - `MergeTreeRadius` (float): bounding-sphere radius of the subtree, >= 0;
 *  - `MergeTreeConeAxis` (float, 3 components): unit normal-cone axis;
 *  - `MergeTreeConeCosine` (float): cosine of the cone half-angle, in [-1, 1];
 *
 * field data:
 *  - `MergeTreeDependencyOffsets` (uint32, vertices + 1 values) and
 *    `MergeTreeDependencies` (uint32): the dependency rows in compressed form;
 *  - `MergeTreeLevelCount` (uint16, one value).
 *
 * Every reader of merge-tree data goes through Read(), which validates the TOM
 * (with vtkTOMFieldData) and then every merge-tree array, so corrupted or
 * foreign data gives a message naming the array, the entry and the problem,
 * never a crash. Integer arrays of other integer types and double arrays in
 * place of float ones are accepted (range-checked), as vtkTOMFieldData does.
 *
 * @sa vtkTOMFieldData vtkMergeTreeBuilder vtkExtractViewDependentMesh
 */
#ifndef vtkMergeTreeFieldData_h
#define vtkMergeTreeFieldData_h

#include "TimeCriticalFiltersModule.h" // for export macro
#include "vtkObject.h"

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class vtkPolyData;
class vtkTOMFieldData;

namespace timecritical
{
struct MergeTree;
struct TOMMesh;
}

class TIMECRITICALFILTERS_EXPORT vtkMergeTreeFieldData : public vtkObject
{
public:
  static vtkMergeTreeFieldData* New();
  vtkTypeMacro(vtkMergeTreeFieldData, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Names of the merge-tree arrays.
  static const char* LevelArrayName() { return "MergeTreeLevel"; }
  static const char* ErrorArrayName() { return "MergeTreeError"; }
  static const char* RadiusArrayName() { return "MergeTreeRadius"; }
  static const char* ConeAxisArrayName() { return "MergeTreeConeAxis"; }
  static const char* ConeCosineArrayName() { return "MergeTreeConeCosine"; }
  static const char* DependencyOffsetsArrayName() { return "MergeTreeDependencyOffsets"; }
  static const char* DependenciesArrayName() { return "MergeTreeDependencies"; }
  static const char* LevelCountArrayName() { return "MergeTreeLevelCount"; }
  ///@}

  /// True when the data carries any merge-tree array (valid or not).
  static bool HasMergeTreeArrays(vtkPolyData* data);

  /**
   * Read and validate the TOM and the merge tree of `data` into this object.
   * Returns false and fills GetErrorMessage() when either is invalid.
   */
  bool Read(vtkPolyData* data);

  /// Problem found by the last Read(), empty after a successful one.
  const char* GetErrorMessage() const;

  /// The TOM part of the last Read() (valid only when Read() succeeded).
  vtkTOMFieldData* GetTOMFieldData() const;

#ifndef __VTK_WRAP__
  /// The merge tree read by the last successful Read().
  const timecritical::MergeTree& GetTree() const;

  /// The TOM read by the last successful Read().
  const timecritical::TOMMesh& GetMesh() const;

  /**
   * Attach the TOM arrays of `mesh` and the merge-tree arrays of `tree` to
   * `data`, whose points and triangles must already be in TOM order.
   */
  static void Write(
    const timecritical::TOMMesh& mesh, const timecritical::MergeTree& tree, vtkPolyData* data);

  /**
   * Check a merge tree against its TOM, as Read() does after reading the
   * arrays. Empty when valid, otherwise the first problem found.
   */
  static std::string Check(const timecritical::TOMMesh& mesh, const timecritical::MergeTree& tree);
#endif

  ///@{
  /// Counts of the last successful Read() (0 otherwise).
  vtkIdType GetNumberOfVertices() const;
  int GetLevelCount() const;
  vtkIdType GetNumberOfDependencies() const;
  ///@}

protected:
  vtkMergeTreeFieldData();
  ~vtkMergeTreeFieldData() override;

private:
  vtkMergeTreeFieldData(const vtkMergeTreeFieldData&) = delete;
  void operator=(const vtkMergeTreeFieldData&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
