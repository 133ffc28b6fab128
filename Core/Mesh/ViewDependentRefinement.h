// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_ViewDependentRefinement_h
#define timecritical_ViewDependentRefinement_h

#include "TimeCriticalMeshCoreExport.h"

#include <cstdint>
#include <vector>

namespace timecritical
{
struct MergeTree;
struct TOMMesh;

/**
 * A view for ViewDependentRefinement, in the object's own coordinates (the
 * caller applies the inverse of the object's model matrix).
 */
struct RefinementView
{
  double Eye[3] = { 0.0, 0.0, 1.0 };        ///< camera position
  double Direction[3] = { 0.0, 0.0, -1.0 }; ///< view direction (normalized internally)
  bool Parallel = false;                    ///< parallel (orthographic) projection
  double ViewportHeight = 512.0;            ///< pixels
  double ViewAngle = 30.0;                  ///< vertical field of view, degrees (perspective)
  double ParallelScale = 1.0;               ///< half the viewport height in world units (parallel)
  /**
   * Up to 6 planes a x + b y + c z + d >= 0 inside; nodes wholly outside one
   * are not refined. Any scale (normalized internally); a plane whose normal
   * (a, b, c) is zero or not finite is ignored.
   */
  int NumberOfFrustumPlanes = 0;
  double FrustumPlanes[6][4] = {};
  /// Direction towards the first light (normalized internally); used by highlight refinement.
  double LightDirection[3] = { 0.0, 0.0, 1.0 };
  /**
   * Perspective: distance of the near clipping plane (world units, > 0), the
   * smallest distance at which an error is projected: nothing nearer is drawn.
   * A node whose bounding sphere holds the eye is thus projected from this
   * distance instead of getting an infinite priority. 0 (default): 1/1000 of
   * the object's radius (VTK's near/far clipping tolerance applied to the
   * object; one distance for all nodes keeps the priorities monotone).
   */
  double NearDistance = 0.0;
};

/// What one update did.
struct RefinementStatistics
{
  uint32_t Splits = 0;        ///< all vertex splits, forced ones included
  uint32_t ForcedSplits = 0;  ///< splits made only to satisfy dependencies (secondary vertices)
  uint32_t Merges = 0;        ///< edge collapses
  uint32_t BlockedSplits = 0; ///< wanted splits left out because a dependency was too fine
  uint32_t DisplayVertices = 0;
  uint32_t DisplayTriangles = 0;
  double Seconds = 0.0; ///< wall time of the update
  /// The work bound (time limit, SetOperationLimit()) stopped the update early:
  /// the front is valid but not yet what an unbounded update would give.
  bool Interrupted = false;
};

/**
 * Run-time view-dependent refinement over a merge tree (Xia, El-Sana &
 * Varshney, section 5): keeps a front of display vertices (all base vertices,
 * closed under parent) and its display triangles, and moves it from frame to
 * frame by vertex splits and edge collapses that replay the build-time
 * collapses exactly (merge-tree dependencies, section 4.4), so every front is
 * a fold-free triangulation of the same topology as the input.
 *
 * Two update modes:
 * - UpdateFixedAccuracy(): split e_v while its projected error exceeds the
 *   pixel threshold (smaller near silhouettes and highlights), forcing the
 *   splits its dependencies need (secondary display vertices, 5.1.2); merge
 *   when it does not. The result depends on the view only, not on the
 *   previous front (which only makes the update incremental).
 * - UpdateBudget(n): dual priority queues (split the largest projected error,
 *   merge the smallest) until the display triangle count reaches n; the
 *   splits a candidate forces are part of its price, paid with merges less
 *   useful than it.
 *
 * Cost per update: the candidates of the front (a sequential sweep over
 * copies of their nodes) plus the splits and merges made. Candidates found
 * unwanted sleep while the eye moves less than a conservative radius (their
 * distance and angular margins), and budget candidates enter the queue with a
 * bound on their key while their threshold factor cannot drop, keyed only if
 * they reach the top; neither changes any decision. Most of an update's time
 * is the splits and merges (cache misses on the per-vertex records, rows and
 * display triangles).
 *
 * Initialize() allocates everything (about 450 bytes per TOM vertex); updates
 * and GetTriangles() never allocate. Not thread-safe; one object per rendered
 * instance.
 */
class TIMECRITICALMESHCORE_EXPORT ViewDependentRefinement
{
public:
  ViewDependentRefinement();
  ~ViewDependentRefinement();
  ViewDependentRefinement(const ViewDependentRefinement&) = delete;
  ViewDependentRefinement& operator=(const ViewDependentRefinement&) = delete;

