// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkExtractViewDependentMesh.
#include "FilterTestSupport.h"
#include "MergeTreeFilterTestSupport.h"
#include "MergeTree.h"
#include "TOMMesh.h"
#include "vtkExtractViewDependentMesh.h"
#include "vtkMergeTreeBuilder.h"
#include "vtkMergeTreeFieldData.h"
#include "vtkTOMBuilder.h"
#include "vtkTOMFieldData.h"

#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkTypeUInt16Array.h"
#include "vtkTypeUInt32Array.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace
{
namespace tt = timecritical::testing;
using tt::BuildTree;
using tt::Copy;
using tt::LinesOnly;
using tt::MakeSphere;
using tt::MessageLog;
using tt::PointKey;
using tt::SphereTree;
using Key = tt::PointKeyType;
}

// ---------------------------------------------------------------------------
// vtkExtractViewDependentMesh

namespace
{
struct Topology
{
  vtkIdType Vertices = 0;
  vtkIdType Edges = 0;
  vtkIdType Faces = 0;
  bool ClosedManifold = true; // every edge in exactly two triangles, once in each direction
  bool AllPointsUsed = true;
  vtkIdType Euler() const { return this->Vertices - this->Edges + this->Faces; }
};

Topology Analyze(vtkPolyData* mesh)
{
  Topology topology;
  topology.Vertices = mesh->GetNumberOfPoints();
  topology.Faces = mesh->GetNumberOfPolys();
  std::map<std::pair<vtkIdType, vtkIdType>, int> directed;
  std::vector<bool> used(mesh->GetNumberOfPoints(), false);
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    vtkIdType size;
    const vtkIdType* ids;
    mesh->GetCellPoints(c, size, ids);
    if (size != 3)
    {
      topology.ClosedManifold = false;
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      used[ids[k]] = true;
      ++directed[{ ids[k], ids[(k + 1) % 3] }];
    }
  }
  std::set<std::pair<vtkIdType, vtkIdType>> undirected;
  for (const auto& entry : directed)
  {
    const auto& edge = entry.first;
    undirected.insert({ std::min(edge.first, edge.second), std::max(edge.first, edge.second) });
    const auto reverse = directed.find({ edge.second, edge.first });
    if (entry.second != 1 || reverse == directed.end() || reverse->second != 1)
    {
      topology.ClosedManifold = false;
    }
  }
  topology.Edges = static_cast<vtkIdType>(undirected.size());
  topology.AllPointsUsed = std::all_of(used.begin(), used.end(), [](bool u) { return u; });
  return topology;
}

void LookAt(vtkCamera* camera, double x, double y, double z)
{
  camera->SetFocalPoint(0, 0, 0);
  camera->SetPosition(x, y, z);
  camera->SetViewUp(0, 1, 0);
  if (std::abs(x) < 1e-9 && std::abs(z) < 1e-9)
  {
    camera->SetViewUp(0, 0, 1);
  }
}

vtkIdType Triangles(vtkExtractViewDependentMesh* extract)
{
  extract->Update();
  return extract->GetOutput()->GetNumberOfPolys();
}

// The sphere tree's coarsest and full triangle counts.
std::pair<vtkIdType, vtkIdType> SphereTriangleRange()
{
  vtkNew<vtkTOMFieldData> tom;
  EXPECT_TRUE(tom->Read(SphereTree()));
  return { tom->GetBaseTriangleCount(), tom->GetNumberOfTriangles() };
}
}

