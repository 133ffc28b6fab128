// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMultiresolutionPolyDataMapper.h"

#include "TOMIndexLayout.h"
#include "TOMMesh.h"
#include "MergeTree.h"
#include "RefinementSettingChecks.h"
#include "TOMTraversal.h"
#include "ViewDependentRefinement.h"
#include "vtkMergeTreeFieldData.h"
#include "vtkTOMFieldData.h"

#include "vtkActor.h"
#include "vtkAppendPolyData.h"
#include "vtkCellArray.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataObjectTreeIterator.h"
#include "vtkFloatArray.h"
#include "vtkHardwareSelector.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLCellToVTKCellMap.h"
#include "vtkOpenGLIndexBufferObject.h"
#include "vtkOpenGLRenderTimer.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLTexture.h"
#include "vtkOpenGLVertexBufferObject.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkScalarsToColors.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkUnsignedCharArray.h"

#include "vtk_glew.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <vector>

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

/// Writes the display vertices of a front (plus base); returns how many.
size_t WriteDisplayVertices(
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

template <typename T>
void Grow(std::vector<T>& v, size_t size)
{
  if (v.size() < size)
  {
    v.resize(size);
  }
}

/**
 * Registers with the render window for the mapper that owns it. VTK's
 * resource-free callback (vtkOpenGLResourceFreeCallback.h) is not installed
 * with ParaView 5.11, so the owner cannot register its own callback, which
 * only vtkOpenGLPolyDataMapper::RenderPiece does, on a vtkPolyData input.
 * This empty polydata mapper registers in its RenderPiece and forwards the
 * window's release (context finalized, or rendering moved to another window)
 * to its owner.
 */
class vtkMultiresolutionReleaseProxy : public vtkOpenGLPolyDataMapper
{
public:
  static vtkMultiresolutionReleaseProxy* New();
  vtkTypeMacro(vtkMultiresolutionReleaseProxy, vtkOpenGLPolyDataMapper);

  vtkMultiresolutionPolyDataMapper* Owner = nullptr;

  void ReleaseGraphicsResources(vtkWindow* window) override
  {
    this->Superclass::ReleaseGraphicsResources(window);
    if (this->Owner)
    {
      this->Owner->ReleaseGraphicsResources(window);
    }
  }

protected:
  vtkMultiresolutionReleaseProxy()
  {
    vtkNew<vtkPolyData> empty; // no points: RenderPiece returns right after registering
    this->SetInputData(empty);
    this->StaticOn();
  }
  ~vtkMultiresolutionReleaseProxy() override = default;

private:
  vtkMultiresolutionReleaseProxy(const vtkMultiresolutionReleaseProxy&) = delete;
  void operator=(const vtkMultiresolutionReleaseProxy&) = delete;
};
vtkStandardNewMacro(vtkMultiresolutionReleaseProxy);
}

struct vtkMultiresolutionPolyDataMapper::Internals
{
  struct Object
  {
    unsigned int FlatIndex = 0;
    bool IsTOM = false;
    timecritical::TOMTraversal Traversal;
    size_t SubstitutionStart = 0; // into Substitution (TOM only)
    size_t TriangleStart = 0;     // into Triangles (TOM) or StaticTriangles (others), in triangles
    uint32_t BaseVertexCount = 0;
    vtkIdType VertexOffset = 0;
    vtkIdType NumberOfVertices = 0;
    vtkIdType PolyOffset = 0; // first of its polygons among the merged polygons
    vtkIdType NumberOfPolys = 0;
    vtkIdType PolyConnectivity = 0;  // point ids of its polygons
    vtkIdType NumberOfTriangles = 0; // at full resolution
    double Bounds[6] = { 1, -1, 1, -1, 1, -1 };
    double Coarsest = 1.0;
    // Leaves with a merge tree: their view-dependent front, and the merge-tree
    // level of each vertex for the resolution map.
    std::unique_ptr<timecritical::ViewDependentRefinement> Refinement;
    std::vector<uint16_t> Levels;
    uint16_t LevelCount = 0;
    vtkIdType Splits = 0;
    vtkIdType Merges = 0;
    double RefinementTime = 0.0;
    // Measured splits + merges per second of this front (time-limited budgets).
    double OperationsPerSecond = 0.0;
    // Grows while a time-limited step is too small for the next split (whose
    // forced splits overshoot it), so that the front never stalls short of its budget.
    double StepScale = 1.0;
    double Resolution = 1.0;
    vtkIdType RenderedTriangles = 0;
    vtkIdType RenderedVertices = 0;
    int ColorLevel = -1;     // level written into ResolutionColors, -1 = none yet
    bool ColorDirty = false; // ResolutionColors of its vertices not yet on the GPU
  };

  std::vector<Object> Objects;
  // What the objects were read from; every leaf is held so that its address
  // cannot be reused by another object while we compare modification times.
  vtkSmartPointer<vtkDataObject> Input;
  vtkMTimeType InputTime = 0;
  std::vector<std::pair<vtkSmartPointer<vtkDataObject>, vtkMTimeType>> Watched;

  vtkNew<vtkTOMFieldData> Reader;
  vtkNew<vtkMergeTreeFieldData> TreeReader;
  // TOM arrays of all TOM objects (leaf point ids); the traversals view them.
  std::vector<uint32_t> Substitution;
  std::vector<uint32_t> Triangles;
  // Surface triangles of the non-TOM objects (merged point ids, degenerate
  // ones dropped as VTK does) and the polygon each comes from.
  std::vector<uint32_t> StaticTriangles;
  std::vector<uint32_t> StaticTriangleCells;

  vtkSmartPointer<vtkPolyData> Merged;
  vtkIdType PolyCellBase = 0; // cell id of the first merged polygon (verts and lines come first)
  bool MergedHasOtherCells = false;
  vtkIdType MaxObjectTriangles = 0;
  size_t MaxSurfaceIndices = 0;
  size_t MaxWireIndices = 0;
  size_t MaxPointIndices = 0;
  vtkIdType TotalVertices = 0;

  // Bumped by any resolution change; the index buffer follows it.
  unsigned long ResolutionVersion = 0;
  unsigned long UploadedVersion = ~0ul;
  bool OnlyIndicesChanged = false;

  // Grow-only buffers: no allocation from frame to frame once grown.
  std::vector<uint32_t> Indices;
  size_t IndexCount = 0;
  std::vector<uint32_t> Scratch;
  std::vector<uint32_t> VertexIndices;
  std::vector<vtkIdType> PrimitiveCells;
  std::vector<unsigned char> CellColors;
  std::vector<float> CellNormals;
  std::vector<unsigned char> CellNormalBytes;

  vtkSmartPointer<vtkUnsignedCharArray> ResolutionColors;
  bool ColorsAreResolutionMap = false; // this->Colors is a resolution map

  vtkNew<vtkMultiresolutionReleaseProxy> ReleaseProxy;
  vtkOpenGLRenderWindow* Window = nullptr; // holds our GL resources; cleared on release

  bool WarnedNonTOM = false;
  bool WarnedBadTree = false;
  bool WarnedNonPolyData = false;
  vtkIdType VertexBufferBuildCount = 0;
  vtkIdType IndexBufferBuildCount = 0;
};

