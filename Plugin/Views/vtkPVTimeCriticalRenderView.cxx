// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPVTimeCriticalRenderView.h"

#include "TimeCriticalStatisticsText.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCollectionIterator.h"
#include "vtkCommand.h"
#include "vtkCameraPass.h"
#include "vtkDataRepresentation.h"
#include "vtkHierarchyBuildCache.h"
#include "vtkHierarchyBuildQueue.h"
#include "vtkIceTCompositePass.h"
#include "vtkImageProcessingPass.h"
#include "vtkMultiProcessController.h"
#include "vtkMultiresolutionPolyDataMapper.h"
#include "vtkObjectFactory.h"
#include "vtkObjectFactoryCollection.h"
#include "vtkOpenGLRenderer.h"
#include "vtkPVProcessWindow.h"
#include "vtkPVSession.h"
#include "vtkPVTimeCriticalStatisticsInformation.h"
#include "vtkSMProxy.h"
#include "vtkSMProxyManager.h"
#include "vtkSMViewProxy.h"
#include "vtkSMSessionProxyManager.h"
#include "vtkProcessModule.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkTimeCriticalCompositeRepresentation.h"
#include "vtkTimeCriticalSurfaceRepresentation.h"
#include "vtkTextProperty.h"
#include "vtkTimeCriticalRenderer.h"
#include "vtkVersion.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace
{
/**
 * vtkPVRenderView creates its renderer inside its constructor (through
 * vtkRenderViewBase) and wires it into the synchronized renderers, the
 * selector, the lights, the culler and the widgets. Replacing it afterwards
 * would mean redoing all of that, so instead the view is constructed while
 * this factory answers vtkRenderer::New(): ParaView 5.11's constructor asks
 * for the orientation axes' renderer first and the view's own second (after
 * the process window's, which RendererOverrideScope creates beforehand where
 * the view will use one), so the second is a vtkTimeCriticalRenderer and
 * every other one a vtkOpenGLRenderer, as VTK's own factory would give. The view's constructor
 * checks the result (an error names a ParaView that builds in another
 * order). The other factories' vtkRenderer overrides are disabled for that
 * time only (the first registered factory would otherwise win) and restored
 * exactly.
 */
class TimeCriticalRendererFactory : public vtkObjectFactory
{
public:
  static TimeCriticalRendererFactory* New()
  {
    auto* factory = new TimeCriticalRendererFactory;
    factory->InitializeObjectBase();
    return factory;
  }
  vtkTypeMacro(TimeCriticalRendererFactory, vtkObjectFactory);
  const char* GetVTKSourceVersion() override { return VTK_SOURCE_VERSION; }
  const char* GetDescription() override
  {
    return "TimeCritical: the renderer of vtkPVTimeCriticalRenderView";
  }

  static constexpr int ViewRendererRequest = 2; // 1-based, see the class comment
  static int Requests;

protected:
  TimeCriticalRendererFactory()
  {
    this->RegisterOverride("vtkRenderer", "vtkTimeCriticalRenderer",
      "the renderer of vtkPVTimeCriticalRenderView", 1, &TimeCriticalRendererFactory::Create);
  }

private:
  static vtkObject* Create()
  {
    if (++Requests == ViewRendererRequest)
    {
      return vtkTimeCriticalRenderer::New();
    }
    return vtkOpenGLRenderer::New();
  }
};
int TimeCriticalRendererFactory::Requests = 0;

/// Installs TimeCriticalRendererFactory for the lifetime of the object.
class RendererOverrideScope
{
public:
  RendererOverrideScope()
  {
    // Views of batch and server processes draw into the process window,
    // created (with a renderer of its own) by the first view: create it
    // now, so that its renderer is not counted.
    if (vtkProcessModule::GetProcessModule())
    {
      switch (vtkProcessModule::GetProcessType())
      {
        case vtkProcessModule::PROCESS_SERVER:
        case vtkProcessModule::PROCESS_RENDER_SERVER:
        case vtkProcessModule::PROCESS_BATCH:
          vtkPVProcessWindow::GetRenderWindow();
          break;
        default:
          break;
      }
    }
    vtkObjectFactoryCollection* factories = vtkObjectFactory::GetRegisteredFactories();
    vtkCollectionSimpleIterator it;
    factories->InitTraversal(it);
    while (vtkObjectFactory* factory = factories->GetNextObjectFactory(it))
    {
      for (int i = 0; i < factory->GetNumberOfOverrides(); ++i)
      {
        if (std::strcmp(factory->GetClassOverrideName(i), "vtkRenderer") == 0 &&
          factory->GetEnableFlag(i))
        {
          this->Disabled.emplace_back(factory, factory->GetClassOverrideWithName(i));
        }
      }
    }
    for (const auto& entry : this->Disabled)
    {
      entry.first->SetEnableFlag(0, "vtkRenderer", entry.second.c_str());
    }
    TimeCriticalRendererFactory::Requests = 0;
    vtkObjectFactory::RegisterFactory(this->Factory);
  }
  ~RendererOverrideScope()
  {
    vtkObjectFactory::UnRegisterFactory(this->Factory);
    for (const auto& entry : this->Disabled)
    {
      entry.first->SetEnableFlag(1, "vtkRenderer", entry.second.c_str());
    }
  }
  RendererOverrideScope(const RendererOverrideScope&) = delete;
  RendererOverrideScope& operator=(const RendererOverrideScope&) = delete;

private:
  vtkNew<TimeCriticalRendererFactory> Factory;
  std::vector<std::pair<vtkObjectFactory*, std::string>> Disabled;
};

/// A client connected to a separate server (whose processes render).
bool IsRemoteClient()
{
  vtkProcessModule* pm = vtkProcessModule::GetProcessModule();
  if (!pm || vtkProcessModule::GetProcessType() != vtkProcessModule::PROCESS_CLIENT)
  {
    return false;
  }
  auto* session = vtkPVSession::SafeDownCast(pm->GetActiveSession());
  return session && session->GetController(vtkPVSession::DATA_SERVER);
}

/// Start-up calibration re-renders the window on this process alone: safe
/// only where no other process composites or mirrors its renders.
bool CalibrationIsSafeHere()
{
  vtkMultiProcessController* global = vtkMultiProcessController::GetGlobalController();
  if (global && global->GetNumberOfProcesses() > 1)
  {
    return false;
  }
  vtkProcessModule* pm = vtkProcessModule::GetProcessModule();
  if (!pm)
  {
    return true; // plain VTK use of the class
  }
  switch (vtkProcessModule::GetProcessType())
  {
    case vtkProcessModule::PROCESS_BATCH:
      return true;
    case vtkProcessModule::PROCESS_CLIENT:
      return !IsRemoteClient();
    default:
      return false;
  }
}

} // namespace

