// SPDX-License-Identifier: BSD-3-Clause
// vtkMultiresolutionPolyDataMapper: block attributes of composite input
// (vtkCompositeDataDisplayAttributes). Each object gets its block's
// visibility, pickability, color and opacity, inherited from parent blocks
// as in vtkCompositePolyDataMapper2; hidden objects are culled (their
// slots), unpickable ones left out of selection passes (Selection.cxx), and
// colors and opacities are drawn as one RGBA per vertex (or per cell), the
// block colors, whose ranges are rewritten in place when attributes change.
#include "vtkMultiresolutionPolyDataMapperInternals.h"

#include "vtkActor.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkDataObjectTree.h"
#include "vtkDataObjectTreeIterator.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLVertexBufferObject.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"

#include <algorithm>
#include <cmath>

namespace
{
/// The attributes a block passes down to its children.
struct BlockState
{
  bool Visible = true;
  bool Pickable = true;
  bool HasColor = false;
  bool HasOpacity = false;
  double Color[3] = { 1.0, 1.0, 1.0 };
  double Opacity = 1.0;
};

/// Applies the attributes of `node` (if any) over what its parent passed down.
BlockState Inherit(const BlockState& parent, vtkCompositeDataDisplayAttributes* attributes,
  vtkDataObject* node)
{
  BlockState state = parent;
  if (!attributes || !node)
  {
    return state;
  }
  if (attributes->HasBlockVisibility(node))
  {
    state.Visible = attributes->GetBlockVisibility(node);
  }
  if (attributes->HasBlockPickability(node))
  {
    state.Pickable = attributes->GetBlockPickability(node);
  }
  if (attributes->HasBlockColor(node))
  {
    state.HasColor = true;
    attributes->GetBlockColor(node, state.Color);
  }
  if (attributes->HasBlockOpacity(node))
  {
    state.HasOpacity = true;
    state.Opacity = attributes->GetBlockOpacity(node);
  }
  return state;
}

/// Whether the object's attributes differ from `state`'s.
template <typename Object>
bool ColorsDiffer(const Object& object, const BlockState& state)
{
  return object.HasBlockColor != state.HasColor || object.HasBlockOpacity != state.HasOpacity ||
    (state.HasColor &&
      !std::equal(state.Color, state.Color + 3, static_cast<const double*>(object.BlockColor))) ||
    (state.HasOpacity && object.BlockOpacity != state.Opacity);
}

unsigned char ToByte(double value)
{
  return static_cast<unsigned char>(std::lround(255.0 * std::min(1.0, std::max(0.0, value))));
}
}

/// Walks the input's tree in flat-index order (preorder, as
/// vtkDataObjectTreeIterator numbers it), passing attributes down.
struct vtkMultiresolutionPolyDataMapper::Internals::BlockWalk
{
  Internals& In;
  vtkCompositeDataDisplayAttributes* Attributes;
  size_t Cursor = 0;
  unsigned int FlatIndex = 0;
  bool VisibilityChanged = false;
  bool PickabilityChanged = false;
  std::vector<char>* ColorChanged = nullptr; // per object

  void Visit(vtkDataObject* node, const BlockState& parent)
  {
    const BlockState state = Inherit(parent, this->Attributes, node);
    const unsigned int index = this->FlatIndex++;
    if (auto tree = vtkDataObjectTree::SafeDownCast(node))
    {
      vtkDataObjectTreeIterator* it = tree->NewTreeIterator();
      it->VisitOnlyLeavesOff();
      it->TraverseSubTreeOff();
      it->SkipEmptyNodesOff();
      for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
      {
        vtkDataObject* child = it->GetCurrentDataObject();
        if (child)
        {
          this->Visit(child, state);
        }
        else
        {
          ++this->FlatIndex; // an empty node still takes its index
        }
      }
      it->Delete();
      return;
    }
    auto& objects = this->In.Objects;
    while (this->Cursor < objects.size() && objects[this->Cursor].FlatIndex < index)
    {
      ++this->Cursor;
    }
    if (this->Cursor < objects.size() && objects[this->Cursor].FlatIndex == index)
    {
      this->Apply(objects[this->Cursor], state);
    }
  }

