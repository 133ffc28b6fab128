// SPDX-License-Identifier: BSD-3-Clause
#include "vtkTimeCriticalRenderer.h"

#include "vtkTimeCriticalRendererInternals.h"

using namespace timecritical::rendering;

static_assert(vtkTimeCriticalRenderer::BUDGET == timecritical::RefinementModeBudget &&
    vtkTimeCriticalRenderer::FIXED_ACCURACY == timecritical::RefinementModeFixedAccuracy,
  "one numbering of the refinement modes (RefinementSettings.h)");

vtkStandardNewMacro(vtkTimeCriticalRenderer);

vtkTimeCriticalRenderer::vtkTimeCriticalRenderer()
  : MeasuredFrameTime(NaN)
  , MeasuredDrawingTime(NaN)
  , Internal(new Internals)
{
  this->Internal->SetCoefficientFloors(false);
  this->Internal->ResetCalibrator();
  this->Internal->Static.SetPixelsPerTriangle(this->StaticPixelsPerTriangle);
  this->Internal->Feedback.SetInitialPixelsPerTriangle(this->StaticPixelsPerTriangle);
  this->SetDegradationFamily(HITCHNER);
  this->SetOptimizationTimeLimit(this->OptimizationTimeLimit);
}

vtkTimeCriticalRenderer::~vtkTimeCriticalRenderer()
{
  if (vtkRenderWindow* window = this->Internal->Window)
  {
    window->RemoveObserver(this->Internal->StartTag);
    window->RemoveObserver(this->Internal->EndTag);
  }
}

//------------------------------------------------------------------------------
// Settings

void vtkTimeCriticalRenderer::SetTargetFrameTime(double seconds)
{
  if (!(seconds > 0.0) || !std::isfinite(seconds))
  {
    vtkErrorMacro("TargetFrameTime must be a positive, finite number of seconds, not "
      << seconds << "; keeping " << this->TargetFrameTime);
    return;
  }
  if (seconds != this->TargetFrameTime)
  {
    this->TargetFrameTime = seconds;
    this->Modified();
  }
}

void vtkTimeCriticalRenderer::SetOptimizationTimeLimit(double seconds)
{
  if (!(seconds >= 0.0) || !std::isfinite(seconds))
  {
    vtkErrorMacro("OptimizationTimeLimit must be a finite number of seconds >= 0, not "
      << seconds << "; keeping " << this->OptimizationTimeLimit);
    return;
  }
  this->OptimizationTimeLimit = seconds;
  auto options = this->Internal->ActiveSet.GetOptions();
  options.TimeLimit = seconds;
  this->Internal->ActiveSet.SetOptions(options);
  this->Modified();
}

void vtkTimeCriticalRenderer::SetPolicy(int policy)
{
  if (policy < ACTIVE_SET || policy > GREEDY_LOD)
  {
    vtkErrorMacro("Unknown policy " << policy << "; keeping " << this->GetPolicyAsString());
    return;
  }
  if (policy != this->Policy)
  {
    this->Policy = policy;
    this->Internal->GetPolicy(policy)->Reset();
    this->Modified();
  }
}

const char* vtkTimeCriticalRenderer::GetPolicyAsString() const
{
  return this->Internal->GetPolicy(this->Policy)->GetName();
}

void vtkTimeCriticalRenderer::SetDegradationFamily(int family)
{
  using Model = timecritical::DegradationModel;
  if (family < HITCHNER || family > YANG_GU_KANG)
  {
    vtkErrorMacro("Unknown degradation family " << family);
    return;
  }
  this->DegradationFamily = family;
  this->Internal->Degradation.SetConfig(Model::MakeConfig(static_cast<Model::Family>(family)));
  this->Modified();
}

void vtkTimeCriticalRenderer::SetStaticPixelsPerTriangle(double k)
{
  if (!(k > 0.0) || !std::isfinite(k))
  {
    vtkErrorMacro("StaticPixelsPerTriangle must be positive and finite, not " << k);
    return;
  }
  this->StaticPixelsPerTriangle = k;
  this->Internal->Static.SetPixelsPerTriangle(k);
  this->Internal->Feedback.SetInitialPixelsPerTriangle(k);
  this->Modified();
}

void vtkTimeCriticalRenderer::SetImportance(vtkActor* actor, double importance)
{
  if (!actor || !(importance >= 0.0) || !std::isfinite(importance))
  {
    vtkErrorMacro("SetImportance needs an actor and a finite importance >= 0, not " << importance);
    return;
  }
  auto& list = this->Internal->Importance;
  list.erase(std::remove_if(list.begin(), list.end(),
               [actor](const std::pair<vtkWeakPointer<vtkActor>, double>& entry)
               { return !entry.first || entry.first == actor; }),
    list.end());
  list.emplace_back(actor, importance);
  this->Modified();
}

double vtkTimeCriticalRenderer::GetImportance(vtkActor* actor) const
{
  for (const auto& entry : this->Internal->Importance)
  {
    if (entry.first == actor)
    {
      return entry.second;
    }
  }
  return 1.0;
}