//------------------------------------------------------------------------------
vtkPVTimeCriticalRenderView* vtkPVTimeCriticalRenderView::New()
{
  if (vtkObject* overridden = vtkObjectFactory::CreateInstance("vtkPVTimeCriticalRenderView"))
  {
    return static_cast<vtkPVTimeCriticalRenderView*>(overridden);
  }
  RendererOverrideScope scope;
  auto* view = new vtkPVTimeCriticalRenderView;
  view->InitializeObjectBase();
  return view;
}

//------------------------------------------------------------------------------
vtkPVTimeCriticalRenderView::vtkPVTimeCriticalRenderView()
{
  vtkTimeCriticalRenderer* renderer = this->GetTimeCriticalRenderer();
  if (!renderer)
  {
    vtkErrorMacro("The render view's renderer is a "
      << this->GetRenderer()->GetClassName()
      << ", not a vtkTimeCriticalRenderer: this ParaView creates its renderer in another way "
         "than TimeCritical expects; frames are drawn without a budget.");
  }
  else if (!CalibrationIsSafeHere())
  {
    renderer->AutomaticCalibrationOff();
  }
  this->Superclass::SetLODRenderingThreshold(std::numeric_limits<double>::max());

  vtkTextProperty* text = this->StatisticsActor->GetTextProperty();
  text->SetFontSize(14);
  text->SetJustificationToLeft();
  text->SetVerticalJustificationToTop();
  text->SetColor(1.0, 1.0, 1.0);
  text->SetBackgroundColor(0.0, 0.0, 0.0);
  text->SetBackgroundOpacity(0.5);
  this->StatisticsActor->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  this->StatisticsActor->SetPosition(0.01, 0.99);
  this->StatisticsActor->SetVisibility(0);
  this->StatisticsActor->SetPickable(0);
  this->GetNonCompositedRenderer()->AddActor(this->StatisticsActor);
}

