// SPDX-License-Identifier: BSD-3-Clause
// vtkMultiresolutionPolyDataMapper: the index buffer of the triangle
// primitive. A full rebuild sizes every buffer for all objects at full
// resolution; an update rewrites the slots of the objects whose content
// changed (IndexSlots.cxx), compacts when there is no room or too much
// padding, and uploads only the rewritten ranges.
#include "vtkMultiresolutionPolyDataMapperInternals.h"

#include "TOMIndexLayout.h"

#include "vtkActor.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLCellToVTKCellMap.h"
#include "vtkOpenGLIndexBufferObject.h"
#include "vtkProperty.h"

#include "vtk_glew.h"

#include <chrono>

using vtkMultiresolutionMapperDetail::ContentKind;
using vtkMultiresolutionMapperDetail::Grow;

namespace
{
/// Dirty ranges closer than this (primitives) are uploaded as one: the
/// unchanged primitives between them cost less than another upload call.
constexpr size_t UploadGap = 256;
}

void vtkMultiresolutionPolyDataMapper::BuildIBO(vtkRenderer* ren, vtkActor* act, vtkPolyData* poly)
{
  if (this->Internal->HasOtherCells)
  {
    // Vertices, lines and strips of non-TOM leaves keep VTK's index buffers.
    this->Superclass::BuildIBO(ren, act, poly);
  }
  else
  {
    this->Primitives[PrimitivePoints].IBO->IndexCount = 0;
    this->Primitives[PrimitiveLines].IBO->IndexCount = 0;
    this->Primitives[PrimitiveTriStrips].IBO->IndexCount = 0;
    this->Primitives[PrimitiveVertices].IBO->IndexCount = 0;
  }
  // Edge flags are per full-resolution primitive; without them every
  // triangle edge is drawn, which is right for triangle meshes.
  this->EdgeValues.clear();
  this->FillIndexBuffer(ren, act, true);
}

void vtkMultiresolutionPolyDataMapper::PatchStripOffset()
{
  // VTK numbers the skeleton's strips right after its (no) polygons; they are
  // drawn after the triangle index buffer, whose primitives (up to its
  // capacity) come first in gl_PrimitiveID + offset and in the cell textures.
  Internals& in = *this->Internal;
  if (in.HasOtherCells)
  {
    vtkIdType* offsets = this->CellCellMap->GetPrimitiveOffsets();
    offsets[3] = offsets[2] + static_cast<vtkIdType>(in.Slots.GetCapacity());
  }
}

//------------------------------------------------------------------------------
void vtkMultiresolutionPolyDataMapper::PrepareLayout(vtkRenderer* ren, vtkActor* act)
{
  // A full rebuild: representation, cell data and the capacity of every
  // buffer for this input; the buffers are (re)allocated at that capacity.
  Internals& in = *this->Internal;
  vtkProperty* prop = act->GetProperty();
  in.Representation = prop->GetRepresentation();
  in.CellData = this->HaveCellScalars || this->HaveCellNormals;
  // Points of TOMs are their active vertices, unless cell data needs one
  // primitive per triangle corner (VTK's layout for points).
  in.Corners = in.Representation == VTK_POINTS && in.CellData;
  in.PerPrimitive = in.Representation == VTK_WIREFRAME ? 2 : in.Representation == VTK_POINTS ? 1 : 3;
  in.VertexVisibility = prop->GetVertexVisibility() != 0;
  in.FullPrimitives.resize(in.Objects.size());
  for (auto& object : in.Objects)
  {
    const auto triangles = static_cast<size_t>(object.NumberOfTriangles);
    size_t& full = in.FullPrimitives[in.IndexOf(object)];
    if (!object.IsTOM)
    {
      full = in.Representation == VTK_SURFACE ? triangles
                                              : static_cast<size_t>(object.PolyConnectivity);
    }
    else if (in.Representation == VTK_POINTS && !in.Corners)
    {
      full = static_cast<size_t>(object.NumberOfVertices);
    }
    else
    {
      full = (in.Representation == VTK_SURFACE ? 1 : 3) * triangles;
    }
    object.Written = Internals::Content();
  }
  // A point with all indices equal is still a point: points get no padding.
  in.Slots.Configure(in.FullPrimitives, in.Representation != VTK_POINTS);
  const size_t capacity = in.Slots.GetCapacity();
  this->PatchStripOffset();
  Grow(in.Indices, in.PerPrimitive * capacity);
  if (in.CellData)
  {
    Grow(in.PrimitiveCells, capacity);
  }
  // Bounds that keep every per-frame insertion within reserved capacity.
  in.DirtyIndices.reserve(3 * in.Objects.size() + 8);
  in.DirtyTexels.reserve(in.Objects.size() + 8);
  if (in.VertexVisibility)
  {
    Grow(in.VertexIndices, static_cast<size_t>(in.TotalVertices));
  }

  vtkOpenGLIndexBufferObject* ibo = this->Primitives[PrimitiveTris].IBO;
  if (capacity > 0)
  {
    // Allocated once at full capacity, written with glBufferSubData.
    ibo->GenerateBuffer(vtkOpenGLBufferObject::ElementArrayBuffer);
    ibo->Bind();
    glBufferData(GL_ELEMENT_ARRAY_BUFFER,
      static_cast<GLsizeiptr>(sizeof(uint32_t) * in.PerPrimitive * capacity), nullptr,
      GL_DYNAMIC_DRAW);
    ibo->Release();
  }
  ibo->IndexCount = 0;
  if (in.CellData)
  {
    this->AllocateCellTextures(ren);
  }
  in.LayoutValid = true;
}