void vtkTimeCriticalRenderer::SetCostCoefficients(
  double frame, double drawCall, double triangle, double pixel)
{
  const double values[] = { frame, drawCall, triangle, pixel };
  for (double value : values)
  {
    if (!(value >= 0.0) || !std::isfinite(value))
    {
      vtkErrorMacro("Cost coefficients must be finite and >= 0; keeping the current ones");
      return;
    }
  }
  if (!(triangle > 0.0))
  {
    vtkErrorMacro("The triangle cost must be positive (a triangle is never free); keeping the "
                  "current coefficients");
    return;
  }
  Internals& in = *this->Internal;
  auto c = in.Model.GetCoefficients();
  c.Frame = frame;
  c.DrawCall = drawCall;
  c.Object = 0.0;
  c.Triangle = triangle;
  c.Pixel = pixel;
  // Used as given (a zero pixel cost too: tests pin coefficients); they are
  // trusted like a calibration, so online refinement may lower the triangle
  // cost to TriangleFloorShare of this one, and none below its physical minimum.
  in.Model.SetMinimumCoefficients(timecritical::FrameCostModel::Coefficients());
  in.Model.SetCoefficients(c);
  in.SetCoefficientFloors(true);
  in.UsingDefaults = false;
  // As much as a calibration's samples: the first frames refine them rather
  // than replace them.
  in.ResetCalibrator(GivenCoefficientFrames);
  in.Corrector.Reset();
  in.StillCorrector.Reset();
  this->Modified();
}

double vtkTimeCriticalRenderer::GetFrameCost() const
{
  return this->Internal->Model.GetCoefficients().Frame;
}
double vtkTimeCriticalRenderer::GetDrawCallCost() const
{
  return this->Internal->Model.GetCoefficients().DrawCall;
}
double vtkTimeCriticalRenderer::GetTriangleCost() const
{
  return this->Internal->Model.GetCoefficients().Triangle;
}
double vtkTimeCriticalRenderer::GetPixelCost() const
{
  return this->Internal->Model.GetCoefficients().Pixel;
}

double vtkTimeCriticalRenderer::GetCostModelResidual() const
{
  return this->Internal->Calibrator.GetResidualScale();
}

void vtkTimeCriticalRenderer::SetCostMargin(double seconds)
{
  if (!(seconds >= 0.0) || !std::isfinite(seconds))
  {
    vtkErrorMacro("CostMargin must be finite and >= 0, not " << seconds);
    return;
  }
  auto c = this->Internal->Model.GetCoefficients();
  c.Margin = seconds;
  this->Internal->Model.SetCoefficients(c);
  this->Modified();
}

double vtkTimeCriticalRenderer::GetCostMargin() const
{
  return this->Internal->Model.GetCoefficients().Margin;
}

//------------------------------------------------------------------------------
// Statistics

vtkIdType vtkTimeCriticalRenderer::GetObjectTriangles(vtkIdType object) const
{
  const auto& in = *this->Internal;
  return object >= 0 && static_cast<std::size_t>(object) < in.Triangles.size()
    ? in.Triangles[object]
    : -1;
}

double vtkTimeCriticalRenderer::GetObjectResolution(vtkIdType object) const
{
  const auto& in = *this->Internal;
  return object >= 0 && static_cast<std::size_t>(object) < in.Resolution.size()
    ? in.Resolution[object]
    : NaN;
}

double vtkTimeCriticalRenderer::GetObjectPixels(vtkIdType object) const
{
  const auto& in = *this->Internal;
  return object >= 0 && static_cast<std::size_t>(object) < in.Pixels.size() ? in.Pixels[object]
                                                                             : NaN;
}

namespace
{
template <typename T>
T PerObject(const std::vector<T>& values, vtkIdType object, T bad)
{
  return object >= 0 && static_cast<std::size_t>(object) < values.size() ? values[object] : bad;
}
}

bool vtkTimeCriticalRenderer::GetObjectIsViewDependent(vtkIdType object) const
{
  return PerObject<char>(this->Internal->ViewDependent, object, 0) != 0;
}

vtkIdType vtkTimeCriticalRenderer::GetObjectVertices(vtkIdType object) const
{
  return PerObject<vtkIdType>(this->Internal->Vertices, object, -1);
}

vtkIdType vtkTimeCriticalRenderer::GetObjectSplits(vtkIdType object) const
{
  return PerObject<vtkIdType>(this->Internal->Splits, object, -1);
}

vtkIdType vtkTimeCriticalRenderer::GetObjectMerges(vtkIdType object) const
{
  return PerObject<vtkIdType>(this->Internal->Merges, object, -1);
}

double vtkTimeCriticalRenderer::GetObjectRefinementTime(vtkIdType object) const
{
  return PerObject<double>(this->Internal->RefinementTimes, object, NaN);
}

namespace
{
// Assigns and marks modified when the value changes (the checks come first).
template <typename T>
void Assign(vtkObject* object, T& member, T value)
{
  if (member != value)
  {
    member = value;
    object->Modified();
  }
}
}

void vtkTimeCriticalRenderer::SetFocusPoint(double x, double y)
{
  if (timecritical::CheckRangeSetting(this, "FocusPoint x", x, 0.0, 1.0) &&
    timecritical::CheckRangeSetting(this, "FocusPoint y", y, 0.0, 1.0))
  {
    Assign(this, this->FocusPoint[0], x);
    Assign(this, this->FocusPoint[1], y);
  }
}

void vtkTimeCriticalRenderer::SetDisplayResolution(double x, double y)
{
  if (timecritical::CheckPositiveSetting(this, "DisplayResolution x", x) &&
    timecritical::CheckPositiveSetting(this, "DisplayResolution y", y))
  {
    Assign(this, this->DisplayResolution[0], x);
    Assign(this, this->DisplayResolution[1], y);
  }
}

void vtkTimeCriticalRenderer::SetDisplaySize(double x, double y)
{
  if (timecritical::CheckPositiveSetting(this, "DisplaySize x", x) &&
    timecritical::CheckPositiveSetting(this, "DisplaySize y", y))
  {
    Assign(this, this->DisplaySize[0], x);
    Assign(this, this->DisplaySize[1], y);
  }
}

void vtkTimeCriticalRenderer::SetViewingDistance(double metres)
{
  if (timecritical::CheckPositiveSetting(this, "ViewingDistance", metres))
  {
    Assign(this, this->ViewingDistance, metres);
  }
}

