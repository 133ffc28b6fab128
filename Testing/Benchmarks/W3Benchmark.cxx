// SPDX-License-Identifier: BSD-3-Clause
/**
 * W3 scale benchmark: a field of at least 2,000 objects and
 * 10 million triangles, replicas of the shared meshes (cow, spot, teapot,
 * homer, fandisk, bunny, igea) and of generated ones (tori, a bumpy sphere, a
 * subdivided cube), one vtkMultiresolutionPolyDataMapper in a
 * vtkTimeCriticalRenderer (active set, 100 ms target), 512x512, a camera that
 * flies into the field, through it and out again.
 *
 * Each distinct mesh is built into a TOM once and cached as a binary .vtp in
 * the output folder. A replica shares its base TOM's connectivity and TOM
 * arrays (cells, TOMSubstitution, field data); its points (float), normals
 * and colours are its own.
 *
 * Memory, sampled as process RSS and glibc heap in use (mallinfo2: uordblks
 * + hblkhd) at: start; the input data built (before the mapper sees it); the
 * mapper's UpdateObjects() (its copies of the TOM arrays; it keeps no merged
 * copy of the leaves); the first render (calibration, mapped colors, vertex
 * and index buffers: llvmpipe keeps GL buffers in process memory); the end of
 * the path.
 *
 * Per frame: wall-clock time around Render() (+ WaitForCompletion),
 * triangles drawn, predicted time. Prints and writes w3.json.
 */
#include "BenchmarkArguments.h"
#include "BenchmarkImages.h"
#include "BenchmarkJson.h"
#include "BenchmarkRandom.h"
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
#include "vtkTOMBuilder.h"

#include "vtkMultiresolutionPolyDataMapper.h"
#include "vtkTOMFieldData.h"
#include "vtkTimeCriticalRenderer.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLVertexBufferObject.h>
#include <vtkOpenGLVertexBufferObjectGroup.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTransform.h>
#include <vtkUnsignedCharArray.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include <malloc.h>
#include <unistd.h>

#include <fstream>

using namespace timecritical::benchmark;
namespace tt = timecritical::testing;

namespace
{
/// The mapper, with read access to its vertex buffer objects' sizes.
class W3Mapper : public vtkMultiresolutionPolyDataMapper
{
public:
  static W3Mapper* New();
  vtkTypeMacro(W3Mapper, vtkMultiresolutionPolyDataMapper);

  /// Bytes of one attribute's buffer as uploaded (tuples x stride) and of its
  /// CPU-side packing vector (capacity), or 0 when there is none.
  void VBOBytes(const char* attribute, double& gl, double& packed)
  {
    gl = packed = 0.0;
    vtkOpenGLVertexBufferObject* vbo = this->VBOs->GetVBO(attribute);
    if (vbo)
    {
      gl = static_cast<double>(vbo->GetNumberOfTuples()) * vbo->GetStride();
      packed = static_cast<double>(vbo->GetPackedVBO().capacity()) * sizeof(float);
    }
  }

protected:
  W3Mapper() = default;
  ~W3Mapper() override = default;

private:
  W3Mapper(const W3Mapper&) = delete;
  void operator=(const W3Mapper&) = delete;
};
vtkStandardNewMacro(W3Mapper);

struct Memory
{
  std::string Label;
  double RSS = 0.0;  ///< bytes
  double Heap = 0.0; ///< glibc heap in use (uordblks + hblkhd), bytes
  double Free = 0.0; ///< free bytes glibc holds (fordblks)
};

Memory Sample(const std::string& label)
{
  Memory m;
  m.Label = label;
  std::ifstream statm("/proc/self/statm");
  long size = 0, resident = 0;
  statm >> size >> resident;
  m.RSS = static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE));
  const struct mallinfo2 info = mallinfo2();
  m.Heap = static_cast<double>(info.uordblks) + static_cast<double>(info.hblkhd);
  m.Free = static_cast<double>(info.fordblks);
  return m;
}