//------------------------------------------------------------------------------
vtkPVTimeCriticalRenderView::~vtkPVTimeCriticalRenderView()
{
  if (vtkRenderWindowInteractor* interactor = this->TimerInteractor)
  {
    if (this->HierarchyTimer != 0)
    {
      interactor->DestroyTimer(this->HierarchyTimer);
    }
    interactor->RemoveObserver(this->TimerObserver);
  }
}

//------------------------------------------------------------------------------
vtkTimeCriticalRenderer* vtkPVTimeCriticalRenderView::GetTimeCriticalRenderer()
{
  return vtkTimeCriticalRenderer::SafeDownCast(this->GetRenderer());
}

//------------------------------------------------------------------------------
// Forwarding. Each setter reports a missing time-critical renderer once (in
// the constructor) and does nothing then.
#define TIMECRITICAL_FORWARD(setter, type, expression)                                           \
  void vtkPVTimeCriticalRenderView::setter(type value)                                           \
  {                                                                                              \
    if (vtkTimeCriticalRenderer* renderer = this->GetTimeCriticalRenderer())                     \
    {                                                                                            \
      expression;                                                                                \
      this->Modified();                                                                          \
    }                                                                                            \
  }

TIMECRITICAL_FORWARD(SetTargetFrameTimeMilliseconds, double,
  renderer->SetTargetFrameTime(value / 1000.0))
TIMECRITICAL_FORWARD(SetOptimizationTimeLimitMilliseconds, double,
  renderer->SetOptimizationTimeLimit(value / 1000.0))
TIMECRITICAL_FORWARD(SetPolicy, int, renderer->SetPolicy(value))
TIMECRITICAL_FORWARD(SetDegradationFamily, int, renderer->SetDegradationFamily(value))
TIMECRITICAL_FORWARD(SetUseVelocity, bool, renderer->SetUseVelocity(value))
TIMECRITICAL_FORWARD(SetUseEccentricity, bool, renderer->SetUseEccentricity(value))
TIMECRITICAL_FORWARD(SetDropObjectsWhenOverloaded, bool,
  renderer->SetDropObjectsWhenOverloaded(value))
TIMECRITICAL_FORWARD(SetHysteresis, double, renderer->SetHysteresis(value))
TIMECRITICAL_FORWARD(SetFocusMode, int, renderer->SetFocusMode(value))
TIMECRITICAL_FORWARD(SetFocusFalloff, int, renderer->SetFocusFalloff(value))
TIMECRITICAL_FORWARD(SetViewDependentRefinement, bool, renderer->SetViewDependentRefinement(value))
TIMECRITICAL_FORWARD(SetRefinementMode, int, renderer->SetRefinementMode(value))
TIMECRITICAL_FORWARD(SetPixelThreshold, double, renderer->SetPixelThreshold(value))
TIMECRITICAL_FORWARD(SetBackFaceSimplification, bool, renderer->SetBackFaceSimplification(value))
TIMECRITICAL_FORWARD(SetSilhouetteRefinement, bool, renderer->SetSilhouetteRefinement(value))
TIMECRITICAL_FORWARD(SetHighlightRefinement, bool, renderer->SetHighlightRefinement(value))
TIMECRITICAL_FORWARD(SetRefinementTimeLimitMilliseconds, double,
  renderer->SetRefinementTimeLimit(value / 1000.0))
#undef TIMECRITICAL_FORWARD

double vtkPVTimeCriticalRenderView::GetTargetFrameTimeMilliseconds()
{
  vtkTimeCriticalRenderer* renderer = this->GetTimeCriticalRenderer();
  return renderer ? renderer->GetTargetFrameTime() * 1000.0 : 0.0;
}