TEST(vtkExtractViewDependentMesh, FrontOfAClosedSurfaceIsAClosedManifold)
{
  vtkNew<vtkExtractViewDependentMesh> extract;
  MessageLog log(extract);
  extract->SetInputData(SphereTree());
  vtkNew<vtkCamera> camera;
  extract->SetCamera(camera);
  const std::array<std::array<double, 3>, 4> eyes = { { { 0, 0, 3 }, { 2, 1, 0.5 },
    { 0.2, -0.3, 0.9 }, { 0, 5, 0 } } };
  std::set<vtkIdType> counts;
  for (const auto& eye : eyes)
  {
    for (double tau : { 0.5, 2.0, 8.0 })
    {
      for (bool budget : { false, true })
      {
        SCOPED_TRACE("eye " + std::to_string(eye[0]) + " " + std::to_string(eye[1]) + " " +
          std::to_string(eye[2]) + ", tau " + std::to_string(tau) +
          (budget ? ", budget" : ", fixed accuracy"));
        LookAt(camera, eye[0], eye[1], eye[2]);
        extract->SetPixelThreshold(tau);
        extract->SetSilhouetteRefinement(tau > 1.0);
        extract->SetRefinementMode(budget ? vtkExtractViewDependentMesh::TRIANGLE_BUDGET
                                          : vtkExtractViewDependentMesh::FIXED_ACCURACY);
        extract->SetTriangleBudget(static_cast<vtkIdType>(2000 / tau));
        extract->Update();
        vtkPolyData* front = extract->GetOutput();
        const Topology topology = Analyze(front);
        EXPECT_TRUE(topology.ClosedManifold);
        EXPECT_TRUE(topology.AllPointsUsed);
        EXPECT_EQ(topology.Euler(), 2) << "V " << topology.Vertices << " E " << topology.Edges
                                       << " F " << topology.Faces;
        EXPECT_EQ(front->GetNumberOfPolys(), extract->GetNumberOfDisplayTriangles());
        EXPECT_EQ(front->GetNumberOfPoints(), extract->GetNumberOfDisplayVertices());
        counts.insert(front->GetNumberOfPolys());
      }
    }
  }
  EXPECT_TRUE(log.Errors.empty()) << log.AllErrors();
  EXPECT_GT(counts.size(), 4u) << "the fronts should differ with the view and the threshold";
}

TEST(vtkExtractViewDependentMesh, TriangleCountDecreasesWithThreshold)
{
  const auto range = SphereTriangleRange();
  vtkNew<vtkExtractViewDependentMesh> extract;
  extract->SetInputData(SphereTree());
  LookAt(extract->GetCamera(), 0, 0, 3);
  extract->BackFaceSimplificationOff();
  extract->FrustumCullingOff();
  extract->SetPixelThreshold(0.0);
  EXPECT_EQ(Triangles(extract), range.second) << "tau = 0 without culling is the full mesh";
  vtkIdType previous = range.second;
  std::vector<vtkIdType> counts;
  for (double tau : { 0.05, 0.25, 0.5, 1.0, 2.0, 4.0, 8.0, 16.0, 64.0, 1e6 })
  {
    extract->SetPixelThreshold(tau);
    const vtkIdType count = Triangles(extract);
    EXPECT_LE(count, previous) << "tau " << tau;
    previous = count;
    counts.push_back(count);
  }
  EXPECT_LT(counts[5], range.second / 2) << "4 pixels should simplify a 40x40 sphere a lot";
  EXPECT_EQ(counts.back(), range.first) << "an enormous threshold gives the coarsest mesh";
  // Going back to a small threshold refines again: the front follows the view, not its history.
  extract->SetPixelThreshold(0.5);
  EXPECT_EQ(Triangles(extract), counts[2]);
}

TEST(vtkExtractViewDependentMesh, MovingTheCameraReExecutes)
{
  vtkNew<vtkExtractViewDependentMesh> extract;
  extract->SetInputData(SphereTree());
  vtkNew<vtkCamera> camera;
  LookAt(camera, 0, 0, 40);
  extract->SetCamera(camera);
  extract->SetPixelThreshold(1.0);
  int executions = 0;
  vtkNew<vtkCallbackCommand> count;
  count->SetClientData(&executions);
  count->SetCallback(
    [](vtkObject*, unsigned long, void* client, void*) { ++*static_cast<int*>(client); });
  extract->AddObserver(vtkCommand::EndEvent, count);
  const vtkIdType far = Triangles(extract);
  EXPECT_EQ(executions, 1);
  extract->Update();
  EXPECT_EQ(executions, 1) << "nothing changed: no new execution";
  camera->SetPosition(0, 0, 2); // through the camera object, not the filter
  const vtkIdType near = Triangles(extract);
  EXPECT_EQ(executions, 2);
  EXPECT_GT(near, far) << "closer means more detail";
  extract->SetCameraPosition(0, 0, 40); // through the filter's proxy setter
  EXPECT_EQ(camera->GetPosition()[2], 40.0);
  EXPECT_EQ(Triangles(extract), far);
  EXPECT_EQ(executions, 3);
  EXPECT_GE(extract->GetNumberOfMerges(), 1);
}