constexpr double MiB = 1024.0 * 1024.0;

/// The process's peak RSS so far (VmHWM), bytes: transient buffers (the
/// vertex buffers' packing during the first upload) show here only.
double PeakRSS()
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
  {
    if (line.rfind("VmHWM:", 0) == 0)
    {
      return 1024.0 * std::stod(line.substr(6)); // kB
    }
  }
  return 0.0;
}

struct Kind
{
  std::string Name;   ///< cache file stem
  std::string File;   ///< shared data file, or empty for a generated mesh
  int Count = 0;      ///< replicas
  vtkIdType StandIn = 0; ///< shared folder absent: triangles of a noisy torus in its place
  vtkSmartPointer<vtkPolyData> TOM;
  vtkIdType Triangles = 0;
  double Radius = 0.0; ///< footprint radius (x-z) about the centre, after normalization
  double Height = 0.0;
  double Center[3] = { 0, 0, 0 };
  double FloorY = 0.0;
  bool Cached = false;
  double BuildSeconds = 0.0;
};

/// Normalized to a largest extent of 10 (the cow's size in W1).
tt::TriangleMesh Normalized(tt::TriangleMesh mesh)
{
  double lo[3] = { 1e300, 1e300, 1e300 }, hi[3] = { -1e300, -1e300, -1e300 };
  for (size_t i = 0; i < mesh.NumberOfPoints(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = std::min(lo[k], mesh.Points[3 * i + k]);
      hi[k] = std::max(hi[k], mesh.Points[3 * i + k]);
    }
  }
  const double extent = std::max({ hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2] });
  const double s = extent > 0 ? 10.0 / extent : 1.0;
  for (size_t i = 0; i < mesh.NumberOfPoints(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      mesh.Points[3 * i + k] = (mesh.Points[3 * i + k] - 0.5 * (lo[k] + hi[k])) * s;
    }
  }
  return mesh;
}

tt::TriangleMesh BumpySphere()
{
  auto mesh = tt::MakeUVSphere(40, 60);
  for (size_t i = 0; i < mesh.NumberOfPoints(); ++i)
  {
    double* p = &mesh.Points[3 * i];
    const double bump = 1.0 + 0.1 * std::sin(6.0 * p[0]) * std::sin(5.0 * p[1]) * std::cos(7.0 * p[2]);
    p[0] *= bump;
    p[1] *= 1.3 * bump;
    p[2] *= bump;
  }
  return mesh;
}

tt::TriangleMesh MakeMesh(const Kind& kind, const std::string& data)
{
  if (!kind.File.empty())
  {
    const std::string path = (std::filesystem::path(data) / kind.File).string();
    return tt::RemoveUnusedPoints(tt::WeldPoints(tt::LoadMesh(path)));
  }
  if (kind.StandIn > 0)
  {
    const auto n = static_cast<size_t>(std::max(6.0, std::sqrt(static_cast<double>(kind.StandIn))));
    return tt::MakeTorus(n, std::max<size_t>(3, n / 2), static_cast<uint32_t>(kind.StandIn), 0.15);
  }
  if (kind.Name == "torus-a")
  {
    return tt::MakeTorus(48, 24, 11u, 0.1);
  }
  if (kind.Name == "torus-b")
  {
    return tt::MakeTorus(64, 32, 12u, 0.15);
  }
  if (kind.Name == "bumpy-sphere")
  {
    return BumpySphere();
  }
  return tt::MakeCube(20);
}

