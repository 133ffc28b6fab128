// SPDX-License-Identifier: BSD-3-Clause
/**
 * WalkthroughBenchmark (W1): Gobbetti & Bouvier's walkthrough of 529 cows
 * (section 7.2.2, Fig. 8) with every resolution policy on the same camera path.
 *
 * Scene: replicas of the cow (one TOM, transformed copies) on a jittered grid
 * in the y = 0 plane, one actor with a vtkMultiresolutionPolyDataMapper in a
 * vtkTimeCriticalRenderer, 512x512. Path: A (all objects visible) -> B (close
 * to one object, few others) -> sudden turn to a view full of objects ->
 * backing away to C. Policies: active set ("timecritical"), none (full
 * resolution, also the reference images), static threshold, feedback,
 * Funkhouser's greedy, and VTK's own vtkLODProp3D (one prop per object with
 * six shared LOD meshes, DesiredUpdateRate = 1 / target).
 *
 * Per frame: wall-clock frame time around Render() (image capture excluded),
 * the renderer's own measurement, predicted and optimizer time, iterations,
 * triangles, culled objects, and PSNR against the 'none' frame of the same
 * camera (OpenImageIO), and popping: the share of the visible objects whose
 * resolution changed from the frame before. With --hysteresis H every policy
 * of the time-critical renderer runs a second time with that hysteresis
 * (vtkTimeCriticalRenderer::SetHysteresis), in the same run, named
 * "<policy>+hysteresis". Prints one table and the goals of TimeCritical,
 * writes walkthrough.json, key frames as PNG and (with matplotlib) the plot.
 * Missed goals are reported, not failed: the exit status is nonzero only for
 * errors.
 *
 *   WalkthroughBenchmark [--quick] [--frames N] [--objects N] [--policies LIST]
 *                        [--target S] [--output DIR] [--json FILE] [--data DIR]
 *                        [--hysteresis H]
 */
#include "BenchmarkArguments.h"
#include "BenchmarkImages.h"
#include "BenchmarkJson.h"
#include "BenchmarkStatistics.h"
#include "BenchmarkTiming.h"
#include "CameraPose.h"
#include "MachineInfo.h"
#include "MeshConversion.h"
#include "PlotScript.h"
#include "PolicyComparison.h"
#include "PolicyGoal.h"
#include "PolicySelection.h"
#include "MeshIO.h"
#include "W1CameraPath.h"
#include "W1Scene.h"
#include "W1SceneExport.h"
#include "W1SceneSpecification.h"
#include "vtkMultiresolutionPolyDataMapper.h"
#include "vtkTOMBuilder.h"
#include "vtkTOMFieldData.h"
#include "vtkTimeCriticalRenderer.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkLODProp3D.h>
#include <vtkMatrix4x4.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkQuadricDecimation.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTransform.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#ifndef TIMECRITICAL_WALKTHROUGH_PLOT_SCRIPT
#define TIMECRITICAL_WALKTHROUGH_PLOT_SCRIPT ""
#endif

namespace
{
using namespace timecritical::benchmark;

//------------------------------------------------------------------------------
// Policies

enum class PolicyKind
{
  None,
  TimeCritical,
  Static,
  Feedback,
  Greedy,
  LODProp3D
};

struct PolicyInfo
{
  PolicyKind Kind;
  const char* Name;  ///< command line and JSON
  const char* Label; ///< table and plot
  int RendererPolicy; ///< vtkTimeCriticalRenderer::Policies, -1 for vtkLODProp3D
};

// 'none' first: its frames are the reference images of all the others.
const PolicyInfo AllPolicies[] = {
  { PolicyKind::None, "none", "none (full res.)", vtkTimeCriticalRenderer::FULL_RESOLUTION },
  { PolicyKind::TimeCritical, "timecritical", "TimeCritical", vtkTimeCriticalRenderer::ACTIVE_SET },
  { PolicyKind::Static, "static", "static threshold", vtkTimeCriticalRenderer::STATIC_THRESHOLD },
  { PolicyKind::Feedback, "feedback", "feedback", vtkTimeCriticalRenderer::FEEDBACK },
  { PolicyKind::Greedy, "greedy", "Funkhouser greedy", vtkTimeCriticalRenderer::GREEDY_LOD },
  { PolicyKind::LODProp3D, "lodprop3d", "vtkLODProp3D", -1 },
};

/// A policy's Name for its aliases on the command line.
std::string CanonicalPolicyName(const std::string& name)
{
  std::string key = name;
  if (key == "activeset" || key == "active-set" || key == "active_set" || key == "tc")
  {
    key = "timecritical";
  }
  else if (key == "full" || key == "full-resolution" || key == "reference")
  {
    key = "none";
  }
  else if (key == "lod" || key == "vtklodprop3d")
  {
    key = "lodprop3d";
  }
  return key;
}

//------------------------------------------------------------------------------
// Settings

struct Settings
{
  bool Quick = false;
  int Frames = W1SceneSpecification::Get().DefaultFrames;
  int Objects = W1SceneSpecification::Get().DefaultObjects;
  double Target = 0.1;
  int WarmupFrames = 3;
  /// vtkLODProp3D tries every never-rendered LOD once before it selects by time.
  int LODWarmupFrames = 8;
  unsigned Seed = W1SceneSpecification::Get().DefaultSeed;
  std::string Output = "walkthrough-output";
  std::string Json; ///< default: Output/walkthrough.json
  std::string DataDirectory = TIMECRITICAL_SHARED_DATA_DIR;
  std::string SceneFile; ///< --write-scene: write W1's scene there and stop
  std::vector<const PolicyInfo*> Policies;
  bool Plot = true;
  /// Reddy's velocity and eccentricity factors (perceptual, not what PSNR rewards).
  bool Perceptual = true;
  double SafetyFactor = 1.5;
  int Family = vtkTimeCriticalRenderer::HITCHNER;
  /// > 0: a second pass of every time-critical-renderer policy with this hysteresis.
  double Hysteresis = 0.0;
};

void PrintUsage()
{
  std::cout
    << "WalkthroughBenchmark: the W1 walkthrough (Gobbetti & Bouvier section 7.2, Fig. 8)\n"
       "  --frames N      frames of the camera path (default 240, at least 10)\n"
       "  --objects N     cow replicas (default 529 = 23x23)\n"
       "  --policies L    comma list of none,timecritical,static,feedback,greedy,lodprop3d\n"
       "                  (default all; 'none' gives the reference images for PSNR)\n"
       "  --target S      target frame time in seconds (default 0.1)\n"
       "  --warmup N      untimed frames at the first camera before each policy (default 3)\n"
       "  --quick         64 objects, 30 frames (smoke test)\n"
       "  --output DIR    output folder (default ./walkthrough-output)\n"
       "  --json FILE     JSON file (default DIR/walkthrough.json)\n"
       "  --data DIR      folder with cow.obj (default " TIMECRITICAL_SHARED_DATA_DIR ")\n"
       "  --seed N        seed of the object placement (default 20001)\n"
       "  --no-plot       do not run scripts/plot_walkthrough.py\n"
       "  --write-scene FILE  write the scene (objects, transforms, colours, camera\n"
       "                  path) as JSON and stop, without rendering\n"
       "  --no-perceptual TimeCritical without Reddy's velocity and eccentricity factors\n"
       "  --safety K      TimeCritical's safety factor (default 1.5)\n"
       "  --hysteresis H  run every time-critical-renderer policy again with hysteresis H\n"
       "                  in (0, 1), named <policy>+hysteresis (popping with and without)\n"
       "  --family N      degradation family: 0 Hitchner (default), 1 Funkhouser,\n"
       "                  2 Gobbetti-Bouvier 1999, 3 Yang-Gu-Kang\n";
}

Settings ParseArguments(int argc, char* argv[])
{
  Settings settings;
  bool help = false, framesSet = false, objectsSet = false, noPlot = false, noPerceptual = false;
  std::string policies;
  BenchmarkArguments arguments(argc, argv);
  arguments.AddFlag("--help", help);
  arguments.AddFlag("-h", help);
  arguments.AddFlag("--quick", settings.Quick);
  arguments.AddInteger("--frames", settings.Frames, 10, 1000000, &framesSet);
  arguments.AddInteger("--objects", settings.Objects, 1, 1000000, &objectsSet);
  arguments.AddInteger("--warmup", settings.WarmupFrames, 0);
  arguments.AddUnsigned("--seed", settings.Seed);
  arguments.AddNumber("--target", settings.Target, [](double x) { return x > 0.0; });
  arguments.AddText("--policies", policies);
  arguments.AddText("--output", settings.Output);
  arguments.AddText("--json", settings.Json);
  arguments.AddText("--data", settings.DataDirectory);
  arguments.AddText("--write-scene", settings.SceneFile);
  arguments.AddFlag("--no-plot", noPlot);
  arguments.AddFlag("--no-perceptual", noPerceptual);
  arguments.AddNumber("--safety", settings.SafetyFactor);
  arguments.AddInteger("--family", settings.Family, 0, 3);
  arguments.AddNumber(
    "--hysteresis", settings.Hysteresis, [](double x) { return x > 0.0 && x < 1.0; });
  arguments.Parse();
  if (help)
  {
    PrintUsage();
    std::exit(0);
  }
  settings.Plot = !noPlot;
  settings.Perceptual = !noPerceptual;
  if (settings.Quick)
  {
    settings.Frames = framesSet ? settings.Frames : 30;
    settings.Objects = objectsSet ? settings.Objects : 64;
  }
  if (settings.Json.empty())
  {
    settings.Json = (std::filesystem::path(settings.Output) / "walkthrough.json").string();
  }
  // Run in the canonical order whatever the order given, so that the
  // reference exists before any policy is compared with it.
  settings.Policies = SelectPolicies(AllPolicies, policies, CanonicalPolicyName);
  return settings;
}

//------------------------------------------------------------------------------
// The object: the cow (or a substitute), its TOM and its LOD meshes

struct ObjectMesh : CowTOM
{
  /// vtkLODProp3D levels: the TOM mesh itself, then quadric decimations.
  std::vector<vtkSmartPointer<vtkPolyData>> LODs;
  std::vector<double> LODFractions;
  double LODSeconds = 0.0;
};

ObjectMesh MakeObject(const Settings& settings)
{
  ObjectMesh object;
  static_cast<CowTOM&>(object) = MakeCowTOM(settings.DataDirectory);

  // vtkLODProp3D levels, computed once and shared by all props: the full
  // mesh is the TOM's own geometry and normals (what the other policies draw
  // at full resolution), the others are the paper's 50, 25, 12, 6, 3 %.
  const Clock::time_point start = Clock::now();
  auto full = vtkSmartPointer<vtkPolyData>::New();
  full->SetPoints(object.TOM->GetPoints());
  full->SetPolys(object.TOM->GetPolys());
  full->GetPointData()->SetNormals(object.TOM->GetPointData()->GetNormals());
  object.LODs.push_back(full);
  object.LODFractions.push_back(1.0);
  auto plain = vtkSmartPointer<vtkPolyData>::New();
  plain->SetPoints(object.TOM->GetPoints());
  plain->SetPolys(object.TOM->GetPolys());
  for (double fraction : { 0.5, 0.25, 0.12, 0.06, 0.03 })
  {
    vtkNew<vtkQuadricDecimation> decimate;
    decimate->SetInputData(plain);
    decimate->SetTargetReduction(1.0 - fraction);
    decimate->VolumePreservationOn();
    decimate->Update();
    object.LODs.push_back(WithNormals(decimate->GetOutput()));
    object.LODFractions.push_back(fraction);
  }
  object.LODSeconds = Seconds(start, Clock::now());
  return object;
}

//------------------------------------------------------------------------------
// vtkLODProp3D that remembers the frame it was last drawn in, so that culled
// props (which keep their last selection) are not counted.

class CountingLODProp3D : public vtkLODProp3D
{
public:
  static CountingLODProp3D* New();
  vtkTypeMacro(CountingLODProp3D, vtkLODProp3D);

