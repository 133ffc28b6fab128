// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkPVTimeCriticalRenderView
 * @brief   ParaView render view that holds a frame-time budget (server side of "TimeCriticalRenderView")
 *
 * A vtkPVRenderView whose renderer is a vtkTimeCriticalRenderer: everything a
 * Render View does (cameras, interaction, colouring, scalar bars, annotations,
 * compositing) works as usual, and the surfaces shown with
 * vtkTimeCriticalSurfaceRepresentation (the default representation of this
 * view for polygonal data) are drawn at the resolutions the renderer's
 * optimizer chooses so that a frame fits TargetFrameTime.
 *
 * Interactive renders (the user drags) are time-budgeted; still renders (at
 * rest, screenshots, Render() in Python) draw every object at full resolution
 * unless FullResolutionStillRenders is off, which budgets them too (for
 * camera paths scripted in Python). ParaView's own interactive LOD (one
 * decimated copy switched on above LODThreshold) is off in this view: the
 * budget replaces it, and SetLODRenderingThreshold() has no effect.
 *
 * ShowStatistics shows the renderer's statistics of the last frame in the
 * view (measured and predicted frame time, triangles drawn of the total,
 * objects drawn and culled, optimizer time). A client connected to a server
 * shows the server's (vtkPVTimeCriticalStatisticsInformation, gathered after
 * each render while ShowStatistics is on).
 *
 * BackgroundHierarchyBuilds (default off here; on for new views of the
 * ParaView GUI, vtkSMTimeCriticalRenderViewProxy): surfaces are shown at once (in
 * full, or large ones from a quick stand-in) while their hierarchies are
 * built on worker threads; each is used
 * from the first render after its build finished. In the GUI (builtin
 * session) the view then renders by itself (a timer of its interactor
 * polls the builds while any is pending), so the hierarchy appears without user
 * action; pvpython and pvbatch have no interactor: scripts render again or
 * call WaitForHierarchies() first. A client of a separate server shows the
 * hierarchies at its next render. Under MPI every rank builds its own
 * pieces; swapping them in needs no communication, so all ranks keep taking
 * the same render path.
 * Parallel (pvbatch, pvserver with several ranks): each rank plans its own
 * objects. Start-up calibration renders would be composited by every rank and
 * must not run on one rank alone, so with more than one rank the cost model
 * starts from this machine class's defaults and learns from every measured
 * frame, compositing included (the time from the window's start to its end
 * of render, of which compositing is part, is what each rank's model fits).
 *
 * @sa vtkTimeCriticalRenderer vtkTimeCriticalSurfaceRepresentation
 */
#ifndef vtkPVTimeCriticalRenderView_h
#define vtkPVTimeCriticalRenderView_h

#include "TimeCriticalViewsModule.h" // for export macro
#include "vtkPVRenderView.h"

#include "vtkNew.h"       // for vtkNew
#include "vtkTextActor.h"   // for vtkNew<vtkTextActor>
#include "vtkTimeCriticalDrawingPass.h" // for vtkNew<vtkTimeCriticalDrawingPass>
#include "vtkWeakPointer.h" // for vtkWeakPointer

#include <string> // for std::string
#include <vector> // for std::vector

class vtkRenderWindowInteractor;
class vtkSMProxy;
class vtkTimeCriticalRenderer;

class TIMECRITICALVIEWS_EXPORT vtkPVTimeCriticalRenderView : public vtkPVRenderView
{
public:
  static vtkPVTimeCriticalRenderView* New();
  vtkTypeMacro(vtkPVTimeCriticalRenderView, vtkPVRenderView);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The renderer that plans every frame (the view's default renderer).
  vtkTimeCriticalRenderer* GetTimeCriticalRenderer();

  ///@{
  /// Frame-time budget settings, forwarded to the renderer (which checks them).
  void SetTargetFrameTimeMilliseconds(double ms);          ///< > 0, default 100
  double GetTargetFrameTimeMilliseconds();
  void SetOptimizationTimeLimitMilliseconds(double ms);    ///< >= 0, default 1
  double GetOptimizationTimeLimitMilliseconds();
  void SetPolicy(int policy);                              ///< vtkTimeCriticalRenderer::Policies
  int GetPolicy();
  void SetDegradationFamily(int family);                   ///< vtkTimeCriticalRenderer::DegradationFamilies
  int GetDegradationFamily();
  void SetUseVelocity(bool on);
  bool GetUseVelocity();
  void SetUseEccentricity(bool on);
  bool GetUseEccentricity();
  /// Leave the least valuable objects out when even their coarsest levels do not fit (default on).
  void SetDropObjectsWhenOverloaded(bool on);
  bool GetDropObjectsWhenOverloaded();
  /// Hysteresis on each object's resolution, in [0, 1) (vtkTimeCriticalRenderer::SetHysteresis; default 0).
  void SetHysteresis(double hysteresis);
  double GetHysteresis();
  /// Where the focus is (vtkTimeCriticalRenderer::FocusModes) and its fall-off (FocusFalloffs).
  void SetFocusMode(int mode);
  int GetFocusMode();
  void SetFocusFalloff(int falloff);
  int GetFocusFalloff();
  ///@}

  ///@{
  /// View-dependent refinement settings, forwarded to the renderer.
  void SetViewDependentRefinement(bool on);
  void SetRefinementMode(int mode); ///< vtkTimeCriticalRenderer::RefinementModes
  void SetPixelThreshold(double pixels);
  void SetBackFaceSimplification(bool on);
  void SetSilhouetteRefinement(bool on);
  void SetHighlightRefinement(bool on);
  void SetRefinementTimeLimitMilliseconds(double ms); ///< >= 0 (0: no limit)
  ///@}

  ///@{
  /**
   * Draw every time-critical object in the grey of its resolution (the
   * papers' resolution maps; lighter is finer). Default off.
   */
  vtkSetMacro(ColorByResolution, bool);
  vtkGetMacro(ColorByResolution, bool);
  ///@}

  ///@{
  /// Still renders draw every object at full resolution (default on); off: they are budgeted too.
  vtkSetMacro(FullResolutionStillRenders, bool);
  vtkGetMacro(FullResolutionStillRenders, bool);
  ///@}

  ///@{
  /// Show the last frame's statistics in the view's upper left corner. Default off.
  void SetShowStatistics(bool on);
  vtkGetMacro(ShowStatistics, bool);
  ///@}

  /**
   * The statistics text ShowStatistics displays: the last frame's figures.
   * On a client connected to a server, the server's (gathered after each
   * render while ShowStatistics is on; the client's own renderer draws no
   * objects there).
   */
  std::string GetStatisticsText();

  /// The figures of this process's renderer (what the server sends its clients).
  std::string GetLocalStatisticsText();

  ///@{
  /**
   * Per-rank statistics of the last distributed render (every rank's
   * renderer plans its own objects): its measured time (of the frame before,
   * as GetMeasuredFrameTime()), predicted time, target, fixed part of the
   * prediction with the safety margin, triangles drawn, and the time of its
   * own drawing (of the frame before, without the compositing that follows;
   * the whole frame where it was not measured apart).
   * Gathered on every rank after each render that all ranks take part in;
   * with one process, rank 0 is this one. NaN or -1 for a bad rank.
   */
  int GetNumberOfRanks();
  double GetRankMeasuredFrameTime(int rank);
  double GetRankPredictedFrameTime(int rank);
  double GetRankTargetFrameTime(int rank);
  double GetRankFixedFrameTime(int rank);
  vtkIdType GetRankTrianglesDrawn(int rank);
  double GetRankDrawingTime(int rank);
  ///@}

  /**
   * With several ranks: the time a frame spends compositing after the
   * drawing, as planned for by every rank's renderer
   * (vtkTimeCriticalRenderer::SetCompositingTime). Estimated from the rank
   * that waits least (the slowest drawer, whose time after its drawing is
   * compositing alone), smoothed over frames. 0 with one rank.
   */
  vtkGetMacro(CompositingTime, double);

  ///@{
  /**
   * Screenshots: when their renders are budgeted (FullResolutionAtRest off)
   * they hold the resolutions of the last planned frame, so that the tiles
   * of a screenshot larger than the view show one frame, not a plan each.
   */
  void PrepareForScreenshot() override;
  void CleanupAfterScreenshot() override;
  ///@}

  /// Has no effect: the frame-time budget replaces ParaView's LOD in this view.
  void SetLODRenderingThreshold(double threshold);

  ///@{
  /**
   * The hierarchy cache of this process (vtkHierarchyBuildCache's shared
   * instance, used by every time-critical representation of the process and
   * their builds): its memory limit in MiB and its directory (empty: no disk
   * cache). One setting per process, so the last view to change it sets it;
   * a view applies a value only when it differs from the view's previous one,
   * so a new view's defaults (0 MiB and no directory: leave the process's
   * setting, by default a quarter of physical memory and no disk cache)
   * change nothing. A negative limit or a directory that cannot be written
   * is an error (the setting is then unchanged, or the disk cache off).
   */
  void SetHierarchyCacheMemoryLimitMiB(double mib);
  double GetHierarchyCacheMemoryLimitMiB();
  void SetHierarchyCacheDirectory(const char* path);
  std::string GetHierarchyCacheDirectory();
  ///@}

  ///@{
  /**
   * Background hierarchy builds for every time-critical surface of the view
   * (vtkTimeCriticalSurfaceRepresentation::SetBackgroundBuilds). Off by
   * default here: every surface then has its hierarchy when first drawn, as
   * tests, benchmarks and scripts that time interactive frames expect. The
   * GUI turns it on for new views (vtkSMTimeCriticalRenderViewProxy).
   */
  void SetBackgroundHierarchyBuilds(bool on);
  vtkGetMacro(BackgroundHierarchyBuilds, bool);
  ///@}

  /**
   * Block until every background build of this process's surfaces has
   * finished and is swapped in (the next render uses them all).
   */
  void WaitForHierarchies();

  /// Surfaces of this process drawn without their hierarchy while it is built.
  int GetNumberOfPendingHierarchies();

protected:
  vtkPVTimeCriticalRenderView();
  ~vtkPVTimeCriticalRenderView() override;

  void Render(bool interactive, bool skip_rendering) override;
  void Update() override;
  void ApplyBackgroundBuilds();
  void ScheduleHierarchyCheck();
  void OnHierarchyTimer(vtkObject* caller, unsigned long event, void* callData);
  bool HierarchiesToShow();
  vtkIdType CountSwappedHierarchies(bool withFinished);
  void AddRepresentationInternal(vtkDataRepresentation* rep) override;
  void GatherRankStatistics();
  void InstallDrawingPass();
  void UpdateCompositingTime(int ranks);
  void FetchServerStatistics();
  vtkSMProxy* FindViewProxy(); ///< a client's proxy of this view (builtin session: the same process)
  double GetRankStatistic(int rank, int field);

  bool ColorByResolution = false;
  bool FullResolutionStillRenders = true;
  bool ShowStatistics = false;
  bool BackgroundHierarchyBuilds = false;
  int HierarchyTimer = 0;                        // the polling timer's id, 0: none
  vtkWeakPointer<vtkRenderWindowInteractor> TimerInteractor; // observed for it
  unsigned long TimerObserver = 0;
  vtkIdType DisplayedSwaps = 0; // hierarchies swapped in as of the last frame drawn
  bool WarnedAboutOtherRepresentations = false;
  double HierarchyCacheMemoryLimitMiB = 0.0; // as last set on this view (0: not set)
  std::string HierarchyCacheDirectory;       // as last set on this view
  std::vector<double> RankStatistics; // per rank: measured, predicted, target, triangles, fixed, drawing
  double CompositingTime = 0.0;
  vtkNew<vtkTimeCriticalDrawingPass> DrawingPass;
  std::string ServerStatisticsText;   // a client's copy of the server's statistics
  bool RendersOnServer = false;       // a client of a separate server (as of the last render)
  vtkWeakPointer<vtkSMProxy> ViewProxy; // a client's proxy of this view, found once
  vtkNew<vtkTextActor> StatisticsActor;

private:
  vtkPVTimeCriticalRenderView(const vtkPVTimeCriticalRenderView&) = delete;
  void operator=(const vtkPVTimeCriticalRenderView&) = delete;
};

#endif