void LoadOrBuild(Kind& kind, const std::string& data, const std::filesystem::path& output)
{
  const std::filesystem::path cache = output / ("w3-tom-" + kind.Name + ".vtp");
  vtkNew<vtkTOMFieldData> check;
  if (std::filesystem::is_regular_file(cache))
  {
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(cache.string().c_str());
    reader->Update();
    vtkPolyData* tom = reader->GetOutput();
    if (tom && tom->GetNumberOfPoints() > 0 && check->Read(tom) && tom->GetPointData()->GetNormals())
    {
      kind.TOM = tom;
      kind.Cached = true;
    }
  }
  if (!kind.TOM)
  {
    const Clock::time_point start = Clock::now();
    vtkNew<vtkTOMBuilder> builder;
    builder->SetInputData(WithNormals(ToPolyData(Normalized(MakeMesh(kind, data)))));
    builder->Update();
    kind.TOM = builder->GetOutput();
    kind.BuildSeconds = Seconds(start, Clock::now());
    if (!check->Read(kind.TOM))
    {
      throw std::runtime_error(kind.Name + ": not a valid TOM: " + check->GetErrorMessage());
    }
    vtkNew<vtkXMLPolyDataWriter> writer; // binary, not appended (README: expat)
    writer->SetDataModeToBinary();
    writer->SetInputData(kind.TOM);
    writer->SetFileName(cache.string().c_str());
    writer->Write();
  }
  kind.Triangles = check->GetNumberOfTriangles();
  double b[6];
  kind.TOM->GetBounds(b);
  kind.Center[0] = 0.5 * (b[0] + b[1]);
  kind.Center[2] = 0.5 * (b[4] + b[5]);
  kind.FloorY = b[2];
  kind.Height = b[3] - b[2];
  kind.Radius = 0.0;
  for (vtkIdType i = 0; i < kind.TOM->GetNumberOfPoints(); ++i)
  {
    double p[3];
    kind.TOM->GetPoint(i, p);
    kind.Radius = std::max(kind.Radius, std::hypot(p[0] - kind.Center[0], p[2] - kind.Center[2]));
  }
}

/// A replica: shared cells, TOM arrays and field data; own float points,
/// normals and colours.
vtkSmartPointer<vtkPolyData> MakeReplica(vtkPolyData* tom, vtkTransform* transform,
  const std::array<unsigned char, 3>& color)
{
  const vtkIdType n = tom->GetNumberOfPoints();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(n);
  vtkNew<vtkFloatArray> normals;
  normals->SetName(tom->GetPointData()->GetNormals()->GetName());
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(n);
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetName("Colors");
  colors->SetNumberOfComponents(3);
  colors->SetNumberOfTuples(n);
  vtkDataArray* sourceNormals = tom->GetPointData()->GetNormals();
  float* xyz = static_cast<vtkFloatArray*>(points->GetData())->GetPointer(0);
  float* nxyz = normals->GetPointer(0);
  unsigned char* rgb = colors->GetPointer(0);
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3], q[3];
    tom->GetPoint(i, p);
    transform->TransformPoint(p, q);
    sourceNormals->GetTuple(i, p);
    transform->TransformNormal(p, p);
    for (int k = 0; k < 3; ++k)
    {
      xyz[3 * i + k] = static_cast<float>(q[k]);
      nxyz[3 * i + k] = static_cast<float>(p[k]);
      rgb[3 * i + k] = color[static_cast<size_t>(k)];
    }
  }
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->SetPoints(points);
  copy->SetPolys(tom->GetPolys());
  vtkPointData* pd = tom->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = pd->GetAbstractArray(a);
    if (array != sourceNormals)
    {
      copy->GetPointData()->AddArray(array); // TOMSubstitution: shared
    }
  }
  copy->GetPointData()->SetNormals(normals);
  copy->GetPointData()->SetScalars(colors);
  copy->GetFieldData()->ShallowCopy(tom->GetFieldData());
  return copy;
}

struct Placed
{
  size_t Kind = 0;
  double X = 0, Z = 0, Scale = 1, Angle = 0;
};

