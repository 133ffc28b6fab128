// SPDX-License-Identifier: BSD-3-Clause
// vtkMultiresolutionPolyDataMapper: hardware selection and selection display.
//
// vtkHardwareSelector renders the actor once per pass; the superclass writes
// gl_PrimitiveID (plus the primitives drawn before) in the cell passes,
// gl_VertexID in the point passes and 1 in the composite pass. Here a
// primitive id becomes the object whose slot holds it and the leaf cell that
// Emit wrote there (the cell textures' mapping), a vertex the object whose
// vertex range holds it; the composite pass, processed again in the
// selector's second iteration when the cell (or point) ids of the first are
// known, becomes the object's flat index. Unpickable blocks are not drawn by
// the selection passes: the vertex shader drops their vertices, flagged 0 in
// a texture buffer of one byte per vertex.
#include "vtkMultiresolutionPolyDataMapperInternals.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCompositeDataSet.h"
#include "vtkHardwareSelector.h"
#include "vtkIdTypeArray.h"
#include "vtkOpenGLCellToVTKCellMap.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkUnsignedIntArray.h"

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <map>

namespace
{
unsigned int ReadPixelId(const unsigned char* low, const unsigned char* high, unsigned int pos)
{
  unsigned int id = low[pos] | (static_cast<unsigned int>(low[pos + 1]) << 8) |
    (static_cast<unsigned int>(low[pos + 2]) << 16);
  if (high)
  {
    id |= static_cast<unsigned int>(high[pos]) << 24;
  }
  return id;
}

/// Bits [shift, shift + 24) of id as the selector's RGB.
void WritePixelId(unsigned char* out, unsigned int pos, vtkIdType id, int shift)
{
  const auto value = static_cast<uint64_t>(id) >> shift;
  out[pos] = static_cast<unsigned char>(value & 0xff);
  out[pos + 1] = static_cast<unsigned char>((value >> 8) & 0xff);
  out[pos + 2] = static_cast<unsigned char>((value >> 16) & 0xff);
}
}

const vtkMultiresolutionPolyDataMapper::Internals::Object*
vtkMultiresolutionPolyDataMapper::Internals::ObjectOfVertex(vtkIdType vertex) const
{
  // Objects are in vertex order; the last one starting at or before the vertex.
  auto it = std::upper_bound(this->Objects.begin(), this->Objects.end(), vertex,
    [](vtkIdType v, const Object& o) { return v < o.VertexOffset; });
  if (it == this->Objects.begin())
  {
    return nullptr;
  }
  --it;
  return vertex < it->VertexOffset + it->NumberOfVertices ? &*it : nullptr;
}

const vtkMultiresolutionPolyDataMapper::Internals::Object*
vtkMultiresolutionPolyDataMapper::Internals::ObjectOfOtherCell(
  vtkIdType cell, vtkIdType& leafCell) const
{
  // The skeleton's cells in VTK's order: every leaf's vertices, then lines,
  // then strips (no polygons); a leaf numbers its own cells verts, lines,
  // polys, strips.
  const Object* last = this->Objects.empty() ? nullptr : &this->Objects.back();
  if (!last || cell < 0)
  {
    return nullptr;
  }
  const vtkIdType counts[2] = { last->VertOffset + last->NumberOfVerts,
    last->LineOffset + last->NumberOfLines };
  int type = 0;
  vtkIdType index = cell;
  while (type < 2 && index >= counts[type])
  {
    index -= counts[type++];
  }
  if (type == 2 && index >= last->StripOffset + last->NumberOfStrips)
  {
    return nullptr;
  }
  auto first = [type](const Object& o)
  { return type == 0 ? o.VertOffset : type == 1 ? o.LineOffset : o.StripOffset; };
  auto count = [type](const Object& o)
  { return type == 0 ? o.NumberOfVerts : type == 1 ? o.NumberOfLines : o.NumberOfStrips; };
  // The last object starting at or before the index that has cells of this type.
  auto it = std::upper_bound(this->Objects.begin(), this->Objects.end(), index,
    [&](vtkIdType i, const Object& o) { return i < first(o); });
  while (it != this->Objects.begin())
  {
    --it;
    if (count(*it) > 0)
    {
      if (index >= first(*it) + count(*it))
      {
        return nullptr;
      }
      const vtkIdType before = type == 0 ? 0
        : type == 1                     ? it->NumberOfVerts
                                        : it->NumberOfVerts + it->NumberOfLines + it->NumberOfPolys;
      leafCell = before + index - first(*it);
      return &*it;
    }
  }
  return nullptr;
}