  /**
   * Copies what it needs of the TOM, its merge tree (same vertices) and the
   * points (3 coordinates per TOM vertex) and starts from the coarsest front.
   * Throws std::invalid_argument when the arrays do not fit together.
   */
  void Initialize(const TOMMesh& tom, const MergeTree& tree, const float* points);
  void Initialize(const TOMMesh& tom, const MergeTree& tree, const double* points);

  /// Back to the coarsest front (base vertices only).
  void Reset();

  //@{
  /// The view used by the next update.
  void SetView(const RefinementView& view);
  const RefinementView& GetView() const { return this->View; }
  //@}

  //@{
  /// Screen-space error threshold tau in pixels (0: full resolution, except culled nodes).
  void SetPixelThreshold(double tau) { this->PixelThreshold = tau; }
  double GetPixelThreshold() const { return this->PixelThreshold; }
  //@}

  //@{
  /// Do not refine nodes whose normal cone faces away from the eye (default on).
  void SetBackFaceSimplification(bool on) { this->BackFaceSimplification = on; }
  bool GetBackFaceSimplification() const { return this->BackFaceSimplification; }
  //@}

  //@{
  /// Near silhouettes (normal cone holds directions perpendicular to the view)
  /// the threshold is multiplied by SilhouetteFactor (in (0, 1], default 0.25;
  /// above 1 counts as 1: a coarser silhouette would break the monotone
  /// priorities that make fixed-accuracy fronts independent of history).
  void SetSilhouetteRefinement(bool on) { this->SilhouetteRefinement = on; }
  bool GetSilhouetteRefinement() const { return this->SilhouetteRefinement; }
  void SetSilhouetteFactor(double f) { this->SilhouetteFactor = f > 1.0 ? 1.0 : f; }
  double GetSilhouetteFactor() const { return this->SilhouetteFactor; }
  //@}

  //@{
  /// Near highlights (cone of reflection vectors of the light holds the
  /// direction to the eye) the threshold is multiplied by HighlightFactor
  /// (in (0, 1], default 0.25; above 1 counts as 1, as for silhouettes).
  void SetHighlightRefinement(bool on) { this->HighlightRefinement = on; }
  bool GetHighlightRefinement() const { return this->HighlightRefinement; }
  void SetHighlightFactor(double f) { this->HighlightFactor = f > 1.0 ? 1.0 : f; }
  double GetHighlightFactor() const { return this->HighlightFactor; }
  //@}

  //@{
  /**
   * Experimental, read by the next Initialize(): the dependency rows are the
   * wings of each split (third corners of its own triangles) instead of the
   * merge tree's rows (all neighbours of u and v before e_v). Same closure
   * rule, far fewer forced splits; every front invariant holds in the tests,
   * but the merge tree's error monotonicity is still computed over the full
   * rows. Default off.
   */
  void SetWingDependencies(bool on) { this->WingDependencies = on; }
  bool GetWingDependencies() const { return this->WingDependencies; }
  //@}

  /// Fixed-accuracy update from the previous front (see the class comment).
  const RefinementStatistics& UpdateFixedAccuracy();

  /**
   * Budget update from the previous front: the display triangle count ends
   * at most `triangleBudget` (unless nothing more can be merged, e.g. the
   * coarsest mesh is larger), spent where the projected error divided by the
   * local threshold factors is largest. A candidate whose forced splits do
   * not fit is paid for with merges less useful than it, or left out.
   *
   * Work bound: with timeLimitSeconds > 0 (and/or SetOperationLimit()) the
   * update stops once that much time has gone (checked every 16 operations,
   * so it may run over by a few microseconds; the priority sweep at the start,
   * O(candidates), is not interrupted) and sets Statistics.Interrupted. Every
   * split (with its forced splits) and merge is complete, so the front is
   * valid, but it may still be over the budget (merges come first when it is).
   * Successive calls with the same view and budget continue from there and
   * reach the front of an unbounded update.
   */
  const RefinementStatistics& UpdateBudget(uint32_t triangleBudget, double timeLimitSeconds = 0.0);

