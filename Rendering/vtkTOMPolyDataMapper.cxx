// SPDX-License-Identifier: BSD-3-Clause
#include "vtkTOMPolyDataMapper.h"

#include "TOMIndexLayout.h"
#include "TOMMesh.h"
#include "TOMTraversal.h"
#include "vtkTOMFieldData.h"

#include "vtkActor.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLIndexBufferObject.h"
#include "vtkPolyData.h"
#include "vtkPolyDataValidator.h"
#include "vtkProperty.h"

#include <string>
#include <vector>

struct vtkTOMPolyDataMapper::Internals
{
  vtkNew<vtkTOMFieldData> Reader;
  timecritical::TOMTraversal Traversal;
  bool Valid = false;
  bool Warned = false;
  vtkMTimeType ReadTime = 0;
  vtkPolyData* ReadData = nullptr;
  // Index data reused from frame to frame: no allocation once grown.
  std::vector<uint32_t> Triangles;
  std::vector<uint32_t> Expanded;
  // What the index buffer holds now; a change of either needs new indices only.
  double UploadedResolution = -1.0;
  int UploadedRepresentation = -1;
  bool OnlyIndicesChanged = false;
  // The input last checked by vtkPolyDataValidator, and its problem ("" when none).
  vtkPolyData* CheckedData = nullptr;
  vtkMTimeType CheckedTime = 0;
  std::string InputProblem;
};

vtkStandardNewMacro(vtkTOMPolyDataMapper);

vtkTOMPolyDataMapper::vtkTOMPolyDataMapper()
  : Internal(new Internals)
{
}

vtkTOMPolyDataMapper::~vtkTOMPolyDataMapper() = default;

bool vtkTOMPolyDataMapper::GetInputIsTOM() const
{
  return this->Internal->Valid;
}

bool vtkTOMPolyDataMapper::CheckInput()
{
  // VTK's bounds and buffer builders trust the connectivity (a negative id
  // corrupts the heap in vtkPolyData::GetCellsBounds).
  Internals& in = *this->Internal;
  vtkPolyData* input = this->GetInput();
  if (!input)
  {
    return true; // the superclass reports a missing input
  }
  if (input != in.CheckedData || input->GetMTime() != in.CheckedTime)
  {
    in.CheckedData = input;
    in.CheckedTime = input->GetMTime();
    in.InputProblem = vtkPolyDataValidator::Check(input);
    if (!in.InputProblem.empty())
    {
      vtkErrorMacro("Input is not drawn: " << in.InputProblem << ".");
    }
  }
  return in.InputProblem.empty();
}

void vtkTOMPolyDataMapper::ComputeBounds()
{
  if (!this->CheckInput())
  {
    vtkMath::UninitializeBounds(this->Bounds);
    return;
  }
  this->Superclass::ComputeBounds();
}

void vtkTOMPolyDataMapper::RenderPiece(vtkRenderer* ren, vtkActor* act)
{
  if (!this->CheckInput())
  {
    this->RenderedTriangles = 0;
    this->RenderedVertices = 0;
    return;
  }
  this->Superclass::RenderPiece(ren, act);
}

bool vtkTOMPolyDataMapper::GetNeedToRebuildBufferObjects(vtkRenderer* ren, vtkActor* act)
{
  const bool all = this->Superclass::GetNeedToRebuildBufferObjects(ren, act);
  const bool indices = this->Internal->UploadedResolution != this->Resolution ||
    this->Internal->UploadedRepresentation != act->GetProperty()->GetRepresentation();
  this->Internal->OnlyIndicesChanged = !all && indices;
  return all || indices;
}

void vtkTOMPolyDataMapper::BuildBufferObjects(vtkRenderer* ren, vtkActor* act)
{
  if (this->Internal->OnlyIndicesChanged && this->Internal->Valid)
  {
    // Vertex buffers stay as uploaded; only the index buffer changes.
    this->UploadResolution(act);
    return;
  }
  this->Superclass::BuildBufferObjects(ren, act);
}

void vtkTOMPolyDataMapper::BuildIBO(vtkRenderer* ren, vtkActor* act, vtkPolyData* poly)
{
  this->Superclass::BuildIBO(ren, act, poly);
  Internals& in = *this->Internal;
  if (poly != in.ReadData || poly->GetMTime() != in.ReadTime)
  {
    in.ReadData = poly;
    in.ReadTime = poly->GetMTime();
    in.Valid = in.Reader->Read(poly);
    if (in.Valid)
    {
      in.Traversal = timecritical::TOMTraversal(in.Reader->GetMesh());
    }
    else if (!in.Warned)
    {
      vtkWarningMacro(
        "Input is not a valid TOM, rendering it at full resolution: " << in.Reader->GetErrorMessage());
      in.Warned = true;
    }
  }
  this->UploadResolution(act);
}

void vtkTOMPolyDataMapper::UploadResolution(vtkActor* act)
{
  Internals& in = *this->Internal;
  const int representation = act->GetProperty()->GetRepresentation();
  in.UploadedResolution = this->Resolution;
  in.UploadedRepresentation = representation;
  if (!in.Valid)
  {
    this->RenderedTriangles = this->CurrentInput ? this->CurrentInput->GetNumberOfPolys() : 0;
    this->RenderedVertices = this->CurrentInput ? this->CurrentInput->GetNumberOfPoints() : 0;
    return;
  }

  const uint32_t target = in.Traversal.GetTrianglesForResolution(this->Resolution);
  const uint32_t vertexCount = in.Traversal.GetVertexCountForTriangles(target);
  const uint32_t triangles = in.Traversal.Extract(vertexCount, in.Triangles);
  this->RenderedTriangles = triangles;
  this->RenderedVertices = vertexCount;

  // The triangle primitive draws GL_TRIANGLES, GL_LINES or GL_POINTS depending
  // on the representation, so its indices follow the same layout as VTK's.
  const uint32_t* data = in.Triangles.data();
  size_t count = 3 * static_cast<size_t>(triangles);
  if (representation == VTK_WIREFRAME)
  {
    in.Expanded.resize(std::max(in.Expanded.size(), 6 * static_cast<size_t>(triangles)));
    timecritical::WriteTriangleEdges(data, triangles, 0, in.Expanded.data());
    data = in.Expanded.data();
    count = 6 * static_cast<size_t>(triangles);
  }
  else if (representation == VTK_POINTS)
  {
    in.Expanded.resize(std::max<size_t>(in.Expanded.size(), vertexCount));
    timecritical::WriteVertexRange(vertexCount, 0, in.Expanded.data());
    data = in.Expanded.data();
    count = vertexCount;
  }
  vtkOpenGLIndexBufferObject* ibo = this->Primitives[PrimitiveTris].IBO;
  if (count > 0)
  {
    ibo->Upload(data, count, vtkOpenGLBufferObject::ElementArrayBuffer);
  }
  ibo->IndexCount = count;
}

void vtkTOMPolyDataMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "RenderedTriangles: " << this->RenderedTriangles << "\n";
  os << indent << "RenderedVertices: " << this->RenderedVertices << "\n";
  os << indent << "InputIsTOM: " << this->Internal->Valid << "\n";
}
