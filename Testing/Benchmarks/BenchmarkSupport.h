// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_BenchmarkSupport_h
#define timecritical_BenchmarkSupport_h

/**
 * Pieces shared by the rendering benchmarks (W1 WalkthroughBenchmark, W2
 * ViewDependentBenchmark): wall-clock frame timing, frame capture, PSNR with
 * OpenImageIO, PNG key frames, JSON text, statistics, the plot script call,
 * and W1's scene (the cow TOM, its jittered field of replicas and camera path),
 * so that W2's mixed scene is exactly W1's. Header-only: each benchmark is one
 * translation unit.
 */
#include "TestMeshIO.h"
#include "vtkTOMBuilder.h"
#include "vtkTOMFieldData.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTransform.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace timecritical
{
namespace benchmark
{
using Clock = std::chrono::steady_clock;
constexpr double NaN = std::numeric_limits<double>::quiet_NaN();
/// Identical images have infinite PSNR; a finite cap keeps means meaningful.
constexpr double PSNRCap = 99.0;
constexpr int WindowSize = 512;
constexpr double ViewAngle = 40.0;

inline double Seconds(Clock::time_point start, Clock::time_point end)
{
  return std::chrono::duration<double>(end - start).count();
}

/// Wall clock around Render() with glFinish after it: the frame is only done
/// when the rasterizer is, whatever the window does at the buffer swap.
inline double TimedRender(vtkRenderWindow* window)
{
  const Clock::time_point start = Clock::now();
  window->Render();
  window->WaitForCompletion();
  return Seconds(start, Clock::now());
}

inline void SetBackground(vtkRenderer* renderer)
{
  renderer->SetBackground(0.32, 0.36, 0.45);
}

//------------------------------------------------------------------------------
// Statistics

inline double Mean(const std::vector<double>& v)
{
  if (v.empty())
  {
    return NaN;
  }
  double sum = 0.0;
  for (double x : v)
  {
    sum += x;
  }
  return sum / static_cast<double>(v.size());
}

inline double MedianOf(std::vector<double> v)
{
  if (v.empty())
  {
    return NaN;
  }
  std::sort(v.begin(), v.end());
  const size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

//------------------------------------------------------------------------------
// Small vector algebra for camera paths

struct Vec3
{
  double X = 0.0, Y = 0.0, Z = 0.0;
};
inline Vec3 operator+(const Vec3& a, const Vec3& b)
{
  return { a.X + b.X, a.Y + b.Y, a.Z + b.Z };
}
inline Vec3 operator-(const Vec3& a, const Vec3& b)
{
  return { a.X - b.X, a.Y - b.Y, a.Z - b.Z };
}
inline Vec3 operator*(const Vec3& a, double s)
{
  return { a.X * s, a.Y * s, a.Z * s };
}
inline Vec3 Lerp(const Vec3& a, const Vec3& b, double t)
{
  return a + (b - a) * t;
}
inline Vec3 Normalized(const Vec3& a)
{
  const double length = std::sqrt(a.X * a.X + a.Y * a.Y + a.Z * a.Z);
  return length > 0.0 ? a * (1.0 / length) : a;
}
inline double SmoothStep(double t)
{
  t = std::min(std::max(t, 0.0), 1.0);
  return t * t * (3.0 - 2.0 * t);
}

struct Pose
{
  Vec3 Position, FocalPoint;
};

inline void ApplyPose(vtkCamera* camera, const Pose& pose)
{
  camera->SetPosition(pose.Position.X, pose.Position.Y, pose.Position.Z);
  camera->SetFocalPoint(pose.FocalPoint.X, pose.FocalPoint.Y, pose.FocalPoint.Z);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(ViewAngle);
}

//------------------------------------------------------------------------------
// Meshes

/// Portable uniform numbers: std::mt19937's output is fixed by the standard,
/// std::uniform_real_distribution's is not.
class Random
{
public:
  explicit Random(unsigned seed)
    : Engine(seed)
  {
  }
  double Uniform(double low, double high)
  {
    const double u = static_cast<double>(this->Engine() >> 8) * (1.0 / 16777216.0);
    return low + (high - low) * u;
  }

private:
  std::mt19937 Engine;
};

inline vtkSmartPointer<vtkPolyData> ToPolyData(const timecritical::testing::TriangleMesh& mesh)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.NumberOfPoints()));
  for (size_t i = 0; i < mesh.NumberOfPoints(); ++i)
  {
    points->SetPoint(static_cast<vtkIdType>(i), &mesh.Points[3 * i]);
  }
  vtkNew<vtkCellArray> polys;
  for (size_t t = 0; t < mesh.NumberOfTriangles(); ++t)
  {
    const vtkIdType ids[3] = { mesh.Triangles[3 * t], mesh.Triangles[3 * t + 1],
      mesh.Triangles[3 * t + 2] };
    polys->InsertNextCell(3, ids);
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetPolys(polys);
  return data;
}

inline vtkSmartPointer<vtkPolyData> WithNormals(vtkPolyData* input)
{
  // Splitting off: one normal per vertex, so shading is smooth and the
  // vertices the TOM orders are the mesh's own.
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(input);
  normals->SplittingOff();
  normals->ConsistencyOn();
  normals->ComputePointNormalsOn();
  normals->ComputeCellNormalsOff();
  normals->Update();
  vtkSmartPointer<vtkPolyData> out = normals->GetOutput();
  return out;
}

//------------------------------------------------------------------------------
// Images

using Image = std::vector<unsigned char>; ///< WindowSize^2 RGB, bottom row first

inline Image Capture(vtkRenderWindow* window, bool front)
{
  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetPixelData(0, 0, WindowSize - 1, WindowSize - 1, front ? 1 : 0, pixels);
  if (pixels->GetNumberOfComponents() != 3 ||
    pixels->GetNumberOfTuples() != static_cast<vtkIdType>(WindowSize) * WindowSize)
  {
    throw std::runtime_error("GetPixelData returned an unexpected image");
  }
  const unsigned char* data = pixels->GetPointer(0);
  return Image(data, data + 3 * static_cast<size_t>(WindowSize) * WindowSize);
}

struct Comparison
{
  double PSNR = NaN; ///< capped at PSNRCap
  bool Identical = false;
};

inline Comparison Compare(Image& image, Image& reference)
{
  const OIIO::ImageSpec spec(WindowSize, WindowSize, 3, OIIO::TypeDesc::UINT8);
  const OIIO::ImageBuf a(spec, image.data());
  const OIIO::ImageBuf b(spec, reference.data());
  // One thread: the comparison runs between timed frames and must not leave
  // a pool of busy threads behind on a 2-core machine.
  const auto result = OIIO::ImageBufAlgo::compare(a, b, 1.0f, 1.0f, OIIO::ROI(), 1);
  if (a.has_error() || b.has_error())
  {
    throw std::runtime_error("OpenImageIO compare failed: " + a.geterror() + b.geterror());
  }
  Comparison comparison;
  comparison.Identical = result.rms_error == 0.0;
  comparison.PSNR = comparison.Identical ? PSNRCap : std::min(result.PSNR, PSNRCap);
  return comparison;
}

inline void WritePNG(Image& image, const std::filesystem::path& path)
{
  vtkNew<vtkUnsignedCharArray> pixels;
  pixels->SetNumberOfComponents(3);
  pixels->SetArray(image.data(), static_cast<vtkIdType>(image.size()), 1); // 1: do not free
  vtkNew<vtkImageData> data;
  data->SetDimensions(WindowSize, WindowSize, 1);
  data->GetPointData()->SetScalars(pixels);
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(data);
  writer->SetFileName(path.string().c_str());
  writer->Write();
  if (writer->GetErrorCode() != 0)
  {
    throw std::runtime_error("cannot write " + path.string());
  }
}

//------------------------------------------------------------------------------
// JSON text and the plot script

inline std::string Number(double value, int digits = 6)
{
  if (!std::isfinite(value))
  {
    return "null";
  }
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*g", digits, value);
  return buffer;
}

inline std::string Quoted(const std::string& text)
{
  std::string out = "\"";
  for (char c : text)
  {
    if (c == '"' || c == '\\')
    {
      out += '\\';
      out += c;
    }
    else if (static_cast<unsigned char>(c) < 0x20)
    {
      char buffer[8];
      std::snprintf(buffer, sizeof(buffer), "\\u%04x", c);
      out += buffer;
    }
    else
    {
      out += c;
    }
  }
  return out + "\"";
}

/**
 * The policies a comma list names (`--policies`), in the order of `all`
 * whatever the order given (so that the full-resolution reference runs
 * first), or all of them for an empty list. `canonical` maps an alias to a
 * policy's Name. Throws std::runtime_error on an unknown name or an empty
 * selection.
 */
template <class Info, size_t N, class Canonical>
std::vector<const Info*> SelectPolicies(
  const Info (&all)[N], const std::string& list, Canonical canonical)
{
  std::vector<bool> wanted(N, list.empty());
  std::stringstream names(list);
  for (std::string name; std::getline(names, name, ',');)
  {
    if (name.empty())
    {
      continue;
    }
    const std::string key = canonical(name);
    const auto found =
      std::find_if(all, all + N, [&key](const Info& info) { return key == info.Name; });
    if (found == all + N)
    {
      throw std::runtime_error("unknown policy '" + name + "' (see --help)");
    }
    wanted[static_cast<size_t>(found - all)] = true;
  }
  std::vector<const Info*> selected;
  for (size_t i = 0; i < N; ++i)
  {
    if (wanted[i])
    {
      selected.push_back(&all[i]);
    }
  }
  if (selected.empty())
  {
    throw std::runtime_error("no policy selected");
  }
  return selected;
}

/// A JSON array of one value per record.
template <class Record, class Getter>
std::string Array(const std::vector<Record>& records, Getter get, int digits = 6)
{
  std::string out = "[";
  for (size_t i = 0; i < records.size(); ++i)
  {
    out += (i ? "," : "") + Number(get(records[i]), digits);
  }
  return out + "]";
}

inline std::string ShellQuoted(const std::string& text)
{
  std::string out = "'";
  for (char c : text)
  {
    out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  }
  return out + "'";
}

/// Runs a matplotlib script on the JSON file; skips (with a message) when the
/// script or matplotlib is missing, throws when the script fails.
inline void RunPlotScript(const std::string& script, const std::string& json, const std::string& png)
{
  if (script.empty() || !std::filesystem::is_regular_file(script))
  {
    std::cerr << "plot: script not found, skipped\n";
    return;
  }
  if (std::system("/usr/bin/python3 -c 'import matplotlib' >/dev/null 2>&1") != 0)
  {
    std::cerr << "plot: /usr/bin/python3 with matplotlib not available, skipped\n";
    return;
  }
  const std::string command = "/usr/bin/python3 " + ShellQuoted(script) + " " +
    ShellQuoted(json) + " --output " + ShellQuoted(png);
  if (std::system(command.c_str()) != 0)
  {
    throw std::runtime_error("the plot script failed: " + command);
  }
  std::cerr << "plot: " << png << "\n";
}

//------------------------------------------------------------------------------
// W1's scene: the cow's TOM and its jittered field of replicas

/// A cow-sized stand-in: an ellipsoid with bumps, 2 * 43 * 68 = 5,848 triangles.
inline timecritical::testing::TriangleMesh MakeSubstituteCow()
{
  auto mesh = timecritical::testing::MakeUVSphere(44, 68);
  for (size_t i = 0; i < mesh.NumberOfPoints(); ++i)
  {
    double* p = &mesh.Points[3 * i];
    const double bump = 1.0 + 0.08 * std::sin(7.0 * p[0]) * std::sin(5.0 * p[1]) * std::cos(6.0 * p[2]);
    // The cow's extents: about 10.4 long (x), 6.4 high (y), 3.4 wide (z).
    p[0] *= 5.2 * bump;
    p[1] *= 3.2 * bump;
    p[2] *= 1.7 * bump;
  }
  return mesh;
}

/// The cow's TOM (vtkTOMBuilder, point normals kept).
struct CowTOM
{
  std::string Source;      ///< file read, or a description of the substitute
  bool Substitute = false; ///< cow.obj was not found
  vtkSmartPointer<vtkPolyData> TOM;
  double BuildSeconds = 0.0;
  vtkIdType Triangles = 0;
  vtkIdType BaseTriangles = 0;
};

inline CowTOM MakeCowTOM(const std::string& dataDirectory)
{
  CowTOM object;
  const std::filesystem::path cow = std::filesystem::path(dataDirectory) / "cow.obj";
  auto input = vtkSmartPointer<vtkPolyData>::New();
  if (std::filesystem::is_regular_file(cow))
  {
    object.Source = cow.string();
    // VTK's reader: double coordinates (as in the file), one point per `v`
    // line and the triangles in file order. cow.obj has no texture
    // coordinates and no duplicate or unused points (checked when this moved
    // from TestMeshIO's loaders, which now read float through OpenMesh), so
    // nothing needs welding; the reader's GroupIds cell array is left out.
    vtkNew<vtkOBJReader> reader;
    reader->SetFileName(cow.string().c_str());
    reader->Update();
    if (reader->GetOutput()->GetNumberOfPolys() == 0)
    {
      throw std::runtime_error("vtkOBJReader read no triangles from " + cow.string());
    }
    input->SetPoints(reader->GetOutput()->GetPoints());
    input->SetPolys(reader->GetOutput()->GetPolys());
  }
  else
  {
    object.Substitute = true;
    object.Source = "substitute: bumpy ellipsoid of 5,848 triangles (" + cow.string() + " not found)";
    std::cerr << "WARNING: " << cow.string()
              << " not found: the scene uses a cow-sized substitute (a bumpy ellipsoid)\n";
    input = ToPolyData(MakeSubstituteCow());
  }

  vtkNew<vtkTOMBuilder> builder;
  builder->SetInputData(WithNormals(input));
  builder->Update();
  object.TOM = builder->GetOutput();
  object.BuildSeconds = builder->GetBuildTime();
  vtkNew<vtkTOMFieldData> tom;
  if (!tom->Read(object.TOM))
  {
    throw std::runtime_error(std::string("vtkTOMBuilder output is not a valid TOM: ") +
      tom->GetErrorMessage());
  }
  object.Triangles = tom->GetNumberOfTriangles();
  object.BaseTriangles = tom->GetBaseTriangleCount();
  if (!object.TOM->GetPointData()->GetNormals())
  {
    throw std::runtime_error("the TOM lost the point normals");
  }
  return object;
}

struct Placement
{
  double X = 0.0, Z = 0.0, Angle = 0.0; ///< position on the plane, rotation about +y (degrees)
  std::array<unsigned char, 3> Color{};
  vtkSmartPointer<vtkTransform> Transform;
};

struct Scene
{
  std::vector<Placement> Objects;
  int GridSide = 0;
  double Spacing = 0.0;
  double Jitter = 0.0;
  double Extent = 0.0;    ///< the herd covers [0, Extent]^2 in x and z
  double Radius = 0.0;    ///< footprint radius of one object about its centre
  double Height = 0.0;    ///< object height (feet at y = 0)
  int Focus = 0;          ///< the object B looks at
  double Bounds[6] = { 0, 0, 0, 0, 0, 0 };
  vtkIdType Triangles = 0;
  int OverlapChecks = 0;
};

inline std::array<unsigned char, 3> RandomColor(Random& random)
{
  // Pleasant, distinct colours: random hue, moderate saturation, bright value.
  const double h = random.Uniform(0.0, 6.0);
  const double s = random.Uniform(0.3, 0.65);
  const double v = random.Uniform(0.7, 0.95);
  const int sector = static_cast<int>(h) % 6;
  const double f = h - std::floor(h);
  const double p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  double rgb[3];
  switch (sector)
  {
    case 0: rgb[0] = v; rgb[1] = t; rgb[2] = p; break;
    case 1: rgb[0] = q; rgb[1] = v; rgb[2] = p; break;
    case 2: rgb[0] = p; rgb[1] = v; rgb[2] = t; break;
    case 3: rgb[0] = p; rgb[1] = q; rgb[2] = v; break;
    case 4: rgb[0] = t; rgb[1] = p; rgb[2] = v; break;
    default: rgb[0] = v; rgb[1] = p; rgb[2] = q; break;
  }
  std::array<unsigned char, 3> color{};
  for (int c = 0; c < 3; ++c)
  {
    color[c] = static_cast<unsigned char>(std::lround(255.0 * rgb[c]));
  }
  return color;
}

inline Scene PlaceObjects(int objects, unsigned seed, vtkPolyData* tom, vtkIdType trianglesPerObject)
{
  Scene scene;
  double b[6];
  tom->GetBounds(b);
  const double cx = 0.5 * (b[0] + b[1]), cz = 0.5 * (b[4] + b[5]);
  for (vtkIdType i = 0; i < tom->GetNumberOfPoints(); ++i)
  {
    double p[3];
    tom->GetPoint(i, p);
    scene.Radius = std::max(scene.Radius, std::hypot(p[0] - cx, p[2] - cz));
  }
  scene.Height = b[3] - b[2];
  // Cells leave 3 units (~0.3 cow lengths) between footprints; the jitter uses
  // 90% of that gap, so no two footprint circles can touch whatever the rotation.
  scene.GridSide = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(objects))));
  scene.Spacing = 2.0 * scene.Radius + 3.0;
  scene.Jitter = 0.45 * (scene.Spacing - 2.0 * scene.Radius);
  scene.Extent = scene.GridSide * scene.Spacing;

  Random random(seed);
  for (int n = 0; n < objects; ++n)
  {
    Placement place;
    const int i = n % scene.GridSide, j = n / scene.GridSide;
    place.X = (i + 0.5) * scene.Spacing + random.Uniform(-scene.Jitter, scene.Jitter);
    place.Z = (j + 0.5) * scene.Spacing + random.Uniform(-scene.Jitter, scene.Jitter);
    place.Angle = random.Uniform(0.0, 360.0);
    place.Color = RandomColor(random);
    place.Transform = vtkSmartPointer<vtkTransform>::New();
    place.Transform->PostMultiply();
    place.Transform->Translate(-cx, -b[2], -cz); // footprint centre to the origin, feet on y = 0
    place.Transform->RotateY(place.Angle);
    place.Transform->Translate(place.X, 0.0, place.Z);
    place.Transform->Update();
    scene.Objects.push_back(place);
  }
  // Verify "no overlaps" rather than trust the construction.
  for (size_t m = 0; m < scene.Objects.size(); ++m)
  {
    for (size_t n = m + 1; n < scene.Objects.size(); ++n)
    {
      ++scene.OverlapChecks;
      const double d = std::hypot(
        scene.Objects[m].X - scene.Objects[n].X, scene.Objects[m].Z - scene.Objects[n].Z);
      if (d < 2.0 * scene.Radius)
      {
        throw std::runtime_error("objects " + std::to_string(m) + " and " + std::to_string(n) +
          " overlap");
      }
    }
  }
  // B focuses on an object in the herd's south-west part: seen from A's side
  // it has a few dozen others behind it, and the sudden turn at B looks along
  // the herd's diagonal, across most of it.
  double best = std::numeric_limits<double>::infinity();
  for (size_t n = 0; n < scene.Objects.size(); ++n)
  {
    const double d = std::hypot(
      scene.Objects[n].X - 0.30 * scene.Extent, scene.Objects[n].Z - 0.25 * scene.Extent);
    if (d < best)
    {
      best = d;
      scene.Focus = static_cast<int>(n);
    }
  }
  scene.Bounds[0] = scene.Bounds[4] = -scene.Radius;
  scene.Bounds[1] = scene.Bounds[5] = scene.Extent + scene.Radius;
  scene.Bounds[2] = 0.0;
  scene.Bounds[3] = scene.Height;
  scene.Triangles = trianglesPerObject * static_cast<vtkIdType>(scene.Objects.size());
  return scene;
}

