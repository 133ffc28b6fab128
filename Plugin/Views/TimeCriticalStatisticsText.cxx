// SPDX-License-Identifier: BSD-3-Clause
#include "TimeCriticalStatisticsText.h"

#include "vtkActor.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleKey.h"
#include "vtkInformationIntegerKey.h"
#include "vtkMultiresolutionPolyDataMapper.h"
#include "vtkNew.h"
#include "vtkTimeCriticalRenderer.h"

#include <cmath>
#include <iomanip>
#include <sstream>

vtkInformationKeyMacro(TimeCriticalStatisticsText, NUMBER_OF_RANKS, Integer);
vtkInformationKeyMacro(TimeCriticalStatisticsText, SLOWEST_MEASURED_TIME, Double);

namespace
{
/// Triangles of all objects at full resolution.
vtkIdType FullTriangles(vtkTimeCriticalRenderer* renderer)
{
  vtkIdType total = 0;
  const vtkIdType objects = renderer->GetNumberOfObjects();
  for (vtkIdType i = 0; i < objects; ++i)
  {
    auto* mapper =
      vtkMultiresolutionPolyDataMapper::SafeDownCast(renderer->GetObjectActor(i)->GetMapper());
    if (mapper)
    {
      total += mapper->GetObjectNumberOfTriangles(renderer->GetObjectIndex(i));
    }
  }
  return total;
}

void WriteFrameTimes(vtkTimeCriticalRenderer* renderer, std::ostringstream& text)
{
  text << "Last frame: ";
  if (renderer->GetLastRenderWasStill())
  {
    text << "still, full resolution\n";
  }
  else
  {
    text << "target " << renderer->GetLastTargetFrameTime() * 1000.0 << " ms, predicted "
         << renderer->GetPredictedFrameTime() * 1000.0 << " ms\n";
  }
  const double measured = renderer->GetMeasuredFrameTime();
  text << "Measured: ";
  if (std::isfinite(measured))
  {
    text << measured * 1000.0 << " ms\n";
  }
  else
  {
    text << "-\n";
  }
}

void WriteRankSummary(vtkTimeCriticalRenderer* renderer, std::ostringstream& text)
{
  vtkInformation* information = renderer->GetInformation();
  const int ranks = information && information->Has(TimeCriticalStatisticsText::NUMBER_OF_RANKS())
    ? information->Get(TimeCriticalStatisticsText::NUMBER_OF_RANKS())
    : 1;
  if (ranks > 1)
  {
    const double slowest = information->Get(TimeCriticalStatisticsText::SLOWEST_MEASURED_TIME());
    text << std::setprecision(1) << "\nRanks: " << ranks << ", slowest measured "
         << slowest * 1000.0 << " ms";
  }
}
}

std::string TimeCriticalStatisticsText::Format(vtkTimeCriticalRenderer* renderer)
{
  if (!renderer)
  {
    return "Time-critical rendering unavailable (see the error messages)";
  }
  const vtkIdType total = FullTriangles(renderer);
  const vtkIdType drawn = renderer->GetObjectTrianglesDrawn();
  const vtkIdType objects = renderer->GetNumberOfObjects();
  std::ostringstream text;
  text << std::fixed << std::setprecision(1);
  WriteFrameTimes(renderer, text);
  text << "Triangles: " << WithThousands(drawn) << " of " << WithThousands(total);
  if (total > 0)
  {
    text << " (" << 100.0 * static_cast<double>(drawn) / static_cast<double>(total) << "%)";
  }
  // Dropped: left out of an overloaded frame (vtkTimeCriticalRenderer::
  // SetDropObjectsWhenOverloaded), named only when there are any.
  const vtkIdType culled = renderer->GetNumberOfCulledObjects();
  const vtkIdType dropped = renderer->GetNumberOfDroppedObjects();
  text << "\nObjects: " << WithThousands(objects - culled - dropped) << " drawn, ";
  if (dropped > 0)
  {
    text << WithThousands(dropped) << " dropped, ";
  }
  text << WithThousands(culled) << " culled\n";
  text << std::setprecision(2) << "Optimizer: " << renderer->GetOptimizationTime() * 1000.0
       << " ms, " << renderer->GetOptimizationIterations() << " iterations";
  WriteRankSummary(renderer, text);
  return text.str();
}

void TimeCriticalStatisticsText::SetRankSummary(
  vtkRenderer* renderer, int ranks, double slowestMeasuredTime)
{
  if (!renderer->GetInformation())
  {
    vtkNew<vtkInformation> information;
    renderer->SetInformation(information);
  }
  renderer->GetInformation()->Set(NUMBER_OF_RANKS(), ranks);
  renderer->GetInformation()->Set(SLOWEST_MEASURED_TIME(), slowestMeasuredTime);
}

std::string TimeCriticalStatisticsText::WithThousands(vtkIdType value)
{
  std::string digits = std::to_string(value);
  for (int i = static_cast<int>(digits.size()) - 3; i > 0; i -= 3)
  {
    digits.insert(static_cast<size_t>(i), ",");
  }
  return digits;
}