  int RenderOpaqueGeometry(vtkViewport* viewport) override
  {
    this->LastFrame = CurrentFrame;
    return this->Superclass::RenderOpaqueGeometry(viewport);
  }

  static long CurrentFrame;
  long LastFrame = -1;

protected:
  CountingLODProp3D() = default;
  ~CountingLODProp3D() override = default;

private:
  CountingLODProp3D(const CountingLODProp3D&) = delete;
  void operator=(const CountingLODProp3D&) = delete;
};
long CountingLODProp3D::CurrentFrame = 0;
vtkStandardNewMacro(CountingLODProp3D);

//------------------------------------------------------------------------------
// Records and statistics

struct FrameRecord : PolicyFrame
{
  double RendererMeasured = NaN; ///< vtkTimeCriticalRenderer::GetMeasuredFrameTime() after it
  double Fixed = NaN;  ///< t_fixed of the prediction
  double Margin = NaN; ///< safety margin kept free of the target
  double Optimizer = NaN;
  double Heuristics = NaN;
  int Iterations = 0;
  bool Converged = true;
  double VisibleTriangles = 0.0; ///< full-resolution triangles of the objects not culled
  double Culled = 0.0;
  std::array<int, 6> LODCounts{}; ///< vtkLODProp3D: props drawn at each level
  /// Popping: share of the visible objects drawn in the frame before too
  /// whose resolution changed (vtkTimeCriticalRenderer::GetNumberOfChangedObjects).
  double Changed = NaN;
};

struct Statistics : PolicyStatistics
{
  double RendererVsWall = NaN; ///< mean (renderer measured - wall) / wall
  double OptimizerMean = NaN, OptimizerMax = NaN;
  double IterationsMean = NaN;
  int ReducedFrames = 0; ///< vtkLODProp3D: frames with some prop below its full level
  std::array<long long, 6> LODPropFrames{}; ///< vtkLODProp3D: props drawn per level, all frames
  /// Over the frames whose full-resolution time ('none', same camera) exceeds
  /// the target: the frames where a policy must reduce, and where unused
  /// budget is image quality given away.
  int HeavyFrames = 0;
  double HeavyMean = NaN, HeavyCV = NaN, HeavyShareWithin = NaN, HeavyPSNRMedian = NaN;
  double ChangedMean = NaN; ///< mean popping share per frame (time-critical renderer only)
};

struct PolicyRun
{
  const PolicyInfo* Policy = nullptr;
  double Hysteresis = 0.0;   ///< vtkTimeCriticalRenderer::SetHysteresis of this run
  std::string Name, Label;   ///< the policy's, with "+hysteresis" for a hysteresis pass
  std::vector<FrameRecord> Frames;
  Statistics Stats;
  double Seconds = 0.0;
  /// Vertex buffer (re)builds of the multiresolution mapper during the timed
  /// frames: they should be 0, only index buffers change per frame.
  long long VertexBufferBuilds = 0;
  /// vtkLODProp3D after the run: mean estimated render time of each level over
  /// all props, and mean allocated render time of the props drawn last frame.
  std::vector<double> LODEstimated;
  double LODAllocated = NaN;
};

/// Frames whose full-resolution time exceeds the target (empty: unknown).
std::vector<bool> HeavyFrames(const std::vector<FrameRecord>& reference, double target)
{
  std::vector<bool> heavy;
  for (const FrameRecord& f : reference)
  {
    heavy.push_back(f.Measured > target);
  }
  return heavy;
}

/// Mean, CV and share within 110% of the target over the heavy frames.
void ComputeHeavyStatistics(
  Statistics& s, const std::vector<FrameRecord>& frames, const std::vector<bool>& heavy, double target)
{
  std::vector<double> times, psnr;
  int within = 0;
  for (size_t i = 0; i < frames.size() && i < heavy.size(); ++i)
  {
    if (heavy[i])
    {
      times.push_back(frames[i].Measured);
      within += frames[i].Measured <= 1.1 * target ? 1 : 0;
      if (std::isfinite(frames[i].PSNR))
      {
        psnr.push_back(frames[i].PSNR);
      }
    }
  }
  s.HeavyFrames = static_cast<int>(times.size());
  if (times.empty())
  {
    return;
  }
  s.HeavyMean = Mean(times);
  double variance = 0.0;
  for (double t : times)
  {
    variance += (t - s.HeavyMean) * (t - s.HeavyMean);
  }
  s.HeavyCV = std::sqrt(variance / static_cast<double>(times.size())) / s.HeavyMean;
  s.HeavyShareWithin = static_cast<double>(within) / static_cast<double>(times.size());
  s.HeavyPSNRMedian = Median(psnr);
}

Statistics ComputeStatistics(const std::vector<FrameRecord>& frames, double target)
{
  Statistics s;
  static_cast<PolicyStatistics&>(s) = ComputePolicyStatistics(frames, target);
  std::vector<double> rendererDiff, optimizer, iterations, changed;
  for (const FrameRecord& f : frames)
  {
    if (std::isfinite(f.Changed))
    {
      changed.push_back(f.Changed);
    }
    if (std::isfinite(f.RendererMeasured) && f.Measured > 0.0)
    {
      rendererDiff.push_back((f.RendererMeasured - f.Measured) / f.Measured);
    }
    if (std::isfinite(f.Optimizer))
    {
      optimizer.push_back(f.Optimizer);
      iterations.push_back(f.Iterations);
    }
    bool reduced = false;
    for (size_t level = 0; level < f.LODCounts.size(); ++level)
    {
      s.LODPropFrames[level] += f.LODCounts[level];
      reduced = reduced || (level > 0 && f.LODCounts[level] > 0);
    }
    s.ReducedFrames += reduced ? 1 : 0;
  }
  if (frames.empty())
  {
    return s;
  }
  s.RendererVsWall = Mean(rendererDiff);
  s.OptimizerMean = Mean(optimizer);
  s.OptimizerMax = optimizer.empty() ? NaN : *std::max_element(optimizer.begin(), optimizer.end());
  s.IterationsMean = Mean(iterations);
  s.ChangedMean = changed.empty() ? NaN : Mean(changed);
  return s;
}

//------------------------------------------------------------------------------
// The benchmark

struct Checks
{
  bool FrontEqualsBack = false;
  bool Deterministic = false;
  double LODFullVsReferencePSNR = NaN; ///< vtkLODProp3D forced to level 0 at A vs the reference
};

class Walkthrough
{
public:
  Walkthrough(const Settings& settings, const ObjectMesh& object, const Scene& scene,
    const W1CameraPath& path)
    : Options(settings)
    , Object(object)
    , Layout(scene)
    , Path(path)
  {
  }