double vtkPVTimeCriticalRenderView::GetOptimizationTimeLimitMilliseconds()
{
  vtkTimeCriticalRenderer* renderer = this->GetTimeCriticalRenderer();
  return renderer ? renderer->GetOptimizationTimeLimit() * 1000.0 : 0.0;
}

int vtkPVTimeCriticalRenderView::GetPolicy()
{
  vtkTimeCriticalRenderer* renderer = this->GetTimeCriticalRenderer();
  return renderer ? renderer->GetPolicy() : -1;
}

int vtkPVTimeCriticalRenderView::GetDegradationFamily()
{
  vtkTimeCriticalRenderer* renderer = this->GetTimeCriticalRenderer();
  return renderer ? renderer->GetDegradationFamily() : -1;
}

bool vtkPVTimeCriticalRenderView::GetUseVelocity()
{
  vtkTimeCriticalRenderer* renderer = this->GetTimeCriticalRenderer();
  return renderer && renderer->GetUseVelocity();
}

bool vtkPVTimeCriticalRenderView::GetUseEccentricity()
{
  vtkTimeCriticalRenderer* renderer = this->GetTimeCriticalRenderer();
  return renderer && renderer->GetUseEccentricity();
}

bool vtkPVTimeCriticalRenderView::GetDropObjectsWhenOverloaded()
{
  vtkTimeCriticalRenderer* renderer = this->GetTimeCriticalRenderer();
  return renderer && renderer->GetDropObjectsWhenOverloaded();
}

double vtkPVTimeCriticalRenderView::GetHysteresis()
{
  vtkTimeCriticalRenderer* renderer = this->GetTimeCriticalRenderer();
  return renderer ? renderer->GetHysteresis() : 0.0;
}

int vtkPVTimeCriticalRenderView::GetFocusMode()
{
  vtkTimeCriticalRenderer* renderer = this->GetTimeCriticalRenderer();
  return renderer ? renderer->GetFocusMode() : -1;
}

int vtkPVTimeCriticalRenderView::GetFocusFalloff()
{
  vtkTimeCriticalRenderer* renderer = this->GetTimeCriticalRenderer();
  return renderer ? renderer->GetFocusFalloff() : -1;
}

//------------------------------------------------------------------------------
void vtkPVTimeCriticalRenderView::SetShowStatistics(bool on)
{
  if (this->ShowStatistics != on)
  {
    this->ShowStatistics = on;
    this->StatisticsActor->SetVisibility(on ? 1 : 0);
    this->Modified();
  }
}

void vtkPVTimeCriticalRenderView::SetLODRenderingThreshold(double)
{
  // The frame-time budget replaces ParaView's single-level LOD in this view.
}

//------------------------------------------------------------------------------
void vtkPVTimeCriticalRenderView::SetHierarchyCacheMemoryLimitMiB(double mib)
{
  if (!(mib >= 0.0) || !std::isfinite(mib))
  {
    vtkErrorMacro("HierarchyCacheMemory must be >= 0 MiB (0: leave the process's limit), not "
      << mib << ".");
    return;
  }
  if (mib != this->HierarchyCacheMemoryLimitMiB)
  {
    this->HierarchyCacheMemoryLimitMiB = mib;
    if (mib > 0.0)
    {
      vtkHierarchyBuildCache::GetSharedInstance()->SetMemoryLimit(
        static_cast<vtkTypeInt64>(std::min(mib, 1e12) * 1024.0 * 1024.0));
    }
  }
}

double vtkPVTimeCriticalRenderView::GetHierarchyCacheMemoryLimitMiB()
{
  return static_cast<double>(vtkHierarchyBuildCache::GetSharedInstance()->GetMemoryLimit()) /
    (1024.0 * 1024.0);
}

void vtkPVTimeCriticalRenderView::SetHierarchyCacheDirectory(const char* path)
{
  const std::string directory = path ? path : "";
  if (directory != this->HierarchyCacheDirectory)
  {
    this->HierarchyCacheDirectory = directory;
    vtkHierarchyBuildCache::GetSharedInstance()->SetDirectory(directory.c_str());
  }
}

