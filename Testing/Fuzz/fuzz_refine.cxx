// SPDX-License-Identifier: BSD-3-Clause
// Fuzz target: the run-time paths on meshes built from the input (format in
// FuzzFormat.h). The mesh goes through MergeTreeBuilder; the TOM is
// extracted at arbitrary resolutions (TOMTraversal, against a reference
// walk), and ViewDependentRefinement is initialized with it and updated a few
// times with arbitrary views (any floats: NaN, infinite, zero directions,
// eyes inside the object), settings and budgets, in fixed-accuracy and budget
// mode. Every front must be the TOM's triangles mapped to their display
// vertices; a fixed-accuracy front must not depend on the previous front.
// With target bit 2 the merge tree is first corrupted within what
// vtkMergeTreeFieldData accepts from a file (finite errors and radii, cones,
// dependency ids below their vertex): no crash, whatever the front.
#include "FuzzChecks.h"
#include "FuzzFormat.h"
#include "MergeTreeBuilder.h"
#include "TOMTraversal.h"
#include "ViewDependentRefinement.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

using namespace timecritical;
using namespace timecritical::fuzz;

namespace
{
/// The display vertex that stands for vertex v: its nearest displayed ancestor.
uint32_t DisplayAncestor(const ViewDependentRefinement& vdr, const TOMMesh& tom, uint32_t v)
{
  while (!vdr.IsDisplayVertex(v))
  {
    FUZZ_REQUIRE(v >= tom.BaseVertexCount, "every base vertex is displayed");
    v = tom.Substitution[v];
  }
  return v;
}

/// Ids in range, statistics consistent, CopyTriangles() within its room.
void CheckFrontBasics(const ViewDependentRefinement& vdr, const TOMMesh& tom, uint32_t copyRoom)
{
  const uint32_t n = tom.GetNumberOfVertices();
  const uint32_t count = vdr.GetNumberOfDisplayTriangles();
  const RefinementStatistics& stats = vdr.GetStatistics();
  FUZZ_REQUIRE(stats.DisplayTriangles == count, "statistics count the display triangles");
  FUZZ_REQUIRE(stats.DisplayVertices == vdr.GetNumberOfDisplayVertices(),
    "statistics count the display vertices");
  FUZZ_REQUIRE(
    count <= tom.GetNumberOfTriangles(), "at most one display triangle per TOM triangle");
  const uint32_t* triangles = vdr.GetTriangles();
  const uint32_t* ids = vdr.GetTriangleIds();
  for (size_t i = 0; i < 3 * size_t(count); ++i)
  {
    FUZZ_REQUIRE(triangles[i] < n && vdr.IsDisplayVertex(triangles[i]),
      "display triangles use display vertices");
  }
  for (uint32_t i = 0; i < count; ++i)
  {
    FUZZ_REQUIRE(ids[i] < tom.GetNumberOfTriangles(), "display triangles name TOM triangles");
  }
  const uint32_t capacity = std::min(count, copyRoom);
  std::vector<uint32_t> copy(3 * size_t(capacity)); // exact room: ASan sees any overrun
  FUZZ_REQUIRE(vdr.CopyTriangles(copy.data(), capacity, 7) == count, "CopyTriangles count");
  for (size_t i = 0; i < copy.size(); ++i)
  {
    FUZZ_REQUIRE(copy[i] == triangles[i] + 7, "CopyTriangles adds the offset");
  }
}

/// The front is the TOM's triangles mapped to display vertices, each
/// non-degenerate one exactly once; display vertices are closed under parent.
void CheckFront(const ViewDependentRefinement& vdr, const TOMMesh& tom)
{
  const uint32_t n = tom.GetNumberOfVertices();
  uint32_t displayed = 0;
  for (uint32_t v = 0; v < n; ++v)
  {
    if (!vdr.IsDisplayVertex(v))
    {
      FUZZ_REQUIRE(v >= tom.BaseVertexCount, "base vertex " + std::to_string(v) + " displayed");
      continue;
    }
    ++displayed;
    FUZZ_REQUIRE(vdr.IsDisplayVertex(tom.Substitution[v]),
      "the parent of display vertex " + std::to_string(v) + " is displayed");
  }
  FUZZ_REQUIRE(displayed == vdr.GetNumberOfDisplayVertices(), "display vertex count");

  std::vector<uint32_t> position(tom.GetNumberOfTriangles(), UINT32_MAX);
  const uint32_t count = vdr.GetNumberOfDisplayTriangles();
  for (uint32_t i = 0; i < count; ++i)
  {
    const uint32_t t = vdr.GetTriangleIds()[i];
    FUZZ_REQUIRE(position[t] == UINT32_MAX, "TOM triangle " + std::to_string(t) + " shown twice");
    position[t] = i;
  }
  for (uint32_t t = 0; t < tom.GetNumberOfTriangles(); ++t)
  {
    uint32_t c[3];
    for (int k = 0; k < 3; ++k)
    {
      c[k] = DisplayAncestor(vdr, tom, tom.Triangles[3 * size_t(t) + k]);
    }
    const bool alive = c[0] != c[1] && c[1] != c[2] && c[0] != c[2];
    FUZZ_REQUIRE(alive == (position[t] != UINT32_MAX),
      "TOM triangle " + std::to_string(t) + (alive ? " alive but not shown" : " shown collapsed"));
    if (alive)
    {
      const uint32_t* shown = vdr.GetTriangles() + 3 * size_t(position[t]);
      FUZZ_REQUIRE(shown[0] == c[0] && shown[1] == c[1] && shown[2] == c[2],
        "TOM triangle " + std::to_string(t) + " shown with its display vertices");
    }
  }
}

/// A float for a tree array that vtkMergeTreeFieldData would accept: finite, >= 0.
float FiniteNonNegative(float x)
{
  return std::isfinite(x) ? std::abs(x) : 0.f;
}

/// Corrupts the tree within what vtkMergeTreeFieldData::Check accepts.
void Corrupt(MergeTree& tree, const TOMMesh& tom, Reader& in)
{
  const uint32_t n = tom.GetNumberOfVertices();
  const int edits = in.Read<uint8_t>() % 16;
  for (int e = 0; e < edits && n > 0; ++e)
  {
    const uint8_t kind = in.Read<uint8_t>();
    const uint32_t index = in.Read<uint32_t>();
    const float value = in.Read<float>();
    const uint32_t v = index % n;
    switch (kind % 5)
    {
      case 0: // a dependency of a removed vertex: any lower id
        if (!tree.Dependencies.empty())
        {
          const size_t k = index % tree.Dependencies.size();
          const auto row =
            std::upper_bound(tree.DependencyOffsets.begin(), tree.DependencyOffsets.end(), k) -
            tree.DependencyOffsets.begin() - 1;
          if (row > 0)
          {
            tree.Dependencies[k] = (index / 7) % uint32_t(row);
          }
        }
        break;
      case 1:
        tree.Error[v] = FiniteNonNegative(value);
        break;
      case 2:
        tree.Radius[v] = FiniteNonNegative(value);
        break;
      case 3:
        tree.ConeCosine[v] = std::isfinite(value) ? std::max(-1.f, std::min(1.f, value)) : -1.f;
        break;
      default:
      {
        // Another unit axis.
        const float angle = FiniteNonNegative(value);
        tree.ConeAxis[3 * size_t(v)] = std::cos(angle);
        tree.ConeAxis[3 * size_t(v) + 1] = std::sin(angle);
        tree.ConeAxis[3 * size_t(v) + 2] = 0.f;
        break;
      }
    }
  }
}

RefinementView MakeView(const ViewInput& in)
{
  RefinementView view;
  for (int i = 0; i < 3; ++i)
  {
    view.Eye[i] = in.Eye[i];
    view.Direction[i] = in.Direction[i];
    view.LightDirection[i] = in.Light[i];
  }
  view.Parallel = (in.Mode & 2) != 0;
  view.ViewportHeight = in.ViewportHeight;
  view.ViewAngle = in.ViewAngle;
  view.ParallelScale = in.ParallelScale;
  view.NearDistance = in.NearDistance;
  view.NumberOfFrustumPlanes = in.Planes % 7;
  for (int p = 0; p < view.NumberOfFrustumPlanes; ++p)
  {
    for (int i = 0; i < 3; ++i)
    {
      view.FrustumPlanes[p][i] = in.PlaneValues[p][i];
    }
    view.FrustumPlanes[p][3] = in.PlaneOffsets[p];
  }
  return view;
}

void Initialize(ViewDependentRefinement& vdr, const TOMMesh& tom, const MergeTree& tree,
  const std::vector<double>& points, const std::vector<float>& floatPoints, bool useFloats)
{
  if (useFloats)
  {
    vdr.Initialize(tom, tree, floatPoints.data());
  }
  else
  {
    vdr.Initialize(tom, tree, points.data());
  }
}

/// Settings from one byte each.
void Configure(ViewDependentRefinement& vdr, const uint8_t settings[4])
{
  vdr.SetPixelThreshold(settings[0] / 16.0);
  vdr.SetBackFaceSimplification((settings[1] & 1) != 0);
  vdr.SetSilhouetteRefinement((settings[1] & 2) != 0);
  vdr.SetHighlightRefinement((settings[1] & 4) != 0);
  vdr.SetWingDependencies((settings[1] & 8) != 0);
  vdr.SetSilhouetteFactor((settings[2] + 1) / 256.0);
  vdr.SetHighlightFactor((settings[3] + 1) / 256.0);
}
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  const MeshInput mesh = DecodeMesh(data, size);
  MergeTreeBuildOptions options;
  options.Collapse.PreserveBoundaries = (mesh.Flags & PreserveBoundaries) != 0;
  options.Collapse.PreserveFeatureEdges = (mesh.Flags & PreserveFeatureEdges) != 0;
  options.Collapse.MinimumTriangleQuality =
    (mesh.Flags & SliverRejection) ? mesh.Options[2] / 255.0 : 0.0;
  options.Errors.ShadingWeight = mesh.Options[3] / 64.0;
  MergeTreeBuildResult built;
  try
  {
    built = MergeTreeBuilder(options).Build(
      mesh.Points.data(), mesh.NumberOfPoints(), mesh.Triangles.data(), mesh.NumberOfTriangles());
  }
  catch (const std::invalid_argument&)
  {
    return 0; // bad ids or coordinates: fuzz_builder checks that contract
  }
  const TOMMesh& tom = built.TOM.Mesh;
  const uint32_t n = tom.GetNumberOfVertices();
  std::vector<double> points(3 * size_t(n));
  for (uint32_t v = 0; v < n; ++v)
  {
    for (int i = 0; i < 3; ++i)
    {
      points[3 * size_t(v) + i] = mesh.Points[3 * size_t(built.TOM.VertexOrder[v]) + i];
    }
  }
  const std::vector<float> floatPoints(points.begin(), points.end());

