// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_CollapseEngine_h
#define timecritical_CollapseEngine_h

/*
 * Internal to TimeCritical::MeshCore: the half-edge collapse engine shared
 * by TOMBuilder (greedy schedule) and MergeTreeBuilder (independent sets by
 * level). Not an API: it may change with the builders. Everything lives in
 * namespace timecritical::collapse; its records, quadrics, cost lanes, heap
 * and allocator have headers of their own.
 */

#include "CheapestTarget.h"
#include "CollapseGeometry.h"
#include "CollapseQuadric.h"
#include "CollapseRecords.h"
#include "CostLanes.h"
#include "FanGroups.h"
#include "HugePageAllocator.h"
#include "IndexedHeap.h"
#include "ProgressReporter.h"
#include "ScratchBlocks.h"
#include "TOMBuildOptions.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace timecritical
{
namespace collapse
{
/**
 * The collapse engine shared by the builders: one simplification of one mesh
 * by half-edge collapses u -> w (vertex substitution, no new vertices), with
 * everything but the choice of which collapse comes next. It reads the input,
 * builds the adjacency, the quadrics and the vertex kinds (boundaries and
 * feature curves), keeps per vertex its cheapest allowed target with an exact
 * key, checks and applies collapses, relaxes the constraints on request, and
 * writes the collapse record out as a TOM. Schedules drive it: TOMBuilder
 * takes the global minimum each time (the heap), MergeTreeBuilder takes
 * independent sets level by level (no heap: keys only).
 *
 * Vertex ids inside are compact "internal" ids: the used input points,
 * numbered in input order.
 */
class CollapseEngine
{
public:
  /// useHeap: keep the vertices in an indexed heap by key (greedy schedules).
  /// The engine keeps a reference to `options` (its progress callback
  /// included): they must outlive it, so a temporary must not be passed.
  CollapseEngine(const TOMBuildOptions& options, bool useHeap)
    : Options(options)
    , Progress(options.Progress)
    , UseHeap(useHeap)
  {
  }

  /**
   * The whole build: reads and checks the input, prepares the mesh, calls
   * schedule() to run the collapses (it returns false to abort), and writes
   * the TOM. Progress 0 after reading, 0.05 before the schedule, 1 at the
   * end; the schedule reports in between.
   */
  TOMBuildResult Run(const double* points, size_t numberOfPoints, const uint32_t* triangles,
    size_t numberOfTriangles, const std::function<bool()>& schedule);

  /// Forwards a fraction done to the progress callback; false: stop.
  bool ReportProgress(double fraction) { return this->Progress.Report(fraction); }

  // --- the state a schedule reads
  uint32_t GetNumberOfVertices() const { return this->N; }
  uint32_t GetRemovedCount() const { return static_cast<uint32_t>(this->RemovedOrder.size()); }
  /// Internal id of the vertex removed at a step (0 = first).
  uint32_t GetRemovedVertex(uint32_t step) const { return this->RemovedOrder[step]; }
  bool IsRemoved(uint32_t v) const { return this->Vertices[v].State & RemovedBit; }
  /// The cheapest allowed target of v and its key (+inf: none, or blocked).
  uint32_t GetTarget(uint32_t v) const { return this->Vertices[v].Target; }
  float GetKey(uint32_t v) const { return this->Vertices[v].Key; }
  bool HeapEmpty() const { return this->Heap.Empty(); }
  uint32_t HeapTop() const { return this->Heap.Top().Vertex; }
  /// Smallest key in the heap after the top (+inf when none).
  float HeapSecondKey() const { return this->Heap.SecondKey(); }

  // --- the operations of a schedule
  /// Whether u -> w keeps the mesh legal at the current relaxation level.
  bool CheckCollapse(uint32_t u, uint32_t w);
  /// Applies u -> w (checked first), updates quadrics and keys, records the step.
  void ApplyCollapse(uint32_t u, uint32_t w);
  /// All allowed targets of v, each once, cheapest first (valid until the next call).
  const std::vector<Candidate>& GatherCandidates(uint32_t v);
  /**
   * When u's cheapest target (failedTarget) is illegal: the cheapest legal
   * one into `found`. False when none is, or none within
   * AlternativeWorkBudget (the schedule then blocks u).
   */
  bool FindLegalAlternative(uint32_t u, uint32_t failedTarget, Candidate& found);
  /// Makes t v's target (the key is set apart, see SetKey).
  void SetTarget(uint32_t v, uint32_t t) { this->Vertices[v].Target = t; }
  /// v's key (and its place in the heap, if there is one).
  void SetKey(uint32_t v, double cost) { this->HeapSet(v, cost); }
  /// v has no legal collapse at this relaxation level until its neighbourhood
  /// changes (a collapse around it re-evaluates it) or the level changes.
  void Block(uint32_t v);
  /// Next relaxation level; false when all are used up (the build is done).
  bool Relax();
  /**
   * Pair contraction, for TOMBuilder's schedules once they are done (no edge
   * collapse left at any level): separate parts join other parts within
   * TOMBuildOptions::PairContractionDistance, each substituted whole into
   * one vertex of the other part, cheapest join first (CollapseEngineJoin.cxx).
   * False when the progress callback aborted the build.
   */
  bool JoinParts();
  int GetRelaxation() const { return this->CurrentLevel; }
  /// A word and a byte per vertex for the schedule, in the vertex's cache
  /// line (uninitialised).
  uint32_t& Tag(uint32_t v) { return this->Vertices[v].Tag; }
  uint8_t& TagByte(uint32_t v) { return this->Vertices[v].TagByte; }
  /// Without a heap: stage 0-5 of the prefetch of v's collapse into its
  /// target (v's record; lists; triangles; neighbours; quadrics), each stage
  /// reading what the earlier ones fetched, for schedules that see several
  /// collapses ahead and spread the stages over them.
  void PrefetchCandidate(uint32_t v, int stage) { this->PrefetchCollapse(v, stage); }

  /// Calls f(x) for each neighbour x of v (twice for most), v's list compacted.
  template <typename F>
  void ForEachNeighbour(uint32_t v, F&& f)
  {
    this->ForEachLiveTriangle(v, [&f](const Tri& tri, uint32_t j) {
      f(tri.V[Next3(j)]);
      f(tri.V[Prev3(j)]);
    });
  }

  /// After Run: hands the working arrays (records, quadrics, triangles,
  /// adjacency) over to blocks for reuse. Nothing may be asked of the engine after.
  void ReleaseWorkingMemory(ScratchBlocks& blocks)
  {
    blocks.Add(std::move(this->Vertices));
    blocks.Add(std::move(this->Quadrics));
    blocks.Add(std::move(this->Tris));
    blocks.Add(std::move(this->Pool));
  }

  /// Heap keys are floats, clamped so that +inf can mean "not in the heap".
  static float KeyOf(double cost)
  {
    return static_cast<float>(std::min(cost, double(std::numeric_limits<float>::max())));
  }

private:
  // --- setup
  void ReadInput(const double* points, size_t numberOfPoints, const uint32_t* triangles,
    size_t numberOfTriangles, TOMBuildResult& result);
  void FillTriangles();
  void DropDuplicateTriangles(TOMBuildResult& result);
  void BuildAdjacency();
  void BuildFaceQuadrics();
  bool ClassifyVertices();
  bool ClassifyClosedFan(uint32_t v, float cosFeature);
  /// What makes an edge a constraint (see ClassifyFanEdge).
  struct EdgeRules
  {
    float CosFeature;      // cosine of the feature angle
    double BoundaryWeight; // weight of the constraint planes along boundaries
  };
  bool ClassifyGeneralFan(uint32_t v, FanGroups& fan, const EdgeRules& rules);
  void ClassifyFanEdge(
    uint32_t v, const FanGroups& fan, const FanGroups::Group& group, const EdgeRules& rules);
  Vec3 NormalOf(uint32_t t) const;
  bool SharpTurn(uint32_t v, uint32_t a, uint32_t b) const;
  void AddConstraintPlane(uint32_t a, uint32_t b, const Vec3& faceNormal, double weight);
  void SeedCandidate(uint32_t v);
  void BeginCollapses();

  // --- collapses
  void RemoveOrphan(uint32_t x, uint32_t w);
  void PrefetchCollapse(uint32_t v, int stage);
  /// New best target of v; prefetch false where the collapse that calls it
  /// fetched v's fan already (its "soon" neighbours).
  void Reevaluate(uint32_t v, bool prefetch = true);
  /// Whether v's fan is beyond MaximumFanSize (then it is parked, see there).
  bool Parked(uint32_t v) const { return this->Vertices[v].LiveCount > MaximumFanSize; }
  void Park(uint32_t v);
  void SetBest(uint32_t v, const Candidate& best);
  void StartLevel(int level);
  /// A fresh stamp for the scratch marks (see MarkU), clearing them all.
  uint32_t NextStampBase()
  {
    if (++this->Stamp >= (1u << 29))
    {
      // Out of stamps (after half a billion checks): clear the marks once.
      for (Vertex& v : this->Vertices)
      {
        v.Mark = 0;
      }
      this->Stamp = 1;
    }
    return this->Stamp << 3;
  }

  // --- the steps of CheckCollapse
  /// Triangles and vertices counted around one end of the edge by the link condition.
  struct LinkCount
  {
    uint32_t Triangles = 0;  // live triangles around the end
    uint32_t Neighbours = 0; // distinct neighbours of the end
    uint32_t Shared = 0;     // triangles on the edge (counted from u only)
  };
  void PrefetchFans(uint32_t u, uint32_t w);
  void MarkLinkOfU(uint32_t u, uint32_t w, uint32_t base, LinkCount& link);
  bool SurvivorsStayValid(uint32_t u, uint32_t w, uint32_t base);
  bool WouldDuplicate(uint32_t w, uint32_t a, uint32_t b);
  bool LinkOfWAllowed(uint32_t u, uint32_t w, uint32_t base, LinkCount& link);

  // --- the steps of ApplyCollapse
  void RecordStep(uint32_t u, uint32_t w);
  uint32_t MoveFanToTarget(uint32_t u, uint32_t w);
  void AddToRing(uint32_t x, uint32_t u, uint32_t ringBase);
  void AppendSurvivors(uint32_t u, uint32_t w, uint32_t survivors);
  void KeepMergedConstraintEdges(uint32_t w);
  void PrefetchSoonTriangles();
  void PrefetchSoonNeighbours();
  void MergeQuadrics(uint32_t u, uint32_t w);
  void RecordStepError(uint32_t w);
  void RetargetSurvivor(uint32_t w);
  void UpdateRing(uint32_t u, uint32_t w);
  void RetryBlocked();
  void RemoveOrphans(uint32_t w);

  void HeapSet(uint32_t v, double cost)
  {
    this->Vertices[v].Key = KeyOf(cost);
    if (this->UseHeap)
    {
      this->Heap.Set(v, this->Vertices[v].Key);
    }
  }
  void HeapRemove(uint32_t v)
  {
    this->Vertices[v].Key = std::numeric_limits<float>::infinity();
    if (this->UseHeap)
    {
      this->Heap.Remove(v);
    }
  }

  /// Walks v's adjacency list, drops dead triangles from it and calls
  /// f(triangle, corner of v) for each live one.
  template <typename F>
  void ForEachLiveTriangle(uint32_t v, F&& f)
  {
    Vertex& rec = this->Vertices[v];
    uint32_t* list = this->Pool.data() + rec.AdjStart;
    const uint32_t n = rec.AdjCount;
    this->Visited += n;
    uint32_t kept = 0;
    for (uint32_t i = 0; i < n; ++i)
    {
      const uint32_t entry = list[i];
      const Tri& tri = this->Tris[entry >> 2];
      if (tri.Flags & DeadFlag)
      {
        continue;
      }
      list[kept++] = entry;
      f(tri, entry & 3u);
    }
    rec.AdjCount = kept;
  }

  /**
   * Calls consider(x) for every neighbour x that v may collapse into under
   * the kind rules of the current level (a neighbour may come twice).
   */
  template <typename F>
  void ForEachAllowedTarget(uint32_t v, F&& consider)
  {
    const int kind = this->EffectiveKind(v);
    if (kind == KindFixed)
    {
      return;
    }
    this->ForEachLiveTriangle(v, [&](const Tri& tri, uint32_t j) {
      if (kind == KindClosed)
      {
        // In a closed, consistently oriented fan each neighbour follows v once.
        consider(tri.V[Next3(j)]);
      }
      else if (kind == KindFree)
      {
        consider(tri.V[Next3(j)]);
        consider(tri.V[Prev3(j)]);
      }
      else
      {
        // A curve vertex only slides along its constraint edges.
        if ((tri.Flags >> j) & 1u)
        {
          consider(tri.V[Next3(j)]);
        }
        if ((tri.Flags >> Prev3(j)) & 1u)
        {
          consider(tri.V[Prev3(j)]);
        }
      }
    });
  }

  bool BestTarget(uint32_t v, Candidate& best, bool prefetch = true);
  int EffectiveKind(uint32_t v) const
  {
    return this->CurrentLevel >= LevelNoConstraints ? static_cast<int>(KindFree)
                                                    : this->Vertices[v].Kind;
  }
  /**
   * Cost of collapsing the vertex with quadric q into `target`: the increase
   * of the quadric error, Q(p) = the area-weighted squared distances of the
   * target from the planes the vertex has accumulated (constraint planes
   * included with their weights), divided by the square root of that area A:
   * the mean squared distance Q/A times the linear size sqrt(A) of the
   * region. Q alone (Garland-Heckbert) favours small triangles whatever their
   * deviation; Q/A follows distances only, and lets large, already simplified
   * regions keep collapsing while their mean stays low, however far their
   * worst parts move. Dividing by sqrt(A) lies between the two, and gave
   * the smallest Hausdorff errors of the exponents of A compared. The cost
   * depends only on the source's quadric and the target's position, so it
   * does not change when the target absorbs other vertices: a collapse
   * changes few keys, which are all kept exact.
   *
   * A small "moment" term, area already gathered at the vertex times the
   * squared length of the move, breaks the ties of flat regions, where every
   * collapse is free: without it a vertex can roll along a row, dragging an
   * ever longer fan that every collapse walks (quadratic time), or swallow
   * a whole plane. Its weight is small enough to only decide where
   * collapses are (nearly) free.
   */
  double Cost(const LocalQuadric& q, uint32_t target) const
  {
    const Vec3& p = this->Vertices[target].P;
    return CostLanes<double>(q).Cost(p.X, p.Y, p.Z);
  }
  LocalQuadric QuadricOf(uint32_t v) const
  {
    return LocalQuadric(this->Quadrics[v], this->Vertices[v].P);
  }

  void EnsureCapacity(uint32_t v, uint32_t needed);
  void CompactPool();

  void BuildOutput(TOMBuildResult& result);

  // --- pair contraction (CollapseEngineJoin.cxx)
  struct PartSet;
  struct Join;
  void LabelParts(PartSet& parts) const;
  bool BestJoin(PartSet& parts, uint32_t part, Join& join);
  void AbsorbPart(PartSet& parts, const Join& join);
  /// One step of an absorbed part: m -> w, killing m's triangles that meet
  /// a vertex of the part substituted before it (CollapseEngine.cxx).
  void AbsorbStep(uint32_t m, uint32_t w);

  const TOMBuildOptions& Options;
  ProgressReporter Progress;

  // Input bookkeeping.
  const uint32_t* InputTriangles = nullptr;
  BigVector<uint32_t> InputIdOf;    // internal vertex -> input point id
  BigVector<uint32_t> InternalIdOf; // input point id -> internal vertex (Invalid if unused)
  BigVector<uint32_t> InputTriOf;   // internal triangle -> input triangle index
  double Scale = 1.0;
  double Diagonal = 0.0; // of the input's bounding box, in the unit box's units
  size_t JoinedParts = 0;

  uint32_t N = 0; // vertices
  uint32_t T = 0; // triangles

  BigVector<Tri> Tris;
  BigVector<Vertex> Vertices;
  BigVector<QuadricRecord> Quadrics;
  BigVector<float> Normals; // unit face normals, during the setup only
  BigVector<ConstraintRecord> Constraints; // one per vertex touched by a constraint plane

  BigVector<uint32_t> Pool;
  size_t PoolUsed = 0;

  IndexedHeap Heap;
  const bool UseHeap;
  int CurrentLevel = LevelAll;
  double CosMaxDeviation = 0.0;
  bool NormalCheckEnabled = true;
  bool SliverCheckEnabled = false;

  uint32_t Stamp = 0;
  uint64_t Visited = 0; // TOMBuildResult::FanTrianglesVisited
  std::vector<Candidate> Scratch;
  std::vector<uint32_t> Ring;  // u's neighbours during a collapse
  std::vector<uint32_t> Soon;  // those of them probably re-evaluated
  std::vector<uint32_t> Retry; // blocked vertices around w during a collapse
  bool RetrySkipped = false;   // some around a hub (RetryFanSize) since the level started
  std::vector<uint32_t> Orphans;
  std::vector<uint32_t> BlockedList;
  std::vector<uint32_t> Merges; // wing vertices whose merged edge keeps a constraint flag

  // The collapse record.
  BigVector<uint32_t> RemovedOrder; // internal id of the vertex removed at each step
  BigVector<uint32_t> SubstituteOf; // internal id -> internal id it was substituted with
  BigVector<float> StepError;       // running max of the geometric error, per step
  BigVector<uint32_t> KillList;     // triangles in the order they died
  BigVector<uint32_t> KillStart;    // per step, first index into KillList
  double RunningError = 0.0;
};
}
}

#endif