std::string vtkPVTimeCriticalRenderView::GetHierarchyCacheDirectory()
{
  return vtkHierarchyBuildCache::GetSharedInstance()->GetDirectory();
}

//------------------------------------------------------------------------------
void vtkPVTimeCriticalRenderView::SetBackgroundHierarchyBuilds(bool on)
{
  if (on != this->BackgroundHierarchyBuilds)
  {
    this->BackgroundHierarchyBuilds = on;
    this->ApplyBackgroundBuilds();
    this->Modified();
  }
}

void vtkPVTimeCriticalRenderView::ApplyBackgroundBuilds()
{
  for (int i = 0; i < this->GetNumberOfRepresentations(); ++i)
  {
    auto* composite =
      vtkTimeCriticalCompositeRepresentation::SafeDownCast(this->GetRepresentation(i));
    vtkTimeCriticalSurfaceRepresentation* surface =
      composite ? composite->GetTimeCriticalSurface() : nullptr;
    if (surface)
    {
      surface->SetBackgroundBuilds(this->BackgroundHierarchyBuilds);
    }
  }
}

void vtkPVTimeCriticalRenderView::Update()
{
  // Representations added since the setting changed get it before they update.
  this->ApplyBackgroundBuilds();
  this->Superclass::Update();
}

void vtkPVTimeCriticalRenderView::WaitForHierarchies()
{
  if (vtkTimeCriticalRenderer* renderer = this->GetTimeCriticalRenderer())
  {
    renderer->WaitForHierarchies();
  }
}

int vtkPVTimeCriticalRenderView::GetNumberOfPendingHierarchies()
{
  vtkTimeCriticalRenderer* renderer = this->GetTimeCriticalRenderer();
  return renderer ? renderer->GetNumberOfPendingHierarchies() : 0;
}

bool vtkPVTimeCriticalRenderView::HierarchiesToShow()
{
  // Builds finished and not yet taken, or hierarchies swapped in since the
  // last frame drawn (ParaView may update the mappers, through their bounds,
  // in a pass that draws nothing).
  return this->CountSwappedHierarchies(true) != this->DisplayedSwaps;
}

vtkIdType vtkPVTimeCriticalRenderView::CountSwappedHierarchies(bool withFinished)
{
  vtkIdType swaps = 0;
  vtkTimeCriticalRenderer* renderer = this->GetTimeCriticalRenderer();
  vtkActorCollection* actors = renderer ? renderer->GetActors() : nullptr;
  vtkCollectionSimpleIterator it;
  if (actors)
  {
    actors->InitTraversal(it);
  }
  while (vtkActor* actor = actors ? actors->GetNextActor(it) : nullptr)
  {
    auto* mapper = vtkMultiresolutionPolyDataMapper::SafeDownCast(actor->GetMapper());
    if (mapper && mapper->GetBackgroundBuilds())
    {
      swaps += mapper->GetNumberOfSwappedHierarchies();
      swaps += withFinished ? mapper->GetBuildQueue()->GetNumberOfFinished() : 0;
    }
  }
  return swaps;
}

void vtkPVTimeCriticalRenderView::ScheduleHierarchyCheck()
{
  // Only where the view has an interactor (the GUI): a timer of the
  // interactor polls the builds every 200 ms while any is pending, and a
  // finished one is shown by a still render of the view's proxy, without
  // user action.
  vtkRenderWindowInteractor* interactor = this->GetInteractor();
  if (!interactor || this->HierarchyTimer != 0 ||
    (this->GetNumberOfPendingHierarchies() == 0 && !this->HierarchiesToShow()))
  {
    return;
  }
  if (interactor != this->TimerInteractor)
  {
    if (vtkRenderWindowInteractor* previous = this->TimerInteractor)
    {
      previous->RemoveObserver(this->TimerObserver);
    }
    this->TimerInteractor = interactor;
    this->TimerObserver = interactor->AddObserver(
      vtkCommand::TimerEvent, this, &vtkPVTimeCriticalRenderView::OnHierarchyTimer);
  }
  this->HierarchyTimer = interactor->CreateRepeatingTimer(200);
}

