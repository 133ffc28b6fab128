// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkPolyDataValidator
 * @brief   checks that a vtkPolyData can be read safely: point ids and coordinates
 *
 * VTK's own filters and mappers trust cell connectivity: a cell that refers
 * to a point id outside [0, number of points) makes them read (and sometimes
 * write) out of bounds, and NaN or infinite coordinates poison bounds,
 * culling and every mesh built from them. Each entry point of TimeCritical
 * (the builder filters, the TOM and merge-tree readers, the multiresolution
 * mapper) runs this one check first and turns a problem into an error message
 * that names it, instead of a crash or silent garbage.
 *
 * Linear in the connectivity and the points; allocates nothing.
 */
#ifndef vtkPolyDataValidator_h
#define vtkPolyDataValidator_h

#include "TimeCriticalFiltersModule.h" // for export macro
#include "vtkObject.h"

#include <string> // for std::string

class vtkPolyData;
class vtkPoints;

class TIMECRITICALFILTERS_EXPORT vtkPolyDataValidator : public vtkObject
{
public:
  static vtkPolyDataValidator* New();
  vtkTypeMacro(vtkPolyDataValidator, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * An empty string when every cell of `data` (vertices, lines, polygons,
   * strips) refers only to existing points and every coordinate is finite;
   * otherwise the first problem, e.g. "cell 3 refers to point -5, but the
   * data has 3 points" (cells numbered as vtkPolyData numbers them: vertices,
   * lines, polygons, strips). Null data is valid (nothing to read).
   */
  static std::string Check(vtkPolyData* data);

  /**
   * Check() for the inputs of the builder filters (vtkTOMBuilder,
   * vtkMergeTreeBuilder): also rejects coordinates of magnitude above
   * timecritical::MaximumCoordinateMagnitude, the cores' own limit (their
   * errors and radii are stored as float): "point 5 has a coordinate of
   * magnitude 2.2e+38, beyond the supported 1e+28 (errors and radii are
   * stored as float); scale the data".
   */
  static std::string CheckBuildInput(vtkPolyData* data);

  /// Only the connectivity part of Check().
  static std::string CheckPointIds(vtkPolyData* data);

  /// Only the coordinate part of Check(): "point 5 has a non-finite (NaN or infinite) coordinate".
  static std::string CheckCoordinates(vtkPoints* points);

  /// Id of the first point with a NaN or infinite coordinate, or -1 (also for null points).
  static vtkIdType FirstNonFinitePoint(vtkPoints* points);

  /// Id of the first point with a coordinate that is NaN or of magnitude above
  /// `limit` (infinite included), or -1 (also for null points).
  static vtkIdType FirstPointBeyond(vtkPoints* points, double limit);

protected:
  vtkPolyDataValidator() = default;
  ~vtkPolyDataValidator() override = default;

private:
  vtkPolyDataValidator(const vtkPolyDataValidator&) = delete;
  void operator=(const vtkPolyDataValidator&) = delete;
};

#endif