/// A transformed copy of the TOM with a colour per vertex. Points and normals
/// are transformed in place in a deep copy, which keeps the TOM arrays (point
/// and field data) untouched; the copy is then checked to still be a TOM.
inline vtkSmartPointer<vtkPolyData> MakeCopy(vtkPolyData* tom, const Placement& place)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(tom);
  vtkPoints* points = copy->GetPoints();
  vtkDataArray* normals = copy->GetPointData()->GetNormals();
  for (vtkIdType i = 0; i < copy->GetNumberOfPoints(); ++i)
  {
    double p[3], n[3];
    points->GetPoint(i, p);
    place.Transform->TransformPoint(p, p);
    points->SetPoint(i, p);
    normals->GetTuple(i, n);
    place.Transform->TransformNormal(n, n);
    normals->SetTuple(i, n);
  }
  points->Modified();
  normals->Modified();
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetName("Colors");
  colors->SetNumberOfComponents(3);
  colors->SetNumberOfTuples(copy->GetNumberOfPoints());
  for (vtkIdType i = 0; i < copy->GetNumberOfPoints(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      colors->SetTypedComponent(i, c, place.Color[c]);
    }
  }
  copy->GetPointData()->SetScalars(colors);
  vtkNew<vtkTOMFieldData> check;
  if (!check->Read(copy))
  {
    throw std::runtime_error(std::string("a transformed copy is not a valid TOM: ") +
      check->GetErrorMessage());
  }
  return copy;
}

