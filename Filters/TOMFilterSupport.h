// SPDX-License-Identifier: BSD-3-Clause
// Private helpers shared by the filters that build TOMs (vtkTOMBuilder,
// vtkMergeTreeBuilder): one way to prepare their input and assemble their
// output, so the two filters accept and carry data identically; and by the
// readers of their arrays (vtkTOMFieldData, vtkMergeTreeFieldData), so both
// accept the same array types.
#ifndef TOMFilterSupport_h
#define TOMFilterSupport_h

#include "TOMBuilder.h" // for TOMBuildOptions

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <cstdint>
#include <functional>
#include <vector>

class vtkAlgorithm;
class vtkObject;
class vtkPolyData;

namespace timecritical
{
/// A filter's input surface, cleaned and triangulated, in the form the cores take.
struct PreparedSurface
{
  /// Merged points with their point data, triangles with their cell data.
  vtkSmartPointer<vtkPolyData> Triangles;
  /// 3 coordinates per point of Triangles.
  std::vector<double> Points;
  /// 3 point ids per triangle given to the cores.
  std::vector<uint32_t> Ids;
  /// The cell of Triangles each triangle of Ids comes from.
  std::vector<vtkIdType> Cells;
  /// Vertex, line, degenerate and (after WriteOrderedSurface) duplicate cells left out.
  vtkIdType NumberOfDroppedCells = 0;
  /// Input points merged into coincident ones.
  vtkIdType NumberOfMergedPoints = 0;
};

enum class SurfaceStatus
{
  Ready,  ///< the surface has triangles
  Empty,  ///< an empty piece (IsEmptyPiece): nothing reported, the caller decides
  Failed, ///< unusable input, already reported as an error on the filter
};

/**
 * Checks and prepares `input` for `filter`: rejects out-of-range point ids,
 * coordinates that are not finite or beyond the cores' limit
 * (vtkPolyDataValidator::CheckBuildInput) and inputs without surface cells;
 * merges coincident points; triangulates polygons and strips; drops
 * vertices and lines with a warning on `filter`, and degenerate (zero-area)
 * cells without one (a debug message); both are counted. Duplicate
 * triangles (same three points, in any order: what appending coincident
 * copies gives) are the cores' to drop (TOMBuildResult), WriteOrderedSurface's
 * to report. Reports progress up to 0.05.
 */
SurfaceStatus PrepareSurface(vtkAlgorithm* filter, vtkPolyData* input, PreparedSurface& surface);

/// Progress callback of the cores: maps [0,1] to [0.05, 0.95] and stops on AbortExecute.
std::function<bool(double)> CoreProgress(vtkAlgorithm* filter);

/**
 * Fills `output` with the points, point data, triangles and cell data of
 * `surface` in the TOM order of `result`, and the field data of `input`.
 * Warns on `filter` about triangles the core dropped (degenerate, duplicate)
 * and counts them in `surface`. The caller then attaches the TOM (and
 * merge-tree) arrays.
 */
void WriteOrderedSurface(vtkAlgorithm* filter, vtkPolyData* input, PreparedSurface& surface,
  const TOMBuildResult& result, vtkPolyData* output);

/**
 * Setter body for a clamped double setting that, unlike vtkSetClampMacro,
 * rejects NaN with an error on `object`. Returns true when `member` changed
 * (the caller then calls Modified()).
 */
bool SetClampedSetting(vtkObject* object, const char* name, double value, double minimum,
  double maximum, double& member);

/// Whether a VTK data type (VTK_INT, ...) holds integers; index arrays must.
bool IsIntegerType(int type);

/**
 * Whether `data` is an empty piece (null, or no points and no cells): what a
 * parallel reader gives the ranks that hold no data. Filters give an empty
 * output for it quietly, as VTK's own filters do.
 */
bool IsEmptyPiece(vtkPolyData* data);
}

#endif