  void Setup();
  void Calibrate();
  PolicyRun Run(const PolicyInfo& policy);
  void WriteResolutionMaps();
  void MeasureNoiseFloor();

  /// The same frame rendered again and again: how much frame times vary with
  /// nothing in the scene changing (the floor under any policy's CV).
  struct NoiseFloor
  {
    int Frames = 0;
    vtkIdType Triangles = 0;
    double Median = NaN, Mean = NaN, Max = NaN, CV = NaN;
    double ShareOver10Percent = NaN; ///< frames more than 10% slower than the median
  } Noise;

  std::vector<Image> Reference;
  std::vector<bool> Heavy; ///< per frame: full resolution ('none') over the target
  Checks Check;
  double CalibrationSeconds = 0.0;
  double Coefficients[5] = { NaN, NaN, NaN, NaN, NaN }; ///< frame, draw call, triangle, pixel, margin
  double SetupSeconds = 0.0;

private:
  vtkSmartPointer<vtkTimeCriticalRenderer> MakeTimeCriticalRenderer(int policy);
  void Use(vtkRenderer* renderer);
  /// A plain vtkRenderer with the scene's actor and camera, made current:
  /// nothing re-chooses the mapper's resolutions.
  vtkSmartPointer<vtkRenderer> UsePlainRenderer();
  /// Removes the current renderer from the window.
  void StopUsing();
  /// The camera at a frame of the path, clipping range over the whole scene.
  void MoveTo(int frame);
  double TimedRender();
  int Key(int frame) const;
  void SaveKeyFrame(const std::string& policy, int frame, Image& image);