  Reader in(mesh.Tail.data(), mesh.Tail.size());
  // Uniform resolutions.
  const TOMTraversal traversal(tom);
  const int resolutions = in.Read<uint8_t>() % 4;
  for (int i = 0; i < resolutions; ++i)
  {
    const uint32_t triangles = traversal.GetTrianglesForResolution(in.Read<float>());
    CheckExtract(tom, traversal, traversal.GetVertexCountForTriangles(triangles));
  }

  // View-dependent refinement.
  const bool corrupted = (mesh.Flags & TargetBit2) != 0;
  MergeTree tree = built.Tree;
  if (corrupted)
  {
    Corrupt(tree, tom, in);
  }
  uint8_t settings[4];
  for (uint8_t& s : settings)
  {
    s = in.Read<uint8_t>();
  }
  ViewDependentRefinement vdr;
  ViewDependentRefinement reference; // fixed-accuracy fronts from the coarsest front
  Configure(vdr, settings);
  Configure(reference, settings);
  try
  {
    Initialize(vdr, tom, tree, points, floatPoints, (mesh.Flags & TargetBit0) != 0);
    Initialize(reference, tom, tree, points, floatPoints, (mesh.Flags & TargetBit0) != 0);
  }
  catch (const std::invalid_argument& e)
  {
    FUZZ_REQUIRE(corrupted, std::string("the builder's merge tree was rejected: ") + e.what());
    return 0;
  }
  FUZZ_REQUIRE(
    vdr.GetNumberOfVertices() == n && vdr.GetNumberOfBaseVertices() == tom.BaseVertexCount,
    "refinement sizes");
  if (!corrupted)
  {
    CheckFront(vdr, tom);
  }