  //@{
  /**
   * At most this many splits and merges per budget update (forced and undone
   * ones included); 0 (default): no limit. A deterministic work bound (tests,
   * callers that measure their own operation rate).
   */
  void SetOperationLimit(uint32_t operations) { this->OperationLimit = operations; }
  uint32_t GetOperationLimit() const { return this->OperationLimit; }
  //@}

  const RefinementStatistics& GetStatistics() const { return this->Statistics; }

  uint32_t GetNumberOfDisplayVertices() const { return this->ActiveVertexCount; }
  uint32_t GetNumberOfDisplayTriangles() const { return this->DisplayCount; }

  /// The display triangles, 3 TOM vertex ids each (GetNumberOfDisplayTriangles() of them).
  const uint32_t* GetTriangles() const { return this->Display.data(); }

  /// The TOM triangle (cell) each display triangle stands for, in the same order.
  const uint32_t* GetTriangleIds() const { return this->DisplayId.data(); }

  /**
   * Copies min(capacity, display triangles) triangles into out (3 ids each),
   * adding `offset` to every id (several objects in one vertex buffer).
   * Returns the number of display triangles.
   */
  uint32_t CopyTriangles(uint32_t* out, uint32_t capacity, uint32_t offset = 0) const;

  /// Whether TOM vertex v is a display vertex.
  bool IsDisplayVertex(uint32_t v) const { return v < this->N && this->Active[v] != 0; }

  uint32_t GetNumberOfVertices() const { return this->N; }
  uint32_t GetNumberOfBaseVertices() const { return this->B; }

private:
  // Defined in ViewDependentRefinementInternals.h (Node, Candidate) and
  // ViewDependentRefinementError.cxx (Sight, ConeTest).
  struct Node;      // per-event view attributes (packed)
  struct Candidate; // a split candidate and its node
  struct Sight;     // where the eye sees a node from
  struct ConeTest;  // what the normal-cone tests of a node found
  struct HeapEntry
  {
    float Key;
    uint32_t Id;
  };