vtkStandardNewMacro(vtkMultiresolutionPolyDataMapper);

vtkMultiresolutionPolyDataMapper::vtkMultiresolutionPolyDataMapper()
  : Internal(new Internals)
{
  this->Internal->ReleaseProxy->Owner = this;
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
  this->TimerQuery->ReleaseGraphicsResources();
  window->PopContext();
  this->VBOBuildState.Clear();
  this->IBOBuildState.Clear();
  this->CellTextureBuildState.Clear();
  in.UploadedVersion = ~0ul;
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
void vtkMultiresolutionPolyDataMapper::UpdateObjects()
{
  Internals& in = *this->Internal;
  if (this->GetNumberOfInputConnections(0) < 1)
  {
    if (in.Input)
    {
      this->ReadObjects(nullptr);
    }
    return;
  }
  if (!this->Static)
  {
    int port = 0;
    if (vtkAlgorithm* producer = this->GetInputAlgorithm(0, 0, port))
    {
      producer->Update(port);
    }
  }
  vtkDataObject* input = this->GetInputDataObject(0, 0);
  bool changed = input != in.Input || (input && input->GetMTime() != in.InputTime);
  for (size_t i = 0; !changed && i < in.Watched.size(); ++i)
  {
    changed = in.Watched[i].first->GetMTime() != in.Watched[i].second;
  }
  if (changed)
  {
    this->ReadObjects(input);
  }
}

//------------------------------------------------------------------------------
void vtkMultiresolutionPolyDataMapper::ReadObjects(vtkDataObject* input)
{
  Internals& in = *this->Internal;
  std::vector<double> previous(in.Objects.size());
  for (size_t i = 0; i < in.Objects.size(); ++i)
  {
    previous[i] = in.Objects[i].Resolution;
  }
  in.Objects.clear();
  in.Watched.clear();
  in.Substitution.clear();
  in.Triangles.clear();
  in.StaticTriangles.clear();
  in.StaticTriangleCells.clear();
  in.Merged = nullptr;
  in.Input = input;
  in.InputTime = input ? input->GetMTime() : 0;
  ++in.ResolutionVersion;

  // Leaves in composite iteration order, the order vtkCellPicker reports.
  std::vector<std::pair<vtkPolyData*, unsigned int>> leaves;
  if (auto poly = vtkPolyData::SafeDownCast(input))
  {
    leaves.emplace_back(poly, 0u);
  }
  else if (auto composite = vtkCompositeDataSet::SafeDownCast(input))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(composite->NewIterator());
    it->SkipEmptyNodesOn();
    // Inner nodes are watched too: setting a block of a nested multiblock
    // modifies that node only, not the root.
    if (auto tree = vtkDataObjectTreeIterator::SafeDownCast(it))
    {
      tree->VisitOnlyLeavesOff();
    }
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      vtkDataObject* leaf = it->GetCurrentDataObject();
      in.Watched.emplace_back(leaf, leaf->GetMTime());
      if (vtkCompositeDataSet::SafeDownCast(leaf))
      {
        continue;
      }
      if (auto leafPoly = vtkPolyData::SafeDownCast(leaf))
      {
        leaves.emplace_back(leafPoly, it->GetCurrentFlatIndex());
      }
      else if (!in.WarnedNonPolyData)
      {
        vtkWarningMacro("Block " << it->GetCurrentFlatIndex() << " is a " << leaf->GetClassName()
                                 << ", not a vtkPolyData: it is not drawn.");
        in.WarnedNonPolyData = true;
      }
    }
  }

  std::vector<vtkPolyData*> parts;
  vtkIdType vertexOffset = 0;
  vtkIdType polyOffset = 0;
  in.MaxObjectTriangles = 0;
  in.MaxSurfaceIndices = in.MaxWireIndices = in.MaxPointIndices = 0;
  for (const auto& leaf : leaves)
  {
    vtkPolyData* poly = leaf.first;
    if (poly->GetNumberOfPoints() < 1)
    {
      continue; // empty leaf: not an object
    }
    if (poly->GetNumberOfPoints() > static_cast<vtkIdType>(UINT32_MAX) - vertexOffset)
    {
      vtkErrorMacro("More than 2^32 points in all leaves; the rest are not drawn.");
      break;
    }
    Internals::Object object;
    object.FlatIndex = leaf.second;
    object.VertexOffset = vertexOffset;
    object.NumberOfVertices = poly->GetNumberOfPoints();
    object.PolyOffset = polyOffset;
    object.NumberOfPolys = poly->GetNumberOfPolys();
    object.PolyConnectivity = poly->GetPolys()->GetNumberOfConnectivityIds();
    if (poly->GetNumberOfCells() > 0)
    {
      poly->GetCellsBounds(object.Bounds);
    }
    else
    {
      poly->GetBounds(object.Bounds);
    }
    object.IsTOM = in.Reader->Read(poly);
    if (object.IsTOM)
    {
      const timecritical::TOMMesh& mesh = in.Reader->GetMesh();
      object.SubstitutionStart = in.Substitution.size();
      object.TriangleStart = in.Triangles.size() / 3;
      object.BaseVertexCount = mesh.BaseVertexCount;
      in.Substitution.insert(
        in.Substitution.end(), mesh.Substitution.begin(), mesh.Substitution.end());
      in.Triangles.insert(in.Triangles.end(), mesh.Triangles.begin(), mesh.Triangles.end());
      object.NumberOfTriangles = mesh.GetNumberOfTriangles();
      object.Coarsest = object.NumberOfTriangles > 0
        ? static_cast<double>(mesh.BaseTriangleCount) / object.NumberOfTriangles
        : 1.0;
    }
    else
    {
      if (!in.WarnedNonTOM)
      {
        vtkWarningMacro("Block " << object.FlatIndex
                                 << " is not a valid TOM, rendering it at full resolution: "
                                 << in.Reader->GetErrorMessage());
        in.WarnedNonTOM = true;
      }
      // Fan triangles in merged point ids, dropping those with coincident
      // points as VTK's own index buffers do, so that primitive ids (and cell
      // colors) line up with VTK's cell map.
      object.TriangleStart = in.StaticTriangles.size() / 3;
      vtkPoints* points = poly->GetPoints();
      vtkCellArray* polys = poly->GetPolys();
      vtkIdType npts = 0;
      const vtkIdType* ids = nullptr;
      double p0[3], p1[3], p2[3];
      auto same = [](const double* a, const double* b)
      { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; };
      for (vtkIdType c = 0; c < object.NumberOfPolys; ++c)
      {
        polys->GetCellAtId(c, npts, ids);
        for (vtkIdType i = 2; i < npts; ++i)
        {
          points->GetPoint(ids[0], p0);
          points->GetPoint(ids[i - 1], p1);
          points->GetPoint(ids[i], p2);
          if (same(p0, p1) || same(p1, p2) || same(p0, p2))
          {
            continue;
          }
          in.StaticTriangles.push_back(static_cast<uint32_t>(ids[0] + vertexOffset));
          in.StaticTriangles.push_back(static_cast<uint32_t>(ids[i - 1] + vertexOffset));
          in.StaticTriangles.push_back(static_cast<uint32_t>(ids[i] + vertexOffset));
          in.StaticTriangleCells.push_back(static_cast<uint32_t>(c));
        }
      }
      object.NumberOfTriangles = static_cast<vtkIdType>(in.StaticTriangles.size() / 3) -
        static_cast<vtkIdType>(object.TriangleStart);
    }
    if (object.IsTOM && vtkMergeTreeFieldData::HasMergeTreeArrays(poly))
    {
      if (in.TreeReader->Read(poly))
      {
        // The refinement keeps its own copy of the points (float, as drawn).
        const timecritical::MergeTree& tree = in.TreeReader->GetTree();
        const vtkIdType count = poly->GetNumberOfPoints();
        std::vector<float> xyz(3 * static_cast<size_t>(count));
        vtkDataArray* coordinates = poly->GetPoints()->GetData();
        for (vtkIdType p = 0; p < count; ++p)
        {
          for (int k = 0; k < 3; ++k)
          {
            xyz[3 * p + k] = static_cast<float>(coordinates->GetComponent(p, k));
          }
        }
        try
        {
          object.Refinement = std::make_unique<timecritical::ViewDependentRefinement>();
          object.Refinement->Initialize(in.TreeReader->GetMesh(), tree, xyz.data());
          object.Levels = tree.Level;
          object.LevelCount = tree.LevelCount;
        }
        catch (const std::exception& e)
        {
          object.Refinement.reset();
          vtkWarningMacro("Block " << object.FlatIndex << ": merge tree not usable (" << e.what()
                                   << "); drawing it as a TOM.");
        }
      }
      else if (!in.WarnedBadTree)
      {
        vtkWarningMacro("Block " << object.FlatIndex << " has invalid merge-tree arrays, drawing it "
                                 << "as a TOM: " << in.TreeReader->GetErrorMessage());
        in.WarnedBadTree = true;
      }
    }
    in.MaxObjectTriangles = std::max(in.MaxObjectTriangles, object.NumberOfTriangles);
    in.MaxSurfaceIndices += 3 * static_cast<size_t>(object.NumberOfTriangles);
    in.MaxWireIndices += object.IsTOM ? 6 * static_cast<size_t>(object.NumberOfTriangles)
                                      : 2 * static_cast<size_t>(object.PolyConnectivity);
    in.MaxPointIndices += object.IsTOM ? std::max(3 * static_cast<size_t>(object.NumberOfTriangles),
                                           static_cast<size_t>(object.NumberOfVertices))
                                       : static_cast<size_t>(object.PolyConnectivity);
    const size_t index = in.Objects.size();
    object.Resolution = index < previous.size() ? previous[index] : 1.0;
    vertexOffset += object.NumberOfVertices;
    polyOffset += object.NumberOfPolys;
    parts.push_back(poly);
    in.Objects.push_back(std::move(object));
  }
  in.TotalVertices = vertexOffset;

  // Views into the TOM arrays, now that they no longer move.
  for (auto& object : in.Objects)
  {
    if (object.IsTOM)
    {
      object.Traversal =
        timecritical::TOMTraversal(in.Substitution.data() + object.SubstitutionStart,
          static_cast<uint32_t>(object.NumberOfVertices),
          in.Triangles.data() + 3 * object.TriangleStart,
          static_cast<uint32_t>(object.NumberOfTriangles), object.BaseVertexCount);
    }
  }
  // The traversal writes batches in place and may use the output as scratch.
  Grow(in.Scratch, 3 * static_cast<size_t>(in.MaxObjectTriangles));

  // One polydata for the superclass's vertex buffers: leaf points in order,
  // leaf cells in order (vtkAppendPolyData keeps the arrays common to all leaves).
  if (parts.size() == 1)
  {
    in.Merged = vtkSmartPointer<vtkPolyData>::New();
    in.Merged->ShallowCopy(parts[0]);
  }
  else if (parts.size() > 1)
  {
    in.Merged = vtkSmartPointer<vtkPolyData>::New();
    vtkNew<vtkAppendPolyData> append;
    append->ExecuteAppend(in.Merged, parts.data(), static_cast<int>(parts.size()));
  }
  in.PolyCellBase = in.Merged ? in.Merged->GetNumberOfVerts() + in.Merged->GetNumberOfLines() : 0;
  in.MergedHasOtherCells = in.Merged &&
    (in.Merged->GetNumberOfVerts() || in.Merged->GetNumberOfLines() ||
      in.Merged->GetNumberOfStrips());
  in.ResolutionColors = nullptr;
}