const vtkMultiresolutionPolyDataMapper::Internals::Object*
vtkMultiresolutionPolyDataMapper::Internals::ObjectOfCell(vtkIdType cell) const
{
  auto it = std::upper_bound(this->Objects.begin(), this->Objects.end(), cell,
    [](vtkIdType c, const Object& o) { return c < o.CellOffset; });
  return it == this->Objects.begin() ? nullptr : &*std::prev(it);
}

/// The state of one ProcessSelectorPixelBuffers call: objects by slot, and
/// (points representation) the drawn triangle that first uses each vertex;
/// the passes that turn the pixels' ids into the leaves' own.
struct vtkMultiresolutionPolyDataMapper::Internals::Selection
{
  Selection(vtkMultiresolutionPolyDataMapper* self, vtkHardwareSelector* selector, size_t triBase)
    : Self(self)
    , In(*self->Internal)
    , TriBase(triBase)
  {
    const Internals& in = this->In;
    for (size_t i = 0; i < in.Objects.size(); ++i)
    {
      if (in.Slots.GetSlot(i).Used > 0)
      {
        this->BySlot.push_back(static_cast<uint32_t>(i));
      }
    }
    std::sort(this->BySlot.begin(), this->BySlot.end(), [&in](uint32_t a, uint32_t b)
      { return in.Slots.GetSlot(a).Start < in.Slots.GetSlot(b).Start; });
    this->PointLow = selector->GetRawPixelBuffer(vtkHardwareSelector::POINT_ID_LOW24);
    this->PointHigh = selector->GetRawPixelBuffer(vtkHardwareSelector::POINT_ID_HIGH24);
    this->CellLow = selector->GetRawPixelBuffer(vtkHardwareSelector::CELL_ID_LOW24);
    this->CellHigh = selector->GetRawPixelBuffer(vtkHardwareSelector::CELL_ID_HIGH24);
  }

  /// Object and leaf cell of primitive p of the triangle index buffer.
  const Object* Decode(size_t p, vtkIdType& leafCell)
  {
    const Internals& in = this->In;
    auto it = std::upper_bound(this->BySlot.begin(), this->BySlot.end(), p,
      [&in](size_t q, uint32_t i) { return q < in.Slots.GetSlot(i).Start; });
    if (it == this->BySlot.begin())
    {
      return nullptr;
    }
    const size_t index = *std::prev(it);
    const Object& object = in.Objects[index];
    const Slot& slot = in.Slots.GetSlot(index);
    const size_t k = p - slot.Start;
    if (k >= slot.Used)
    {
      return nullptr; // padding: degenerate, never drawn
    }
    const vtkIdType polyBase = object.NumberOfVerts + object.NumberOfLines;
    const size_t perTriangle = in.Representation == VTK_SURFACE ? 1 : 3;
    const bool vertices = in.Representation == VTK_POINTS && !in.Corners;
    switch (object.Written.Kind)
    {
      case ContentKind::Front:
        if (vertices)
        {
          leafCell = polyBase + this->VertexCell(index, k);
        }
        else
        {
          leafCell = polyBase + object.Refinement->GetTriangleIds()[k / perTriangle];
        }
        return &object;
      case ContentKind::Prefix:
        // TOM triangle t is cell t of the leaf's polygons.
        leafCell = polyBase + (vertices ? this->VertexCell(index, k) : k / perTriangle);
        return &object;
      case ContentKind::Whole:
        leafCell = polyBase + this->WholeCell(object, k);
        return &object;
      default:
        return nullptr;
    }
  }

  /// Polygon of a non-TOM object's k-th primitive.
  vtkIdType WholeCell(const Object& object, size_t k) const
  {
    if (this->In.Representation == VTK_SURFACE)
    {
      return this->In.StaticTriangleCells[object.TriangleStart + k];
    }
    // One primitive per polygon corner, as Emit writes them.
    vtkCellArray* polys = object.Leaf->GetPolys();
    vtkIdType c = 0;
    for (vtkIdType lo = 0, hi = object.NumberOfPolys - 1; lo <= hi;)
    {
      const vtkIdType mid = (lo + hi) / 2;
      if (polys->GetOffsetsArray()->GetComponent(mid, 0) <= static_cast<double>(k))
      {
        c = mid;
        lo = mid + 1;
      }
      else
      {
        hi = mid - 1;
      }
    }
    return c;
  }


