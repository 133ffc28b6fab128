// SPDX-License-Identifier: BSD-3-Clause
// vtkMultiresolutionPolyDataMapper: construction, graphics resources, bounds,
// the render of one piece and PrintSelf. The other jobs are in
// vtkMultiresolutionPolyDataMapper{Objects,Fronts,VertexBuffers,IndexBuffer,
// IndexSlots,Colors,Blocks,Selection}.cxx, around the state of
// vtkMultiresolutionPolyDataMapperInternals.h.
#include "vtkMultiresolutionPolyDataMapperInternals.h"

#include "vtkActor.h"
#include "vtkCommand.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLIndexBufferObject.h"
#include "vtkOpenGLRenderTimer.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLTexture.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTextureObject.h"

#include <algorithm>

vtkStandardNewMacro(vtkMultiresolutionReleaseProxy);

vtkMultiresolutionReleaseProxy::vtkMultiresolutionReleaseProxy()
{
  vtkNew<vtkPolyData> empty; // no points: RenderPiece returns right after registering
  this->SetInputData(empty);
  this->StaticOn();
}

void vtkMultiresolutionReleaseProxy::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Superclass::ReleaseGraphicsResources(window);
  if (this->Owner)
  {
    this->Owner->ReleaseGraphicsResources(window);
  }
}

vtkStandardNewMacro(vtkMultiresolutionPolyDataMapper);

vtkMultiresolutionPolyDataMapper::vtkMultiresolutionPolyDataMapper()
  : Internal(new Internals)
{
  this->Internal->ReleaseProxy->Owner = this;
  this->Internal->Reader->SetRememberValidated(true);
}

vtkMultiresolutionPolyDataMapper::~vtkMultiresolutionPolyDataMapper()
{
  // Our buffers live in the window that still holds them (it would have
  // released them otherwise): free them there before the superclass deletes them.
  this->ReleaseGraphicsResources(nullptr);
  this->Internal->ReleaseProxy->Owner = nullptr;
}

void vtkMultiresolutionPolyDataMapper::ReleaseGraphicsResources(vtkWindow*)
{
  // The superclass releases only through its own callback, which cannot be
  // registered here (see vtkMultiresolutionReleaseProxy). Like that callback,
  // release in the context of the window that holds the buffers, whatever
  // window (or none) the caller names.
  Internals& in = *this->Internal;
  vtkOpenGLRenderWindow* window = in.Window;
  if (!window)
  {
    return; // nothing on any GPU
  }
  in.Window = nullptr;
  window->PushContext();
  this->VBOs->ReleaseGraphicsResources(window);
  for (int i = PrimitiveStart; i < PrimitiveEnd; ++i)
  {
    this->Primitives[i].ReleaseGraphicsResources(window);
    this->SelectionPrimitives[i].ReleaseGraphicsResources(window);
  }
  if (this->InternalColorTexture)
  {
    this->InternalColorTexture->ReleaseGraphicsResources(window);
  }
  if (this->CellScalarTexture)
  {
    this->CellScalarTexture->ReleaseGraphicsResources(window);
  }
  if (this->CellScalarBuffer)
  {
    this->CellScalarBuffer->ReleaseGraphicsResources();
  }
  if (this->CellNormalTexture)
  {
    this->CellNormalTexture->ReleaseGraphicsResources(window);
  }
  if (this->CellNormalBuffer)
  {
    this->CellNormalBuffer->ReleaseGraphicsResources();
  }
  if (this->EdgeTexture)
  {
    this->EdgeTexture->ReleaseGraphicsResources(window);
  }
  if (this->EdgeBuffer)
  {
    this->EdgeBuffer->ReleaseGraphicsResources();
  }
  if (in.PickTexture)
  {
    in.PickTexture->ReleaseGraphicsResources(window);
    in.PickBuffer->ReleaseGraphicsResources();
    in.PickFlagsStale = true;
  }
  this->TimerQuery->ReleaseGraphicsResources();
  window->PopContext();
  this->VBOBuildState.Clear();
  this->IBOBuildState.Clear();
  this->CellTextureBuildState.Clear();
  in.UploadedVersion = ~0ul;
  in.LayoutValid = false;
  this->Modified();
}

