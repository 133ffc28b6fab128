// SPDX-License-Identifier: BSD-3-Clause
#ifndef TimeCriticalStatisticsText_h
#define TimeCriticalStatisticsText_h

#include "vtkType.h" // for vtkIdType

#include <string> // for std::string

class vtkInformationDoubleKey;
class vtkInformationIntegerKey;
class vtkRenderer;
class vtkTimeCriticalRenderer;

/**
 * The statistics overlay of the Time-Critical Render View: formats the last
 * frame's figures of a vtkTimeCriticalRenderer (target, prediction,
 * measurement, triangles, objects drawn, dropped and culled, optimizer, and the slowest rank when
 * several rendered) into the text the view shows and a server sends its
 * clients (vtkPVTimeCriticalStatisticsInformation). Both read it from the
 * renderer, so neither needs the other.
 *
 * The rank summary is gathered by the view (a collective after each render)
 * and kept on the renderer's information with SetRankSummary().
 */
class TimeCriticalStatisticsText
{
public:
  /// The overlay text of `renderer`'s last frame; null: a note that time-critical rendering is
  /// unavailable.
  static std::string Format(vtkTimeCriticalRenderer* renderer);

  /// Keeps the ranks that rendered the last frame and the slowest one's measured time (seconds).
  static void SetRankSummary(vtkRenderer* renderer, int ranks, double slowestMeasuredTime);

  /// `value` with thousands separators (1,234,567).
  static std::string WithThousands(vtkIdType value);

  ///@{
  /// Keys of the rank summary on the renderer's information.
  static vtkInformationIntegerKey* NUMBER_OF_RANKS();
  static vtkInformationDoubleKey* SLOWEST_MEASURED_TIME();
  ///@}
};

#endif
