// SPDX-License-Identifier: BSD-3-Clause
/**
 * ViewDependentBenchmark (W2): view-dependent refinement of one large object
 * (Xia, El-Sana & Varshney's merge trees) against full resolution and the
 * uniform TOM, on one camera path, and the same object in W1's scene.
 *
 * Object: igea after one Loop subdivision (~1.07M triangles; a generated bumpy
 * sphere when the shared data folder is absent or with --quick), merge tree
 * built once by vtkMergeTreeBuilder and cached as a binary .vtp in the output
 * folder. 512x512, 120 frames: orbit, zoom in close to the face, a scene light
 * that turns while the camera is close, zoom out.
 *
 * Policies, each over the whole path: full resolution (its frames are the
 * PSNR references), view-dependent fixed accuracy (tau = 1 px), the uniform
 * TOM at the triangle count of that tau front in the same frame, and the
 * budget-driven front in vtkTimeCriticalRenderer (active set, 100 ms; its
 * pixel threshold, a floor below which budget fronts refine nothing, is 0 by
 * default so that the budget decides, not tau).
 * OpenMesh's VDPM is listed with the reason it is not run. Per frame:
 * wall-clock frame time around Render() (glFinish, image capture excluded),
 * triangles, refinement time, splits and merges, PSNR (OpenImageIO).
 *
 * --mixed: W1's 529 cows plus the large object in front of them, rendered by
 * vtkTimeCriticalRenderer at 100 ms on W1's camera path, next to the cows
 * alone (W1's TimeCritical policy) on the same path and, when given, the
 * figures of a W1 run (walkthrough.json).
 *
 * Missed goals are reported, not failed: the exit status is nonzero only for
 * errors.
 */
#include "BenchmarkArguments.h"
#include "BenchmarkImages.h"
#include "BenchmarkJson.h"
#include "BenchmarkStatistics.h"
#include "BenchmarkTiming.h"
#include "CameraPose.h"
#include "LoopSubdivision.h"
#include "MachineInfo.h"
#include "MergeTreeAttributes.h"
#include "MeshConversion.h"
#include "PlotScript.h"
#include "PolicyComparison.h"
#include "PolicyGoal.h"
#include "PolicySelection.h"
#include "MeshIO.h"
#include "W1CameraPath.h"
#include "W1Scene.h"
#include "W1SceneSpecification.h"
#include "vtkMergeTreeBuilder.h"
#include "vtkMergeTreeFieldData.h"
#include "vtkMultiresolutionPolyDataMapper.h"
#include "vtkTOMBuilder.h"
#include "vtkTOMFieldData.h"
#include "vtkTimeCriticalRenderer.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkTransform.h>
#include <vtkUnsignedCharArray.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include <cstdint>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>

#ifndef TIMECRITICAL_VIEWDEPENDENT_PLOT_SCRIPT
#define TIMECRITICAL_VIEWDEPENDENT_PLOT_SCRIPT ""
#endif

