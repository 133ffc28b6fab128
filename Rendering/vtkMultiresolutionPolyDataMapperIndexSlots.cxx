// SPDX-License-Identifier: BSD-3-Clause
// vtkMultiresolutionPolyDataMapper: the content of the index buffer's slots.
//
// The triangle primitive's index buffer holds one slot per object, in
// primitives of the drawn representation (triangles, lines or points): the
// object's primitives, then degenerate ones (all indices one vertex: no
// fragments) as room to grow. gl_PrimitiveID counts the degenerate
// primitives too, so the cell textures follow the same layout (texel = slot
// position; the texels of padding are never read, having no fragments). An
// update rewrites only the objects whose content changed, in their slot, and
// uploads only those ranges; timecritical::IndexSlotAllocator decides where
// slots go (grown in place, moved to a hole or the tail, trimmed, compacted),
// this file writes what they hold. Unused ranges (holes) are degenerate.
#include "vtkMultiresolutionPolyDataMapperInternals.h"

#include "TOMIndexLayout.h"

#include "vtkCellArray.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cstring>

using vtkMultiresolutionMapperDetail::Content;
using vtkMultiresolutionMapperDetail::ContentKind;

size_t vtkMultiresolutionMapperDetail::WriteDisplayVertices(
  const timecritical::ViewDependentRefinement& front, uint32_t base, uint32_t* out)
{
  size_t n = 0;
  const uint32_t count = front.GetNumberOfVertices();
  for (uint32_t v = 0; v < count; ++v)
  {
    if (front.IsDisplayVertex(v))
    {
      out[n++] = base + v;
    }
  }
  return n;
}

Content vtkMultiresolutionPolyDataMapper::Internals::Describe(
  const Object& object, bool viewDependent) const
{
  Content content;
  if (!object.Visible || !(object.Resolution > 0.0))
  {
    content.Kind = ContentKind::Culled; // a hidden block too (block attributes)
  }
  else if (object.Refinement && viewDependent)
  {
    content.Kind = ContentKind::Front;
    content.Key = object.FrontVersion;
  }
  else if (object.IsTOM)
  {
    content.Kind = ContentKind::Prefix;
    content.Key = object.Traversal.GetVertexCountForTriangles(
      object.Traversal.GetTrianglesForResolution(object.Resolution));
  }
  else
  {
    content.Kind = ContentKind::Whole;
  }
  return content;
}

size_t vtkMultiresolutionPolyDataMapper::Internals::Stage(Object& object, const Content& content)
{
  const bool surface = this->Representation == VTK_SURFACE;
  const bool points = this->Representation == VTK_POINTS && !this->Corners;
  size_t count = 0;
  switch (content.Kind)
  {
    case ContentKind::Front:
    {
      const size_t triangles = object.Refinement->GetNumberOfDisplayTriangles();
      count = points ? object.Refinement->GetNumberOfDisplayVertices()
                     : (surface ? 1 : 3) * triangles;
      break;
    }
    case ContentKind::Prefix:
    {
      // The prefix's size is known once extracted (into Scratch, then copied
      // with the object's vertex offset into its slot).
      const auto vertexCount = static_cast<uint32_t>(content.Key);
      if (points)
      {
        this->StagedTriangles = object.Traversal.Extract(vertexCount, nullptr, 0); // counts only
        count = vertexCount;
      }
      else
      {
        this->StagedTriangles = object.Traversal.Extract(
          vertexCount, this->Scratch.data(), static_cast<uint32_t>(this->Scratch.size() / 3));
        count = (surface ? 1 : 3) * static_cast<size_t>(this->StagedTriangles);
      }
      break;
    }
    case ContentKind::Whole:
      count = surface ? static_cast<size_t>(object.NumberOfTriangles)
                      : static_cast<size_t>(object.PolyConnectivity);
      break;
    default:
      break;
  }
  // Never more than at full resolution, what the buffers were sized for
  // (valid data never needs the clamp).
  return std::min(count, this->Slots.GetSlot(this->IndexOf(object)).Full);
}

namespace
{
/// Writes `count` copies of a cell id (one per primitive of a triangle or polygon).
vtkIdType* AddCells(vtkIdType* cells, vtkIdType cell, size_t count)
{
  for (size_t k = 0; k < count; ++k)
  {
    *cells++ = cell;
  }
  return cells;
}

/// Cells in leaf order (the order of cell colours): a leaf's polygons follow its vertices and lines.
template <typename Object>
vtkIdType FirstPolygonCell(const Object& object)
{
  return object.CellOffset + object.NumberOfVerts + object.NumberOfLines;
}
}

void vtkMultiresolutionPolyDataMapper::Internals::Emit(const Object& object,
  const Content& content, size_t used, uint32_t* out, vtkIdType* cells) const
{
  // Cell data: one cell per primitive; a triangle is 3 lines or 3 corner points.
  switch (content.Kind)
  {
    case ContentKind::Front:
      this->EmitFront(object, used, out, cells);
      break;
    case ContentKind::Prefix:
      this->EmitPrefix(object, content, used, out, cells);
      break;
    case ContentKind::Whole:
      this->EmitWhole(object, out, cells);
      break;
    default:
      break;
  }
}