void vtkTimeCriticalRenderer::SetStillUpdateRateThreshold(double rate)
{
  if (timecritical::CheckNonNegativeSetting(this, "StillUpdateRateThreshold", rate))
  {
    Assign(this, this->StillUpdateRateThreshold, rate);
  }
}

void vtkTimeCriticalRenderer::SetSafetyFactor(double k)
{
  if (timecritical::CheckRangeSetting(this, "SafetyFactor", k, 0.0, 10.0))
  {
    Assign(this, this->SafetyFactor, k);
  }
}

void vtkTimeCriticalRenderer::SetNewObjectCostFactor(double factor)
{
  if (timecritical::CheckRangeSetting(this, "NewObjectCostFactor", factor, 1.0, 10.0))
  {
    Assign(this, this->NewObjectCostFactor, factor);
  }
}

void vtkTimeCriticalRenderer::SetPixelThreshold(double tau)
{
  if (!timecritical::CheckNonNegativeSetting(this, "PixelThreshold", tau))
  {
    return;
  }
  if (this->PixelThreshold != tau)
  {
    this->PixelThreshold = tau;
    this->Modified();
  }
}

void vtkTimeCriticalRenderer::SetRefinementTimeLimit(double seconds)
{
  if (!timecritical::CheckNonNegativeSetting(this, "RefinementTimeLimit", seconds))
  {
    return;
  }
  if (this->RefinementTimeLimit != seconds)
  {
    this->RefinementTimeLimit = seconds;
    this->Modified();
  }
}

void vtkTimeCriticalRenderer::SetSilhouetteFactor(double factor)
{
  if (!timecritical::CheckFactorSetting(this, "SilhouetteFactor", factor))
  {
    return;
  }
  if (this->SilhouetteFactor != factor)
  {
    this->SilhouetteFactor = factor;
    this->Modified();
  }
}

void vtkTimeCriticalRenderer::SetHighlightFactor(double factor)
{
  if (!timecritical::CheckFactorSetting(this, "HighlightFactor", factor))
  {
    return;
  }
  if (this->HighlightFactor != factor)
  {
    this->HighlightFactor = factor;
    this->Modified();
  }
}

vtkActor* vtkTimeCriticalRenderer::GetObjectActor(vtkIdType object) const
{
  const auto& in = *this->Internal;
  return object >= 0 && static_cast<std::size_t>(object) < in.ObjectActor.size()
    ? in.Actors[in.ObjectActor[object]].Actor
    : nullptr;
}

vtkIdType vtkTimeCriticalRenderer::GetObjectIndex(vtkIdType object) const
{
  const auto& in = *this->Internal;
  return object >= 0 && static_cast<std::size_t>(object) < in.ObjectIndex.size()
    ? in.ObjectIndex[object]
    : -1;
}

//------------------------------------------------------------------------------
// Frame timing: the window's StartEvent to its EndEvent, which includes the
// buffer swap where a software rasterizer finishes its work.

void vtkTimeCriticalRenderer::WatchWindow()
{
  Internals& in = *this->Internal;
  if (in.Window == this->RenderWindow)
  {
    return;
  }
  if (vtkRenderWindow* old = in.Window)
  {
    old->RemoveObserver(in.StartTag);
    old->RemoveObserver(in.EndTag);
  }
  in.Window = this->RenderWindow;
  in.FrameStartValid = false;
  if (this->RenderWindow)
  {
    in.StartTag = this->RenderWindow->AddObserver(
      vtkCommand::StartEvent, this, &vtkTimeCriticalRenderer::OnWindowStart);
    in.EndTag = this->RenderWindow->AddObserver(
      vtkCommand::EndEvent, this, &vtkTimeCriticalRenderer::OnWindowEnd);
  }
}

void vtkTimeCriticalRenderer::OnWindowStart()
{
  this->Internal->FrameStart = Clock::now();
  this->Internal->FrameStartValid = true;
  this->Internal->FramePending = false;
  this->Internal->DrawingEndValid = false;
}

void vtkTimeCriticalRenderer::MarkDrawingFinished()
{
  this->Internal->DrawingEnd = Clock::now();
  this->Internal->DrawingEndValid = true;
}

void vtkTimeCriticalRenderer::SetCompositingTime(double seconds)
{
  if (!(seconds >= 0.0) || !std::isfinite(seconds))
  {
    vtkErrorMacro("SetCompositingTime(" << seconds << "): must be finite and >= 0 seconds");
    return;
  }
  this->CompositingTime = seconds; // render state, as the resolutions: no Modified()
}

