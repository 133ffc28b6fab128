// SPDX-License-Identifier: BSD-3-Clause
// vtkMultiresolutionPolyDataMapper: the vertex buffers, appended from the
// leaves themselves (no merged copy of them is kept), rebuilt only when the
// leaves, the attributes drawn or the shift and scale change; a change of
// the colors alone re-uploads the color buffer.
#include "vtkMultiresolutionPolyDataMapperInternals.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLCellToVTKCellMap.h"
#include "vtkOpenGLTexture.h"
#include "vtkOpenGLVertexBufferObject.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkTransform.h"
#include "vtkUnsignedCharArray.h"

#include <functional>
#include <string>

bool vtkMultiresolutionPolyDataMapper::GetNeedToRebuildBufferObjects(
  vtkRenderer* ren, vtkActor* act)
{
  Internals& in = *this->Internal;
  const bool all = this->Superclass::GetNeedToRebuildBufferObjects(ren, act);
  // Resolutions changed during selection passes wait for the next frame (see RenderPiece).
  const bool indices = in.UploadedVersion != in.ResolutionVersion &&
    (!ren->GetSelector() || !in.LayoutValid);
  in.OnlyIndicesChanged = !all && indices;
  return all || indices;
}

void vtkMultiresolutionPolyDataMapper::BuildBufferObjects(vtkRenderer* ren, vtkActor* act)
{
  Internals& in = *this->Internal;
  if (in.OnlyIndicesChanged)
  {
    // Vertex buffers stay as uploaded; only the slots of changed objects are rewritten.
    in.OnlyIndicesChanged = false;
    this->FillIndexBuffer(ren, act, false);
    return;
  }
  if (this->ColorByResolution && !in.ResolutionColors && in.TotalVertices > 0)
  {
    in.ResolutionColors = vtkSmartPointer<vtkUnsignedCharArray>::New();
    in.ResolutionColors->SetName("ResolutionMap");
    in.ResolutionColors->SetNumberOfComponents(4);
    in.ResolutionColors->SetNumberOfTuples(in.TotalVertices);
    in.ResolutionColors->Fill(255);
    for (auto& object : in.Objects)
    {
      object.ColorLevel = -1;
    }
  }
  // In map mode the superclass must take the resolution colors as point
  // colors, never as cell colors (which it picks when the data has no point
  // scalars and ScalarVisibility is on).
  const vtkTypeBool scalarVisibility = this->ScalarVisibility;
  if (this->ColorByResolution)
  {
    this->ScalarVisibility = 0;
  }
  const auto start = std::chrono::steady_clock::now();
  this->BuildVertexBuffers(ren, act);
  this->LastVertexBufferBuildTime =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  this->ScalarVisibility = scalarVisibility;
  ++in.VertexBufferBuildCount;
}

void vtkMultiresolutionPolyDataMapper::BuildVertexBuffers(vtkRenderer* ren, vtkActor* act)
{
  // What vtkOpenGLPolyDataMapper::BuildBufferObjects does for one polydata,
  // with the vertex buffers appended from the leaves (in object order, the
  // vertex offsets) instead of read from one merged copy of them.
  Internals& in = *this->Internal;
  vtkPolyData* skeleton = this->CurrentInput;
  const bool pointNormals = this->PrepareColorsAndCellTextures(ren, act);
  vtkDataArray* pointColors = this->HaveCellScalars ? nullptr : this->Colors;

  // The vertex buffers follow the leaves (a re-read makes a new skeleton),
  // the attributes drawn and the shift and scale method; a change of the
  // colors alone re-uploads the color buffer only.
  const int tcoords = this->GetTCoordsSource();
  vtkStateStorage leafState;
  this->GetLeafBufferState(leafState, pointNormals, tcoords);
  vtkStateStorage colorState;
  colorState.Append(pointColors, "colors");
  colorState.Append(pointColors ? pointColors->GetMTime() : 0, "colors mtime");
  vtkOpenGLVertexBufferObjectGroup* vbos = this->VBOs;
  vtkOpenGLVertexBufferObject* colorVBO = vbos->GetVBO("scalarColor");
  const bool rebuild = in.ForceVertexUpload || in.LeafVBOState != leafState ||
    !vbos->GetVBO("vertexMC") || (pointColors != nullptr) != (colorVBO != nullptr);
  if (!rebuild)
  {
    if (in.ColorVBOState != colorState && colorVBO)
    {
      colorVBO->UploadDataArray(pointColors);
      in.ColorVBOState = colorState;
    }
    this->BuildIBO(ren, act, skeleton);
    this->VBOBuildTime.Modified();
    return;
  }
  in.LeafVBOState = leafState;
  in.ColorVBOState = colorState;
  in.ForceVertexUpload = false;
  vbos->ClearAllVBOs();
  this->AppendLeafBuffers(ren, act, pointColors, pointNormals, tcoords);
  this->BuildIBO(ren, act, skeleton);
  this->VBOBuildTime.Modified();
}

