// SPDX-License-Identifier: BSD-3-Clause
// vtkTimeCriticalRenderer's private state, shared by its implementation
// files (vtkTimeCriticalRenderer.cxx: settings, objects, the frame;
// vtkTimeCriticalRendererCalibration.cxx: the start-up calibration;
// vtkTimeCriticalRendererDropping.cxx: objects dropped when overloaded;
// vtkTimeCriticalRendererHysteresis.cxx: hysteresis and popping counts;
// vtkTimeCriticalRendererFocus.cxx: where the focus is and its fall-off;
// vtkTimeCriticalRendererHierarchies.cxx: background builds).
#ifndef vtkTimeCriticalRendererInternals_h
#define vtkTimeCriticalRendererInternals_h

#include "vtkTimeCriticalRenderer.h"

#include "vtkMultiresolutionPolyDataMapper.h"

#include "RefinementSettingChecks.h"
#include "RefinementSettings.h"

#include "ActiveSetPolicy.h"
#include "CostModelCalibrator.h"
#include "DegradationModel.h"
#include "FeedbackPolicy.h"
#include "FrameCostModel.h"
#include "FrameTimeCorrector.h"
#include "FullResolutionPolicy.h"
#include "GreedyLODPolicy.h"
#include "HysteresisBand.h"
#include "StaticThresholdPolicy.h"
#include "TupleProblem.h"
#include "ViewHeuristics.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPolyData.h"
#include "vtkProp.h"
#include "vtkRenderWindow.h"
#include "vtkWeakPointer.h"
#include "vtk_glew.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace timecritical
{
namespace rendering
{
using Clock = std::chrono::steady_clock;
constexpr double NaN = std::numeric_limits<double>::quiet_NaN();
constexpr double Infinity = std::numeric_limits<double>::infinity();
constexpr std::size_t FeatureCount = timecritical::FrameCostModel::FeatureCount;

inline double Seconds(Clock::time_point a, Clock::time_point b)
{
  return std::chrono::duration<double>(b - a).count();
}

/// Starting coefficients, of the order of Mesa llvmpipe at 512x512 on two
/// cores; calibration replaces them within the first frames.
inline timecritical::FrameCostModel::Coefficients DefaultCoefficients()
{
  timecritical::FrameCostModel::Coefficients c;
  c.Frame = 2e-3;
  c.DrawCall = 0.3e-3;
  c.Object = 0.0;
  c.Triangle = 0.2e-6;
  c.Pixel = 5e-9;
  return c;
}

/// Typical magnitude of each feature, so the calibrator works on scaled values.
constexpr double FeatureScales[FeatureCount] = { 1.0, 10.0, 500.0, 1e5, 1e6 };

/// Online refinement may lower the triangle cost to this share of the value
/// a calibration measured (or the user set), no further: frames fitted in
/// the loop need not depend on the triangles (the optimizer holds the time
/// at the target whatever it draws), and a triangle cost that drifts to 0
/// draws every object in full. The other coefficients only have their
/// physical floors: a calibration that overestimates the fill must stay
/// correctable, and too low a fill cost cannot draw more than the budget.
/// Costs above the calibration are never bounded (that side only coarsens).
constexpr double TriangleFloorShare = 0.5;

/// Share of the time left after the fixed part and the objects' minimum that
/// the safety margin may take: the rest always goes to the objects, so a
/// large margin coarsens the frame gracefully instead of emptying it.
constexpr double MaximumMarginShare = 0.5;

/// The margin never exceeds this share of the target: noise that large is
/// the machine's (other processes, a start-up transient), and planning the
/// frame at half the target (the cap was 0.5) halves its image quality to
/// protect against it.
constexpr double MaximumMargin = 0.25;

/// Weight of coefficients given by SetCostCoefficients() in the online fit,
/// in frames (a calibration has 14 samples).
constexpr double GivenCoefficientFrames = 16.0;

/// Interactive frames the online fit needs before a model that was never
/// calibrated counts as measured (as many as a calibration's samples).
constexpr int OnlineFramesToTrust = 14;
} // namespace rendering
} // namespace timecritical
namespace tcr = timecritical::rendering; // short name for the state below