  void Apply(Object& object, const BlockState& state)
  {
    const size_t i = this->In.IndexOf(object);
    if (object.Visible != state.Visible)
    {
      object.Visible = state.Visible;
      this->VisibilityChanged = true;
      (*this->ColorChanged)[i] = 1; // hidden vertices, lines and strips: alpha 0
    }
    if (object.Pickable != state.Pickable)
    {
      object.Pickable = state.Pickable;
      this->PickabilityChanged = true;
    }
    if (ColorsDiffer(object, state))
    {
      object.HasBlockColor = state.HasColor;
      object.HasBlockOpacity = state.HasOpacity;
      std::copy(state.Color, state.Color + 3, object.BlockColor);
      object.BlockOpacity = state.Opacity;
      (*this->ColorChanged)[i] = 1;
    }
  }
};

//------------------------------------------------------------------------------
void vtkMultiresolutionPolyDataMapper::SetCompositeDataDisplayAttributes(
  vtkCompositeDataDisplayAttributes* attributes)
{
  // Render state, like the resolutions: not a modification of the mapper.
  Internals& in = *this->Internal;
  if (in.BlockAttributes != attributes)
  {
    in.BlockAttributes = attributes;
    in.BlockAttributesTime = ~vtkMTimeType(0); // applied at the next update
  }
}

vtkCompositeDataDisplayAttributes* vtkMultiresolutionPolyDataMapper::GetCompositeDataDisplayAttributes()
{
  return this->Internal->BlockAttributes;
}

namespace
{
/// The attributes to set for the block of a flat index (created when the
/// mapper has none), or null with an error when no block has that index.
vtkCompositeDataDisplayAttributes* AttributesFor(
  vtkMultiresolutionPolyDataMapper* self, unsigned int flatIndex, vtkDataObject*& block)
{
  vtkDataObject* input =
    self->GetNumberOfInputConnections(0) > 0 ? self->GetInputDataObject(0, 0) : nullptr;
  block = !input || flatIndex == 0
    ? input
    : vtkCompositeDataDisplayAttributes::DataObjectFromIndex(flatIndex, input);
  if (!block)
  {
    vtkErrorWithObjectMacro(self, "No block of flat index " << flatIndex << " in the input; ignored.");
    return nullptr;
  }
  if (!self->GetCompositeDataDisplayAttributes())
  {
    self->SetCompositeDataDisplayAttributes(
      vtkSmartPointer<vtkCompositeDataDisplayAttributes>::New());
  }
  return self->GetCompositeDataDisplayAttributes();
}
}

void vtkMultiresolutionPolyDataMapper::SetBlockVisibility(unsigned int flatIndex, bool visible)
{
  vtkDataObject* block = nullptr;
  if (auto* attributes = AttributesFor(this, flatIndex, block))
  {
    attributes->SetBlockVisibility(block, visible);
  }
}

void vtkMultiresolutionPolyDataMapper::SetBlockColor(
  unsigned int flatIndex, double r, double g, double b)
{
  const double color[3] = { r, g, b };
  if (!std::all_of(color, color + 3, [](double c) { return std::isfinite(c); }))
  {
    vtkErrorMacro("Block color of flat index " << flatIndex << " is not finite; ignored.");
    return;
  }
  vtkDataObject* block = nullptr;
  if (auto* attributes = AttributesFor(this, flatIndex, block))
  {
    attributes->SetBlockColor(block, color);
  }
}

void vtkMultiresolutionPolyDataMapper::SetBlockPickability(unsigned int flatIndex, bool pickable)
{
  vtkDataObject* block = nullptr;
  if (auto* attributes = AttributesFor(this, flatIndex, block))
  {
    attributes->SetBlockPickability(block, pickable);
  }
}

void vtkMultiresolutionPolyDataMapper::SetBlockOpacity(unsigned int flatIndex, double opacity)
{
  if (!(opacity >= 0.0 && opacity <= 1.0))
  {
    vtkErrorMacro("Block opacity " << opacity << " of flat index " << flatIndex
                                   << " is not in [0, 1]; ignored.");
    return;
  }
  vtkDataObject* block = nullptr;
  if (auto* attributes = AttributesFor(this, flatIndex, block))
  {
    attributes->SetBlockOpacity(block, opacity);
  }
}

bool vtkMultiresolutionPolyDataMapper::GetObjectVisibility(vtkIdType i) const
{
  return this->IsValidObject(i) && this->Internal->Objects[i].Visible;
}

