// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPVTimeCriticalStatisticsInformation.h"

#include "vtkClientServerStream.h"
#include "TimeCriticalStatisticsText.h"
#include "vtkObjectFactory.h"
#include "vtkPVRenderView.h"
#include "vtkTimeCriticalRenderer.h"

vtkStandardNewMacro(vtkPVTimeCriticalStatisticsInformation);

vtkPVTimeCriticalStatisticsInformation::vtkPVTimeCriticalStatisticsInformation()
{
  this->RootOnly = 1; // rank 0's text holds the ranks' summary
}

vtkPVTimeCriticalStatisticsInformation::~vtkPVTimeCriticalStatisticsInformation() = default;

void vtkPVTimeCriticalStatisticsInformation::CopyFromObject(vtkObject* object)
{
  // The view's own text (vtkPVTimeCriticalRenderView::GetLocalStatisticsText()),
  // read from its renderer so that this class needs no view.
  auto* view = vtkPVRenderView::SafeDownCast(object);
  const bool ours = view && view->IsA("vtkPVTimeCriticalRenderView");
  auto* renderer = ours ? vtkTimeCriticalRenderer::SafeDownCast(view->GetRenderer()) : nullptr;
  this->Text = ours ? TimeCriticalStatisticsText::Format(renderer) : std::string();
  this->NumberOfDroppedObjects = renderer ? renderer->GetNumberOfDroppedObjects() : 0;
}

void vtkPVTimeCriticalStatisticsInformation::AddInformation(vtkPVInformation* other)
{
  auto* statistics = vtkPVTimeCriticalStatisticsInformation::SafeDownCast(other);
  if (statistics && this->Text.empty())
  {
    this->Text = statistics->Text;
    this->NumberOfDroppedObjects = statistics->NumberOfDroppedObjects;
  }
}

void vtkPVTimeCriticalStatisticsInformation::CopyToStream(vtkClientServerStream* stream)
{
  stream->Reset();
  *stream << vtkClientServerStream::Reply << this->Text.c_str()
          << static_cast<vtkTypeInt64>(this->NumberOfDroppedObjects) << vtkClientServerStream::End;
}

void vtkPVTimeCriticalStatisticsInformation::CopyFromStream(const vtkClientServerStream* stream)
{
  const char* text = nullptr;
  this->Text = stream->GetArgument(0, 0, &text) && text ? text : "";
  vtkTypeInt64 dropped = 0;
  this->NumberOfDroppedObjects =
    stream->GetArgument(0, 1, &dropped) ? static_cast<vtkIdType>(dropped) : 0;
}

void vtkPVTimeCriticalStatisticsInformation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Text: " << this->Text << "\n";
  os << indent << "NumberOfDroppedObjects: " << this->NumberOfDroppedObjects << "\n";
}
