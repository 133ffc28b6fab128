// SPDX-License-Identifier: BSD-3-Clause
// vtkMultiresolutionPolyDataMapper: colors. Scalars mapped per leaf into one
// array in leaf order, translucency, the cell textures (looked up by
// gl_PrimitiveID, so they follow the index buffer's slots) and the
// resolution map's grey levels.
#include "vtkMultiresolutionPolyDataMapperInternals.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLookupTable.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLCellToVTKCellMap.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLVertexBufferObject.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"
#include "vtkScalarsToColors.h"
#include "vtkTextureObject.h"
#include "vtkUnsignedCharArray.h"

#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using vtkMultiresolutionMapperDetail::Grow;

namespace
{
/// Grey levels of the resolution map: few enough that a small change of
/// resolution rarely rewrites colors, many enough to tell resolutions apart.
constexpr int ColorLevels = 64;

unsigned char GreyForLevel(int level)
{
  const double grey = 0.25 + 0.75 * static_cast<double>(level) / (ColorLevels - 1);
  return static_cast<unsigned char>(std::lround(255.0 * grey));
}
}

//------------------------------------------------------------------------------
vtkUnsignedCharArray* vtkMultiresolutionPolyDataMapper::MapScalars(double alpha)
{
  int cellFlag = 0;
  return this->MapScalars(alpha, cellFlag);
}

vtkUnsignedCharArray* vtkMultiresolutionPolyDataMapper::MapScalars(double alpha, int& cellFlag)
{
  Internals& in = *this->Internal;
  cellFlag = 0;
  if (this->ColorByResolution && in.ResolutionColors)
  {
    // The resolution map is this mapper's own vertex colors.
    if (this->Colors != in.ResolutionColors)
    {
      if (this->Colors)
      {
        this->Colors->UnRegister(this);
      }
      this->Colors = in.ResolutionColors;
      this->Colors->Register(this);
    }
    in.ColorsAreResolutionMap = true;
    this->ReleaseColorTexture();
    return this->Colors;
  }
  if (in.ColorsAreResolutionMap || (in.BlockColors && this->Colors == in.BlockColors))
  {
    // Leaving the resolution map or the block colors: never let the
    // superclass reuse them as its colors.
    if (this->Colors)
    {
      this->Colors->UnRegister(this);
      this->Colors = nullptr;
    }
    in.ColorsAreResolutionMap = false;
    in.ColorsValid = false;
  }
  if (in.BlockMode)
  {
    return this->MapBlockColors(alpha, cellFlag);
  }
  return this->MapScalarColors(alpha, cellFlag);
}

vtkUnsignedCharArray* vtkMultiresolutionPolyDataMapper::MapScalarColors(double alpha, int& cellFlag)
{
  Internals& in = *this->Internal;
  cellFlag = 0;
  // Only arrays common to all leaves color (as vtkAppendPolyData keeps them):
  // the skeleton has those. One leaf maps its own array, without a copy.
  vtkAbstractArray* common = in.Skeleton ? vtkAbstractMapper::GetAbstractScalars(in.Skeleton,
                                             this->ScalarMode, this->ArrayAccessMode, this->ArrayId,
                                             this->ArrayName, cellFlag)
                                         : nullptr;
  if (!this->ScalarVisibility || !common || in.Objects.size() == 1)
  {
    vtkDataSet* data = common && in.Objects.size() == 1
      ? static_cast<vtkDataSet*>(in.Objects[0].Leaf)
      : static_cast<vtkDataSet*>(in.Skeleton);
    in.ColorsValid = false; // the superclass's own colors: no per-leaf cache
    return this->Superclass::MapScalars(data, alpha, cellFlag);
  }
  return this->MapLeafScalars(common, alpha, cellFlag);
}

vtkAbstractArray* vtkMultiresolutionPolyDataMapper::GetLeafScalars(
  vtkPolyData* leaf, vtkAbstractArray* common, int cellFlag)
{
  // By name when the common array has one (array ids count the common arrays).
  const char* name = common->GetName();
  if (name && *name && cellFlag < 2)
  {
    vtkDataSetAttributes* attributes = cellFlag == 1
      ? static_cast<vtkDataSetAttributes*>(leaf->GetCellData())
      : static_cast<vtkDataSetAttributes*>(leaf->GetPointData());
    return attributes->GetAbstractArray(name);
  }
  int flag = 0;
  return vtkAbstractMapper::GetAbstractScalars(
    leaf, this->ScalarMode, this->ArrayAccessMode, this->ArrayId, this->ArrayName, flag);
}