void vtkPVTimeCriticalRenderView::OnHierarchyTimer(vtkObject*, unsigned long, void* callData)
{
  if (this->HierarchyTimer == 0 || !callData || *static_cast<int*>(callData) != this->HierarchyTimer)
  {
    return; // someone else's timer
  }
  // A still render of the view's proxy, as the GUI's own renders are (the
  // interactor's Render() did not render the view in ParaView 5.11's GUI).
  auto* proxy = vtkSMViewProxy::SafeDownCast(this->FindViewProxy());
  if (proxy && this->HierarchiesToShow())
  {
    proxy->StillRender();
  }
  if (!proxy || (this->GetNumberOfPendingHierarchies() == 0 && !this->HierarchiesToShow()))
  {
    this->TimerInteractor->DestroyTimer(this->HierarchyTimer);
    this->HierarchyTimer = 0;
  }
}

//------------------------------------------------------------------------------
void vtkPVTimeCriticalRenderView::Render(bool interactive, bool skip_rendering)
{
  if (vtkTimeCriticalRenderer* renderer = this->GetTimeCriticalRenderer())
  {
    renderer->SetStillRendering(!interactive && this->FullResolutionStillRenders);
    vtkActorCollection* actors = renderer->GetActors();
    vtkCollectionSimpleIterator it;
    actors->InitTraversal(it);
    while (vtkActor* actor = actors->GetNextActor(it))
    {
      if (auto* mapper = vtkMultiresolutionPolyDataMapper::SafeDownCast(actor->GetMapper()))
      {
        mapper->SetColorByResolution(this->ColorByResolution);
      }
    }
  }
  // The overlay shows the figures of the frame before: one text for every
  // pass of this render (screenshots may draw a frame several times).
  if (this->ShowStatistics)
  {
    this->StatisticsActor->SetInput(this->GetStatisticsText().c_str());
  }
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (controller && controller->GetNumberOfProcesses() > 1)
  {
    this->InstallDrawingPass();
  }
  this->Superclass::Render(interactive, skip_rendering);
  this->GatherRankStatistics();
  // Known while rendering (the session is active then), used afterwards.
  this->RendersOnServer = IsRemoteClient();
  if (this->ShowStatistics && this->RendersOnServer)
  {
    this->FetchServerStatistics(); // for the overlay of the next render
  }
  if (this->BackgroundHierarchyBuilds)
  {
    if (!skip_rendering)
    {
      this->DisplayedSwaps = this->CountSwappedHierarchies(false);
    }
    this->ScheduleHierarchyCheck();
  }
}

//------------------------------------------------------------------------------
namespace
{
constexpr int RankStatisticsFields = 6;
/// Weight of the newest frame in the smoothed compositing time.
constexpr double CompositingSmoothing = 0.3;
}

void vtkPVTimeCriticalRenderView::GatherRankStatistics()
{
  vtkTimeCriticalRenderer* renderer = this->GetTimeCriticalRenderer();
  if (!renderer)
  {
    return;
  }
  const double mine[RankStatisticsFields] = { renderer->GetMeasuredFrameTime(),
    renderer->GetPredictedFrameTime(), renderer->GetLastTargetFrameTime(),
    static_cast<double>(renderer->GetObjectTrianglesDrawn()),
    renderer->GetFixedFrameTime() + renderer->GetSafetyMargin(),
    renderer->GetMeasuredDrawingTime() };
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const int ranks = controller ? controller->GetNumberOfProcesses() : 1;
  if (ranks > 1 && !this->GetUseDistributedRenderingForRender())
  {
    return; // not every rank rendered: no collective
  }
  this->RankStatistics.resize(static_cast<size_t>(RankStatisticsFields * ranks));
  if (ranks > 1)
  {
    controller->AllGather(mine, this->RankStatistics.data(), RankStatisticsFields);
  }
  else
  {
    std::copy(mine, mine + RankStatisticsFields, this->RankStatistics.begin());
  }
  if (ranks > 1)
  {
    this->UpdateCompositingTime(ranks);
  }
  double slowest = 0.0;
  for (int rank = 0; rank < ranks; ++rank)
  {
    const double rankTime = this->GetRankMeasuredFrameTime(rank);
    slowest = std::isfinite(rankTime) ? std::max(slowest, rankTime) : slowest;
  }
  TimeCriticalStatisticsText::SetRankSummary(renderer, ranks, slowest);
}

