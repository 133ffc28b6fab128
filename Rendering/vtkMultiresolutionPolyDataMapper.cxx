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
#include "vtkCellArray.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataObjectTreeIterator.h"
#include "vtkDataSetAttributes.h"
#include "vtkFloatArray.h"
#include "vtkHardwareSelector.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkLookupTable.h"
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
#include "vtkPolyDataValidator.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkScalarsToColors.h"
#include "vtkSmartPointer.h"
#include "vtkStateStorage.h"
#include "vtkTextureObject.h"
#include "vtkTransform.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnsignedIntArray.h"

#include "vtk_glew.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <map>
#include <memory>
#include <set>
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

/// What an object's index slot holds: compared with what it should hold to
/// tell which objects an update must rewrite.
enum class ContentKind
{
  Unwritten,
  Culled,
  Front,  ///< Key: the front's version
  Prefix, ///< Key: the TOM's active vertex count
  Whole   ///< non-TOM leaf in full
};

struct Content
{
  ContentKind Kind = ContentKind::Unwritten;
  uint64_t Key = 0;
  bool operator==(const Content& other) const
  {
    return this->Kind == other.Kind && this->Key == other.Key;
  }
};

/// Primitives [Start, Start + Size) of the index buffer.
struct Range
{
  size_t Start = 0;
  size_t Size = 0;
};

/// Padding every slot gets on top of IndexSlack's share, so that small
/// objects can change by a few triangles in place.
constexpr size_t MinimumSlack = 8;

/// Dirty ranges closer than this (primitives) are uploaded as one: the
/// unchanged primitives between them cost less than another upload call.
constexpr size_t UploadGap = 256;

/// Sorts and merges ranges (in place, no allocation), clipped to [0, end).
void CoalesceRanges(std::vector<Range>& ranges, size_t end)
{
  std::sort(ranges.begin(), ranges.end(),
    [](const Range& a, const Range& b) { return a.Start < b.Start; });
  size_t kept = 0;
  for (const Range& range : ranges)
  {
    const size_t stop = std::min(range.Start + range.Size, end);
    if (range.Start >= stop)
    {
      continue;
    }
    if (kept > 0 && range.Start <= ranges[kept - 1].Start + ranges[kept - 1].Size + UploadGap)
    {
      Range& last = ranges[kept - 1];
      last.Size = std::max(last.Start + last.Size, stop) - last.Start;
    }
    else
    {
      ranges[kept++] = Range{ range.Start, stop - range.Start };
    }
  }
  ranges.resize(kept); // shrinking: no allocation
}
}

struct vtkMultiresolutionPolyDataMapper::Internals
{
  struct Object
  {
    unsigned int FlatIndex = 0;
    bool IsTOM = false;
    vtkPolyData* Leaf = nullptr; // held by Input (polydata) or Watched (composite)
    // Its cells by type, and the first of its vertices, lines and strips
    // among all leaves' (the skeleton's cells: verts, lines, strips).
    vtkIdType NumberOfVerts = 0;
    vtkIdType NumberOfLines = 0;
    vtkIdType NumberOfStrips = 0;
    vtkIdType VertOffset = 0;
    vtkIdType LineOffset = 0;
    vtkIdType StripOffset = 0;
    vtkIdType CellOffset = 0; // first of its cells among all leaves' cells in leaf order
    timecritical::TOMTraversal Traversal;
    size_t SubstitutionStart = 0; // into Substitution (TOM only)
    size_t TriangleStart = 0;     // into Triangles (TOM) or StaticTriangles (others), in triangles
    uint32_t BaseVertexCount = 0;
    vtkIdType VertexOffset = 0;
    vtkIdType NumberOfVertices = 0;
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
    // Bumped when a refinement moved the front: its slot must be rewritten.
    uint64_t FrontVersion = 0;
    // Its slot in the index buffer, in primitives of the drawn representation:
    // [SlotStart, SlotStart + SlotUsed) are its primitives, the rest up to
    // SlotSize degenerate (room to grow in place).
    size_t SlotStart = 0;
    size_t SlotSize = 0;
    size_t SlotUsed = 0;
    size_t FullPrimitives = 0; // at full resolution: no slot needs more
    Content Written;           // what the slot holds
    bool Rewritten = false;    // by the last render
  };

  std::vector<Object> Objects;
  // What the objects were read from; every leaf is held so that its address
  // cannot be reused by another object while we compare modification times.
  vtkSmartPointer<vtkDataObject> Input;
  vtkMTimeType InputTime = 0;
  std::vector<std::pair<vtkSmartPointer<vtkDataObject>, vtkMTimeType>> Watched;

  // TOM arrays of all TOM objects (leaf point ids); the traversals view them.
  // Leaves that share their cells and TOMSubstitution arrays share one copy.
  std::vector<uint32_t> Substitution;
  std::vector<uint32_t> Triangles;
  // Surface triangles of the non-TOM objects (merged point ids, degenerate
  // ones dropped as VTK does) and the polygon each comes from.
  std::vector<uint32_t> StaticTriangles;
  std::vector<uint32_t> StaticTriangleCells;

  // The superclass's input (CurrentInput), which holds no copy of the leaves:
  // no points, and arrays of no tuples named and flagged as those common to
  // all leaves (they decide the shaders' attributes and the coloring mode),
  // plus the vertices, lines and strips of the leaves in merged point ids
  // (drawn with VTK's own index buffers). Vertex buffers are appended from
  // the leaves, scalars mapped per leaf (BuildBufferObjects, MapScalars).
  vtkSmartPointer<vtkPolyData> Skeleton;
  bool HasOtherCells = false; // the skeleton has vertices, lines or strips
  vtkIdType TotalCells = 0;
  vtkIdType MaxObjectTriangles = 0;
  size_t MaxSurfaceIndices = 0;
  size_t MaxWireIndices = 0;
  size_t MaxPointIndices = 0;
  vtkIdType TotalVertices = 0;

  // Bumped by any resolution change; the index buffer follows it.
  unsigned long ResolutionVersion = 0;
  unsigned long UploadedVersion = ~0ul;
  bool OnlyIndicesChanged = false;