  // Hierarchy tables (ViewDependentRefinementTables.cxx): what Initialize()
  // builds from the TOM and its merge tree, in this order.
  template <typename T>
  void InitializeImpl(const TOMMesh& tom, const MergeTree& tree, const T* points);
  /// Rev, RevOffsets: the transpose of the requirement rows Req, ReqOffsets.
  void TransposeRequirements();
  /// Children, and each vertex's child offsets and previous sibling (0: none).
  void BuildChildren(std::vector<uint32_t>& childOffsets, std::vector<uint32_t>& previousSibling);
  /// BlockOffsets; returns the split event of each triangle (UINT32_MAX: base).
  std::vector<uint32_t> BuildBlocks(const TOMMesh& tom);
  /// BirthCorners, StarOffsets and StarSlots.
  void BuildStars(const TOMMesh& tom, const std::vector<uint32_t>& event);
  /// Replaces the requirement rows with the wings of each split (SetWingDependencies()).
  void UseWingRequirements();
  void BuildLinks(const std::vector<uint32_t>& childOffsets);
  /// Needs, from the requirement rows, which it then drops.
  void BuildNeeds(const std::vector<uint32_t>& previousSibling);
  /// Sizes everything the updates use (they never allocate).
  void AllocateUpdateState();
  /// Widens nodes so that priorities never grow down the split order (see .cxx).
  void MakePrioritiesMonotone();
  void PrepareView();
  /// Distance below which errors are not projected closer (RefinementView::NearDistance).
  double NearPlane() const
  {
    return this->View.NearDistance > 0.0 ? this->View.NearDistance : this->DefaultNear;
  }
  /// Starts a new update: frame stamps (priority cache, queues) move on.
  void NextFrame();
  // Projected error (ViewDependentRefinementError.cxx; the small members
  // that several files' loops call are inline, in the internal header).
  /// Projected error of event v over its local threshold factor; negative when culled.
  double Priority(uint32_t v) const;
  /// How far the eye may move (the settings, light and viewport staying)
  /// before an unwanted node can be wanted, and before its threshold factor
  /// can drop below Factor (0: no such bound).
  struct Sleep
  {
    double Wake = 0.0;
    double FactorRadius = 0.0;
    float Factor = 0.0f;
  };
  /// Priority() of a node, and with `sleep` how long it keeps.
  double Evaluate(const Node& node, Sleep* sleep = nullptr) const;
  // The steps of Evaluate().
  /// Wholly outside a frustum plane.
  inline bool Outside(const Sight& sight) const;
  /// Perspective sight of the node; true when that alone decides `key`.
  inline bool SeePerspective(const Node& node, Sight& sight, Sleep* sleep, double& key) const;
  /// Back-face and silhouette tests; true when every normal faces away.
  inline bool FacesAway(const Node& node, const Sight& sight, ConeTest& cone, Sleep* sleep) const;
  inline void TestHighlight(const Node& node, const Sight& sight, ConeTest& cone) const;
  /// How long the decision on a node with this key keeps (perspective).
  inline void MeasureSleep(
    const Node& node, const Sight& sight, const ConeTest& cone, double key, Sleep& sleep) const;
  /// >= the key of a node whose threshold factor is at least `factor` (the
  /// current eye, near plane and tau; ignores culling, which only lowers keys).
  double KeyBound(const Node& node, float factor) const;
  void Doze(Candidate& e, const Sleep& sleep) const; // e keeps what Evaluate() found
  /// Eye move that keeps angular margins (sines; < 0: none) at dist, radius r.
  double WakeRadius(double dist, double r, double margin0, double margin1) const;

  /// Priority(v), computed once per update.
  float Key(uint32_t v);
  bool Wanted(uint32_t v);
  /// Whether a node with this key is split (or kept) at the pixel threshold.
  bool IsWanted(float key) const
  {
    return key >= 0.0f && (key > this->PixelThreshold || this->PixelThreshold <= 0.0);
  }
  /// Conservative, cheap: true only when Wanted(v) is false (whatever the culling).
  bool SurelyUnwanted(const Node& node) const;

  // The front (ViewDependentRefinementFront.cxx).
  void Split(uint32_t v);
  void Merge(uint32_t v);
  /// Splits v and, first, every split it needs. Returns false when blocked.
  bool ForceSplit(uint32_t v);
  /// No display vertex needs v (and v is a leaf, the last child of its parent).
  bool CanMerge(uint32_t v) const;
  /// First inactive vertex whose split v needs, v itself when none; UINT32_MAX
  /// when blocked. Resumes the scan at (stage, index), 0 at first.
  uint32_t NextRequirement(uint32_t v, uint8_t& stage, uint32_t& index) const;
  void PrefetchOperation(uint32_t v) const; // what Split(v) or Merge(v) reads
  uint32_t NextChild(uint32_t w) const;
  uint32_t LastActiveChild(uint32_t w) const;
  void AddDisplay(uint32_t t);
  void RemoveDisplay(uint32_t t);
  // Candidate lists, kept up to date by Split() and Merge().
  void RefreshSplitCandidate(uint32_t w);
  void RefreshMergeCandidate(uint32_t x);
  void LeaveMergeCandidates(uint32_t x); // x no longer CanMerge()
  // One more / one fewer displayed vertex needs x (Holds).
  void Hold(uint32_t x);
  void Release(uint32_t x);