namespace
{
using namespace timecritical::benchmark;
namespace tt = timecritical::testing;

//------------------------------------------------------------------------------
// Policies

enum class PolicyKind
{
  Full,
  FixedAccuracy,
  Uniform,
  Budget,
  VDPM
};

struct PolicyInfo
{
  PolicyKind Kind;
  const char* Name;  ///< command line and JSON
  const char* Label; ///< table and plot
};

// Run order: 'full' gives the references, 'tau1' the triangle counts 'uniform' matches.
const PolicyInfo AllPolicies[] = {
  { PolicyKind::Full, "full", "full resolution" },
  { PolicyKind::FixedAccuracy, "tau1", "view-dep. tau=1px" },
  { PolicyKind::Uniform, "uniform", "uniform TOM" },
  { PolicyKind::Budget, "budget", "view-dep. budget" },
  { PolicyKind::VDPM, "vdpm", "OpenMesh VDPM" },
};

/// Why OpenMesh's VDPM is not a peer here (checked against Debian 12's libopenmesh-dev 9.0).
const char* const VDPMReason =
  "not run: Debian's OpenMesh 9.0 library ships only VDPM's data structures (VHierarchy, "
  "VFront, VHierarchyWindow, ViewingParameters); the view-dependent refinement loop (qrefine, "
  "force_vsplit, ecol_legal, screen-space tests) lives only in the Qt viewer "
  "OpenMesh-Synthesizer of libopenmesh-apps (with OpenMesh-mkbalancedpm for the hierarchy "
  "file), an interactive GUI with no camera-path scripting, timing or image output, whose "
  "source is not installed; driving VDPM on W2's path would mean writing that loop again, "
  "i.e. a second view-dependent renderer, not measuring OpenMesh's";

/// A policy's Name for its aliases on the command line.
std::string CanonicalPolicyName(const std::string& name)
{
  std::string key = name;
  if (key == "none" || key == "reference" || key == "full-resolution")
  {
    key = "full";
  }
  else if (key == "fixed" || key == "fixed-accuracy" || key == "tau" || key == "vd")
  {
    key = "tau1";
  }
  else if (key == "tom")
  {
    key = "uniform";
  }
  else if (key == "timecritical" || key == "tc")
  {
    key = "budget";
  }
  return key;
}

//------------------------------------------------------------------------------
// Settings

struct Settings
{
  bool Quick = false;
  int Frames = 120;
  double Target = 0.1;
  double Tau = 1.0;
  /// Budget fronts refine nothing below their pixel threshold (a floor): 0
  /// lets the budget alone decide, 1 would cap them at the tau = 1 front.
  double BudgetTau = 0.0;
  double RefinementLimit = -1.0; // < 0: the renderer's default
  int WarmupFrames = 3;
  int LoopLevels = 1;
  bool Rebuild = false;
  /// Shading weight of the merge tree's errors (MergeTreeErrorOptions); < 0: the builder's.
  double ShadingWeight = -1.0;
  bool Mixed = false;
  int MixedObjects = W1SceneSpecification::Get().DefaultObjects;
  int MixedFrames = 0;        ///< 0: Frames
  int MixedReferenceStep = 6; ///< PSNR of the mixed scene on every k-th frame
  bool MixedCows = true;      ///< also the cows alone (W1's TimeCritical) on the mixed path
  unsigned Seed = W1SceneSpecification::Get().DefaultSeed;
  std::string W1Json;
  std::string Output = "viewdependent-output";
  std::string Json; ///< default: Output/viewdependent.json
  std::string DataDirectory = TIMECRITICAL_SHARED_DATA_DIR;
  std::vector<const PolicyInfo*> Policies;
  bool Plot = true;
};

void PrintUsage()
{
  std::cout
    << "ViewDependentBenchmark: the W2 benchmark (view-dependent refinement of one large object)\n"
       "  --frames N         frames of the camera path (default 120, at least 10)\n"
       "  --policies L       comma list of full,tau1,uniform,budget,vdpm (default all; 'full'\n"
       "                     gives the PSNR references, 'uniform' needs 'tau1')\n"
       "  --tau PX           pixel threshold of the fixed-accuracy policy (default 1)\n"
       "  --budget-tau PX    pixel threshold (floor) of the budget fronts (default 0: the\n"
       "                     budget alone decides; with 1 they stop at the tau=1 front)\n"
       "  --refinement-limit S  refinement time limit per frame of the budget policy and\n"
       "                     --mixed (vtkTimeCriticalRenderer::SetRefinementTimeLimit;\n"
       "                     default: the renderer's)\n"
       "  --target S         target frame time of the budget policy and --mixed (default 0.1)\n"
       "  --warmup N         untimed frames at the first camera before each policy (default 3)\n"
       "  --loop N           Loop subdivisions of igea (default 1: ~1.07M triangles)\n"
       "  --rebuild          rebuild the merge tree even when the cached .vtp matches\n"
       "  --shading-weight W recompute the tree's errors with this MergeTreeErrorOptions::\n"
       "                     ShadingWeight (default: the builder's errors, as cached)\n"
       "  --mixed            also W1's cow field with the object in front, vtkTimeCriticalRenderer\n"
       "  --mixed-objects N  cows of --mixed (default 529)\n"
       "  --mixed-frames N   frames of W1's path for --mixed (default: --frames)\n"
       "  --mixed-step K     PSNR of --mixed on every K-th frame (default 6; its references\n"
       "                     cost seconds each)\n"
       "  --no-mixed-cows    --mixed without the cows-alone comparison run\n"
       "  --w1-json FILE     W1's walkthrough.json, whose TimeCritical figures --mixed shows\n"
       "  --quick            generated 20K-triangle object, 24 frames, --mixed with 16 cows\n"
       "  --output DIR       output folder (default ./viewdependent-output)\n"
       "  --json FILE        JSON file (default DIR/viewdependent.json)\n"
       "  --data DIR         folder with igea.ply and cow.obj (default " TIMECRITICAL_SHARED_DATA_DIR
       ")\n"
       "  --no-plot          do not run scripts/plot_viewdependent.py\n";
}

Settings ParseArguments(int argc, char* argv[])
{
  Settings settings;
  bool help = false, framesSet = false, mixedObjectsSet = false, noPlot = false;
  std::string policies;
  const auto atLeast = [](double minimum) { return [minimum](double x) { return x >= minimum; }; };
  BenchmarkArguments arguments(argc, argv);
  arguments.AddFlag("--help", help);
  arguments.AddFlag("-h", help);
  arguments.AddFlag("--quick", settings.Quick);
  arguments.AddInteger("--frames", settings.Frames, 10, 1000000, &framesSet);
  arguments.AddText("--policies", policies);
  arguments.AddNumber("--tau", settings.Tau, atLeast(0.0));
  arguments.AddNumber("--budget-tau", settings.BudgetTau, atLeast(0.0));
  arguments.AddNumber("--refinement-limit", settings.RefinementLimit, atLeast(0.0));
  arguments.AddNumber("--target", settings.Target, atLeast(1e-3));
  arguments.AddInteger("--warmup", settings.WarmupFrames, 0);
  arguments.AddInteger("--loop", settings.LoopLevels, 0);
  arguments.AddFlag("--rebuild", settings.Rebuild);
  arguments.AddNumber("--shading-weight", settings.ShadingWeight, atLeast(0.0));
  arguments.AddFlag("--mixed", settings.Mixed);
  arguments.AddInteger("--mixed-objects", settings.MixedObjects, 1, 1000000, &mixedObjectsSet);
  arguments.AddInteger("--mixed-frames", settings.MixedFrames, 10);
  arguments.AddInteger("--mixed-step", settings.MixedReferenceStep, 1);
  arguments.AddFlag("--no-mixed-cows", settings.MixedCows, false);
  arguments.AddText("--w1-json", settings.W1Json);
  arguments.AddText("--output", settings.Output);
  arguments.AddText("--json", settings.Json);
  arguments.AddText("--data", settings.DataDirectory);
  arguments.AddFlag("--no-plot", noPlot);
  arguments.Parse();
  if (help)
  {
    PrintUsage();
    std::exit(0);
  }
  settings.Plot = !noPlot;
  if (settings.Quick)
  {
    settings.Frames = framesSet ? settings.Frames : 24;
    settings.MixedObjects = mixedObjectsSet ? settings.MixedObjects : 16;
  }
  if (settings.MixedFrames == 0)
  {
    settings.MixedFrames = settings.Frames;
  }
  if (settings.Json.empty())
  {
    settings.Json = (std::filesystem::path(settings.Output) / "viewdependent.json").string();
  }
  settings.Policies = SelectPolicies(AllPolicies, policies, CanonicalPolicyName);
  auto selected = [&settings](const PolicyInfo& policy) {
    return std::find(settings.Policies.begin(), settings.Policies.end(), &policy) !=
      settings.Policies.end();
  };
  if (selected(AllPolicies[2]) && !selected(AllPolicies[1]))
  {
    throw std::runtime_error("policy 'uniform' matches the triangles of 'tau1': select both");
  }
  return settings;
}

//------------------------------------------------------------------------------
// The large object and its merge tree (cached)

struct LargeObject
{
  std::string Name;         ///< short name, used in file names
  std::string Source;       ///< what it was made from
  bool Generated = false;   ///< the shared mesh was not used
  std::string CachePath;
  bool FromCache = false;
  vtkSmartPointer<vtkPolyData> Tree;
  vtkIdType Triangles = 0, Vertices = 0;
  int Levels = 0;
  double BuildSeconds = NaN;   ///< vtkMergeTreeBuilder::GetBuildTime() (of the cached build when read)
  double PrepareSeconds = NaN; ///< load, subdivision and normals before the build
  double CacheSeconds = NaN;   ///< reading (or writing) the cache
  double Center[3] = { 0, 0, 0 };
  double Radius = 1.0; ///< half the bounding box diagonal
  double Bounds[6] = { 0, 0, 0, 0, 0, 0 };
};

/// FNV-1a: a stable cache key (std::hash may differ between builds).
std::string HashHex(const std::string& text)
{
  uint64_t h = 1469598103934665603ULL;
  for (unsigned char c : text)
  {
    h = (h ^ c) * 1099511628211ULL;
  }
  char buffer[24];
  std::snprintf(buffer, sizeof(buffer), "%016llx", static_cast<unsigned long long>(h));
  return buffer;
}

/// A bumpy sphere: curvature everywhere, so that refinement has something to do.
tt::TriangleMesh MakeGeneratedObject(size_t subdivisions)
{
  tt::TriangleMesh mesh = tt::MakeSphere(subdivisions);
  for (size_t i = 0; i < mesh.NumberOfPoints(); ++i)
  {
    double* p = &mesh.Points[3 * i];
    const double bump = 1.0 + 0.06 * std::sin(9.0 * p[0]) * std::sin(7.0 * p[1]) * std::sin(8.0 * p[2]) +
      0.02 * std::sin(31.0 * p[0] + 17.0 * p[2]);
    for (int c = 0; c < 3; ++c)
    {
      p[c] *= bump;
    }
  }
  return mesh;
}

void SetFieldString(vtkPolyData* data, const char* name, const std::string& value)
{
  vtkNew<vtkStringArray> array;
  array->SetName(name);
  array->InsertNextValue(value);
  data->GetFieldData()->AddArray(array);
}

void SetFieldNumber(vtkPolyData* data, const char* name, double value)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->InsertNextValue(value);
  data->GetFieldData()->AddArray(array);
}

std::string FieldString(vtkPolyData* data, const char* name)
{
  auto* array = vtkStringArray::SafeDownCast(data->GetFieldData()->GetAbstractArray(name));
  return array && array->GetNumberOfValues() > 0 ? array->GetValue(0) : std::string();
}

double FieldNumber(vtkPolyData* data, const char* name)
{
  vtkDataArray* array = data->GetFieldData()->GetArray(name);
  return array && array->GetNumberOfTuples() > 0 ? array->GetComponent(0, 0) : NaN;
}