//------------------------------------------------------------------------------
vtkIdType vtkMultiresolutionPolyDataMapper::GetNumberOfObjects() const
{
  return static_cast<vtkIdType>(this->Internal->Objects.size());
}

void vtkMultiresolutionPolyDataMapper::SetObjectResolution(vtkIdType i, double r)
{
  if (!this->IsValidObject(i))
  {
    return;
  }
  if (std::isnan(r))
  {
    vtkErrorMacro("Resolution of object " << i << " is NaN; ignored.");
    return;
  }
  r = std::min(1.0, std::max(0.0, r));
  // Resolutions are per-frame render state: they change the index buffer
  // only, so they do not Modified() the mapper (that would rebuild every
  // buffer and recompile the shaders).
  Internals::Object& object = this->Internal->Objects[i];
  if (object.Resolution != r)
  {
    object.Resolution = r;
    ++this->Internal->ResolutionVersion;
  }
}

double vtkMultiresolutionPolyDataMapper::GetObjectResolution(vtkIdType i) const
{
  return this->IsValidObject(i) ? this->Internal->Objects[i].Resolution : 0.0;
}

void vtkMultiresolutionPolyDataMapper::SetResolution(double r)
{
  if (std::isnan(r))
  {
    vtkErrorMacro("Resolution is NaN; ignored.");
    return;
  }
  for (vtkIdType i = 0; i < this->GetNumberOfObjects(); ++i)
  {
    this->SetObjectResolution(i, r);
  }
}

void vtkMultiresolutionPolyDataMapper::SetObjectResolutions(const double* r, vtkIdType n)
{
  if (n != this->GetNumberOfObjects() || (n > 0 && !r))
  {
    vtkErrorMacro("SetObjectResolutions needs " << this->GetNumberOfObjects() << " values, got "
                                                << n << "; ignored.");
    return;
  }
  bool nan = false;
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (std::isnan(r[i]))
    {
      nan = true;
      continue;
    }
    this->SetObjectResolution(i, r[i]);
  }
  if (nan)
  {
    vtkErrorMacro("NaN resolutions were ignored.");
  }
}

bool vtkMultiresolutionPolyDataMapper::IsValidObject(vtkIdType i) const
{
  if (i < 0 || i >= this->GetNumberOfObjects())
  {
    vtkErrorMacro(
      "Object index " << i << " out of range [0, " << this->GetNumberOfObjects() << ").");
    return false;
  }
  return true;
}

void vtkMultiresolutionPolyDataMapper::GetObjectBounds(vtkIdType i, double bounds[6]) const
{
  if (!this->IsValidObject(i))
  {
    vtkMath::UninitializeBounds(bounds);
    return;
  }
  std::copy(this->Internal->Objects[i].Bounds, this->Internal->Objects[i].Bounds + 6, bounds);
}