void vtkTimeCriticalRenderer::OnWindowEnd()
{
  Internals& in = *this->Internal;
  if (!in.FramePending || !in.FrameStartValid)
  {
    return;
  }
  in.FramePending = false;
  in.FrameStartValid = false;
  this->MeasuredFrameTime = Seconds(in.FrameStart, Clock::now());
  // The model learns this renderer's own drawing: where the frame goes on
  // after it (compositing, and waiting for other processes there), up to the
  // drawing's end.
  this->MeasuredDrawingTime =
    in.DrawingEndValid ? Seconds(in.FrameStart, in.DrawingEnd) : this->MeasuredFrameTime;
  in.DrawingEndValid = false;
  this->DataChangeTime = this->MeasureDataChange();
  // A frame that calibrated took the hidden renders' time too: the user
  // waited for it, but it says nothing about the model.
  const bool calibrated = in.PendingCalibrated;
  in.PendingCalibrated = false;
  if (this->OnlineCalibration && !calibrated)
  {
    (in.PendingStill ? in.StillCorrector : in.Corrector)
      .Update(in.RawPrediction, this->MeasuredDrawingTime);
    // The coefficients learn from the frames they plan. Still frames all
    // have the same features (everything in full): a run of them (ParaView
    // draws one after every interaction, a scripted path may draw hundreds)
    // would fade every other direction out of the fit and leave the split
    // between fixed and per-triangle cost to chance; the first budgeted
    // frame after them was then planned with a fixed part many times the
    // real one. Their own correction above still follows them.
    // The fronts' refinement time is measured, not modelled by the
    // features: the model learns the drawing alone.
    const double drawing = this->MeasuredDrawingTime - this->RefinementTime - this->DataChangeTime;
    if (in.PendingStill && in.UsingDefaults)
    {
      this->ScaleDefaultCoefficients(drawing);
    }
    // Frames that dropped objects do not refit the coefficients either: the
    // drop holds them at the target whatever they draw, so their time says
    // little about the features, and the optimizer's own time (it grows with
    // the objects in view) went to the fill coefficient, which then valued
    // every object by its pixels and dropped large ones (W6). Their
    // correction above still follows them.
    else if (!in.PendingStill && this->NumberOfDroppedObjects == 0)
    {
      if (in.Calibrator.Update(in.Features.data(), drawing))
      {
        in.StoreCoefficients();
      }
      // Enough frames fitted: the model is a measurement of this machine
      // (what dropping objects needs), as after a calibration.
      if (in.UsingDefaults && ++in.OnlineFrames >= tcr::OnlineFramesToTrust)
      {
        in.UsingDefaults = false;
      }
    }
  }
}

double vtkTimeCriticalRenderer::MeasureDataChange()
{
  // The reads as measured before the frame was planned, the vertex buffer
  // builds as they went in its drawing.
  double seconds = 0.0;
  for (const auto& entry : this->Internal->Actors)
  {
    if (entry.ReadTime > 0.0)
    {
      seconds += entry.ReadTime + entry.Mapper->GetLastVertexBufferBuildTime();
    }
  }
  return seconds;
}

//------------------------------------------------------------------------------
// The frame

void vtkTimeCriticalRenderer::StillRender()
{
  if (!this->RenderWindow)
  {
    vtkErrorMacro("StillRender() needs a render window");
    return;
  }
  this->Internal->StillRequested = true;
  this->RenderWindow->Render();
  this->Internal->StillRequested = false;
}

double vtkTimeCriticalRenderer::GetEffectiveTargetFrameTime()
{
  if (this->StillRendering)
  {
    return Infinity;
  }
  if (this->UseDesiredUpdateRate && this->RenderWindow)
  {
    const double rate = this->RenderWindow->GetDesiredUpdateRate();
    return rate > this->StillUpdateRateThreshold ? 1.0 / rate : Infinity;
  }
  return this->TargetFrameTime;
}

void vtkTimeCriticalRenderer::ResetCamera(const double bounds[6])
{
  this->Superclass::ResetCamera(bounds);
  Internals& in = *this->Internal;
  in.CameraWasReset = true;
  if (in.CalibrationProvisional)
  {
    in.CalibrationProvisional = false;
    in.CalibrationRequested = true; // again, in the next frame, at the view of the data
  }
}

void vtkTimeCriticalRenderer::DeviceRender()
{
  Internals& in = *this->Internal;
  if (this->HoldResolutions || this->GetSelector())
  {
    // The mappers keep the resolutions of the last plan (render state). A
    // hardware selection's passes are such renders too: they must all see
    // the frame the user saw, and are no frames to plan or measure.
    in.FramePending = false;
    this->Superclass::DeviceRender();
    return;
  }
  this->WatchWindow();
  if (!in.FrameStartValid)
  {
    // First frame after attaching to the window, or a render not started by
    // the window: time from here.
    in.FrameStart = Clock::now();
    in.FrameStartValid = true;
  }

  const double target = in.StillRequested ? Infinity : this->GetEffectiveTargetFrameTime();
  const bool still = !std::isfinite(target);
  in.EffectiveTarget = target;

  const auto heuristicsStart = Clock::now();
  this->GatherObjects();
  // Automatic calibration runs in the first render with objects, whatever
  // kind it is: that is the start-up frame the user waits for anyway. With
  // UseDesiredUpdateRate every frame before the first drag is a still frame;
  // waiting for an adaptive one would put the calibration's seconds into the
  // user's first interaction.
  // With background hierarchy builds it waits until none is pending: objects
  // drawn in full while their hierarchy builds have no resolution to vary,
  // and their full cost in every hidden render would make each sample cost
  // a frame or more. Once held back so, it does not run at all: the frame in
  // which the last hierarchy arrives may come while the user drags, where
  // one calibration stalls 1.0-1.4 s, and spread over frames its hidden
  // renders made 13 frames of 150-210 ms against a 100 ms target (llvmpipe:
  // fill-bound, a hidden render costs about a frame). The frames themselves
  // calibrate the model then (OnlineCalibration).
  auto awaitingHierarchies = [this]() { return this->GetNumberOfPendingHierarchies() > 0; };
  const bool automatic = this->AutomaticCalibration && !this->Calibrated &&
    !this->CalibrationAttempted && !in.CalibrationHeldBack && this->Policy != FULL_RESOLUTION &&
    !in.ObjectActor.empty();
  if (automatic && awaitingHierarchies())
  {
    in.CalibrationHeldBack = true;
  }
  else if (in.CalibrationRequested || automatic)
  {
    const bool requested = in.CalibrationRequested;
    in.CalibrationRequested = false;
    this->RunCalibration();
    in.PendingCalibrated = true;
    in.CalibrationProvisional = !requested && this->Calibrated && !in.CameraWasReset;
  }
  this->MeasureObjects();
  this->HeuristicsTime = Seconds(heuristicsStart, Clock::now());

  this->ChooseResolutions(still);
  this->LastTargetFrameTime = target;
  this->LastRenderWasStill = still;

  this->Superclass::DeviceRender();
  this->FinishFrame();
}