struct vtkTimeCriticalRenderer::Internals
{
  // Models and policies (one instance each, reused every frame).
  timecritical::FrameCostModel Model{ tcr::DefaultCoefficients(),
    timecritical::FrameCostModel::PixelMode::Additive };
  timecritical::CostModelCalibrator Calibrator{ tcr::FeatureCount,
    timecritical::CostModelCalibrator::Options(), tcr::FeatureScales };
  timecritical::FrameTimeCorrector Corrector;
  // Still frames (every object in full) have their own correction: they are
  // far outside the interactive frames' range, and one of them must not
  // jolt the next interactive frame's prediction.
  timecritical::FrameTimeCorrector StillCorrector;
  double RawPrediction = tcr::NaN; // the model's prediction of the pending frame, uncorrected
  // The coefficients are the defaults, never measured here (no calibration,
  // none given): the first still frame scales them to this machine.
  bool UsingDefaults = true;
  bool PendingStill = false;  // the pending frame is a still frame
  bool PendingCalibrated = false; // the pending frame ran the calibration's hidden renders
  timecritical::DegradationModel Degradation;
  timecritical::ActiveSetPolicy ActiveSet;
  timecritical::FullResolutionPolicy FullResolution;
  timecritical::StaticThresholdPolicy Static;
  timecritical::FeedbackPolicy Feedback;
  timecritical::GreedyLODPolicy Greedy;

  // The window whose Start/End events time the frames.
  vtkWeakPointer<vtkRenderWindow> Window;
  unsigned long StartTag = 0, EndTag = 0;
  tcr::Clock::time_point FrameStart;
  bool FrameStartValid = false;
  tcr::Clock::time_point DrawingEnd; // MarkDrawingFinished() in the current frame
  bool DrawingEndValid = false;
  bool FramePending = false; // this renderer drew in the window's current frame
  std::array<double, tcr::FeatureCount> Features{};

  // The start-up calibration's samples (Calibration.cxx).
  struct CalibrationRun
  {
    static constexpr std::size_t MaxSamples = 2 + 3 * 4;
    std::size_t Step = 0; // next step of the plan (see CalibrationStep)
    double Sizing = 0.0;  // the target the samples are sized to (s)
    double TriangleCost = 0.0;
    double CoarseTime = 0.0, CoarseTriangles = 0.0;
    double X[MaxSamples * tcr::FeatureCount] = {};
    double Times[MaxSamples] = {};
    std::size_t Samples = 0;
  };
  CalibrationRun Calibration;
  bool CalibrationHeldBack = false; // background builds held the automatic calibration back
  int OnlineFrames = 0;             // frames the online fit took while UsingDefaults

  bool StillRequested = false;
  bool CalibrationRequested = false;
  bool CameraWasReset = false;        // ResetCamera() ran at least once
  bool CalibrationProvisional = false; // the automatic calibration ran before any camera reset
  double EffectiveTarget = 0.1; // target of the frame being planned (s), +inf for a still frame

  // Multiresolution actors of the frame and their objects.
  struct ActorEntry
  {
    vtkActor* Actor = nullptr;
    vtkMultiresolutionPolyDataMapper* Mapper = nullptr;
    std::size_t First = 0, Count = 0; // object range
    double ReadTime = 0.0; // seconds the mapper spent reading its objects since the last frame
  };
  std::vector<ActorEntry> Actors;
  std::vector<std::pair<vtkWeakPointer<vtkActor>, double>> Importance;

  // Per object (frame numbering).
  std::vector<std::size_t> ObjectActor;
  std::vector<vtkIdType> ObjectIndex;
  std::vector<std::array<double, 6>> Bounds;
  std::vector<double> MaxTriangles, MaxVertices, Coarsest, Pixels, CenterX, CenterY, Resolution,
    PreviousResolution, Velocity, Eccentricity, Importances;
  std::vector<char> Culled;
  std::vector<vtkIdType> Triangles;
  // Refinement statistics per object, and the fronts' time of the last frame.
  std::vector<vtkIdType> Vertices, Splits, Merges;
  std::vector<double> RefinementTimes;
  std::vector<char> ViewDependent;
  double RefinementEstimate = 0.0; // smoothed refinement time of the recent frames
  double DataChangeEstimate = 0.0; // this frame's reads, and vertex buffer builds to come

  // Visible objects, compacted for the policies.
  std::vector<std::size_t> Visible;
  std::vector<timecritical::DegradationModel::ObjectView> Views;
  std::vector<double> Weight, MaxTime, MinResolution, VisiblePixels, VisibleTriangles, Previous,
    Chosen;
  // Dropping (overloaded frames), per visible object: the time the object
  // takes whatever its resolution (fill, setup), what it loses when not
  // drawn, its tuple's algorithm (TupleProblem::NotDrawn: dropped). Members,
  // so that their capacity is kept from frame to frame.
  std::vector<double> ObjectFixedCost, DropDegradation;
  std::vector<int> TupleAlgorithm;
  std::vector<char> Dropped; // per object (frame numbering)
  bool DropPossible = false; // this frame may drop (interactive, setting on, policy that drops)
  double DrawnPixels = 0.0;  // covered pixels of the objects drawn (not dropped)
  timecritical::PolicyResult DropResult; // the choice of a frame that dropped
  timecritical::HysteresisBand Band;     // hysteresis of the frames that drop

