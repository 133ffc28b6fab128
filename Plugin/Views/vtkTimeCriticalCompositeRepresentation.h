// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkTimeCriticalCompositeRepresentation
 * @brief   ParaView's geometry representation with time-critical surfaces
 *
 * Server side of the "TimeCriticalGeometryRepresentation" proxy, the default
 * representation of polygonal data in vtkPVTimeCriticalRenderView. It offers
 * the representation types of ParaView's own (Outline, Points, Wireframe,
 * Surface, Surface With Edges, Feature Edges, 3D Glyphs, Point Gaussian), with
 * the four surface types drawn by a vtkTimeCriticalSurfaceRepresentation
 * instead of ParaView's surface representation: when the proxy registers both
 * for those keys, the time-critical one replaces the other. The other types
 * are ParaView's own.
 *
 * @sa vtkTimeCriticalSurfaceRepresentation vtkPVTimeCriticalRenderView
 */
#ifndef vtkTimeCriticalCompositeRepresentation_h
#define vtkTimeCriticalCompositeRepresentation_h

#include "TimeCriticalViewsModule.h" // for export macro
#include "vtkPVCompositeRepresentation.h"
#include "vtkWeakPointer.h" // for vtkWeakPointer

class vtkTimeCriticalSurfaceRepresentation;

class TIMECRITICALVIEWS_EXPORT vtkTimeCriticalCompositeRepresentation
  : public vtkPVCompositeRepresentation
{
public:
  static vtkTimeCriticalCompositeRepresentation* New();
  vtkTypeMacro(vtkTimeCriticalCompositeRepresentation, vtkPVCompositeRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Registers a vtkTimeCriticalSurfaceRepresentation under the four surface keys.
  void AddRepresentation(const char* key, vtkPVDataRepresentation* repr) override;

  /// As the superclass; a surface key also sets the time-critical surface's type.
  void SetActiveRepresentation(const char* key);

  vtkTimeCriticalSurfaceRepresentation* GetTimeCriticalSurface();

protected:
  vtkTimeCriticalCompositeRepresentation();
  ~vtkTimeCriticalCompositeRepresentation() override;

private:
  vtkTimeCriticalCompositeRepresentation(const vtkTimeCriticalCompositeRepresentation&) = delete;
  void operator=(const vtkTimeCriticalCompositeRepresentation&) = delete;

  vtkWeakPointer<vtkTimeCriticalSurfaceRepresentation> TimeCriticalSurface;
};

#endif