TEST(vtkExtractViewDependentMesh, BackFacesAndOutsideTheFrustumStayCoarse)
{
  vtkNew<vtkExtractViewDependentMesh> extract;
  extract->SetInputData(SphereTree());
  LookAt(extract->GetCamera(), 0, 0, 3);
  extract->SetPixelThreshold(0.5);
  extract->BackFaceSimplificationOff();
  extract->FrustumCullingOff();
  const vtkIdType all = Triangles(extract);
  extract->BackFaceSimplificationOn();
  const vtkIdType front = Triangles(extract);
  EXPECT_LT(front, all);
  // Triangles facing away from the eye are larger on average.
  vtkPolyData* mesh = extract->GetOutput();
  double area[2] = { 0, 0 };
  int number[2] = { 0, 0 };
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    const vtkIdType* ids;
    vtkIdType size;
    mesh->GetCellPoints(c, size, ids);
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      mesh->GetPoint(ids[k], p[k]);
    }
    const double u[3] = { p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2] };
    const double v[3] = { p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2] };
    const double n[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
      u[0] * v[1] - u[1] * v[0] };
    const double centroidZ = (p[0][2] + p[1][2] + p[2][2]) / 3.0;
    const int back = centroidZ < -0.1 ? 1 : 0;
    if (centroidZ > 0.1 || back)
    {
      area[back] += 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      ++number[back];
    }
  }
  ASSERT_GT(number[0], 0);
  ASSERT_GT(number[1], 0);
  EXPECT_GT(area[1] / number[1], 2.0 * area[0] / number[0]);
  EXPECT_GT(number[0], number[1]);

  // Looking away from the sphere, far enough for its nodes' bounding spheres
  // to lie behind the frustum's side planes: nothing is refined.
  extract->FrustumCullingOn();
  extract->BackFaceSimplificationOff();
  LookAt(extract->GetCamera(), 0, 0, 30);
  extract->GetCamera()->SetFocalPoint(0, 0, 60);
  EXPECT_EQ(Triangles(extract), SphereTriangleRange().first);
}

namespace
{
// Triangles of `mesh` whose centroid lies within `degrees` of `direction` as
// seen from the origin (the sphere's centre).
int TrianglesAround(vtkPolyData* mesh, const double direction[3], double degrees)
{
  const double length = std::sqrt(
    direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
  int count = 0;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    const vtkIdType* ids;
    vtkIdType size;
    mesh->GetCellPoints(c, size, ids);
    double centroid[3] = { 0, 0, 0 };
    for (int k = 0; k < 3; ++k)
    {
      double p[3];
      mesh->GetPoint(ids[k], p);
      for (int i = 0; i < 3; ++i)
      {
        centroid[i] += p[i] / 3.0;
      }
    }
    const double norm =
      std::sqrt(centroid[0] * centroid[0] + centroid[1] * centroid[1] + centroid[2] * centroid[2]);
    const double cosine =
      (centroid[0] * direction[0] + centroid[1] * direction[1] + centroid[2] * direction[2]) /
      (norm * length);
    count += cosine >= std::cos(degrees * 3.14159265358979 / 180.0) ? 1 : 0;
  }
  return count;
}
}

