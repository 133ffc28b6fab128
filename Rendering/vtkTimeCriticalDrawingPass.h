// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkTimeCriticalDrawingPass
 * @brief   render pass that tells a vtkTimeCriticalRenderer when its drawing is finished
 *
 * Renders its delegate pass, waits for the drawing to complete (glFinish),
 * and tells the state's renderer, when it is a vtkTimeCriticalRenderer, that
 * this frame's drawing is done (vtkTimeCriticalRenderer::MarkDrawingFinished).
 * Put where a frame holds more than the renderer's own drawing after it: a
 * parallel compositing pass, for instance, delegates the drawing to this
 * pass, so that each process's cost model learns the time of its own
 * drawing, not its wait for the slowest process in the composite
 * (vtkPVTimeCriticalRenderView installs it inside ParaView's IceT pass).
 * The wait costs nothing there: compositing reads the image back, which
 * waits for the drawing anyway.
 *
 * Without a delegate it renders nothing.
 *
 * @sa vtkTimeCriticalRenderer
 */
#ifndef vtkTimeCriticalDrawingPass_h
#define vtkTimeCriticalDrawingPass_h

#include "TimeCriticalRenderingModule.h" // for export macro
#include "vtkRenderPass.h"

class TIMECRITICALRENDERING_EXPORT vtkTimeCriticalDrawingPass : public vtkRenderPass
{
public:
  static vtkTimeCriticalDrawingPass* New();
  vtkTypeMacro(vtkTimeCriticalDrawingPass, vtkRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The pass that draws (ParaView's default pass, for instance).
  virtual void SetDelegatePass(vtkRenderPass* pass);
  vtkGetObjectMacro(DelegatePass, vtkRenderPass);
  ///@}

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkTimeCriticalDrawingPass();
  ~vtkTimeCriticalDrawingPass() override;

  vtkRenderPass* DelegatePass = nullptr;

private:
  vtkTimeCriticalDrawingPass(const vtkTimeCriticalDrawingPass&) = delete;
  void operator=(const vtkTimeCriticalDrawingPass&) = delete;
};

#endif