int vtkMultiresolutionPolyDataMapper::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port != 0)
  {
    return 0;
  }
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  return 1;
}

//------------------------------------------------------------------------------
void vtkMultiresolutionPolyDataMapper::ComputeBounds()
{
  Internals& in = *this->Internal;
  vtkMath::UninitializeBounds(this->Bounds);
  bool first = true;
  for (const auto& object : in.Objects)
  {
    if (!object.Visible || !vtkMath::AreBoundsInitialized(object.Bounds))
    {
      continue; // hidden blocks do not count, as in vtkCompositePolyDataMapper2
    }
    for (int k = 0; k < 3; ++k)
    {
      this->Bounds[2 * k] =
        first ? object.Bounds[2 * k] : std::min(this->Bounds[2 * k], object.Bounds[2 * k]);
      this->Bounds[2 * k + 1] = first ? object.Bounds[2 * k + 1]
                                      : std::max(this->Bounds[2 * k + 1], object.Bounds[2 * k + 1]);
    }
    first = false;
  }
}

double* vtkMultiresolutionPolyDataMapper::GetBounds()
{
  // The superclass asks GetInput(), a polydata; composite input has leaves.
  this->UpdateObjects();
  this->ComputeBounds();
  return this->Bounds;
}

//------------------------------------------------------------------------------
void vtkMultiresolutionPolyDataMapper::RenderPiece(vtkRenderer* ren, vtkActor* act)
{
  Internals& in = *this->Internal;
  this->NumberOfDrawCalls = 0;
  if (ren->GetRenderWindow()->CheckAbortStatus())
  {
    return;
  }
  // Registration first: moving to another window releases our buffers.
  in.ReleaseProxy->RenderPiece(ren, act);
  in.Window = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  if (this->GetNumberOfInputConnections(0) < 1)
  {
    vtkErrorMacro("No input!");
    return;
  }
  this->InvokeEvent(vtkCommand::StartEvent, nullptr);
  this->UpdateObjects();
  this->InvokeEvent(vtkCommand::EndEvent, nullptr);

  this->CurrentInput = in.Skeleton;
  if (!in.Skeleton || in.TotalVertices == 0)
  {
    // Nothing to draw (empty input or no polydata leaf).
    this->RenderedTriangles = 0;
    this->RenderedVertices = 0;
    this->NumberOfPaddingPrimitives = 0;
    for (auto& object : in.Objects)
    {
      object.RenderedTriangles = 0;
      object.RenderedVertices = 0;
    }
    return;
  }

  // Selection passes draw what the last frame drew: fronts and slots must not
  // change between the passes, whose ids are decoded against the slots.
  if (!ren->GetSelector())
  {
    this->RefineObjects(ren, act);
  }
  this->NumberOfRewrittenObjects = 0;
  this->IndexBytesUploaded = 0;
  this->CellDataBytesUploaded = 0;
  this->ColorBytesUploaded = 0;
  this->IndexUpdateTime = 0.0;
  for (auto& object : in.Objects)
  {
    object.Rewritten = false;
  }

  // As vtkOpenGLPolyDataMapper::RenderPiece, on the skeleton. Its GPU timer
  // (TimeToDraw) keys on the input's cells, which the skeleton does not hold:
  // the same schedule here with the leaves' cells (every render from a
  // million cells up, at least every 100 renders).
  if (in.TotalCells > 0)
  {
    ++this->TimerQueryCounter;
    if (this->TimerQueryCounter > 100 ||
      static_cast<double>(this->TimerQueryCounter) > 1e6 / static_cast<double>(in.TotalCells))
    {
      this->TimerQuery->ReusableStart();
      this->TimerQueryCounter = 0;
    }
  }
  this->UpdateCameraShiftScale(ren, act);
  this->PrepareBlockColors(act);
  this->ActivatePickability(ren);
  this->RenderPieceStart(ren, act);
  this->UploadBlockColors();
  this->RenderPieceDraw(ren, act);
  this->RenderPieceFinish(ren, act);
  this->DeactivatePickability();

  // Draw calls made by RenderPieceDraw: one per non-empty primitive type.
  const bool edges = act->GetProperty()->GetEdgeVisibility() &&
    act->GetProperty()->GetRepresentation() == VTK_SURFACE && !ren->GetSelector();
  const int last = edges ? PrimitiveEnd : PrimitiveTriStrips + 1;
  for (int i = PrimitiveStart; i < last; ++i)
  {
    this->NumberOfDrawCalls += this->Primitives[i].IBO->IndexCount > 0;
    this->NumberOfDrawCalls += this->SelectionPrimitives[i].IBO->IndexCount > 0;
  }
  this->NumberOfPaddingPrimitives = this->Primitives[PrimitiveTris].IBO->IndexCount > 0
    ? static_cast<vtkIdType>(in.Slots.GetTail() - in.Slots.GetUsed())
    : 0;
}