  /// Points representation: the leaf polygon of the first drawn triangle
  /// that uses the k-th vertex of the object's slot.
  vtkIdType VertexCell(size_t index, size_t k)
  {
    const Object& object = this->In.Objects[index];
    std::vector<int64_t>& cells = this->VertexCells[index];
    std::vector<uint32_t>& order = this->SlotVertices[index];
    if (cells.empty())
    {
      cells.assign(static_cast<size_t>(object.NumberOfVertices), -1);
      std::vector<uint32_t> triangles;
      const uint32_t* ids = nullptr;
      size_t count = 0;
      if (object.Written.Kind == ContentKind::Front)
      {
        const timecritical::ViewDependentRefinement& front = *object.Refinement;
        count = front.GetNumberOfDisplayTriangles();
        triangles.assign(front.GetTriangles(), front.GetTriangles() + 3 * count);
        ids = front.GetTriangleIds();
        for (uint32_t v = 0; v < front.GetNumberOfVertices(); ++v)
        {
          if (front.IsDisplayVertex(v))
          {
            order.push_back(v);
          }
        }
      }
      else
      {
        const auto vertexCount = static_cast<uint32_t>(object.Written.Key);
        count = object.Traversal.Extract(vertexCount, triangles);
        for (uint32_t v = 0; v < vertexCount; ++v)
        {
          order.push_back(v);
        }
      }
      for (size_t t = count; t-- > 0;)
      {
        for (int c = 0; c < 3; ++c)
        {
          cells[triangles[3 * t + c]] = ids ? ids[t] : static_cast<int64_t>(t);
        }
      }
    }
    const uint32_t vertex = k < order.size() ? order[k] : 0;
    return std::max<int64_t>(cells[vertex], 0);
  }


  /// Object and leaf cell of the cell id at pixel pos (cell passes).
  const Object* CellHit(unsigned int pos, vtkIdType& leafCell)
  {
    const Internals& in = this->In;
    const size_t raw = ReadPixelId(this->CellLow, this->CellHigh, pos);
    if (in.LayoutValid && raw >= this->TriBase && raw < this->TriBase + in.Slots.GetTail())
    {
      return this->Decode(raw - this->TriBase, leafCell);
    }
    if (!in.HasOtherCells)
    {
      return nullptr;
    }
    const vtkIdType merged =
      this->Self->CellCellMap->ConvertOpenGLCellIdToVTKCellId(false, static_cast<vtkIdType>(raw));
    return in.ObjectOfOtherCell(merged, leafCell);
  }

  /// Point id passes: the leaf's point id (or its id array's value) of the drawn vertex.
  void WritePointIds(int pass, unsigned char* out, const std::vector<unsigned int>& pixels)
  {
    for (const unsigned int pos : pixels)
    {
      const vtkIdType vertex = ReadPixelId(this->PointLow, this->PointHigh, pos);
      const Object* object = this->In.ObjectOfVertex(vertex);
      if (!out || !object)
      {
        continue;
      }
      vtkIdType id = vertex - object->VertexOffset;
      vtkIdTypeArray* ids = this->Self->PointIdArrayName
        ? vtkArrayDownCast<vtkIdTypeArray>(
            object->Leaf->GetPointData()->GetArray(this->Self->PointIdArrayName))
        : nullptr;
      if (ids && id < ids->GetNumberOfTuples())
      {
        id = ids->GetValue(id);
      }
      WritePixelId(out, pos, id, pass == vtkHardwareSelector::POINT_ID_LOW24 ? 0 : 24);
    }
  }

  /// Cell id passes: the leaf's cell id (or its id array's value) of the drawn primitive.
  void WriteCellIds(int pass, unsigned char* out, const std::vector<unsigned int>& pixels)
  {
    for (const unsigned int pos : pixels)
    {
      vtkIdType id = 0;
      const Object* object = this->CellHit(pos, id);
      if (!out || !object)
      {
        continue;
      }
      vtkIdTypeArray* ids = this->Self->CellIdArrayName
        ? vtkArrayDownCast<vtkIdTypeArray>(
            object->Leaf->GetCellData()->GetArray(this->Self->CellIdArrayName))
        : nullptr;
      if (ids && id < ids->GetNumberOfTuples())
      {
        id = ids->GetValue(id);
      }
      WritePixelId(out, pos, id, pass == vtkHardwareSelector::CELL_ID_LOW24 ? 0 : 24);
    }
  }