bool vtkMultiresolutionPolyDataMapper::PrepareColorsAndCellTextures(vtkRenderer* ren, vtkActor* act)
{
  vtkPolyData* skeleton = this->CurrentInput;
  this->MapScalars(1.0);
  if (this->ColorTextureMap)
  {
    if (!this->InternalColorTexture)
    {
      this->InternalColorTexture = vtkOpenGLTexture::New();
      this->InternalColorTexture->RepeatOff();
    }
    this->InternalColorTexture->SetInputData(this->ColorTextureMap);
  }

  // Cell colors: cell scalars, or scalars without point scalars.
  this->HaveCellScalars = false;
  if (this->ScalarVisibility && this->Colors && this->Colors->GetNumberOfTuples() > 0 &&
    this->ScalarMode != VTK_SCALAR_MODE_USE_POINT_FIELD_DATA &&
    (this->ScalarMode == VTK_SCALAR_MODE_USE_CELL_DATA ||
      this->ScalarMode == VTK_SCALAR_MODE_USE_CELL_FIELD_DATA ||
      this->ScalarMode == VTK_SCALAR_MODE_USE_FIELD_DATA || !skeleton->GetPointData()->GetScalars()))
  {
    this->HaveCellScalars = true;
  }
  if (this->Internal->BlockMode && !this->ColorByResolution)
  {
    this->HaveCellScalars = this->Internal->BlockCells; // block colors say which
  }
  const int representation = act->GetProperty()->GetRepresentation();
  const int interpolation = act->GetProperty()->GetInterpolation();
  const bool pointNormals =
    interpolation != VTK_FLAT && skeleton->GetPointData()->GetNormals() != nullptr;
  this->HaveCellNormals = !pointNormals && skeleton->GetCellData()->GetNormals() != nullptr;

  vtkCellArray* prims[4] = { skeleton->GetVerts(), skeleton->GetLines(), skeleton->GetPolys(),
    skeleton->GetStrips() };
  this->CellCellMap->SetStartOffset(0);
  this->TempState.Clear();
  for (vtkCellArray* prim : prims)
  {
    this->TempState.Append(prim->GetNumberOfCells() ? prim->GetMTime() : 0, "prim mtime");
  }
  this->TempState.Append(representation, "representation");
  this->TempState.Append(interpolation, "interpolation");
  this->TempState.Append(skeleton->GetMTime(), "polydata mtime");
  this->TempState.Append(this->GetMTime(), "this mtime");
  if (this->CellTextureBuildState != this->TempState)
  {
    this->CellTextureBuildState = this->TempState;
    this->BuildCellTextures(ren, act, prims, representation);
  }
  this->CellCellMap->BuildPrimitiveOffsetsIfNeeded(prims, representation, skeleton->GetPoints());
  return pointNormals;
}

int vtkMultiresolutionPolyDataMapper::GetTCoordsSource()
{
  // 0: none, 1: the leaves' texture coordinates, 2: the mapped scalars' color coordinates.
  vtkPolyData* skeleton = this->CurrentInput;
  return !this->HaveTCoords(skeleton)                                       ? 0
    : this->InterpolateScalarsBeforeMapping && this->ColorCoordinates ? 2
    : skeleton->GetPointData()->GetTCoords()                          ? 1
                                                                      : 0;
}