  // The index buffer of the triangle primitive as per-object slots, laid out
  // by the last full rebuild (FillIndexBuffer): its representation, and the
  // capacity that holds every object at full resolution (the CPU copy, the
  // GPU buffer and the cell textures all have it, so that no update reallocates).
  bool LayoutValid = false;
  int Representation = VTK_SURFACE;
  size_t PerPrimitive = 3; // indices per primitive
  bool CanPad = true;      // degenerate primitives exist (not for points)
  bool CellData = false;
  bool Corners = false; // points with cell data: one point per triangle corner
  bool VertexVisibility = false;
  size_t Capacity = 0;  // primitives
  size_t Tail = 0;      // primitives drawn: slots, padding and holes
  size_t Used = 0;      // primitives of the objects; the other Tail - Used are degenerate
  std::vector<Range> Holes;        // free ranges below Tail, sorted and merged
  std::vector<Range> DirtyIndices; // rewritten by this update (primitives)
  std::vector<Range> DirtyTexels;  // cells rewritten by this update (primitives)
  size_t TexelBase = 0;            // texel of primitive 0 (non-TOM vertices and lines first)
  size_t Texels = 0;
  bool FloatCellNormals = true;
  uint32_t StagedTriangles = 0; // of the TOM prefix extracted into Scratch
  vtkIdType RelayoutCount = 0;
  std::vector<uint32_t> SlotOrder;      // objects by slot position (Compact)
  size_t SlottedObjects = 0;            // objects with a slot
  std::vector<uint32_t> CompactIndices; // GetLastIndices(), built on demand
  bool CompactValid = false;

  // Grow-only buffers: no allocation from frame to frame once grown.
  std::vector<uint32_t> Indices;
  std::vector<uint32_t> Scratch;
  std::vector<uint32_t> VertexIndices;
  std::vector<vtkIdType> PrimitiveCells;
  std::vector<unsigned char> CellColors;
  std::vector<float> CellNormals;
  std::vector<unsigned char> CellNormalBytes;

  vtkSmartPointer<vtkUnsignedCharArray> ResolutionColors;
  bool ColorsAreResolutionMap = false; // this->Colors is a resolution map
  // The leaves' mapped scalars (MapLeafScalars): when, and for what.
  vtkTimeStamp ColorsTime;
  bool ColorsValid = false;
  double ColorsAlpha = 1.0;
  int ColorsCellFlag = 0;
  bool ColorsTexture = false;
  // HasTranslucentPolygonalGeometry's last answer, and when.
  vtkTimeStamp TranslucentTime;
  bool TranslucentValid = false;
  bool Translucent = false;
  // What the vertex buffers were built from (BuildVertexBuffers).
  vtkStateStorage LeafVBOState;
  vtkStateStorage ColorVBOState;
  bool ForceVertexUpload = false; // a camera-based shift and scale moved

  vtkNew<vtkMultiresolutionReleaseProxy> ReleaseProxy;
  vtkOpenGLRenderWindow* Window = nullptr; // holds our GL resources; cleared on release

  bool WarnedNonTOM = false;
  bool WarnedBadTree = false;
  bool WarnedNonPolyData = false;
  // Selection display: the leaf whose nodes BuildSelectionIBO adds.
  bool SelectionByFlatIndex = false;
  unsigned int SelectionFlatIndex = 0;
  vtkIdType VertexBufferBuildCount = 0;
  vtkIdType IndexBufferBuildCount = 0;

  // Hardware selection: which object drew a primitive or vertex, and its leaf's ids.
  struct Selection;
  const Object* ObjectOfVertex(vtkIdType vertex) const;
  const Object* ObjectOfOtherCell(vtkIdType cell, vtkIdType& leafCell) const;
  const Object* ObjectOfCell(vtkIdType cell) const; ///< cell in leaf order (Object::CellOffset)

  Content Describe(const Object& object, bool viewDependent) const;
  size_t Stage(Object& object, const Content& content);
  void Emit(const Object& object, const Content& content, size_t used, uint32_t* out,
    vtkIdType* cells) const;
  void SetRenderedCounts(Object& object, const Content& content) const;
  size_t SlotSizeFor(size_t used, size_t full, double slack) const;
  bool Allocate(size_t size, size_t& start, bool& fresh);
  void Release(size_t start, size_t size);
  bool GrowInPlace(Object& object, size_t size, bool& fresh);
  void FillDegenerate(size_t start, size_t count, uint32_t vertex);
  void WriteSlot(Object& object, const Content& content, size_t used, size_t extent);
  void ClearSlot(Object& object);
  bool Update(Object& object, const Content& content, double slack);
  void LayOut(bool viewDependent, double slack);
  void Compact(double slack);
  size_t PaddingLimit(double slack) const;
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
  // Released, not cleared: they are sized for this input below.
  std::vector<uint32_t>().swap(in.Substitution);
  std::vector<uint32_t>().swap(in.Triangles);
  std::vector<uint32_t>().swap(in.StaticTriangles);
  std::vector<uint32_t>().swap(in.StaticTriangleCells);
  in.Skeleton = nullptr;
  in.LayoutValid = false; // other objects: the next render lays the index buffer out
  in.CompactValid = false;
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

  // Locals: a reader keeps a copy of the last mesh it read.
  vtkNew<vtkTOMFieldData> reader;
  vtkNew<vtkMergeTreeFieldData> treeReader;

  // A TOM's arrays are copied once per pair of (cells, TOMSubstitution) arrays
  // (replicas of a mesh often share them), into vectors reserved for the
  // leaves that carry TOM arrays: no growth slack. The leaves hold the arrays
  // for this call, so their addresses are stable keys.
  using TOMKey = std::pair<const void*, const void*>;
  auto tomKey = [](vtkPolyData* poly)
  {
    return TOMKey(poly->GetPolys(),
      poly->GetPointData()->GetAbstractArray(vtkTOMFieldData::SubstitutionArrayName()));
  };
  std::map<TOMKey, std::pair<size_t, size_t>> copied; // substitution and triangle starts
  {
    std::set<TOMKey> seen;
    size_t substitution = 0;
    size_t triangles = 0;
    for (const auto& leaf : leaves)
    {
      if (vtkTOMFieldData::HasTOMArrays(leaf.first) && seen.insert(tomKey(leaf.first)).second)
      {
        substitution += static_cast<size_t>(leaf.first->GetNumberOfPoints());
        triangles += 3 * static_cast<size_t>(leaf.first->GetNumberOfPolys());
      }
    }
    in.Substitution.reserve(substitution);
    in.Triangles.reserve(triangles);
  }

