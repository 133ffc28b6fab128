// SPDX-License-Identifier: BSD-3-Clause
#include "vtkTimeCriticalSurfaceRepresentation.h"

#include "vtkCommand.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkDataObject.h"
#include "vtkMultiresolutionHierarchyBuilder.h"
#include "vtkMultiresolutionPolyDataMapper.h"
#include "vtkObjectFactory.h"
#include "vtkPVLODActor.h"
#include "vtkPVRenderView.h"

vtkStandardNewMacro(vtkTimeCriticalSurfaceRepresentation);

//------------------------------------------------------------------------------
vtkTimeCriticalSurfaceRepresentation::vtkTimeCriticalSurfaceRepresentation()
{
  // The base class made a vtkCompositePolyDataMapper2 and set it up; the
  // multiresolution mapper takes its place with the same selection.
  vtkMultiresolutionPolyDataMapper* mapper = vtkMultiresolutionPolyDataMapper::New();
  mapper->SetSelection(this->Mapper->GetSelection());
  mapper->SetProcessIdArrayName("vtkProcessId");
  mapper->SetCompositeIdArrayName("vtkCompositeIndex");
  // Block colors, opacities and visibilities (Multiblock Inspector), as the
  // base class gives its vtkCompositePolyDataMapper2.
  vtkNew<vtkCompositeDataDisplayAttributes> blockAttributes;
  mapper->SetCompositeDataDisplayAttributes(blockAttributes);
  this->Mapper->Delete();
  this->Mapper = mapper;
  this->SetArrayIdNames(nullptr, nullptr);
  this->Actor->SetMapper(this->Mapper);
  // No decimated LOD copy: the view's budget replaces it.
  this->SetSuppressLOD(true);

  // Hierarchies are built on the surface the geometry filter extracts,
  // before the data is delivered to the rendering processes.
  this->HierarchyBuilder->SetInputConnection(this->GeometryFilter->GetOutputPort());
  this->MultiBlockMaker->SetInputConnection(this->HierarchyBuilder->GetOutputPort());
  // One progress from 0 to 1 for the whole update: the surface extraction
  // takes its first tenth, the builds (far longer) the rest. The base
  // class's observers would restart the bar between the stages.
  this->GeometryFilter->RemoveObservers(vtkCommand::ProgressEvent);
  this->MultiBlockMaker->RemoveObservers(vtkCommand::ProgressEvent);
  this->GeometryFilter->AddObserver(vtkCommand::ProgressEvent, this,
    &vtkTimeCriticalSurfaceRepresentation::ForwardBuildProgress);
  this->HierarchyBuilder->AddObserver(vtkCommand::ProgressEvent, this,
    &vtkTimeCriticalSurfaceRepresentation::ForwardBuildProgress);
}

vtkTimeCriticalSurfaceRepresentation::~vtkTimeCriticalSurfaceRepresentation() = default;

//------------------------------------------------------------------------------
void vtkTimeCriticalSurfaceRepresentation::SetHierarchy(int hierarchy)
{
  if (hierarchy != this->HierarchyBuilder->GetHierarchy())
  {
    this->HierarchyBuilder->SetHierarchy(hierarchy);
    this->GetMultiresolutionMapper()->SetBackgroundHierarchy(
      this->HierarchyBuilder->GetHierarchy());
    this->MarkModified();
  }
}

void vtkTimeCriticalSurfaceRepresentation::SetBackgroundBuilds(bool on)
{
  if (on == this->BackgroundBuilds)
  {
    return;
  }
  this->BackgroundBuilds = on;
  // Background: the extracted surfaces go straight to the delivery and the
  // mapper builds; otherwise the builder builds before the delivery.
  this->MultiBlockMaker->SetInputConnection(on ? this->GeometryFilter->GetOutputPort()
                                               : this->HierarchyBuilder->GetOutputPort());
  vtkMultiresolutionPolyDataMapper* mapper = this->GetMultiresolutionMapper();
  mapper->SetBackgroundHierarchy(this->HierarchyBuilder->GetHierarchy());
  mapper->SetBackgroundBuilds(on);
  this->MarkModified();
}

int vtkTimeCriticalSurfaceRepresentation::GetHierarchy()
{
  return this->HierarchyBuilder->GetHierarchy();
}

vtkMultiresolutionHierarchyBuilder* vtkTimeCriticalSurfaceRepresentation::GetHierarchyBuilder()
{
  return this->HierarchyBuilder;
}

vtkMultiresolutionPolyDataMapper* vtkTimeCriticalSurfaceRepresentation::GetMultiresolutionMapper()
{
  return vtkMultiresolutionPolyDataMapper::SafeDownCast(this->Mapper);
}

//------------------------------------------------------------------------------
int vtkTimeCriticalSurfaceRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* request_type, vtkInformation* inInfo, vtkInformation* outInfo)
{
  // The base class hands block attributes to a vtkCompositePolyDataMapper2
  // only, and marks them applied whatever its mapper: whether they must be
  // applied is decided before it runs, and they are given to our mapper after.
  vtkDataObject* delivered = nullptr;
  bool blockAttributes = false;
  if (request_type == vtkPVView::REQUEST_RENDER())
  {
    delivered = vtkPVView::GetDeliveredPiece(inInfo, this);
    blockAttributes = delivered &&
      (this->BlockAttributeTime < delivered->GetMTime() || this->BlockAttrChanged);
  }
  if (!this->Superclass::ProcessViewRequest(request_type, inInfo, outInfo))
  {
    return 0;
  }
  if (blockAttributes)
  {
    this->PopulateBlockAttributes(
      this->GetMultiresolutionMapper()->GetCompositeDataDisplayAttributes(), delivered);
  }
  if (request_type == vtkPVView::REQUEST_UPDATE())
  {
    vtkPVRenderView::SetRequiresDistributedRendering(inInfo, this, true);
    vtkPVRenderView::SetOrderedCompositingConfiguration(inInfo, this, 0);
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkTimeCriticalSurfaceRepresentation::SetArrayIdNames(
  const char* pointArray, const char* cellArray)
{
  // Not the superclass's: it sets them on a vtkCompositePolyDataMapper2.
  auto* mapper = vtkMultiresolutionPolyDataMapper::SafeDownCast(this->Mapper);
  mapper->SetPointIdArrayName(pointArray ? pointArray : "vtkOriginalPointIds");
  mapper->SetCellIdArrayName(cellArray ? cellArray : "vtkOriginalCellIds");
}

//------------------------------------------------------------------------------
void vtkTimeCriticalSurfaceRepresentation::ForwardBuildProgress(
  vtkObject* caller, unsigned long, void*)
{
  auto* algorithm = static_cast<vtkAlgorithm*>(caller);
  const double progress = algorithm->GetProgress();
  if (progress > 0.0 && progress < 1.0)
  {
    this->UpdateProgress(
      algorithm == this->GeometryFilter ? 0.1 * progress : 0.1 + 0.9 * progress);
  }
  if (this->AbortExecute)
  {
    algorithm->SetAbortExecute(1);
  }
}

//------------------------------------------------------------------------------
void vtkTimeCriticalSurfaceRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "HierarchyBuilder: " << this->HierarchyBuilder << "\n";
  os << indent << "BackgroundBuilds: " << this->BackgroundBuilds << "\n";
}
