// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_W1Scene_h
#define timecritical_W1Scene_h

/**
 * W1's scene: the cow's TOM and its jittered herd of replicas, laid out by
 * W1Scene.json (W1SceneSpecification), so that W1 (WalkthroughBenchmark),
 * W2's mixed scene (ViewDependentBenchmark --mixed), the interactive
 * benchmark and scripts/make_w1_scene.py all draw the same herd.
 */
#include "MeshIO.h"

#include <vtkSmartPointer.h>
#include <vtkType.h>

#include <array>
#include <string>
#include <vector>

class vtkPolyData;
class vtkTransform;

namespace timecritical
{
namespace benchmark
{
class BenchmarkRandom;

/// A random hue, moderate saturation and bright value (W1Scene.json's
/// colors): pleasant, distinct colours; three draws of `random`.
std::array<unsigned char, 3> RandomColor(BenchmarkRandom& random);

/// The cow-sized stand-in for a missing cow.obj: a bumpy ellipsoid of
/// 5,848 triangles with the cow's extents.
timecritical::testing::TriangleMesh MakeSubstituteCow();

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

/// The TOM of dataDirectory/cow.obj, or of the substitute (with a warning)
/// when the file is missing; throws std::runtime_error on an unreadable file.
CowTOM MakeCowTOM(const std::string& dataDirectory);

/// One replica: where it stands, how it is turned, its colour.
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
  double Extent = 0.0; ///< the herd covers [0, Extent]^2 in x and z
  double Radius = 0.0; ///< footprint radius of one object about its centre
  double Height = 0.0; ///< object height (feet at y = 0)
  std::array<double, 3> Anchor{}; ///< the object's footprint centre, at its feet
  int Focus = 0;                  ///< the object B looks at
  double Bounds[6] = { 0, 0, 0, 0, 0, 0 };
  vtkIdType Triangles = 0;
  int OverlapChecks = 0;
};

/// `objects` replicas of `tom` (whose triangle count is trianglesPerObject)
/// on a jittered grid, turned and coloured by std::mt19937(seed); throws if
/// two footprints overlap.
Scene PlaceObjects(int objects, unsigned seed, vtkPolyData* tom, vtkIdType trianglesPerObject);

/// A transformed copy of the TOM with a colour per vertex, checked to still
/// be a TOM (the TOM arrays are left as they are).
vtkSmartPointer<vtkPolyData> MakeCopy(vtkPolyData* tom, const Placement& place);
}
}

#endif