LargeObject MakeLargeObject(const Settings& settings)
{
  LargeObject object;
  const std::filesystem::path igea = std::filesystem::path(settings.DataDirectory) / "igea.ply";
  const bool useIgea = !settings.Quick && std::filesystem::is_regular_file(igea);
  std::string key;
  if (useIgea)
  {
    object.Name = "igea-loop" + std::to_string(settings.LoopLevels);
    object.Source = igea.string() + " + " + std::to_string(settings.LoopLevels) +
      " level(s) of vtkLoopSubdivisionFilter";
    key = "W2 merge tree v1|" + std::filesystem::absolute(igea).string() + "|" +
      std::to_string(std::filesystem::file_size(igea)) + "|" +
      std::to_string(std::filesystem::last_write_time(igea).time_since_epoch().count()) +
      "|loop " + std::to_string(settings.LoopLevels);
  }
  else
  {
    object.Generated = true;
    const size_t subdivisions = settings.Quick ? 5 : 7;
    object.Name = "bumpy-sphere-" + std::to_string(subdivisions);
    object.Source = "generated: bumpy icosphere of " +
      std::to_string(20 * (1u << (2 * subdivisions))) + " triangles (" +
      (settings.Quick ? std::string("--quick") : igea.string() + " not found") + ")";
    if (!settings.Quick)
    {
      std::cerr << "WARNING: " << igea.string()
                << " not found: the large object is a generated bumpy sphere\n";
    }
    key = "W2 merge tree v1|" + object.Source;
  }
  object.CachePath =
    (std::filesystem::path(settings.Output) / (object.Name + "-mergetree-" + HashHex(key) + ".vtp"))
      .string();

  vtkNew<vtkMergeTreeFieldData> check;
  if (!settings.Rebuild && std::filesystem::is_regular_file(object.CachePath))
  {
    const Clock::time_point start = Clock::now();
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(object.CachePath.c_str());
    reader->Update();
    vtkSmartPointer<vtkPolyData> cached = reader->GetOutput();
    if (cached && FieldString(cached, "W2CacheKey") == key && check->Read(cached) &&
      cached->GetPointData()->GetNormals())
    {
      object.Tree = cached;
      object.FromCache = true;
      object.BuildSeconds = FieldNumber(cached, "W2BuildSeconds");
      object.PrepareSeconds = FieldNumber(cached, "W2PrepareSeconds");
      object.CacheSeconds = Seconds(start, Clock::now());
    }
    else
    {
      std::cerr << "cache " << object.CachePath << " does not match: rebuilding\n";
    }
  }
  if (!object.Tree)
  {
    const Clock::time_point start = Clock::now();
    vtkSmartPointer<vtkPolyData> input;
    if (useIgea)
    {
      input = ToPolyData(tt::RemoveUnusedPoints(tt::WeldPoints(tt::LoadMesh(igea.string()))));
      input = LoopSubdivide(input, settings.LoopLevels);
    }
    else
    {
      input = ToPolyData(MakeGeneratedObject(settings.Quick ? 5 : 7));
    }
    input = WithNormals(input);
    object.PrepareSeconds = Seconds(start, Clock::now());
    vtkNew<vtkMergeTreeBuilder> builder;
    builder->SetInputData(input);
    builder->Update();
    object.Tree = builder->GetOutput();
    object.BuildSeconds = builder->GetBuildTime();
    if (!check->Read(object.Tree))
    {
      throw std::runtime_error(std::string("vtkMergeTreeBuilder output is not a valid merge tree: ") +
        check->GetErrorMessage());
    }
    if (!object.Tree->GetPointData()->GetNormals())
    {
      throw std::runtime_error("the merge tree lost the point normals");
    }
    SetFieldString(object.Tree, "W2CacheKey", key);
    SetFieldNumber(object.Tree, "W2BuildSeconds", object.BuildSeconds);
    SetFieldNumber(object.Tree, "W2PrepareSeconds", object.PrepareSeconds);
    const Clock::time_point write = Clock::now();
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetFileName(object.CachePath.c_str());
    writer->SetInputData(object.Tree);
    writer->SetDataModeToBinary(); // not appended: see the README's known platform issue
    if (writer->Write() == 0)
    {
      std::cerr << "WARNING: cannot write the cache " << object.CachePath << "\n";
    }
    object.CacheSeconds = Seconds(write, Clock::now());
  }
  if (settings.ShadingWeight >= 0.0)
  {
    // The same tree with other errors (the cache keeps the builder's).
    timecritical::MergeTreeErrorOptions options;
    options.ShadingWeight = settings.ShadingWeight;
    std::vector<double> points(3 * static_cast<size_t>(object.Tree->GetNumberOfPoints()));
    for (vtkIdType i = 0; i < object.Tree->GetNumberOfPoints(); ++i)
    {
      object.Tree->GetPoint(i, &points[3 * static_cast<size_t>(i)]);
    }
    const timecritical::MergeTree tree = timecritical::ComputeMergeTree(
      check->GetMesh(), points.data(), check->GetTree().Level.data(), options);
    vtkDataArray* error =
      object.Tree->GetPointData()->GetArray(vtkMergeTreeFieldData::ErrorArrayName());
    if (!error || error->GetNumberOfTuples() != static_cast<vtkIdType>(tree.Error.size()))
    {
      throw std::runtime_error("--shading-weight: the tree has no matching error array");
    }
    for (vtkIdType i = 0; i < error->GetNumberOfTuples(); ++i)
    {
      error->SetComponent(i, 0, tree.Error[static_cast<size_t>(i)]);
    }
    error->Modified();
    object.Tree->Modified();
    object.Source += ", errors with shading weight " + std::to_string(settings.ShadingWeight);
  }
  object.Triangles = object.Tree->GetNumberOfPolys();
  object.Vertices = check->GetNumberOfVertices();
  object.Levels = check->GetLevelCount();
  object.Tree->GetBounds(object.Bounds);
  for (int c = 0; c < 3; ++c)
  {
    object.Center[c] = 0.5 * (object.Bounds[2 * c] + object.Bounds[2 * c + 1]);
  }
  object.Radius = 0.5 *
    std::sqrt(std::pow(object.Bounds[1] - object.Bounds[0], 2) +
      std::pow(object.Bounds[3] - object.Bounds[2], 2) +
      std::pow(object.Bounds[5] - object.Bounds[4], 2));
  return object;
}

//------------------------------------------------------------------------------
// W2 camera and light path: a pure function of the frame index.

/// Phases as fractions of the path: orbit, zoom in, close (light turns), zoom out.
constexpr double OrbitEnd = 0.30, ZoomInEnd = 0.50, LightStart = 0.52, LightEnd = 0.78,
                 ZoomOutStart = 0.80;

class ObjectPath
{
public:
  ObjectPath(const LargeObject& object, int frames)
    : Frames(frames)
    , Radius(object.Radius)
  {
    this->Center = { object.Center[0], object.Center[1], object.Center[2] };
    // The face looks along +z in igea's frame: close-ups aim in front of the
    // centre, at eyes and nose.
    this->Face = this->Center + Vec3{ 0.0, 0.02 * this->Radius, 0.30 * this->Radius };
  }

  double Fraction(int frame) const
  {
    return this->Frames > 1 ? static_cast<double>(frame) / (this->Frames - 1) : 0.0;
  }

  Pose At(int frame) const
  {
    const double s = this->Fraction(frame);
    const double far = 2.6, close = 0.8; // distances to the focal point, in radii
    double azimuth = 0.0, distance = far, elevation = 15.0;
    Vec3 focal = this->Center;
    if (s <= OrbitEnd)
    {
      // Orbit from behind the head round to the face.
      azimuth = -180.0 + 180.0 * SmoothStep(s / OrbitEnd);
    }
    else if (s <= ZoomInEnd)
    {
      const double t = SmoothStep((s - OrbitEnd) / (ZoomInEnd - OrbitEnd));
      distance = far + (close - far) * t;
      elevation = 15.0 - 10.0 * t;
      focal = Lerp(this->Center, this->Face, t);
    }
    else if (s <= ZoomOutStart)
    {
      // Close to the face, drifting sideways a little.
      const double t = (s - ZoomInEnd) / (ZoomOutStart - ZoomInEnd);
      azimuth = 25.0 * SmoothStep(t);
      distance = close;
      elevation = 5.0;
      focal = this->Face;
    }
    else
    {
      const double t = SmoothStep((s - ZoomOutStart) / (1.0 - ZoomOutStart));
      azimuth = 25.0 + 65.0 * t;
      distance = close + (far - close) * t;
      elevation = 5.0 + 10.0 * t;
      focal = Lerp(this->Face, this->Center, t);
    }
    const double a = azimuth * M_PI / 180.0, e = elevation * M_PI / 180.0;
    const Vec3 direction{ std::sin(a) * std::cos(e), std::sin(e), std::cos(a) * std::cos(e) };
    return { focal + direction * (distance * this->Radius), focal };
  }

  /// Light direction (towards the light): from the left to the right of the
  /// face, once, while the camera is close; fixed before and after.
  Vec3 LightDirection(int frame) const
  {
    const double t = SmoothStep((this->Fraction(frame) - LightStart) / (LightEnd - LightStart));
    const double a = (-70.0 + 140.0 * t) * M_PI / 180.0, e = 35.0 * M_PI / 180.0;
    return { std::sin(a) * std::cos(e), std::sin(e), std::cos(a) * std::cos(e) };
  }

  int Frame(double fraction) const
  {
    return static_cast<int>(std::lround(fraction * (this->Frames - 1)));
  }

  /// Key frames: name and frame.
  std::vector<std::pair<std::string, int>> Keys() const
  {
    return { { "start", 0 }, { "orbit", this->Frame(0.5 * OrbitEnd) }, { "front", this->Frame(OrbitEnd) },
      { "close", this->Frame(LightStart) }, { "light", this->Frame(LightEnd) },
      { "end", this->Frames - 1 } };
  }

  Vec3 GetCenter() const { return this->Center; }
  double GetRadius() const { return this->Radius; }

private:
  int Frames;
  double Radius;
  Vec3 Center, Face;
};

//------------------------------------------------------------------------------
// Records and statistics

struct FrameRecord : PolicyFrame
{
  double Refinement = NaN; ///< seconds refining the front(s) in that render
  double ObjectTriangles = 0.0; ///< of the large object's front (W2: = Triangles)
  double Vertices = 0.0;
  double Splits = 0.0, Merges = 0.0;
  double Resolution = NaN; ///< budget: the policy's resolution of the large object
};

struct Statistics : PolicyStatistics
{
  double TrianglesShare = NaN;       ///< mean / full triangle count
  double TrianglesMedianShare = NaN; ///< median / full triangle count
  double RefinementMean = NaN, RefinementMax = NaN;
  double RefinementPer100K = NaN; ///< mean refinement time x 100K / mean display triangles
  /// Mean refinement time of the frames whose front has 50K to 200K display triangles.
  double RefinementNear100K = NaN;
  int RefinementNear100KFrames = 0;
  double SplitsMean = NaN, MergesMean = NaN;
};