void vtkMultiresolutionPolyDataMapper::FillIndexBuffer(
  vtkRenderer* ren, vtkActor* act, bool rebuild)
{
  Internals& in = *this->Internal;
  const auto startTime = std::chrono::steady_clock::now();
  in.UploadedVersion = in.ResolutionVersion;
  ++in.IndexBufferBuildCount;
  in.CompactValid = false;
  bool layOut = rebuild || !in.LayoutValid;
  if (layOut)
  {
    this->PrepareLayout(ren, act);
  }
  else
  {
    layOut = !this->UpdateSlots();
  }
  if (layOut)
  {
    in.LayOut(this->ViewDependentRefinement, this->IndexSlack);
  }
  this->UploadIndexRanges();

  this->RenderedTriangles = 0;
  this->RenderedVertices = 0;
  for (auto& object : in.Objects)
  {
    this->RenderedTriangles += object.RenderedTriangles;
    this->RenderedVertices += object.RenderedVertices;
    this->NumberOfRewrittenObjects += object.Rewritten ? 1 : 0;
    if (object.Rewritten && object.Written.Kind != ContentKind::Culled)
    {
      this->UpdateResolutionColor(&object - in.Objects.data());
    }
  }
  if (in.VertexVisibility)
  {
    this->FillVertexIndices();
  }
  if (in.ResolutionColors && this->ColorByResolution)
  {
    this->UploadResolutionColors();
  }
  this->IndexUpdateTime =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - startTime).count();
}

bool vtkMultiresolutionPolyDataMapper::UpdateSlots()
{
  // Rewrites the slots of the objects whose content changed; false when the
  // buffer must be laid out again.
  Internals& in = *this->Internal;
  in.DirtyIndices.clear();
  in.DirtyTexels.clear();
  bool compacted = false;
  for (auto& object : in.Objects)
  {
    const Internals::Content content = in.Describe(object, this->ViewDependentRefinement);
    if (content == object.Written)
    {
      continue; // unchanged: neither extracted nor uploaded
    }
    if (!in.Update(object, content, this->IndexSlack))
    {
      // No room left: compact and try again; points (which cannot pad)
      // and a buffer full even then are laid out again from scratch.
      if (!in.Slots.GetCanPad() || compacted)
      {
        return false;
      }
      in.Compact(this->IndexSlack);
      compacted = true;
      if (!in.Update(object, content, this->IndexSlack))
      {
        return false;
      }
    }
    in.SetRenderedCounts(object, content);
  }
  // Padding costs drawing time: compacted when it exceeds its limit.
  if (in.Slots.GetTail() - in.Slots.GetUsed() > in.Slots.PaddingLimit(this->IndexSlack))
  {
    in.Compact(this->IndexSlack);
  }
  return true;
}

