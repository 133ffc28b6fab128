// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkTOMFieldData
 * @brief   reads and writes the Totally Ordered Mesh arrays of a vtkPolyData
 *
 * A TOM travels as an ordinary vtkPolyData: points sorted by removal,
 * triangles sorted in prefix order, one 32-bit point-data array
 * `TOMSubstitution` and small field data (`TOMCounts`: vertices, triangles,
 * base vertices, base triangles; `TOMErrorCurve`: pairs of triangle count and
 * geometric error). Every reader of TOM data goes through Read(), which checks
 * the arrays with timecritical::TOMValidator, so corrupted or foreign data is
 * reported with a precise message instead of crashing anything.
 */
#ifndef vtkTOMFieldData_h
#define vtkTOMFieldData_h

#include "TimeCriticalFiltersModule.h" // for export macro
#include "vtkObject.h"

#include <memory> // for std::unique_ptr

class vtkPolyData;

namespace timecritical
{
struct TOMMesh;
}

class TIMECRITICALFILTERS_EXPORT vtkTOMFieldData : public vtkObject
{
public:
  static vtkTOMFieldData* New();
  vtkTypeMacro(vtkTOMFieldData, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Names of the arrays a TOM carries.
  static const char* SubstitutionArrayName() { return "TOMSubstitution"; }
  static const char* CountsArrayName() { return "TOMCounts"; }
  static const char* ErrorCurveArrayName() { return "TOMErrorCurve"; }
  ///@}

  /// True when the data carries the TOM arrays (valid or not).
  static bool HasTOMArrays(vtkPolyData* data);

  /**
   * Read and validate the TOM of `data` into this object.
   * Returns false and fills GetErrorMessage() when the data is not a valid TOM.
   */
  bool Read(vtkPolyData* data);

  /// Problem found by the last Read(), empty after a successful one.
  const char* GetErrorMessage() const;

  ///@{
  /**
   * Remember the meshes that validated (by the addresses and modification
   * times of their points, TOM arrays and polygons), so that a later Read()
   * of the same, unmodified data skips the costly checks (the coordinates and
   * the replay of every prefix); the structural checks and the copy still
   * run. For a reader that reads the same leaves again and again, as a
   * mapper swapping in new hierarchies among old ones. Off by default.
   * What is remembered lasts for the current and the previous reading pass
   * (StartReadingPass() starts a new one), so that leaves gone are forgotten.
   */
  void SetRememberValidated(bool remember);
  bool GetRememberValidated() const;
  void StartReadingPass();
  ///@}

  /// Frees the copy of the last mesh read (GetMesh() is then empty).
  void ReleaseMesh();

#ifndef __VTK_WRAP__
  /// The mesh read by the last successful Read().
  const timecritical::TOMMesh& GetMesh() const;

  /**
   * Attach the TOM arrays of `mesh` to `data`, whose points and triangles
   * must already be in TOM order.
   */
  static void Write(const timecritical::TOMMesh& mesh, vtkPolyData* data);
#endif

  ///@{
  /// Counts of the last successful Read().
  vtkIdType GetNumberOfVertices() const;
  vtkIdType GetNumberOfTriangles() const;
  vtkIdType GetBaseVertexCount() const;
  vtkIdType GetBaseTriangleCount() const;
  ///@}

protected:
  vtkTOMFieldData();
  ~vtkTOMFieldData() override;

private:
  vtkTOMFieldData(const vtkTOMFieldData&) = delete;
  void operator=(const vtkTOMFieldData&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