void vtkMultiresolutionPolyDataMapper::PrepareLeafLookupTable(
  vtkAbstractArray* common, int cellFlag)
{
  // The first leaf's table when its scalars have one (as vtkMapper takes its
  // input's), else the mapper's own; the mapper's range unless told otherwise.
  if (this->ArrayComponent < 0 || common->GetNumberOfComponents() <= this->ArrayComponent)
  {
    this->ArrayComponent = 0;
  }
  vtkDataArray* first = vtkArrayDownCast<vtkDataArray>(
    this->GetLeafScalars(this->Internal->Objects[0].Leaf, common, cellFlag));
  if (first && first->GetLookupTable())
  {
    this->SetLookupTable(first->GetLookupTable());
  }
  else
  {
    if (!this->LookupTable)
    {
      this->CreateDefaultLookupTable();
    }
    this->LookupTable->Build();
  }
  if (!this->UseLookupTableScalarRange)
  {
    this->LookupTable->SetRange(this->ScalarRange);
  }
}

vtkUnsignedCharArray* vtkMultiresolutionPolyDataMapper::MapLeafScalars(
  vtkAbstractArray* common, double alpha, int cellFlag)
{
  // Each leaf's scalars mapped with the mapper's one lookup table and range,
  // into one array in leaf order (point colors in vertex buffer order, cell
  // colors in the cells' leaf order: Object::CellOffset), as vtkMapper maps
  // one dataset's. Interpolated scalars (texture coloring) concatenate the
  // leaves' texture coordinates instead.
  Internals& in = *this->Internal;
  this->PrepareLeafLookupTable(common, cellFlag);
  const bool texture = this->CanUseTextureMapForColoring(in.Skeleton) != 0;
  const vtkMTimeType newest = std::max(
    { this->GetMTime(), in.Skeleton->GetMTime(), this->LookupTable->GetMTime() });
  const bool cached = in.ColorsValid && in.ColorsTime > newest && in.ColorsAlpha == alpha &&
    in.ColorsCellFlag == cellFlag && in.ColorsTexture == texture &&
    (texture ? this->ColorCoordinates != nullptr : this->Colors != nullptr);
  if (cached)
  {
    return texture ? nullptr : this->Colors;
  }
  auto release = [this](auto*& array)
  {
    if (array)
    {
      array->UnRegister(this);
      array = nullptr;
    }
  };
  release(this->Colors);
  release(this->ColorCoordinates);
  if (!texture)
  {
    release(this->ColorTextureMap);
  }
  const vtkIdType total = cellFlag == 1 ? in.TotalCells : in.TotalVertices;
  vtkSmartPointer<vtkUnsignedCharArray> colors;
  vtkSmartPointer<vtkFloatArray> coordinates;
  const double lutAlpha = this->LookupTable->GetAlpha();
  this->LookupTable->SetAlpha(alpha);
  for (const auto& object : in.Objects)
  {
    vtkAbstractArray* scalars = this->GetLeafScalars(object.Leaf, common, cellFlag);
    const vtkIdType offset = cellFlag == 1 ? object.CellOffset : object.VertexOffset;
    const vtkIdType count = cellFlag == 1 ? object.Leaf->GetNumberOfCells() : object.NumberOfVertices;
    if (!scalars || scalars->GetNumberOfTuples() != count)
    {
      continue; // not drawn in color (a valid leaf always has it: common array)
    }
    if (texture)
    {
      // Texture coordinates of this leaf's scalars; the texture is the table's.
      this->MapScalarsToTexture(scalars, alpha);
      if (!this->ColorCoordinates)
      {
        continue;
      }
      if (!coordinates)
      {
        coordinates = vtkSmartPointer<vtkFloatArray>::New();
        coordinates->SetNumberOfComponents(this->ColorCoordinates->GetNumberOfComponents());
        coordinates->SetNumberOfTuples(total);
        coordinates->Fill(0.0);
      }
      for (vtkIdType t = 0; t < count; ++t)
      {
        coordinates->SetTuple(offset + t, t, this->ColorCoordinates);
      }
      release(this->ColorCoordinates);
      continue;
    }
    vtkSmartPointer<vtkUnsignedCharArray> mapped;
    mapped.TakeReference(this->LookupTable->MapScalars(scalars, this->ColorMode, this->ArrayComponent));
    if (!mapped || mapped->GetNumberOfComponents() != 4)
    {
      continue;
    }
    if (!colors)
    {
      colors = vtkSmartPointer<vtkUnsignedCharArray>::New();
      colors->SetNumberOfComponents(4);
      colors->SetNumberOfTuples(total);
      colors->Fill(255);
    }
    std::memcpy(colors->GetPointer(4 * offset), mapped->GetPointer(0), 4 * static_cast<size_t>(count));
  }
  this->LookupTable->SetAlpha(lutAlpha);
  if (coordinates)
  {
    this->ColorCoordinates = coordinates;
    this->ColorCoordinates->Register(this);
  }
  if (colors)
  {
    this->Colors = colors;
    this->Colors->Register(this);
  }
  in.ColorsTime.Modified();
  in.ColorsValid = true;
  in.ColorsAlpha = alpha;
  in.ColorsCellFlag = cellFlag;
  in.ColorsTexture = texture;
  return this->Colors;
}