bool vtkMultiresolutionPolyDataMapper::GetObjectPickability(vtkIdType i) const
{
  return this->IsValidObject(i) && this->Internal->Objects[i].Pickable;
}

//------------------------------------------------------------------------------
void vtkMultiresolutionPolyDataMapper::UpdateBlockAttributes()
{
  // After every UpdateObjects(): does nothing unless the attributes changed
  // or the objects were read again.
  Internals& in = *this->Internal;
  vtkCompositeDataDisplayAttributes* attributes = in.BlockAttributes;
  const vtkMTimeType time = attributes ? attributes->GetMTime() : 0;
  const bool reread = in.BlockSkeleton != in.Skeleton;
  if (!reread && in.BlockAttributesTime == time)
  {
    return;
  }
  in.BlockAttributesTime = time;
  in.BlockSkeleton = in.Skeleton;

  std::vector<char> changed(in.Objects.size(), 0);
  Internals::BlockWalk walk{ in, attributes };
  walk.ColorChanged = &changed;
  if (in.Input)
  {
    walk.Visit(in.Input, BlockState());
  }
  if (walk.VisibilityChanged)
  {
    ++in.ResolutionVersion; // hidden objects' slots are culled, shown ones drawn again
  }
  this->UpdatePickability(walk.PickabilityChanged || reread);

  bool mode = false;
  in.AnyTranslucentBlock = in.AnyOpaqueBlock = false;
  for (const auto& object : in.Objects)
  {
    const bool otherCells = object.NumberOfVerts + object.NumberOfLines + object.NumberOfStrips > 0;
    mode = mode || object.HasBlockColor || object.HasBlockOpacity || (!object.Visible && otherCells);
    if (object.Visible)
    {
      const bool translucent = object.HasBlockOpacity && object.BlockOpacity < 1.0;
      in.AnyTranslucentBlock = in.AnyTranslucentBlock || translucent;
      in.AnyOpaqueBlock = in.AnyOpaqueBlock || !translucent;
    }
  }
  if (mode != in.BlockMode)
  {
    // Entering or leaving block colors changes the color buffer and the
    // shaders: the one full rebuild block attributes cause.
    in.BlockMode = mode;
    in.BlockColorsStale = true;
    this->Modified();
    return;
  }
  if (!in.BlockMode || in.BlockColorsStale || !in.BlockColors || reread)
  {
    in.BlockColorsStale = true;
    return;
  }
  for (size_t i = 0; i < changed.size(); ++i)
  {
    if (changed[i])
    {
      this->WriteBlockColors(static_cast<vtkIdType>(i));
      in.Objects[i].ColorDirty = true;
      in.BlockColorsDirty = true;
    }
  }
}

//------------------------------------------------------------------------------
void vtkMultiresolutionPolyDataMapper::PrepareBlockColors(vtkActor* act)
{
  // Objects without a block color nor scalars get the property's color: the
  // diffuse one unless only ambient light colors the surface (wireframe and
  // points in ParaView), and block opacities replace the property's opacity.
  Internals& in = *this->Internal;
  vtkProperty* prop = act->GetProperty();
  double color[4] = { 1.0, 1.0, 1.0, prop->GetOpacity() };
  if (prop->GetDiffuse() > 0.0 || prop->GetAmbient() <= 0.0)
  {
    prop->GetDiffuseColor(color);
  }
  else
  {
    prop->GetAmbientColor(color);
  }
  if (!std::equal(color, color + 4, in.BlockPropertyColor))
  {
    std::copy(color, color + 4, in.BlockPropertyColor);
    in.BlockColorsStale = true; // property changes rebuild the buffers anyway
  }
}