  const Settings& Options;
  const ObjectMesh& Object;
  const Scene& Layout;
  const W1CameraPath& Path;

  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkCamera> Camera;
  vtkNew<vtkMultiresolutionPolyDataMapper> Mapper;
  vtkNew<vtkActor> Actor;
  vtkSmartPointer<vtkRenderer> Current;
  std::vector<vtkSmartPointer<vtkPolyDataMapper>> LODMappers;
  std::vector<vtkSmartPointer<CountingLODProp3D>> LODProps;
  std::vector<int> LODIds;
  vtkNew<vtkRenderer> LODRenderer;
  /// Object resolutions of TimeCritical at key frames B and the turn, for the resolution maps.
  std::vector<std::vector<double>> MapResolutions;
  std::vector<int> MapFrames;

public:
  /// Hysteresis of the time-critical renderers made from now on (0: none).
  double Hysteresis = 0.0;
};

void Walkthrough::Setup()
{
  const Clock::time_point start = Clock::now();
  this->Window->SetSize(WindowSize, WindowSize);
  this->Window->SetMultiSamples(0);
  this->Window->SetWindowName("WalkthroughBenchmark");
  ApplyPose(this->Camera, this->Path.At(0));

  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(static_cast<unsigned>(this->Layout.Objects.size()));
  for (size_t i = 0; i < this->Layout.Objects.size(); ++i)
  {
    blocks->SetBlock(static_cast<unsigned>(i), MakeCopy(this->Object.TOM, this->Layout.Objects[i]));
  }
  this->Mapper->SetInputDataObject(blocks);
  this->Actor->SetMapper(this->Mapper);

  // vtkLODProp3D scene: the same placements as actor matrices, the six LOD
  // mappers shared by all props, one property (the object's colour) per prop.
  for (const auto& lod : this->Object.LODs)
  {
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(lod);
    mapper->ScalarVisibilityOff();
    this->LODMappers.push_back(mapper);
  }
  for (const Placement& place : this->Layout.Objects)
  {
    auto prop = vtkSmartPointer<CountingLODProp3D>::New();
    vtkNew<vtkProperty> property;
    // The same colour values the vertex colours hold: diffuse color = c / 255 in both.
    property->SetColor(place.Color[0] / 255.0, place.Color[1] / 255.0, place.Color[2] / 255.0);
    std::vector<int> ids;
    for (size_t level = 0; level < this->LODMappers.size(); ++level)
    {
      const int id = prop->AddLOD(this->LODMappers[level], property, 0.0);
      prop->SetLODLevel(id, static_cast<double>(level)); // lower level = better quality
      ids.push_back(id);
    }
    if (this->LODIds.empty())
    {
      this->LODIds = ids;
    }
    else if (ids != this->LODIds)
    {
      throw std::runtime_error("vtkLODProp3D gave different LOD ids to equal props");
    }
    prop->SetUserMatrix(place.Transform->GetMatrix());
    this->LODRenderer->AddViewProp(prop);
    this->LODProps.push_back(prop);
  }
  this->LODRenderer->SetActiveCamera(this->Camera);
  SetBackground(this->LODRenderer);
  this->SetupSeconds = Seconds(start, Clock::now());
}

void Walkthrough::Use(vtkRenderer* renderer)
{
  this->StopUsing();
  this->Current = renderer;
  this->Window->AddRenderer(renderer);
}

vtkSmartPointer<vtkRenderer> Walkthrough::UsePlainRenderer()
{
  auto plain = vtkSmartPointer<vtkRenderer>::New();
  plain->AddActor(this->Actor);
  plain->SetActiveCamera(this->Camera);
  SetBackground(plain);
  this->Use(plain);
  return plain;
}

void Walkthrough::StopUsing()
{
  if (this->Current)
  {
    this->Window->RemoveRenderer(this->Current);
  }
  this->Current = nullptr;
}

void Walkthrough::MoveTo(int frame)
{
  ApplyPose(this->Camera, this->Path.At(frame));
  this->Current->ResetCameraClippingRange(const_cast<double*>(this->Layout.Bounds));
}

vtkSmartPointer<vtkTimeCriticalRenderer> Walkthrough::MakeTimeCriticalRenderer(int policy)
{
  auto renderer = vtkSmartPointer<vtkTimeCriticalRenderer>::New();
  renderer->AddActor(this->Actor);
  renderer->SetActiveCamera(this->Camera);
  SetBackground(renderer);
  renderer->SetTargetFrameTime(this->Options.Target);
  renderer->SetUseVelocity(this->Options.Perceptual);
  renderer->SetUseEccentricity(this->Options.Perceptual);
  renderer->SetSafetyFactor(this->Options.SafetyFactor);
  renderer->SetDegradationFamily(this->Options.Family);
  renderer->SetPolicy(policy);
  renderer->SetHysteresis(this->Hysteresis);
  if (std::isfinite(this->Coefficients[0]))
  {
    // Every policy starts from the same calibration (and refines it online),
    // so results do not depend on the order the policies run in.
    renderer->AutomaticCalibrationOff();
    renderer->SetCostCoefficients(
      this->Coefficients[0], this->Coefficients[1], this->Coefficients[2], this->Coefficients[3]);
    renderer->SetCostMargin(this->Coefficients[4]);
  }
  return renderer;
}

void Walkthrough::Calibrate()
{
  auto renderer = this->MakeTimeCriticalRenderer(vtkTimeCriticalRenderer::ACTIVE_SET);
  this->Use(renderer);
  this->MoveTo(0);
  const Clock::time_point start = Clock::now();
  if (!renderer->Calibrate())
  {
    throw std::runtime_error("vtkTimeCriticalRenderer::Calibrate() failed on the scene");
  }
  this->CalibrationSeconds = Seconds(start, Clock::now());
  this->Coefficients[0] = renderer->GetFrameCost();
  this->Coefficients[1] = renderer->GetDrawCallCost();
  this->Coefficients[2] = renderer->GetTriangleCost();
  this->Coefficients[3] = renderer->GetPixelCost();
  this->Coefficients[4] = renderer->GetCostMargin();
}

double Walkthrough::TimedRender()
{
  return timecritical::benchmark::TimedRender(this->Window);
}

int Walkthrough::Key(int frame) const
{
  if (frame == this->Path.GetKeyA())
  {
    return 0;
  }
  if (frame == this->Path.GetKeyB())
  {
    return 1;
  }
  if (frame == this->Path.GetKeyTurn())
  {
    return 2;
  }
  if (frame == this->Path.GetKeyC())
  {
    return 3;
  }
  return -1;
}

const char* const KeyNames[] = { "A", "B", "turn", "C" };

void Walkthrough::SaveKeyFrame(const std::string& policy, int frame, Image& image)
{
  const int key = this->Key(frame);
  if (key >= 0)
  {
    WritePNG(image, std::filesystem::path(this->Options.Output) /
        (policy + "_" + KeyNames[key] + ".png"));
  }
}

PolicyRun Walkthrough::Run(const PolicyInfo& policy)
{
  PolicyRun run;
  run.Policy = &policy;
  run.Hysteresis = this->Hysteresis;
  run.Name = std::string(policy.Name) + (run.Hysteresis > 0.0 ? "+hysteresis" : "");
  run.Label = std::string(policy.Label) + (run.Hysteresis > 0.0 ? " +hyst." : "");
  const bool lod = policy.Kind == PolicyKind::LODProp3D;
  const bool reference = policy.Kind == PolicyKind::None;
  vtkSmartPointer<vtkTimeCriticalRenderer> tc;
  if (lod)
  {
    this->Use(this->LODRenderer);
    // vtkLODProp3D chooses levels from the time the renderer allocates it,
    // which follows the window's desired update rate.
    this->Window->SetDesiredUpdateRate(1.0 / this->Options.Target);
  }
  else
  {
    tc = this->MakeTimeCriticalRenderer(policy.RendererPolicy);
    this->Use(tc);
    this->Window->SetDesiredUpdateRate(0.0001);
  }
  const Clock::time_point start = Clock::now();
  const int frames = this->Options.Frames;
  if (reference)
  {
    this->Reference.assign(static_cast<size_t>(frames), Image());
  }

  // Warm-up at the first camera, untimed: shaders, buffers, the policies'
  // first-frame state; vtkLODProp3D needs one frame per never-drawn level.
  const int warmup = lod ? std::max(this->Options.WarmupFrames, this->Options.LODWarmupFrames)
                         : this->Options.WarmupFrames;
  this->MoveTo(0);
  Image previous;
  for (int i = 0; i < warmup; ++i)
  {
    ++CountingLODProp3D::CurrentFrame;
    this->TimedRender();
    if (reference && i + 2 >= warmup)
    {
      // The reference must be what the screen shows and the same every time.
      Image front = Capture(this->Window, true);
      if (i + 1 == warmup)
      {
        this->Check.FrontEqualsBack = front == Capture(this->Window, false);
        this->Check.Deterministic = !previous.empty() && front == previous;
      }
      previous = std::move(front);
    }
  }
  if (lod && !this->Reference.empty())
  {
    // Sanity check of the comparison itself: every prop at its full level
    // must match the reference closely (same mesh, colours and lights).
    for (auto& prop : this->LODProps)
    {
      prop->AutomaticLODSelectionOff();
      prop->SetSelectedLODID(this->LODIds[0]);
    }
    ++CountingLODProp3D::CurrentFrame;
    this->TimedRender();
    Image full = Capture(this->Window, true);
    this->Check.LODFullVsReferencePSNR = Compare(full, this->Reference[0]).PSNR;
    WritePNG(full, std::filesystem::path(this->Options.Output) / "lodprop3d_A_full_level.png");
    for (auto& prop : this->LODProps)
    {
      prop->AutomaticLODSelectionOn();
    }
    for (int i = 0; i < 2; ++i) // let the level-0 timings blend out again
    {
      ++CountingLODProp3D::CurrentFrame;
      this->TimedRender();
    }
  }

  const vtkIdType buildsBefore = this->Mapper->GetVertexBufferBuildCount();
  for (int frame = 0; frame < frames; ++frame)
  {
    this->MoveTo(frame);
    ++CountingLODProp3D::CurrentFrame;
    FrameRecord record;
    record.Measured = this->TimedRender();
    if (tc)
    {
      record.RendererMeasured = tc->GetMeasuredFrameTime();
      record.Predicted = tc->GetPredictedFrameTime();
      record.Fixed = tc->GetFixedFrameTime();
      record.Margin = tc->GetSafetyMargin();
      record.Optimizer = tc->GetOptimizationTime();
      record.Heuristics = tc->GetHeuristicsTime();
      record.Iterations = tc->GetOptimizationIterations();
      record.Converged = tc->GetOptimizationConverged();
      record.Triangles = static_cast<double>(tc->GetTrianglesDrawn());
      record.Culled = static_cast<double>(tc->GetNumberOfCulledObjects());
      const double visible = static_cast<double>(tc->GetNumberOfObjects()) - record.Culled;
      if (frame > 0 && visible > 0.0)
      {
        record.Changed = static_cast<double>(tc->GetNumberOfChangedObjects()) / visible;
      }
      for (vtkIdType i = 0; i < tc->GetNumberOfObjects(); ++i)
      {
        if (tc->GetObjectResolution(i) > 0.0)
        {
          record.VisibleTriangles += static_cast<double>(
            this->Mapper->GetObjectNumberOfTriangles(tc->GetObjectIndex(i)));
        }
      }
      if (policy.Kind == PolicyKind::TimeCritical && run.Hysteresis == 0.0 &&
        (frame == this->Path.GetKeyB() || frame == this->Path.GetKeyTurn()))
      {
        std::vector<double> r(static_cast<size_t>(this->Mapper->GetNumberOfObjects()));
        for (size_t i = 0; i < r.size(); ++i)
        {
          r[i] = this->Mapper->GetObjectResolution(static_cast<vtkIdType>(i));
        }
        this->MapResolutions.push_back(r);
        this->MapFrames.push_back(frame);
      }
    }
    else
    {
      // Triangles from the level each drawn prop used this frame.
      int drawn = 0;
      for (auto& prop : this->LODProps)
      {
        if (prop->LastFrame != CountingLODProp3D::CurrentFrame)
        {
          continue;
        }
        ++drawn;
        const int id = prop->GetLastRenderedLODID();
        const auto it = std::find(this->LODIds.begin(), this->LODIds.end(), id);
        if (it == this->LODIds.end())
        {
          throw std::runtime_error("vtkLODProp3D drew an unknown LOD id");
        }
        const size_t level = static_cast<size_t>(it - this->LODIds.begin());
        record.Triangles += static_cast<double>(this->Object.LODs[level]->GetNumberOfPolys());
        record.VisibleTriangles += static_cast<double>(this->Object.Triangles);
        ++record.LODCounts[level];
      }
      record.Culled = static_cast<double>(this->LODProps.size()) - drawn;
    }

    // Capture and compare outside the timed region.
    Image image = Capture(this->Window, true);
    if (reference)
    {
      this->SaveKeyFrame(policy.Name, frame, image);
      this->Reference[static_cast<size_t>(frame)] = std::move(image);
    }
    else
    {
      if (!this->Reference.empty())
      {
        const Comparison c = Compare(image, this->Reference[static_cast<size_t>(frame)]);
        record.PSNR = c.PSNR;
        record.Identical = c.Identical;
      }
      this->SaveKeyFrame(run.Name, frame, image);
    }
    run.Frames.push_back(record);
    if (frame % 20 == 0 || frame == frames - 1)
    {
      char psnr[32] = "";
      if (std::isfinite(record.PSNR))
      {
        std::snprintf(psnr, sizeof(psnr), ", PSNR %.2f dB", record.PSNR);
      }
      std::fprintf(stderr, "  [%s] frame %3d/%d: %7.1f ms, %9.0f triangles, %4.0f culled%s\n",
        run.Name.c_str(), frame + 1, frames, 1000.0 * record.Measured, record.Triangles, record.Culled,
        psnr);
    }
  }
  run.Seconds = Seconds(start, Clock::now());
  if (lod)
  {
    // Why levels are (not) chosen: what vtkLODProp3D believes each level costs.
    run.LODEstimated.assign(this->LODIds.size(), 0.0);
    double allocated = 0.0;
    int drawn = 0;
    for (auto& prop : this->LODProps)
    {
      for (size_t level = 0; level < this->LODIds.size(); ++level)
      {
        run.LODEstimated[level] += prop->GetLODEstimatedRenderTime(this->LODIds[level]) /
          static_cast<double>(this->LODProps.size());
      }
      if (prop->LastFrame == CountingLODProp3D::CurrentFrame)
      {
        allocated += prop->GetAllocatedRenderTime();
        ++drawn;
      }
    }
    run.LODAllocated = drawn > 0 ? allocated / drawn : NaN;
  }
  run.VertexBufferBuilds =
    static_cast<long long>(this->Mapper->GetVertexBufferBuildCount() - buildsBefore);
  run.Stats = ComputeStatistics(run.Frames, this->Options.Target);
  if (reference)
  {
    this->Heavy = HeavyFrames(run.Frames, this->Options.Target);
  }
  ComputeHeavyStatistics(run.Stats, run.Frames, this->Heavy, this->Options.Target);
  if (lod)
  {
    this->Window->SetDesiredUpdateRate(0.0001);
  }
  // Release the policy's renderer before the next one starts.
  if (tc)
  {
    this->Window->RemoveRenderer(tc);
    this->Current = nullptr;
  }
  return run;
}

void Walkthrough::WriteResolutionMaps()
{
  // A plain renderer with the same actor and camera: nothing re-chooses the
  // resolutions, so the map shows exactly what TimeCritical drew at that frame.
  this->UsePlainRenderer();
  this->Mapper->ColorByResolutionOn();
  for (size_t m = 0; m < this->MapFrames.size(); ++m)
  {
    const int frame = this->MapFrames[m];
    const std::vector<double>& r = this->MapResolutions[m];
    this->Mapper->SetObjectResolutions(r.data(), static_cast<vtkIdType>(r.size()));
    this->MoveTo(frame);
    this->Window->Render();
    Image image = Capture(this->Window, true);
    WritePNG(image, std::filesystem::path(this->Options.Output) /
        (std::string("timecritical_") + KeyNames[this->Key(frame)] + "_resolution.png"));
  }
  this->Mapper->ColorByResolutionOff();
  this->StopUsing();
}

void Walkthrough::MeasureNoiseFloor()
{
  // Three quarters along the path (backing away: many objects in view), every
  // object at one resolution, with a plain renderer so nothing re-chooses.
  this->UsePlainRenderer();
  this->MoveTo((3 * this->Options.Frames) / 4);
  this->Mapper->SetResolution(0.2);
  const int warmup = 5, frames = this->Options.Quick ? 10 : 40;
  std::vector<double> times;
  for (int f = 0; f < warmup + frames; ++f)
  {
    const double t = this->TimedRender();
    if (f >= warmup)
    {
      times.push_back(t);
    }
  }
  this->Noise.Frames = frames;
  this->Noise.Triangles = this->Mapper->GetRenderedTriangles();
  this->Noise.Median = Median(times);
  this->Noise.Mean = Mean(times);
  this->Noise.Max = *std::max_element(times.begin(), times.end());
  double variance = 0.0;
  int slow = 0;
  for (double t : times)
  {
    variance += (t - this->Noise.Mean) * (t - this->Noise.Mean);
    slow += t > 1.1 * this->Noise.Median ? 1 : 0;
  }
  this->Noise.CV = std::sqrt(variance / frames) / this->Noise.Mean;
  this->Noise.ShareOver10Percent = static_cast<double>(slow) / frames;
  this->StopUsing();
}

//------------------------------------------------------------------------------
// Output

using Goal = PolicyGoal;

std::vector<Goal> EvaluateGoals(
  const std::vector<PolicyRun>& runs, double target, const Walkthrough::NoiseFloor& noise)
{
  std::vector<Goal> goals;
  const PolicyRun* tc = nullptr;
  for (const auto& run : runs)
  {
    if (run.Policy->Kind == PolicyKind::TimeCritical && run.Hysteresis == 0.0)
    {
      tc = &run;
    }
  }
  if (!tc)
  {
    return goals;
  }
  const Statistics& s = tc->Stats;
  char buffer[160];
  std::snprintf(buffer, sizeof(buffer), "%.1f%%", 100.0 * s.ShareWithin);
  goals.push_back({ "frames <= " + Number(1100.0 * target, 4) + " ms", ">= 99%", buffer,
    s.ShareWithin >= 0.99 });
  // The budget used where it matters: frames that cannot be drawn in full.
  if (s.HeavyFrames > 0)
  {
    std::snprintf(buffer, sizeof(buffer), "%.1f ms (%d frames)", 1000.0 * s.HeavyMean,
      s.HeavyFrames);
    goals.push_back({ "mean frame time, full res. > target", ">= " + Number(900.0 * target, 4) +
        " ms", buffer, s.HeavyMean >= 0.9 * target });
    std::snprintf(buffer, sizeof(buffer), "%.1f%% (noise floor %.1f%%)", 100.0 * s.HeavyCV,
      100.0 * noise.CV);
    goals.push_back({ "frame time CV, full res. > target", "<= 5% (report)", buffer,
      s.HeavyCV <= 0.05 });
  }
  else
  {
    goals.push_back({ "mean frame time, full res. > target", ">= " + Number(900.0 * target, 4) +
        " ms", "no 'none' run or no such frame", false, false });
  }
  std::snprintf(buffer, sizeof(buffer), "%.1f%%", 100.0 * s.PredictionError);
  goals.push_back({ "mean |predicted - measured| / measured", "<= 10%", buffer,
    s.PredictionError <= 0.10 });
  std::snprintf(buffer, sizeof(buffer), "max %.3f ms (mean %.3f)", 1000.0 * s.OptimizerMax,
    1000.0 * s.OptimizerMean);
  goals.push_back({ "optimizer time", "<= 1 ms", buffer, s.OptimizerMax <= 0.001 });
  if (std::isfinite(s.PSNRMedian))
  {
    double bestOther = -std::numeric_limits<double>::infinity();
    std::string bestName = "-";
    for (const auto& run : runs)
    {
      if (&run != tc && run.Policy->Kind != PolicyKind::None && run.Hysteresis == 0.0 &&
        std::isfinite(run.Stats.PSNRMedian) && run.Stats.PSNRMedian > bestOther)
      {
        bestOther = run.Stats.PSNRMedian;
        bestName = run.Policy->Name;
      }
    }
    if (std::isfinite(bestOther))
    {
      std::snprintf(buffer, sizeof(buffer), "%.2f dB (next: %s %.2f)", s.PSNRMedian,
        bestName.c_str(), bestOther);
      goals.push_back({ "median PSNR vs full resolution", "above every peer", buffer,
        s.PSNRMedian > bestOther, true });
    }
    else
    {
      std::snprintf(buffer, sizeof(buffer), "%.2f dB (no other policy run)", s.PSNRMedian);
      goals.push_back(
        { "median PSNR vs full resolution", "above every peer", buffer, false, false });
    }
  }
  return goals;
}

/// Popping with and without hysteresis: share of the objects whose resolution changes per frame.
void PrintPopping(const std::vector<PolicyRun>& runs)
{
  std::printf("\npopping (visible objects whose resolution changed from the frame before):\n"
              "%-26s %10s %9s %8s %8s %9s\n",
    "policy", "hysteresis", "changed", "mean ms", "<=110ms", "PSNR med");
  for (const auto& run : runs)
  {
    const Statistics& s = run.Stats;
    if (std::isfinite(s.ChangedMean) && run.Policy->Kind != PolicyKind::None)
    {
      std::printf("%-26s %10.2f %8.1f%% %8.1f %8s %9s\n", run.Label.c_str(), run.Hysteresis,
        100.0 * s.ChangedMean, 1000.0 * s.Mean, PercentCell(s.ShareWithin).c_str(),
        DecibelCell(s.PSNRMedian).c_str());
    }
  }
}

void PrintTable(const std::vector<PolicyRun>& runs, const std::vector<Goal>& goals, double target)
{
  std::printf("\n%-24s %8s %8s %8s %7s %8s %8s %9s %9s %8s %8s %10s\n", "policy", "mean ms",
    "median", "max ms", "CV", "<=110ms", "pred.err", "opt mean", "opt max", "PSNR dB",
    "PSNR med", "tris/frame");
  for (const auto& run : runs)
  {
    const Statistics& s = run.Stats;
    const bool isReference = run.Policy->Kind == PolicyKind::None;
    const auto db = [isReference](double x) {
      return isReference ? std::string("ref") : DecibelCell(x);
    };
    std::printf("%-24s %8.1f %8.1f %8.1f %7s %8s %8s %9s %9s %8s %8s %10.0f\n", run.Label.c_str(),
      1000.0 * s.Mean, 1000.0 * s.Median, 1000.0 * s.Max, PercentCell(s.CV).c_str(),
      PercentCell(s.ShareWithin).c_str(), PercentCell(s.PredictionError).c_str(),
      MillisecondsCell(s.OptimizerMean, 3).c_str(), MillisecondsCell(s.OptimizerMax, 3).c_str(),
      db(s.PSNRMean).c_str(), db(s.PSNRMedian).c_str(),
      s.TrianglesMean);
  }
  std::printf("(target %.0f ms; PSNR against the 'none' frame of the same camera, identical "
              "images counted as %.0f dB, which lifts the mean of policies that draw some frames "
              "in full; optimizer times in ms)\n",
    1000.0 * target, PSNRCap);
  if (!runs.empty() && runs.front().Stats.HeavyFrames > 0)
  {
    std::printf("\nframes whose full-resolution time exceeds the target (%d of %d):\n%-24s %8s "
                "%7s %8s %9s\n",
      runs.front().Stats.HeavyFrames, runs.front().Stats.Frames, "policy", "mean ms", "CV",
      "<=110ms", "PSNR med");
    for (const auto& run : runs)
    {
      const Statistics& s = run.Stats;
      std::printf("%-24s %8.1f %6.1f%% %7.1f%% %9.2f\n", run.Label.c_str(), 1000.0 * s.HeavyMean,
        100.0 * s.HeavyCV, 100.0 * s.HeavyShareWithin, s.HeavyPSNRMedian);
    }
  }
  PrintPopping(runs);
  if (!goals.empty())
  {
    PrintGoals("TimeCritical goals", goals, 40, 32);
  }
}

void WriteJson(const Settings& settings, const ObjectMesh& object, const Scene& scene,
  const W1CameraPath& path, const Walkthrough& walk, const std::vector<PolicyRun>& runs,
  const std::vector<Goal>& goals, const double load[2])
{
  std::ofstream out(settings.Json);
  if (!out)
  {
    throw std::runtime_error("cannot write " + settings.Json);
  }
  out << "{\n  \"benchmark\": \"WalkthroughBenchmark\",\n";
  out << "  \"settings\": {\"frames\": " << settings.Frames << ", \"objects\": " << settings.Objects
      << ", \"target_frame_time\": " << Number(settings.Target) << ", \"quick\": "
      << (settings.Quick ? "true" : "false") << ", \"warmup_frames\": " << settings.WarmupFrames
      << ", \"lodprop3d_warmup_frames\": " << settings.LODWarmupFrames << ", \"seed\": "
      << settings.Seed << ", \"window\": [" << WindowSize << ", " << WindowSize
      << "], \"view_angle\": " << ViewAngle << ", \"psnr_cap\": " << PSNRCap
      << ", \"perceptual\": " << (settings.Perceptual ? "true" : "false")
      << ", \"safety_factor\": " << Number(settings.SafetyFactor) << ", \"degradation_family\": "
      << settings.Family << ", \"load_average_start\": " << Number(load[0], 3) << ", \"load_average_end\": "
      << Number(load[1], 3) << "},\n";
  out << "  \"scene\": {\"mesh\": " << Quoted(object.Source) << ", \"substitute\": "
      << (object.Substitute ? "true" : "false") << ", \"triangles_per_object\": "
      << object.Triangles << ", \"base_triangles_per_object\": " << object.BaseTriangles
      << ", \"objects\": " << scene.Objects.size() << ", \"triangles\": " << scene.Triangles
      << ", \"grid\": " << scene.GridSide << ", \"spacing\": " << Number(scene.Spacing)
      << ", \"jitter\": " << Number(scene.Jitter) << ", \"footprint_radius\": "
      << Number(scene.Radius) << ", \"focus_object\": " << scene.Focus
      << ", \"tom_build_seconds\": " << Number(object.BuildSeconds)
      << ", \"setup_seconds\": " << Number(walk.SetupSeconds) << ", \"lod_triangles\": [";
  for (size_t i = 0; i < object.LODs.size(); ++i)
  {
    out << (i ? ", " : "") << object.LODs[i]->GetNumberOfPolys();
  }
  out << "], \"lod_fractions\": [";
  for (size_t i = 0; i < object.LODFractions.size(); ++i)
  {
    out << (i ? ", " : "") << Number(object.LODFractions[i]);
  }
  out << "]},\n";
  out << "  \"calibration\": {\"seconds\": " << Number(walk.CalibrationSeconds)
      << ", \"frame\": " << Number(walk.Coefficients[0]) << ", \"draw_call\": "
      << Number(walk.Coefficients[1]) << ", \"triangle\": " << Number(walk.Coefficients[2])
      << ", \"pixel\": " << Number(walk.Coefficients[3]) << ", \"margin\": "
      << Number(walk.Coefficients[4]) << "},\n";
  out << "  \"noise_floor\": {\"frames\": " << walk.Noise.Frames << ", \"triangles\": "
      << walk.Noise.Triangles << ", \"median\": " << Number(walk.Noise.Median) << ", \"mean\": "
      << Number(walk.Noise.Mean) << ", \"max\": " << Number(walk.Noise.Max) << ", \"cv\": "
      << Number(walk.Noise.CV) << ", \"share_over_110_percent_of_median\": "
      << Number(walk.Noise.ShareOver10Percent) << "},\n";
  out << "  \"checks\": {\"front_buffer_equals_back_buffer\": "
      << (walk.Check.FrontEqualsBack ? "true" : "false")
      << ", \"reference_deterministic\": " << (walk.Check.Deterministic ? "true" : "false")
      << ", \"lodprop3d_full_level_psnr\": " << Number(walk.Check.LODFullVsReferencePSNR) << "},\n";
  out << "  \"path\": {\"key_frames\": {\"A\": " << path.GetKeyA() << ", \"B\": " << path.GetKeyB()
      << ", \"turn\": " << path.GetKeyTurn() << ", \"C\": " << path.GetKeyC()
      << "}, \"position\": [";
  for (int f = 0; f < settings.Frames; ++f)
  {
    const Pose pose = path.At(f);
    out << (f ? "," : "") << "[" << Number(pose.Position.X) << "," << Number(pose.Position.Y) << ","
        << Number(pose.Position.Z) << "]";
  }
  out << "], \"focal_point\": [";
  for (int f = 0; f < settings.Frames; ++f)
  {
    const Pose pose = path.At(f);
    out << (f ? "," : "") << "[" << Number(pose.FocalPoint.X) << "," << Number(pose.FocalPoint.Y)
        << "," << Number(pose.FocalPoint.Z) << "]";
  }
  out << "]},\n  \"policies\": [\n";
  for (size_t p = 0; p < runs.size(); ++p)
  {
    const PolicyRun& run = runs[p];
    const Statistics& s = run.Stats;
    out << "    {\"name\": " << Quoted(run.Name) << ", \"label\": " << Quoted(run.Label)
        << ", \"hysteresis\": " << Number(run.Hysteresis) << ", \"seconds\": " << Number(run.Seconds)
        << ", \"vertex_buffer_builds\": " << run.VertexBufferBuilds
        << ", \"lod_estimated_render_time\": [";
    for (size_t level = 0; level < run.LODEstimated.size(); ++level)
    {
      out << (level ? ", " : "") << Number(run.LODEstimated[level]);
    }
    out << "], \"lod_allocated_render_time\": " << Number(run.LODAllocated)
        << ",\n     \"statistics\": {" << PolicyStatisticsJsonFields(s)
        << ", \"min\": " << Number(s.Min) << ", \"cv\": " << Number(s.CV)
        << ", \"prediction_error_max\": " << Number(s.PredictionErrorMax)
        << ", \"renderer_vs_wall\": " << Number(s.RendererVsWall)
        << ", \"optimizer_mean\": " << Number(s.OptimizerMean)
        << ", \"optimizer_max\": " << Number(s.OptimizerMax)
        << ", \"iterations_mean\": " << Number(s.IterationsMean)
        << ", \"frames_with_reduced_lod\": " << s.ReducedFrames
        << ", \"heavy_frames\": " << s.HeavyFrames << ", \"heavy_mean\": " << Number(s.HeavyMean)
        << ", \"heavy_cv\": " << Number(s.HeavyCV)
        << ", \"heavy_share_within_110_percent\": " << Number(s.HeavyShareWithin)
        << ", \"heavy_psnr_median\": " << Number(s.HeavyPSNRMedian)
        << ", \"changed_mean\": " << Number(s.ChangedMean) << "},\n";
    const auto& f = run.Frames;
    out << "     \"frames\": {\n";
    out << "      " << PolicyFramesJsonFields(f, ",\n      ") << ",\n";
    out << "      \"renderer_measured\": "
        << Array(f, [](const FrameRecord& r) { return r.RendererMeasured; }) << ",\n";
    out << "      \"fixed\": " << Array(f, [](const FrameRecord& r) { return r.Fixed; }) << ",\n";
    out << "      \"changed\": " << Array(f, [](const FrameRecord& r) { return r.Changed; })
        << ",\n";
    out << "      \"margin\": " << Array(f, [](const FrameRecord& r) { return r.Margin; }) << ",\n";
    out << "      \"optimizer\": " << Array(f, [](const FrameRecord& r) { return r.Optimizer; })
        << ",\n";
    out << "      \"heuristics\": " << Array(f, [](const FrameRecord& r) { return r.Heuristics; })
        << ",\n";
    out << "      \"iterations\": "
        << Array(f, [](const FrameRecord& r) { return static_cast<double>(r.Iterations); }) << ",\n";
    out << "      \"converged\": "
        << Array(f, [](const FrameRecord& r) { return r.Converged ? 1.0 : 0.0; }) << ",\n";
    out << "      \"visible_triangles\": "
        << Array(f, [](const FrameRecord& r) { return r.VisibleTriangles; }, 10) << ",\n";
    out << "      \"culled\": " << Array(f, [](const FrameRecord& r) { return r.Culled; });
    if (run.Policy->Kind == PolicyKind::LODProp3D)
    {
      out << ",\n      \"lod_counts\": [";
      for (size_t level = 0; level < 6; ++level)
      {
        out << (level ? ", " : "")
            << Array(f, [level](const FrameRecord& r) { return r.LODCounts[level]; });
      }
      out << "]";
    }
    out << "\n     }}" << (p + 1 < runs.size() ? "," : "") << "\n";
  }
  out << "  ],\n  \"goals\": " << GoalsJson(goals) << "\n}\n";
  if (!out)
  {
    throw std::runtime_error("error writing " + settings.Json);
  }
}

void Plot(const Settings& settings)
{
  RunPlotScript(TIMECRITICAL_WALKTHROUGH_PLOT_SCRIPT, settings.Json,
    (std::filesystem::path(settings.Output) / "walkthrough.png").string());
}
}

