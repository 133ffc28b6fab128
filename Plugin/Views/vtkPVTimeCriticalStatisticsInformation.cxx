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
  this->Text = view && view->IsA("vtkPVTimeCriticalRenderView")
    ? TimeCriticalStatisticsText::Format(vtkTimeCriticalRenderer::SafeDownCast(view->GetRenderer()))
    : std::string();
}

void vtkPVTimeCriticalStatisticsInformation::AddInformation(vtkPVInformation* other)
{
  auto* statistics = vtkPVTimeCriticalStatisticsInformation::SafeDownCast(other);
  if (statistics && this->Text.empty())
  {
    this->Text = statistics->Text;
  }
}

void vtkPVTimeCriticalStatisticsInformation::CopyToStream(vtkClientServerStream* stream)
{
  stream->Reset();
  *stream << vtkClientServerStream::Reply << this->Text.c_str() << vtkClientServerStream::End;
}

void vtkPVTimeCriticalStatisticsInformation::CopyFromStream(const vtkClientServerStream* stream)
{
  const char* text = nullptr;
  this->Text = stream->GetArgument(0, 0, &text) && text ? text : "";
}

void vtkPVTimeCriticalStatisticsInformation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Text: " << this->Text << "\n";
}