bool vtkMultiresolutionPolyDataMapper::HasTranslucentPolygonalGeometry()
{
  if (this->ColorByResolution)
  {
    return false;
  }
  const Internals& in = *this->Internal;
  return (in.BlockMode && in.AnyTranslucentBlock) || this->HasTranslucentScalars();
}

bool vtkMultiresolutionPolyDataMapper::HasOpaqueGeometry()
{
  const Internals& in = *this->Internal;
  if (this->ColorByResolution || !in.BlockMode || !in.AnyTranslucentBlock)
  {
    return !this->HasTranslucentPolygonalGeometry();
  }
  // Translucent blocks beside opaque ones: the opaque ones are drawn in the
  // opaque pass when the shaders can tell them apart (block colors over
  // opaque scalars; see ReplaceShaderValues).
  return in.AnyOpaqueBlock && !this->HasTranslucentScalars();
}

bool vtkMultiresolutionPolyDataMapper::HasTranslucentScalars()
{
  Internals& in = *this->Internal;
  if (!this->ScalarVisibility || !in.Skeleton)
  {
    return false;
  }
  int cellFlag = 0;
  vtkAbstractArray* common = vtkAbstractMapper::GetAbstractScalars(
    in.Skeleton, this->ScalarMode, this->ArrayAccessMode, this->ArrayId, this->ArrayName, cellFlag);
  if (!common)
  {
    return false;
  }
  vtkScalarsToColors* lut = this->GetLookupTable();
  lut->Build();
  // Asked every frame: the answer is kept until the mapper, its table or the
  // leaves (a re-read) change, instead of asking every leaf again.
  const vtkMTimeType newest =
    std::max({ this->GetMTime(), lut->GetMTime(), in.Skeleton->GetMTime() });
  if (in.TranslucentValid && in.TranslucentTime > newest)
  {
    return in.Translucent;
  }
  in.Translucent = false;
  for (const auto& object : in.Objects)
  {
    vtkAbstractArray* scalars = this->GetLeafScalars(object.Leaf, common, cellFlag);
    unsigned char ghostsToSkip = 0;
    vtkUnsignedCharArray* ghosts =
      vtkAbstractMapper::GetGhostArray(object.Leaf, this->ScalarMode, ghostsToSkip);
    if (scalars &&
      lut->IsOpaque(scalars, this->ColorMode, this->ArrayComponent, ghosts, ghostsToSkip) == 0)
    {
      in.Translucent = true;
      break;
    }
  }
  in.TranslucentValid = true;
  in.TranslucentTime.Modified();
  return in.Translucent;
}

void vtkMultiresolutionPolyDataMapper::BuildCellTextures(
  vtkRenderer*, vtkActor*, vtkCellArray* prims[4], int representation)
{
  // Only the cell map here, and only for the vertices, lines and strips of
  // non-TOM leaves: the textures follow the index buffer's slots and are
  // written with them (AllocateCellTextures, UploadCellTexels).
  if ((this->HaveCellScalars || this->HaveCellNormals) && this->Internal->HasOtherCells)
  {
    this->CellCellMap->Update(prims, representation, this->CurrentInput->GetPoints());
  }
}