void vtkMultiresolutionPolyDataMapper::Internals::EmitFront(
  const Object& object, size_t used, uint32_t* out, vtkIdType* cells) const
{
  const auto base = static_cast<uint32_t>(object.VertexOffset);
  const size_t perTriangle = this->Representation == VTK_SURFACE ? 1 : 3;
  const bool points = this->Representation == VTK_POINTS && !this->Corners;
  const timecritical::ViewDependentRefinement& front = *object.Refinement;
  const auto triangles = static_cast<uint32_t>(
    std::min<size_t>(front.GetNumberOfDisplayTriangles(), used / perTriangle));
  if (this->Representation == VTK_WIREFRAME)
  {
    timecritical::WriteTriangleEdges(front.GetTriangles(), triangles, base, out);
  }
  else if (points)
  {
    vtkMultiresolutionMapperDetail::WriteDisplayVertices(front, base, out);
  }
  else
  {
    front.CopyTriangles(out, triangles, base);
  }
  if (cells)
  {
    // TOM triangle t is cell t of the leaf.
    const vtkIdType firstCell = FirstPolygonCell(object);
    const uint32_t* ids = front.GetTriangleIds();
    for (uint32_t t = 0; t < triangles; ++t)
    {
      cells = AddCells(cells, firstCell + ids[t], perTriangle);
    }
  }
}

void vtkMultiresolutionPolyDataMapper::Internals::EmitPrefix(const Object& object,
  const Content& content, size_t used, uint32_t* out, vtkIdType* cells) const
{
  const auto base = static_cast<uint32_t>(object.VertexOffset);
  const size_t perTriangle = this->Representation == VTK_SURFACE ? 1 : 3;
  const bool points = this->Representation == VTK_POINTS && !this->Corners;
  const auto triangles =
    static_cast<uint32_t>(std::min<size_t>(this->StagedTriangles, used / perTriangle));
  const uint32_t* staged = this->Scratch.data();
  if (this->Representation == VTK_WIREFRAME)
  {
    timecritical::WriteTriangleEdges(staged, triangles, base, out);
  }
  else if (points)
  {
    timecritical::WriteVertexRange(static_cast<size_t>(content.Key), base, out);
  }
  else
  {
    const size_t count = 3 * static_cast<size_t>(triangles);
    for (size_t k = 0; k < count; ++k)
    {
      out[k] = staged[k] + base;
    }
  }
  if (cells)
  {
    const vtkIdType firstCell = FirstPolygonCell(object);
    for (uint32_t t = 0; t < triangles; ++t)
    {
      cells = AddCells(cells, firstCell + t, perTriangle);
    }
  }
}

void vtkMultiresolutionPolyDataMapper::Internals::EmitWhole(
  const Object& object, uint32_t* out, vtkIdType* cells) const
{
  // Not a TOM: full resolution, in VTK's layout per representation.
  const auto base = static_cast<uint32_t>(object.VertexOffset);
  const vtkIdType firstCell = FirstPolygonCell(object);
  if (this->Representation == VTK_SURFACE)
  {
    const size_t count = 3 * static_cast<size_t>(object.NumberOfTriangles);
    const uint32_t* src = this->StaticTriangles.data() + 3 * object.TriangleStart;
    std::copy(src, src + count, out);
    if (cells)
    {
      const uint32_t* ids = this->StaticTriangleCells.data() + object.TriangleStart;
      for (vtkIdType t = 0; t < object.NumberOfTriangles; ++t)
      {
        cells = AddCells(cells, firstCell + ids[t], 1);
      }
    }
    return;
  }
  vtkIdType npts = 0;
  const vtkIdType* ids = nullptr;
  vtkCellArray* polys = object.Leaf->GetPolys();
  for (vtkIdType c = 0; c < object.NumberOfPolys; ++c)
  {
    polys->GetCellAtId(c, npts, ids);
    for (vtkIdType i = 0; i < npts; ++i)
    {
      *out++ = static_cast<uint32_t>(ids[i]) + base;
      if (this->Representation == VTK_WIREFRAME)
      {
        *out++ = static_cast<uint32_t>(ids[i + 1 < npts ? i + 1 : 0]) + base;
      }
    }
    if (cells)
    {
      cells = AddCells(cells, firstCell + c, static_cast<size_t>(npts));
    }
  }
}

void vtkMultiresolutionPolyDataMapper::Internals::SetRenderedCounts(
  Object& object, const Content& content) const
{
  switch (content.Kind)
  {
    case ContentKind::Front:
      object.RenderedTriangles = object.Refinement->GetNumberOfDisplayTriangles();
      object.RenderedVertices = object.Refinement->GetNumberOfDisplayVertices();
      break;
    case ContentKind::Prefix:
      object.RenderedTriangles = this->StagedTriangles;
      object.RenderedVertices = static_cast<vtkIdType>(content.Key);
      break;
    case ContentKind::Whole:
      object.RenderedTriangles = object.NumberOfTriangles;
      object.RenderedVertices = object.NumberOfVertices;
      break;
    default:
      object.RenderedTriangles = 0;
      object.RenderedVertices = 0;
      break;
  }
}

