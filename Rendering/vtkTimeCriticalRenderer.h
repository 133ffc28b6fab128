// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkTimeCriticalRenderer
 * @brief   a renderer that holds a target frame time by choosing per-object resolutions
 *
 * Each frame, before VTK's OpenGL pipeline draws, this renderer
 * 1. finds the objects of every visible actor whose mapper is a
 *    vtkMultiresolutionPolyDataMapper (each polydata leaf is one object),
 * 2. culls objects outside the view frustum and measures per object the
 *    projected pixel coverage of its bounding box, its apparent velocity and
 *    its eccentricity from the focus point (timecritical::ViewHeuristics),
 * 3. predicts the frame's cost (timecritical::FrameCostModel, calibrated on
 *    this machine at start-up and refined from every measured frame) and the
 *    degradation of each object (timecritical::DegradationModel),
 * 4. chooses resolutions with the selected policy (Gobbetti & Bouvier's
 *    active-set optimizer by default) within OptimizationTimeLimit,
 * 5. hands them to the mappers and lets vtkOpenGLRenderer draw.
 * Ordinary actors in the same renderer are drawn as usual; their triangles,
 * pixels and draw calls count in the fixed part of the predicted time.
 *
 * Frame times are measured from the render window's StartEvent to its
 * EndEvent (which includes the buffer swap, when a software rasterizer does
 * most of its work).
 *
 * Still rendering: StillRender() draws one frame with every object at full
 * resolution. With UseDesiredUpdateRate on, the target follows the render
 * window's DesiredUpdateRate, which VTK's interactors raise while the user
 * interacts and drop to their StillUpdateRate at rest: a rate at or below
 * StillUpdateRateThreshold then draws at full resolution, so the view is
 * coarse while moving and exact at rest with any VTK interactor. The target
 * TargetFrameTime is then not used for planning:
 * GetEffectiveTargetFrameTime() says what is.
 *
 * Cost model: calibrated in the first render that has objects (still or
 * not: the start-up frame the user waits for anyway; about a dozen frames'
 * worth of the target, see Calibrate()), then refined from every measured
 * frame it planned (not from still frames, whose features never vary:
 * they have a correction of their own). Without a calibration (turned off,
 * or a parallel render, where one process cannot render alone) the model
 * starts from defaults, scaled once to this machine by the first measured
 * still frame. Online refinement cannot lower the triangle cost below half of
 * what the calibration measured (or SetCostCoefficients() gave), nor any
 * coefficient below what no hardware beats, so a triangle never becomes
 * free. The safety margin
 * follows the measured noise but never takes more than half of the time the
 * fixed part leaves the objects.
 *
 * View-dependent refinement: objects that carry a merge tree (built by
 * vtkMergeTreeBuilder) are drawn as view-dependent fronts (see
 * vtkMultiresolutionPolyDataMapper), with the refinement settings of this
 * renderer, which it applies to every multiresolution mapper it draws. In
 * BUDGET mode (default) such an object's triangle budget is the resolution
 * the policy chose times its triangle count, spent where the projected error
 * is largest: the optimizer decides how many triangles, the refinement where
 * they go. In FIXED_ACCURACY mode (Pasman & Jansen's fixed accuracy) it is
 * refined until no projected error exceeds PixelThreshold, whatever that
 * costs; its triangles of the previous frame then count as fixed cost. The
 * refinement time of the previous frame counts in the fixed cost too.
 *
 * Objects are numbered per frame: the visible actors in the renderer's prop
 * order, then the objects of each mapper in order; GetObjectActor() and
 * GetObjectIndex() map a number back.
 *
 * @sa vtkMultiresolutionPolyDataMapper vtkTOMBuilder
 */
#ifndef vtkTimeCriticalRenderer_h
#define vtkTimeCriticalRenderer_h

#include "TimeCriticalRenderingModule.h" // for export macro
#include "vtkOpenGLRenderer.h"

#include <memory> // for std::unique_ptr

class vtkActor;

class TIMECRITICALRENDERING_EXPORT vtkTimeCriticalRenderer : public vtkOpenGLRenderer
{
public:
  static vtkTimeCriticalRenderer* New();
  vtkTypeMacro(vtkTimeCriticalRenderer, vtkOpenGLRenderer);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Policies
  {
    ACTIVE_SET = 0,       ///< Gobbetti & Bouvier's predictive optimization (default)
    FULL_RESOLUTION = 1,  ///< none: every object at full resolution
    STATIC_THRESHOLD = 2, ///< fixed pixels-per-triangle threshold
    FEEDBACK = 3,         ///< threshold adapted from the previous frame times
    GREEDY_LOD = 4        ///< Funkhouser & Séquin's incremental greedy over six LODs
  };

  enum DegradationFamilies
  {
    HITCHNER = 0,              ///< w_i = Npix / Nmaxtri, alpha = 1 (default)
    FUNKHOUSER = 1,            ///< w_i = Npix / Nmaxtri^2, alpha = 2
    GOBBETTI_BOUVIER_1999 = 2, ///< w_i = Npix sqrt(Nmaxtri), alpha = -1/2
    YANG_GU_KANG = 3           ///< Yang et al.'s representation model (alpha = -1/2)
  };

  ///@{
  /**
   * Target frame time t_desired in seconds (> 0 and finite; default 0.1).
   * This is the setting: with UseDesiredUpdateRate on it is not what frames
   * are planned for (see GetEffectiveTargetFrameTime()).
   */
  void SetTargetFrameTime(double seconds);
  vtkGetMacro(TargetFrameTime, double);
  ///@}

  /**
   * The target the next frame will be planned for, in seconds: 1 /
   * DesiredUpdateRate of the render window with UseDesiredUpdateRate on,
   * else TargetFrameTime; +infinity when the next frame is a still frame
   * (StillRendering on, or a rate at or below StillUpdateRateThreshold:
   * every object in full, whatever it costs). GetLastTargetFrameTime() is that of the last frame.
   */
  double GetEffectiveTargetFrameTime();

  ///@{
  /**
   * CPU time limit t_opt of the optimizer in seconds (>= 0; default 0.001).
   * 0: no iteration; the active-set policy then uses the closed-form
   * allocation (every object at kappa g_i, clamped and scaled to fit; see
   * timecritical::ActiveSetOptimizer), or last frame's when that is better.
   */
  void SetOptimizationTimeLimit(double seconds);
  vtkGetMacro(OptimizationTimeLimit, double);
  ///@}

  ///@{
  /// How resolutions are chosen.
  void SetPolicy(int policy);
  vtkGetMacro(Policy, int);
  void SetPolicyToActiveSet() { this->SetPolicy(ACTIVE_SET); }
  void SetPolicyToFullResolution() { this->SetPolicy(FULL_RESOLUTION); }
  void SetPolicyToStaticThreshold() { this->SetPolicy(STATIC_THRESHOLD); }
  void SetPolicyToFeedback() { this->SetPolicy(FEEDBACK); }
  void SetPolicyToGreedyLOD() { this->SetPolicy(GREEDY_LOD); }
  const char* GetPolicyAsString() const;
  ///@}

  ///@{
  /// Degradation heuristic (eq. 10 families).
  void SetDegradationFamily(int family);
  vtkGetMacro(DegradationFamily, int);
  ///@}

  ///@{
  /// Reddy's velocity and eccentricity factors (eq. 7). Default on.
  vtkSetMacro(UseVelocity, bool);
  vtkGetMacro(UseVelocity, bool);
  vtkBooleanMacro(UseVelocity, bool);
  vtkSetMacro(UseEccentricity, bool);
  vtkGetMacro(UseEccentricity, bool);
  vtkBooleanMacro(UseEccentricity, bool);
  ///@}

  ///@{
  /**
   * Focus point for eccentricity, in normalized viewport coordinates
   * ([0,1]^2, (0.5, 0.5) = screen centre, the default).
   */
  void SetFocusPoint(double x, double y); ///< each in [0, 1]
  void SetFocusPoint(const double point[2]) { this->SetFocusPoint(point[0], point[1]); }
  vtkGetVector2Macro(FocusPoint, double);
  ///@}

  ///@{
  /**
   * Where the focus of the eccentricity factor is (Funkhouser & Séquin's
   * focus follows the screen centre or the cursor): FIXED_POINT uses
   * FocusPoint (default); SCREEN_CENTER the viewport's centre; CURSOR the
   * render window interactor's last event position (the mouse), or
   * FocusPoint when the window has no interactor. A mode out of range is an
   * error and leaves the setting as it was.
   */
  enum FocusModes
  {
    FIXED_POINT = 0,
    SCREEN_CENTER = 1,
    CURSOR = 2
  };
  void SetFocusMode(int mode);
  vtkGetMacro(FocusMode, int);
  void SetFocusModeToFixedPoint() { this->SetFocusMode(FIXED_POINT); }
  void SetFocusModeToScreenCenter() { this->SetFocusMode(SCREEN_CENTER); }
  void SetFocusModeToCursor() { this->SetFocusMode(CURSOR); }
  /// The focus of the last frame, in normalized viewport coordinates.
  vtkGetVector2Macro(LastFocus, double);
  ///@}

  ///@{
  /**
   * How an object's benefit falls with its distance from the focus
   * (UseEccentricity on): FAMILY_DEFAULT as the degradation family has it
   * (Reddy's eccentricity model of eq. 7, Yang et al.'s linear focus for
   * YANG_GU_KANG; default), REDDY Reddy's model, LINEAR Funkhouser &
   * Séquin's linear fall-off, 1 - E / LinearFalloffDegrees (E the distance
   * in visual degrees, floored at 0.01). Out of range: an error, the setting
   * kept.
   */
  enum FocusFalloffs
  {
    FAMILY_DEFAULT = 0,
    REDDY = 1,
    LINEAR = 2
  };
  void SetFocusFalloff(int falloff);
  vtkGetMacro(FocusFalloff, int);
  void SetFocusFalloffToReddy() { this->SetFocusFalloff(REDDY); }
  void SetFocusFalloffToLinear() { this->SetFocusFalloff(LINEAR); }
  void SetLinearFalloffDegrees(double degrees); ///< finite and > 0 (default 30)
  vtkGetMacro(LinearFalloffDegrees, double);
  ///@}

  ///@{
  /// Physical display for eq. 8: resolution (pixels), size and viewing distance (metres).
  void SetDisplayResolution(double x, double y); ///< pixels, finite and > 0
  void SetDisplayResolution(const double r[2]) { this->SetDisplayResolution(r[0], r[1]); }
  vtkGetVector2Macro(DisplayResolution, double);
  void SetDisplaySize(double x, double y); ///< metres, finite and > 0
  void SetDisplaySize(const double size[2]) { this->SetDisplaySize(size[0], size[1]); }
  vtkGetVector2Macro(DisplaySize, double);
  void SetViewingDistance(double metres); ///< finite and > 0
  vtkGetMacro(ViewingDistance, double);
  ///@}

  ///@{
  /// Pixels per triangle of the static policy (and the feedback policy's start). Default 8.
  void SetStaticPixelsPerTriangle(double k);
  vtkGetMacro(StaticPixelsPerTriangle, double);
  ///@}

  /// User importance w_s of an actor's objects (default 1, >= 0).
  void SetImportance(vtkActor* actor, double importance);
  double GetImportance(vtkActor* actor) const;

  ///@{
  /// Target from the render window's DesiredUpdateRate (see class comment). Default off.
  vtkSetMacro(UseDesiredUpdateRate, bool);
  vtkGetMacro(UseDesiredUpdateRate, bool);
  vtkBooleanMacro(UseDesiredUpdateRate, bool);
  void SetStillUpdateRateThreshold(double rate); ///< frames per second, finite and >= 0
  vtkGetMacro(StillUpdateRateThreshold, double);
  ///@}

  ///@{
  /**
   * "No polygons" level (Funkhouser & Séquin): when even the coarsest levels
   * of the visible objects do not fit the target, an interactive frame
   * leaves the least valuable objects out so that it holds the target.
   * Default on. Used by the ACTIVE_SET and GREEDY_LOD policies (their
   * SelectTuples(): timecritical::TupleOptimizer, GreedyTupleSelector);
   * the other policies, and still frames, draw every visible object. An
   * object's value is what it loses when not drawn, Interest x Npix (its
   * projected pixels times the velocity, eccentricity and importance
   * factors, as timecritical::AlgorithmDegradation has it), and objects are
   * dropped strictly by value: one is dropped only while every less valuable
   * one is dropped too, or when they could not make room for it together. A frame whose fixed part alone (clear, swap, ordinary
   * actors, draw calls) reaches the target drops nothing: no choice of
   * objects could hold it, and a frame never drops every object (the most
   * valuable one is drawn, over the target), and neither does a frame
   * planned with a cost
   * model never measured here (no calibration, no given coefficients and no
   * still frame yet): its overestimates would empty the view. Dropped
   * objects are not drawn at all (resolution 0, as a
   * culled object: nothing of them is drawn, picked or shown in the
   * resolution map); a bounding-box outline level is not offered (see
   * docs/rendering.md).
   */
  vtkSetMacro(DropObjectsWhenOverloaded, bool);
  vtkGetMacro(DropObjectsWhenOverloaded, bool);
  vtkBooleanMacro(DropObjectsWhenOverloaded, bool);
  /// Objects the last frame dropped (0 when it was not overloaded).
  vtkGetMacro(NumberOfDroppedObjects, vtkIdType);
  /// Whether the last frame dropped object i (false for a bad index).
  bool GetObjectDropped(vtkIdType object) const;
  ///@}

  ///@{
  /**
   * Hysteresis h on each object's choice, for every policy (Funkhouser &
   * Séquin's benefit factor for temporal coherence; timecritical::
   * HysteresisBand): a change of an object's resolution from the last frame
   * must pay for itself by a factor 1 / (1 - h) in marginal value
   * (degradation saved per second), so small changes of the view do not make
   * resolutions flip-flop (popping). The continuous policies keep last
   * frame's resolution of every object whose new one lies within a factor
   * (1 - h)^(-1 / (alpha + 1)) of it, as long as the frame stays within its
   * budget; GREEDY_LOD weighs its level moves by the same factor; frames that
   * drop objects hold the drawn objects' resolutions alike. Still frames
   * ignore it. In [0, 1); a value outside is an error and leaves the setting
   * as it was. Default 0 (none; see docs/benchmarks/w1.md for what it costs
   * and saves).
   */
  void SetHysteresis(double hysteresis);
  vtkGetMacro(Hysteresis, double);
  ///@}

  ///@{
  /**
   * Popping statistics of the last frame: of the visible objects drawn in
   * the frame before too, those whose resolution changed (dropped ones
   * included), and those the hysteresis kept at their last resolution.
   */
  vtkGetMacro(NumberOfChangedObjects, vtkIdType);
  vtkGetMacro(NumberOfHeldObjects, vtkIdType);
  ///@}

  /// Render the window once with every object at full resolution.
  void StillRender();

  /**
   * As vtkRenderer's; in addition, an automatic calibration made before the
   * camera was ever reset (a script's first render, which ParaView's
   * simple.Render draws before resetting the camera to the data, may see
   * only a corner of the scene) runs again in the next frame, at the view of
   * the data.
   */
  using Superclass::ResetCamera;
  void ResetCamera(const double bounds[6]) override;

  ///@{
  /**
   * Background hierarchy builds (vtkMultiresolutionPolyDataMapper::
   * SetBackgroundBuilds): block until every multiresolution mapper of this
   * renderer's actors has its pending builds finished and swapped in (for
   * scripts and tests that need the final image; the next render uses
   * them), and the number of leaves still drawn without their hierarchy.
   */
  void WaitForHierarchies();
  int GetNumberOfPendingHierarchies();
  ///@}

  ///@{
  /**
   * While on, every render is a still frame: every object at full
   * resolution, as StillRender() draws. For applications that decide
   * themselves which renders are still (ParaView's still renders: at rest,
   * screenshots). Default off.
   */
  vtkSetMacro(StillRendering, bool);
  vtkGetMacro(StillRendering, bool);
  vtkBooleanMacro(StillRendering, bool);
  ///@}

  ///@{
  /**
   * While on, renders draw every object as the last planned frame left it:
   * no culling, no optimization, no measurement (the statistics stay those
   * of that frame). For captures that draw one frame in several passes,
   * such as tiled screenshots, whose tiles would otherwise each get a plan
   * of their own. Default off. Hardware selection (a vtkHardwareSelector
   * on this renderer) always renders this way.
   */
  vtkSetMacro(HoldResolutions, bool);
  vtkGetMacro(HoldResolutions, bool);
  vtkBooleanMacro(HoldResolutions, bool);
  ///@}

  ///@{
  /**
   * Cost model calibration. AutomaticCalibration (default on) runs
   * Calibrate()'s renders in the first render with objects, still or not
   * (unless the policy is FULL_RESOLUTION), so that no interactive frame
   * pays for it. With background hierarchy builds pending in that render it
   * does not run (the frame in which the builds end may come while the user
   * drags): the model is then fitted from the frames themselves, and counts
   * as measured after 14 of them. OnlineCalibration (default on) refines the
   * coefficients
   * from every measured frame, within lower bounds (see the class comment).
   * Turn both off and set the coefficients for deterministic resolutions
   * (tests).
   */
  vtkSetMacro(AutomaticCalibration, bool);
  vtkGetMacro(AutomaticCalibration, bool);
  vtkBooleanMacro(AutomaticCalibration, bool);
  vtkSetMacro(OnlineCalibration, bool);
  vtkGetMacro(OnlineCalibration, bool);
  vtkBooleanMacro(OnlineCalibration, bool);
  ///@}

  /**
   * Start-up calibration: renders the current scene hidden at several
   * resolutions and zoom factors, times them, and fits the cost model; the
   * online refinement may then lower the triangle cost to half of the fit,
   * no further. The renders are sized to the target (the larger of
   * TargetFrameTime and the effective target): 14 samples of two renders,
   * each drawing at most what one target affords, about 12 targets in all
   * plus the first upload of the scene, never more than 30 targets
   * (GetCalibrationTime() has the last one's seconds). Needs a render
   * window. Returns false (and keeps the previous coefficients) when the
   * scene has nothing to measure.
   */
  bool Calibrate();
  vtkGetMacro(Calibrated, bool);
  /**
   * Whether the cost model is a measurement of this machine: calibrated,
   * given (SetCostCoefficients), scaled by a still frame, or fitted from 14
   * interactive frames. Until then no frame drops objects.
   */
  bool GetCostModelMeasured() const;
  vtkGetMacro(CalibrationTime, double);   ///< seconds of the last calibration (0: none)
  vtkGetMacro(CalibrationRenders, int);   ///< hidden calibration renders so far

  ///@{
  /**
   * Cost coefficients (seconds): per frame, per draw call, per triangle and
   * per covered pixel (bounding-box pixels of the objects), plus a safety
   * margin added to the fixed time. All finite and >= 0, the triangle cost
   * > 0. They are used as given; online refinement (when on) may lower the
   * triangle cost to half of it, and none below its physical minimum
   * (timecritical::FrameCostModel::PhysicalMinimum(): a pixel is never free
   * either, so a pixel cost of 0 becomes 1e-12 after the first measured
   * frame).
   */
  void SetCostCoefficients(double frame, double drawCall, double triangle, double pixel);
  double GetFrameCost() const;
  double GetDrawCallCost() const;
  double GetTriangleCost() const;
  double GetPixelCost() const;
  void SetCostMargin(double seconds);
  double GetCostMargin() const;
  ///@}

  ///@{
  /**
   * Safety factor k: the optimizer plans for predicted + k sigma <= target,
   * sigma the recent relative spread of measured / predicted times (with
   * OnlineCalibration; none without),
   * so that frames miss the target rarely rather than half the time (the
   * paper's "worst case estimate"). The reported prediction stays unbiased.
   * The margin k sigma target is capped at a quarter of the target and at
   * half of what the fixed part and the objects' coarsest levels leave of it
   * (so a noisy machine coarsens the frame rather than emptying it).
   * Default 1.5; 0 plans to the target itself.
   */
  void SetSafetyFactor(double k); ///< in [0, 10]
  vtkGetMacro(SafetyFactor, double);
  ///@}

  ///@{
  /**
   * Cost multiplier, for one frame, of objects that were not drawn in the
   * previous frame (newly visible, or back from culling). Data that was not
   * touched for a while is slower to draw the first time (caches, memory the
   * system reclaimed): on this project's machines a sudden turn to a view of
   * new objects costs about twice as much in its first frame. Default 2; 1
   * treats them like the others.
   */
  void SetNewObjectCostFactor(double factor); ///< in [1, 10]
  vtkGetMacro(NewObjectCostFactor, double);
  ///@}

  ///@{
  /**
   * Seconds of every frame spent after this renderer's drawing, in parallel
   * compositing for instance: the optimizer plans the drawing for the target
   * minus this time (part of the fixed time). Such a frame should have its
   * drawing's end marked (MarkDrawingFinished, done by
   * vtkTimeCriticalDrawingPass), so that the cost model learns the drawing
   * alone. vtkPVTimeCriticalRenderView sets it under MPI from the ranks'
   * measurements. >= 0; default 0.
   */
  void SetCompositingTime(double seconds);
  vtkGetMacro(CompositingTime, double);
  ///@}

  /**
   * Marks the end of this frame's drawing (called by
   * vtkTimeCriticalDrawingPass once the drawing is complete). In a frame so
   * marked the cost model learns from the time from the frame's start to
   * this mark (MeasuredDrawingTime) instead of the whole frame.
   */
  void MarkDrawingFinished();

  ///@{
  /// Statistics of the last frame.
  /// The last frame's drawing: up to MarkDrawingFinished() where it was marked, else the whole frame.
  vtkGetMacro(MeasuredDrawingTime, double);
  vtkGetMacro(PredictedFrameTime, double);   ///< still frames too (their own correction)
  vtkGetMacro(FixedFrameTime, double);       ///< t_fixed of the prediction
  vtkGetMacro(SafetyMargin, double);         ///< k sigma kept free of the target (s)
  vtkGetMacro(LastTargetFrameTime, double);  ///< target the last frame was planned for (+inf: still)
  vtkGetMacro(MeasuredFrameTime, double);    ///< last completed frame (NaN before any)
  vtkGetMacro(OptimizationTime, double);     ///< seconds spent in the policy
  vtkGetMacro(HeuristicsTime, double);       ///< seconds spent culling and measuring
  /**
   * Seconds the last frame spent on changed data, outside the cost model:
   * mappers reading their objects again (new input, changed leaves, finished
   * background builds swapped in) and rebuilding their vertex buffers. The
   * frame plans for it as fixed time (the vertex buffers by their last
   * build's time) and the online calibration leaves it out.
   */
  vtkGetMacro(DataChangeTime, double);
  vtkGetMacro(OptimizationIterations, int);
  vtkGetMacro(OptimizationConverged, bool);
  vtkGetMacro(TrianglesDrawn, vtkIdType);    ///< all triangles (objects and ordinary actors)
  vtkGetMacro(ObjectTrianglesDrawn, vtkIdType); ///< triangles of the multiresolution objects
  vtkGetMacro(NumberOfObjects, vtkIdType);
  vtkGetMacro(NumberOfCulledObjects, vtkIdType);
  vtkGetMacro(CoveredPixels, double); ///< projected pixels of the visible objects (sum)
  double GetCostModelResidual() const; ///< robust scale of the prediction residuals (s)
  vtkGetMacro(LastRenderWasStill, bool);
  vtkIdType GetObjectTriangles(vtkIdType object) const;  ///< -1 for a bad index
  double GetObjectResolution(vtkIdType object) const;     ///< 0 when culled, NaN for a bad index
  double GetObjectPixels(vtkIdType object) const;         ///< projected coverage
  vtkActor* GetObjectActor(vtkIdType object) const;
  vtkIdType GetObjectIndex(vtkIdType object) const;       ///< index within the actor's mapper
  ///@}

  ///@{
  /**
   * View-dependent refinement settings, applied to every multiresolution
   * mapper drawn. They follow timecritical::RefinementSettings
   * (RefinementSettings.h), as in the mapper and vtkExtractViewDependentMesh:
   * one numbering of the modes, a number out of range (NaN included) is an
   * error and leaves the setting as it was, a mode out of range is clamped.
   */
  enum RefinementModes
  {
    BUDGET = 0,        ///< front refined to the policy's triangle budget
    FIXED_ACCURACY = 1 ///< front refined to PixelThreshold
  };
  vtkSetMacro(ViewDependentRefinement, bool);
  vtkGetMacro(ViewDependentRefinement, bool);
  vtkBooleanMacro(ViewDependentRefinement, bool);
  vtkSetClampMacro(RefinementMode, int, BUDGET, FIXED_ACCURACY);
  vtkGetMacro(RefinementMode, int);
  void SetRefinementModeToBudget() { this->SetRefinementMode(BUDGET); }
  void SetRefinementModeToFixedAccuracy() { this->SetRefinementMode(FIXED_ACCURACY); }
  void SetPixelThreshold(double tau); ///< pixels, finite and >= 0 (default 1)
  vtkGetMacro(PixelThreshold, double);
  vtkSetMacro(BackFaceSimplification, bool);
  vtkGetMacro(BackFaceSimplification, bool);
  vtkBooleanMacro(BackFaceSimplification, bool);
  vtkSetMacro(SilhouetteRefinement, bool);
  vtkGetMacro(SilhouetteRefinement, bool);
  vtkBooleanMacro(SilhouetteRefinement, bool);
  void SetSilhouetteFactor(double factor); ///< in (0, 1], default 0.25
  vtkGetMacro(SilhouetteFactor, double);
  vtkSetMacro(HighlightRefinement, bool);
  vtkGetMacro(HighlightRefinement, bool);
  vtkBooleanMacro(HighlightRefinement, bool);
  void SetHighlightFactor(double factor); ///< in (0, 1], default 0.5
  vtkGetMacro(HighlightFactor, double);
  /**
   * BUDGET mode: seconds per frame the fronts of one mapper may spend on
   * refinement (default 0.01; 0: no limit). A front then moves towards the
   * budget the policy gives it by what fits in the limit, so a large change
   * of view or budget spreads over a few frames instead of stalling one.
   * Still frames are never limited.
   */
  void SetRefinementTimeLimit(double seconds);
  vtkGetMacro(RefinementTimeLimit, double);
  ///@}

  ///@{
  /// Refinement statistics of the last frame.
  vtkGetMacro(RefinementTime, double); ///< seconds spent refining all fronts
  bool GetObjectIsViewDependent(vtkIdType object) const;
  vtkIdType GetObjectVertices(vtkIdType object) const; ///< display vertices drawn, -1 for a bad index
  vtkIdType GetObjectSplits(vtkIdType object) const;   ///< vertex splits, -1 for a bad index
  vtkIdType GetObjectMerges(vtkIdType object) const;   ///< edge collapses, -1 for a bad index
  double GetObjectRefinementTime(vtkIdType object) const; ///< seconds, NaN for a bad index
  ///@}

  void DeviceRender() override;

protected:
  vtkTimeCriticalRenderer();
  ~vtkTimeCriticalRenderer() override;

  double TargetFrameTime = 0.1;
  double OptimizationTimeLimit = 0.001;
  int Policy = ACTIVE_SET;
  int DegradationFamily = HITCHNER;
  bool UseVelocity = true;
  bool UseEccentricity = true;
  double FocusPoint[2] = { 0.5, 0.5 };
  int FocusMode = FIXED_POINT;
  int FocusFalloff = FAMILY_DEFAULT;
  double LinearFalloffDegrees = 30.0;
  double LastFocus[2] = { 0.5, 0.5 };
  double DisplayResolution[2] = { 1920.0, 1080.0 };
  double DisplaySize[2] = { 0.531, 0.299 };
  double ViewingDistance = 0.6;
  double StaticPixelsPerTriangle = 8.0;
  bool UseDesiredUpdateRate = false;
  bool StillRendering = false;
  bool HoldResolutions = false;
  double StillUpdateRateThreshold = 0.001;
  bool AutomaticCalibration = true;
  bool OnlineCalibration = true;
  bool Calibrated = false;
  bool CalibrationAttempted = false; // automatic calibration runs once, even if it fails
  double CalibrationTime = 0.0;
  int CalibrationRenders = 0;
  double LastTargetFrameTime = 0.1;
  double SafetyFactor = 1.5;
  double NewObjectCostFactor = 2.0;
  bool ViewDependentRefinement = true;
  int RefinementMode = BUDGET;
  double PixelThreshold = 1.0;
  bool BackFaceSimplification = true;
  bool SilhouetteRefinement = true;
  double SilhouetteFactor = 0.25;
  bool HighlightRefinement = true;
  double HighlightFactor = 0.5;
  double RefinementTimeLimit = 0.01;
  double RefinementTime = 0.0;

  double PredictedFrameTime = 0.0;
  double FixedFrameTime = 0.0;
  double SafetyMargin = 0.0;
  double MeasuredFrameTime;
  double MeasuredDrawingTime;
  double CompositingTime = 0.0;
  double OptimizationTime = 0.0;
  double HeuristicsTime = 0.0;
  double DataChangeTime = 0.0;
  int OptimizationIterations = 0;
  bool OptimizationConverged = true;
  vtkIdType TrianglesDrawn = 0;
  vtkIdType ObjectTrianglesDrawn = 0;
  vtkIdType NumberOfObjects = 0;
  vtkIdType NumberOfCulledObjects = 0;
  double CoveredPixels = 0.0;
  bool LastRenderWasStill = false;
  bool DropObjectsWhenOverloaded = true;
  vtkIdType NumberOfDroppedObjects = 0;
  double Hysteresis = 0.0;
  vtkIdType NumberOfChangedObjects = 0;
  vtkIdType NumberOfHeldObjects = 0;

private:
  vtkTimeCriticalRenderer(const vtkTimeCriticalRenderer&) = delete;
  void operator=(const vtkTimeCriticalRenderer&) = delete;

  void WatchWindow();
  void OnWindowStart();
  void OnWindowEnd();
  void ScaleDefaultCoefficients(double measured);
  void GatherObjects();
  void MeasureObjects();
  void ChooseResolutions(bool still);
  // Dropping (vtkTimeCriticalRendererDropping.cxx): the visible objects'
  // per-object fixed costs and values (returns the sum of those costs), the
  // safety margin, and the choice with dropping when the frame is overloaded.
  double PrepareDropping(bool still, double correction);
  double PlanningMargin(double target, double fixed, double objectFixed, bool still);
  bool ChooseWithDropping(double target, double fixed, double objectFixed);
  void RunCalibration();
  void CalibrationStep(double savedAngle, double savedScale);
  double CalibrationSample(double r, int renders, bool record = true);
  void FinishCalibration();
  // Hysteresis (vtkTimeCriticalRendererHysteresis.cxx): holds the drawn
  // objects of a frame that dropped (returns the cost the holds added), and
  // counts the changes of the frame's choice.
  double HoldDrawnObjects(double slack);
  void CountChanges();
  // Focus (vtkTimeCriticalRendererFocus.cxx): the frame's focus in normalized
  // viewport coordinates (LastFocus), and the eccentricity model to use.
  void UpdateFocus();
  int EccentricityModel(int familyDefault) const;
  double MeasureDataChange(); ///< seconds of the pending frame's reads and vertex buffer builds
  void FinishFrame();

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