void vtkTimeCriticalRenderer::GatherObjects()
{
  Internals& in = *this->Internal;
  in.Actors.clear();
  in.ObjectActor.clear();
  in.ObjectIndex.clear();
  in.Load = timecritical::FrameCostModel::FrameLoad();
  in.DataChangeEstimate = 0.0;

  int size[2] = { 0, 0 }, origin[2] = { 0, 0 };
  this->GetTiledSizeAndOrigin(&size[0], &size[1], &origin[0], &origin[1]);
  in.ViewportWidth = size[0];
  in.ViewportHeight = size[1];

  for (int p = 0; p < this->PropArrayCount; ++p)
  {
    vtkProp* prop = this->PropArray[p];
    vtkActor* actor = vtkActor::SafeDownCast(prop);
    auto* mapper =
      actor ? vtkMultiresolutionPolyDataMapper::SafeDownCast(actor->GetMapper()) : nullptr;
    if (!mapper)
    {
      // An ordinary prop: one draw call, its triangles and pixels are fixed cost.
      in.Load.DrawCalls += 1.0;
      vtkMapper* other = actor ? actor->GetMapper() : nullptr;
      if (auto* poly = other ? vtkPolyData::SafeDownCast(other->GetInputDataObject(0, 0)) : nullptr)
      {
        in.Load.OtherTriangles += static_cast<double>(poly->GetNumberOfPolys()) +
          static_cast<double>(poly->GetNumberOfStrips());
      }
      continue;
    }
    mapper->SetViewDependentRefinement(this->ViewDependentRefinement);
    mapper->SetRefinementMode(this->RefinementMode);
    mapper->SetPixelThreshold(this->PixelThreshold);
    mapper->SetBackFaceSimplification(this->BackFaceSimplification);
    mapper->SetSilhouetteRefinement(this->SilhouetteRefinement);
    mapper->SetSilhouetteFactor(this->SilhouetteFactor);
    mapper->SetHighlightRefinement(this->HighlightRefinement);
    mapper->SetHighlightFactor(this->HighlightFactor);
    mapper->UpdateObjects();
    Internals::ActorEntry entry;
    entry.ReadTime = mapper->TakeObjectReadTime(in.FrameStart);
    if (entry.ReadTime > 0.0)
    {
      in.DataChangeEstimate += entry.ReadTime + mapper->GetLastVertexBufferBuildTime();
    }
    entry.Actor = actor;
    entry.Mapper = mapper;
    entry.First = in.ObjectActor.size();
    entry.Count = static_cast<std::size_t>(mapper->GetNumberOfObjects());
    for (std::size_t i = 0; i < entry.Count; ++i)
    {
      in.ObjectActor.push_back(in.Actors.size());
      in.ObjectIndex.push_back(static_cast<vtkIdType>(i));
    }
    in.Actors.push_back(entry);
  }

  const std::size_t n = in.ObjectActor.size();
  this->NumberOfObjects = static_cast<vtkIdType>(n);
  in.Bounds.resize(n);
  for (auto* v : { &in.MaxTriangles, &in.MaxVertices, &in.Coarsest, &in.Pixels, &in.CenterX,
         &in.CenterY, &in.Resolution, &in.PreviousResolution, &in.Velocity, &in.Eccentricity,
         &in.Importances })
  {
    v->resize(n);
  }
  in.Culled.resize(n);
  in.Dropped.resize(n);
  in.Triangles.resize(n);
  in.Vertices.resize(n);
  in.Splits.resize(n);
  in.Merges.resize(n);
  in.RefinementTimes.resize(n);
  in.ViewDependent.resize(n);
  for (const auto& entry : in.Actors)
  {
    const double importance = this->GetImportance(entry.Actor);
    for (std::size_t i = 0; i < entry.Count; ++i)
    {
      const std::size_t o = entry.First + i;
      const vtkIdType index = static_cast<vtkIdType>(i);
      entry.Mapper->GetObjectBounds(index, in.Bounds[o].data());
      in.MaxTriangles[o] = static_cast<double>(entry.Mapper->GetObjectNumberOfTriangles(index));
      in.MaxVertices[o] = static_cast<double>(entry.Mapper->GetObjectNumberOfVertices(index));
      in.Coarsest[o] = entry.Mapper->GetObjectCoarsestResolution(index);
      in.Importances[o] = importance;
      in.ViewDependent[o] = entry.Mapper->GetObjectIsViewDependent(index) ? 1 : 0;
    }
  }
}