void vtkMultiresolutionPolyDataMapper::UpdateResolutionColor(vtkIdType i)
{
  Internals& in = *this->Internal;
  if (!in.ResolutionColors || !this->ColorByResolution)
  {
    return;
  }
  Internals::Object& object = in.Objects[i];
  if (object.Refinement && this->ViewDependentRefinement)
  {
    // Per vertex, by merge-tree level: only the display vertices are drawn,
    // so the greys follow the front without being rewritten.
    if (object.ColorLevel != ColorLevels)
    {
      object.ColorLevel = ColorLevels;
      unsigned char* rgba = in.ResolutionColors->GetPointer(4 * object.VertexOffset);
      const double levels = std::max<double>(object.LevelCount, 1);
      for (vtkIdType v = 0; v < object.NumberOfVertices; ++v, rgba += 4)
      {
        const double finest = 1.0 - std::min<double>(object.Levels[v], levels) / levels;
        rgba[0] = rgba[1] = rgba[2] =
          GreyForLevel(static_cast<int>(std::lround(finest * (ColorLevels - 1))));
        rgba[3] = 255;
      }
      object.ColorDirty = true;
    }
    return;
  }
  const double fraction = object.NumberOfTriangles > 0
    ? static_cast<double>(object.RenderedTriangles) / object.NumberOfTriangles
    : 1.0;
  const int level = static_cast<int>(std::lround(fraction * (ColorLevels - 1)));
  if (level != object.ColorLevel)
  {
    object.ColorLevel = level;
    const unsigned char grey = GreyForLevel(level);
    unsigned char* rgba = in.ResolutionColors->GetPointer(4 * object.VertexOffset);
    for (vtkIdType v = 0; v < object.NumberOfVertices; ++v, rgba += 4)
    {
      rgba[0] = rgba[1] = rgba[2] = grey;
      rgba[3] = 255;
    }
    object.ColorDirty = true;
  }
}

//------------------------------------------------------------------------------
void vtkMultiresolutionPolyDataMapper::AllocateCellTextures(vtkRenderer* ren)
{
  // VTK looks cell values up by gl_PrimitiveID, which counts the primitives
  // actually drawn, padding included: texel TexelBase + p holds the cell of
  // index-buffer primitive p. Vertices and lines (first) and strips (after
  // the index buffer's capacity, PatchStripOffset) of non-TOM leaves keep
  // VTK's layout; they are written here, the slots' texels with their slots.
  Internals& in = *this->Internal;
  vtkIdType* offsets = this->CellCellMap->GetPrimitiveOffsets();
  in.TexelBase = in.HasOtherCells ? static_cast<size_t>(offsets[2]) : 0;
  const size_t mapSize = in.HasOtherCells ? this->CellCellMap->GetSize() : 0;
  in.Texels = in.TexelBase + in.Slots.GetCapacity() + (mapSize > in.TexelBase ? mapSize - in.TexelBase : 0);
  in.Texels = std::max<size_t>(in.Texels, 1); // texture buffers may not be empty
  vtkOpenGLRenderWindow* renWin = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  const auto texels = static_cast<unsigned int>(in.Texels);

  if (this->HaveCellScalars && this->Colors)
  {
    Grow(in.CellColors, 4 * in.Texels);
    if (!this->CellScalarTexture)
    {
      this->CellScalarTexture = vtkTextureObject::New();
      this->CellScalarBuffer = vtkOpenGLBufferObject::New();
      this->CellScalarBuffer->SetType(vtkOpenGLBufferObject::TextureBuffer);
    }
    this->CellScalarTexture->SetContext(renWin);
    this->CellScalarBuffer->GenerateBuffer(vtkOpenGLBufferObject::TextureBuffer);
    this->CellScalarBuffer->Bind();
    glBufferData(GL_TEXTURE_BUFFER, static_cast<GLsizeiptr>(4 * in.Texels), nullptr, GL_DYNAMIC_DRAW);
    this->CellScalarBuffer->Release();
    this->CellScalarTexture->CreateTextureBuffer(texels, 4, VTK_UNSIGNED_CHAR, this->CellScalarBuffer);
  }
  if (this->HaveCellNormals && this->CurrentInput->GetCellData()->GetNormals())
  {
    Grow(in.CellNormals, 4 * in.Texels);
    if (!this->CellNormalTexture)
    {
      this->CellNormalTexture = vtkTextureObject::New();
      this->CellNormalBuffer = vtkOpenGLBufferObject::New();
      this->CellNormalBuffer->SetType(vtkOpenGLBufferObject::TextureBuffer);
    }
    this->CellNormalTexture->SetContext(renWin);
    // Without float textures, normals as bytes, as VTK does.
    in.FloatCellNormals =
      renWin->GetDefaultTextureInternalFormat(VTK_FLOAT, 4, false, true, false) != 0;
    if (!in.FloatCellNormals)
    {
      Grow(in.CellNormalBytes, 4 * in.Texels);
    }
    this->CellNormalBuffer->GenerateBuffer(vtkOpenGLBufferObject::TextureBuffer);
    this->CellNormalBuffer->Bind();
    glBufferData(GL_TEXTURE_BUFFER,
      static_cast<GLsizeiptr>((in.FloatCellNormals ? 16 : 4) * in.Texels), nullptr, GL_DYNAMIC_DRAW);
    this->CellNormalBuffer->Release();
    this->CellNormalTexture->CreateTextureBuffer(texels, 4,
      in.FloatCellNormals ? VTK_FLOAT : VTK_UNSIGNED_CHAR, this->CellNormalBuffer);
  }
  this->UploadCellTexels(0, in.TexelBase);
  this->UploadCellTexels(in.TexelBase + in.Slots.GetCapacity(), in.Texels);
}