  /// Composite pass: the flat index of the drawing leaf (or its composite id array's value).
  void WriteCompositeIndices(
    bool pointField, unsigned char* out, const std::vector<unsigned int>& pixels)
  {
    for (const unsigned int pos : pixels)
    {
      vtkIdType cell = -1;
      const Object* object = pointField
        ? this->In.ObjectOfVertex(ReadPixelId(this->PointLow, this->PointHigh, pos))
        : this->CellHit(pos, cell);
      if (!out || !object)
      {
        continue;
      }
      vtkIdType value = object->FlatIndex;
      vtkUnsignedIntArray* values = this->Self->CompositeIdArrayName && cell >= 0
        ? vtkArrayDownCast<vtkUnsignedIntArray>(
            object->Leaf->GetCellData()->GetArray(this->Self->CompositeIdArrayName))
        : nullptr;
      if (values && cell < values->GetNumberOfTuples())
      {
        value = values->GetValue(cell);
      }
      WritePixelId(out, pos, value, 0);
    }
  }

  vtkMultiresolutionPolyDataMapper* Self;
  const Internals& In;
  size_t TriBase;
  const unsigned char* PointLow = nullptr;
  const unsigned char* PointHigh = nullptr;
  const unsigned char* CellLow = nullptr;
  const unsigned char* CellHigh = nullptr;
  std::vector<uint32_t> BySlot;
  std::map<size_t, std::vector<int64_t>> VertexCells;
  std::map<size_t, std::vector<uint32_t>> SlotVertices;
};

void vtkMultiresolutionPolyDataMapper::UpdateMaximumPointCellIds(vtkRenderer* ren, vtkActor* act)
{
  // The superclass bounds the primitive ids drawn; the ids reported are the
  // leaves' own, which can be larger (a large leaf drawn coarse).
  this->Superclass::UpdateMaximumPointCellIds(ren, act);
  vtkHardwareSelector* selector = ren->GetSelector();
  selector->UpdateMaximumPointId(this->Internal->TotalVertices - 1); // drawn vertex ids
  for (const auto& object : this->Internal->Objects)
  {
    selector->UpdateMaximumPointId(object.NumberOfVertices - 1);
    selector->UpdateMaximumCellId(object.Leaf->GetNumberOfCells() - 1);
    vtkIdTypeArray* ids = this->PointIdArrayName
      ? vtkArrayDownCast<vtkIdTypeArray>(object.Leaf->GetPointData()->GetArray(this->PointIdArrayName))
      : nullptr;
    if (ids)
    {
      selector->UpdateMaximumPointId(static_cast<vtkIdType>(ids->GetRange()[1]));
    }
    ids = this->CellIdArrayName
      ? vtkArrayDownCast<vtkIdTypeArray>(object.Leaf->GetCellData()->GetArray(this->CellIdArrayName))
      : nullptr;
    if (ids)
    {
      selector->UpdateMaximumCellId(static_cast<vtkIdType>(ids->GetRange()[1]));
    }
  }
}

void vtkMultiresolutionPolyDataMapper::BuildSelectionIBO(
  vtkPolyData*, std::vector<unsigned int> (&indices)[4], vtkIdType)
{
  // VTK builds it from its input's cells, which the skeleton does not hold:
  // each leaf's instead, with its vertex offset, for the nodes of its flat
  // index (composite input; a polydata input takes every node).
  Internals& in = *this->Internal;
  in.SelectionByFlatIndex = vtkCompositeDataSet::SafeDownCast(in.Input) != nullptr;
  for (const auto& object : in.Objects)
  {
    in.SelectionFlatIndex = object.FlatIndex;
    this->Superclass::BuildSelectionIBO(object.Leaf, indices, object.VertexOffset);
  }
}

void vtkMultiresolutionPolyDataMapper::AddPointIdsToSelectionPrimitives(vtkPolyData* poly,
  const char* arrayName, unsigned int processId, unsigned int compositeIndex, vtkIdType selectedId)
{
  const Internals& in = *this->Internal;
  if (!in.SelectionByFlatIndex || compositeIndex == in.SelectionFlatIndex)
  {
    // VTK's lookup by value keys on a composite id array's values (0 without one).
    this->Superclass::AddPointIdsToSelectionPrimitives(
      poly, arrayName, processId, this->CompositeIdArrayName ? compositeIndex : 0, selectedId);
  }
}