  // What each mapper's objects looked like last frame (for warm start and velocity).
  struct MapperHistory
  {
    std::vector<double> Resolution, CenterX, CenterY;
    bool Seen = false;
  };
  std::unordered_map<vtkMultiresolutionPolyDataMapper*, MapperHistory> History;
  std::vector<double> ResolutionScratch;

  // Ordinary props.
  timecritical::FrameCostModel::FrameLoad Load;
  double TotalPixels = 0.0;
  double ViewportWidth = 0.0, ViewportHeight = 0.0;
  vtkNew<vtkMatrix4x4> ObjectToClip; // per actor, reused: no allocation per frame

  /// Hands Resolution (frame numbering) to every mapper.
  void ApplyResolutions()
  {
    for (const auto& entry : this->Actors)
    {
      entry.Mapper->SetObjectResolutions(
        this->Resolution.data() + entry.First, static_cast<vtkIdType>(entry.Count));
    }
  }

  timecritical::ResolutionPolicy* GetPolicy(int policy)
  {
    switch (policy)
    {
      case vtkTimeCriticalRenderer::FULL_RESOLUTION:
        return &this->FullResolution;
      case vtkTimeCriticalRenderer::STATIC_THRESHOLD:
        return &this->Static;
      case vtkTimeCriticalRenderer::FEEDBACK:
        return &this->Feedback;
      case vtkTimeCriticalRenderer::GREEDY_LOD:
        return &this->Greedy;
      default:
        return &this->ActiveSet;
    }
  }

  void StoreCoefficients()
  {
    double theta[tcr::FeatureCount], lower[tcr::FeatureCount];
    this->Calibrator.GetCoefficients(theta);
    for (std::size_t j = 0; j < tcr::FeatureCount; ++j)
    {
      lower[j] = this->Calibrator.GetLowerBound(j);
    }
    timecritical::FrameCostModel floors;
    floors.SetFeatureWeights(lower);
    this->Model.SetMinimumCoefficients(floors.GetCoefficients());
    this->Model.SetFeatureWeights(theta);
  }

  /// frames: how many frames' worth the current coefficients count for
  /// (CostModelCalibrator::SetCoefficients).
  void ResetCalibrator(double frames = 0.0)
  {
    double theta[tcr::FeatureCount];
    this->Model.GetFeatureWeights(theta);
    this->Calibrator.SetCoefficients(theta, frames);
  }

  /// Lower bounds of every coefficient: the physical ones, or a share of
  /// measured (trusted) coefficients. The defaults are not measured on this
  /// machine, so they only get the physical bounds.
  void SetCoefficientFloors(bool measured)
  {
    const auto physical = timecritical::FrameCostModel::PhysicalMinimum();
    timecritical::FrameCostModel::Coefficients floor = physical;
    if (measured)
    {
      floor.Triangle =
        std::max(physical.Triangle, tcr::TriangleFloorShare * this->Model.GetCoefficients().Triangle);
    }
    this->ApplyFloors(floor);
  }

  /// The floors bound every fit; the model itself keeps the current
  /// coefficients even where they are lower (coefficients set by hand are
  /// used as given), and is bounded by the floors from the next fit on.
  void ApplyFloors(const timecritical::FrameCostModel::Coefficients& floor)
  {
    const auto& c = this->Model.GetCoefficients();
    auto minimum = floor;
    minimum.Frame = std::min(floor.Frame, c.Frame);
    minimum.DrawCall = std::min(floor.DrawCall, c.DrawCall);
    minimum.Object = std::min(floor.Object, c.Object);
    minimum.Triangle = std::min(floor.Triangle, c.Triangle);
    minimum.Pixel = std::min(floor.Pixel, c.Pixel);
    this->Model.SetMinimumCoefficients(minimum);
    double lower[tcr::FeatureCount];
    timecritical::FrameCostModel bounds(floor);
    bounds.GetFeatureWeights(lower);
    this->Calibrator.SetLowerBounds(lower);
  }
};

#endif
