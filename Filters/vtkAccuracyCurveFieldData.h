// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkAccuracyCurveFieldData
 * @brief   reads, derives and writes the accuracy curve of a multiresolution object
 *
 * The accuracy curve (Pasman & Jansen; timecritical::AccuracyCurve) of an
 * object gives the triangles needed for each relative accuracy, the object's
 * size over its geometric error. It travels in the field data of the
 * object's dataset, beside the TOM arrays (vtkTOMFieldData), so it is saved
 * with .vtp and .vtm files:
 *  - `AccuracyCurve` (double, 3 components A, R, K per piece): the paper's
 *    triples, in increasing A;
 *  - `AccuracyCurveMaximumAccuracy` (double, one value): the last accuracy
 *    the curve reaches, -1 when it has no end (the full mesh, error 0, reaches
 *    every accuracy; -1 because ASCII .vtp files cannot hold infinity);
 *  - `AccuracyCurveSize` (double, one value): the object size the relative
 *    accuracies refer to (the diagonal of the bounding box of the points).
 *
 * Derive() makes the curve of a multiresolution object from what it stores:
 * a merge tree's node errors (vtkMergeTreeFieldData) when it has them, else
 * the TOM's error curve: triangles against size / error, through the error
 * curve's samples. For a merge tree the mesh with n vertices counts the
 * largest error of the vertices it lacks, so its curve bounds the triangles
 * of a uniform front from above.
 *
 * Every reader goes through Read(), which checks the arrays with
 * timecritical::AccuracyCurve, so bad arrays give a message, never a crash.
 *
 * @sa vtkAccuracyCurveHierarchy vtkTOMFieldData vtkMergeTreeFieldData
 */
#ifndef vtkAccuracyCurveFieldData_h
#define vtkAccuracyCurveFieldData_h

#include "TimeCriticalFiltersModule.h" // for export macro
#include "vtkObject.h"

#include <memory> // for std::unique_ptr

class vtkDataObject;
class vtkPolyData;

namespace timecritical
{
class AccuracyCurve;
class TOMErrorCurve;
struct MergeTree;
struct TOMMesh;
}

class TIMECRITICALFILTERS_EXPORT vtkAccuracyCurveFieldData : public vtkObject
{
public:
  static vtkAccuracyCurveFieldData* New();
  vtkTypeMacro(vtkAccuracyCurveFieldData, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Names of the field-data arrays of a curve.
  static const char* CurveArrayName() { return "AccuracyCurve"; }
  static const char* MaximumAccuracyArrayName() { return "AccuracyCurveMaximumAccuracy"; }
  static const char* SizeArrayName() { return "AccuracyCurveSize"; }
  ///@}

  /// Samples kept in the curve derived from a merge tree (as a TOM's error curve keeps).
  static constexpr unsigned MergeTreeCurveSamples = 48;

  /// True when `data` carries the curve array (valid or not).
  static bool HasAccuracyCurve(vtkDataObject* data);

  /**
   * Read and check the stored curve of `data`. Returns false and fills
   * GetErrorMessage() when it has none or a bad one.
   */
  bool Read(vtkDataObject* data);

  /**
   * Derive the curve of a multiresolution object from its merge tree or its
   * TOM error curve (see the class comment). Returns false and fills
   * GetErrorMessage() when `data` is neither a valid TOM with an error curve
   * nor a valid merge tree, or has no extent.
   */
  bool Derive(vtkPolyData* data);

  /// The stored curve when `data` has one (checked), else Derive().
  bool ReadOrDerive(vtkPolyData* data);

  /// Derive() and write the curve into the field data of `data` (false when Derive fails).
  bool Attach(vtkPolyData* data);

  /// Write the curve of the last successful Read or Derive into `data` (false when there is none).
  bool WriteTo(vtkDataObject* data) const;

  /// Problem found by the last Read, Derive or ReadOrDerive; empty after a success.
  const char* GetErrorMessage() const;

  ///@{
  /// The curve of the last success (0 pieces, NaN values otherwise).
  int GetNumberOfPieces() const;
  double GetSize() const;
  double GetMaximumAccuracy() const;
  /// Triangles for a relative accuracy (+infinity above the maximum; NaN for a bad argument).
  double GetResources(double relativeAccuracy) const;
  /// Best relative accuracy for a triangle quota (0 when nothing fits; NaN for a bad argument).
  double GetAccuracy(double triangleQuota) const;
  ///@}

#ifndef __VTK_WRAP__
  /// The curve of the last success (empty otherwise).
  const timecritical::AccuracyCurve& GetCurve() const;

  /// The relative curve of a TOM error curve for an object of the given size.
  static timecritical::AccuracyCurve FromErrorCurve(
    const timecritical::TOMErrorCurve& errorCurve, double size);

  /// The relative curve of a merge tree's node errors (see the class comment).
  static timecritical::AccuracyCurve FromMergeTree(
    const timecritical::TOMMesh& mesh, const timecritical::MergeTree& tree, double size);

  /// Write `curve`, relative to `size`, into the field data of `data`.
  static void Write(const timecritical::AccuracyCurve& curve, double size, vtkDataObject* data);
#endif

protected:
  vtkAccuracyCurveFieldData();
  ~vtkAccuracyCurveFieldData() override;

private:
  vtkAccuracyCurveFieldData(const vtkAccuracyCurveFieldData&) = delete;
  void operator=(const vtkAccuracyCurveFieldData&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