TEST(vtkExtractViewDependentMesh, SilhouetteAndHighlightRefinementAddDetail)
{
  vtkNew<vtkExtractViewDependentMesh> extract;
  extract->SetInputData(SphereTree());
  LookAt(extract->GetCamera(), 0, 0, 3);
  extract->SetPixelThreshold(4.0);
  // Both on by default, as in the mapper and the renderer.
  EXPECT_TRUE(extract->GetSilhouetteRefinement());
  EXPECT_TRUE(extract->GetHighlightRefinement());
  EXPECT_EQ(extract->GetHighlightFactor(), 0.5);
  extract->SilhouetteRefinementOff();
  extract->HighlightRefinementOff();
  const vtkIdType plain = Triangles(extract);
  const double towardsEye[3] = { 0, 0, 1 };
  const int plainAtCentre = TrianglesAround(extract->GetOutput(), towardsEye, 20.0);
  extract->SilhouetteRefinementOn();
  extract->SetSilhouetteFactor(0.1);
  const vtkIdType silhouette = Triangles(extract);
  EXPECT_GT(silhouette, plain);
  extract->SilhouetteRefinementOff();

  // Light at the eye: the highlight is at the centre of the view.
  extract->HighlightRefinementOn();
  extract->SetHighlightFactor(0.1);
  extract->SetLightDirection(0, 0, 1);
  const vtkIdType highlight = Triangles(extract);
  EXPECT_GT(highlight, plain);
  const int highlightAtCentre = TrianglesAround(extract->GetOutput(), towardsEye, 20.0);
  EXPECT_GT(highlightAtCentre, plainAtCentre);
  // Light from +x: the highlight moves halfway between light and eye.
  extract->SetLightDirection(1, 0, 0);
  extract->Update();
  const double halfway[3] = { 1, 0, 1 };
  const double opposite[3] = { -1, 0, 1 };
  EXPECT_GT(TrianglesAround(extract->GetOutput(), halfway, 20.0),
    2 * TrianglesAround(extract->GetOutput(), opposite, 20.0));
}

TEST(vtkExtractViewDependentMesh, TriangleBudget)
{
  const auto range = SphereTriangleRange();
  vtkNew<vtkExtractViewDependentMesh> extract;
  extract->SetInputData(SphereTree());
  LookAt(extract->GetCamera(), 1, 2, 3);
  extract->SetRefinementModeToTriangleBudget();
  // The threshold is a floor in budget mode: at 0 only the budget limits the front.
  extract->SetPixelThreshold(0.0);
  vtkIdType previous = 0;
  for (vtkIdType budget : { vtkIdType(0), vtkIdType(100), vtkIdType(400), vtkIdType(1000),
         vtkIdType(2000) })
  {
    extract->SetTriangleBudget(budget);
    const vtkIdType count = Triangles(extract);
    EXPECT_LE(count, std::max(budget, range.first) + 16) << "budget " << budget;
    EXPECT_GE(count, previous);
    if (budget >= 100)
    {
      EXPECT_GT(count, budget * 3 / 4) << "budget " << budget;
    }
    previous = count;
  }
  EXPECT_EQ(extract->GetRefinementMode(), vtkExtractViewDependentMesh::TRIANGLE_BUDGET);
}