  std::vector<vtkPolyData*> parts;
  vtkIdType vertexOffset = 0;
  vtkIdType vertOffset = 0;
  vtkIdType lineOffset = 0;
  vtkIdType stripOffset = 0;
  vtkIdType cellOffset = 0;
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
    // Bad point ids would make VTK's bounds, the index buffers and the vertex
    // buffer builder read out of bounds; NaN coordinates would poison bounds and culling.
    const std::string problem = vtkPolyDataValidator::Check(poly);
    if (!problem.empty())
    {
      vtkErrorMacro("Block " << leaf.second << " is not drawn: " << problem << ".");
      continue;
    }
    Internals::Object object;
    object.FlatIndex = leaf.second;
    object.Leaf = poly;
    object.NumberOfVerts = poly->GetNumberOfVerts();
    object.NumberOfLines = poly->GetNumberOfLines();
    object.NumberOfStrips = poly->GetNumberOfStrips();
    object.VertOffset = vertOffset;
    object.LineOffset = lineOffset;
    object.StripOffset = stripOffset;
    object.CellOffset = cellOffset;
    object.VertexOffset = vertexOffset;
    object.NumberOfVertices = poly->GetNumberOfPoints();
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
    object.IsTOM = reader->Read(poly);
    if (object.IsTOM)
    {
      const timecritical::TOMMesh& mesh = reader->GetMesh();
      object.BaseVertexCount = mesh.BaseVertexCount;
      auto found = copied.emplace(
        tomKey(poly), std::make_pair(in.Substitution.size(), in.Triangles.size() / 3));
      object.SubstitutionStart = found.first->second.first;
      object.TriangleStart = found.first->second.second;
      if (found.second)
      {
        in.Substitution.insert(
          in.Substitution.end(), mesh.Substitution.begin(), mesh.Substitution.end());
        in.Triangles.insert(in.Triangles.end(), mesh.Triangles.begin(), mesh.Triangles.end());
      }
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
                                 << reader->GetErrorMessage());
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
      if (treeReader->Read(poly))
      {
        // The refinement keeps its own copy of the points (float, as drawn).
        const timecritical::MergeTree& tree = treeReader->GetTree();
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
          object.Refinement->Initialize(treeReader->GetMesh(), tree, xyz.data());
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
                                 << "as a TOM: " << treeReader->GetErrorMessage());
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
    vertOffset += object.NumberOfVerts;
    lineOffset += object.NumberOfLines;
    stripOffset += object.NumberOfStrips;
    cellOffset += poly->GetNumberOfCells();
    parts.push_back(poly);
    in.Objects.push_back(std::move(object));
  }
  in.TotalVertices = vertexOffset;
  // No-ops unless a leaf with TOM arrays was not valid; the static ones grew by push_back.
  in.Substitution.shrink_to_fit();
  in.Triangles.shrink_to_fit();
  in.StaticTriangles.shrink_to_fit();
  in.StaticTriangleCells.shrink_to_fit();

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

  in.TotalCells = cellOffset;

  // The skeleton (see Internals::Skeleton): arrays common to all leaves, as
  // vtkAppendPolyData would keep them, without tuples; the leaves' other cells.
  in.HasOtherCells = false;
  if (!parts.empty())
  {
    in.Skeleton = vtkSmartPointer<vtkPolyData>::New();
    vtkNew<vtkPoints> none;
    in.Skeleton->SetPoints(none);
    vtkDataSetAttributes::FieldList pointFields(static_cast<int>(parts.size()));
    vtkDataSetAttributes::FieldList cellFields(static_cast<int>(parts.size()));
    for (size_t k = 0; k < parts.size(); ++k)
    {
      if (k == 0)
      {
        pointFields.InitializeFieldList(parts[k]->GetPointData());
        cellFields.InitializeFieldList(parts[k]->GetCellData());
      }
      else
      {
        pointFields.IntersectFieldList(parts[k]->GetPointData());
        cellFields.IntersectFieldList(parts[k]->GetCellData());
      }
    }
    // One tuple of room: 0 would reserve the sum of the leaves' tuples.
    in.Skeleton->GetPointData()->CopyAllocate(pointFields, 1);
    in.Skeleton->GetCellData()->CopyAllocate(cellFields, 1);
    // Edge flags are ignored (see the class comment); VTK would read them per point.
    in.Skeleton->GetPointData()->SetActiveAttribute(-1, vtkDataSetAttributes::EDGEFLAG);

    vtkNew<vtkCellArray> verts, lines, strips;
    std::vector<vtkIdType> shifted;
    for (const auto& object : in.Objects)
    {
      vtkCellArray* from[3] = { object.Leaf->GetVerts(), object.Leaf->GetLines(),
        object.Leaf->GetStrips() };
      vtkCellArray* to[3] = { verts, lines, strips };
      for (int type = 0; type < 3; ++type)
      {
        vtkIdType npts = 0;
        const vtkIdType* ids = nullptr;
        for (vtkIdType c = 0; c < from[type]->GetNumberOfCells(); ++c)
        {
          from[type]->GetCellAtId(c, npts, ids);
          shifted.assign(ids, ids + npts);
          for (vtkIdType& id : shifted)
          {
            id += object.VertexOffset;
          }
          to[type]->InsertNextCell(npts, shifted.data());
        }
      }
    }
    in.HasOtherCells =
      verts->GetNumberOfCells() || lines->GetNumberOfCells() || strips->GetNumberOfCells();
    if (in.HasOtherCells)
    {
      in.Skeleton->SetVerts(verts);
      in.Skeleton->SetLines(lines);
      in.Skeleton->SetStrips(strips);
    }
  }
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
  const Internals& in = *this->Internal;
  return in.LayoutValid ? static_cast<vtkIdType>(in.PerPrimitive * in.Used) : 0;
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
      if (in.LayoutValid && object.SlotUsed > 0)
      {
        const uint32_t* slot = in.Indices.data() + in.PerPrimitive * object.SlotStart;
        in.CompactIndices.insert(
          in.CompactIndices.end(), slot, slot + in.PerPrimitive * object.SlotUsed);
      }
    }
    in.CompactValid = true;
  }
  return in.CompactIndices.data();
}

vtkIdType vtkMultiresolutionPolyDataMapper::GetIndexBufferRelayoutCount() const
{
  return this->Internal->RelayoutCount;
}