/// The flight: from high above one corner (the whole field in view) down into
/// the field, along an S through it at twice an object's height, looking
/// ahead, and up and out over the far side looking back at the centre.
class FlightPath
{
public:
  FlightPath(double extent, double height, int frames)
    : L(extent)
    , H(height)
    , Frames(frames)
  {
  }
  Vec3 Inside(double u) const
  {
    const double x = this->L * (0.08 + 0.84 * u);
    const double z = this->L * (0.5 + 0.3 * std::sin(2.0 * 3.14159265358979 * u));
    return { x, 2.0 * this->H, z };
  }
  Pose At(int frame) const
  {
    const double s = this->Frames > 1 ? static_cast<double>(frame) / (this->Frames - 1) : 0.0;
    const Vec3 centre{ 0.5 * this->L, 0.0, 0.5 * this->L };
    const Vec3 A{ -0.6 * this->L, 0.8 * this->L, 0.5 * this->L };
    const double in = 0.2, out = 0.85;
    Pose pose;
    if (s <= in)
    {
      const double t = SmoothStep(s / in);
      pose.Position = Lerp(A, this->Inside(0.0), t);
      pose.FocalPoint = Lerp(centre, this->Ahead(0.0), t);
    }
    else if (s <= out)
    {
      const double u = (s - in) / (out - in);
      pose.Position = this->Inside(u);
      pose.FocalPoint = this->Ahead(u);
    }
    else
    {
      const double t = SmoothStep((s - out) / (1.0 - out));
      const Vec3 C{ 1.3 * this->L, 0.6 * this->L, 0.5 * this->L };
      pose.Position = Lerp(this->Inside(1.0), C, t);
      pose.FocalPoint = Lerp(this->Ahead(1.0), centre, t);
    }
    return pose;
  }

private:
  Vec3 Ahead(double u) const
  {
    const Vec3 p = this->Inside(u), q = this->Inside(u + 0.02);
    const Vec3 d = Normalized(q - p);
    return p + d * (0.2 * this->L) + Vec3{ 0.0, -2.0 * this->H, 0.0 };
  }
  double L, H;
  int Frames;
};

struct Frame
{
  double Measured = NaN, Predicted = NaN;
  vtkIdType Triangles = 0;
  int Culled = 0;
};

void Usage()
{
  std::cout << "W3Benchmark: >= 10M triangles in >= 2,000 objects at a 100 ms target\n"
               "  --output DIR   results (w3.json) and the TOM cache (default ./w3-output)\n"
               "  --data DIR     shared meshes (default: the configured shared data folder)\n"
               "  --frames N     frames of the flight (default 120)\n"
               "  --target S     target frame time in seconds (default 0.1)\n"
               "  --scale F      replicas per kind times F (default 1; --quick: 0.02)\n"
               "  --warmup N     untimed frames at the first camera after the first render\n"
               "                 (default 3, as W1)\n"
               "  --quick        a small scene (--scale 0.02), 20 frames (smoke test)\n"
               "  --no-plot      accepted for scripts/benchmark-runner.sh (there is no plot)\n";
}
} // namespace