void vtkTimeCriticalRenderer::MeasureObjects()
{
  Internals& in = *this->Internal;
  using timecritical::ViewHeuristics;
  vtkCamera* camera = this->GetActiveCamera();
  const double width = in.ViewportWidth, height = in.ViewportHeight;
  const double aspect = height > 0.0 ? width / height : 1.0;
  vtkMatrix4x4* viewProjection = camera->GetCompositeProjectionTransformMatrix(aspect, -1, 1);

  // Ordinary props: pixels of their world bounds.
  in.Load.OtherPixels = 0.0;
  for (int p = 0; p < this->PropArrayCount; ++p)
  {
    vtkActor* actor = vtkActor::SafeDownCast(this->PropArray[p]);
    if (actor && vtkMultiresolutionPolyDataMapper::SafeDownCast(actor->GetMapper()))
    {
      continue;
    }
    const double* bounds = this->PropArray[p]->GetBounds();
    if (bounds && bounds[0] <= bounds[1])
    {
      in.Load.OtherPixels +=
        ViewHeuristics::Project(viewProjection->GetData(), bounds, width, height).Pixels;
    }
  }

  const double dt = std::isfinite(this->MeasuredFrameTime) && this->MeasuredFrameTime > 0.0
    ? this->MeasuredFrameTime
    : (std::isfinite(in.EffectiveTarget) ? in.EffectiveTarget : this->TargetFrameTime);
  this->UpdateFocus();
  const double focusX = this->LastFocus[0] * width;
  const double focusY = this->LastFocus[1] * height;
  timecritical::DegradationModel::DisplayParameters display;
  display.ResolutionX = this->DisplayResolution[0];
  display.ResolutionY = this->DisplayResolution[1];
  display.SizeX = this->DisplaySize[0];
  display.SizeY = this->DisplaySize[1];
  display.ViewingDistance = this->ViewingDistance;
  in.Degradation.SetDisplay(display);
  auto config = in.Degradation.GetConfig();
  const auto defaults = timecritical::DegradationModel::MakeConfig(config.WeightFamily);
  config.Velocity = this->UseVelocity ? defaults.Velocity
                                      : timecritical::DegradationModel::VelocityModel::None;
  config.Eccentricity = this->UseEccentricity
    ? static_cast<timecritical::DegradationModel::EccentricityModel>(
        this->EccentricityModel(static_cast<int>(defaults.Eccentricity)))
    : timecritical::DegradationModel::EccentricityModel::None;
  config.LinearFalloffDegrees = this->LinearFalloffDegrees;
  in.Degradation.SetConfig(config);

  in.TotalPixels = 0.0;
  vtkIdType culled = 0;
  for (auto& entry : in.Actors)
  {
    vtkMatrix4x4::Multiply4x4(viewProjection, entry.Actor->GetMatrix(), in.ObjectToClip);
    auto& history = in.History[entry.Mapper];
    const bool known = history.Resolution.size() == entry.Count;
    for (std::size_t i = 0; i < entry.Count; ++i)
    {
      const std::size_t o = entry.First + i;
      const auto projection =
        ViewHeuristics::Project(in.ObjectToClip->GetData(), in.Bounds[o].data(), width, height);
      // Hidden blocks (block visibility) are culled: no budget is spent on them.
      const bool hidden = !entry.Mapper->GetObjectVisibility(static_cast<vtkIdType>(i));
      in.Culled[o] = projection.Culled || hidden ? 1 : 0;
      in.Pixels[o] = projection.Pixels;
      in.CenterX[o] = projection.CenterX;
      in.CenterY[o] = projection.CenterY;
      in.Eccentricity[o] =
        in.Degradation.PixelsToDegrees(ViewHeuristics::Eccentricity(projection, focusX, focusY));
      in.Velocity[o] = known
        ? in.Degradation.PixelsToDegrees(ViewHeuristics::Velocity(
            history.CenterX[i], history.CenterY[i], projection.CenterX, projection.CenterY, dt))
        : 0.0;
      in.PreviousResolution[o] = known ? history.Resolution[i] : NaN;
      if (in.Culled[o])
      {
        ++culled;
      }
      else
      {
        in.TotalPixels += projection.Pixels;
      }
    }
  }
  this->NumberOfCulledObjects = culled;
  this->CoveredPixels = in.TotalPixels;
  in.Load.Objects = static_cast<double>(in.ObjectActor.size() - static_cast<std::size_t>(culled));
}