TEST(vtkExtractViewDependentMesh, PointAndCellDataOfTheFront)
{
  vtkPolyData* tree = SphereTree();
  vtkNew<vtkMergeTreeFieldData> reader;
  ASSERT_TRUE(reader->Read(tree));
  vtkNew<vtkExtractViewDependentMesh> extract;
  extract->SetInputData(tree);
  LookAt(extract->GetCamera(), 0, 1, 2);
  extract->SetPixelThreshold(3.0);
  extract->GenerateLocalLevelsOn();
  extract->Update();
  vtkPolyData* front = extract->GetOutput();
  ASSERT_GT(front->GetNumberOfPolys(), 0);
  std::map<Key, vtkIdType> treeIds;
  for (vtkIdType i = 0; i < tree->GetNumberOfPoints(); ++i)
  {
    treeIds[PointKey(tree, i)] = i;
  }
  vtkDataArray* normals = front->GetPointData()->GetNormals();
  ASSERT_NE(normals, nullptr);
  for (vtkIdType i = 0; i < front->GetNumberOfPoints(); ++i)
  {
    const auto found = treeIds.find(PointKey(front, i));
    ASSERT_NE(found, treeIds.end()) << "output points are input points";
    for (int c = 0; c < 3; ++c)
    {
      ASSERT_EQ(normals->GetComponent(i, c),
        tree->GetPointData()->GetNormals()->GetComponent(found->second, c));
    }
  }
  // Each triangle carries the cell data of a TOM triangle it comes from: one
  // whose corners are the triangle's corners or merged into them.
  vtkDataArray* cellIds = front->GetCellData()->GetArray("InputCellId");
  ASSERT_NE(cellIds, nullptr);
  std::set<double> distinct;
  for (vtkIdType c = 0; c < front->GetNumberOfCells(); ++c)
  {
    distinct.insert(cellIds->GetTuple1(c));
  }
  EXPECT_EQ(static_cast<vtkIdType>(distinct.size()), front->GetNumberOfCells());
  // TOM and merge-tree arrays do not describe the front.
  for (const char* name : { "TOMSubstitution", "MergeTreeLevel", "MergeTreeError",
         "MergeTreeRadius", "MergeTreeConeAxis", "MergeTreeConeCosine" })
  {
    EXPECT_EQ(front->GetPointData()->GetAbstractArray(name), nullptr) << name;
  }
  for (const char* name : { "TOMCounts", "TOMErrorCurve", "MergeTreeDependencyOffsets",
         "MergeTreeDependencies", "MergeTreeLevelCount" })
  {
    EXPECT_EQ(front->GetFieldData()->GetAbstractArray(name), nullptr) << name;
  }
  // Local levels: within [0, LevelCount], coarser on the back.
  auto* levels = vtkTypeUInt16Array::SafeDownCast(
    front->GetCellData()->GetArray(vtkExtractViewDependentMesh::LocalLevelArrayName()));
  ASSERT_NE(levels, nullptr);
  int maximum = 0;
  for (vtkIdType c = 0; c < levels->GetNumberOfValues(); ++c)
  {
    maximum = std::max<int>(maximum, levels->GetValue(c));
  }
  EXPECT_GT(maximum, 0);
  EXPECT_LE(maximum, reader->GetLevelCount());

  // At full resolution every local level is 0.
  extract->BackFaceSimplificationOff();
  extract->FrustumCullingOff();
  extract->SetPixelThreshold(0.0);
  extract->Update();
  levels = vtkTypeUInt16Array::SafeDownCast(
    extract->GetOutput()->GetCellData()->GetArray(vtkExtractViewDependentMesh::LocalLevelArrayName()));
  ASSERT_NE(levels, nullptr);
  EXPECT_EQ(levels->GetValueRange()[1], 0);
  EXPECT_EQ(extract->GetOutput()->GetNumberOfPoints(), tree->GetNumberOfPoints());
}

TEST(vtkExtractViewDependentMesh, ParallelProjectionAndViewport)
{
  vtkNew<vtkExtractViewDependentMesh> extract;
  extract->SetInputData(SphereTree());
  extract->SetCameraPosition(0, 0, 5);
  extract->SetCameraFocalPoint(0, 0, 0);
  extract->SetCameraViewUp(0, 1, 0);
  extract->SetCameraParallelProjection(true);
  extract->SetCameraParallelScale(0.6);
  extract->SetPixelThreshold(2.0);
  const vtkIdType small = Triangles(extract);
  extract->SetViewportSize(2048, 2048);
  const vtkIdType large = Triangles(extract);
  EXPECT_GT(large, small) << "more pixels, more detail";
  extract->SetCameraParallelScale(6.0);
  EXPECT_LT(Triangles(extract), large) << "zoomed out, less detail";
  EXPECT_TRUE(extract->GetCamera()->GetParallelProjection());
}