vtkIdType vtkMultiresolutionPolyDataMapper::GetObjectNumberOfTriangles(vtkIdType i) const
{
  return this->IsValidObject(i) ? this->Internal->Objects[i].NumberOfTriangles : 0;
}

vtkIdType vtkMultiresolutionPolyDataMapper::GetObjectNumberOfVertices(vtkIdType i) const
{
  return this->IsValidObject(i) ? this->Internal->Objects[i].NumberOfVertices : 0;
}

double vtkMultiresolutionPolyDataMapper::GetObjectCoarsestResolution(vtkIdType i) const
{
  return this->IsValidObject(i) ? this->Internal->Objects[i].Coarsest : 1.0;
}

bool vtkMultiresolutionPolyDataMapper::GetObjectIsTOM(vtkIdType i) const
{
  return this->IsValidObject(i) && this->Internal->Objects[i].IsTOM;
}

unsigned int vtkMultiresolutionPolyDataMapper::GetObjectFlatIndex(vtkIdType i) const
{
  return this->IsValidObject(i) ? this->Internal->Objects[i].FlatIndex : 0u;
}

namespace
{
/// Sets a refinement setting as render state: the fronts and the index buffer
/// follow it (version bump), the vertex buffers and shaders do not.
template <typename T>
void SetRenderState(T& member, T value, unsigned long& version)
{
  if (member != value)
  {
    member = value;
    ++version;
  }
}
}

void vtkMultiresolutionPolyDataMapper::SetViewDependentRefinement(bool on)
{
  SetRenderState(this->ViewDependentRefinement, on, this->Internal->ResolutionVersion);
}

void vtkMultiresolutionPolyDataMapper::SetRefinementMode(int mode)
{
  SetRenderState(this->RefinementMode, std::min(std::max(mode, static_cast<int>(BUDGET)),
    static_cast<int>(FIXED_ACCURACY)), this->Internal->ResolutionVersion);
}

void vtkMultiresolutionPolyDataMapper::SetBackFaceSimplification(bool on)
{
  SetRenderState(this->BackFaceSimplification, on, this->Internal->ResolutionVersion);
}

void vtkMultiresolutionPolyDataMapper::SetSilhouetteRefinement(bool on)
{
  SetRenderState(this->SilhouetteRefinement, on, this->Internal->ResolutionVersion);
}

void vtkMultiresolutionPolyDataMapper::SetHighlightRefinement(bool on)
{
  SetRenderState(this->HighlightRefinement, on, this->Internal->ResolutionVersion);
}

void vtkMultiresolutionPolyDataMapper::SetPixelThreshold(double tau)
{
  if (timecritical::CheckNonNegativeSetting(this, "PixelThreshold", tau))
  {
    SetRenderState(this->PixelThreshold, tau, this->Internal->ResolutionVersion);
  }
}

void vtkMultiresolutionPolyDataMapper::SetRefinementTimeLimit(double seconds)
{
  if (timecritical::CheckNonNegativeSetting(this, "RefinementTimeLimit", seconds))
  {
    SetRenderState(this->RefinementTimeLimit, seconds, this->Internal->ResolutionVersion);
  }
}

void vtkMultiresolutionPolyDataMapper::SetSilhouetteFactor(double factor)
{
  if (timecritical::CheckFactorSetting(this, "SilhouetteFactor", factor))
  {
    this->SilhouetteFactor = factor;
  }
}

void vtkMultiresolutionPolyDataMapper::SetHighlightFactor(double factor)
{
  if (timecritical::CheckFactorSetting(this, "HighlightFactor", factor))
  {
    this->HighlightFactor = factor;
  }
}

vtkIdType vtkMultiresolutionPolyDataMapper::GetObjectRenderedVertices(vtkIdType i) const
{
  return this->IsValidObject(i) ? this->Internal->Objects[i].RenderedVertices : 0;
}

bool vtkMultiresolutionPolyDataMapper::GetObjectIsViewDependent(vtkIdType i) const
{
  return this->IsValidObject(i) && this->ViewDependentRefinement &&
    this->Internal->Objects[i].Refinement != nullptr;
}

vtkIdType vtkMultiresolutionPolyDataMapper::GetObjectSplits(vtkIdType i) const
{
  return this->IsValidObject(i) ? this->Internal->Objects[i].Splits : 0;
}

vtkIdType vtkMultiresolutionPolyDataMapper::GetObjectMerges(vtkIdType i) const
{
  return this->IsValidObject(i) ? this->Internal->Objects[i].Merges : 0;
}

double vtkMultiresolutionPolyDataMapper::GetObjectRefinementTime(vtkIdType i) const
{
  return this->IsValidObject(i) ? this->Internal->Objects[i].RefinementTime : 0.0;
}

vtkIdType vtkMultiresolutionPolyDataMapper::GetObjectRenderedTriangles(vtkIdType i) const
{
  return this->IsValidObject(i) ? this->Internal->Objects[i].RenderedTriangles : 0;
}

vtkIdType vtkMultiresolutionPolyDataMapper::GetObjectVertexOffset(vtkIdType i) const
{
  return this->IsValidObject(i) ? this->Internal->Objects[i].VertexOffset : -1;
}

vtkIdType vtkMultiresolutionPolyDataMapper::GetVertexBufferBuildCount() const
{
  return this->Internal->VertexBufferBuildCount;
}

vtkIdType vtkMultiresolutionPolyDataMapper::GetIndexBufferBuildCount() const
{
  return this->Internal->IndexBufferBuildCount;
}

vtkMTimeType vtkMultiresolutionPolyDataMapper::GetVertexBufferUploadTime(const char* attribute)
{
  vtkOpenGLVertexBufferObject* vbo = attribute ? this->VBOs->GetVBO(attribute) : nullptr;
  return vbo ? static_cast<vtkMTimeType>(vbo->GetUploadTime()) : 0;
}

vtkIdType vtkMultiresolutionPolyDataMapper::GetLastIndexCount() const
{
  return static_cast<vtkIdType>(this->Internal->IndexCount);
}

const unsigned int* vtkMultiresolutionPolyDataMapper::GetLastIndices() const
{
  return this->Internal->Indices.data();
}