void vtkMultiresolutionPolyDataMapper::AddCellIdsToSelectionPrimitives(vtkPolyData* poly,
  const char* arrayName, unsigned int processId, unsigned int compositeIndex, vtkIdType selectedId)
{
  const Internals& in = *this->Internal;
  if (!in.SelectionByFlatIndex || compositeIndex == in.SelectionFlatIndex)
  {
    this->Superclass::AddCellIdsToSelectionPrimitives(
      poly, arrayName, processId, this->CompositeIdArrayName ? compositeIndex : 0, selectedId);
  }
}

void vtkMultiresolutionPolyDataMapper::ProcessSelectorPixelBuffers(
  vtkHardwareSelector* sel, std::vector<unsigned int>& pixeloffsets, vtkProp* prop)
{
  Internals& in = *this->Internal;
  if (!this->PopulateSelectionSettings || !this->CurrentInput || in.Objects.empty())
  {
    return;
  }
  const int pass = sel->GetCurrentPass();
  const bool pointField = sel->GetFieldAssociation() == vtkDataObject::FIELD_ASSOCIATION_POINTS;
  const unsigned char* pointLow = sel->GetRawPixelBuffer(vtkHardwareSelector::POINT_ID_LOW24);
  const unsigned char* pointHigh = sel->GetRawPixelBuffer(vtkHardwareSelector::POINT_ID_HIGH24);
  if (pass == vtkHardwareSelector::PROCESS_PASS)
  {
    this->WriteProcessIds(sel, pixeloffsets);
    return;
  }
  const unsigned char* cellLow = sel->GetRawPixelBuffer(vtkHardwareSelector::CELL_ID_LOW24);
  const unsigned char* cellHigh = sel->GetRawPixelBuffer(vtkHardwareSelector::CELL_ID_HIGH24);

  // Primitive ids of the triangle index buffer start after the vertices and
  // lines of non-TOM leaves, drawn first (PrimitiveIDOffset).
  vtkCellArray* prims[4] = { this->CurrentInput->GetVerts(), this->CurrentInput->GetLines(),
    this->CurrentInput->GetPolys(), this->CurrentInput->GetStrips() };
  const int representation = static_cast<vtkActor*>(prop)->GetProperty()->GetRepresentation();
  if (in.HasOtherCells)
  {
    this->CellCellMap->Update(prims, representation, this->CurrentInput->GetPoints());
    this->PatchStripOffset();
  }
  const size_t triBase =
    in.HasOtherCells ? static_cast<size_t>(this->CellCellMap->GetPrimitiveOffsets()[2]) : 0;
  Internals::Selection selection(this, sel, triBase);

  if ((pass == vtkHardwareSelector::POINT_ID_LOW24 ||
        pass == vtkHardwareSelector::POINT_ID_HIGH24) &&
    pointLow && (pass == vtkHardwareSelector::POINT_ID_LOW24 || pointHigh))
  {
    selection.WritePointIds(pass, sel->GetPixelBuffer(pass), pixeloffsets);
  }
  if ((pass == vtkHardwareSelector::CELL_ID_LOW24 || pass == vtkHardwareSelector::CELL_ID_HIGH24) &&
    !pointField && cellLow && (pass == vtkHardwareSelector::CELL_ID_LOW24 || cellHigh))
  {
    selection.WriteCellIds(pass, sel->GetPixelBuffer(pass), pixeloffsets);
  }
  // Polydata input keeps the superclass's composite value.
  if (pass == vtkHardwareSelector::COMPOSITE_INDEX_PASS &&
    vtkCompositeDataSet::SafeDownCast(in.Input) && (pointField ? pointLow : cellLow))
  {
    selection.WriteCompositeIndices(pointField, sel->GetPixelBuffer(pass), pixeloffsets);
  }
}

void vtkMultiresolutionPolyDataMapper::WriteProcessIds(
  vtkHardwareSelector* sel, const std::vector<unsigned int>& pixeloffsets)
{
  // Process ids from a point array of the leaves, by the drawn vertex.
  const Internals& in = *this->Internal;
  const unsigned char* pointLow = sel->GetRawPixelBuffer(vtkHardwareSelector::POINT_ID_LOW24);
  const unsigned char* pointHigh = sel->GetRawPixelBuffer(vtkHardwareSelector::POINT_ID_HIGH24);
  unsigned char* out = sel->GetRawPixelBuffer(vtkHardwareSelector::PROCESS_PASS);
  if (!sel->GetUseProcessIdFromData() || !this->ProcessIdArrayName || !out || !pointLow)
  {
    return;
  }
  for (const unsigned int pos : pixeloffsets)
  {
    const vtkIdType vertex = ReadPixelId(pointLow, pointHigh, pos);
    const Internals::Object* object = in.ObjectOfVertex(vertex);
    vtkUnsignedIntArray* values = object
      ? vtkArrayDownCast<vtkUnsignedIntArray>(
          object->Leaf->GetPointData()->GetArray(this->ProcessIdArrayName))
      : nullptr;
    if (values && vertex - object->VertexOffset < values->GetNumberOfTuples())
    {
      WritePixelId(out, pos, values->GetValue(vertex - object->VertexOffset) + 1, 0);
    }
  }
}