void vtkMultiresolutionPolyDataMapper::UploadCellTexels(size_t begin, size_t end)
{
  Internals& in = *this->Internal;
  end = std::min(end, in.Texels);
  if (begin >= end)
  {
    return;
  }
  // Cell (in leaf order, Object::CellOffset) of texel i: the slots' from
  // their primitives, the other cells' from VTK's map of the skeleton's.
  const size_t trisEnd = in.TexelBase + in.Slots.GetCapacity();
  const size_t mapSize = in.HasOtherCells ? this->CellCellMap->GetSize() : 0;
  auto cellOf = [&](size_t i) -> vtkIdType
  {
    if (i >= in.TexelBase && i < trisEnd)
    {
      return in.PrimitiveCells[i - in.TexelBase];
    }
    const size_t index = i < in.TexelBase ? i : i - in.Slots.GetCapacity();
    vtkIdType leafCell = 0;
    const Internals::Object* object =
      index < mapSize ? in.ObjectOfOtherCell(this->CellCellMap->GetValue(index), leafCell) : nullptr;
    return object ? object->CellOffset + leafCell : 0;
  };

  if (this->HaveCellScalars && this->Colors && in.CellColors.size() >= 4 * in.Texels)
  {
    const int components = this->Colors->GetNumberOfComponents();
    const unsigned char* colors = this->Colors->GetPointer(0);
    const bool single =
      this->FieldDataTupleId > -1 && this->ScalarMode == VTK_SCALAR_MODE_USE_FIELD_DATA;
    const vtkIdType tuples = this->Colors->GetNumberOfTuples();
    for (size_t i = begin; i < end; ++i)
    {
      vtkIdType cell = single ? this->FieldDataTupleId : cellOf(i);
      cell = std::min<vtkIdType>(std::max<vtkIdType>(cell, 0), tuples - 1);
      for (int k = 0; k < 4; ++k)
      {
        in.CellColors[4 * i + k] = k < components ? colors[components * cell + k] : 255;
      }
    }
    this->CellScalarBuffer->Bind();
    glBufferSubData(GL_TEXTURE_BUFFER, static_cast<GLintptr>(4 * begin),
      static_cast<GLsizeiptr>(4 * (end - begin)), in.CellColors.data() + 4 * begin);
    this->CellScalarBuffer->Release();
    this->CellDataBytesUploaded += static_cast<vtkIdType>(4 * (end - begin));
  }

  if (this->HaveCellNormals && this->CurrentInput->GetCellData()->GetNormals() &&
    in.CellNormals.size() >= 4 * in.Texels)
  {
    double normal[3] = { 0.0, 0.0, 1.0 };
    for (size_t i = begin; i < end; ++i)
    {
      // Each leaf's own cell normals (one lookup per texel: cell normals are rare).
      const vtkIdType cell = cellOf(i);
      const Internals::Object* object = in.ObjectOfCell(cell);
      vtkDataArray* normals = object ? object->Leaf->GetCellData()->GetNormals() : nullptr;
      const vtkIdType leafCell = object ? cell - object->CellOffset : 0;
      if (normals && leafCell < normals->GetNumberOfTuples())
      {
        normals->GetTuple(leafCell, normal);
      }
      for (int k = 0; k < 3; ++k)
      {
        in.CellNormals[4 * i + k] = static_cast<float>(normal[k]);
      }
      in.CellNormals[4 * i + 3] = 0.0f;
    }
    this->CellNormalBuffer->Bind();
    if (in.FloatCellNormals)
    {
      glBufferSubData(GL_TEXTURE_BUFFER, static_cast<GLintptr>(16 * begin),
        static_cast<GLsizeiptr>(16 * (end - begin)), in.CellNormals.data() + 4 * begin);
      this->CellDataBytesUploaded += static_cast<vtkIdType>(16 * (end - begin));
    }
    else
    {
      for (size_t i = 4 * begin; i < 4 * end; ++i)
      {
        in.CellNormalBytes[i] = static_cast<unsigned char>(127.0 * (in.CellNormals[i] + 1.0));
      }
      glBufferSubData(GL_TEXTURE_BUFFER, static_cast<GLintptr>(4 * begin),
        static_cast<GLsizeiptr>(4 * (end - begin)), in.CellNormalBytes.data() + 4 * begin);
      this->CellDataBytesUploaded += static_cast<vtkIdType>(4 * (end - begin));
    }
    this->CellNormalBuffer->Release();
  }
}