void vtkMultiresolutionPolyDataMapper::Internals::FillDegenerate(
  size_t start, size_t count, uint32_t vertex)
{
  if (count == 0)
  {
    return;
  }
  uint32_t* out = this->Indices.data() + this->PerPrimitive * start;
  std::fill(out, out + this->PerPrimitive * count, vertex);
  this->DirtyIndices.push_back(Range{ start, count });
}

void vtkMultiresolutionPolyDataMapper::Internals::WriteSlot(Object& object,
  const Content& content, size_t used, size_t extent)
{
  // extent: how much of the slot may hold anything but degenerate primitives
  // (its old content, or never written).
  const size_t index = this->IndexOf(object);
  const Slot& slot = this->Slots.GetSlot(index);
  if (used > 0)
  {
    this->Emit(object, content, used, this->Indices.data() + this->PerPrimitive * slot.Start,
      this->CellData ? this->PrimitiveCells.data() + slot.Start : nullptr);
    this->DirtyIndices.push_back(Range{ slot.Start, used });
    if (this->CellData)
    {
      this->DirtyTexels.push_back(Range{ slot.Start, used });
    }
  }
  if (extent > used)
  {
    this->FillDegenerate(
      slot.Start + used, extent - used, static_cast<uint32_t>(object.VertexOffset));
  }
  object.Rewritten = object.Rewritten || used > 0 || slot.Used > 0;
  this->Slots.SetUsed(index, used);
  object.Written = content;
}

void vtkMultiresolutionPolyDataMapper::Internals::ClearSlot(Object& object)
{
  const size_t index = this->IndexOf(object);
  const Slot& slot = this->Slots.GetSlot(index);
  this->FillDegenerate(slot.Start, slot.Used, static_cast<uint32_t>(object.VertexOffset));
  object.Rewritten = object.Rewritten || slot.Used > 0;
  this->Slots.Free(index);
}

bool vtkMultiresolutionPolyDataMapper::Internals::Update(
  Object& object, const Content& content, double slack)
{
  const size_t used = this->Stage(object, content);
  const size_t index = this->IndexOf(object);
  const timecritical::IndexSlotAllocator::Placement placement =
    this->Slots.Place(index, used, slack);
  // Where the slot was before it moved (or was freed) draws nothing from now on.
  this->FillDegenerate(
    placement.Vacated.Start, placement.Vacated.Size, static_cast<uint32_t>(object.VertexOffset));
  object.Rewritten = object.Rewritten || placement.Vacated.Size > 0;
  if (!placement.Placed)
  {
    return false;
  }
  if (used == 0)
  {
    object.Written = content;
    return true;
  }
  this->WriteSlot(object, content, used, placement.Extent);
  // Far below its slot: the end goes back (it is degenerate already).
  this->Slots.Trim(index, slack);
  return true;
}

void vtkMultiresolutionPolyDataMapper::Internals::LayOut(bool viewDependent, double slack)
{
  this->DirtyIndices.clear();
  this->DirtyTexels.clear();
  this->Slots.BeginLayout();
  for (auto& object : this->Objects)
  {
    const Content content = this->Describe(object, viewDependent);
    const size_t used = this->Stage(object, content);
    // Slots never exceed full resolution: they fit the capacity.
    const Slot& slot = this->Slots.AppendSlot(this->IndexOf(object), used, slack);
    this->WriteSlot(object, content, used, slot.Size);
    this->SetRenderedCounts(object, content);
  }
  // Everything drawn is uploaded.
  this->DirtyIndices.clear();
  this->DirtyTexels.clear();
  this->DirtyIndices.push_back(Range{ 0, this->Slots.GetTail() });
  if (this->CellData)
  {
    this->DirtyTexels.push_back(Range{ 0, this->Slots.GetTail() });
  }
}

void vtkMultiresolutionPolyDataMapper::Internals::Compact(double slack)
{
  // Slots move down in buffer order over the holes, their padding trimmed to
  // a fresh layout's: the content is moved, not extracted again.
  size_t moved = SIZE_MAX; // first primitive that changes: uploaded from there on
  const size_t k = this->PerPrimitive;
  for (const auto& move : this->Slots.Compact(slack))
  {
    // [Used, Size) is degenerate already.
    std::memmove(this->Indices.data() + k * move.To, this->Indices.data() + k * move.From,
      sizeof(uint32_t) * k * move.Size);
    if (this->CellData)
    {
      std::memmove(this->PrimitiveCells.data() + move.To, this->PrimitiveCells.data() + move.From,
        sizeof(vtkIdType) * move.Used);
    }
    this->Objects[move.SlotIndex].Rewritten = true;
    moved = std::min(moved, move.To);
  }
  const size_t tail = this->Slots.GetTail();
  if (moved < tail)
  {
    // Ranges rewritten before (by this update) below `moved` stay dirty.
    this->DirtyIndices.push_back(Range{ moved, tail - moved });
    if (this->CellData)
    {
      this->DirtyTexels.push_back(Range{ moved, tail - moved });
    }
  }
}