struct PolicyRun
{
  std::string Name, Label;
  PolicyKind Kind = PolicyKind::Full;
  bool Ran = true;
  std::string Note;
  std::vector<FrameRecord> Frames;
  Statistics Stats;
  double Seconds = 0.0;
};

Statistics ComputeStatistics(const std::vector<FrameRecord>& frames, double target, double full)
{
  Statistics s;
  static_cast<PolicyStatistics&>(s) = ComputePolicyStatistics(frames, target);
  std::vector<double> refinement, near100K, splits, merges;
  for (const FrameRecord& f : frames)
  {
    if (std::isfinite(f.Refinement))
    {
      refinement.push_back(f.Refinement);
      splits.push_back(f.Splits);
      merges.push_back(f.Merges);
      if (f.ObjectTriangles >= 5e4 && f.ObjectTriangles <= 2e5)
      {
        near100K.push_back(f.Refinement);
      }
    }
  }
  if (frames.empty())
  {
    return s;
  }
  s.TrianglesShare = full > 0.0 ? s.TrianglesMean / full : NaN;
  s.TrianglesMedianShare = full > 0.0 ? s.TrianglesMedian / full : NaN;
  s.RefinementMean = Mean(refinement);
  s.RefinementMax = refinement.empty() ? NaN : *std::max_element(refinement.begin(), refinement.end());
  s.RefinementPer100K = s.TrianglesMean > 0.0 ? s.RefinementMean * 1e5 / s.TrianglesMean : NaN;
  s.RefinementNear100K = Mean(near100K);
  s.RefinementNear100KFrames = static_cast<int>(near100K.size());
  s.SplitsMean = Mean(splits);
  s.MergesMean = Mean(merges);
  return s;
}

void Progress(const std::string& name, int frame, int frames, const FrameRecord& r)
{
  if (frame % 20 != 0 && frame != frames - 1)
  {
    return;
  }
  char psnr[32] = "";
  if (std::isfinite(r.PSNR))
  {
    std::snprintf(psnr, sizeof(psnr), ", PSNR %.2f dB", r.PSNR);
  }
  char refine[48] = "";
  if (std::isfinite(r.Refinement))
  {
    std::snprintf(refine, sizeof(refine), ", refine %.2f ms", 1000.0 * r.Refinement);
  }
  std::fprintf(stderr, "  [%s] frame %3d/%d: %8.1f ms, %9.0f triangles%s%s\n", name.c_str(),
    frame + 1, frames, 1000.0 * r.Measured, r.Triangles, refine, psnr);
}

//------------------------------------------------------------------------------
// W2: the large object alone

struct Checks
{
  bool ReferenceDeterministic = false;
  double PlainMapperPSNR = NaN; ///< vtkPolyDataMapper at frame 0 vs the reference
};

class ViewDependent
{
public:
  ViewDependent(const Settings& settings, const LargeObject& object, const ObjectPath& path)
    : Options(settings)
    , Object(object)
    , Path(path)
  {
  }

  void Setup();
  PolicyRun Run(const PolicyInfo& policy);
  void WriteResolutionMaps(const PolicyRun& run);

  std::vector<Image> Reference;
  std::vector<double> FixedAccuracyTriangles; ///< per frame, for 'uniform'
  Checks Check;
  double CalibrationSeconds = NaN;

private:
  void Use(vtkRenderer* renderer);
  vtkSmartPointer<vtkRenderer> MakePlainRenderer(vtkActor* actor);
  void MoveTo(int frame);
  void Configure(PolicyKind kind);
  void SaveKeyFrame(const std::string& name, int frame, Image& image, const char* suffix = "");

  const Settings& Options;
  const LargeObject& Object;
  const ObjectPath& Path;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkCamera> Camera;
  vtkNew<vtkLight> Light;
  vtkNew<vtkMultiresolutionPolyDataMapper> Mapper;
  vtkNew<vtkActor> Actor;
  vtkSmartPointer<vtkRenderer> Current;
  /// Budget policy: the resolution chosen at each key frame (for the resolution maps).
  std::vector<std::pair<int, double>> KeyResolutions;
};

void SetMaterial(vtkActor* actor)
{
  // Some ambient light so that the side away from the light is not black,
  // and a highlight that moves as the light turns.
  vtkProperty* property = actor->GetProperty();
  property->SetColor(0.86, 0.80, 0.72);
  property->SetAmbient(0.12);
  property->SetDiffuse(0.8);
  property->SetSpecular(0.35);
  property->SetSpecularPower(40.0);
}

void ViewDependent::Setup()
{
  this->Window->SetSize(WindowSize, WindowSize);
  this->Window->SetMultiSamples(0);
  this->Window->SetWindowName("ViewDependentBenchmark");
  // A scene light, not a headlight: it turns on its own during the path.
  this->Light->SetLightTypeToSceneLight();
  this->Light->SetPositional(false);
  this->Mapper->SetInputData(this->Object.Tree);
  this->Mapper->ScalarVisibilityOff();
  this->Actor->SetMapper(this->Mapper);
  SetMaterial(this->Actor);
}

void ViewDependent::Use(vtkRenderer* renderer)
{
  if (this->Current)
  {
    this->Window->RemoveRenderer(this->Current);
  }
  this->Current = renderer;
  if (renderer)
  {
    renderer->SetActiveCamera(this->Camera);
    renderer->AddLight(this->Light);
    SetBackground(renderer);
    this->Window->AddRenderer(renderer);
  }
}

vtkSmartPointer<vtkRenderer> ViewDependent::MakePlainRenderer(vtkActor* actor)
{
  auto plain = vtkSmartPointer<vtkRenderer>::New();
  plain->AddActor(actor);
  return plain;
}

void ViewDependent::MoveTo(int frame)
{
  ApplyPose(this->Camera, this->Path.At(frame));
  const Vec3 c = this->Path.GetCenter();
  const Vec3 d = this->Path.LightDirection(frame);
  const double r = 10.0 * this->Path.GetRadius();
  this->Light->SetFocalPoint(c.X, c.Y, c.Z);
  this->Light->SetPosition(c.X + r * d.X, c.Y + r * d.Y, c.Z + r * d.Z);
  this->Current->ResetCameraClippingRange(const_cast<double*>(this->Object.Bounds));
}

void ViewDependent::Configure(PolicyKind kind)
{
  // Every policy states all settings: vtkTimeCriticalRenderer pushes its own
  // onto the mapper, and the uniform policy changes the resolution.
  vtkMultiresolutionPolyDataMapper* m = this->Mapper;
  m->ColorByResolutionOff();
  m->SetViewDependentRefinement(kind == PolicyKind::FixedAccuracy || kind == PolicyKind::Budget);
  m->SetRefinementMode(kind == PolicyKind::FixedAccuracy
      ? vtkMultiresolutionPolyDataMapper::FIXED_ACCURACY
      : vtkMultiresolutionPolyDataMapper::BUDGET);
  m->SetPixelThreshold(kind == PolicyKind::Budget ? this->Options.BudgetTau : this->Options.Tau);
  m->BackFaceSimplificationOn();
  m->SilhouetteRefinementOn();
  m->HighlightRefinementOn();
  m->SetResolution(1.0);
}

void ViewDependent::SaveKeyFrame(const std::string& name, int frame, Image& image, const char* suffix)
{
  for (const auto& key : this->Path.Keys())
  {
    if (key.second == frame)
    {
      WritePNG(image, std::filesystem::path(this->Options.Output) /
          (name + "_" + key.first + suffix + ".png"));
      return;
    }
  }
}

bool IsKey(const ObjectPath& path, int frame)
{
  for (const auto& key : path.Keys())
  {
    if (key.second == frame)
    {
      return true;
    }
  }
  return false;
}

