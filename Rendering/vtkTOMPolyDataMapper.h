// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkTOMPolyDataMapper
 * @brief   renders a Totally Ordered Mesh at a chosen resolution
 *
 * An OpenGL polydata mapper for the output of vtkTOMBuilder. Points and their
 * attributes are uploaded once, at full resolution; changing the resolution
 * only rewrites the index buffer, filled by the TOM traversal core (no
 * allocation once the buffer has grown). Cell data stays correct because the
 * triangles of every resolution are a prefix of the cells.
 *
 * Input that is not a valid TOM renders at full resolution with one warning.
 *
 * @sa vtkTOMBuilder vtkExtractTOMResolution
 */
#ifndef vtkTOMPolyDataMapper_h
#define vtkTOMPolyDataMapper_h

#include "TimeCriticalRenderingModule.h" // for export macro
#include "vtkOpenGLPolyDataMapper.h"

#include <memory> // for std::unique_ptr

class TIMECRITICALRENDERING_EXPORT vtkTOMPolyDataMapper : public vtkOpenGLPolyDataMapper
{
public:
  static vtkTOMPolyDataMapper* New();
  vtkTypeMacro(vtkTOMPolyDataMapper, vtkOpenGLPolyDataMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Fraction of the full triangle count to draw, in [0,1]. Default 1.
  vtkSetClampMacro(Resolution, double, 0.0, 1.0);
  vtkGetMacro(Resolution, double);
  ///@}

  ///@{
  /// What the last render drew.
  vtkGetMacro(RenderedTriangles, vtkIdType);
  vtkGetMacro(RenderedVertices, vtkIdType);
  ///@}

  /// True when the current input was read as a valid TOM.
  bool GetInputIsTOM() const;

protected:
  vtkTOMPolyDataMapper();
  ~vtkTOMPolyDataMapper() override;

  ///@{
  /// Input with bad point ids or coordinates: an error, no bounds, nothing drawn.
  void RenderPiece(vtkRenderer* ren, vtkActor* act) override;
  void ComputeBounds() override;
  ///@}
  bool GetNeedToRebuildBufferObjects(vtkRenderer* ren, vtkActor* act) override;
  void BuildBufferObjects(vtkRenderer* ren, vtkActor* act) override;
  void BuildIBO(vtkRenderer* ren, vtkActor* act, vtkPolyData* poly) override;

  double Resolution = 1.0;
  vtkIdType RenderedTriangles = 0;
  vtkIdType RenderedVertices = 0;

private:
  /// Checks the input once per version (vtkPolyDataValidator); false, with one error, when bad.
  bool CheckInput();

  vtkTOMPolyDataMapper(const vtkTOMPolyDataMapper&) = delete;
  void operator=(const vtkTOMPolyDataMapper&) = delete;

  void UploadResolution(vtkActor* act);

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