vtkUnsignedCharArray* vtkMultiresolutionPolyDataMapper::MapBlockColors(double alpha, int& cellFlag)
{
  Internals& in = *this->Internal;
  auto setColors = [this](vtkUnsignedCharArray* array)
  {
    if (this->Colors != array)
    {
      if (array)
      {
        array->Register(this);
      }
      if (this->Colors)
      {
        this->Colors->UnRegister(this);
      }
      this->Colors = array;
    }
  };
  // The scalar colors first, from their own cache (which keys on
  // this->Colors), as colors per vertex or cell: block colors replace them
  // per object, which texture coloring cannot.
  setColors(in.BaseColors);
  const vtkTypeBool interpolate = this->InterpolateScalarsBeforeMapping;
  this->InterpolateScalarsBeforeMapping = 0;
  vtkUnsignedCharArray* base = this->MapScalarColors(alpha, cellFlag);
  this->InterpolateScalarsBeforeMapping = interpolate;
  const vtkIdType total = cellFlag == 1 ? in.TotalCells : in.TotalVertices;
  if (base && (base->GetNumberOfComponents() != 4 || base->GetNumberOfTuples() != total))
  {
    base = nullptr; // e.g. one field-data tuple: the property's color instead
  }
  in.BaseColors = base;
  const bool cells = base && cellFlag == 1;
  cellFlag = cells ? 1 : 0;
  const vtkMTimeType baseTime = base ? base->GetMTime() : 0;
  if (in.BlockColorsStale || !in.BlockColors || cells != in.BlockCells ||
    baseTime != in.BlockBaseTime)
  {
    if (!in.BlockColors)
    {
      in.BlockColors = vtkSmartPointer<vtkUnsignedCharArray>::New();
      in.BlockColors->SetName("BlockColors");
      in.BlockColors->SetNumberOfComponents(4);
    }
    in.BlockColors->SetNumberOfTuples(cells ? in.TotalCells : in.TotalVertices);
    in.BlockCells = cells;
    in.BlockBaseTime = baseTime;
    for (vtkIdType i = 0; i < static_cast<vtkIdType>(in.Objects.size()); ++i)
    {
      this->WriteBlockColors(i);
      in.Objects[i].ColorDirty = false;
    }
    in.BlockColors->Modified(); // uploaded whole
    in.BlockColorsStale = false;
    in.BlockColorsDirty = false;
  }
  // Colored per vertex or cell, never through the scalars' texture.
  this->ReleaseColorTexture();
  setColors(in.BlockColors);
  return this->Colors;
}

void vtkMultiresolutionPolyDataMapper::WriteBlockColors(vtkIdType i)
{
  // Object i's range of the block colors: hidden (alpha 0: its vertices,
  // lines and strips are dropped by the vertex shader), its block color, or
  // its scalar colors (else the property's), alpha times its block opacity.
  Internals& in = *this->Internal;
  const Internals::Object& object = in.Objects[i];
  const vtkIdType start = in.BlockCells ? object.CellOffset : object.VertexOffset;
  const vtkIdType count =
    in.BlockCells ? object.Leaf->GetNumberOfCells() : object.NumberOfVertices;
  if (!in.BlockColors || 4 * (start + count) > in.BlockColors->GetNumberOfValues())
  {
    return;
  }
  unsigned char* out = in.BlockColors->GetPointer(4 * start);
  const double propertyOpacity = in.BlockPropertyColor[3];
  // The shader multiplies by the property's opacity, which a block opacity replaces.
  const double factor = !object.Visible ? 0.0
    : object.HasBlockOpacity
    ? (propertyOpacity > 0.0 ? std::min(1.0, object.BlockOpacity / propertyOpacity) : 0.0)
    : 1.0;
  const unsigned char* base = in.BaseColors && !object.HasBlockColor
    ? in.BaseColors->GetPointer(4 * start)
    : nullptr;
  unsigned char uniform[4] = { 255, 255, 255, 255 };
  const double* color = object.HasBlockColor ? object.BlockColor : in.BlockPropertyColor;
  for (int k = 0; k < 3; ++k)
  {
    uniform[k] = ToByte(color[k]);
  }
  for (vtkIdType t = 0; t < count; ++t, out += 4)
  {
    const unsigned char* rgba = base ? base + 4 * t : uniform;
    out[0] = rgba[0];
    out[1] = rgba[1];
    out[2] = rgba[2];
    out[3] = factor == 1.0 ? rgba[3]
                           : static_cast<unsigned char>(std::lround(rgba[3] * factor));
  }
}

