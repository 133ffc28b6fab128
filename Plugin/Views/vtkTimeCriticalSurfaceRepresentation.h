// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkTimeCriticalSurfaceRepresentation
 * @brief   ParaView surface representation drawn by the time-critical renderer
 *
 * The Surface, Wireframe, Points and Surface With Edges representation of
 * vtkPVTimeCriticalRenderView (server side of the
 * "TimeCriticalSurfaceRepresentation" proxy): ParaView's surface
 * representation (colouring, opacity, lighting, representation types,
 * visibility all as there) whose mapper is a vtkMultiresolutionPolyDataMapper,
 * so that every polydata leaf of its data is one object of the renderer's
 * optimizer.
 *
 * The hierarchies the mapper draws are built by a
 * vtkMultiresolutionHierarchyBuilder between ParaView's geometry filter and
 * the data delivery: once per leaf (with progress in ParaView's progress
 * bar), again only when the leaf's content changes, and never for leaves that
 * already carry one (TOMs or merge trees saved by the TimeCritical filters).
 * Hierarchy chooses uniform TOMs (default) or merge trees (view-dependent
 * refinement as well).
 *
 * With BackgroundBuilds on (the view's BackgroundHierarchyBuilds), the
 * builder is skipped: the surfaces are delivered as extracted, drawn at once
 * (in full, or large ones from a quick stand-in), and the mapper builds
 * their hierarchies on worker threads
 * (vtkMultiresolutionPolyDataMapper::SetBackgroundBuilds), so that a new
 * time step or an upstream edit never holds the view for a build.
 *
 * In parallel every rank builds and draws its own pieces (the data is never
 * gathered onto one rank nor redistributed): translucent surfaces whose
 * pieces interleave in depth are composited in rank order.
 *
 * ParaView's interactive LOD is not used (the view's budget replaces it).
 * Block colours, block opacities and block visibilities of composite data
 * (the Multiblock Inspector's) are given to the mapper as the Render View
 * gives them to its composite mapper: a hidden block is culled and costs
 * the view's budget nothing, a block colour replaces the colouring of that
 * block, a translucent block is drawn in the translucent pass.
 *
 * @sa vtkPVTimeCriticalRenderView vtkTimeCriticalCompositeRepresentation
 */
#ifndef vtkTimeCriticalSurfaceRepresentation_h
#define vtkTimeCriticalSurfaceRepresentation_h

#include "TimeCriticalViewsModule.h" // for export macro
#include "vtkGeometryRepresentationWithFaces.h"
#include "vtkNew.h" // for vtkNew

class vtkMultiresolutionHierarchyBuilder;
class vtkMultiresolutionPolyDataMapper;

class TIMECRITICALVIEWS_EXPORT vtkTimeCriticalSurfaceRepresentation
  : public vtkGeometryRepresentationWithFaces
{
public:
  static vtkTimeCriticalSurfaceRepresentation* New();
  vtkTypeMacro(vtkTimeCriticalSurfaceRepresentation, vtkGeometryRepresentationWithFaces);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// vtkMultiresolutionHierarchyBuilder::Hierarchies: TOTALLY_ORDERED_MESH (default) or MERGE_TREE.
  void SetHierarchy(int hierarchy);
  int GetHierarchy();
  ///@}

  ///@{
  /**
   * Skip the synchronous builder and let the mapper build the hierarchies
   * in the background (see the class comment). Default off; set by
   * vtkPVTimeCriticalRenderView from its BackgroundHierarchyBuilds.
   */
  void SetBackgroundBuilds(bool on);
  vtkGetMacro(BackgroundBuilds, bool);
  ///@}

  vtkMultiresolutionHierarchyBuilder* GetHierarchyBuilder();
  vtkMultiresolutionPolyDataMapper* GetMultiresolutionMapper();

  /**
   * As ParaView's surface representation, except that the data stays on the
   * rank that built it: the view renders it where it is (distributed
   * rendering, never gathered onto one rank, which would append the pieces'
   * hierarchies into an invalid one) and does not redistribute it for
   * ordered compositing.
   */
  int ProcessViewRequest(vtkInformationRequestKey* request_type, vtkInformation* inInfo,
    vtkInformation* outInfo) override;

  /**
   * Hardware selection's id arrays, on the multiresolution mapper (which
   * reports each leaf's own cell and point ids at any resolution): default
   * vtkOriginalPointIds and vtkOriginalCellIds, which ParaView's geometry
   * filter adds and the hierarchy builders carry through their reordering,
   * so selections name the cells of the data as it was loaded.
   */
  void SetArrayIdNames(const char* pointArray, const char* cellArray) override;

protected:
  vtkTimeCriticalSurfaceRepresentation();
  ~vtkTimeCriticalSurfaceRepresentation() override;

  void ForwardBuildProgress(vtkObject* caller, unsigned long, void*);

private:
  vtkTimeCriticalSurfaceRepresentation(const vtkTimeCriticalSurfaceRepresentation&) = delete;
  void operator=(const vtkTimeCriticalSurfaceRepresentation&) = delete;

  vtkNew<vtkMultiresolutionHierarchyBuilder> HierarchyBuilder;
  bool BackgroundBuilds = false;
};

#endif