//------------------------------------------------------------------------------
// W1's camera path (section 7.2.2): a pure function of the frame index.

class CameraPath
{
public:
  CameraPath(const Scene& scene, int frames)
    : Frames(frames)
  {
    const double L = scene.Extent;
    const double r = scene.Radius;
    this->Center = { 0.5 * L, 0.0, 0.5 * L };
    const Placement& focus = scene.Objects[static_cast<size_t>(scene.Focus)];
    this->Target = { focus.X, 0.5 * scene.Height, focus.Z };
    // A: outside the herd beyond one corner and high up: the whole herd in view.
    this->A = this->Center + Vec3{ 1.115 * L, 0.932 * L, -1.121 * L };
    // B: about four footprint radii from the focus object on A's side, above
    // it: the object fills a third of the view, a few dozen others the
    // background (full resolution costs about 1/17 of A there).
    const Vec3 towardA = Normalized(Vec3{ this->A.X - this->Target.X, 0.0, this->A.Z - this->Target.Z });
    this->B = this->Target + towardA * (4.4 * r) + Vec3{ 0.0, 2.5 * r, 0.0 };
    // The sudden turn: from looking down at the object to looking along the
    // herd's diagonal, slightly downward: near objects large, hundreds behind.
    this->TurnDirection = Normalized(Vec3{ 1.0, -0.12, 1.0 });
    this->TurnFocus = this->B + this->TurnDirection * (0.31 * L);
    // C: backed away along the diagonal, outside the herd and up again.
    const Vec3 back = Normalized(Vec3{ 1.0, 0.0, 1.0 });
    this->C = Vec3{ this->B.X, 0.0, this->B.Z } - back * (0.932 * L) + Vec3{ 0.0, 0.528 * L, 0.0 };
    this->KeyB = static_cast<int>(std::lround(0.45 * (frames - 1)));
  }