void vtkMultiresolutionPolyDataMapper::UploadBlockColors()
{
  // After the buffers are up to date: the ranges of the objects whose block
  // attributes changed (cell colors: the slots' texels, all rewritten).
  Internals& in = *this->Internal;
  if (!in.BlockColorsDirty || !in.BlockMode || this->ColorByResolution)
  {
    return;
  }
  in.BlockColorsDirty = false;
  if (this->Colors != in.BlockColors)
  {
    return; // not drawn from them (yet): the next map uploads them whole
  }
  if (!in.BlockCells)
  {
    this->UploadDirtyColors(in.BlockColors);
    return;
  }
  for (auto& object : in.Objects)
  {
    object.ColorDirty = false;
  }
  if (in.LayoutValid && in.CellData)
  {
    this->UploadCellTexels(0, in.Texels);
  }
}

//------------------------------------------------------------------------------
void vtkMultiresolutionPolyDataMapper::ReplaceShaderValues(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  // blockPass keeps translucent objects out of the opaque pass (0) and
  // opaque ones out of the translucent pass (1); 2 draws all.
  Internals& in = *this->Internal;
  const bool blocks = in.BlockMode && !this->ColorByResolution;
  vtkShader* fragment = shaders[vtkShader::Fragment];
  if (blocks && in.BlockCells && this->HaveCellScalars && fragment)
  {
    // Cell colors: by each fragment's opacity, after the color code (which
    // the superclass writes at the Color tag, before the Edges one).
    std::string source = fragment->GetSource();
    vtkShaderProgram::Substitute(
      source, "//VTK::Color::Dec", "//VTK::Color::Dec\nuniform int blockPass;", false);
    vtkShaderProgram::Substitute(source, "//VTK::Edges::Impl",
      "//VTK::Edges::Impl\n"
      "  if ((blockPass == 0 && opacity < 1.0) || (blockPass == 1 && opacity >= 1.0))\n"
      "    {\n"
      "    discard;\n"
      "    }\n",
      false);
    fragment->SetSource(source);
  }
  this->Superclass::ReplaceShaderValues(shaders, ren, act);
  this->ReplacePickabilityShaderValues(shaders[vtkShader::Vertex], ren);
  // Point colors: by the vertex's block alpha, in the vertex shader, which
  // drops a primitive before rasterization by moving all its vertices
  // outside the clip volume (a block's vertices share its opacity class); a
  // vertex of alpha 0 (hidden block: its vertices, lines and strips) is
  // never drawn.
  vtkShader* vertex = shaders[vtkShader::Vertex];
  if (!blocks || !vertex)
  {
    return;
  }
  std::string source = vertex->GetSource();
  if (source.find("in vec4 scalarColor;") == std::string::npos)
  {
    return; // cell colors or no colors in this program
  }
  vtkMultiresolutionMapperDetail::AddVertexDiscard(source, "uniform int blockPass;",
    "scalarColor.a <= 0.0 || (blockPass == 0 && scalarColor.a < 1.0) ||\n"
    "    (blockPass == 1 && scalarColor.a >= 1.0)");
  vertex->SetSource(source);
}

void vtkMultiresolutionMapperDetail::AddVertexDiscard(
  std::string& source, const char* declaration, const char* condition)
{
  vtkShaderProgram::Substitute(
    source, "//VTK::Clip::Dec", std::string("//VTK::Clip::Dec\n") + declaration, false);
  vtkShaderProgram::Substitute(source, "//VTK::CustomEnd::Impl",
    std::string("if (") + condition +
      ")\n"
      "  {\n"
      "  gl_Position = vec4(2.0, 2.0, 2.0, 1.0);\n"
      "  }\n"
      "//VTK::CustomEnd::Impl",
    false);
}

void vtkMultiresolutionPolyDataMapper::SetMapperShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::SetMapperShaderParameters(cellBO, ren, act);
  vtkShaderProgram* program = cellBO.Program;
  this->SetPickabilityShaderParameters(program);
  if (!program || !program->IsUniformUsed("blockPass"))
  {
    return;
  }
  // Split by pass only when the actor is drawn in both (opaque blocks beside
  // translucent ones); selection passes draw every shown block (but the
  // unpickable ones, dropped through pickableVertices).
  int pass = 2;
  if (!ren->GetSelector() && act->HasOpaqueGeometry() && act->HasTranslucentPolygonalGeometry())
  {
    pass = act->IsRenderingTranslucentPolygonalGeometry() ? 1 : 0;
  }
  program->SetUniformi("blockPass", pass);
}