PolicyRun ViewDependent::Run(const PolicyInfo& policy)
{
  PolicyRun run;
  run.Name = policy.Name;
  run.Label = policy.Label;
  run.Kind = policy.Kind;
  const int frames = this->Options.Frames;
  const bool reference = policy.Kind == PolicyKind::Full;
  this->Configure(policy.Kind);
  vtkSmartPointer<vtkTimeCriticalRenderer> tc;
  if (policy.Kind == PolicyKind::Budget)
  {
    tc = vtkSmartPointer<vtkTimeCriticalRenderer>::New();
    tc->AddActor(this->Actor);
    tc->SetTargetFrameTime(this->Options.Target);
    tc->SetPolicyToActiveSet();
    tc->ViewDependentRefinementOn();
    tc->SetRefinementModeToBudget();
    tc->SetPixelThreshold(this->Options.BudgetTau);
    if (this->Options.RefinementLimit >= 0.0)
    {
      tc->SetRefinementTimeLimit(this->Options.RefinementLimit);
    }
    this->Use(tc);
    this->MoveTo(0);
    const Clock::time_point start = Clock::now();
    if (!tc->Calibrate())
    {
      throw std::runtime_error("vtkTimeCriticalRenderer::Calibrate() failed on the object");
    }
    this->CalibrationSeconds = Seconds(start, Clock::now());
  }
  else
  {
    this->Use(this->MakePlainRenderer(this->Actor));
  }
  if (reference)
  {
    this->Reference.assign(static_cast<size_t>(frames), Image());
  }
  if (policy.Kind == PolicyKind::FixedAccuracy)
  {
    this->FixedAccuracyTriangles.assign(static_cast<size_t>(frames), NaN);
  }
  const double full = static_cast<double>(this->Object.Triangles);
  const auto setUniform = [&](int frame) {
    if (policy.Kind == PolicyKind::Uniform)
    {
      // The same number of triangles as the tau front of this frame, as a TOM prefix.
      const double t = this->FixedAccuracyTriangles[static_cast<size_t>(frame)];
      this->Mapper->SetResolution(std::isfinite(t) ? std::min(1.0, t / full) : 1.0);
    }
  };

  // Warm-up at the first camera, untimed: shaders, buffers, the first front.
  this->MoveTo(0);
  Image previous;
  for (int i = 0; i < this->Options.WarmupFrames; ++i)
  {
    setUniform(0);
    TimedRender(this->Window);
    if (reference && i + 2 >= this->Options.WarmupFrames)
    {
      Image front = Capture(this->Window, true);
      this->Check.ReferenceDeterministic = !previous.empty() && front == previous;
      previous = std::move(front);
    }
  }

  const Clock::time_point start = Clock::now();
  for (int frame = 0; frame < frames; ++frame)
  {
    this->MoveTo(frame);
    setUniform(frame);
    FrameRecord record;
    record.Measured = TimedRender(this->Window);
    record.Triangles = static_cast<double>(this->Mapper->GetRenderedTriangles());
    record.ObjectTriangles = record.Triangles;
    record.Vertices = static_cast<double>(this->Mapper->GetRenderedVertices());
    if (policy.Kind == PolicyKind::FixedAccuracy || policy.Kind == PolicyKind::Budget)
    {
      record.Refinement = this->Mapper->GetRefinementTime();
      record.Splits = static_cast<double>(this->Mapper->GetObjectSplits(0));
      record.Merges = static_cast<double>(this->Mapper->GetObjectMerges(0));
    }
    if (policy.Kind == PolicyKind::FixedAccuracy)
    {
      this->FixedAccuracyTriangles[static_cast<size_t>(frame)] = record.Triangles;
    }
    if (tc)
    {
      record.Resolution = tc->GetObjectResolution(0);
      record.Predicted = tc->GetPredictedFrameTime();
      if (IsKey(this->Path, frame))
      {
        this->KeyResolutions.emplace_back(frame, record.Resolution);
      }
    }
    Image image = Capture(this->Window, true);
    this->SaveKeyFrame(run.Name, frame, image);
    if (reference)
    {
      this->Reference[static_cast<size_t>(frame)] = std::move(image);
    }
    else if (!this->Reference.empty())
    {
      const Comparison c = Compare(image, this->Reference[static_cast<size_t>(frame)]);
      record.PSNR = c.PSNR;
      record.Identical = c.Identical;
    }
    run.Frames.push_back(record);
    Progress(run.Name, frame, frames, record);
  }
  run.Seconds = Seconds(start, Clock::now());
  run.Stats = ComputeStatistics(run.Frames, this->Options.Target, full);

  if (reference)
  {
    // Sanity check of the references: VTK's own mapper on the same mesh,
    // light and camera must give (nearly) the same first frame.
    vtkNew<vtkPolyDataMapper> plainMapper;
    plainMapper->SetInputData(this->Object.Tree);
    plainMapper->ScalarVisibilityOff();
    vtkNew<vtkActor> plainActor;
    plainActor->SetMapper(plainMapper);
    SetMaterial(plainActor);
    this->Use(this->MakePlainRenderer(plainActor));
    this->MoveTo(0);
    this->Window->Render();
    Image image = Capture(this->Window, true);
    this->Check.PlainMapperPSNR = Compare(image, this->Reference[0]).PSNR;
  }
  this->Use(nullptr);
  return run;
}

void ViewDependent::WriteResolutionMaps(const PolicyRun& run)
{
  // Re-rendered after the run with a plain renderer at each key frame's
  // camera (the front refines from the previous key frame's, to the same
  // threshold or the budget recorded), in the grey of each vertex's level.
  this->Configure(run.Kind);
  this->Use(this->MakePlainRenderer(this->Actor));
  this->Mapper->ColorByResolutionOn();
  for (const auto& key : this->Path.Keys())
  {
    if (run.Kind == PolicyKind::Budget)
    {
      const auto it = std::find_if(this->KeyResolutions.begin(), this->KeyResolutions.end(),
        [&](const std::pair<int, double>& k) { return k.first == key.second; });
      if (it == this->KeyResolutions.end())
      {
        continue;
      }
      this->Mapper->SetResolution(it->second);
    }
    this->MoveTo(key.second);
    for (int i = 0; i < 3; ++i) // let the front settle at this camera
    {
      this->Window->Render();
    }
    Image image = Capture(this->Window, true);
    this->SaveKeyFrame(run.Name, key.second, image, "_resolution");
  }
  this->Mapper->ColorByResolutionOff();
  this->Use(nullptr);
}

//------------------------------------------------------------------------------
// --mixed: W1's cows with the large object in front

struct MixedRun
{
  std::string Name, Label;
  std::vector<FrameRecord> Frames;
  Statistics Stats;
  double Seconds = 0.0;
  double CalibrationSeconds = NaN;
};

struct W1Figures
{
  bool Found = false;
  std::string Source;
  double Frames = NaN, Mean = NaN, Median = NaN, Max = NaN, ShareWithin = NaN, PSNRMean = NaN,
         PSNRMedian = NaN;
};

struct MixedResult
{
  std::string CowSource;
  bool CowSubstitute = false;
  int Cows = 0;
  vtkIdType CowTriangles = 0, SceneTriangles = 0;
  double ObjectScale = NaN, ObjectHeight = NaN;
  std::vector<int> ReferenceFrames;
  std::vector<MixedRun> Runs;
  W1Figures W1;
};

/// Numbers from W1's walkthrough.json: its 'timecritical' policy statistics.
W1Figures ReadW1(const std::string& file)
{
  W1Figures w1;
  w1.Source = file;
  std::ifstream in(file);
  if (file.empty() || !in)
  {
    return w1;
  }
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t policy = text.find("\"name\": \"timecritical\"");
  const size_t statistics = policy == std::string::npos ? policy : text.find("\"statistics\"", policy);
  if (statistics == std::string::npos)
  {
    return w1;
  }
  const std::string block = text.substr(statistics, text.find('}', statistics) - statistics);
  const auto number = [&](const std::string& key) {
    std::smatch match;
    const std::regex pattern("\"" + key + "\": ([-0-9.eE+]+)");
    return std::regex_search(block, match, pattern) ? std::stod(match[1].str()) : NaN;
  };
  w1.Found = true;
  w1.Frames = number("frames");
  w1.Mean = number("mean");
  w1.Median = number("median");
  w1.Max = number("max");
  w1.ShareWithin = number("share_within_110_percent");
  w1.PSNRMean = number("psnr_mean");
  w1.PSNRMedian = number("psnr_median");
  return w1;
}