int main(int argc, char* argv[])
{
  try
  {
    const Settings settings = ParseArguments(argc, argv);
    if (!settings.SceneFile.empty())
    {
      const CowTOM object = MakeCowTOM(settings.DataDirectory);
      const Scene scene =
        PlaceObjects(settings.Objects, settings.Seed, object.TOM, object.Triangles);
      WriteW1SceneJson(settings.SceneFile, object, scene, W1CameraPath(scene, settings.Frames),
        settings.Frames, settings.Seed);
      std::cerr << "scene: " << settings.SceneFile << "\n";
      return 0;
    }
    if (!std::getenv("DISPLAY"))
    {
      std::cerr << "WalkthroughBenchmark needs an X display (VTK here is an X build): run it "
                   "under xvfb-run -a -s \"-screen 0 1024x768x24\" or scripts/run-walkthrough.sh\n";
      return 2;
    }
    std::filesystem::create_directories(settings.Output);
    double load[2] = { LoadAverages()[0], NaN };

    std::cerr << "building the object's TOM and LODs...\n";
    const ObjectMesh object = MakeObject(settings);
    const Scene scene = PlaceObjects(settings.Objects, settings.Seed, object.TOM, object.Triangles);
    const W1CameraPath path(scene, settings.Frames);
    std::cerr << "scene: " << scene.Objects.size() << " objects x " << object.Triangles
              << " triangles = " << scene.Triangles << " triangles (" << object.Source << ")\n";

    Walkthrough walk(settings, object, scene, path);
    walk.Setup();
    std::cerr << "calibrating the cost model...\n";
    walk.Calibrate();
    std::cerr << "  frame " << 1000.0 * walk.Coefficients[0] << " ms, draw call "
              << 1000.0 * walk.Coefficients[1] << " ms, triangle " << 1e9 * walk.Coefficients[2]
              << " ns, pixel " << 1e9 * walk.Coefficients[3] << " ns, margin "
              << 1000.0 * walk.Coefficients[4] << " ms (" << walk.CalibrationSeconds << " s)\n";

    std::vector<PolicyRun> runs;
    for (const PolicyInfo* policy : settings.Policies)
    {
      std::cerr << "policy " << policy->Name << ": " << settings.Frames << " frames\n";
      runs.push_back(walk.Run(*policy));
      if (policy->Kind == PolicyKind::TimeCritical)
      {
        walk.WriteResolutionMaps();
      }
    }
    // The same policies with hysteresis, in the same run (popping with and without).
    walk.Hysteresis = settings.Hysteresis;
    for (const PolicyInfo* policy : settings.Policies)
    {
      if (settings.Hysteresis > 0.0 && policy->RendererPolicy >= 0 &&
        policy->Kind != PolicyKind::None)
      {
        std::cerr << "policy " << policy->Name << " with hysteresis " << settings.Hysteresis
                  << ": " << settings.Frames << " frames\n";
        runs.push_back(walk.Run(*policy));
      }
    }
    std::cerr << "noise floor: one frame rendered again and again...\n";
    walk.MeasureNoiseFloor();
    load[1] = LoadAverages()[0];

    const std::vector<Goal> goals = EvaluateGoals(runs, settings.Target, walk.Noise);
    std::printf("WalkthroughBenchmark: %zu objects, %lld triangles, %d frames, target %.0f ms%s\n",
      scene.Objects.size(), static_cast<long long>(scene.Triangles), settings.Frames,
      1000.0 * settings.Target, object.Substitute ? " (SUBSTITUTE MESH: cow.obj not found)" : "");
    std::printf("reference images: front buffer %s back buffer, %s run to run; "
                "vtkLODProp3D at full level vs reference: %s dB\n",
      walk.Check.FrontEqualsBack ? "equals" : "DIFFERS FROM",
      walk.Check.Deterministic ? "identical" : "NOT identical",
      Number(walk.Check.LODFullVsReferencePSNR, 4).c_str());
    for (const auto& run : runs)
    {
      if (run.Policy->Kind == PolicyKind::LODProp3D)
      {
        const Statistics& s = run.Stats;
        std::printf("vtkLODProp3D: props drawn per level (100/50/25/12/6/3%%) over all frames: "
                    "%lld/%lld/%lld/%lld/%lld/%lld; frames with a reduced level: %d of %d\n",
          s.LODPropFrames[0], s.LODPropFrames[1], s.LODPropFrames[2], s.LODPropFrames[3],
          s.LODPropFrames[4], s.LODPropFrames[5], s.ReducedFrames, s.Frames);
        std::printf("vtkLODProp3D: mean estimated render time per level (ms): ");
        for (double t : run.LODEstimated)
        {
          std::printf("%.4f ", 1000.0 * t);
        }
        std::printf("; mean time allocated to a drawn prop: %.4f ms\n", 1000.0 * run.LODAllocated);
      }
      if (run.VertexBufferBuilds > 0)
      {
        std::printf("note: %s: the multiresolution mapper rebuilt its vertex buffers %lld times "
                    "during the timed frames\n",
          run.Name.c_str(), run.VertexBufferBuilds);
      }
      if (std::isfinite(run.Stats.RendererVsWall) &&
        std::abs(run.Stats.RendererVsWall) > 0.05)
      {
        std::printf("note: %s: the renderer's measured frame time differs from the wall clock "
                    "by %.1f%% on average\n",
          run.Name.c_str(), 100.0 * run.Stats.RendererVsWall);
      }
    }
    PrintTable(runs, goals, settings.Target);
    std::printf("\nnoise floor (the same frame, %lld triangles, rendered %d times): median %.1f ms, "
                "max %.1f ms, CV %.1f%%, %.0f%% of the frames more than 10%% over the median\n",
      static_cast<long long>(walk.Noise.Triangles), walk.Noise.Frames, 1000.0 * walk.Noise.Median,
      1000.0 * walk.Noise.Max, 100.0 * walk.Noise.CV, 100.0 * walk.Noise.ShareOver10Percent);
    WriteJson(settings, object, scene, path, walk, runs, goals, load);
    std::printf("\nJSON: %s, images in %s\n", settings.Json.c_str(), settings.Output.c_str());
    std::fflush(stdout);
    if (settings.Plot)
    {
      Plot(settings);
    }
    return 0;
  }
  catch (const std::exception& error)
  {
    std::cerr << "WalkthroughBenchmark: error: " << error.what() << "\n";
    return 1;
  }
}
