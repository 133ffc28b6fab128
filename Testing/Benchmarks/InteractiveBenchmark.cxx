// SPDX-License-Identifier: BSD-3-Clause
/**
 * InteractiveBenchmark: vtkTimeCriticalRenderer driven the way a user drives
 * it, through a real vtkRenderWindowInteractor with
 * vtkInteractorStyleTrackballCamera and UseDesiredUpdateRate on.
 *
 * Scene: W1's cows (one TOM, transformed copies on a jittered grid), 324 by
 * default (1.9 million triangles), one vtkMultiresolutionPolyDataMapper, a
 * 512x512 window, automatic calibration (nothing set by hand). Script: start
 * up (the interactor's Initialize() and the first render: a still frame),
 * then drags of scripted mouse events (press, moves, release; rotate, pan,
 * zoom in turn) with still frames between them, as when the user lets go.
 *
 * Per frame: wall clock around the event that rendered it (the style's work,
 * the render and the swap; glFinish after), the renderer's own measurement,
 * its prediction, target and triangles. Reported: the cold start (first
 * render, of which calibration), interactive frames against the target and
 * the stalls (frames over twice the target), the still frames' predictions,
 * and whether each image at rest equals full resolution (after the session,
 * a plain vtkRenderer drawing every object in full with each rest camera,
 * compared pixel for pixel).
 *
 * Exit status 1 on errors, on a hidden calibration render after the
 * start-up frame, and on an image at rest that differs from full
 * resolution; timings are reported, not failed (they depend on the machine).
 *
 *   InteractiveBenchmark [--quick] [--objects N] [--rate FPS] [--drags N]
 *                        [--moves N] [--output DIR] [--json FILE] [--data DIR]
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
#include "PolicySelection.h"
#include "MeshIO.h"
#include "W1CameraPath.h"
#include "W1Scene.h"
#include "W1SceneSpecification.h"
#include "vtkMultiresolutionPolyDataMapper.h"
#include "vtkTOMBuilder.h"
#include "vtkTOMFieldData.h"
#include "vtkTimeCriticalRenderer.h"

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTransform.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
using namespace timecritical::benchmark;

struct Settings
{
  bool Quick = false;
  int Objects = 324;
  double Rate = 15.0; ///< the interactor's DesiredUpdateRate (VTK's default)
  int Drags = 6;
  int Moves = 40;
  bool RestCheck = true;
  unsigned Seed = W1SceneSpecification::Get().DefaultSeed;

  std::string Output = "interactive-output";
  std::string Json;
  std::string DataDirectory = TIMECRITICAL_SHARED_DATA_DIR;
};

void PrintUsage()
{
  std::cout
    << "InteractiveBenchmark: vtkTimeCriticalRenderer under a vtkRenderWindowInteractor\n"
       "  --objects N   cow replicas (default 324: 1.9M triangles)\n"
       "  --rate FPS    the interactor's DesiredUpdateRate (default 15: target 67 ms)\n"
       "  --drags N     drags (rotate, pan, zoom in turn; default 6)\n"
       "  --moves N     mouse moves per drag (default 40)\n"
       "  --no-rest-check  do not compare the images at rest with full resolution\n"
       "  --quick       36 objects, 2 drags of 10 moves (smoke test)\n"
       "  --output DIR  output folder (default ./interactive-output)\n"
       "  --json FILE   JSON file (default DIR/interactive.json)\n"
       "  --data DIR    folder with cow.obj (default " TIMECRITICAL_SHARED_DATA_DIR ")\n"
       "  --seed N      seed of the object placement (default 20001)\n";
}

Settings ParseArguments(int argc, char* argv[])
{
  Settings settings;
  bool help = false, objectsSet = false, dragsSet = false, movesSet = false;
  BenchmarkArguments arguments(argc, argv);
  arguments.AddFlag("--help", help);
  arguments.AddFlag("-h", help);
  arguments.AddFlag("--quick", settings.Quick);
  arguments.AddFlag("--no-rest-check", settings.RestCheck, false);
  arguments.AddInteger("--objects", settings.Objects, 1, 1000000, &objectsSet);
  arguments.AddInteger("--drags", settings.Drags, 1, 1000000, &dragsSet);
  arguments.AddInteger("--moves", settings.Moves, 1, 1000000, &movesSet);
  arguments.AddUnsigned("--seed", settings.Seed);
  arguments.AddNumber("--rate", settings.Rate, [](double x) { return x > 0.01; });
  arguments.AddText("--output", settings.Output);
  arguments.AddText("--json", settings.Json);
  arguments.AddText("--data", settings.DataDirectory);
  arguments.Parse();
  if (help)
  {
    PrintUsage();
    std::exit(0);
  }
  if (settings.Quick)
  {
    settings.Objects = objectsSet ? settings.Objects : 36;
    settings.Drags = dragsSet ? settings.Drags : 2;
    settings.Moves = movesSet ? settings.Moves : 10;
  }
  if (settings.Json.empty())
  {
    settings.Json = (std::filesystem::path(settings.Output) / "interactive.json").string();
  }
  return settings;
}

struct FrameRecord
{
  int Drag = -1;         ///< -1: start-up
  bool Still = false;    ///< drawn at full resolution (a still frame)
  double Wall = NaN;     ///< wall clock around the event (+ glFinish)
  double Measured = NaN; ///< the renderer's StartEvent-to-EndEvent time
  double Predicted = NaN;
  double Target = NaN; ///< planned target (NaN for a still frame)
  double Triangles = 0.0;
  int CalibrationRenders = 0; ///< hidden calibration renders so far
  double IndexUpdate = NaN;   ///< the mapper's CPU seconds updating index data
  double IndexBytes = 0.0;    ///< bytes of index data uploaded
  double Padding = 0.0;       ///< degenerate primitives drawn (slot slack)
  double Relayouts = 0.0;     ///< index buffer layouts so far
  double Heuristics = NaN, Optimizer = NaN; ///< the renderer's CPU seconds
};

struct RestCheck
{
  int Drag = 0;
  bool Identical = false;
  double PSNR = NaN;
};

/// Counts the render window's renders (each event may render once or not at all).
struct RenderCounter
{
  long Count = 0;
  static void Callback(vtkObject*, unsigned long, void* data, void*)
  {
    ++static_cast<RenderCounter*>(data)->Count;
  }
};

class Session
{
public:
  explicit Session(const Settings& settings)
    : Options(settings)
  {
  }

  void Setup();
  void StartUp();
  void Drag(int index);
  /// Keeps the image at rest and its camera, for CheckRest().
  void KeepRest(int index);
  void Repaint(int index) { this->Record(index, this->TimedRepaint()); }
  void CheckRest();

  std::vector<FrameRecord> Frames;
  std::vector<RestCheck> Rest;
  double StartUpSeconds = NaN;
  double CalibrationSeconds = NaN;
  int CalibrationRendersAtStartUp = 0;
  double Coefficients[4] = { NaN, NaN, NaN, NaN };
  vtkIdType SceneTriangles = 0;
  std::string Source;
  bool Substitute = false;

private:
  void Record(int drag, double wall);
  double TimedEvent(unsigned long event, int x, int y);
  double TimedRepaint();

  const Settings& Options;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderWindowInteractor> Interactor;
  vtkNew<vtkInteractorStyleTrackballCamera> Style;
  vtkNew<vtkTimeCriticalRenderer> Renderer;
  vtkNew<vtkMultiresolutionPolyDataMapper> Mapper;
  vtkNew<vtkActor> Actor;
  vtkNew<vtkCallbackCommand> Counting;
  RenderCounter Renders;
  struct RestView
  {
    int Drag = 0;
    Image Pixels;
    vtkSmartPointer<vtkCamera> Camera = vtkSmartPointer<vtkCamera>::New();
  };
  std::vector<RestView> RestViews;
};

void Session::Setup()
{
  const CowTOM object = MakeCowTOM(this->Options.DataDirectory);
  this->Source = object.Source;
  this->Substitute = object.Substitute;
  const Scene scene = PlaceObjects(this->Options.Objects, this->Options.Seed, object.TOM, object.Triangles);
  this->SceneTriangles = scene.Triangles;
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(static_cast<unsigned>(scene.Objects.size()));
  for (size_t i = 0; i < scene.Objects.size(); ++i)
  {
    blocks->SetBlock(static_cast<unsigned>(i), MakeCopy(object.TOM, scene.Objects[i]));
  }
  this->Mapper->SetInputDataObject(blocks);
  this->Actor->SetMapper(this->Mapper);
  this->Renderer->AddActor(this->Actor);
  SetBackground(this->Renderer);
  // What a user writes: the interactors' rates drive the target.
  this->Renderer->UseDesiredUpdateRateOn();

  this->Window->SetSize(WindowSize, WindowSize);
  this->Window->SetMultiSamples(0);
  this->Window->SetWindowName("InteractiveBenchmark");
  this->Window->AddRenderer(this->Renderer);
  this->Interactor->SetRenderWindow(this->Window);
  this->Interactor->SetInteractorStyle(this->Style);
  this->Interactor->SetDesiredUpdateRate(this->Options.Rate);

  // The herd from above one corner, as in W1's first frame.
  vtkCamera* camera = this->Renderer->GetActiveCamera();
  camera->SetViewAngle(ViewAngle);
  const double e = scene.Extent;
  camera->SetFocalPoint(0.5 * e, 0.0, 0.5 * e);
  camera->SetPosition(-0.25 * e, 0.45 * e, -0.25 * e);
  camera->SetViewUp(0.0, 1.0, 0.0);
  this->Renderer->ResetCameraClippingRange();

  this->Counting->SetCallback(&RenderCounter::Callback);
  this->Counting->SetClientData(&this->Renders);
  this->Window->AddObserver(vtkCommand::EndEvent, this->Counting);
}

void Session::Record(int drag, double wall)
{
  FrameRecord record;
  record.Drag = drag;
  record.Still = this->Renderer->GetLastRenderWasStill();
  record.Wall = wall;
  record.Measured = this->Renderer->GetMeasuredFrameTime();
  record.Predicted = this->Renderer->GetPredictedFrameTime();
  const double target = this->Renderer->GetLastTargetFrameTime();
  record.Target = std::isfinite(target) ? target : NaN;
  record.Triangles = static_cast<double>(this->Renderer->GetTrianglesDrawn());
  record.CalibrationRenders = this->Renderer->GetCalibrationRenders();
  record.IndexUpdate = this->Mapper->GetIndexUpdateTime();
  record.IndexBytes = static_cast<double>(this->Mapper->GetIndexBytesUploaded());
  record.Padding = static_cast<double>(this->Mapper->GetNumberOfPaddingPrimitives());
  record.Relayouts = static_cast<double>(this->Mapper->GetIndexBufferRelayoutCount());
  record.Heuristics = this->Renderer->GetHeuristicsTime();
  record.Optimizer = this->Renderer->GetOptimizationTime();
  this->Frames.push_back(record);
}

void Session::StartUp()
{
  // The cold start: what the user waits for before the first image.
  const Clock::time_point start = Clock::now();
  this->Interactor->Initialize();
  const long before = this->Renders.Count;
  this->Window->Render();
  this->Window->WaitForCompletion();
  this->StartUpSeconds = Seconds(start, Clock::now());
  if (this->Renders.Count == before)
  {
    throw std::runtime_error("the start-up render did not render");
  }
  this->CalibrationSeconds = this->Renderer->GetCalibrationTime();
  this->CalibrationRendersAtStartUp = this->Renderer->GetCalibrationRenders();
  this->Coefficients[0] = this->Renderer->GetFrameCost();
  this->Coefficients[1] = this->Renderer->GetDrawCallCost();
  this->Coefficients[2] = this->Renderer->GetTriangleCost();
  this->Coefficients[3] = this->Renderer->GetPixelCost();
  this->Record(-1, this->StartUpSeconds);
  // A repaint a moment later (an expose): a second still frame.
  this->Record(-1, this->TimedRepaint());
}

double Session::TimedRepaint()
{
  const Clock::time_point start = Clock::now();
  this->Interactor->Render();
  this->Window->WaitForCompletion();
  return Seconds(start, Clock::now());
}

double Session::TimedEvent(unsigned long event, int x, int y)
{
  this->Interactor->SetEventInformation(x, y, 0, 0);
  const Clock::time_point start = Clock::now();
  this->Interactor->InvokeEvent(event, nullptr);
  this->Window->WaitForCompletion();
  return Seconds(start, Clock::now());
}

void Session::Drag(int index)
{
  // Rotate, pan, zoom in turn, each a straight stroke from near the centre.
  static const unsigned long Press[] = { vtkCommand::LeftButtonPressEvent,
    vtkCommand::MiddleButtonPressEvent, vtkCommand::RightButtonPressEvent };
  static const unsigned long Release[] = { vtkCommand::LeftButtonReleaseEvent,
    vtkCommand::MiddleButtonReleaseEvent, vtkCommand::RightButtonReleaseEvent };
  const int kind = index % 3;
  const int moves = this->Options.Moves;
  // Zoom strokes alternate in and out so that the view stays on the herd.
  const double direction = (index / 3) % 2 == 0 ? 1.0 : -1.0;
  const double dx = kind == 2 ? 0.0 : direction * 120.0 / moves;
  const double dy = kind == 0 ? 40.0 / moves : (kind == 2 ? direction * 60.0 / moves : 0.0);
  double x = WindowSize / 2.0, y = WindowSize / 2.0;
  long before = this->Renders.Count;
  double t = this->TimedEvent(Press[kind], static_cast<int>(x), static_cast<int>(y));
  if (this->Renders.Count != before)
  {
    this->Record(index, t);
  }
  for (int m = 0; m < moves; ++m)
  {
    x += dx;
    y += dy;
    before = this->Renders.Count;
    t = this->TimedEvent(vtkCommand::MouseMoveEvent, static_cast<int>(std::lround(x)),
      static_cast<int>(std::lround(y)));
    if (this->Renders.Count != before)
    {
      this->Record(index, t);
    }
  }
  // Letting go: the style drops the rate to the still rate and renders.
  before = this->Renders.Count;
  t = this->TimedEvent(Release[kind], static_cast<int>(std::lround(x)), static_cast<int>(std::lround(y)));
  if (this->Renders.Count != before)
  {
    this->Record(index, t);
  }
}

void Session::KeepRest(int index)
{
  if (!this->Renderer->GetLastRenderWasStill())
  {
    throw std::runtime_error("the frame after a release was not a still frame");
  }
  RestView view;
  view.Drag = index;
  view.Pixels = Capture(this->Window, true);
  view.Camera->DeepCopy(this->Renderer->GetActiveCamera());
  this->RestViews.push_back(std::move(view));
}

void Session::CheckRest()
{
  // After the session (rendering something else in between would disturb the
  // frame times): full resolution drawn independently of the time-critical
  // renderer, a plain vtkRenderer with the same actor and each rest camera,
  // every object in full, compared pixel for pixel.
  vtkNew<vtkRenderer> plain;
  plain->AddActor(this->Actor);
  SetBackground(plain);
  this->Window->RemoveRenderer(this->Renderer);
  this->Window->AddRenderer(plain);
  this->Mapper->SetResolution(1.0);
  for (RestView& view : this->RestViews)
  {
    plain->GetActiveCamera()->DeepCopy(view.Camera);
    this->Window->Render();
    this->Window->WaitForCompletion();
    Image full = Capture(this->Window, true);
    const Comparison c = Compare(view.Pixels, full);
    RestCheck check;
    check.Drag = view.Drag;
    check.Identical = c.Identical;
    check.PSNR = c.PSNR;
    this->Rest.push_back(check);
    if (view.Drag == 0 || !c.Identical)
    {
      const std::filesystem::path folder(this->Options.Output);
      WritePNG(view.Pixels, folder / ("rest_" + std::to_string(view.Drag) + ".png"));
      WritePNG(full, folder / ("rest_" + std::to_string(view.Drag) + "_full.png"));
    }
  }
  this->Window->RemoveRenderer(plain);
  this->Window->AddRenderer(this->Renderer);
}

struct Summary
{
  int Interactive = 0, Still = 0;
  double Mean = NaN, Median = NaN, Max = NaN, CV = NaN;
  double ShareWithin = NaN; ///< interactive frames <= 1.1 target
  int Stalls = 0;           ///< interactive frames > 2 target
  double FirstDragMax = NaN;
  double PredictionError = NaN; ///< interactive, mean |p - m| / m (renderer's measurement)
  double StillPredictionError = NaN;
  double StillMean = NaN;
  int HiddenRendersAfterStartUp = 0;
  int RestIdentical = 0;
};

Summary Summarize(const Session& session)
{
  Summary s;
  std::vector<double> times, errors, stillErrors, still, firstDrag;
  for (const FrameRecord& f : session.Frames)
  {
    if (f.Still)
    {
      ++s.Still;
      still.push_back(f.Wall);
      if (f.Measured > 0.0 && std::isfinite(f.Predicted))
      {
        stillErrors.push_back(std::abs(f.Predicted - f.Measured) / f.Measured);
      }
      continue;
    }
    ++s.Interactive;
    times.push_back(f.Wall);
    s.Stalls += f.Wall > 2.0 * f.Target ? 1 : 0;
    if (f.Drag == 0)
    {
      firstDrag.push_back(f.Wall);
    }
    if (f.Measured > 0.0 && std::isfinite(f.Predicted))
    {
      errors.push_back(std::abs(f.Predicted - f.Measured) / f.Measured);
    }
  }
  int within = 0;
  for (const FrameRecord& f : session.Frames)
  {
    within += !f.Still && f.Wall <= 1.1 * f.Target ? 1 : 0;
  }
  if (!times.empty())
  {
    s.Mean = Mean(times);
    s.Median = Median(times);
    s.Max = *std::max_element(times.begin(), times.end());
    double variance = 0.0;
    for (double t : times)
    {
      variance += (t - s.Mean) * (t - s.Mean);
    }
    s.CV = std::sqrt(variance / static_cast<double>(times.size())) / s.Mean;
    s.ShareWithin = static_cast<double>(within) / static_cast<double>(times.size());
  }
  s.FirstDragMax = firstDrag.empty() ? NaN : *std::max_element(firstDrag.begin(), firstDrag.end());
  s.PredictionError = Mean(errors);
  s.StillPredictionError = Mean(stillErrors);
  s.StillMean = Mean(still);
  s.HiddenRendersAfterStartUp =
    session.Frames.empty() ? 0 : session.Frames.back().CalibrationRenders - session.CalibrationRendersAtStartUp;
  for (const RestCheck& r : session.Rest)
  {
    s.RestIdentical += r.Identical ? 1 : 0;
  }
  return s;
}

void WriteJson(const Settings& settings, const Session& session, const Summary& s,
  const double load[2])
{
  std::ofstream out(settings.Json);
  if (!out)
  {
    throw std::runtime_error("cannot write " + settings.Json);
  }
  out << "{\n  \"benchmark\": \"InteractiveBenchmark\",\n";
  out << "  \"settings\": {\"objects\": " << settings.Objects << ", \"triangles\": "
      << session.SceneTriangles << ", \"mesh\": " << Quoted(session.Source)
      << ", \"substitute\": " << (session.Substitute ? "true" : "false")
      << ", \"desired_update_rate\": " << Number(settings.Rate) << ", \"drags\": "
      << settings.Drags << ", \"moves\": " << settings.Moves << ", \"window\": [" << WindowSize
      << ", " << WindowSize << "], \"load_average_start\": " << Number(load[0], 3)
      << ", \"load_average_end\": " << Number(load[1], 3) << "},\n";
  out << "  \"start_up\": {\"seconds\": " << Number(session.StartUpSeconds)
      << ", \"calibration_seconds\": " << Number(session.CalibrationSeconds)
      << ", \"calibration_renders\": " << session.CalibrationRendersAtStartUp
      << ", \"frame\": " << Number(session.Coefficients[0]) << ", \"draw_call\": "
      << Number(session.Coefficients[1]) << ", \"triangle\": " << Number(session.Coefficients[2])
      << ", \"pixel\": " << Number(session.Coefficients[3]) << "},\n";
  out << "  \"summary\": {\"interactive_frames\": " << s.Interactive << ", \"still_frames\": "
      << s.Still << ", \"mean\": " << Number(s.Mean) << ", \"median\": " << Number(s.Median)
      << ", \"max\": " << Number(s.Max) << ", \"cv\": " << Number(s.CV)
      << ", \"share_within_110_percent\": " << Number(s.ShareWithin) << ", \"stalls\": "
      << s.Stalls << ", \"first_drag_max\": " << Number(s.FirstDragMax)
      << ", \"prediction_error\": " << Number(s.PredictionError)
      << ", \"still_prediction_error\": " << Number(s.StillPredictionError)
      << ", \"still_mean\": " << Number(s.StillMean)
      << ", \"hidden_renders_after_start_up\": " << s.HiddenRendersAfterStartUp
      << ", \"rest_identical\": " << s.RestIdentical << ", \"rest_checks\": "
      << session.Rest.size() << "},\n";
  out << "  \"rest\": [";
  for (size_t i = 0; i < session.Rest.size(); ++i)
  {
    out << (i ? ", " : "") << "{\"drag\": " << session.Rest[i].Drag << ", \"identical\": "
        << (session.Rest[i].Identical ? "true" : "false") << ", \"psnr\": "
        << Number(session.Rest[i].PSNR) << "}";
  }
  out << "],\n  \"frames\": {\n";
  const auto& f = session.Frames;
  out << "    \"drag\": " << Array(f, [](const FrameRecord& r) { return r.Drag; }) << ",\n";
  out << "    \"still\": " << Array(f, [](const FrameRecord& r) { return r.Still ? 1.0 : 0.0; })
      << ",\n";
  out << "    \"wall\": " << Array(f, [](const FrameRecord& r) { return r.Wall; }) << ",\n";
  out << "    \"measured\": " << Array(f, [](const FrameRecord& r) { return r.Measured; }) << ",\n";
  out << "    \"predicted\": " << Array(f, [](const FrameRecord& r) { return r.Predicted; })
      << ",\n";
  out << "    \"target\": " << Array(f, [](const FrameRecord& r) { return r.Target; }) << ",\n";
  out << "    \"triangles\": " << Array(f, [](const FrameRecord& r) { return r.Triangles; }, 10)
      << ",\n";
  out << "    \"index_update\": " << Array(f, [](const FrameRecord& r) { return r.IndexUpdate; })
      << ",\n";
  out << "    \"index_bytes\": " << Array(f, [](const FrameRecord& r) { return r.IndexBytes; }, 12)
      << ",\n";
  out << "    \"padding\": " << Array(f, [](const FrameRecord& r) { return r.Padding; }, 12)
      << ",\n";
  out << "    \"relayouts\": " << Array(f, [](const FrameRecord& r) { return r.Relayouts; })
      << ",\n";
  out << "    \"heuristics\": " << Array(f, [](const FrameRecord& r) { return r.Heuristics; })
      << ",\n";
  out << "    \"optimizer\": " << Array(f, [](const FrameRecord& r) { return r.Optimizer; })
      << ",\n";
  out << "    \"calibration_renders\": "
      << Array(f, [](const FrameRecord& r) { return r.CalibrationRenders; }) << "\n";
  out << "  }\n}\n";
  if (!out)
  {
    throw std::runtime_error("error writing " + settings.Json);
  }
}
}

int main(int argc, char* argv[])
{
  try
  {
    const Settings settings = ParseArguments(argc, argv);
    if (!std::getenv("DISPLAY"))
    {
      std::cerr << "InteractiveBenchmark needs an X display (a real interactor): run it under "
                   "xvfb-run -a -s \"-screen 0 1024x768x24\"\n";
      return 2;
    }
    std::filesystem::create_directories(settings.Output);
    double load[2] = { LoadAverages()[0], NaN };
    Session session(settings);
    std::cerr << "building the scene...\n";
    session.Setup();
    std::cerr << "start-up render...\n";
    session.StartUp();
    for (int d = 0; d < settings.Drags; ++d)
    {
      session.Drag(d);
      if (settings.RestCheck)
      {
        session.KeepRest(d);
      }
      session.Repaint(d); // a still frame more, as an expose at rest gives
      std::cerr << "  drag " << d + 1 << "/" << settings.Drags << " done\n";
    }
    session.CheckRest();
    load[1] = LoadAverages()[0];
    const Summary s = Summarize(session);
    const double target = 1.0 / settings.Rate;
    std::printf("InteractiveBenchmark: %d objects, %lld triangles%s, interactor rate %.1f/s "
                "(target %.1f ms), %d drags of %d moves\n",
      settings.Objects, static_cast<long long>(session.SceneTriangles),
      session.Substitute ? " (SUBSTITUTE MESH)" : "", settings.Rate, 1000.0 * target,
      settings.Drags, settings.Moves);
    std::printf("start-up (Initialize + first render, a still frame): %.2f s, of which "
                "calibration %.2f s in %d hidden renders\n",
      session.StartUpSeconds, session.CalibrationSeconds, session.CalibrationRendersAtStartUp);
    std::printf("interactive frames: %d, mean %.1f ms, median %.1f, max %.1f, CV %.1f%%, "
                "%.1f%% within 110%% of the target\n",
      s.Interactive, 1000.0 * s.Mean, 1000.0 * s.Median, 1000.0 * s.Max, 100.0 * s.CV,
      100.0 * s.ShareWithin);
    std::printf("stalls (interactive frames over 2x the target): %d; first drag's slowest frame "
                "%.1f ms\n",
      s.Stalls, 1000.0 * s.FirstDragMax);
    std::printf("prediction error: interactive %.1f%%, still %.1f%% (still frames: %d, mean "
                "%.2f s)\n",
      100.0 * s.PredictionError, 100.0 * s.StillPredictionError, s.Still, s.StillMean);
    std::printf("hidden calibration renders after the start-up frame: %d\n",
      s.HiddenRendersAfterStartUp);
    std::printf("image at rest equal to full resolution: %d of %zu\n", s.RestIdentical,
      session.Rest.size());
    std::printf("load average: %.2f at the start, %.2f at the end\n", load[0], load[1]);
    WriteJson(settings, session, s, load);
    std::printf("JSON: %s\n", settings.Json.c_str());
    bool failed = false;
    if (s.HiddenRendersAfterStartUp != 0)
    {
      std::cerr << "FAILED: calibration rendered after the start-up frame\n";
      failed = true;
    }
    if (s.RestIdentical != static_cast<int>(session.Rest.size()))
    {
      std::cerr << "FAILED: an image at rest differs from full resolution\n";
      failed = true;
    }
    if (s.Interactive == 0)
    {
      std::cerr << "FAILED: the drags rendered no interactive frame\n";
      failed = true;
    }
    return failed ? 1 : 0;
  }
  catch (const std::exception& error)
  {
    std::cerr << "InteractiveBenchmark: error: " << error.what() << "\n";
    return 1;
  }
}
