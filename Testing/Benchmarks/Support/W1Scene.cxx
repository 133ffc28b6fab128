// SPDX-License-Identifier: BSD-3-Clause
#include "W1Scene.h"

#include "BenchmarkRandom.h"
#include "MeshConversion.h"
#include "W1SceneSpecification.h"
#include "vtkTOMBuilder.h"
#include "vtkTOMFieldData.h"

#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTransform.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <stdexcept>

namespace timecritical
{
namespace benchmark
{
namespace
{
/// cow.obj as VTK's reader gives it: double coordinates (as in the file),
/// one point per `v` line and the triangles in file order. cow.obj has no
/// texture coordinates and no duplicate or unused points, so nothing needs
/// welding; the reader's GroupIds cell array is left out.
vtkSmartPointer<vtkPolyData> ReadOBJ(const std::filesystem::path& file)
{
  vtkNew<vtkOBJReader> reader;
  reader->SetFileName(file.string().c_str());
  reader->Update();
  if (reader->GetOutput()->GetNumberOfPolys() == 0)
  {
    throw std::runtime_error("vtkOBJReader read no triangles from " + file.string());
  }
  auto input = vtkSmartPointer<vtkPolyData>::New();
  input->SetPoints(reader->GetOutput()->GetPoints());
  input->SetPolys(reader->GetOutput()->GetPolys());
  return input;
}

/// Verifies "no overlaps" rather than trusting the construction.
void CheckNoOverlaps(Scene& scene);
}

std::array<unsigned char, 3> RandomColor(BenchmarkRandom& random)
{
  const W1SceneSpecification& spec = W1SceneSpecification::Get();
  const double h = random.Uniform(spec.Hue[0], spec.Hue[1]);
  const double s = random.Uniform(spec.Saturation[0], spec.Saturation[1]);
  const double v = random.Uniform(spec.Value[0], spec.Value[1]);
  const int sector = static_cast<int>(h) % 6;
  const double f = h - std::floor(h);
  const double p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  const double sectors[6][3] = { { v, t, p }, { q, v, p }, { p, v, t }, { p, q, v }, { t, p, v },
    { v, p, q } };
  std::array<unsigned char, 3> color{};
  for (int c = 0; c < 3; ++c)
  {
    color[c] = static_cast<unsigned char>(std::lround(255.0 * sectors[sector][c]));
  }
  return color;
}

namespace
{
void CheckNoOverlaps(Scene& scene)
{
  for (size_t m = 0; m < scene.Objects.size(); ++m)
  {
    for (size_t n = m + 1; n < scene.Objects.size(); ++n)
    {
      ++scene.OverlapChecks;
      const double d = std::hypot(
        scene.Objects[m].X - scene.Objects[n].X, scene.Objects[m].Z - scene.Objects[n].Z);
      if (d < 2.0 * scene.Radius)
      {
        throw std::runtime_error(
          "objects " + std::to_string(m) + " and " + std::to_string(n) + " overlap");
      }
    }
  }
}

/// The object nearest the specification's focus point: in the herd's
/// south-west part, so that seen from A's side it has a few dozen others
/// behind it, and the sudden turn at B looks across most of the herd.
int FocusObject(const Scene& scene)
{
  const W1SceneSpecification& spec = W1SceneSpecification::Get();
  double best = std::numeric_limits<double>::infinity();
  int focus = 0;
  for (size_t n = 0; n < scene.Objects.size(); ++n)
  {
    const double d = std::hypot(scene.Objects[n].X - spec.FocusNear[0] * scene.Extent,
      scene.Objects[n].Z - spec.FocusNear[1] * scene.Extent);
    if (d < best)
    {
      best = d;
      focus = static_cast<int>(n);
    }
  }
  return focus;
}

/// Footprint centre, radius and height of the object.
void MeasureObject(vtkPolyData* tom, Scene& scene)
{
  double b[6];
  tom->GetBounds(b);
  scene.Anchor = { 0.5 * (b[0] + b[1]), b[2], 0.5 * (b[4] + b[5]) };
  for (vtkIdType i = 0; i < tom->GetNumberOfPoints(); ++i)
  {
    double p[3];
    tom->GetPoint(i, p);
    scene.Radius =
      std::max(scene.Radius, std::hypot(p[0] - scene.Anchor[0], p[2] - scene.Anchor[2]));
  }
  scene.Height = b[3] - b[2];
}
}

timecritical::testing::TriangleMesh MakeSubstituteCow()
{
  const W1SceneSpecification& spec = W1SceneSpecification::Get();
  auto mesh =
    timecritical::testing::MakeUVSphere(spec.SubstituteLatitudes, spec.SubstituteLongitudes);
  const auto& frequency = spec.BumpFrequencies;
  for (size_t i = 0; i < mesh.NumberOfPoints(); ++i)
  {
    double* p = &mesh.Points[3 * i];
    const double bump = 1.0 +
      spec.BumpAmplitude * std::sin(frequency[0] * p[0]) * std::sin(frequency[1] * p[1]) *
        std::cos(frequency[2] * p[2]);
    for (int k = 0; k < 3; ++k)
    {
      p[k] *= spec.SubstituteScale[static_cast<size_t>(k)] * bump;
    }
  }
  return mesh;
}

CowTOM MakeCowTOM(const std::string& dataDirectory)
{
  CowTOM object;
  const std::filesystem::path cow = std::filesystem::path(dataDirectory) / "cow.obj";
  vtkSmartPointer<vtkPolyData> input;
  if (std::filesystem::is_regular_file(cow))
  {
    object.Source = cow.string();
    input = ReadOBJ(cow);
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
    throw std::runtime_error(
      std::string("vtkTOMBuilder output is not a valid TOM: ") + tom->GetErrorMessage());
  }
  object.Triangles = tom->GetNumberOfTriangles();
  object.BaseTriangles = tom->GetBaseTriangleCount();
  if (!object.TOM->GetPointData()->GetNormals())
  {
    throw std::runtime_error("the TOM lost the point normals");
  }
  return object;
}

Scene PlaceObjects(int objects, unsigned seed, vtkPolyData* tom, vtkIdType trianglesPerObject)
{
  const W1SceneSpecification& spec = W1SceneSpecification::Get();
  Scene scene;
  MeasureObject(tom, scene);
  scene.GridSide = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(objects))));
  scene.Spacing = 2.0 * scene.Radius + spec.Gap;
  scene.Jitter = spec.JitterFractionOfGap * (scene.Spacing - 2.0 * scene.Radius);
  scene.Extent = scene.GridSide * scene.Spacing;

  BenchmarkRandom random(seed);
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
    // Footprint centre to the origin, feet on y = 0, then turn and place.
    place.Transform->Translate(-scene.Anchor[0], -scene.Anchor[1], -scene.Anchor[2]);
    place.Transform->RotateY(place.Angle);
    place.Transform->Translate(place.X, 0.0, place.Z);
    place.Transform->Update();
    scene.Objects.push_back(place);
  }
  CheckNoOverlaps(scene);
  scene.Focus = FocusObject(scene);
  scene.Bounds[0] = scene.Bounds[4] = -scene.Radius;
  scene.Bounds[1] = scene.Bounds[5] = scene.Extent + scene.Radius;
  scene.Bounds[2] = 0.0;
  scene.Bounds[3] = scene.Height;
  scene.Triangles = trianglesPerObject * static_cast<vtkIdType>(scene.Objects.size());
  return scene;
}

vtkSmartPointer<vtkPolyData> MakeCopy(vtkPolyData* tom, const Placement& place)
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
      colors->SetTypedComponent(i, c, place.Color[static_cast<size_t>(c)]);
    }
  }
  copy->GetPointData()->SetScalars(colors);
  vtkNew<vtkTOMFieldData> check;
  if (!check->Read(copy))
  {
    throw std::runtime_error(
      std::string("a transformed copy is not a valid TOM: ") + check->GetErrorMessage());
  }
  return copy;
}
}
}
