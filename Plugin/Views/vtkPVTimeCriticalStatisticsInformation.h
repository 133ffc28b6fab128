// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkPVTimeCriticalStatisticsInformation
 * @brief   the statistics of a vtkPVTimeCriticalRenderView, gathered from the server
 *
 * In client-server mode the time-critical renderer that plans the frames is
 * the server's: the client's view gathers this information after each
 * render in which ShowStatistics is on, to show the server's figures in its
 * overlay, and the number of objects that frame dropped. With several server
 * ranks they are rank 0's, whose text already holds the slowest rank's time.
 *
 * @sa vtkPVTimeCriticalRenderView
 */
#ifndef vtkPVTimeCriticalStatisticsInformation_h
#define vtkPVTimeCriticalStatisticsInformation_h

#include "TimeCriticalViewsModule.h" // for export macro
#include "vtkPVInformation.h"

#include <string> // for std::string

class TIMECRITICALVIEWS_EXPORT vtkPVTimeCriticalStatisticsInformation : public vtkPVInformation
{
public:
  static vtkPVTimeCriticalStatisticsInformation* New();
  vtkTypeMacro(vtkPVTimeCriticalStatisticsInformation, vtkPVInformation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// From a vtkPVTimeCriticalRenderView (anything else gives no text).
  void CopyFromObject(vtkObject* object) override;
  /// Keeps the first non-empty text (rank 0's comes first).
  void AddInformation(vtkPVInformation* other) override;
  void CopyToStream(vtkClientServerStream* stream) override;
  void CopyFromStream(const vtkClientServerStream* stream) override;

  /// The statistics text (empty when none was gathered).
  const char* GetText() const { return this->Text.c_str(); }
  /// Objects the last frame left out because it was overloaded (0 when none was gathered).
  vtkIdType GetNumberOfDroppedObjects() const { return this->NumberOfDroppedObjects; }

protected:
  vtkPVTimeCriticalStatisticsInformation();
  ~vtkPVTimeCriticalStatisticsInformation() override;

private:
  vtkPVTimeCriticalStatisticsInformation(const vtkPVTimeCriticalStatisticsInformation&) = delete;
  void operator=(const vtkPVTimeCriticalStatisticsInformation&) = delete;

  std::string Text;
  vtkIdType NumberOfDroppedObjects = 0;
};

#endif