int main(int argc, char* argv[])
{
  std::string outputText = "w3-output";
  std::string data = TIMECRITICAL_SHARED_DATA_DIR;
  int frames = 120;
  double target = 0.1;
  double scale = 1.0;
  int warmup = 3;
  bool help = false, quick = false, noPlot = false, framesSet = false, scaleSet = false;
  try
  {
    BenchmarkArguments arguments(argc, argv);
    arguments.AddFlag("--help", help);
    arguments.AddFlag("-h", help);
    arguments.AddFlag("--quick", quick);
    arguments.AddFlag("--no-plot", noPlot); // accepted for scripts/benchmark-runner.sh
    arguments.AddText("--output", outputText);
    arguments.AddText("--data", data);
    arguments.AddInteger("--frames", frames, 2, 1000000, &framesSet);
    arguments.AddNumber("--target", target, [](double x) { return x > 0.0; });
    arguments.AddInteger("--warmup", warmup, 0);
    arguments.AddNumber("--scale", scale, [](double x) { return x > 0.0; }, &scaleSet);
    arguments.Parse();
  }
  catch (const std::exception& error)
  {
    std::cerr << "W3Benchmark: " << error.what() << "\n";
    Usage();
    return 2;
  }
  if (help)
  {
    Usage();
    return 0;
  }
  if (quick)
  {
    scale = scaleSet ? scale : 0.02;
    frames = framesSet ? frames : 20;
  }
  const std::filesystem::path output = outputText;
  try
  {
    std::filesystem::create_directories(output);
    const std::string loadStart = LoadAverageText();
    std::vector<Memory> memory;
    memory.push_back(Sample("start"));
    const bool shared = std::filesystem::is_regular_file(std::filesystem::path(data) / "cow.obj");
    std::vector<Kind> kinds;
    if (!shared)
    {
      std::cerr << "WARNING: " << data << "/cow.obj not found: noisy tori of similar triangle "
                << "counts stand in for the shared meshes\n";
    }
    auto add = [&](const char* name, const char* file, int count, vtkIdType triangles = 0)
    {
      Kind kind;
      kind.Name = name;
      kind.File = shared ? file : "";
      kind.Count = std::max(1, static_cast<int>(std::lround(count * scale)));
      if (!shared && kind.File.empty() && std::string(file).size() > 0)
      {
        kind.Name = std::string("generated-") + name; // the shared folder is absent
        kind.StandIn = triangles;
      }
      kinds.push_back(kind);
    };
    add("cow", "cow.obj", 560, 5804);
    add("spot", "spot.obj", 300, 5856);
    add("teapot", "teapot.obj", 200, 6320);
    add("homer", "homer.obj", 120, 12000);
    add("fandisk", "fandisk.obj", 100, 12946);
    add("bunny", "stanford-bunny.obj", 12, 69451);
    add("igea", "igea.ply", 2, 268686);
    add("torus-a", "", 300);
    add("torus-b", "", 150);
    add("bumpy-sphere", "", 150);
    add("cube", "", 130);

    const Clock::time_point buildStart = Clock::now();
    for (Kind& kind : kinds)
    {
      LoadOrBuild(kind, data, output);
      std::cout << "  " << kind.Name << ": " << kind.Triangles << " triangles x " << kind.Count
                << (kind.Cached ? " (cached TOM)" : " (TOM built in " + Number(kind.BuildSeconds, 3) + " s)")
                << "\n";
    }
    const double tomSeconds = Seconds(buildStart, Clock::now());

    // Layout: a jittered grid, kinds shuffled over the cells, a random scale
    // in [0.7, 1.3] and rotation about +y per object.
    std::vector<Placed> placed;
    for (size_t k = 0; k < kinds.size(); ++k)
    {
      for (int c = 0; c < kinds[k].Count; ++c)
      {
        Placed p;
        p.Kind = k;
        placed.push_back(p);
      }
    }
    BenchmarkRandom random(2026u);
    for (size_t i = placed.size(); i > 1; --i)
    {
      const size_t j = static_cast<size_t>(random.Uniform(0.0, static_cast<double>(i)));
      std::swap(placed[i - 1], placed[std::min(j, i - 1)]);
    }
    double radius = 0.0, height = 0.0;
    for (const Kind& kind : kinds)
    {
      radius = std::max(radius, 1.3 * kind.Radius);
      height = std::max(height, kind.Height);
    }
    const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(placed.size()))));
    const double spacing = 2.0 * radius + 3.0;
    const double jitter = 0.45 * (spacing - 2.0 * radius);
    const double extent = side * spacing;

    vtkNew<vtkMultiBlockDataSet> blocks;
    blocks->SetNumberOfBlocks(static_cast<unsigned>(placed.size()));
    vtkIdType sceneTriangles = 0, scenePoints = 0;
    for (size_t n = 0; n < placed.size(); ++n)
    {
      Placed& p = placed[n];
      const Kind& kind = kinds[p.Kind];
      const int i = static_cast<int>(n) % side, j = static_cast<int>(n) / side;
      p.X = (i + 0.5) * spacing + random.Uniform(-jitter, jitter);
      p.Z = (j + 0.5) * spacing + random.Uniform(-jitter, jitter);
      p.Scale = random.Uniform(0.7, 1.3);
      p.Angle = random.Uniform(0.0, 360.0);
      vtkNew<vtkTransform> transform;
      transform->PostMultiply();
      transform->Translate(-kind.Center[0], -kind.FloorY, -kind.Center[2]);
      transform->Scale(p.Scale, p.Scale, p.Scale);
      transform->RotateY(p.Angle);
      transform->Translate(p.X, 0.0, p.Z);
      transform->Update();
      blocks->SetBlock(static_cast<unsigned>(n), MakeReplica(kind.TOM, transform, RandomColor(random)));
      sceneTriangles += kind.Triangles;
      scenePoints += kind.TOM->GetNumberOfPoints();
    }
    const double inputSeconds = Seconds(buildStart, Clock::now());
    memory.push_back(Sample("input data built"));
    const double inputHeap = memory.back().Heap - memory.front().Heap;
    std::cout << "W3 scene: " << placed.size() << " objects, " << sceneTriangles << " triangles, "
              << scenePoints << " points, field " << Number(extent, 4) << " units wide; TOMs "
              << Number(tomSeconds, 3) << " s, input " << Number(inputSeconds, 3) << " s, "
              << Number(inputHeap / MiB, 4) << " MiB heap\n";


    vtkNew<vtkCamera> camera;
    const FlightPath path(extent, height, frames);
    ApplyPose(camera, path.At(0));
    vtkNew<W3Mapper> mapper;
    mapper->SetInputDataObject(blocks);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    vtkNew<vtkTimeCriticalRenderer> renderer;
    renderer->AddActor(actor);
    renderer->SetActiveCamera(camera);
    renderer->SetTargetFrameTime(target);
    renderer->SetOptimizationTimeLimit(0.001);
    renderer->SetPolicyToActiveSet();
    SetBackground(renderer);
    vtkNew<vtkRenderWindow> window;
    window->SetSize(WindowSize, WindowSize);
    window->SetMultiSamples(0);
    window->SetWindowName("W3Benchmark");
    window->AddRenderer(renderer);
    const double bounds[6] = { -radius, extent + radius, 0.0, 1.3 * height, -radius, extent + radius };

    Clock::time_point t0 = Clock::now();
    mapper->UpdateObjects();
    const double readSeconds = Seconds(t0, Clock::now());
    memory.push_back(Sample("mapper UpdateObjects (TOM copies)"));

    renderer->ResetCameraClippingRange(const_cast<double*>(bounds));
    t0 = Clock::now();
    TimedRender(window); // calibration + first upload + first frame
    const double firstSeconds = Seconds(t0, Clock::now());
    memory.push_back(Sample("first render (calibration, buffers)"));
    const double peakFirst = PeakRSS();

    for (int w = 0; w < warmup; ++w)
    {
      TimedRender(window);
    }

    std::vector<Frame> records;
    for (int f = 0; f < frames; ++f)
    {
      ApplyPose(camera, path.At(f));
      renderer->ResetCameraClippingRange(const_cast<double*>(bounds));
      Frame record;
      record.Measured = TimedRender(window);
      record.Predicted = renderer->GetPredictedFrameTime();
      record.Triangles = renderer->GetObjectTrianglesDrawn();
      record.Culled = renderer->GetNumberOfCulledObjects();
      records.push_back(record);
    }
    memory.push_back(Sample("after the flight"));
    const std::string loadEnd = LoadAverageText();

    std::vector<double> times, triangles;
    int within = 0;
    for (const Frame& r : records)
    {
      times.push_back(r.Measured);
      triangles.push_back(static_cast<double>(r.Triangles));
      within += r.Measured <= 1.1 * target;
    }
    const double mean = Mean(times), median = Median(times);
    const double maximum = *std::max_element(times.begin(), times.end());
    const double share = static_cast<double>(within) / records.size();

    double vbo[3][2];
    const char* attributes[3] = { "vertexMC", "normalMC", "scalarColor" };
    double vboGL = 0.0, vboPacked = 0.0;
    for (int a = 0; a < 3; ++a)
    {
      mapper->VBOBytes(attributes[a], vbo[a][0], vbo[a][1]);
      vboGL += vbo[a][0];
      vboPacked += vbo[a][1];
    }
    const double ibo = 4.0 * 3.0 * static_cast<double>(sceneTriangles); // the full-size uint32 index buffer
    const Memory& input = memory[1];
    const Memory& objects = memory[memory.size() - 3];
    const Memory& first = memory[memory.size() - 2];
    const Memory& last = memory.back();
    const double T = static_cast<double>(sceneTriangles);

    std::cout << "\nW3: " << placed.size() << " objects, " << sceneTriangles << " triangles, "
              << frames << " frames, target " << 1000 * target << " ms\n"
              << "  frame time mean / median / max: " << Number(1000 * mean, 4) << " / "
              << Number(1000 * median, 4) << " / " << Number(1000 * maximum, 4) << " ms\n"
              << "  frames <= " << 1100 * target << " ms: " << Number(100 * share, 4) << "% (goal >= 99%: "
              << (share >= 0.99 ? "met" : "MISSED") << ")\n"
              << "  triangles drawn mean / max: " << Number(Mean(triangles), 6) << " / "
              << Number(*std::max_element(triangles.begin(), triangles.end()), 6) << "\n"
              << "  UpdateObjects " << Number(readSeconds, 3) << " s, first render " << Number(firstSeconds, 3)
              << " s (calibration " << Number(renderer->GetCalibrationTime(), 3) << " s)\n"
              << "  load average: start " << loadStart << ", end " << loadEnd << "\n"
              << "Memory (RSS / heap in use, MiB; heap delta per input triangle):\n";
    for (size_t m = 0; m < memory.size(); ++m)
    {
      const double dHeap = m > 0 ? memory[m].Heap - memory[m - 1].Heap : 0.0;
      std::cout << "  " << memory[m].Label << ": " << Number(memory[m].RSS / MiB, 5) << " / "
                << Number(memory[m].Heap / MiB, 5) << " (heap " << (dHeap >= 0 ? "+" : "")
                << Number(dHeap / MiB, 4) << " MiB, " << Number(dHeap / T, 4) << " B/tri)\n";
    }
    std::cout << "  renderer above the input data, after the first render: RSS "
              << Number((first.RSS - input.RSS) / MiB, 5) << " MiB (" << Number((first.RSS - input.RSS) / T, 4)
              << " B/tri), heap " << Number((first.Heap - input.Heap) / MiB, 5) << " MiB ("
              << Number((first.Heap - input.Heap) / T, 4) << " B/tri); after the flight: RSS "
              << Number((last.RSS - input.RSS) / MiB, 5) << " MiB; peak RSS up to the first render "
              << Number(peakFirst / MiB, 5) << " MiB (" << Number((peakFirst - input.RSS) / T, 4)
              << " B/tri above the input)\n"
              << "  of which mapper UpdateObjects: heap " << Number((objects.Heap - input.Heap) / MiB, 5)
              << " MiB (" << Number((objects.Heap - input.Heap) / T, 4) << " B/tri)\n"
              << "  vertex buffers: GL " << Number(vboGL / MiB, 5) << " MiB (" << Number(vboGL / T, 4)
              << " B/tri), CPU packing vectors " << Number(vboPacked / MiB, 5) << " MiB ("
              << Number(vboPacked / T, 4) << " B/tri); index buffer at full size "
              << Number(ibo / MiB, 5) << " MiB (12 B/tri)\n";
    for (int a = 0; a < 3; ++a)
    {
      std::cout << "    " << attributes[a] << ": GL " << Number(vbo[a][0] / T, 4) << " B/tri, packing vector "
                << Number(vbo[a][1] / T, 4) << " B/tri\n";
    }

    std::ofstream json(output / "w3.json");
    json << "{\n  \"objects\": " << placed.size() << ", \"triangles\": " << sceneTriangles
         << ", \"points\": " << scenePoints << ", \"frames\": " << frames
         << ", \"warmup\": " << warmup << ", \"target\": " << Number(target) << ", \"extent\": " << Number(extent)
         << ", \"shared_data\": " << (shared ? "true" : "false") << ",\n  \"kinds\": [";
    for (size_t k = 0; k < kinds.size(); ++k)
    {
      json << (k ? ", " : "") << "{\"name\": " << Quoted(kinds[k].Name) << ", \"triangles\": "
           << kinds[k].Triangles << ", \"replicas\": " << kinds[k].Count << ", \"cached\": "
           << (kinds[k].Cached ? "true" : "false") << "}";
    }
    json << "],\n  \"seconds\": {\"toms\": " << Number(tomSeconds) << ", \"input\": " << Number(inputSeconds)
         << ", \"update_objects\": " << Number(readSeconds) << ", \"first_render\": " << Number(firstSeconds)
         << ", \"calibration\": " << Number(renderer->GetCalibrationTime()) << "},\n"
         << "  \"frame_time\": {\"mean\": " << Number(mean) << ", \"median\": " << Number(median)
         << ", \"max\": " << Number(maximum) << ", \"share_within_110_percent\": " << Number(share)
         << "},\n  \"triangles_drawn\": {\"mean\": " << Number(Mean(triangles)) << ", \"max\": "
         << Number(*std::max_element(triangles.begin(), triangles.end())) << "},\n"
         << "  \"load_average\": {\"start\": " << Quoted(loadStart) << ", \"end\": " << Quoted(loadEnd)
         << "},\n  \"memory\": [";
    for (size_t m = 0; m < memory.size(); ++m)
    {
      json << (m ? ", " : "") << "{\"label\": " << Quoted(memory[m].Label) << ", \"rss\": "
           << Number(memory[m].RSS, 12) << ", \"heap\": " << Number(memory[m].Heap, 12)
           << ", \"heap_free\": " << Number(memory[m].Free, 12) << "}";
    }
    json << "],\n  \"breakdown_bytes\": {\"input_heap\": " << Number(inputHeap, 12)
         << ", \"update_objects_heap\": " << Number(objects.Heap - input.Heap, 12)
         << ", \"first_render_heap\": " << Number(first.Heap - objects.Heap, 12)
         << ", \"renderer_above_input_rss\": " << Number(first.RSS - input.RSS, 12)
         << ", \"renderer_above_input_heap\": " << Number(first.Heap - input.Heap, 12)
         << ", \"peak_rss_first_render\": " << Number(peakFirst, 12)
         << ", \"vbo_gl\": " << Number(vboGL, 12) << ", \"vbo_packed\": " << Number(vboPacked, 12)
         << ", \"ibo_full\": " << Number(ibo, 12) << ", \"vbo\": {";
    for (int a = 0; a < 3; ++a)
    {
      json << (a ? ", " : "") << Quoted(attributes[a]) << ": {\"gl\": " << Number(vbo[a][0], 12)
           << ", \"packed\": " << Number(vbo[a][1], 12) << "}";
    }
    json << "}},\n  \"rows\": [";
    for (size_t f = 0; f < records.size(); ++f)
    {
      json << (f ? ",\n    " : "\n    ") << "{\"frame\": " << f << ", \"measured\": "
           << Number(records[f].Measured) << ", \"predicted\": " << Number(records[f].Predicted)
           << ", \"triangles\": " << records[f].Triangles << ", \"culled\": " << records[f].Culled << "}";
    }
    json << "\n  ]\n}\n";
    std::cout << "wrote " << (output / "w3.json").string() << "\n";
  }
  catch (const std::exception& e)
  {
    std::cerr << "W3Benchmark: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