  // The updates (ViewDependentRefinementUpdates.cxx: both modes;
  // ViewDependentRefinementBudget.cxx: the budget's queues).
  /// Merges every unwanted vertex that nothing displayed needs, finest first
  /// (stops early when a bounded budget update runs out of time).
  void MergeUnwanted();
  /// Whether the running bounded budget update must stop (sets Interrupted).
  bool OutOfTime();
  // Budget mode: push display vertex w's split candidate, or merge candidate
  // v, with its current priority.
  void OfferSplit(uint32_t w);
  void OfferMerge(uint32_t v);
  void SortPending(uint32_t size);
  void ReachSplitTop();
  // The steps of UpdateBudget().
  /// Keys the split candidates into Pending (sorted) and the merge candidates into MergeHeap.
  void QueueBudgetCandidates();
  /// Splits and merges towards the budget, best first, until it is spent.
  void SpendBudget(uint32_t triangleBudget);
  /// Splits the top candidate, whose own triangles fit, paying for the
  /// splits it forces with less useful merges, or undoes it all.
  void SplitPaidFor(const HeapEntry& top, uint32_t triangleBudget);
  /// Full: one merge less useful than the top candidate, towards its split;
  /// false when nothing more fits.
  bool TradeForSplit(const HeapEntry& top, uint32_t triangleBudget, uint32_t& misfits);
  /// Pops the smallest mergeable entry; UINT32_MAX when there is none.
  uint32_t PopMerge();
  /// The smallest mergeable entry, left on the heap; nullptr when there is none.
  const HeapEntry* TopMerge();
  void PopSplit();
  /// Undoes the merges of the running trade since TradeLog[from], newest first.
  void UndoMerges(uint32_t from);

  /// What Split() and Merge() must tell the running update about new candidates.
  enum class UpdateMode
  {
    None,
    Fixed,
    Budget
  };
  UpdateMode Mode = UpdateMode::None;

  uint32_t N = 0;
  uint32_t B = 0;
  uint32_t T = 0;
  std::vector<uint32_t> Parent;
  std::vector<uint32_t> Children; // of each vertex, sorted by id
  /// What Split(), Merge(), the candidate lists and the key cache read of one
  /// vertex, in one cache line (vertices are reached at random).
  struct alignas(64) Links
  {
    uint32_t Parent;
    uint32_t ChildBegin, ChildEnd; // Children
    uint32_t ActiveChildren;       // displayed children: a prefix of the sorted ones
    uint32_t SplitPos, MergePos;   // in SplitList, MergeList (UINT32_MAX: absent)
    uint32_t NeedBegin, NeedEnd;   // Needs
    uint32_t BlockBegin, BlockEnd; // triangles born at the split
    uint32_t Slot; // index in Children and Nodes (UINT32_MAX: a base vertex)
    uint32_t Spare;
    uint32_t StarBegin, StarEnd;   // StarSlots
    uint32_t KeyFrame;             // Priority() of frame KeyFrame, as a float
    float Key;
  };
  std::vector<Links> Link;
  std::vector<uint8_t> Active;
  // Requirement rows (see the .cxx): vertices that must be displayed, with no
  // displayed child above v, while v is; and their transpose (Initialize() only).
  std::vector<uint32_t> ReqOffsets, Req;
  std::vector<uint32_t> RevOffsets, Rev;
  // What each vertex needs besides its parent and previous sibling, in one run
  // (one cache miss): the events whose row holds its parent, between its
  // previous sibling and it (the same at every split: siblings go in order),
  // then its row.
  std::vector<uint32_t> Needs;
  // Displayed vertices that need the vertex: its displayed children, its next
  // sibling, the displayed vertices whose row holds it, and the events whose
  // row vertex has a displayed child above them (kept by Split() and Merge();
  // a display vertex can be merged exactly when this is 0).
  std::vector<uint32_t> Holds;
  std::vector<uint32_t> BlockOffsets; // triangles of block v: [BlockOffsets[v], BlockOffsets[v+1])
  std::vector<uint32_t> BirthCorners; // corners of each triangle when it appears
  std::vector<uint32_t> StarOffsets, StarSlots; // slots 3t+k that turn from parent to v at split
  std::vector<Node> Nodes; // of the events, in Children's order (siblings adjacent)

  std::vector<uint32_t> Display;   // 3 ids per display triangle
  std::vector<uint32_t> DisplayId; // TOM triangle of each display triangle
  std::vector<uint32_t> DisplayPos; // TOM triangle -> display index or UINT32_MAX
  uint32_t DisplayCount = 0;
  uint32_t ActiveVertexCount = 0;

