// SPDX-License-Identifier: BSD-3-Clause
#include "vtkTimeCriticalDrawingPass.h"

#include "vtkObjectFactory.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkTimeCriticalRenderer.h"
#include "vtk_glew.h"

vtkStandardNewMacro(vtkTimeCriticalDrawingPass);
vtkCxxSetObjectMacro(vtkTimeCriticalDrawingPass, DelegatePass, vtkRenderPass);

vtkTimeCriticalDrawingPass::vtkTimeCriticalDrawingPass() = default;

vtkTimeCriticalDrawingPass::~vtkTimeCriticalDrawingPass()
{
  this->SetDelegatePass(nullptr);
}

void vtkTimeCriticalDrawingPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  if (!this->DelegatePass)
  {
    return;
  }
  this->DelegatePass->Render(s);
  this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
  if (auto* renderer = vtkTimeCriticalRenderer::SafeDownCast(s->GetRenderer()))
  {
    glFinish(); // the drawing's time includes its rasterization
    renderer->MarkDrawingFinished();
  }
}

void vtkTimeCriticalDrawingPass::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->DelegatePass)
  {
    this->DelegatePass->ReleaseGraphicsResources(window);
  }
}

void vtkTimeCriticalDrawingPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DelegatePass: " << this->DelegatePass << "\n";
}
