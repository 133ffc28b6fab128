// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkMultiresolutionPolyDataMapper
 * @brief   draws many Totally Ordered Meshes, each at its own resolution, in O(1) draw calls
 *
 * Input is a vtkPolyData or a composite dataset (vtkMultiBlockDataSet,
 * vtkPartitionedDataSet, vtkPartitionedDataSetCollection). Every non-empty
 * polydata leaf is an *object* with its own resolution, numbered in the
 * composite iteration order (0 for polydata input).
 *
 * Why one draw call: a draw call has a fixed cost on the CPU, so hundreds of
 * objects drawn separately can cost more than the frame budget before a
 * single triangle is rasterized. All leaves are concatenated once into one
 * vertex buffer group (positions, normals, scalars, texture coordinates, in
 * leaf order, appended from the leaves themselves: the mapper keeps no merged
 * copy of them), and one index buffer holds a *slot* per object: its active
 * triangles (written by the TOM traversal core with the object's vertex
 * offset added), then degenerate triangles (all three indices equal: no
 * fragments) as room to grow (IndexSlack). A frame rewrites only the slots of
 * objects whose mesh changed and uploads only those ranges (glBufferSubData);
 * unchanged objects are neither extracted nor uploaded. An object that
 * outgrows its slot moves to a free range; padding is compacted (slots moved,
 * not extracted again) when it exceeds twice a fresh layout's. Nothing is
 * allocated per frame. A resolution of 0 leaves the object out (culled).
 * A degenerate triangle is far cheaper to draw than a real one (it is
 * rejected before rasterization), so padding costs little drawing time.
 * The slots are laid out by timecritical::IndexSlotAllocator.
 *
 * Otherwise it behaves like VTK's polydata mapper: scalar coloring, lighting,
 * surface/wireframe/points representation, software picking (vtkCellPicker
 * reports the composite flat index and the leaf's cell id, at full resolution).
 * Set composite input with SetInputDataObject() or SetInputConnection().
 * Point and cell data arrays are those common to all leaves (as
 * vtkAppendPolyData keeps them). Cell colors and cell normals stay right at
 * every resolution: VTK looks them up by primitive id (gl_PrimitiveID, which
 * counts degenerate primitives too), so their textures follow the slots and
 * are rewritten with them (only when cell data is used).
 *
 * Resolutions are render state: setting them does not Modified() the mapper
 * (that would rebuild every buffer and recompile shaders); the next render
 * rewrites the slots of the objects whose mesh changed.
 *
 * ColorByResolution draws the papers' resolution maps: each object in one
 * grey level, 0.25 + 0.75 f with f its drawn fraction of triangles quantized
 * to 64 levels (lighter = more detail), lit like any surface. The grey levels
 * are a point color array of this mapper: in map mode the color buffer
 * follows the resolutions, and only the vertices of objects whose level
 * changed are rewritten in place. Turning it off restores normal coloring.
 *
 * View-dependent refinement: a leaf that also carries a merge tree (the
 * output of vtkMergeTreeBuilder) is drawn as a view-dependent front
 * (timecritical::ViewDependentRefinement, Xia, El-Sana & Varshney) refined
 * for the renderer's active camera at every render, from the previous front.
 * In BUDGET mode (default) the front gets the object's resolution times its
 * triangle count, spent where the projected error is largest; in
 * FIXED_ACCURACY mode it is refined until no projected error exceeds
 * PixelThreshold pixels, whatever it costs (a resolution of 0 still culls).
 * The vertex buffer stays static: only the object's slot follows its front.
 * With ColorByResolution such an object is drawn in the grey of each
 * vertex's merge-tree level (lighter = finer), which shows the local level of
 * detail.
 *
 * Leaves that are not valid TOMs render at full resolution with one warning
 * per mapper; their vertices, lines and strips are always drawn in full (in
 * extra draw calls, whatever their resolution) and edge flags are ignored.
 *
 * Block attributes (vtkCompositeDataDisplayAttributes, as ParaView's
 * Multiblock Inspector sets them) are honoured as vtkCompositePolyDataMapper2
 * does, with attributes of a parent block applying to its children: a hidden
 * block is culled whatever its resolution (and vtkTimeCriticalRenderer spends
 * no budget on it); a block color replaces the scalar coloring of that
 * block; a block opacity below 1 makes the block translucent. Colors and
 * opacities are drawn as one RGBA color per vertex (per cell with cell
 * scalars) in the same draw call: the vertex shader (the fragment shader
 * with cell colors) drops translucent objects from the opaque pass and
 * opaque ones from the translucent pass.
 * Attributes are render state: a change rewrites the colors of the blocks
 * that changed (a visibility change their index slots) and nothing else.
 * An unpickable block (pickability, inherited like the others) is drawn but
 * never selected: hardware selection passes do not draw it (its vertices are
 * dropped by the vertex shader through a flag per vertex), so that, as with
 * vtkCompositePolyDataMapper2, what lies behind it can be selected through
 * it (cells; a point selection's depth comes from a normal render, which
 * draws it).
 *
 * Hardware selection (vtkHardwareSelector, ParaView's area selection)
 * reports each leaf's flat index (composite input) and the leaf's own cell
 * and point ids of what the last frame drew, at any resolution and for
 * view-dependent fronts: selection passes neither refine fronts nor apply
 * resolution changes, so that every pass draws, and is decoded against, the
 * same slots. In the points representation a cell selection reports, for
 * each drawn vertex, the first drawn triangle that uses it.
 *
 * Limitations: selection's point passes draw the padding as points at the
 * first vertex of an object (possibly a culled one). Selection display
 * (vtkMapper::SetSelection) outlines the selected cells at full resolution.
 * Points have no degenerate form: in the points representation slots fit
 * exactly and a change of any object's point count lays the buffer out
 * again. Memory above the input: the TOM arrays copied for the traversal
 * (once per distinct mesh: 12 bytes per triangle and 4 per vertex), the
 * mapped colors (4 bytes per vertex, or per cell), the index buffer (up to
 * 12 bytes per full-resolution triangle on the CPU and on the GPU: its
 * capacity) and cell textures (4 or 16 bytes per full-resolution primitive);
 * the vertex buffers' CPU packing is freed once uploaded, so rebuilding them
 * (a leaf changed, camera-based shift and scale moved) appends the leaves
 * again. A change of colors alone re-uploads the color buffer only.
 *
 * @sa vtkTOMPolyDataMapper vtkTimeCriticalRenderer vtkTOMBuilder
 */
#ifndef vtkMultiresolutionPolyDataMapper_h
#define vtkMultiresolutionPolyDataMapper_h

#include "TimeCriticalRenderingModule.h" // for export macro
#include "vtkOpenGLPolyDataMapper.h"

#include <chrono>  // for TakeObjectReadTime
#include <map>     // for ReplaceShaderValues
#include <memory>  // for std::unique_ptr
#include <string>  // for UploadLeafBuffers
#include <utility> // for UploadLeafBuffers
#include <vector>  // for ProcessSelectorPixelBuffers

class vtkCompositeDataDisplayAttributes;
class vtkHierarchyBuildQueue;
class vtkShaderProgram;
class vtkStateStorage;

class TIMECRITICALRENDERING_EXPORT vtkMultiresolutionPolyDataMapper : public vtkOpenGLPolyDataMapper
{
public:
  static vtkMultiresolutionPolyDataMapper* New();
  vtkTypeMacro(vtkMultiresolutionPolyDataMapper, vtkOpenGLPolyDataMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Bring the input up to date and (re)read its objects when it changed.
   * Rendering does this itself; call it to query objects before the first
   * render (vtkTimeCriticalRenderer does). Resolutions of objects that keep
   * their index survive a re-read; new objects start at 1.
   */
  void UpdateObjects();

  /// Objects found by the last UpdateObjects() or render.
  vtkIdType GetNumberOfObjects() const;

  ///@{
  /**
   * Resolution of object i: fraction of its full triangle count, in [0, 1];
   * values in (0, coarsest] draw the coarsest mesh, 0 draws nothing. Out of
   * range indices and NaN are reported with an error and ignored.
   */
  void SetObjectResolution(vtkIdType i, double r);
  double GetObjectResolution(vtkIdType i) const;
  ///@}

  /// Set every object's resolution.
  void SetResolution(double r);

#ifndef __VTK_WRAP__
  /// Set resolutions of objects [0, n) from r (n must equal GetNumberOfObjects()).
  void SetObjectResolutions(const double* r, vtkIdType n);
#endif

  ///@{
  /// Per-object data (valid after UpdateObjects()).
  void GetObjectBounds(vtkIdType i, double bounds[6]) const;
  vtkIdType GetObjectNumberOfTriangles(vtkIdType i) const; ///< at full resolution
  vtkIdType GetObjectNumberOfVertices(vtkIdType i) const;  ///< at full resolution
  double GetObjectCoarsestResolution(vtkIdType i) const; ///< base triangles / all; 1 when not a TOM
  bool GetObjectIsTOM(vtkIdType i) const;
  unsigned int GetObjectFlatIndex(vtkIdType i) const; ///< composite flat index (0 for polydata)
  vtkIdType GetObjectRenderedTriangles(vtkIdType i) const; ///< drawn by the last render
  vtkIdType GetObjectRenderedVertices(vtkIdType i) const;  ///< drawn by the last render
  ///@}

  ///@{
  /// Totals of the last render.
  vtkGetMacro(RenderedTriangles, vtkIdType);
  vtkGetMacro(RenderedVertices, vtkIdType);
  vtkGetMacro(NumberOfDrawCalls, int);
  ///@}

  ///@{
  /**
   * Index updates of the last render: objects whose index data was rewritten
   * (all drawn ones when the buffer was laid out again), bytes uploaded to
   * the index buffers and to the cell-data textures, and the CPU seconds of
   * the update (extraction, writes and upload calls). All 0 when nothing changed.
   */
  vtkGetMacro(NumberOfRewrittenObjects, vtkIdType);
  bool GetObjectRewritten(vtkIdType i) const;
  vtkGetMacro(IndexBytesUploaded, vtkIdType);
  vtkGetMacro(CellDataBytesUploaded, vtkIdType);
  vtkGetMacro(IndexUpdateTime, double);
  ///@}

  /// Degenerate primitives (slot padding and holes) drawn by the last render.
  vtkGetMacro(NumberOfPaddingPrimitives, vtkIdType);

  ///@{
  /**
   * Block attributes of composite input (visibility, pickability, color,
   * opacity), keyed
   * by the input's data objects as in vtkCompositePolyDataMapper2; none by
   * default. Changes apply at the next render without rebuilding buffers.
   * The flat-index setters create the attributes when there are none and
   * report an error for a flat index that names no block of the input.
   */
  void SetCompositeDataDisplayAttributes(vtkCompositeDataDisplayAttributes* attributes);
  vtkCompositeDataDisplayAttributes* GetCompositeDataDisplayAttributes();
  void SetBlockVisibility(unsigned int flatIndex, bool visible);
  void SetBlockColor(unsigned int flatIndex, double r, double g, double b);
  void SetBlockOpacity(unsigned int flatIndex, double opacity);
  void SetBlockPickability(unsigned int flatIndex, bool pickable);
  bool GetObjectVisibility(vtkIdType i) const; ///< false: a hidden block
  bool GetObjectPickability(vtkIdType i) const; ///< false: never selected
  ///@}

  /// Bytes of vertex colors rewritten in place by the last render (resolution map, block colors).
  vtkGetMacro(ColorBytesUploaded, vtkIdType);

  /// Full layouts of the index buffer so far (rebuilds and compactions).
  vtkIdType GetIndexBufferRelayoutCount() const;

  ///@{
  /**
   * Room reserved in each object's index slot, as a fraction of its drawn
   * primitives (plus 8), so that it can grow without moving; padding is
   * compacted once it exceeds twice that. Default 0.1. 0: every slot fits
   * exactly, and any change of an object's size lays the buffer out again.
   */
  vtkSetClampMacro(IndexSlack, double, 0.0, 4.0);
  vtkGetMacro(IndexSlack, double);
  ///@}

  ///@{
  /// Resolution map: grey level per object, lighter = more detail. Default off.
  vtkSetMacro(ColorByResolution, bool);
  vtkGetMacro(ColorByResolution, bool);
  vtkBooleanMacro(ColorByResolution, bool);
  ///@}

  enum RefinementModes
  {
    BUDGET = 0,        ///< triangle budget = resolution x full triangle count
    FIXED_ACCURACY = 1 ///< refine until the projected error is below PixelThreshold
  };

  ///@{
  /**
   * View-dependent refinement of leaves that carry a merge tree (default on).
   * Off: they are drawn as plain TOMs (uniform prefix at their resolution).
   * These settings, like the resolutions, are render state: they change the
   * index buffer only and do not modify the mapper.
   */
  void SetViewDependentRefinement(bool on);
  vtkGetMacro(ViewDependentRefinement, bool);
  vtkBooleanMacro(ViewDependentRefinement, bool);
  void SetRefinementMode(int mode); ///< clamped to [BUDGET, FIXED_ACCURACY]
  vtkGetMacro(RefinementMode, int);
  void SetRefinementModeToBudget() { this->SetRefinementMode(BUDGET); }
  void SetRefinementModeToFixedAccuracy() { this->SetRefinementMode(FIXED_ACCURACY); }
  ///@}

  ///@{
  /**
   * BUDGET mode: seconds the fronts of this mapper may spend refining per
   * render (0, the default: no limit). Splits and merges cost about the same
   * each, so a front moves towards its budget by at most the triangles that
   * fit in the limit at its measured rate, and reaches it over a few frames
   * after a large change instead of in one long frame (the paper's
   * frame-to-frame coherence). vtkTimeCriticalRenderer sets it.
   */
  void SetRefinementTimeLimit(double seconds);
  vtkGetMacro(RefinementTimeLimit, double);
  ///@}

  ///@{
  /**
   * Screen-space error threshold tau, pixels, finite and >= 0; default 1.
   * FIXED_ACCURACY: fronts are refined until no projected error exceeds it.
   * BUDGET: a floor, detail below it is not bought even when the budget
   * allows (0 spends the whole budget). Near silhouettes and highlights it is
   * multiplied by their factors.
   */
  void SetPixelThreshold(double tau);
  vtkGetMacro(PixelThreshold, double);
  ///@}

  ///@{
  /// Regions whose normal cone faces away from the viewer are not refined (default on).
  void SetBackFaceSimplification(bool on);
  vtkGetMacro(BackFaceSimplification, bool);
  vtkBooleanMacro(BackFaceSimplification, bool);
  ///@}

  ///@{
  /// Finer threshold (tau times the factor, in (0, 1]) near silhouettes (default on, 0.25).
  void SetSilhouetteRefinement(bool on);
  vtkGetMacro(SilhouetteRefinement, bool);
  vtkBooleanMacro(SilhouetteRefinement, bool);
  void SetSilhouetteFactor(double factor);
  vtkGetMacro(SilhouetteFactor, double);
  ///@}

  ///@{
  /// Finer threshold near specular highlights of the first light (default on, 0.5).
  void SetHighlightRefinement(bool on);
  vtkGetMacro(HighlightRefinement, bool);
  vtkBooleanMacro(HighlightRefinement, bool);
  void SetHighlightFactor(double factor);
  vtkGetMacro(HighlightFactor, double);
  ///@}

  ///@{
  /// Per-object refinement statistics of the last render (0 for objects without a merge tree).
  bool GetObjectIsViewDependent(vtkIdType i) const; ///< carries a merge tree and refinement is on
  vtkIdType GetObjectSplits(vtkIdType i) const;
  vtkIdType GetObjectMerges(vtkIdType i) const;
  double GetObjectRefinementTime(vtkIdType i) const; ///< seconds
  ///@}

  /// Seconds spent refining all view-dependent objects in the last render.
  vtkGetMacro(RefinementTime, double);

  ///@{
  /**
   * Background hierarchy builds (default off). On: polydata leaves that
   * carry no hierarchy (no TOM arrays; with BackgroundHierarchy MERGE_TREE,
   * no merge tree) are drawn at once, in full as fixed-cost objects, while
   * their hierarchy is built on worker threads (vtkHierarchyBuildQueue,
   * keyed by the leaf's content hash, so equal leaves are built once). The
   * first UpdateObjects() or render after a build finished swaps the
   * hierarchy in: the objects are read again and the buffers rebuilt,
   * without executing the pipeline (the object then becomes a TOM, or a
   * view-dependent front). Large leaves are drawn meanwhile from a quick
   * reduction (BackgroundInterimDivisions), also as fixed-cost objects. The builders' messages are reported then, on the
   * caller's thread; a leaf whose build fails stays drawn in full. A new
   * input cancels the builds of leaves it no longer has. Picking and
   * selection report the ids of what is drawn: the leaf's own until the
   * swap, the hierarchy's (reordered, with vtkOriginalCellIds carried)
   * after. The leaves' arrays are read by the workers while the mapper
   * holds them: a pipeline must not refill the same arrays in place while
   * builds run (VTK's and ParaView's filters make new ones at each
   * execution). Off: such leaves are drawn in full, as before.
   */
  void SetBackgroundBuilds(bool on);
  vtkGetMacro(BackgroundBuilds, bool);
  vtkBooleanMacro(BackgroundBuilds, bool);
  /**
   * While its build is pending, a leaf of at least 4096 triangles is drawn
   * from a quick stand-in instead of in full: vtkBinnedDecimation on a grid
   * of about this many bins a side, on the leaf's own points (made once per
   * leaf on the rendering thread: on a 700K-triangle surface 4% of the
   * triangles in under 0.1 s, against 1.5 s for the TOM, drawn 7 times
   * faster than the leaf in full; docs/rendering.md). Default 64; 0 draws
   * pending leaves in full. Stand-ins have the leaf's point data and the
   * cell data of the triangles they keep; picking reports those.
   */
  void SetBackgroundInterimDivisions(int divisions);
  vtkGetMacro(BackgroundInterimDivisions, int);
  /// vtkHierarchyBuildQueue::Hierarchies: TOTALLY_ORDERED_MESH (0, default) or MERGE_TREE (1).
  void SetBackgroundHierarchy(int hierarchy);
  vtkGetMacro(BackgroundHierarchy, int);
  /**
   * Leaves drawn without their hierarchy while its build is pending
   * (queued, running, or finished and not yet swapped in), as of the last
   * UpdateObjects() or render.
   */
  int GetNumberOfPendingHierarchies() const;
  /// Hierarchies swapped in so far (each leaf's build once it is used).
  vtkGetMacro(NumberOfSwappedHierarchies, vtkIdType);
  /**
   * Builds the background workers finished, and leaves they found in the
   * process's hierarchy cache instead of building, so far (0 before the first
   * background build).
   */
  vtkIdType GetNumberOfBackgroundBuilds();
  vtkIdType GetNumberOfBackgroundCacheHits();
  /**
   * Block until every pending build of the current leaves has finished and
   * is swapped in (for scripts and tests that need the final image). Does
   * nothing when BackgroundBuilds is off.
   */
  void WaitForHierarchies();
#ifndef __VTK_WRAP__
  /**
   * The mapper's build queue (created with the first background build):
   * its thread count, result store, statistics and test hooks.
   */
  vtkHierarchyBuildQueue* GetBuildQueue();
#endif
  ///@}

  ///@{
  /**
   * Work outside the budget's model, for the renderer to count as spent:
   * reads of the objects so far (each new input, changed leaf or swap of
   * finished builds reads them all), the seconds of the last vertex buffer
   * build (a read is followed by one at the next draw; 0 before the first),
   * and (C++) the seconds of the reads since the last TakeObjectReadTime(),
   * 0 when the last of them ended before `frameStart` (reads outside the
   * frame, as a ResetCamera() before it). Taking starts the count again: the
   * renderer that plans the frames takes it once per frame.
   */
  vtkGetMacro(NumberOfObjectReads, vtkIdType);
  vtkGetMacro(LastVertexBufferBuildTime, double);
#ifndef __VTK_WRAP__
  double TakeObjectReadTime(std::chrono::steady_clock::time_point frameStart);
#endif
  ///@}

  /// Bounds of the whole input (all leaves).
  void ComputeBounds() override;
  double* GetBounds() VTK_SIZEHINT(6) override;
  void GetBounds(double bounds[6]) override
  {
    this->Superclass::GetBounds(bounds);
  }

  void RenderPiece(vtkRenderer* ren, vtkActor* act) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

  ///@{
  /**
   * Scalars are mapped per leaf with the mapper's lookup table and range into
   * one array in leaf order (vtkMapper's versions read GetInput(), which is
   * null for composite input); with ColorByResolution the resolution map's
   * colors are returned instead.
   */
  using Superclass::MapScalars;
  vtkUnsignedCharArray* MapScalars(double alpha) override;
  vtkUnsignedCharArray* MapScalars(double alpha, int& cellFlag) override;
  bool HasTranslucentPolygonalGeometry() override;
  bool HasOpaqueGeometry() override;
  ///@}

  /// First point of object i in the merged vertex buffer (indices drawn for it are offset by this).
  vtkIdType GetObjectVertexOffset(vtkIdType i) const;

  ///@{
  /**
   * Diagnostics (used by the tests): how many times the vertex buffers were
   * (re)built by the superclass and the index buffer was filled, when the
   * vertex buffer of an attribute ("vertexMC", "normalMC", "scalarColor") was
   * last uploaded (0 when there is none), and the indices drawn for the
   * triangle primitive by the last render (merged point ids).
   */
  vtkIdType GetVertexBufferBuildCount() const;
  vtkIdType GetIndexBufferBuildCount() const;
  vtkMTimeType GetVertexBufferUploadTime(const char* attribute);
  vtkIdType GetLastIndexCount() const;
#ifndef __VTK_WRAP__
  const unsigned int* GetLastIndices() const;
#endif
  ///@}

protected:
  vtkMultiresolutionPolyDataMapper();
  ~vtkMultiresolutionPolyDataMapper() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  bool GetNeedToRebuildBufferObjects(vtkRenderer* ren, vtkActor* act) override;
  void BuildBufferObjects(vtkRenderer* ren, vtkActor* act) override;
  void BuildIBO(vtkRenderer* ren, vtkActor* act, vtkPolyData* poly) override;
  void UpdateCameraShiftScale(vtkRenderer* ren, vtkActor* act) override;
  void BuildCellTextures(
    vtkRenderer* ren, vtkActor* act, vtkCellArray* prims[4], int representation) override;

  ///@{
  /**
   * Block opacities: the vertex shader keeps each object in its pass; block
   * pickability: selection passes drop unpickable objects (Blocks.cxx,
   * Selection.cxx).
   */
  void ReplaceShaderValues(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  bool GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  ///@}

  ///@{
  /**
   * Hardware selection: the cell passes draw primitive ids of the index
   * buffer's slots and the composite pass one value for all leaves; these
   * turn them into each leaf's flat index and its own cell and point ids.
   */
  void ProcessSelectorPixelBuffers(
    vtkHardwareSelector* sel, std::vector<unsigned int>& pixeloffsets, vtkProp* prop) override;
  void UpdateMaximumPointCellIds(vtkRenderer* ren, vtkActor* act) override;
  ///@}

  ///@{
  /**
   * Selection display (vtkMapper::SetSelection): each leaf's selected cells
   * or points, by its own ids and the nodes' composite index (its flat
   * index), drawn at full resolution.
   */
  void BuildSelectionIBO(
    vtkPolyData* poly, std::vector<unsigned int> (&indices)[4], vtkIdType offset) override;
  void AddPointIdsToSelectionPrimitives(vtkPolyData* poly, const char* arrayName,
    unsigned int processId, unsigned int compositeIndex, vtkIdType selectedId) override;
  void AddCellIdsToSelectionPrimitives(vtkPolyData* poly, const char* arrayName,
    unsigned int processId, unsigned int compositeIndex, vtkIdType selectedId) override;
  ///@}

  vtkIdType RenderedTriangles = 0;
  vtkIdType RenderedVertices = 0;
  int NumberOfDrawCalls = 0;
  vtkIdType NumberOfRewrittenObjects = 0;
  vtkIdType IndexBytesUploaded = 0;
  vtkIdType CellDataBytesUploaded = 0;
  vtkIdType ColorBytesUploaded = 0;
  double IndexUpdateTime = 0.0;
  vtkIdType NumberOfPaddingPrimitives = 0;
  double IndexSlack = 0.1;
  bool ColorByResolution = false;
  bool ViewDependentRefinement = true;
  int RefinementMode = BUDGET;
  double RefinementTimeLimit = 0.0;
  double PixelThreshold = 1.0;
  bool BackFaceSimplification = true;
  bool SilhouetteRefinement = true;
  double SilhouetteFactor = 0.25;
  bool HighlightRefinement = true;
  double HighlightFactor = 0.5;
  double RefinementTime = 0.0;
  bool BackgroundBuilds = false;
  int BackgroundHierarchy = 0;
  int BackgroundInterimDivisions = 64;
  vtkIdType NumberOfSwappedHierarchies = 0;
  vtkIdType NumberOfObjectReads = 0;
  double UntakenObjectReadTime = 0.0;
  std::chrono::steady_clock::time_point LastObjectReadEnd;
  double LastVertexBufferBuildTime = 0.0;

private:
  vtkMultiresolutionPolyDataMapper(const vtkMultiresolutionPolyDataMapper&) = delete;
  void operator=(const vtkMultiresolutionPolyDataMapper&) = delete;

  bool IsValidObject(vtkIdType i) const; ///< with an error when not
  vtkAbstractArray* GetLeafScalars(vtkPolyData* leaf, vtkAbstractArray* common, int cellFlag);
  vtkUnsignedCharArray* MapLeafScalars(vtkAbstractArray* common, double alpha, int cellFlag);
  void PrepareLeafLookupTable(vtkAbstractArray* common, int cellFlag);
  void BuildVertexBuffers(vtkRenderer* ren, vtkActor* act);
  bool PrepareColorsAndCellTextures(vtkRenderer* ren, vtkActor* act); ///< point normals drawn
  int GetTCoordsSource();
  void GetLeafBufferState(vtkStateStorage& state, bool pointNormals, int tcoords);
  void AppendLeafBuffers(
    vtkRenderer* ren, vtkActor* act, vtkDataArray* pointColors, bool pointNormals, int tcoords);
  void UploadLeafBuffers(
    vtkRenderer* ren, const std::vector<std::pair<std::string, int>>& appended);
  void PatchStripOffset();
  void ReadObjects(vtkDataObject* input);
  bool TakeBuiltHierarchies(); ///< whether a finished build is to be swapped in
  void FillIndexBuffer(vtkRenderer* ren, vtkActor* act, bool rebuild);
  bool UpdateSlots();
  void UploadIndexRanges();
  void FillVertexIndices();
  void WriteProcessIds(vtkHardwareSelector* sel, const std::vector<unsigned int>& pixeloffsets);
  void PrepareLayout(vtkRenderer* ren, vtkActor* act);
  void RefineObjects(vtkRenderer* ren, vtkActor* act);
  void AllocateCellTextures(vtkRenderer* ren);
  void UploadCellTexels(size_t begin, size_t end);
  void UpdateResolutionColor(vtkIdType i);
  void UploadResolutionColors();
  void UploadDirtyColors(vtkUnsignedCharArray* colors);
  vtkUnsignedCharArray* MapScalarColors(double alpha, int& cellFlag);
  bool HasTranslucentScalars();
  // Block attributes (Blocks.cxx).
  void UpdateBlockAttributes();
  void PrepareBlockColors(vtkActor* act);
  vtkUnsignedCharArray* MapBlockColors(double alpha, int& cellFlag);
  void WriteBlockColors(vtkIdType i);
  /// Drops the superclass's scalar texture (colours given per vertex or cell instead).
  void ReleaseColorTexture();
  void UploadBlockColors();
  // Block pickability in selection passes (Selection.cxx).
  void UpdatePickability(bool stale);
  void ReplacePickabilityShaderValues(vtkShader* vertex, vtkRenderer* ren);
  void SetPickabilityShaderParameters(vtkShaderProgram* program);
  void ActivatePickability(vtkRenderer* ren);
  void DeactivatePickability();

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