MixedResult RunMixed(const Settings& settings, const LargeObject& object)
{
  MixedResult result;
  const CowTOM cow = MakeCowTOM(settings.DataDirectory);
  const Scene scene = PlaceObjects(settings.MixedObjects, settings.Seed, cow.TOM, cow.Triangles);
  const W1CameraPath path(scene, settings.MixedFrames);
  result.CowSource = cow.Source;
  result.CowSubstitute = cow.Substitute;
  result.Cows = static_cast<int>(scene.Objects.size());
  result.CowTriangles = scene.Triangles;
  result.SceneTriangles = scene.Triangles + object.Triangles;

  vtkNew<vtkRenderWindow> window;
  window->SetSize(WindowSize, WindowSize);
  window->SetMultiSamples(0);
  window->SetWindowName("ViewDependentBenchmark --mixed");
  vtkNew<vtkCamera> camera;

  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(static_cast<unsigned>(scene.Objects.size()));
  for (size_t i = 0; i < scene.Objects.size(); ++i)
  {
    blocks->SetBlock(static_cast<unsigned>(i), MakeCopy(cow.TOM, scene.Objects[i]));
  }
  vtkNew<vtkMultiresolutionPolyDataMapper> cowMapper;
  cowMapper->SetInputDataObject(blocks);
  vtkNew<vtkActor> cows;
  cows->SetMapper(cowMapper);

  // The large object stands just outside the herd's corner on A's side,
  // facing A (its face looks along +z), as tall as a fifth of the herd.
  const double L = scene.Extent;
  const Vec3 base{ 1.08 * L, 0.0, -0.08 * L };
  const Vec3 a = path.GetA();
  result.ObjectHeight = 0.2 * L;
  result.ObjectScale = result.ObjectHeight / (object.Bounds[3] - object.Bounds[2]);
  vtkNew<vtkTransform> place;
  place->PostMultiply();
  place->Translate(-object.Center[0], -object.Bounds[2], -object.Center[2]);
  place->Scale(result.ObjectScale, result.ObjectScale, result.ObjectScale);
  place->RotateY(std::atan2(a.X - base.X, a.Z - base.Z) * 180.0 / M_PI);
  place->Translate(base.X, base.Y, base.Z);
  vtkNew<vtkMultiresolutionPolyDataMapper> bigMapper;
  bigMapper->SetInputData(object.Tree);
  bigMapper->ScalarVisibilityOff();
  vtkNew<vtkActor> big;
  big->SetMapper(bigMapper);
  big->SetUserTransform(place);
  SetMaterial(big);
  double bounds[6];
  std::copy(scene.Bounds, scene.Bounds + 6, bounds);
  double b[6];
  big->GetBounds(b);
  for (int c = 0; c < 3; ++c)
  {
    bounds[2 * c] = std::min(bounds[2 * c], b[2 * c]);
    bounds[2 * c + 1] = std::max(bounds[2 * c + 1], b[2 * c + 1]);
  }

  const int frames = settings.MixedFrames;
  for (int f = 0; f < frames; ++f)
  {
    if (f % settings.MixedReferenceStep == 0 || f == path.GetKeyB() || f == path.GetKeyTurn() ||
      f == frames - 1)
    {
      result.ReferenceFrames.push_back(f);
    }
  }
  const char* const keyNames[] = { "A", "B", "turn", "C" };
  const int keyFrames[] = { path.GetKeyA(), path.GetKeyB(), path.GetKeyTurn(), path.GetKeyC() };
  const auto keyName = [&](int frame) -> const char* {
    for (int k = 0; k < 4; ++k)
    {
      if (keyFrames[k] == frame)
      {
        return keyNames[k];
      }
    }
    return nullptr;
  };
  const auto moveTo = [&](vtkRenderer* renderer, int frame) {
    ApplyPose(camera, path.At(frame));
    renderer->ResetCameraClippingRange(bounds);
  };

  // Two scenes on the same path: the cows with the object, and the cows alone (W1).
  for (int withObject = 1; withObject >= (settings.MixedCows ? 0 : 1); --withObject)
  {
    const std::string name = withObject ? "mixed" : "cows";
    std::cerr << "mixed scene: " << (withObject ? "cows + large object" : "cows alone (W1)")
              << ", references on " << result.ReferenceFrames.size() << " frames...\n";
    // References: a plain renderer, everything at full resolution, view-dependence off.
    std::vector<Image> references(static_cast<size_t>(frames));
    {
      vtkNew<vtkRenderer> plain;
      plain->AddActor(cows);
      if (withObject)
      {
        plain->AddActor(big);
      }
      plain->SetActiveCamera(camera);
      SetBackground(plain);
      window->AddRenderer(plain);
      cowMapper->SetResolution(1.0);
      bigMapper->SetResolution(1.0);
      bigMapper->ViewDependentRefinementOff();
      for (int f : result.ReferenceFrames)
      {
        moveTo(plain, f);
        window->Render();
        references[static_cast<size_t>(f)] = Capture(window, true);
        if (const char* key = keyName(f))
        {
          WritePNG(references[static_cast<size_t>(f)],
            std::filesystem::path(settings.Output) / (name + "_full_" + key + ".png"));
        }
      }
      window->RemoveRenderer(plain);
    }

    MixedRun run;
    run.Name = name;
    run.Label = withObject ? "cows + object, TimeCritical" : "cows alone (W1), TimeCritical";
    vtkNew<vtkTimeCriticalRenderer> tc;
    tc->AddActor(cows);
    if (withObject)
    {
      tc->AddActor(big);
    }
    tc->SetActiveCamera(camera);
    SetBackground(tc);
    tc->SetTargetFrameTime(settings.Target);
    tc->SetPolicyToActiveSet();
    tc->ViewDependentRefinementOn();
    tc->SetRefinementModeToBudget();
    tc->SetPixelThreshold(settings.BudgetTau);
    if (settings.RefinementLimit >= 0.0)
    {
      tc->SetRefinementTimeLimit(settings.RefinementLimit);
    }
    window->AddRenderer(tc);
    moveTo(tc, 0);
    Clock::time_point start = Clock::now();
    if (!tc->Calibrate())
    {
      throw std::runtime_error("vtkTimeCriticalRenderer::Calibrate() failed on the mixed scene");
    }
    run.CalibrationSeconds = Seconds(start, Clock::now());
    for (int i = 0; i < settings.WarmupFrames; ++i)
    {
      TimedRender(window);
    }
    start = Clock::now();
    for (int f = 0; f < frames; ++f)
    {
      moveTo(tc, f);
      FrameRecord record;
      record.Measured = TimedRender(window);
      record.Triangles = static_cast<double>(tc->GetTrianglesDrawn());
      record.Predicted = tc->GetPredictedFrameTime();
      if (withObject)
      {
        record.Refinement = tc->GetRefinementTime();
        record.Splits = static_cast<double>(bigMapper->GetObjectSplits(0));
        record.Merges = static_cast<double>(bigMapper->GetObjectMerges(0));
        record.Resolution = bigMapper->GetObjectResolution(0);
        record.ObjectTriangles = static_cast<double>(bigMapper->GetRenderedTriangles());
      }
      if (!references[static_cast<size_t>(f)].empty())
      {
        Image image = Capture(window, true);
        const Comparison c = Compare(image, references[static_cast<size_t>(f)]);
        record.PSNR = c.PSNR;
        record.Identical = c.Identical;
        if (const char* key = keyName(f))
        {
          WritePNG(image, std::filesystem::path(settings.Output) / (name + "_tc_" + key + ".png"));
        }
      }
      run.Frames.push_back(record);
      Progress(name, f, frames, record);
    }
    run.Seconds = Seconds(start, Clock::now());
    run.Stats = ComputeStatistics(run.Frames, settings.Target, static_cast<double>(
      withObject ? result.SceneTriangles : result.CowTriangles));
    window->RemoveRenderer(tc);
    result.Runs.push_back(run);
  }
  result.W1 = ReadW1(settings.W1Json);
  return result;
}

//------------------------------------------------------------------------------
// Goals, table, JSON

using Goal = PolicyGoal;

const PolicyRun* FindRun(const std::vector<PolicyRun>& runs, PolicyKind kind)
{
  for (const auto& run : runs)
  {
    if (run.Kind == kind && run.Ran)
    {
      return &run;
    }
  }
  return nullptr;
}

std::string Format(const char* format, double a, double b = 0.0, double c = 0.0, double d = 0.0)
{
  char buffer[160];
  std::snprintf(buffer, sizeof(buffer), format, a, b, c, d);
  return buffer;
}

/// Refinement time per frame for fronts of about 100K display triangles (50K
/// to 200K); without such frames, the mean scaled to 100K, not evaluated.
Goal IncrementalGoal(const std::string& name, const Statistics& s)
{
  if (s.RefinementNear100KFrames > 0)
  {
    return { name, "<= 5 ms at ~100K tris",
      Format("%.2f ms mean over %.0f frames of 50-200K tris (max %.2f ms, all frames)",
        1000.0 * s.RefinementNear100K, s.RefinementNear100KFrames, 1000.0 * s.RefinementMax),
      s.RefinementNear100K <= 0.005 };
  }
  return { name, "<= 5 ms at ~100K tris",
    Format("no frame of 50-200K tris: %.2f ms at %.0fK mean (%.2f ms/100K)",
      1000.0 * s.RefinementMean, s.TrianglesMean / 1000.0, 1000.0 * s.RefinementPer100K),
    false, false };
}