void vtkMultiresolutionPolyDataMapper::UploadResolutionColors()
{
  this->UploadDirtyColors(this->Internal->ResolutionColors);
}

void vtkMultiresolutionPolyDataMapper::UploadDirtyColors(vtkUnsignedCharArray* colors)
{
  // The resolution map's or the block colors' vertex colors.
  Internals& in = *this->Internal;
  vtkOpenGLVertexBufferObject* vbo = this->VBOs->GetVBO("scalarColor");
  const bool inPlace = vbo &&
    vbo->GetNumberOfTuples() == static_cast<unsigned int>(in.TotalVertices) &&
    vbo->GetStride() == 4 && vbo->GetDataType() == VTK_UNSIGNED_CHAR;
  if (vbo && !inPlace)
  {
    vbo->UploadDataArray(colors);
  }
  else if (inPlace)
  {
    // Only the vertices of objects whose colors changed, one write per
    // run of consecutive such objects. The array's MTime is left alone: the
    // buffer holds its values.
    vbo->Bind();
    const size_t count = in.Objects.size();
    for (size_t i = 0; i < count;)
    {
      if (!in.Objects[i].ColorDirty)
      {
        ++i;
        continue;
      }
      const vtkIdType begin = in.Objects[i].VertexOffset;
      vtkIdType end = begin;
      for (; i < count && in.Objects[i].ColorDirty; ++i)
      {
        end = in.Objects[i].VertexOffset + in.Objects[i].NumberOfVertices;
      }
      glBufferSubData(GL_ARRAY_BUFFER, static_cast<GLintptr>(4 * begin),
        static_cast<GLsizeiptr>(4 * (end - begin)), colors->GetPointer(4 * begin));
      this->ColorBytesUploaded += 4 * (end - begin);
    }
    vbo->Release();
  }
  // Without a color buffer yet, the superclass uploads the whole array.
  for (auto& object : in.Objects)
  {
    object.ColorDirty = false;
  }
}

//------------------------------------------------------------------------------
void vtkMultiresolutionPolyDataMapper::ReleaseColorTexture()
{
  if (this->ColorCoordinates)
  {
    this->ColorCoordinates->UnRegister(this);
    this->ColorCoordinates = nullptr;
  }
  if (this->ColorTextureMap)
  {
    this->ColorTextureMap->UnRegister(this);
    this->ColorTextureMap = nullptr;
  }
}