void vtkMultiresolutionPolyDataMapper::UploadIndexRanges()
{
  // Upload the rewritten ranges.
  Internals& in = *this->Internal;
  const size_t tail = in.Slots.GetTail();
  timecritical::IndexSlotAllocator::CoalesceRanges(in.DirtyIndices, tail, UploadGap);
  timecritical::IndexSlotAllocator::CoalesceRanges(in.DirtyTexels, tail, UploadGap);
  vtkOpenGLIndexBufferObject* ibo = this->Primitives[PrimitiveTris].IBO;
  if (!in.DirtyIndices.empty())
  {
    ibo->Bind();
    const size_t bytes = sizeof(uint32_t) * in.PerPrimitive;
    for (const Internals::Range& range : in.DirtyIndices)
    {
      glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLintptr>(bytes * range.Start),
        static_cast<GLsizeiptr>(bytes * range.Size),
        in.Indices.data() + in.PerPrimitive * range.Start);
      this->IndexBytesUploaded += static_cast<vtkIdType>(bytes * range.Size);
    }
    ibo->Release();
  }
  // Only padding left (everything culled): no draw call.
  ibo->IndexCount = in.Slots.GetUsed() > 0 ? in.PerPrimitive * tail : 0;
  for (const Internals::Range& range : in.DirtyTexels)
  {
    this->UploadCellTexels(in.TexelBase + range.Start, in.TexelBase + range.Start + range.Size);
  }
}

void vtkMultiresolutionPolyDataMapper::FillVertexIndices()
{
  // Vertices drawn as points over the surface (a second draw call): all rewritten.
  Internals& in = *this->Internal;
  size_t count = 0;
  for (const auto& object : in.Objects)
  {
    const auto base = static_cast<uint32_t>(object.VertexOffset);
    if (object.Written.Kind == ContentKind::Front)
    {
      count += vtkMultiresolutionMapperDetail::WriteDisplayVertices(
        *object.Refinement, base, in.VertexIndices.data() + count);
    }
    else
    {
      const auto vertices = static_cast<size_t>(object.RenderedVertices);
      timecritical::WriteVertexRange(vertices, base, in.VertexIndices.data() + count);
      count += vertices;
    }
  }
  vtkOpenGLIndexBufferObject* vertexIBO = this->Primitives[PrimitiveVertices].IBO;
  if (count > 0)
  {
    vertexIBO->Upload(in.VertexIndices.data(), count, vtkOpenGLBufferObject::ElementArrayBuffer);
    this->IndexBytesUploaded += static_cast<vtkIdType>(sizeof(uint32_t) * count);
  }
  vertexIBO->IndexCount = count;
}

//------------------------------------------------------------------------------
vtkIdType vtkMultiresolutionPolyDataMapper::GetIndexBufferBuildCount() const
{
  return this->Internal->IndexBufferBuildCount;
}

vtkIdType vtkMultiresolutionPolyDataMapper::GetLastIndexCount() const
{
  const Internals& in = *this->Internal;
  return in.LayoutValid ? static_cast<vtkIdType>(in.PerPrimitive * in.Slots.GetUsed()) : 0;
}

const unsigned int* vtkMultiresolutionPolyDataMapper::GetLastIndices() const
{
  // The objects' slots without their padding, in object order (diagnostics:
  // built on demand, may allocate).
  Internals& in = *this->Internal;
  if (!in.CompactValid)
  {
    in.CompactIndices.clear();
    for (const auto& object : in.Objects)
    {
      const Internals::Slot& slot = in.SlotOf(object);
      if (in.LayoutValid && slot.Used > 0)
      {
        const uint32_t* first = in.Indices.data() + in.PerPrimitive * slot.Start;
        in.CompactIndices.insert(
          in.CompactIndices.end(), first, first + in.PerPrimitive * slot.Used);
      }
    }
    in.CompactValid = true;
  }
  return in.CompactIndices.data();
}

vtkIdType vtkMultiresolutionPolyDataMapper::GetIndexBufferRelayoutCount() const
{
  return static_cast<vtkIdType>(this->Internal->Slots.GetLayoutCount());
}