TEST(vtkExtractViewDependentMesh, BadSettingsAreRejected)
{
  vtkNew<vtkExtractViewDependentMesh> extract;
  MessageLog log(extract);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const vtkMTimeType before = extract->GetMTime();
  extract->SetPixelThreshold(nan);
  extract->SetSilhouetteFactor(nan);
  extract->SetHighlightFactor(nan);
  extract->SetLightDirection(nan, 0, 1);
  extract->SetLightDirection(0, 0, 0);
  extract->SetViewportSize(0, 100);
  extract->SetCameraPosition(nan, 0, 0);
  extract->SetCameraFocalPoint(0, nan, 0);
  extract->SetCameraViewUp(0, 0, 0);
  extract->SetCameraViewAngle(nan);
  extract->SetCameraViewAngle(200);
  extract->SetCameraParallelScale(-1);
  EXPECT_EQ(log.Errors.size(), 12u);
  EXPECT_TRUE(log.ErrorContains("PixelThreshold must be a finite number >= 0"));
  EXPECT_TRUE(log.ErrorContains("LightDirection must be a finite, non-zero vector"));
  EXPECT_TRUE(log.ErrorContains("ViewportSize must be at least 1 x 1"));
  EXPECT_EQ(extract->GetMTime(), before);
  EXPECT_EQ(extract->GetPixelThreshold(), 1.0);
  EXPECT_EQ(extract->GetViewportSize()[0], 512);
  EXPECT_EQ(extract->GetLightDirection()[2], 1.0);
  // Out-of-range numbers are rejected as in the mapper and the renderer
  // (RefinementSettings.h): an error, and the setting stays.
  extract->SetPixelThreshold(-3.0);
  EXPECT_EQ(extract->GetPixelThreshold(), 1.0);
  extract->SetSilhouetteFactor(0.0);
  EXPECT_EQ(extract->GetSilhouetteFactor(), 0.25);
  extract->SetHighlightFactor(1.5);
  EXPECT_EQ(extract->GetHighlightFactor(), 0.5);
  extract->SetTriangleBudget(-1);
  EXPECT_EQ(extract->GetTriangleBudget(), 10000);
  EXPECT_EQ(log.Errors.size(), 16u);
  EXPECT_TRUE(log.ErrorContains("SilhouetteFactor must be in (0, 1], not 0; ignored."));
  EXPECT_TRUE(log.ErrorContains("TriangleBudget must be an integer in [0, 2147483647]"));
  EXPECT_EQ(extract->GetMTime(), before);
  // Modes are clamped (VTK's clamp macro), as in the mapper and the renderer.
  extract->SetRefinementMode(7);
  EXPECT_EQ(extract->GetRefinementMode(), vtkExtractViewDependentMesh::FIXED_ACCURACY);
  extract->SetRefinementMode(-2);
  EXPECT_EQ(extract->GetRefinementMode(), vtkExtractViewDependentMesh::BUDGET);
  // The own camera comes back after SetCamera(nullptr).
  extract->SetCamera(nullptr);
  EXPECT_NE(extract->GetCamera(), nullptr);
}

TEST(vtkExtractViewDependentMesh, EmptyAndForeignInput)
{
  vtkNew<vtkExtractViewDependentMesh> extract;
  MessageLog log(extract);
  vtkNew<vtkPolyData> empty;
  extract->SetInputData(empty);
  extract->Update();
  EXPECT_TRUE(log.Errors.empty()) << log.AllErrors();
  EXPECT_EQ(extract->GetOutput()->GetNumberOfPoints(), 0);

  extract->SetInputData(MakeSphere(8));
  extract->Update();
  EXPECT_TRUE(log.ErrorContains("Input is not a valid merge tree: not a merge tree"))
    << log.AllErrors();
  EXPECT_EQ(extract->GetOutput()->GetNumberOfPoints(), 0);

  // Merge-tree arrays on no points at all: an empty tree, whether valid or not, is no crash.
  vtkNew<vtkPolyData> emptyTree;
  vtkMergeTreeFieldData::Write(timecritical::TOMMesh(), timecritical::MergeTree(), emptyTree);
  extract->SetInputData(emptyTree);
  extract->Update();
  EXPECT_EQ(extract->GetOutput()->GetNumberOfPoints(), 0);

  // A valid tree afterwards works again.
  log.Errors.clear();
  extract->SetInputData(SphereTree());
  extract->Update();
  EXPECT_TRUE(log.Errors.empty()) << log.AllErrors();
  EXPECT_GT(extract->GetOutput()->GetNumberOfPolys(), 0);
}