  // Split candidates: the next child of each display vertex that has one
  // (positions by owner); merge candidates: exactly the vertices CanMerge().
  std::vector<Candidate> SplitList;
  std::vector<uint32_t> MergeList;
  uint32_t SplitListSize = 0, MergeListSize = 0;

  std::vector<uint32_t> Touched;    // TouchFrame stamp: split, merged or left out by this budget update
  uint32_t TouchFrame = 0;          // Frame of the budget update that an interrupted one continues
  bool ContinueUpdate = false;      // the last budget update was interrupted
  uint32_t Frame = 0;

  std::vector<uint32_t> Stack; // forced splits, and where each one's scan stands
  std::vector<uint8_t> StackStage;
  std::vector<uint32_t> StackIndex;
  std::vector<uint32_t> Work;  // wanted fixed-accuracy split candidates
  uint32_t WorkSize = 0;
  // MergeUnwanted()'s queue, finest first: a bit per vertex, popped by a
  // downward scan (every push is below the last pop, so one sweep suffices).
  std::vector<uint64_t> MergeBits;
  bool Merging = false; // MergeUnwanted() runs: new merge candidates go to MergeBits
  // Budget heaps (lazy: entries are checked when they reach the top).
  std::vector<HeapEntry> SplitHeap, MergeHeap;
  uint32_t SplitSize = 0, MergeSize = 0;
  // Split candidates of the sweep by key bucket, taken into SplitHeap from the
  // top bucket down as needed (SortPending(), ReachSplitTop()).
  std::vector<HeapEntry> Pending, Sorted;
  std::vector<uint32_t> BucketStart;
  uint32_t PendingEnd = 0;  // not taken yet: Sorted[0, PendingEnd)
  float SplitFloor = 0.0f;  // every entry not taken is below it
  std::vector<uint32_t> SplitLog; // splits of the current forced split, to undo an overshoot
  uint32_t SplitLogSize = 0;
  std::vector<uint32_t> TradeLog; // merges of the running trade, to undo a failed one
  uint32_t TradeLogSize = 0;
  uint32_t TradeFor = 0; // the split the running trade pays for
  // Work bound of the running budget update.
  uint32_t OperationLimit = 0;
  uint32_t UndoneOperations = 0; // splits and merges of undone forced splits
  uint32_t Checks = 0;
  double Deadline = 0.0; // steady clock, seconds; 0: none
  bool Bounded = false;

  bool WingDependencies = false;
  RefinementView View;
  double PixelThreshold = 1.0;
  bool BackFaceSimplification = true;
  bool SilhouetteRefinement = false;
  double SilhouetteFactor = 0.25;
  bool HighlightRefinement = false;
  double HighlightFactor = 0.25;

  // Derived from View by PrepareView().
  double EyeX = 0, EyeY = 0, EyeZ = 0;
  double DirX = 0, DirY = 0, DirZ = -1;
  double LightX = 0, LightY = 0, LightZ = 1;
  double PixelsPerUnit = 1.0; // parallel: per world unit; perspective: times distance
  bool BrokenView = false;    // eye or direction not finite: everything culled
  double MinimumFactor = 1.0; // smallest threshold factor (silhouette, highlight)
  double UnwantedScale = 0.0; // PixelsPerUnit / (MinimumFactor * tau * (1 - 1e-6)); 0: none
  // Candidate sleep (see PrepareView()): the eye's path length, its last
  // position, and the settings the sleeping candidates were decided with.
  double Odometer = 0.0;
  double LastEye[3] = { 0.0, 0.0, 0.0 };
  double SleepSettings[9] = {};
  double DefaultNear = 1e-3; // 1/1000 of the object's radius (Initialize())
  // Normalized frustum planes as x, y, z, w rows of 8 (unused ones never
  // cull): one branch-free, vectorizable test per node, in double so that its
  // rounding stays far below the nesting margin of MakePrioritiesMonotone().
  int PlaneCount = 0;
  alignas(32) double Planes[4][8] = {};

  RefinementStatistics Statistics;
};
}

#endif