//------------------------------------------------------------------------------
void vtkMultiresolutionPolyDataMapper::ComputeBounds()
{
  Internals& in = *this->Internal;
  vtkMath::UninitializeBounds(this->Bounds);
  bool first = true;
  for (const auto& object : in.Objects)
  {
    if (!vtkMath::AreBoundsInitialized(object.Bounds))
    {
      continue;
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
    return this->Colors;
  }
  if (in.ColorsAreResolutionMap)
  {
    // Leaving the resolution map: never let the superclass reuse its colors.
    if (this->Colors)
    {
      this->Colors->UnRegister(this);
      this->Colors = nullptr;
    }
    in.ColorsAreResolutionMap = false;
  }
  vtkDataSet* data = in.Merged ? static_cast<vtkDataSet*>(in.Merged) : this->GetInput();
  return this->Superclass::MapScalars(data, alpha, cellFlag);
}

bool vtkMultiresolutionPolyDataMapper::HasTranslucentPolygonalGeometry()
{
  Internals& in = *this->Internal;
  if (this->ColorByResolution || !this->ScalarVisibility || !in.Merged)
  {
    return false;
  }
  int cellFlag = 0;
  vtkAbstractArray* scalars = vtkAbstractMapper::GetAbstractScalars(
    in.Merged, this->ScalarMode, this->ArrayAccessMode, this->ArrayId, this->ArrayName, cellFlag);
  if (!scalars)
  {
    return false;
  }
  unsigned char ghostsToSkip = 0;
  vtkUnsignedCharArray* ghosts =
    vtkAbstractMapper::GetGhostArray(in.Merged, this->ScalarMode, ghostsToSkip);
  vtkScalarsToColors* lut = this->GetLookupTable();
  lut->Build();
  return lut->IsOpaque(scalars, this->ColorMode, this->ArrayComponent, ghosts, ghostsToSkip) == 0;
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

  this->CurrentInput = in.Merged;
  if (!in.Merged || !in.Merged->GetPoints())
  {
    // Nothing to draw (empty input or no polydata leaf).
    this->RenderedTriangles = 0;
    this->RenderedVertices = 0;
    for (auto& object : in.Objects)
    {
      object.RenderedTriangles = 0;
      object.RenderedVertices = 0;
    }
    return;
  }

  this->RefineObjects(ren, act);
  this->NumberOfRewrittenObjects = 0;
  this->IndexBytesUploaded = 0;
  this->CellDataBytesUploaded = 0;
  this->IndexUpdateTime = 0.0;

  // As vtkOpenGLPolyDataMapper::RenderPiece, on the merged leaves.
  this->UpdateCameraShiftScale(ren, act);
  this->RenderPieceStart(ren, act);
  this->RenderPieceDraw(ren, act);
  this->RenderPieceFinish(ren, act);

  // Draw calls made by RenderPieceDraw: one per non-empty primitive type.
  const bool edges = act->GetProperty()->GetEdgeVisibility() &&
    act->GetProperty()->GetRepresentation() == VTK_SURFACE && !ren->GetSelector();
  const int last = edges ? PrimitiveEnd : PrimitiveTriStrips + 1;
  for (int i = PrimitiveStart; i < last; ++i)
  {
    this->NumberOfDrawCalls += this->Primitives[i].IBO->IndexCount > 0;
    this->NumberOfDrawCalls += this->SelectionPrimitives[i].IBO->IndexCount > 0;
  }
}

//------------------------------------------------------------------------------
void vtkMultiresolutionPolyDataMapper::RefineObjects(vtkRenderer* ren, vtkActor* act)
{
  Internals& in = *this->Internal;
  this->RefinementTime = 0.0;
  bool any = false;
  for (auto& object : in.Objects)
  {
    object.Splits = object.Merges = 0;
    object.RefinementTime = 0.0;
    any = any || (object.Refinement && object.Resolution > 0.0);
  }
  if (!any || !this->ViewDependentRefinement)
  {
    return;
  }

  // The view in the leaves' own coordinates (all share the actor's matrix).
  double toObject[16];
  vtkMatrix4x4::Invert(act->GetMatrix()->GetData(), toObject);
  auto point = [&](const double w[3], double o[3])
  {
    for (int r = 0; r < 3; ++r)
    {
      o[r] = toObject[4 * r] * w[0] + toObject[4 * r + 1] * w[1] + toObject[4 * r + 2] * w[2] +
        toObject[4 * r + 3];
    }
  };
  auto direction = [&](const double w[3], double o[3])
  {
    for (int r = 0; r < 3; ++r)
    {
      o[r] = toObject[4 * r] * w[0] + toObject[4 * r + 1] * w[1] + toObject[4 * r + 2] * w[2];
    }
    vtkMath::Normalize(o);
  };
  vtkCamera* camera = ren->GetActiveCamera();
  timecritical::RefinementView view;
  point(camera->GetPosition(), view.Eye);
  direction(camera->GetDirectionOfProjection(), view.Direction);
  view.Parallel = camera->GetParallelProjection() != 0;
  int width = 0, height = 0;
  ren->GetTiledSize(&width, &height);
  view.ViewportHeight = std::max(height, 1);
  view.ViewAngle = camera->GetViewAngle();
  if (camera->GetUseHorizontalViewAngle() && width > 0 && height > 0)
  {
    // The projected error needs the vertical angle; a horizontal one spans the width.
    const double half = 0.5 * vtkMath::RadiansFromDegrees(view.ViewAngle);
    view.ViewAngle = 2.0 *
      vtkMath::DegreesFromRadians(std::atan(std::tan(half) * static_cast<double>(height) / width));
  }
  // World lengths to object lengths: the actor's uniform scale (cube root of
  // the determinant for the rare non-uniform case).
  const double scale = std::cbrt(std::abs(act->GetMatrix()->Determinant()));
  view.ParallelScale = camera->GetParallelScale() / (scale > 0.0 ? scale : 1.0);
  // Nothing nearer than the near plane is drawn: a node around the eye is
  // projected from there instead of with an unbounded error.
  view.NearDistance = camera->GetClippingRange()[0] / (scale > 0.0 ? scale : 1.0);
  // Frustum planes from the world-to-clip matrix the draw uses (cached by the
  // camera until it changes; vtkCamera::GetFrustumPlanes() would rebuild a
  // transform concatenation, allocating, at every call). vtkOpenGLCamera
  // keeps it transposed: row r of the clip matrix is column r of wcdc.
  double planes[24];
  if (auto* glCamera = vtkOpenGLCamera::SafeDownCast(camera))
  {
    vtkMatrix4x4 *wcvc = nullptr, *vcdc = nullptr, *wcdc = nullptr;
    vtkMatrix3x3* normals = nullptr;
    glCamera->GetKeyMatrices(ren, wcvc, normals, vcdc, wcdc);
    // Left, right, bottom, top, near, far: w +- x, w +- y, w +- z >= 0 inside.
    for (int i = 0; i < 6; ++i)
    {
      const int axis = i / 2;
      const double sign = i % 2 == 0 ? 1.0 : -1.0;
      for (int c = 0; c < 4; ++c)
      {
        planes[4 * i + c] = wcdc->GetElement(c, 3) + sign * wcdc->GetElement(c, axis);
      }
    }
  }
  else
  {
    camera->GetFrustumPlanes(ren->GetTiledAspectRatio(), planes);
  }
  const double* model = act->GetMatrix()->GetData();
  view.NumberOfFrustumPlanes = 6;
  for (int i = 0; i < 6; ++i)
  {
    // A plane p (world) is p M in object coordinates; renormalized so that
    // distances stay in object units.
    double* o = view.FrustumPlanes[i];
    for (int c = 0; c < 4; ++c)
    {
      o[c] = planes[4 * i] * model[c] + planes[4 * i + 1] * model[4 + c] +
        planes[4 * i + 2] * model[8 + c] + planes[4 * i + 3] * model[12 + c];
    }
    const double norm = std::sqrt(o[0] * o[0] + o[1] * o[1] + o[2] * o[2]);
    for (int c = 0; c < 4; ++c)
    {
      o[c] = norm > 0.0 ? o[c] / norm : 0.0;
    }
  }
  // Towards the first switched-on light; a headlight when there is none.
  double toLight[3] = { -view.Direction[0], -view.Direction[1], -view.Direction[2] };
  vtkLightCollection* lights = ren->GetLights();
  vtkCollectionSimpleIterator it;
  lights->InitTraversal(it);
  while (vtkLight* light = lights->GetNextLight(it))
  {
    if (light->GetSwitch())
    {
      double position[3], focal[3], world[3];
      light->GetTransformedPosition(position);
      light->GetTransformedFocalPoint(focal);
      for (int k = 0; k < 3; ++k)
      {
        world[k] = position[k] - focal[k];
      }
      if (vtkMath::Norm(world) > 0.0)
      {
        direction(world, toLight);
      }
      break;
    }
  }
  std::copy(toLight, toLight + 3, view.LightDirection);

  // The time limit is shared by the fronts drawn this render.
  int fronts = 0;
  for (const auto& object : in.Objects)
  {
    fronts += object.Refinement && object.Resolution > 0.0;
  }
  const double limit = this->RefinementTimeLimit / std::max(fronts, 1);

  bool changed = false;
  for (auto& object : in.Objects)
  {
    if (!object.Refinement || !(object.Resolution > 0.0))
    {
      continue; // culled objects keep their front for when they come back
    }
    timecritical::ViewDependentRefinement& front = *object.Refinement;
    front.SetView(view);
    front.SetPixelThreshold(this->PixelThreshold);
    front.SetBackFaceSimplification(this->BackFaceSimplification);
    front.SetSilhouetteRefinement(this->SilhouetteRefinement);
    front.SetSilhouetteFactor(this->SilhouetteFactor);
    front.SetHighlightRefinement(this->HighlightRefinement);
    front.SetHighlightFactor(this->HighlightFactor);
    double budget = std::min<double>(
      std::lround(object.Resolution * object.NumberOfTriangles), object.NumberOfTriangles);
    bool limited = false;
    if (limit > 0.0)
    {
      // A split or a merge changes about two triangles; until a rate is
      // measured, assume 2 us per operation (llvmpipe-class machines).
      const double rate = object.OperationsPerSecond > 0.0 ? object.OperationsPerSecond : 5e5;
      const double step = object.StepScale * (2.0 * limit * rate + 64.0);
      const double current = front.GetNumberOfDisplayTriangles();
      const double wanted = budget;
      budget = std::min(std::max(budget, current - step), current + step);
      limited = budget != wanted;
    }
    const auto start = std::chrono::steady_clock::now();
    const timecritical::RefinementStatistics& statistics = this->RefinementMode == FIXED_ACCURACY
      ? front.UpdateFixedAccuracy()
      // The step keeps the work near the limit; the core's own deadline
      // (twice the limit, at least 2 ms so that every update makes progress)
      // stops what the measured rate did not foresee.
      : front.UpdateBudget(static_cast<uint32_t>(std::max(budget, 0.0)),
          limit > 0.0 ? std::max(2.0 * limit, 2e-3) : 0.0);
    object.RefinementTime =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double operations = static_cast<double>(statistics.Splits) + statistics.Merges;
    if (operations > 0)
    {
      object.StepScale = 1.0;
    }
    else if (limited)
    {
      object.StepScale = std::min(2.0 * object.StepScale, 1e6);
    }
    if (operations >= 256 && object.RefinementTime > 0.0)
    {
      // Smoothed: one slow frame (a page fault, another process) must not
      // freeze the front.
      const double measured = operations / object.RefinementTime;
      object.OperationsPerSecond = object.OperationsPerSecond > 0.0
        ? 0.7 * object.OperationsPerSecond + 0.3 * measured
        : measured;
    }
    object.Splits = statistics.Splits;
    object.Merges = statistics.Merges;
    this->RefinementTime += object.RefinementTime;
    changed = changed || statistics.Splits > 0 || statistics.Merges > 0;
  }
  if (changed)
  {
    ++in.ResolutionVersion; // the index buffer follows the fronts
  }
}

//------------------------------------------------------------------------------
bool vtkMultiresolutionPolyDataMapper::GetNeedToRebuildBufferObjects(
  vtkRenderer* ren, vtkActor* act)
{
  Internals& in = *this->Internal;
  const bool all = this->Superclass::GetNeedToRebuildBufferObjects(ren, act);
  const bool indices = in.UploadedVersion != in.ResolutionVersion;
  in.OnlyIndicesChanged = !all && indices;
  return all || indices;
}

void vtkMultiresolutionPolyDataMapper::BuildBufferObjects(vtkRenderer* ren, vtkActor* act)
{
  Internals& in = *this->Internal;
  if (in.OnlyIndicesChanged)
  {
    // Vertex buffers stay as uploaded; only the index buffer changes.
    in.OnlyIndicesChanged = false;
    this->FillIndexBuffer(ren, act);
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
  this->Superclass::BuildBufferObjects(ren, act);
  this->ScalarVisibility = scalarVisibility;
  ++in.VertexBufferBuildCount;
}

void vtkMultiresolutionPolyDataMapper::BuildCellTextures(
  vtkRenderer*, vtkActor*, vtkCellArray* prims[4], int representation)
{
  // Only the cell map here, and only for the vertices, lines and strips of
  // non-TOM leaves: the textures follow the drawn primitives and are uploaded
  // with the index buffer (UploadCellTextures).
  if ((this->HaveCellScalars || this->HaveCellNormals) && this->Internal->MergedHasOtherCells)
  {
    this->CellCellMap->Update(prims, representation, this->CurrentInput->GetPoints());
  }
}

void vtkMultiresolutionPolyDataMapper::BuildIBO(vtkRenderer* ren, vtkActor* act, vtkPolyData* poly)
{
  if (this->Internal->MergedHasOtherCells)
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
  this->FillIndexBuffer(ren, act);
}

//------------------------------------------------------------------------------
void vtkMultiresolutionPolyDataMapper::FillIndexBuffer(vtkRenderer* ren, vtkActor* act)
{
  Internals& in = *this->Internal;
  const auto startTime = std::chrono::steady_clock::now();
  in.UploadedVersion = in.ResolutionVersion;
  ++in.IndexBufferBuildCount;
  vtkProperty* prop = act->GetProperty();
  const int representation = prop->GetRepresentation();
  const bool cellData = this->HaveCellScalars || this->HaveCellNormals;
  // Points of TOMs are their active vertices, unless cell data needs one
  // primitive per triangle corner (VTK's layout for points).
  const bool corners = representation == VTK_POINTS && cellData;
  const size_t capacity = representation == VTK_WIREFRAME ? in.MaxWireIndices
    : representation == VTK_POINTS                        ? in.MaxPointIndices
                                                          : in.MaxSurfaceIndices;
  Grow(in.Indices, capacity);
  if (cellData)
  {
    Grow(in.PrimitiveCells, capacity);
  }
  const bool vertexVisibility = prop->GetVertexVisibility() != 0;
  if (vertexVisibility)
  {
    Grow(in.VertexIndices, static_cast<size_t>(in.TotalVertices));
  }
  vtkCellArray* polys = this->CurrentInput->GetPolys();

  uint32_t* indices = in.Indices.data();
  size_t n = 0;          // indices written
  size_t primitives = 0; // primitives written (for cell data)
  size_t vertexIndices = 0;
  this->RenderedTriangles = 0;
  this->RenderedVertices = 0;
  auto addCells = [&](vtkIdType cell, size_t count)
  {
    for (size_t k = 0; k < count; ++k)
    {
      in.PrimitiveCells[primitives++] = cell;
    }
  };

  for (auto& object : in.Objects)
  {
    object.RenderedTriangles = 0;
    object.RenderedVertices = 0;
    if (!(object.Resolution > 0.0))
    {
      continue; // culled
    }
    ++this->NumberOfRewrittenObjects;
    const uint32_t base = static_cast<uint32_t>(object.VertexOffset);
    const vtkIdType firstCell = in.PolyCellBase + object.PolyOffset;
    if (object.Refinement && this->ViewDependentRefinement)
    {
      // The view-dependent front, refined by RefineObjects() for this render.
      const timecritical::ViewDependentRefinement& front = *object.Refinement;
      const uint32_t triangles = front.GetNumberOfDisplayTriangles();
      if (representation == VTK_WIREFRAME)
      {
        timecritical::WriteTriangleEdges(front.GetTriangles(), triangles, base, indices + n);
        n += 6 * static_cast<size_t>(triangles);
      }
      else if (representation == VTK_POINTS && !corners)
      {
        n += WriteDisplayVertices(front, base, indices + n);
      }
      else
      {
        front.CopyTriangles(indices + n, static_cast<uint32_t>((capacity - n) / 3), base);
        n += 3 * static_cast<size_t>(triangles);
      }
      if (cellData)
      {
        // TOM triangle t is cell t of the leaf.
        const size_t perTriangle = representation == VTK_SURFACE ? 1 : 3;
        const uint32_t* ids = front.GetTriangleIds();
        for (uint32_t t = 0; t < triangles; ++t)
        {
          addCells(firstCell + ids[t], perTriangle);
        }
      }
      object.RenderedTriangles = triangles;
      object.RenderedVertices = front.GetNumberOfDisplayVertices();
    }
    else if (object.IsTOM)
    {
      const timecritical::TOMTraversal& traversal = object.Traversal;
      const uint32_t vertexCount = traversal.GetVertexCountForTriangles(
        traversal.GetTrianglesForResolution(object.Resolution));
      uint32_t triangles = 0;
      if (representation == VTK_WIREFRAME)
      {
        triangles = traversal.Extract(
          vertexCount, in.Scratch.data(), static_cast<uint32_t>(in.Scratch.size() / 3));
        timecritical::WriteTriangleEdges(in.Scratch.data(), triangles, base, indices + n);
        n += 6 * static_cast<size_t>(triangles);
      }
      else if (representation == VTK_POINTS && !corners)
      {
        triangles = traversal.Extract(vertexCount, nullptr, 0); // counts only
        timecritical::WriteVertexRange(vertexCount, base, indices + n);
        n += vertexCount;
      }
      else
      {
        // Straight into the index buffer, then shifted to merged point ids.
        uint32_t* out = indices + n;
        triangles = traversal.Extract(vertexCount, out, static_cast<uint32_t>((capacity - n) / 3));
        const size_t count = 3 * static_cast<size_t>(triangles);
        for (size_t k = 0; k < count; ++k)
        {
          out[k] += base;
        }
        n += count;
      }
      if (cellData)
      {
        const size_t perTriangle = representation == VTK_SURFACE ? 1 : 3;
        for (uint32_t t = 0; t < triangles; ++t)
        {
          addCells(firstCell + t, perTriangle);
        }
      }
      object.RenderedTriangles = triangles;
      object.RenderedVertices = vertexCount;
    }
    else
    {
      // Not a TOM: full resolution, in VTK's layout per representation.
      if (representation == VTK_SURFACE)
      {
        const size_t count = 3 * static_cast<size_t>(object.NumberOfTriangles);
        const uint32_t* src = in.StaticTriangles.data() + 3 * object.TriangleStart;
        std::copy(src, src + count, indices + n);
        n += count;
        if (cellData)
        {
          const uint32_t* cells = in.StaticTriangleCells.data() + object.TriangleStart;
          for (vtkIdType t = 0; t < object.NumberOfTriangles; ++t)
          {
            addCells(firstCell + cells[t], 1);
          }
        }
      }
      else
      {
        vtkIdType npts = 0;
        const vtkIdType* ids = nullptr;
        for (vtkIdType c = 0; c < object.NumberOfPolys; ++c)
        {
          polys->GetCellAtId(object.PolyOffset + c, npts, ids);
          for (vtkIdType i = 0; i < npts; ++i)
          {
            indices[n++] = static_cast<uint32_t>(ids[i]);
            if (representation == VTK_WIREFRAME)
            {
              indices[n++] = static_cast<uint32_t>(ids[i + 1 < npts ? i + 1 : 0]);
            }
          }
          if (cellData)
          {
            addCells(firstCell + c, static_cast<size_t>(npts));
          }
        }
      }
      object.RenderedTriangles = object.NumberOfTriangles;
      object.RenderedVertices = object.NumberOfVertices;
    }
    if (vertexVisibility && object.Refinement && this->ViewDependentRefinement)
    {
      vertexIndices +=
        WriteDisplayVertices(*object.Refinement, base, in.VertexIndices.data() + vertexIndices);
    }
    else if (vertexVisibility)
    {
      const auto count = static_cast<size_t>(object.RenderedVertices);
      timecritical::WriteVertexRange(count, base, in.VertexIndices.data() + vertexIndices);
      vertexIndices += count;
    }
    this->RenderedTriangles += object.RenderedTriangles;
    this->RenderedVertices += object.RenderedVertices;

    if (in.ResolutionColors && this->ColorByResolution && object.Refinement &&
      this->ViewDependentRefinement)
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
    }
    else if (in.ResolutionColors && this->ColorByResolution)
    {
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
  }

  in.IndexCount = n;
  vtkOpenGLIndexBufferObject* ibo = this->Primitives[PrimitiveTris].IBO;
  if (n > 0)
  {
    ibo->Upload(indices, n, vtkOpenGLBufferObject::ElementArrayBuffer);
    this->IndexBytesUploaded += static_cast<vtkIdType>(4 * n);
  }
  ibo->IndexCount = n;

  if (vertexVisibility)
  {
    vtkOpenGLIndexBufferObject* vertexIBO = this->Primitives[PrimitiveVertices].IBO;
    if (vertexIndices > 0)
    {
      vertexIBO->Upload(
        in.VertexIndices.data(), vertexIndices, vtkOpenGLBufferObject::ElementArrayBuffer);
      this->IndexBytesUploaded += static_cast<vtkIdType>(4 * vertexIndices);
    }
    vertexIBO->IndexCount = vertexIndices;
  }
  if (cellData)
  {
    this->UploadCellTextures(ren, primitives);
  }
  if (in.ResolutionColors && this->ColorByResolution)
  {
    this->UploadResolutionColors();
  }
  this->IndexUpdateTime =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - startTime).count();
}

//------------------------------------------------------------------------------
void vtkMultiresolutionPolyDataMapper::UploadCellTextures(vtkRenderer* ren, size_t primitives)
{
  // VTK looks cell values up by gl_PrimitiveID, which counts the primitives
  // actually drawn: with triangles dropped they no longer follow the cell
  // ids, so the textures are rebuilt in drawn order. Vertices and lines (first)
  // and strips (after the polygons) of non-TOM leaves keep VTK's layout.
  Internals& in = *this->Internal;
  vtkPolyData* poly = this->CurrentInput;
  vtkIdType* offsets = this->CellCellMap->GetPrimitiveOffsets();
  const size_t mapSize = this->CellCellMap->GetSize();
  const size_t trisStart = in.MergedHasOtherCells ? static_cast<size_t>(offsets[2]) : 0;
  const size_t stripsStart = in.MergedHasOtherCells ? static_cast<size_t>(offsets[3]) : 0;
  const bool strips = in.MergedHasOtherCells && poly->GetNumberOfStrips() > 0;
  size_t total = trisStart + primitives;
  if (strips)
  {
    total = std::max(total, mapSize);
  }
  total = std::max<size_t>(total, 1); // texture buffers may not be empty
  // Cell id of texel i.
  auto cellOf = [&](size_t i) -> vtkIdType
  {
    if (i >= trisStart && i < trisStart + primitives && !(strips && i >= stripsStart))
    {
      return in.PrimitiveCells[i - trisStart];
    }
    return i < mapSize ? this->CellCellMap->GetValue(i) : 0;
  };
  vtkOpenGLRenderWindow* renWin = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());

  if (this->HaveCellScalars && this->Colors)
  {
    const int components = this->Colors->GetNumberOfComponents();
    const unsigned char* colors = this->Colors->GetPointer(0);
    const bool single =
      this->FieldDataTupleId > -1 && this->ScalarMode == VTK_SCALAR_MODE_USE_FIELD_DATA;
    const vtkIdType tuples = this->Colors->GetNumberOfTuples();
    Grow(in.CellColors, 4 * total);
    for (size_t i = 0; i < total; ++i)
    {
      vtkIdType cell = single ? this->FieldDataTupleId : cellOf(i);
      cell = std::min<vtkIdType>(std::max<vtkIdType>(cell, 0), tuples - 1);
      for (int k = 0; k < 4; ++k)
      {
        in.CellColors[4 * i + k] = k < components ? colors[components * cell + k] : 255;
      }
    }
    if (!this->CellScalarTexture)
    {
      this->CellScalarTexture = vtkTextureObject::New();
      this->CellScalarBuffer = vtkOpenGLBufferObject::New();
      this->CellScalarBuffer->SetType(vtkOpenGLBufferObject::TextureBuffer);
    }
    this->CellScalarTexture->SetContext(renWin);
    this->CellScalarBuffer->Upload(
      in.CellColors.data(), 4 * total, vtkOpenGLBufferObject::TextureBuffer);
    this->CellDataBytesUploaded += static_cast<vtkIdType>(4 * total);
    this->CellScalarTexture->CreateTextureBuffer(
      static_cast<unsigned int>(total), 4, VTK_UNSIGNED_CHAR, this->CellScalarBuffer);
  }

  vtkDataArray* normals = poly->GetCellData()->GetNormals();
  if (this->HaveCellNormals && normals)
  {
    Grow(in.CellNormals, 4 * total);
    const vtkIdType tuples = normals->GetNumberOfTuples();
    double normal[3];
    for (size_t i = 0; i < total; ++i)
    {
      const vtkIdType cell = std::min<vtkIdType>(std::max<vtkIdType>(cellOf(i), 0), tuples - 1);
      normals->GetTuple(cell, normal);
      in.CellNormals[4 * i] = static_cast<float>(normal[0]);
      in.CellNormals[4 * i + 1] = static_cast<float>(normal[1]);
      in.CellNormals[4 * i + 2] = static_cast<float>(normal[2]);
      in.CellNormals[4 * i + 3] = 0.0f;
    }
    if (!this->CellNormalTexture)
    {
      this->CellNormalTexture = vtkTextureObject::New();
      this->CellNormalBuffer = vtkOpenGLBufferObject::New();
      this->CellNormalBuffer->SetType(vtkOpenGLBufferObject::TextureBuffer);
    }
    this->CellNormalTexture->SetContext(renWin);
    if (renWin->GetDefaultTextureInternalFormat(VTK_FLOAT, 4, false, true, false))
    {
      this->CellNormalBuffer->Upload(
        in.CellNormals.data(), 4 * total, vtkOpenGLBufferObject::TextureBuffer);
      this->CellDataBytesUploaded += static_cast<vtkIdType>(16 * total);
      this->CellNormalTexture->CreateTextureBuffer(
        static_cast<unsigned int>(total), 4, VTK_FLOAT, this->CellNormalBuffer);
    }
    else
    {
      // No float textures: normals as bytes, as VTK does.
      Grow(in.CellNormalBytes, 4 * total);
      for (size_t i = 0; i < 4 * total; ++i)
      {
        in.CellNormalBytes[i] = static_cast<unsigned char>(127.0 * (in.CellNormals[i] + 1.0));
      }
      this->CellNormalBuffer->Upload(
        in.CellNormalBytes.data(), 4 * total, vtkOpenGLBufferObject::TextureBuffer);
      this->CellDataBytesUploaded += static_cast<vtkIdType>(4 * total);
      this->CellNormalTexture->CreateTextureBuffer(
        static_cast<unsigned int>(total), 4, VTK_UNSIGNED_CHAR, this->CellNormalBuffer);
    }
  }
}