  for (int update = 0; update < 6 && !in.AtEnd(); ++update)
  {
    const ViewInput view = DecodeView(in);
    if (view.Reset & 1)
    {
      vdr.Reset();
    }
    vdr.SetView(MakeView(view));
    const bool budget = (view.Mode & 1) != 0;
    if (budget)
    {
      vdr.SetOperationLimit(view.OperationLimit);
      vdr.UpdateBudget(view.Budget % (2 * tom.GetNumberOfTriangles() + 8));
    }
    else
    {
      vdr.UpdateFixedAccuracy();
    }
    CheckFrontBasics(vdr, tom, view.Budget & 0xff);
    if (corrupted)
    {
      continue;
    }
    CheckFront(vdr, tom);
    if (!budget)
    {
      // From the coarsest front: a fresh object (which also checks Reset()'s
      // front against Initialize()'s when the input asked for resets).
      ViewDependentRefinement fresh;
      ViewDependentRefinement& scratch = (view.Reset & 2) ? fresh : reference;
      if (view.Reset & 2)
      {
        Configure(fresh, settings);
        Initialize(fresh, tom, tree, points, floatPoints, (mesh.Flags & TargetBit0) != 0);
      }
      else
      {
        reference.Reset();
      }
      scratch.SetView(MakeView(view));
      scratch.UpdateFixedAccuracy();
      for (uint32_t v = 0; v < n; ++v)
      {
        FUZZ_REQUIRE(scratch.IsDisplayVertex(v) == vdr.IsDisplayVertex(v),
          "fixed-accuracy front of vertex " + std::to_string(v) +
            " depends on the previous front");
      }
    }
  }
  return 0;
}