//------------------------------------------------------------------------------
void vtkMultiresolutionPolyDataMapper::UpdatePickability(bool stale)
{
  // After the block walk: whether selection passes must drop some objects.
  Internals& in = *this->Internal;
  in.PickFlagsStale = in.PickFlagsStale || stale;
  const bool any = std::any_of(in.Objects.begin(), in.Objects.end(),
    [](const Internals::Object& object) { return !object.Pickable; });
  if (any != in.AnyUnpickable)
  {
    in.AnyUnpickable = any;
    in.PickabilityModeTime.Modified(); // selection shaders gain or lose the test
  }
}

bool vtkMultiresolutionPolyDataMapper::GetNeedToRebuildShaders(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  // A change of selection pass rebuilds the shaders anyway (the
  // superclass's selection state); so does a change of whether some object
  // is unpickable, should it come between two renders of the same pass.
  return this->Superclass::GetNeedToRebuildShaders(cellBO, ren, act) ||
    (ren->GetSelector() && cellBO.ShaderSourceTime < this->Internal->PickabilityModeTime);
}

void vtkMultiresolutionPolyDataMapper::ReplacePickabilityShaderValues(
  vtkShader* vertex, vtkRenderer* ren)
{
  // Selection passes only: a vertex flagged 0 is moved outside the clip
  // volume, so that no primitive of an unpickable object is rasterized
  // (gl_VertexID is the vertex's index in the merged vertex buffer).
  if (!vertex || !ren->GetSelector() || !this->Internal->AnyUnpickable)
  {
    return;
  }
  std::string source = vertex->GetSource();
  vtkMultiresolutionMapperDetail::AddVertexDiscard(source, "uniform samplerBuffer pickableVertices;",
    "texelFetch(pickableVertices, gl_VertexID).r < 0.5");
  vertex->SetSource(source);
}

void vtkMultiresolutionPolyDataMapper::SetPickabilityShaderParameters(vtkShaderProgram* program)
{
  const Internals& in = *this->Internal;
  if (program && in.PickTextureActive && program->IsUniformUsed("pickableVertices"))
  {
    program->SetUniformi("pickableVertices", in.PickTexture->GetTextureUnit());
  }
}

void vtkMultiresolutionPolyDataMapper::ActivatePickability(vtkRenderer* ren)
{
  // Before a selection pass draws: the flags of the current objects on the
  // GPU (written again only when pickability or the objects changed).
  Internals& in = *this->Internal;
  if (!ren->GetSelector() || !in.AnyUnpickable)
  {
    return;
  }
  if (!in.PickTexture)
  {
    in.PickTexture = vtkSmartPointer<vtkTextureObject>::New();
    in.PickBuffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    in.PickBuffer->SetType(vtkOpenGLBufferObject::TextureBuffer);
    in.PickFlagsStale = true;
  }
  if (in.PickFlagsStale)
  {
    std::vector<unsigned char> flags(
      static_cast<size_t>(std::max<vtkIdType>(in.TotalVertices, 1)), 255);
    for (const auto& object : in.Objects)
    {
      if (!object.Pickable)
      {
        std::fill_n(flags.begin() + static_cast<std::ptrdiff_t>(object.VertexOffset),
          static_cast<size_t>(object.NumberOfVertices), static_cast<unsigned char>(0));
      }
    }
    in.PickTexture->SetContext(static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow()));
    in.PickBuffer->Upload(flags, vtkOpenGLBufferObject::TextureBuffer);
    in.PickTexture->CreateTextureBuffer(
      static_cast<unsigned int>(flags.size()), 1, VTK_UNSIGNED_CHAR, in.PickBuffer);
    in.PickFlagsStale = false;
  }
  in.PickTexture->Activate();
  in.PickTextureActive = true;
}

void vtkMultiresolutionPolyDataMapper::DeactivatePickability()
{
  Internals& in = *this->Internal;
  if (in.PickTextureActive)
  {
    in.PickTexture->Deactivate();
    in.PickTextureActive = false;
  }
}