  Pose At(int frame) const
  {
    Pose pose;
    if (frame <= this->KeyB)
    {
      // Approach: fast at A, slowing down to a stop at B (ease-out), the
      // view turning from the herd's centre to the focus object.
      const double s = this->KeyB > 0 ? static_cast<double>(frame) / this->KeyB : 1.0;
      pose.Position = Lerp(this->A, this->B, 1.0 - (1.0 - s) * (1.0 - s));
      pose.FocalPoint = Lerp(this->Center, this->Target, SmoothStep(1.3 * s));
    }
    else
    {
      // After the turn (one frame): backing away, slowly at first (ease-in),
      // the view drifting back to the herd's centre.
      const int last = this->Frames - 1;
      const double s = last > this->KeyB + 1
        ? static_cast<double>(frame - this->KeyB - 1) / (last - this->KeyB - 1)
        : 1.0;
      pose.Position = Lerp(this->B, this->C, s * s);
      pose.FocalPoint = Lerp(this->TurnFocus, this->Center, SmoothStep(s));
    }
    return pose;
  }

  int GetKeyA() const { return 0; }
  int GetKeyB() const { return this->KeyB; }
  int GetKeyTurn() const { return std::min(this->KeyB + 1, this->Frames - 1); }
  int GetKeyC() const { return this->Frames - 1; }
  Vec3 GetA() const { return this->A; }
  Vec3 GetCenter() const { return this->Center; }

private:
  int Frames;
  int KeyB = 0;
  Vec3 Center, Target, A, B, C, TurnDirection, TurnFocus;
};
}
}

#endif