void vtkPVTimeCriticalRenderView::UpdateCompositingTime(int ranks)
{
  // After its drawing, a rank composites, and waits there for the slowest
  // drawer; that one does not wait, so the least time any rank spent after
  // its drawing is the compositing itself.
  double least = std::numeric_limits<double>::infinity();
  for (int rank = 0; rank < ranks; ++rank)
  {
    const double after = this->GetRankMeasuredFrameTime(rank) - this->GetRankDrawingTime(rank);
    least = std::isfinite(after) && after >= 0.0 ? std::min(least, after) : least;
  }
  if (!std::isfinite(least))
  {
    return;
  }
  this->CompositingTime = this->CompositingTime > 0.0
    ? (1.0 - CompositingSmoothing) * this->CompositingTime + CompositingSmoothing * least
    : least;
  if (vtkTimeCriticalRenderer* renderer = this->GetTimeCriticalRenderer())
  {
    renderer->SetCompositingTime(this->CompositingTime);
  }
}

void vtkPVTimeCriticalRenderView::InstallDrawingPass()
{
  // ParaView composites through an IceT pass behind the renderer's camera
  // pass (behind an image-processing pass where there is one); the IceT
  // pass delegates the drawing. The drawing pass goes between the two, again
  // whenever ParaView has replaced the delegate.
  vtkRenderPass* pass = this->GetRenderer()->GetPass();
  if (auto* processing = vtkImageProcessingPass::SafeDownCast(pass))
  {
    pass = processing->GetDelegatePass();
  }
  if (auto* camera = vtkCameraPass::SafeDownCast(pass))
  {
    pass = camera->GetDelegatePass();
  }
  auto* icet = vtkIceTCompositePass::SafeDownCast(pass);
  if (!icet || icet->GetRenderPass() == this->DrawingPass.GetPointer())
  {
    return;
  }
  this->DrawingPass->SetDelegatePass(icet->GetRenderPass());
  icet->SetRenderPass(this->DrawingPass);
}

double vtkPVTimeCriticalRenderView::GetRankDrawingTime(int rank)
{
  return this->GetRankStatistic(rank, 5);
}

int vtkPVTimeCriticalRenderView::GetNumberOfRanks()
{
  return static_cast<int>(this->RankStatistics.size() / RankStatisticsFields);
}

double vtkPVTimeCriticalRenderView::GetRankStatistic(int rank, int field)
{
  if (rank < 0 || rank >= this->GetNumberOfRanks())
  {
    vtkErrorMacro("No statistics for rank " << rank << " (" << this->GetNumberOfRanks()
                                            << " ranks gathered)");
    return std::numeric_limits<double>::quiet_NaN();
  }
  return this->RankStatistics[static_cast<size_t>(rank * RankStatisticsFields + field)];
}

double vtkPVTimeCriticalRenderView::GetRankMeasuredFrameTime(int rank)
{
  return this->GetRankStatistic(rank, 0);
}

double vtkPVTimeCriticalRenderView::GetRankPredictedFrameTime(int rank)
{
  return this->GetRankStatistic(rank, 1);
}

double vtkPVTimeCriticalRenderView::GetRankTargetFrameTime(int rank)
{
  return this->GetRankStatistic(rank, 2);
}

double vtkPVTimeCriticalRenderView::GetRankFixedFrameTime(int rank)
{
  return this->GetRankStatistic(rank, 4);
}

vtkIdType vtkPVTimeCriticalRenderView::GetRankTrianglesDrawn(int rank)
{
  const double triangles = this->GetRankStatistic(rank, 3);
  return std::isfinite(triangles) ? static_cast<vtkIdType>(triangles) : -1;
}