std::vector<Goal> EvaluateGoals(const std::vector<PolicyRun>& runs, const Settings& settings)
{
  std::vector<Goal> goals;
  const PolicyRun* tau = FindRun(runs, PolicyKind::FixedAccuracy);
  const PolicyRun* uniform = FindRun(runs, PolicyKind::Uniform);
  const PolicyRun* budget = FindRun(runs, PolicyKind::Budget);
  const bool psnr = FindRun(runs, PolicyKind::Full) != nullptr;
  const std::string tauName = "tau=" + Number(settings.Tau, 3) + " px";
  if (tau)
  {
    const Statistics& s = tau->Stats;
    goals.push_back({ tauName + ": mean triangles / full", "<= 20%",
      Format("%.1f%% (median frame %.1f%%)", 100.0 * s.TrianglesShare,
        100.0 * s.TrianglesMedianShare),
      s.TrianglesShare <= 0.20 });
    goals.push_back({ tauName + ": mean PSNR vs full", ">= 40 dB",
      psnr ? Format("%.2f dB (median %.2f)", s.PSNRMean, s.PSNRMedian) : "no reference",
      s.PSNRMean >= 40.0, psnr });
    goals.push_back(IncrementalGoal("incremental update (" + tauName + ")", s));
  }
  if (tau && uniform)
  {
    const double gain = tau->Stats.PSNRMean - uniform->Stats.PSNRMean;
    const double gainMedian = tau->Stats.PSNRMedian - uniform->Stats.PSNRMedian;
    goals.push_back({ "view-dep. vs uniform TOM, equal tris", ">= +3 dB",
      psnr ? Format("%+.2f dB mean (%+.2f median)", gain, gainMedian) : "no reference",
      gain >= 3.0, psnr });
  }
  if (budget)
  {
    const Statistics& s = budget->Stats;
    goals.push_back({ "budget: frames <= " + Number(1100.0 * settings.Target, 4) + " ms", ">= 99%",
      Format("%.1f%% (median %.1f ms, max %.1f ms)", 100.0 * s.ShareWithin, 1000.0 * s.Median,
        1000.0 * s.Max),
      s.ShareWithin >= 0.99 });
    goals.push_back(IncrementalGoal("incremental update (budget)", s));
  }
  return goals;
}

void PrintRow(const std::string& label, const Statistics& s, bool reference)
{
  std::printf("%-30s %8s %8s %8s %8s %8s %9s %8s %8s %9s %9s\n", label.c_str(),
    MillisecondsCell(s.Mean).c_str(), MillisecondsCell(s.Median).c_str(),
    MillisecondsCell(s.Max).c_str(), PercentCell(s.ShareWithin).c_str(),
    PercentCell(s.TrianglesShare).c_str(), Format("%.0f", s.TrianglesMean).c_str(),
    reference ? "ref" : DecibelCell(s.PSNRMean).c_str(),
    reference ? "ref" : DecibelCell(s.PSNRMedian).c_str(),
    std::isfinite(s.RefinementMean) ? Format("%.2f", 1000.0 * s.RefinementMean).c_str() : "-",
    std::isfinite(s.RefinementMax) ? Format("%.2f", 1000.0 * s.RefinementMax).c_str() : "-");
}

void PrintHeader()
{
  std::printf("%-30s %8s %8s %8s %8s %8s %9s %8s %8s %9s %9s\n", "policy", "mean ms", "median",
    "max ms", "<=110ms", "tris %", "tris", "PSNR dB", "PSNR med", "refine ms", "ref. max");
}

std::string StatisticsJson(const Statistics& s)
{
  std::ostringstream out;
  out << "{" << PolicyStatisticsJsonFields(s) << ", \"triangles_share\": "
      << Number(s.TrianglesShare) << ", \"triangles_median_share\": "
      << Number(s.TrianglesMedianShare) << ", \"psnr_frames\": " << s.PSNRFrames
      << ", \"refinement_mean\": "
      << Number(s.RefinementMean) << ", \"refinement_max\": " << Number(s.RefinementMax)
      << ", \"refinement_per_100k_triangles\": " << Number(s.RefinementPer100K)
      << ", \"refinement_50k_to_200k\": " << Number(s.RefinementNear100K)
      << ", \"refinement_50k_to_200k_frames\": " << s.RefinementNear100KFrames
      << ", \"splits_mean\": " << Number(s.SplitsMean) << ", \"merges_mean\": "
      << Number(s.MergesMean) << "}";
  return out.str();
}

std::string FramesJson(const std::vector<FrameRecord>& f)
{
  std::ostringstream out;
  out << "{" << PolicyFramesJsonFields(f, ", ") << ", \"object_triangles\": "
      << Array(f, [](const FrameRecord& r) { return r.ObjectTriangles; }, 10)
      << ", \"vertices\": " << Array(f, [](const FrameRecord& r) { return r.Vertices; }, 10)
      << ", \"refinement\": " << Array(f, [](const FrameRecord& r) { return r.Refinement; })
      << ", \"splits\": " << Array(f, [](const FrameRecord& r) { return r.Splits; }, 10)
      << ", \"merges\": " << Array(f, [](const FrameRecord& r) { return r.Merges; }, 10)
      << ", \"resolution\": " << Array(f, [](const FrameRecord& r) { return r.Resolution; }) << "}";
  return out.str();
}