void vtkMultiresolutionPolyDataMapper::GetLeafBufferState(
  vtkStateStorage& state, bool pointNormals, int tcoords)
{
  vtkPolyData* skeleton = this->CurrentInput;
  state.Append(skeleton->GetMTime(), "skeleton");
  state.Append(pointNormals, "normals");
  state.Append(tcoords, "tcoords");
  state.Append(tcoords == 2 ? this->ColorCoordinates->GetMTime() : 0, "color coordinates");
  state.Append(
    vtkFloatArray::SafeDownCast(skeleton->GetPointData()->GetTangents()) != nullptr, "tangents");
  std::string extras;
  for (const auto& extra : this->ExtraAttributes)
  {
    extras += extra.first + "=" + extra.second.DataArrayName + ";";
  }
  state.Append(std::hash<std::string>()(extras), "extra attributes");
  state.Append(this->ShiftScaleMethod, "shift scale");
}

void vtkMultiresolutionPolyDataMapper::Internals::AppendLeafArrays(
  vtkMultiresolutionPolyDataMapper* self, const char* attribute, LeafArrayGetter get,
  const char* name, AppendedAttributes& appended) const
{
  for (const auto& object : this->Objects)
  {
    vtkDataArray* array = get(object.Leaf, name);
    if (!array || array->GetNumberOfTuples() != object.NumberOfVertices)
    {
      vtkErrorWithObjectMacro(self, "Block " << object.FlatIndex << " lacks the " << attribute
                                             << " array of the other leaves; not drawn right.");
      continue;
    }
    self->VBOs->AppendDataArray(attribute, array, VTK_FLOAT);
    if (appended.empty() || appended.back().first != attribute)
    {
      appended.emplace_back(attribute, array->GetNumberOfComponents());
    }
  }
}

void vtkMultiresolutionPolyDataMapper::AppendLeafBuffers(
  vtkRenderer* ren, vtkActor* act, vtkDataArray* pointColors, bool pointNormals, int tcoords)
{
  // Per leaf: attributes whose arrays are common to all leaves (the
  // skeleton's); colors and color coordinates are one array already.
  Internals& in = *this->Internal;
  vtkPolyData* skeleton = this->CurrentInput;
  vtkOpenGLVertexBufferObjectGroup* vbos = this->VBOs;
  Internals::AppendedAttributes appended;
  auto pointArray = [](vtkPolyData* leaf, const char* name) -> vtkDataArray*
  { return leaf->GetPointData()->GetArray(name); };
  for (const auto& extra : this->ExtraAttributes)
  {
    const char* name = extra.second.DataArrayName.c_str();
    if (skeleton->GetPointData()->GetArray(name))
    {
      in.AppendLeafArrays(this, extra.first.c_str(), pointArray, name, appended);
    }
  }
  in.AppendLeafArrays(
    this, "vertexMC",
    [](vtkPolyData* leaf, const char*) -> vtkDataArray* { return leaf->GetPoints()->GetData(); },
    nullptr, appended);
  vtkOpenGLVertexBufferObject* positions = vbos->GetVBO("vertexMC");
  if (positions)
  {
    // Before BuildAllVBOs: the first leaf's block sets the shift and scale.
    positions->SetCoordShiftAndScaleMethod(
      static_cast<vtkOpenGLVertexBufferObject::ShiftScaleMethod>(this->ShiftScaleMethod));
    positions->SetProp3D(act);
    positions->SetCamera(ren->GetActiveCamera());
  }
  if (pointNormals)
  {
    in.AppendLeafArrays(
      this, "normalMC",
      [](vtkPolyData* leaf, const char*) -> vtkDataArray*
      { return leaf->GetPointData()->GetNormals(); },
      nullptr, appended);
  }
  vbos->AppendDataArray("scalarColor", pointColors, VTK_UNSIGNED_CHAR);
  if (tcoords == 2)
  {
    vbos->AppendDataArray("tcoord", this->ColorCoordinates, VTK_FLOAT);
  }
  else if (tcoords == 1)
  {
    in.AppendLeafArrays(
      this, "tcoord",
      [](vtkPolyData* leaf, const char*) -> vtkDataArray*
      { return leaf->GetPointData()->GetTCoords(); },
      nullptr, appended);
  }
  if (vtkFloatArray::SafeDownCast(skeleton->GetPointData()->GetTangents()))
  {
    in.AppendLeafArrays(
      this, "tangentMC",
      [](vtkPolyData* leaf, const char*) -> vtkDataArray*
      { return leaf->GetPointData()->GetTangents(); },
      nullptr, appended);
  }
  this->UploadLeafBuffers(ren, appended);
}