void vtkTimeCriticalRenderer::ChooseResolutions(bool still)
{
  Internals& in = *this->Internal;
  const std::size_t n = in.ObjectActor.size();

  in.Visible.clear();
  in.Views.clear();
  for (std::size_t o = 0; o < n; ++o)
  {
    if (in.Culled[o])
    {
      continue;
    }
    in.Visible.push_back(o);
    timecritical::DegradationModel::ObjectView view;
    view.Pixels = in.Pixels[o];
    view.VelocityDegrees = in.Velocity[o];
    view.EccentricityDegrees = in.Eccentricity[o];
    view.Importance = in.Importances[o];
    view.MaxTriangles = in.MaxTriangles[o];
    view.MaxVertices = in.MaxVertices[o];
    in.Views.push_back(view);
  }
  const std::size_t m = in.Visible.size();
  for (auto* v : { &in.Weight, &in.MaxTime, &in.MinResolution, &in.VisiblePixels,
         &in.VisibleTriangles, &in.Previous, &in.Chosen })
  {
    v->resize(m);
  }
  bool anyPrevious = false;
  for (std::size_t k = 0; k < m; ++k)
  {
    const std::size_t o = in.Visible[k];
    in.VisiblePixels[k] = in.Pixels[o];
    in.VisibleTriangles[k] = in.MaxTriangles[o];
    in.Previous[k] = in.PreviousResolution[o];
    anyPrevious = anyPrevious || std::isfinite(in.Previous[k]);
    in.Coarsest[o] = std::isfinite(in.Coarsest[o]) ? in.Coarsest[o] : 1.0;
  }
  in.Degradation.Evaluate(m, in.Views.data(), in.Weight.data());
  // The model's short-term error in this view (FrameTimeCorrector) scales
  // every predicted time; still frames have their own.
  const double correction = this->OnlineCalibration
    ? (still ? in.StillCorrector : in.Corrector).GetFactor()
    : 1.0;
  in.PendingStill = still;
  for (std::size_t k = 0; k < m; ++k)
  {
    const std::size_t o = in.Visible[k];
    const double cold = std::isfinite(in.PreviousResolution[o]) ? 1.0 : this->NewObjectCostFactor;
    in.MaxTime[k] = correction * cold * in.Model.MaxTime(in.MaxTriangles[o]);
    in.MinResolution[k] = in.Model.MinimumResolution(in.MaxTriangles[o], in.Pixels[o], in.Coarsest[o]);
  }
  // Fixed accuracy: fronts take the triangles their threshold needs; their
  // last count is fixed cost, and a zero cost keeps the policy from
  // culling or coarsening them.
  double fixedFronts = 0.0;
  if (this->RefinementMode == FIXED_ACCURACY)
  {
    for (std::size_t k = 0; k < m; ++k)
    {
      const std::size_t o = in.Visible[k];
      if (in.ViewDependent[o])
      {
        const double last = std::isfinite(in.PreviousResolution[o])
          ? static_cast<double>(in.Triangles[o])
          : in.Coarsest[o] * in.MaxTriangles[o];
        fixedFronts += in.Model.MaxTime(last);
        in.MaxTime[k] = 0.0;
        in.MinResolution[k] = 1.0;
      }
    }
  }

  // Draw calls: one per multiresolution mapper with a visible object.
  double mapperCalls = 0.0;
  for (const auto& entry : in.Actors)
  {
    for (std::size_t i = 0; i < entry.Count; ++i)
    {
      if (!in.Culled[entry.First + i])
      {
        mapperCalls += 1.0;
        break;
      }
    }
  }
  timecritical::FrameCostModel::FrameLoad load = in.Load;
  load.DrawCalls += mapperCalls;
  const double fixed = correction * (in.Model.FixedTime(load, in.TotalPixels) + fixedFronts) +
    in.RefinementEstimate + this->CompositingTime + in.DataChangeEstimate;
  // Time-limited budget fronts: at most the limit per mapper this frame.
  for (const auto& entry : in.Actors)
  {
    entry.Mapper->SetRefinementTimeLimit(
      this->RefinementMode == BUDGET && !still ? this->RefinementTimeLimit : 0.0);
  }

  timecritical::PolicyInput input;
  input.Count = m;
  input.Weight = in.Weight.data();
  input.MaxTime = in.MaxTime.data();
  input.MinResolution = in.MinResolution.data();
  input.Pixels = in.VisiblePixels.data();
  input.MaxTriangles = in.VisibleTriangles.data();
  input.Previous = anyPrevious ? in.Previous.data() : nullptr;
  input.Alpha = in.Degradation.GetAlpha();
  const double target = in.EffectiveTarget;
  const double objectFixed = this->PrepareDropping(still, correction);
  this->SafetyMargin = this->PlanningMargin(target, fixed, objectFixed, still);
  input.TargetFrameTime = target - this->SafetyMargin;
  input.FixedTime = fixed;
  input.LastFrameTime = this->MeasuredFrameTime;
  input.Hysteresis = still ? 0.0 : this->Hysteresis;

  // Overloaded (even the coarsest levels do not fit): the least valuable
  // objects are dropped; otherwise the policy chooses resolutions as usual.
  const bool dropping = this->ChooseWithDropping(input.TargetFrameTime, fixed, objectFixed);
  const timecritical::PolicyResult result = dropping
    ? in.DropResult
    : (still ? &in.FullResolution : in.GetPolicy(this->Policy))->Select(input, in.Chosen.data());
  this->PredictedFrameTime = result.PredictedFrameTime;
  // What the model predicts of the drawing (compositing is measured apart).
  in.RawPrediction = (result.PredictedFrameTime - this->CompositingTime) / correction;
  this->FixedFrameTime = fixed;
  this->OptimizationTime = result.Seconds;
  this->OptimizationIterations = result.Iterations;
  this->OptimizationConverged = result.Converged;
  this->NumberOfHeldObjects = static_cast<vtkIdType>(result.Held);
  this->CountChanges();

  std::fill(in.Resolution.begin(), in.Resolution.end(), 0.0);
  for (std::size_t k = 0; k < m; ++k)
  {
    in.Resolution[in.Visible[k]] = in.Chosen[k];
  }
  in.ApplyResolutions();
}

void vtkTimeCriticalRenderer::FinishFrame()
{
  Internals& in = *this->Internal;
  double objectTriangles = 0.0;
  for (auto& entry : in.Actors)
  {
    auto& history = in.History[entry.Mapper];
    history.Resolution.resize(entry.Count);
    history.CenterX.resize(entry.Count);
    history.CenterY.resize(entry.Count);
    history.Seen = true;
    for (std::size_t i = 0; i < entry.Count; ++i)
    {
      const std::size_t o = entry.First + i;
      const auto index = static_cast<vtkIdType>(i);
      in.Triangles[o] = entry.Mapper->GetObjectRenderedTriangles(index);
      in.Vertices[o] = entry.Mapper->GetObjectRenderedVertices(index);
      in.Splits[o] = entry.Mapper->GetObjectSplits(index);
      in.Merges[o] = entry.Mapper->GetObjectMerges(index);
      in.RefinementTimes[o] = entry.Mapper->GetObjectRefinementTime(index);
      objectTriangles += static_cast<double>(in.Triangles[o]);
      // Culled and dropped objects restart from rmin when they come back
      // (NaN = new: their data was not touched, so it is planned cold).
      history.Resolution[i] = in.Culled[o] || in.Dropped[o] ? NaN : in.Resolution[o];
      history.CenterX[i] = in.CenterX[o];
      history.CenterY[i] = in.CenterY[o];
    }
  }
  // Forget mappers that were not drawn this frame (they may have been deleted).
  for (auto it = in.History.begin(); it != in.History.end();)
  {
    it = it->second.Seen ? std::next(it) : in.History.erase(it);
  }
  for (auto& entry : in.History)
  {
    entry.second.Seen = false;
  }

  this->RefinementTime = 0.0;
  for (const auto& entry : in.Actors)
  {
    this->RefinementTime += entry.Mapper->GetRefinementTime();
  }
  // Smoothed, so that one frame of large changes does not starve the next
  // frame's budget (which would swing the fronts back the other way).
  in.RefinementEstimate = 0.5 * in.RefinementEstimate + 0.5 * this->RefinementTime;
  this->ObjectTrianglesDrawn = static_cast<vtkIdType>(objectTriangles);
  this->TrianglesDrawn = static_cast<vtkIdType>(objectTriangles + in.Load.OtherTriangles);
  timecritical::FrameCostModel::FrameLoad load = in.Load;
  double mapperCalls = 0.0;
  for (const auto& entry : in.Actors)
  {
    mapperCalls += entry.Mapper->GetNumberOfDrawCalls();
  }
  load.DrawCalls += mapperCalls;
  // Dropped objects cover no pixel and take no setup: the model learns what was drawn.
  load.Objects -= static_cast<double>(this->NumberOfDroppedObjects);
  in.Model.GetFeatures(load, objectTriangles, in.DrawnPixels, in.Features.data());
  in.FramePending = true;
}