bool vtkMultiresolutionPolyDataMapper::GetObjectRewritten(vtkIdType i) const
{
  return this->IsValidObject(i) && this->Internal->Objects[i].Rewritten;
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

vtkUnsignedCharArray* vtkMultiresolutionPolyDataMapper::MapLeafScalars(
  vtkAbstractArray* common, double alpha, int cellFlag)
{
  // Each leaf's scalars mapped with the mapper's one lookup table and range,
  // into one array in leaf order (point colors in vertex buffer order, cell
  // colors in the cells' leaf order: Object::CellOffset), as vtkMapper maps
  // one dataset's. Interpolated scalars (texture coloring) concatenate the
  // leaves' texture coordinates instead.
  Internals& in = *this->Internal;
  if (this->ArrayComponent < 0 || common->GetNumberOfComponents() <= this->ArrayComponent)
  {
    this->ArrayComponent = 0;
  }
  vtkDataArray* first = vtkArrayDownCast<vtkDataArray>(
    this->GetLeafScalars(in.Objects[0].Leaf, common, cellFlag));
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
  Internals& in = *this->Internal;
  if (this->ColorByResolution || !this->ScalarVisibility || !in.Skeleton)
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
  this->NumberOfPaddingPrimitives = this->Primitives[PrimitiveTris].IBO->IndexCount > 0
    ? static_cast<vtkIdType>(in.Tail - in.Used)
    : 0;
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
    // A plane p (world) is p M in object coordinates (the refinement
    // normalizes it).
    double* o = view.FrustumPlanes[i];
    for (int c = 0; c < 4; ++c)
    {
      o[c] = planes[4 * i] * model[c] + planes[4 * i + 1] * model[4 + c] +
        planes[4 * i + 2] * model[8 + c] + planes[4 * i + 3] * model[12 + c];
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
    if (statistics.Splits > 0 || statistics.Merges > 0)
    {
      ++object.FrontVersion; // its slot is rewritten, the others' are not
      changed = true;
    }
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
  this->BuildVertexBuffers(ren, act);
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
  vtkDataArray* pointColors = this->Colors;
  if (this->ScalarVisibility && this->Colors && this->Colors->GetNumberOfTuples() > 0 &&
    this->ScalarMode != VTK_SCALAR_MODE_USE_POINT_FIELD_DATA &&
    (this->ScalarMode == VTK_SCALAR_MODE_USE_CELL_DATA ||
      this->ScalarMode == VTK_SCALAR_MODE_USE_CELL_FIELD_DATA ||
      this->ScalarMode == VTK_SCALAR_MODE_USE_FIELD_DATA || !skeleton->GetPointData()->GetScalars()))
  {
    this->HaveCellScalars = true;
    pointColors = nullptr;
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

  // The vertex buffers follow the leaves (a re-read makes a new skeleton),
  // the attributes drawn and the shift and scale method; a change of the
  // colors alone re-uploads the color buffer only.
  const int tcoords = !this->HaveTCoords(skeleton) ? 0
    : this->InterpolateScalarsBeforeMapping && this->ColorCoordinates ? 2
    : skeleton->GetPointData()->GetTCoords() ? 1
                                              : 0;
  vtkStateStorage leafState;
  leafState.Append(skeleton->GetMTime(), "skeleton");
  leafState.Append(pointNormals, "normals");
  leafState.Append(tcoords, "tcoords");
  leafState.Append(tcoords == 2 ? this->ColorCoordinates->GetMTime() : 0, "color coordinates");
  leafState.Append(vtkFloatArray::SafeDownCast(skeleton->GetPointData()->GetTangents()) != nullptr,
    "tangents");
  std::string extras;
  for (const auto& extra : this->ExtraAttributes)
  {
    extras += extra.first + "=" + extra.second.DataArrayName + ";";
  }
  leafState.Append(std::hash<std::string>()(extras), "extra attributes");
  leafState.Append(this->ShiftScaleMethod, "shift scale");
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

  // Per leaf: attributes whose arrays are common to all leaves (the
  // skeleton's); colors and color coordinates are one array already.
  std::vector<std::pair<std::string, int>> appended; // attribute, components
  auto appendLeaves = [&](const char* attribute, vtkDataArray* (*get)(vtkPolyData*, const char*),
                        const char* name, int type)
  {
    for (const auto& object : in.Objects)
    {
      vtkDataArray* array = get(object.Leaf, name);
      if (!array || array->GetNumberOfTuples() != object.NumberOfVertices)
      {
        vtkErrorMacro("Block " << object.FlatIndex << " lacks the " << attribute
                               << " array of the other leaves; not drawn right.");
        continue;
      }
      vbos->AppendDataArray(attribute, array, type);
      if (appended.empty() || appended.back().first != attribute)
      {
        appended.emplace_back(attribute, array->GetNumberOfComponents());
      }
    }
  };
  auto pointArray = [](vtkPolyData* leaf, const char* name) -> vtkDataArray*
  { return leaf->GetPointData()->GetArray(name); };
  for (const auto& extra : this->ExtraAttributes)
  {
    const char* name = extra.second.DataArrayName.c_str();
    if (skeleton->GetPointData()->GetArray(name))
    {
      appendLeaves(extra.first.c_str(), pointArray, name, VTK_FLOAT);
    }
  }
  appendLeaves(
    "vertexMC", [](vtkPolyData* leaf, const char*) { return leaf->GetPoints()->GetData(); },
    nullptr, VTK_FLOAT);
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
    appendLeaves(
      "normalMC", [](vtkPolyData* leaf, const char*) { return leaf->GetPointData()->GetNormals(); },
      nullptr, VTK_FLOAT);
  }
  vbos->AppendDataArray("scalarColor", pointColors, VTK_UNSIGNED_CHAR);
  if (tcoords == 2)
  {
    vbos->AppendDataArray("tcoord", this->ColorCoordinates, VTK_FLOAT);
  }
  else if (tcoords == 1)
  {
    appendLeaves(
      "tcoord", [](vtkPolyData* leaf, const char*) { return leaf->GetPointData()->GetTCoords(); },
      nullptr, VTK_FLOAT);
  }
  if (vtkFloatArray::SafeDownCast(skeleton->GetPointData()->GetTangents()))
  {
    appendLeaves(
      "tangentMC", [](vtkPolyData* leaf, const char*) { return leaf->GetPointData()->GetTangents(); },
      nullptr, VTK_FLOAT);
  }
  // Several blocks per attribute are packed on the CPU and uploaded: the
  // packing vectors are reserved at their size (no growth slack) and freed
  // once uploaded, so that no CPU copy of the vertex data stays.
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
  positions = vbos->GetVBO("vertexMC");
  if (positions && positions->GetCoordShiftAndScaleEnabled())
  {
    const std::vector<double>& shift = positions->GetShift();
    const std::vector<double>& scale = positions->GetScale();
    this->VBOInverseTransform->Identity();
    this->VBOInverseTransform->Translate(shift[0], shift[1], shift[2]);
    this->VBOInverseTransform->Scale(1.0 / scale[0], 1.0 / scale[1], 1.0 / scale[2]);
    this->VBOInverseTransform->GetTranspose(this->VBOShiftScale);
  }
  this->BuildIBO(ren, act, skeleton);
  this->VBOBuildTime.Modified();
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

//------------------------------------------------------------------------------
// Index slots. The triangle primitive's index buffer holds one slot per
// object, in primitives of the drawn representation (triangles, lines or
// points): the object's primitives, then degenerate ones (all indices one
// vertex: no fragments) as room to grow. gl_PrimitiveID counts the degenerate
// primitives too, so the cell textures follow the same layout (texel = slot
// position; the texels of padding are never read, having no fragments). An update rewrites only the objects whose content changed, in
// their slot, and uploads only those ranges; an object that outgrows its slot
// grows into the hole or end after it, or moves to a hole or the end; one that
// shrinks far below it gives the rest back. Unused ranges (holes) are
// degenerate. The whole buffer is laid out again (compacted) only when no
// room is left or padding exceeds its limit.

Content vtkMultiresolutionPolyDataMapper::Internals::Describe(
  const Object& object, bool viewDependent) const
{
  Content content;
  if (!(object.Resolution > 0.0))
  {
    content.Kind = ContentKind::Culled;
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
  return std::min(count, object.FullPrimitives);
}

void vtkMultiresolutionPolyDataMapper::Internals::Emit(const Object& object,
  const Content& content, size_t used, uint32_t* out, vtkIdType* cells) const
{
  const auto base = static_cast<uint32_t>(object.VertexOffset);
  // Cells in leaf order (the order of cell colours): a leaf's polygons follow its vertices and lines.
  const vtkIdType firstCell = object.CellOffset + object.NumberOfVerts + object.NumberOfLines;
  // Cell data: one cell per primitive; a triangle is 3 lines or 3 corner points.
  const size_t perTriangle = this->Representation == VTK_SURFACE ? 1 : 3;
  auto addCells = [&](vtkIdType cell, size_t count)
  {
    for (size_t k = 0; k < count; ++k)
    {
      *cells++ = cell;
    }
  };
  const bool points = this->Representation == VTK_POINTS && !this->Corners;
  if (content.Kind == ContentKind::Front)
  {
    const timecritical::ViewDependentRefinement& front = *object.Refinement;
    const auto triangles = static_cast<uint32_t>(
      std::min<size_t>(front.GetNumberOfDisplayTriangles(), used / perTriangle));
    if (this->Representation == VTK_WIREFRAME)
    {
      timecritical::WriteTriangleEdges(front.GetTriangles(), triangles, base, out);
    }
    else if (points)
    {
      WriteDisplayVertices(front, base, out);
    }
    else
    {
      front.CopyTriangles(out, triangles, base);
    }
    if (cells)
    {
      // TOM triangle t is cell t of the leaf.
      const uint32_t* ids = front.GetTriangleIds();
      for (uint32_t t = 0; t < triangles; ++t)
      {
        addCells(firstCell + ids[t], perTriangle);
      }
    }
  }
  else if (content.Kind == ContentKind::Prefix)
  {
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
      for (uint32_t t = 0; t < triangles; ++t)
      {
        addCells(firstCell + t, perTriangle);
      }
    }
  }
  else if (content.Kind == ContentKind::Whole)
  {
    // Not a TOM: full resolution, in VTK's layout per representation.
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
          addCells(firstCell + ids[t], 1);
        }
      }
    }
    else
    {
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
          addCells(firstCell + c, static_cast<size_t>(npts));
        }
      }
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

size_t vtkMultiresolutionPolyDataMapper::Internals::SlotSizeFor(
  size_t used, size_t full, double slack) const
{
  if (used == 0 || !this->CanPad)
  {
    return used;
  }
  const size_t extra = slack > 0.0 ? static_cast<size_t>(slack * used) + MinimumSlack : 0;
  return std::max(used, std::min(full, used + extra));
}

bool vtkMultiresolutionPolyDataMapper::Internals::Allocate(size_t size, size_t& start, bool& fresh)
{
  // First fit among the holes (degenerate already), else past the end.
  for (auto hole = this->Holes.begin(); hole != this->Holes.end(); ++hole)
  {
    if (hole->Size >= size)
    {
      start = hole->Start;
      hole->Start += size;
      hole->Size -= size;
      if (hole->Size == 0)
      {
        this->Holes.erase(hole);
      }
      fresh = false;
      return true;
    }
  }
  if (this->Tail + size > this->Capacity)
  {
    return false;
  }
  start = this->Tail;
  this->Tail += size;
  fresh = true; // never written in this layout
  return true;
}

void vtkMultiresolutionPolyDataMapper::Internals::Release(size_t start, size_t size)
{
  if (size == 0)
  {
    return;
  }
  // Holes stay sorted and merged, so there are at most objects + 1 of them
  // (the capacity reserved at layout: inserting never allocates).
  auto hole = std::lower_bound(this->Holes.begin(), this->Holes.end(), start,
    [](const Range& range, size_t value) { return range.Start < value; });
  if (hole != this->Holes.begin() && std::prev(hole)->Start + std::prev(hole)->Size == start)
  {
    --hole;
    hole->Size += size;
  }
  else
  {
    hole = this->Holes.insert(hole, Range{ start, size });
  }
  const auto next = std::next(hole);
  if (next != this->Holes.end() && hole->Start + hole->Size == next->Start)
  {
    hole->Size += next->Size;
    hole = std::prev(this->Holes.erase(next));
  }
  if (hole->Start + hole->Size == this->Tail)
  {
    // A hole at the end is simply not drawn.
    this->Tail = hole->Start;
    this->Holes.erase(hole);
  }
}

bool vtkMultiresolutionPolyDataMapper::Internals::GrowInPlace(
  Object& object, size_t size, bool& fresh)
{
  const size_t end = object.SlotStart + object.SlotSize;
  const size_t extra = size - object.SlotSize;
  if (object.SlotSize == 0)
  {
    return false;
  }
  if (end == this->Tail)
  {
    if (object.SlotStart + size > this->Capacity)
    {
      return false;
    }
    this->Tail = object.SlotStart + size;
    object.SlotSize = size;
    fresh = true;
    return true;
  }
  auto hole = std::lower_bound(this->Holes.begin(), this->Holes.end(), end,
    [](const Range& range, size_t value) { return range.Start < value; });
  if (hole == this->Holes.end() || hole->Start != end || hole->Size < extra)
  {
    return false;
  }
  hole->Start += extra;
  hole->Size -= extra;
  if (hole->Size == 0)
  {
    this->Holes.erase(hole);
  }
  object.SlotSize = size;
  fresh = false;
  return true;
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
  if (used > 0)
  {
    this->Emit(object, content, used,
      this->Indices.data() + this->PerPrimitive * object.SlotStart,
      this->CellData ? this->PrimitiveCells.data() + object.SlotStart : nullptr);
    this->DirtyIndices.push_back(Range{ object.SlotStart, used });
    if (this->CellData)
    {
      this->DirtyTexels.push_back(Range{ object.SlotStart, used });
    }
  }
  if (extent > used)
  {
    this->FillDegenerate(
      object.SlotStart + used, extent - used, static_cast<uint32_t>(object.VertexOffset));
  }
  this->Used = this->Used - object.SlotUsed + used;
  object.Rewritten = object.Rewritten || used > 0 || object.SlotUsed > 0;
  object.SlotUsed = used;
  object.Written = content;
}

void vtkMultiresolutionPolyDataMapper::Internals::ClearSlot(Object& object)
{
  this->FillDegenerate(
    object.SlotStart, object.SlotUsed, static_cast<uint32_t>(object.VertexOffset));
  object.Rewritten = object.Rewritten || object.SlotUsed > 0;
  this->Used -= object.SlotUsed;
  object.SlotUsed = 0;
  this->Release(object.SlotStart, object.SlotSize);
  this->SlottedObjects -= object.SlotSize > 0 ? 1 : 0;
  object.SlotStart = 0;
  object.SlotSize = 0;
}

bool vtkMultiresolutionPolyDataMapper::Internals::Update(
  Object& object, const Content& content, double slack)
{
  const size_t used = this->Stage(object, content);
  if (!this->CanPad && used != object.SlotSize)
  {
    return false; // points: no degenerate point (nor hole), every slot fits exactly
  }
  if (used == 0)
  {
    this->ClearSlot(object);
    object.Written = content;
    return true;
  }
  size_t extent = object.SlotUsed;
  if (used > object.SlotSize)
  {
    const size_t size = this->SlotSizeFor(used, object.FullPrimitives, slack);
    bool fresh = false;
    if (!this->GrowInPlace(object, size, fresh))
    {
      this->ClearSlot(object);
      size_t start = 0;
      if (!this->Allocate(size, start, fresh))
      {
        return false;
      }
      object.SlotStart = start;
      object.SlotSize = size;
      ++this->SlottedObjects;
      extent = 0;
    }
    if (fresh)
    {
      extent = size;
    }
  }
  this->WriteSlot(object, content, used, extent);
  // Far below its slot: the end goes back (it is degenerate already).
  const size_t size = this->SlotSizeFor(used, object.FullPrimitives, slack);
  if (object.SlotSize > 2 * size)
  {
    this->Release(object.SlotStart + size, object.SlotSize - size);
    object.SlotSize = size;
  }
  return true;
}

void vtkMultiresolutionPolyDataMapper::Internals::LayOut(
  bool viewDependent, double slack)
{
  this->DirtyIndices.clear();
  this->DirtyTexels.clear();
  this->Holes.clear();
  this->Tail = 0;
  this->Used = 0;
  this->SlottedObjects = 0;
  for (auto& object : this->Objects)
  {
    const Content content = this->Describe(object, viewDependent);
    const size_t used = this->Stage(object, content);
    object.SlotStart = this->Tail;
    object.SlotSize = this->SlotSizeFor(used, object.FullPrimitives, slack);
    object.SlotUsed = 0;
    this->SlottedObjects += object.SlotSize > 0 ? 1 : 0;
    this->Tail += object.SlotSize; // slots never exceed full resolution: fits the capacity
    this->WriteSlot(object, content, used, object.SlotSize);
    this->SetRenderedCounts(object, content);
  }
  // Everything drawn is uploaded.
  this->DirtyIndices.clear();
  this->DirtyTexels.clear();
  this->DirtyIndices.push_back(Range{ 0, this->Tail });
  if (this->CellData)
  {
    this->DirtyTexels.push_back(Range{ 0, this->Tail });
  }
  ++this->RelayoutCount;
}

size_t vtkMultiresolutionPolyDataMapper::Internals::PaddingLimit(double slack) const
{
  // Twice what a fresh layout leaves; with no slack, none.
  return slack > 0.0
    ? 2 * (static_cast<size_t>(slack * this->Used) + MinimumSlack * this->SlottedObjects)
    : 0;
}

void vtkMultiresolutionPolyDataMapper::Internals::Compact(double slack)
{
  // Slots move down in buffer order over the holes, their padding trimmed to
  // a fresh layout's: the content is moved, not extracted again.
  this->SlotOrder.clear();
  for (size_t i = 0; i < this->Objects.size(); ++i)
  {
    if (this->Objects[i].SlotSize > 0)
    {
      this->SlotOrder.push_back(static_cast<uint32_t>(i)); // capacity reserved at layout
    }
  }
  std::sort(this->SlotOrder.begin(), this->SlotOrder.end(), [this](uint32_t a, uint32_t b)
    { return this->Objects[a].SlotStart < this->Objects[b].SlotStart; });
  size_t tail = 0;
  size_t moved = SIZE_MAX; // first primitive that changes: uploaded from there on
  const size_t k = this->PerPrimitive;
  for (uint32_t i : this->SlotOrder)
  {
    Object& object = this->Objects[i];
    // Never larger than now, so that every slot moves down (or stays).
    const size_t size = std::min(object.SlotSize,
      this->SlotSizeFor(object.SlotUsed, object.FullPrimitives, slack));
    if (object.SlotStart != tail)
    {
      // [SlotUsed, size) is degenerate already.
      std::memmove(this->Indices.data() + k * tail, this->Indices.data() + k * object.SlotStart,
        sizeof(uint32_t) * k * size);
      if (this->CellData)
      {
        std::memmove(this->PrimitiveCells.data() + tail,
          this->PrimitiveCells.data() + object.SlotStart, sizeof(vtkIdType) * object.SlotUsed);
      }
      object.Rewritten = true;
      moved = std::min(moved, tail);
    }
    object.SlotStart = tail;
    object.SlotSize = size;
    tail += size;
  }
  this->Holes.clear();
  this->Tail = tail;
  if (moved < tail)
  {
    // Ranges rewritten before (by this update) below `moved` stay dirty.
    this->DirtyIndices.push_back(Range{ moved, tail - moved });
    if (this->CellData)
    {
      this->DirtyTexels.push_back(Range{ moved, tail - moved });
    }
  }
  ++this->RelayoutCount;
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
  // A point with all indices equal is still a point: points get no padding.
  in.CanPad = in.Representation != VTK_POINTS;
  in.VertexVisibility = prop->GetVertexVisibility() != 0;
  in.Capacity = 0;
  for (auto& object : in.Objects)
  {
    const auto triangles = static_cast<size_t>(object.NumberOfTriangles);
    if (!object.IsTOM)
    {
      object.FullPrimitives = in.Representation == VTK_SURFACE
        ? triangles
        : static_cast<size_t>(object.PolyConnectivity);
    }
    else if (in.Representation == VTK_POINTS && !in.Corners)
    {
      object.FullPrimitives = static_cast<size_t>(object.NumberOfVertices);
    }
    else
    {
      object.FullPrimitives = (in.Representation == VTK_SURFACE ? 1 : 3) * triangles;
    }
    in.Capacity += object.FullPrimitives;
    object.SlotStart = object.SlotSize = object.SlotUsed = 0;
    object.Written = Content();
  }
  this->PatchStripOffset();
  Grow(in.Indices, in.PerPrimitive * in.Capacity);
  if (in.CellData)
  {
    Grow(in.PrimitiveCells, in.Capacity);
  }
  // Bounds that keep every per-frame insertion within reserved capacity.
  in.Holes.reserve(in.Objects.size() + 2);
  in.SlotOrder.reserve(in.Objects.size());
  in.DirtyIndices.reserve(3 * in.Objects.size() + 8);
  in.DirtyTexels.reserve(in.Objects.size() + 8);
  if (in.VertexVisibility)
  {
    Grow(in.VertexIndices, static_cast<size_t>(in.TotalVertices));
  }

  vtkOpenGLIndexBufferObject* ibo = this->Primitives[PrimitiveTris].IBO;
  if (in.Capacity > 0)
  {
    // Allocated once at full capacity, written with glBufferSubData.
    ibo->GenerateBuffer(vtkOpenGLBufferObject::ElementArrayBuffer);
    ibo->Bind();
    glBufferData(GL_ELEMENT_ARRAY_BUFFER,
      static_cast<GLsizeiptr>(sizeof(uint32_t) * in.PerPrimitive * in.Capacity), nullptr,
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
    in.DirtyIndices.clear();
    in.DirtyTexels.clear();
    bool compacted = false;
    for (auto& object : in.Objects)
    {
      const Content content = in.Describe(object, this->ViewDependentRefinement);
      if (content == object.Written)
      {
        continue; // unchanged: neither extracted nor uploaded
      }
      if (!in.Update(object, content, this->IndexSlack))
      {
        // No room left: compact and try again; points (which cannot pad)
        // and a buffer full even then are laid out again from scratch.
        if (!in.CanPad || compacted)
        {
          layOut = true;
          break;
        }
        in.Compact(this->IndexSlack);
        compacted = true;
        if (!in.Update(object, content, this->IndexSlack))
        {
          layOut = true;
          break;
        }
      }
      in.SetRenderedCounts(object, content);
    }
    // Padding costs drawing time: compacted when it exceeds its limit.
    if (!layOut && in.Tail - in.Used > in.PaddingLimit(this->IndexSlack))
    {
      in.Compact(this->IndexSlack);
    }
  }
  if (layOut)
  {
    in.LayOut(this->ViewDependentRefinement, this->IndexSlack);
  }

  // Upload the rewritten ranges.
  CoalesceRanges(in.DirtyIndices, in.Tail);
  CoalesceRanges(in.DirtyTexels, in.Tail);
  vtkOpenGLIndexBufferObject* ibo = this->Primitives[PrimitiveTris].IBO;
  if (!in.DirtyIndices.empty())
  {
    ibo->Bind();
    const size_t bytes = sizeof(uint32_t) * in.PerPrimitive;
    for (const Range& range : in.DirtyIndices)
    {
      glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLintptr>(bytes * range.Start),
        static_cast<GLsizeiptr>(bytes * range.Size),
        in.Indices.data() + in.PerPrimitive * range.Start);
      this->IndexBytesUploaded += static_cast<vtkIdType>(bytes * range.Size);
    }
    ibo->Release();
  }
  // Only padding left (everything culled): no draw call.
  ibo->IndexCount = in.Used > 0 ? in.PerPrimitive * in.Tail : 0;
  for (const Range& range : in.DirtyTexels)
  {
    this->UploadCellTexels(in.TexelBase + range.Start, in.TexelBase + range.Start + range.Size);
  }

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
    // Vertices drawn as points over the surface (a second draw call): all rewritten.
    size_t count = 0;
    for (const auto& object : in.Objects)
    {
      const auto base = static_cast<uint32_t>(object.VertexOffset);
      if (object.Written.Kind == ContentKind::Front)
      {
        count += WriteDisplayVertices(*object.Refinement, base, in.VertexIndices.data() + count);
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
      vertexIBO->Upload(
        in.VertexIndices.data(), count, vtkOpenGLBufferObject::ElementArrayBuffer);
      this->IndexBytesUploaded += static_cast<vtkIdType>(sizeof(uint32_t) * count);
    }
    vertexIBO->IndexCount = count;
  }
  if (in.ResolutionColors && this->ColorByResolution)
  {
    this->UploadResolutionColors();
  }
  this->IndexUpdateTime =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - startTime).count();
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
  in.Texels = in.TexelBase + in.Capacity + (mapSize > in.TexelBase ? mapSize - in.TexelBase : 0);
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
  this->UploadCellTexels(in.TexelBase + in.Capacity, in.Texels);
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
  const size_t trisEnd = in.TexelBase + in.Capacity;
  const size_t mapSize = in.HasOtherCells ? this->CellCellMap->GetSize() : 0;
  auto cellOf = [&](size_t i) -> vtkIdType
  {
    if (i >= in.TexelBase && i < trisEnd)
    {
      return in.PrimitiveCells[i - in.TexelBase];
    }
    const size_t index = i < in.TexelBase ? i : i - in.Capacity;
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
// Hardware selection. vtkHardwareSelector renders the actor once per pass; the
// superclass writes gl_PrimitiveID (plus the primitives drawn before) in the
// cell passes, gl_VertexID in the point passes and 1 in the composite pass.
// Here a primitive id becomes the object whose slot holds it and the leaf cell
// that Emit wrote there (the cell textures' mapping), a vertex the object whose
// vertex range holds it; the composite pass, processed again in the selector's
// second iteration when the cell (or point) ids of the first are known,
// becomes the object's flat index.

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

void vtkMultiresolutionPolyDataMapper::PatchStripOffset()
{
  // VTK numbers the skeleton's strips right after its (no) polygons; they are
  // drawn after the triangle index buffer, whose primitives (up to its
  // capacity) come first in gl_PrimitiveID + offset and in the cell textures.
  Internals& in = *this->Internal;
  if (in.HasOtherCells)
  {
    vtkIdType* offsets = this->CellCellMap->GetPrimitiveOffsets();
    offsets[3] = offsets[2] + static_cast<vtkIdType>(in.Capacity);
  }
}

/// The state of one ProcessSelectorPixelBuffers call: objects by slot, and
/// (points representation) the drawn triangle that first uses each vertex.
struct vtkMultiresolutionPolyDataMapper::Internals::Selection
{
  explicit Selection(const Internals& in)
    : In(in)
  {
    for (size_t i = 0; i < in.Objects.size(); ++i)
    {
      if (in.Objects[i].SlotUsed > 0)
      {
        this->BySlot.push_back(static_cast<uint32_t>(i));
      }
    }
    std::sort(this->BySlot.begin(), this->BySlot.end(), [&in](uint32_t a, uint32_t b)
      { return in.Objects[a].SlotStart < in.Objects[b].SlotStart; });
  }

  /// Object and leaf cell of primitive p of the triangle index buffer.
  const Object* Decode(size_t p, vtkIdType& leafCell)
  {
    const Internals& in = this->In;
    auto it = std::upper_bound(this->BySlot.begin(), this->BySlot.end(), p,
      [&in](size_t q, uint32_t i) { return q < in.Objects[i].SlotStart; });
    if (it == this->BySlot.begin())
    {
      return nullptr;
    }
    const size_t index = *std::prev(it);
    const Object& object = in.Objects[index];
    const size_t k = p - object.SlotStart;
    if (k >= object.SlotUsed)
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
        if (in.Representation == VTK_SURFACE)
        {
          leafCell = polyBase + in.StaticTriangleCells[object.TriangleStart + k];
        }
        else
        {
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
          leafCell = polyBase + c;
        }
        return &object;
      default:
        return nullptr;
    }
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

  const Internals& In;
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
    // Process ids from a point array of the leaves, by the drawn vertex.
    unsigned char* out = sel->GetRawPixelBuffer(pass);
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
  Internals::Selection selection(in);
  auto cellHit = [&](unsigned int pos, vtkIdType& leafCell) -> const Internals::Object*
  {
    const size_t raw = ReadPixelId(cellLow, cellHigh, pos);
    if (in.LayoutValid && raw >= triBase && raw < triBase + in.Tail)
    {
      return selection.Decode(raw - triBase, leafCell);
    }
    if (!in.HasOtherCells)
    {
      return nullptr;
    }
    const vtkIdType merged =
      this->CellCellMap->ConvertOpenGLCellIdToVTKCellId(false, static_cast<vtkIdType>(raw));
    return in.ObjectOfOtherCell(merged, leafCell);
  };

  if ((pass == vtkHardwareSelector::POINT_ID_LOW24 ||
        pass == vtkHardwareSelector::POINT_ID_HIGH24) &&
    pointLow && (pass == vtkHardwareSelector::POINT_ID_LOW24 || pointHigh))
  {
    unsigned char* out = sel->GetPixelBuffer(pass);
    for (const unsigned int pos : pixeloffsets)
    {
      const vtkIdType vertex = ReadPixelId(pointLow, pointHigh, pos);
      const Internals::Object* object = in.ObjectOfVertex(vertex);
      if (!out || !object)
      {
        continue;
      }
      vtkIdType id = vertex - object->VertexOffset;
      vtkIdTypeArray* ids = this->PointIdArrayName
        ? vtkArrayDownCast<vtkIdTypeArray>(object->Leaf->GetPointData()->GetArray(this->PointIdArrayName))
        : nullptr;
      if (ids && id < ids->GetNumberOfTuples())
      {
        id = ids->GetValue(id);
      }
      WritePixelId(out, pos, id, pass == vtkHardwareSelector::POINT_ID_LOW24 ? 0 : 24);
    }
  }

  if ((pass == vtkHardwareSelector::CELL_ID_LOW24 || pass == vtkHardwareSelector::CELL_ID_HIGH24) &&
    !pointField && cellLow && (pass == vtkHardwareSelector::CELL_ID_LOW24 || cellHigh))
  {
    unsigned char* out = sel->GetPixelBuffer(pass);
    for (const unsigned int pos : pixeloffsets)
    {
      vtkIdType id = 0;
      const Internals::Object* object = cellHit(pos, id);
      if (!out || !object)
      {
        continue;
      }
      vtkIdTypeArray* ids = this->CellIdArrayName
        ? vtkArrayDownCast<vtkIdTypeArray>(object->Leaf->GetCellData()->GetArray(this->CellIdArrayName))
        : nullptr;
      if (ids && id < ids->GetNumberOfTuples())
      {
        id = ids->GetValue(id);
      }
      WritePixelId(out, pos, id, pass == vtkHardwareSelector::CELL_ID_LOW24 ? 0 : 24);
    }
  }

  // Polydata input keeps the superclass's composite value.
  if (pass == vtkHardwareSelector::COMPOSITE_INDEX_PASS &&
    vtkCompositeDataSet::SafeDownCast(in.Input) && (pointField ? pointLow : cellLow))
  {
    unsigned char* out = sel->GetPixelBuffer(pass);
    for (const unsigned int pos : pixeloffsets)
    {
      vtkIdType cell = -1;
      const Internals::Object* object = pointField
        ? in.ObjectOfVertex(ReadPixelId(pointLow, pointHigh, pos))
        : cellHit(pos, cell);
      if (!out || !object)
      {
        continue;
      }
      vtkIdType value = object->FlatIndex;
      vtkUnsignedIntArray* values = this->CompositeIdArrayName && cell >= 0
        ? vtkArrayDownCast<vtkUnsignedIntArray>(
            object->Leaf->GetCellData()->GetArray(this->CompositeIdArrayName))
        : nullptr;
      if (values && cell < values->GetNumberOfTuples())
      {
        value = values->GetValue(cell);
      }
      WritePixelId(out, pos, value, 0);
    }
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
  os << indent << "IndexSlack: " << this->IndexSlack << "\n";
  os << indent << "NumberOfRewrittenObjects: " << this->NumberOfRewrittenObjects << "\n";
  os << indent << "IndexBytesUploaded: " << this->IndexBytesUploaded << "\n";
  os << indent << "CellDataBytesUploaded: " << this->CellDataBytesUploaded << "\n";
  os << indent << "NumberOfPaddingPrimitives: " << this->NumberOfPaddingPrimitives << "\n";
  os << indent << "IndexBufferRelayoutCount: " << in.RelayoutCount << "\n";
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