void WriteJson(const Settings& settings, const LargeObject& object, const ObjectPath& path,
  const ViewDependent& bench, const std::vector<PolicyRun>& runs, const std::vector<Goal>& goals,
  const MixedResult* mixed, const double load[2])
{
  std::ofstream out(settings.Json);
  if (!out)
  {
    throw std::runtime_error("cannot write " + settings.Json);
  }
  out << "{\n  \"benchmark\": \"ViewDependentBenchmark\",\n";
  out << "  \"settings\": {\"frames\": " << settings.Frames << ", \"tau\": " << Number(settings.Tau)
      << ", \"budget_tau\": " << Number(settings.BudgetTau)
      << ", \"refinement_limit\": " << Number(settings.RefinementLimit)
      << ", \"target_frame_time\": " << Number(settings.Target) << ", \"quick\": "
      << (settings.Quick ? "true" : "false") << ", \"warmup_frames\": " << settings.WarmupFrames
      << ", \"loop_levels\": " << settings.LoopLevels << ", \"window\": [" << WindowSize << ", "
      << WindowSize << "], \"view_angle\": " << ViewAngle << ", \"psnr_cap\": " << PSNRCap
      << ", \"load_average_start\": " << Number(load[0], 3) << ", \"load_average_end\": "
      << Number(load[1], 3) << "},\n";
  out << "  \"object\": {\"name\": " << Quoted(object.Name) << ", \"source\": "
      << Quoted(object.Source) << ", \"generated\": " << (object.Generated ? "true" : "false")
      << ", \"triangles\": " << object.Triangles << ", \"vertices\": " << object.Vertices
      << ", \"levels\": " << object.Levels << ", \"build_seconds\": " << Number(object.BuildSeconds)
      << ", \"build_rate_mtri_per_s\": " << Number(1e-6 * object.Triangles / object.BuildSeconds)
      << ", \"prepare_seconds\": " << Number(object.PrepareSeconds) << ", \"cache\": "
      << Quoted(object.CachePath) << ", \"from_cache\": " << (object.FromCache ? "true" : "false")
      << ", \"cache_seconds\": " << Number(object.CacheSeconds) << ", \"radius\": "
      << Number(object.Radius) << "},\n";
  out << "  \"checks\": {\"reference_deterministic\": "
      << (bench.Check.ReferenceDeterministic ? "true" : "false")
      << ", \"vtkpolydatamapper_vs_reference_psnr\": " << Number(bench.Check.PlainMapperPSNR)
      << ", \"calibration_seconds\": " << Number(bench.CalibrationSeconds) << "},\n";
  out << "  \"path\": {\"phases\": {\"orbit_end\": " << OrbitEnd << ", \"zoom_in_end\": "
      << ZoomInEnd << ", \"light_start\": " << LightStart << ", \"light_end\": " << LightEnd
      << ", \"zoom_out_start\": " << ZoomOutStart << "}, \"key_frames\": {";
  const auto keys = path.Keys();
  for (size_t k = 0; k < keys.size(); ++k)
  {
    out << (k ? ", " : "") << Quoted(keys[k].first) << ": " << keys[k].second;
  }
  out << "}, \"distance\": [";
  for (int f = 0; f < settings.Frames; ++f)
  {
    const Pose pose = path.At(f);
    const Vec3 d = pose.Position - path.GetCenter();
    out << (f ? "," : "") << Number(std::sqrt(d.X * d.X + d.Y * d.Y + d.Z * d.Z) / object.Radius, 4);
  }
  out << "]},\n  \"policies\": [\n";
  for (size_t p = 0; p < runs.size(); ++p)
  {
    const PolicyRun& run = runs[p];
    out << "    {\"name\": " << Quoted(run.Name) << ", \"label\": " << Quoted(run.Label)
        << ", \"ran\": " << (run.Ran ? "true" : "false") << ", \"note\": " << Quoted(run.Note);
    if (run.Ran)
    {
      out << ", \"seconds\": " << Number(run.Seconds) << ",\n     \"statistics\": "
          << StatisticsJson(run.Stats) << ",\n     \"frames\": " << FramesJson(run.Frames);
    }
    out << "}" << (p + 1 < runs.size() ? "," : "") << "\n";
  }
  out << "  ],\n  \"goals\": " << GoalsJson(goals);
  if (mixed)
  {
    out << ",\n  \"mixed\": {\"cow_mesh\": " << Quoted(mixed->CowSource) << ", \"cow_substitute\": "
        << (mixed->CowSubstitute ? "true" : "false") << ", \"cows\": " << mixed->Cows
        << ", \"cow_triangles\": " << mixed->CowTriangles << ", \"scene_triangles\": "
        << mixed->SceneTriangles << ", \"object_scale\": " << Number(mixed->ObjectScale)
        << ", \"object_height\": " << Number(mixed->ObjectHeight) << ", \"frames\": "
        << settings.MixedFrames << ", \"reference_frames\": [";
    for (size_t i = 0; i < mixed->ReferenceFrames.size(); ++i)
    {
      out << (i ? "," : "") << mixed->ReferenceFrames[i];
    }
    out << "],\n   \"runs\": [\n";
    for (size_t r = 0; r < mixed->Runs.size(); ++r)
    {
      const MixedRun& run = mixed->Runs[r];
      out << "    {\"name\": " << Quoted(run.Name) << ", \"label\": " << Quoted(run.Label)
          << ", \"seconds\": " << Number(run.Seconds) << ", \"calibration_seconds\": "
          << Number(run.CalibrationSeconds) << ",\n     \"statistics\": "
          << StatisticsJson(run.Stats) << ",\n     \"frames\": " << FramesJson(run.Frames) << "}"
          << (r + 1 < mixed->Runs.size() ? "," : "") << "\n";
    }
    const W1Figures& w1 = mixed->W1;
    out << "   ],\n   \"w1\": {\"source\": " << Quoted(w1.Source) << ", \"found\": "
        << (w1.Found ? "true" : "false") << ", \"frames\": " << Number(w1.Frames)
        << ", \"mean\": " << Number(w1.Mean) << ", \"median\": " << Number(w1.Median)
        << ", \"max\": " << Number(w1.Max) << ", \"share_within_110_percent\": "
        << Number(w1.ShareWithin) << ", \"psnr_mean\": " << Number(w1.PSNRMean)
        << ", \"psnr_median\": " << Number(w1.PSNRMedian) << "}}";
  }
  out << "\n}\n";
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
      std::cerr << "ViewDependentBenchmark needs an X display (VTK here is an X build): run it "
                   "under xvfb-run -a -s \"-screen 0 1024x768x24\" or scripts/run-viewdependent.sh\n";
      return 2;
    }
    std::filesystem::create_directories(settings.Output);
    double load[2] = { LoadAverages()[0], NaN };

    std::cerr << "preparing the large object and its merge tree...\n";
    const LargeObject object = MakeLargeObject(settings);
    std::cerr << "object: " << object.Source << ": " << object.Triangles << " triangles, "
              << object.Levels << " levels, merge tree "
              << (object.FromCache ? "read from " : "built and cached in ") << object.CachePath
              << " (build " << object.BuildSeconds << " s, cache " << object.CacheSeconds << " s)\n";
    const ObjectPath path(object, settings.Frames);
    ViewDependent bench(settings, object, path);
    bench.Setup();

    std::vector<PolicyRun> runs;
    for (const PolicyInfo* policy : settings.Policies)
    {
      if (policy->Kind == PolicyKind::VDPM)
      {
        PolicyRun run;
        run.Name = policy->Name;
        run.Label = policy->Label;
        run.Kind = policy->Kind;
        run.Ran = false;
        run.Note = VDPMReason;
        runs.push_back(run);
        continue;
      }
      std::cerr << "policy " << policy->Name << ": " << settings.Frames << " frames\n";
      runs.push_back(bench.Run(*policy));
    }
    for (const auto& run : runs)
    {
      if (run.Ran && (run.Kind == PolicyKind::FixedAccuracy || run.Kind == PolicyKind::Budget))
      {
        bench.WriteResolutionMaps(run);
      }
    }

    std::unique_ptr<MixedResult> mixed;
    if (settings.Mixed)
    {
      mixed = std::make_unique<MixedResult>(RunMixed(settings, object));
    }
    load[1] = LoadAverages()[0];

    const std::vector<Goal> goals = EvaluateGoals(runs, settings);
    std::printf("ViewDependentBenchmark: %s, %lld triangles, %d levels, %d frames at %dx%d%s\n",
      object.Source.c_str(), static_cast<long long>(object.Triangles), object.Levels,
      settings.Frames, WindowSize, WindowSize,
      object.Generated ? " (GENERATED OBJECT: igea.ply not used)" : "");
    std::printf("merge tree: %s, build %.2f s (%.2f Mtri/s), preparation %.2f s, cache %s %.2f s\n",
      object.FromCache ? "cached" : "built", object.BuildSeconds,
      1e-6 * object.Triangles / object.BuildSeconds, object.PrepareSeconds,
      object.FromCache ? "read" : "write", object.CacheSeconds);
    std::printf("references: %s run to run; VTK's vtkPolyDataMapper vs reference at frame 0: %s dB\n",
      bench.Check.ReferenceDeterministic ? "identical" : "NOT identical",
      Number(bench.Check.PlainMapperPSNR, 4).c_str());
    std::printf("\n");
    PrintHeader();
    for (const auto& run : runs)
    {
      if (run.Ran)
      {
        PrintRow(run.Label, run.Stats, run.Kind == PolicyKind::Full);
      }
      else
      {
        std::printf("%-30s %s\n", run.Label.c_str(), run.Note.c_str());
      }
    }
    std::printf("(PSNR against the full-resolution frame of the same camera and light, identical "
                "images counted as %.0f dB; refinement times in ms)\n",
      PSNRCap);
    PrintGoals("W2 goals", goals, 42, 52);
    if (mixed)
    {
      std::printf("\nmixed scene: %d cows (%lld triangles%s) + the object (%lld triangles) in "
                  "front, W1's path, %d frames, target %.0f ms, PSNR on %zu frames\n",
        mixed->Cows, static_cast<long long>(mixed->CowTriangles),
        mixed->CowSubstitute ? ", SUBSTITUTE cow" : "", static_cast<long long>(object.Triangles),
        settings.MixedFrames, 1000.0 * settings.Target, mixed->ReferenceFrames.size());
      PrintHeader();
      for (const auto& run : mixed->Runs)
      {
        PrintRow(run.Label, run.Stats, false);
      }
      if (mixed->W1.Found)
      {
        std::printf("%-30s %8s %8s %8s %8s %8s %9s %8s %8s   (%s, %.0f frames)\n",
          "W1 TimeCritical (json)", MillisecondsCell(mixed->W1.Mean).c_str(),
          MillisecondsCell(mixed->W1.Median).c_str(), MillisecondsCell(mixed->W1.Max).c_str(),
          PercentCell(mixed->W1.ShareWithin).c_str(), "", "",
          DecibelCell(mixed->W1.PSNRMean).c_str(), DecibelCell(mixed->W1.PSNRMedian).c_str(),
          mixed->W1.Source.c_str(), mixed->W1.Frames);
      }
      else if (!settings.W1Json.empty())
      {
        std::printf("(W1 figures: %s not found or without a timecritical policy)\n",
          settings.W1Json.c_str());
      }
    }
    WriteJson(settings, object, path, bench, runs, goals, mixed.get(), load);
    std::printf("\nJSON: %s, images in %s\n", settings.Json.c_str(), settings.Output.c_str());
    std::fflush(stdout);
    if (settings.Plot)
    {
      RunPlotScript(TIMECRITICAL_VIEWDEPENDENT_PLOT_SCRIPT, settings.Json,
        (std::filesystem::path(settings.Output) / "viewdependent.png").string());
    }
    return 0;
  }
  catch (const std::exception& error)
  {
    std::cerr << "ViewDependentBenchmark: error: " << error.what() << "\n";
    return 1;
  }
}
