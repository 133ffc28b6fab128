// SPDX-License-Identifier: BSD-3-Clause
/**
 * The state of vtkMultiresolutionPolyDataMapper shared by its implementation
 * files (private header, not installed): the objects read from the input and
 * their TOM copies (Objects.cxx), the view-dependent fronts (Fronts.cxx),
 * the vertex buffers appended from the leaves (VertexBuffers.cxx), the index
 * buffer's per-object slots (IndexBuffer.cxx, IndexSlots.cxx, laid out by
 * timecritical::IndexSlotAllocator), scalar colors, cell textures and the
 * resolution map (Colors.cxx), block attributes (Blocks.cxx) and hardware
 * selection (Selection.cxx).
 */
#ifndef vtkMultiresolutionPolyDataMapperInternals_h
#define vtkMultiresolutionPolyDataMapperInternals_h

#include "vtkMultiresolutionPolyDataMapper.h"

#include "IndexSlotAllocator.h"
#include "RefinementSettings.h"
#include "TOMTraversal.h"
#include "ViewDependentRefinement.h"
#include "vtkHierarchyBuildQueue.h"
#include "vtkTOMFieldData.h"

#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkNew.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkProperty.h" // for VTK_SURFACE
#include "vtkTextureObject.h"
#include "vtkUnsignedCharArray.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkSmartPointer.h"
#include "vtkStateStorage.h"
#include "vtkTimeStamp.h"

#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

class vtkDataArray;
class vtkOpenGLRenderWindow;
class vtkPolyData;
class vtkUnsignedCharArray;
class vtkMergeTreeFieldData;
class vtkTOMFieldData;

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

  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkMultiresolutionReleaseProxy();
  ~vtkMultiresolutionReleaseProxy() override = default;

private:
  vtkMultiresolutionReleaseProxy(const vtkMultiresolutionReleaseProxy&) = delete;
  void operator=(const vtkMultiresolutionReleaseProxy&) = delete;
};

namespace vtkMultiresolutionMapperDetail
{
/// Grows v to at least `size` elements (grow-only buffers: no allocation once grown).
template <typename T>
void Grow(std::vector<T>& v, size_t size)
{
  if (v.size() < size)
  {
    v.resize(size);
  }
}

/**
 * Adds to a vertex shader's source a uniform declaration and a test that
 * moves the vertex outside the clip volume when `condition` holds: a
 * primitive all of whose vertices are moved is never rasterized.
 */
void AddVertexDiscard(std::string& source, const char* declaration, const char* condition);

/// Writes the display vertices of a front (plus base); returns how many.
size_t WriteDisplayVertices(
  const timecritical::ViewDependentRefinement& front, uint32_t base, uint32_t* out);

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
}

struct vtkMultiresolutionPolyDataMapper::Internals
{
  using Content = vtkMultiresolutionMapperDetail::Content;
  using ContentKind = vtkMultiresolutionMapperDetail::ContentKind;
  using Range = timecritical::IndexSlotAllocator::Range;
  using Slot = timecritical::IndexSlotAllocator::Slot;

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
    // Its slot in the index buffer is Slots.GetSlot(its index).
    Content Written;        // what the slot holds
    bool Rewritten = false; // by the last render
    // Block attributes (vtkCompositeDataDisplayAttributes, inherited from
    // parent blocks; Blocks.cxx). An invisible object is culled; an
    // unpickable one is left out of selection passes (Selection.cxx).
    bool Visible = true;
    bool Pickable = true;
    bool HasBlockColor = false;
    bool HasBlockOpacity = false;
    double BlockColor[3] = { 1.0, 1.0, 1.0 };
    double BlockOpacity = 1.0;
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
  bool CellData = false;
  bool Corners = false; // points with cell data: one point per triangle corner
  bool VertexVisibility = false;
  timecritical::IndexSlotAllocator Slots; // one per object, in primitives
  std::vector<size_t> FullPrimitives;     // per object, at full resolution
  std::vector<Range> DirtyIndices;        // rewritten by this update (primitives)
  std::vector<Range> DirtyTexels;         // cells rewritten by this update (primitives)
  size_t TexelBase = 0; // texel of primitive 0 (non-TOM vertices and lines first)
  size_t Texels = 0;
  bool FloatCellNormals = true;
  uint32_t StagedTriangles = 0;         // of the TOM prefix extracted into Scratch
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
  // Block attributes (Blocks.cxx): applied for these attributes (MTime) and
  // objects (the skeleton of their read, held so that its address is not reused).
  vtkSmartPointer<vtkCompositeDataDisplayAttributes> BlockAttributes;
  vtkMTimeType BlockAttributesTime = 0;
  vtkSmartPointer<vtkPolyData> BlockSkeleton;
  // Block mode: some object has a block color or opacity (or hides vertices,
  // lines or strips), so the mapper draws BlockColors, one RGBA per vertex
  // (or per cell with cell scalars): the scalar colors (BaseColors) or the
  // property's color, replaced by block colors, alpha times block opacity,
  // 0 for invisible objects. Rewritten per object when attributes change.
  bool BlockMode = false;
  bool BlockCells = false;        // BlockColors are per cell
  bool BlockColorsStale = true;   // rebuild all of BlockColors at the next map
  bool BlockColorsDirty = false;  // objects' ColorDirty ranges not on the GPU yet
  bool AnyTranslucentBlock = false;
  bool AnyOpaqueBlock = false;
  vtkSmartPointer<vtkUnsignedCharArray> BlockColors;
  vtkSmartPointer<vtkUnsignedCharArray> BaseColors;
  vtkMTimeType BlockBaseTime = 0;
  double BlockPropertyColor[4] = { -1.0, -1.0, -1.0, -1.0 };
  // Block pickability (Selection.cxx): while some object is unpickable,
  // selection passes read a flag per vertex (0 for the vertices of
  // unpickable objects) from a texture buffer at gl_VertexID and drop
  // those vertices in the vertex shader, so that an unpickable block is not
  // drawn by selection passes, as in vtkCompositePolyDataMapper2.
  bool AnyUnpickable = false;
  bool PickFlagsStale = true;         // rewrite and upload the flags before the next selection
  vtkTimeStamp PickabilityModeTime;   // AnyUnpickable changed: selection shaders rebuilt
  vtkSmartPointer<vtkTextureObject> PickTexture;
  vtkSmartPointer<vtkOpenGLBufferObject> PickBuffer;
  bool PickTextureActive = false;
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