void vtkMultiresolutionPolyDataMapper::UploadLeafBuffers(
  vtkRenderer* ren, const std::vector<std::pair<std::string, int>>& appended)
{
  // Several blocks per attribute are packed on the CPU and uploaded: the
  // packing vectors are reserved at their size (no growth slack) and freed
  // once uploaded, so that no CPU copy of the vertex data stays.
  Internals& in = *this->Internal;
  vtkOpenGLVertexBufferObjectGroup* vbos = this->VBOs;
  for (const auto& attribute : appended)
  {
    vtkOpenGLVertexBufferObject* vbo = vbos->GetVBO(attribute.first.c_str());
    if (vbo && in.Objects.size() > 1)
    {
      // Floats: a tuple is its components, no padding.
      vbo->GetPackedVBO().reserve(static_cast<size_t>(in.TotalVertices) * attribute.second);
    }
  }
  vbos->BuildAllVBOs(ren);
  for (const auto& attribute : appended)
  {
    if (vtkOpenGLVertexBufferObject* vbo = vbos->GetVBO(attribute.first.c_str()))
    {
      std::vector<float>().swap(vbo->GetPackedVBO());
    }
  }
  vtkOpenGLVertexBufferObject* positions = vbos->GetVBO("vertexMC");
  if (positions && positions->GetCoordShiftAndScaleEnabled())
  {
    const std::vector<double>& shift = positions->GetShift();
    const std::vector<double>& scale = positions->GetScale();
    this->VBOInverseTransform->Identity();
    this->VBOInverseTransform->Translate(shift[0], shift[1], shift[2]);
    this->VBOInverseTransform->Scale(1.0 / scale[0], 1.0 / scale[1], 1.0 / scale[2]);
    this->VBOInverseTransform->GetTranspose(this->VBOShiftScale);
  }
}

void vtkMultiresolutionPolyDataMapper::UpdateCameraShiftScale(vtkRenderer* ren, vtkActor* act)
{
  // Camera-based shift and scale: a new shift needs every leaf's points
  // uploaded again (as VTK re-uploads its input's), so the vertex buffers
  // are rebuilt from the leaves this frame.
  if (this->PauseShiftScale ||
    (this->ShiftScaleMethod != vtkOpenGLVertexBufferObject::NEAR_PLANE_SHIFT_SCALE &&
      this->ShiftScaleMethod != vtkOpenGLVertexBufferObject::FOCAL_POINT_SHIFT_SCALE))
  {
    return;
  }
  vtkOpenGLVertexBufferObject* positions = this->VBOs->GetVBO("vertexMC");
  if (positions && this->CurrentInput)
  {
    positions->SetCamera(ren->GetActiveCamera());
    positions->SetProp3D(act);
    positions->UpdateShiftScale(this->CurrentInput->GetPoints()->GetData());
    if (positions->GetMTime() > positions->GetUploadTime())
    {
      this->VBOBuildState.Clear();
      this->Internal->ForceVertexUpload = true;
    }
  }
}

vtkIdType vtkMultiresolutionPolyDataMapper::GetVertexBufferBuildCount() const
{
  return this->Internal->VertexBufferBuildCount;
}

vtkMTimeType vtkMultiresolutionPolyDataMapper::GetVertexBufferUploadTime(const char* attribute)
{
  vtkOpenGLVertexBufferObject* vbo = attribute ? this->VBOs->GetVBO(attribute) : nullptr;
  return vbo ? static_cast<vtkMTimeType>(vbo->GetUploadTime()) : 0;
}