//------------------------------------------------------------------------------
void vtkTimeCriticalRenderer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TargetFrameTime: " << this->TargetFrameTime << "\n";
  os << indent << "EffectiveTargetFrameTime: " << this->GetEffectiveTargetFrameTime() << "\n";
  os << indent << "LastTargetFrameTime: " << this->LastTargetFrameTime << "\n";
  os << indent << "OptimizationTimeLimit: " << this->OptimizationTimeLimit << "\n";
  os << indent << "Policy: " << this->GetPolicyAsString() << "\n";
  os << indent << "DegradationFamily: " << this->DegradationFamily << "\n";
  os << indent << "UseVelocity: " << this->UseVelocity << "\n";
  os << indent << "UseEccentricity: " << this->UseEccentricity << "\n";
  os << indent << "FocusPoint: " << this->FocusPoint[0] << ", " << this->FocusPoint[1] << "\n";
  os << indent << "FocusMode: " << this->FocusMode << "\n";
  os << indent << "FocusFalloff: " << this->FocusFalloff << "\n";
  os << indent << "LinearFalloffDegrees: " << this->LinearFalloffDegrees << "\n";
  os << indent << "LastFocus: " << this->LastFocus[0] << ", " << this->LastFocus[1] << "\n";
  os << indent << "DisplayResolution: " << this->DisplayResolution[0] << " x "
     << this->DisplayResolution[1] << "\n";
  os << indent << "DisplaySize: " << this->DisplaySize[0] << " x " << this->DisplaySize[1] << "\n";
  os << indent << "ViewingDistance: " << this->ViewingDistance << "\n";
  os << indent << "StaticPixelsPerTriangle: " << this->StaticPixelsPerTriangle << "\n";
  os << indent << "UseDesiredUpdateRate: " << this->UseDesiredUpdateRate << "\n";
  os << indent << "StillRendering: " << this->StillRendering << "\n";
  os << indent << "HoldResolutions: " << this->HoldResolutions << "\n";
  os << indent << "StillUpdateRateThreshold: " << this->StillUpdateRateThreshold << "\n";
  os << indent << "AutomaticCalibration: " << this->AutomaticCalibration << "\n";
  os << indent << "OnlineCalibration: " << this->OnlineCalibration << "\n";
  os << indent << "Calibrated: " << this->Calibrated << " (" << this->CalibrationRenders
     << " renders, last " << this->CalibrationTime << " s)\n";
  os << indent << "Cost (frame, draw call, triangle, pixel, margin): " << this->GetFrameCost()
     << ", " << this->GetDrawCallCost() << ", " << this->GetTriangleCost() << ", "
     << this->GetPixelCost() << ", " << this->GetCostMargin() << "\n";
  os << indent << "SafetyFactor: " << this->SafetyFactor << "\n";
  os << indent << "NewObjectCostFactor: " << this->NewObjectCostFactor << "\n";
  os << indent << "ViewDependentRefinement: " << this->ViewDependentRefinement << "\n";
  os << indent << "RefinementMode: "
     << timecritical::RefinementModeName(timecritical::ClampRefinementMode(this->RefinementMode))
     << "\n";
  os << indent << "PixelThreshold: " << this->PixelThreshold << "\n";
  os << indent << "BackFaceSimplification: " << this->BackFaceSimplification << "\n";
  os << indent << "SilhouetteRefinement: " << this->SilhouetteRefinement << " (factor "
     << this->SilhouetteFactor << ")\n";
  os << indent << "HighlightRefinement: " << this->HighlightRefinement << " (factor "
     << this->HighlightFactor << ")\n";
  os << indent << "RefinementTimeLimit: " << this->RefinementTimeLimit << "\n";
  os << indent << "RefinementTime: " << this->RefinementTime << "\n";
  os << indent << "PredictedFrameTime: " << this->PredictedFrameTime << "\n";
  os << indent << "MeasuredFrameTime: " << this->MeasuredFrameTime << "\n";
  os << indent << "MeasuredDrawingTime: " << this->MeasuredDrawingTime << "\n";
  os << indent << "CompositingTime: " << this->CompositingTime << "\n";
  os << indent << "OptimizationTime: " << this->OptimizationTime << "\n";
  os << indent << "OptimizationIterations: " << this->OptimizationIterations << "\n";
  os << indent << "TrianglesDrawn: " << this->TrianglesDrawn << "\n";
  os << indent << "NumberOfObjects: " << this->NumberOfObjects << "\n";
  os << indent << "NumberOfCulledObjects: " << this->NumberOfCulledObjects << "\n";
  os << indent << "DropObjectsWhenOverloaded: " << this->DropObjectsWhenOverloaded << "\n";
  os << indent << "NumberOfDroppedObjects: " << this->NumberOfDroppedObjects << "\n";
  os << indent << "Hysteresis: " << this->Hysteresis << "\n";
  os << indent << "NumberOfChangedObjects: " << this->NumberOfChangedObjects << "\n";
  os << indent << "NumberOfHeldObjects: " << this->NumberOfHeldObjects << "\n";
}