  // Background builds (Background.cxx): the queue, the finished hierarchies
  // of current leaves by key (the leaves' content hashes, kept in their
  // LeafFacts) and the keys whose build failed (drawn in full), the keys of
  // the last read (with their block, for messages), and results taken
  // (grow-only).
  vtkSmartPointer<vtkHierarchyBuildQueue> Queue;
  std::map<uint64_t, vtkSmartPointer<vtkPolyData>> Built;
  // Stand-ins drawn while pending (null: the leaf itself), by key.
  std::map<uint64_t, vtkSmartPointer<vtkPolyData>> Interims;
  static constexpr vtkIdType InterimMinimumTriangles = 4096; // below: drawn in full
  std::set<uint64_t> Failed;
  std::vector<std::pair<uint64_t, unsigned int>> CurrentKeys;
  std::vector<vtkHierarchyBuildQueue::Result> Taken;
  int PendingHierarchies = 0;
  // Every swap reads all objects again (a stall on large inputs): while builds
  // go on, finished ones are swapped in at most once per SwapInterval.
  static constexpr double SwapInterval = 2.0; // seconds
  std::chrono::steady_clock::time_point LastSwap;
  bool ForceRead = false;       // a background setting changed: read the objects again
  bool BackgroundReset = false; // forget the builds at the next read

  // What a read learns of a leaf that stays true while the leaf is not
  // modified: the validator's verdict, the cells' bounds and (background
  // builds) the content hash. Swapping in finished builds reads every leaf
  // again; the unchanged ones are not checked or hashed again. Entries of
  // this read and of the previous one (kept with their leaves, so that the
  // addresses stay theirs).
  struct LeafFacts
  {
    vtkSmartPointer<vtkPolyData> Leaf;
    vtkMTimeType Time = 0;
    std::string Problem; // vtkPolyDataValidator::Check's verdict
    double Bounds[6] = { 1, -1, 1, -1, 1, -1 };
    bool Hashed = false; // Key is the leaf's content hash
    uint64_t Key = 0;
  };
  std::unordered_map<vtkPolyData*, LeafFacts> Facts;
  std::unordered_map<vtkPolyData*, LeafFacts> PreviousFacts;
  LeafFacts& FactsOf(vtkPolyData* leaf);
  // The TOM reader, remembering which arrays validated (see vtkTOMFieldData).
  vtkNew<vtkTOMFieldData> Reader;

  bool WarnedNonTOM = false;
  bool WarnedBadTree = false;
  bool WarnedNonPolyData = false;
  // Selection display: the leaf whose nodes BuildSelectionIBO adds.
  bool SelectionByFlatIndex = false;
  unsigned int SelectionFlatIndex = 0;
  vtkIdType VertexBufferBuildCount = 0;
  vtkIdType IndexBufferBuildCount = 0;

  size_t IndexOf(const Object& object) const
  {
    return static_cast<size_t>(&object - this->Objects.data());
  }
  const Slot& SlotOf(const Object& object) const
  {
    return this->Slots.GetSlot(this->IndexOf(object));
  }