void vtkMultiresolutionPolyDataMapper::UploadResolutionColors()
{
  Internals& in = *this->Internal;
  vtkOpenGLVertexBufferObject* vbo = this->VBOs->GetVBO("scalarColor");
  const bool inPlace = vbo &&
    vbo->GetNumberOfTuples() == static_cast<unsigned int>(in.TotalVertices) &&
    vbo->GetStride() == 4 && vbo->GetDataType() == VTK_UNSIGNED_CHAR;
  if (vbo && !inPlace)
  {
    vbo->UploadDataArray(in.ResolutionColors);
  }
  else if (inPlace)
  {
    // Only the vertices of objects whose grey level changed, one write per
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
        static_cast<GLsizeiptr>(4 * (end - begin)), in.ResolutionColors->GetPointer(4 * begin));
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
     << (this->RefinementMode == FIXED_ACCURACY ? "FIXED_ACCURACY" : "BUDGET") << "\n";
  os << indent << "PixelThreshold: " << this->PixelThreshold << "\n";
  os << indent << "BackFaceSimplification: " << this->BackFaceSimplification << "\n";
  os << indent << "SilhouetteRefinement: " << this->SilhouetteRefinement
     << " (factor " << this->SilhouetteFactor << ")\n";
  os << indent << "HighlightRefinement: " << this->HighlightRefinement
     << " (factor " << this->HighlightFactor << ")\n";
  os << indent << "RefinementTime: " << this->RefinementTime << "\n";
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