TEST(vtkExtractViewDependentMesh, RealMeshWhenAvailable)
{
  const std::string cow = std::string(TIMECRITICAL_SHARED_DATA_DIR) + "/cow.obj";
  if (!std::ifstream(cow).good())
  {
    GTEST_SKIP() << cow << " not found";
  }
  vtkNew<vtkOBJReader> obj;
  obj->SetFileName(cow.c_str());
  vtkNew<vtkMergeTreeBuilder> builder;
  builder->SetInputConnection(obj->GetOutputPort());
  vtkNew<vtkExtractViewDependentMesh> extract;
  extract->SetInputConnection(builder->GetOutputPort());
  builder->Update();
  double bounds[6];
  builder->GetOutput()->GetBounds(bounds);
  const double center[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  const double size = bounds[1] - bounds[0] + bounds[3] - bounds[2] + bounds[5] - bounds[4];
  extract->SetCameraFocalPoint(center[0], center[1], center[2]);
  extract->SetCameraPosition(center[0], center[1], center[2] + 2 * size);
  extract->SetPixelThreshold(1.0);
  const Topology full = Analyze(builder->GetOutput());
  extract->Update();
  const Topology front = Analyze(extract->GetOutput());
  EXPECT_EQ(front.Euler(), full.Euler());
  EXPECT_EQ(front.ClosedManifold, full.ClosedManifold);
  EXPECT_LT(front.Faces, full.Faces);
  EXPECT_GT(front.Faces, 0);
}

TEST(vtkExtractViewDependentMesh, PrintSelfReportsSettings)
{
  vtkNew<vtkExtractViewDependentMesh> extract;
  std::ostringstream text;
  extract->Print(text);
  for (const char* expected :
    { "PixelThreshold: 1", "RefinementMode: FIXED_ACCURACY", "ViewportSize: 512 x 512" })
  {
    EXPECT_NE(text.str().find(expected), std::string::npos) << expected;
  }
}

TEST(vtkExtractViewDependentMesh, ModesAreNumberedAsInTheMapperAndRenderer)
{
  EXPECT_EQ(vtkExtractViewDependentMesh::BUDGET, 0);
  EXPECT_EQ(vtkExtractViewDependentMesh::FIXED_ACCURACY, 1);
  // The budget mode's former name stays an alias.
  EXPECT_EQ(vtkExtractViewDependentMesh::TRIANGLE_BUDGET, vtkExtractViewDependentMesh::BUDGET);
  vtkNew<vtkExtractViewDependentMesh> extract;
  EXPECT_EQ(extract->GetRefinementMode(), vtkExtractViewDependentMesh::FIXED_ACCURACY);
  extract->SetRefinementModeToTriangleBudget();
  EXPECT_EQ(extract->GetRefinementMode(), vtkExtractViewDependentMesh::BUDGET);
  extract->SetRefinementModeToFixedAccuracy();
  extract->SetRefinementModeToBudget();
  EXPECT_EQ(extract->GetRefinementMode(), vtkExtractViewDependentMesh::BUDGET);
}

TEST(vtkExtractViewDependentMesh, LegacyModeTranslatesTheFormerNumbering)
{
  vtkNew<vtkExtractViewDependentMesh> extract;
  MessageLog log(extract);
  extract->SetRefinementModeToBudget();
  extract->SetLegacyRefinementMode(0); // formerly fixed accuracy
  EXPECT_EQ(extract->GetRefinementMode(), vtkExtractViewDependentMesh::FIXED_ACCURACY);
  extract->SetLegacyRefinementMode(1); // formerly the triangle budget
  EXPECT_EQ(extract->GetRefinementMode(), vtkExtractViewDependentMesh::BUDGET);
  EXPECT_TRUE(log.Errors.empty());
  extract->SetLegacyRefinementMode(2);
  EXPECT_EQ(extract->GetRefinementMode(), vtkExtractViewDependentMesh::BUDGET);
  EXPECT_EQ(log.Errors.size(), 1u);
  EXPECT_TRUE(log.ErrorContains("former RefinementMode must be 0 (fixed accuracy) or 1"));
}

TEST(vtkExtractViewDependentMesh, BudgetModeOutputMatchesTheBudget)
{
  vtkNew<vtkExtractViewDependentMesh> extract;
  extract->SetInputData(SphereTree());
  LookAt(extract->GetCamera(), 0, 0, 3);
  extract->SetPixelThreshold(0.0);
  extract->SetTriangleBudget(300);
  extract->SetLegacyRefinementMode(1);
  const vtkIdType budget = Triangles(extract);
  EXPECT_LE(budget, 300 + 16);
  EXPECT_GT(budget, 300 * 3 / 4);
  extract->SetLegacyRefinementMode(0);
  EXPECT_GT(Triangles(extract), 300) << "fixed accuracy at 0 px: full detail in view";
}