  // Reading (Objects.cxx). Leaves are (polydata, flat index) pairs.
  using Leaves = std::vector<std::pair<vtkPolyData*, unsigned int>>;
  /// Where the next object's vertices and cells start among all leaves'.
  struct Offsets
  {
    vtkIdType Vertex = 0;
    vtkIdType Vert = 0;
    vtkIdType Line = 0;
    vtkIdType Strip = 0;
    vtkIdType Cell = 0;
  };
  /// A TOM's arrays are copied once per pair of (cells, TOMSubstitution)
  /// arrays: the pair, and where the copy starts (substitution, triangle).
  using TOMKey = std::pair<const void*, const void*>;
  using TOMCopies = std::map<TOMKey, std::pair<size_t, size_t>>;
  static TOMKey KeyOfTOM(vtkPolyData* poly);

  void ReleaseObjects(vtkDataObject* input);
  Leaves CollectLeaves(vtkMultiresolutionPolyDataMapper* self, vtkDataObject* input);
  void ReserveTOMCopies(const Leaves& leaves);
  static Object StartObject(vtkPolyData* poly, unsigned int flatIndex, const Offsets& offsets);
  void ReadTOM(Object& object, vtkTOMFieldData* reader, TOMCopies& copies);
  void ReadNonTOM(Object& object, vtkMultiresolutionPolyDataMapper* self, vtkTOMFieldData* reader,
    bool explained);
  void ReadMergeTree(
    Object& object, vtkMultiresolutionPolyDataMapper* self, vtkMergeTreeFieldData* treeReader);
  void AddObject(Object&& object, const std::vector<double>& previous, Offsets& offsets);
  void FinishObjects(const Offsets& offsets);
  void BuildSkeleton();

  // Background builds (Background.cxx): each leaf that needs a hierarchy is
  // replaced by its finished build, or submitted; `explained` marks those
  // drawn without one for a known reason (pending, or failed with an error).
  void SubstituteBuiltLeaves(vtkMultiresolutionPolyDataMapper* self, Leaves& leaves,
    std::vector<char>& explained);
  uint64_t KeyOf(vtkPolyData* leaf); ///< the leaf's content hash, computed once per unmodified leaf
  vtkPolyData* InterimOf(vtkPolyData* leaf, uint64_t key, int divisions);
  void ClearBackground(bool read); ///< a setting changed; read: read the leaves again
  void ForgetBuilds();              ///< at a read, once no object draws them

  // View-dependent fronts (Fronts.cxx): refines one front for the view;
  // returns whether it moved.
  static bool RefineFront(Object& object, const timecritical::RefinementView& view,
    const timecritical::RefinementSettings& settings, double limit);
  // The mapper's refinement settings in the shared settings type.
  static timecritical::RefinementSettings GetSettings(const vtkMultiresolutionPolyDataMapper& mapper);
  // The renderer's camera, viewport, frustum and first light in the leaves' coordinates.
  static timecritical::RefinementView ComputeView(vtkRenderer* ren, vtkActor* act);

  // Vertex buffers (VertexBuffers.cxx): appends every leaf's array of an
  // attribute, read by `get` (with `name`), to the vertex buffer group.
  using LeafArrayGetter = vtkDataArray* (*)(vtkPolyData*, const char*);
  using AppendedAttributes = std::vector<std::pair<std::string, int>>; // name, components
  void AppendLeafArrays(vtkMultiresolutionPolyDataMapper* self, const char* attribute,
    LeafArrayGetter get, const char* name, AppendedAttributes& appended) const;

  // Hardware selection (Selection.cxx): which object drew a primitive or
  // vertex, and its leaf's ids.
  struct Selection;
  const Object* ObjectOfVertex(vtkIdType vertex) const;
  const Object* ObjectOfOtherCell(vtkIdType cell, vtkIdType& leafCell) const;
  const Object* ObjectOfCell(vtkIdType cell) const; ///< cell in leaf order (Object::CellOffset)

  // Block attributes (Blocks.cxx): the walk that gives each object its block's.
  struct BlockWalk;

  // Index slots (IndexSlots.cxx).
  Content Describe(const Object& object, bool viewDependent) const;
  size_t Stage(Object& object, const Content& content);
  void Emit(const Object& object, const Content& content, size_t used, uint32_t* out,
    vtkIdType* cells) const;
  void EmitFront(const Object& object, size_t used, uint32_t* out, vtkIdType* cells) const;
  void EmitPrefix(const Object& object, const Content& content, size_t used, uint32_t* out,
    vtkIdType* cells) const;
  void EmitWhole(const Object& object, uint32_t* out, vtkIdType* cells) const;
  void SetRenderedCounts(Object& object, const Content& content) const;
  void FillDegenerate(size_t start, size_t count, uint32_t vertex);
  void WriteSlot(Object& object, const Content& content, size_t used, size_t extent);
  void ClearSlot(Object& object);
  bool Update(Object& object, const Content& content, double slack);
  void LayOut(bool viewDependent, double slack);
  void Compact(double slack);
};

#endif