//------------------------------------------------------------------------------
void vtkMultiresolutionPolyDataMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const Internals& in = *this->Internal;
  os << indent << "NumberOfObjects: " << in.Objects.size() << "\n";
  os << indent << "ColorByResolution: " << this->ColorByResolution << "\n";
  os << indent << "RenderedTriangles: " << this->RenderedTriangles << "\n";
  os << indent << "RenderedVertices: " << this->RenderedVertices << "\n";
  os << indent << "NumberOfDrawCalls: " << this->NumberOfDrawCalls << "\n";
  os << indent << "ViewDependentRefinement: " << this->ViewDependentRefinement << "\n";
  os << indent << "RefinementMode: "
     << timecritical::RefinementModeName(timecritical::ClampRefinementMode(this->RefinementMode))
     << "\n";
  os << indent << "PixelThreshold: " << this->PixelThreshold << "\n";
  os << indent << "BackFaceSimplification: " << this->BackFaceSimplification << "\n";
  os << indent << "SilhouetteRefinement: " << this->SilhouetteRefinement
     << " (factor " << this->SilhouetteFactor << ")\n";
  os << indent << "HighlightRefinement: " << this->HighlightRefinement
     << " (factor " << this->HighlightFactor << ")\n";
  os << indent << "RefinementTime: " << this->RefinementTime << "\n";
  os << indent << "IndexSlack: " << this->IndexSlack << "\n";
  os << indent << "BackgroundBuilds: " << this->BackgroundBuilds << " (hierarchy "
     << this->BackgroundHierarchy << ", pending " << in.PendingHierarchies << ", swapped in "
     << this->NumberOfSwappedHierarchies << ")\n";
  os << indent << "NumberOfObjectReads: " << this->NumberOfObjectReads << " (untaken "
     << this->UntakenObjectReadTime << " s; last vertex buffer build "
     << this->LastVertexBufferBuildTime << " s)\n";
  os << indent << "NumberOfRewrittenObjects: " << this->NumberOfRewrittenObjects << "\n";
  os << indent << "IndexBytesUploaded: " << this->IndexBytesUploaded << "\n";
  os << indent << "CellDataBytesUploaded: " << this->CellDataBytesUploaded << "\n";
  os << indent << "NumberOfPaddingPrimitives: " << this->NumberOfPaddingPrimitives << "\n";
  os << indent << "IndexBufferRelayoutCount: " << in.Slots.GetLayoutCount() << "\n";
  const size_t shown = std::min<size_t>(in.Objects.size(), 20);
  for (size_t i = 0; i < shown; ++i)
  {
    const auto& object = in.Objects[i];
    os << indent << "Object " << i << ": flat index " << object.FlatIndex
       << (object.IsTOM ? ", TOM" : ", not a TOM") << ", " << object.NumberOfTriangles
       << " triangles, resolution " << object.Resolution << ", drawn " << object.RenderedTriangles
       << "\n";
  }
  if (shown < in.Objects.size())
  {
    os << indent << "... " << in.Objects.size() - shown << " more objects\n";
  }
}