//------------------------------------------------------------------------------
void vtkPVTimeCriticalRenderView::PrepareForScreenshot()
{
  this->Superclass::PrepareForScreenshot();
  vtkTimeCriticalRenderer* renderer = this->GetTimeCriticalRenderer();
  const bool budgetedCapture =
    !this->FullResolutionStillRenders || this->GetUseInteractiveRenderingForScreenshots();
  if (renderer && budgetedCapture && !renderer->GetLastRenderWasStill() &&
    renderer->GetNumberOfObjects() > 0)
  {
    renderer->HoldResolutionsOn();
  }
}

void vtkPVTimeCriticalRenderView::CleanupAfterScreenshot()
{
  if (vtkTimeCriticalRenderer* renderer = this->GetTimeCriticalRenderer())
  {
    renderer->HoldResolutionsOff();
  }
  this->Superclass::CleanupAfterScreenshot();
}

//------------------------------------------------------------------------------
void vtkPVTimeCriticalRenderView::AddRepresentationInternal(vtkDataRepresentation* rep)
{
  if (!this->WarnedAboutOtherRepresentations && rep->IsA("vtkPVCompositeRepresentation") &&
    !rep->IsA("vtkTimeCriticalCompositeRepresentation"))
  {
    this->WarnedAboutOtherRepresentations = true;
    vtkWarningMacro("Data that is not polygonal (or is shown with a representation other than "
                    "the time-critical surface) is drawn by ParaView's standard "
                    "representations in this view: at full resolution, as a fixed cost of "
                    "every frame, outside the time-critical control.");
  }
  this->Superclass::AddRepresentationInternal(rep);
}

//------------------------------------------------------------------------------
std::string vtkPVTimeCriticalRenderView::GetStatisticsText()
{
  if (this->RendersOnServer)
  {
    // The surfaces are drawn (and planned) by the server's processes.
    return this->ServerStatisticsText.empty() ? "Time-critical rendering on the server"
                                              : this->ServerStatisticsText;
  }
  return this->GetLocalStatisticsText();
}

vtkSMProxy* vtkPVTimeCriticalRenderView::FindViewProxy()
{
  vtkSMProxyManager* manager =
    vtkSMProxyManager::IsInitialized() ? vtkSMProxyManager::GetProxyManager() : nullptr;
  vtkSMSessionProxyManager* pxm = manager ? manager->GetActiveSessionProxyManager() : nullptr;
  for (unsigned int i = 0, count = pxm ? pxm->GetNumberOfProxies("views") : 0;
       i < count && !this->ViewProxy; ++i)
  {
    vtkSMProxy* candidate = pxm->GetProxy("views", pxm->GetProxyName("views", i));
    if (candidate && candidate->GetClientSideObject() == this)
    {
      this->ViewProxy = candidate;
    }
  }
  return this->ViewProxy;
}

void vtkPVTimeCriticalRenderView::FetchServerStatistics()
{
  // This object is the client's half of a view proxy: find the proxy (once)
  // to ask the server, after the render, when the server waits for requests.
  if (vtkSMProxy* proxy = this->FindViewProxy())
  {
    vtkNew<vtkPVTimeCriticalStatisticsInformation> statistics;
    // The processes that render (the data server's in a session without a
    // separate render server); the information comes from their root.
    const vtkTypeUInt32 where = (proxy->GetLocation() & vtkPVSession::RENDER_SERVER)
      ? vtkPVSession::RENDER_SERVER
      : vtkPVSession::DATA_SERVER;
    proxy->GatherInformation(statistics, where);
    this->ServerStatisticsText = statistics->GetText();
  }
}

std::string vtkPVTimeCriticalRenderView::GetLocalStatisticsText()
{
  return TimeCriticalStatisticsText::Format(this->GetTimeCriticalRenderer());
}

//------------------------------------------------------------------------------
void vtkPVTimeCriticalRenderView::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ColorByResolution: " << this->ColorByResolution << "\n";
  os << indent << "FullResolutionStillRenders: " << this->FullResolutionStillRenders << "\n";
  os << indent << "ShowStatistics: " << this->ShowStatistics << "\n";
  os << indent << "CompositingTime: " << this->CompositingTime << "\n";
  os << indent << "BackgroundHierarchyBuilds: " << this->BackgroundHierarchyBuilds << "\n";
  os << indent << "TimeCriticalRenderer: " << this->GetTimeCriticalRenderer() << "\n";
}
