// SPDX-License-Identifier: BSD-3-Clause
// Tests of the VTK-free mesh support library (Testing/Support/MeshIO.h):
// the shared meshes load with the counts of ../shared/data/README.md, igea's
// triangle strips decode to a closed consistently wound surface, OBJ/PLY
// variants parse (through OpenMesh's readers), what OpenMesh would misread or
// skip silently is reported as an error, and the generators are clean.
#include "MeshIO.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

using namespace timecritical::testing;

namespace
{
#define REQUIRE_SHARED_MESH(variable, name)                                                        \
  const SharedMesh variable = FindSharedMesh(name);                                                \
  if (!variable.Available)                                                                         \
  {                                                                                                \
    GTEST_SKIP() << "shared mesh not available: " << variable.Path;                                \
  }

/// A file in the temporary folder, removed when it goes out of scope.
class TempFile
{
public:
  explicit TempFile(const std::string& suffix)
  {
    static unsigned counter = 0;
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::random_device random;
    this->Path = (std::filesystem::temp_directory_path() /
      ("timecritical-meshio-" + std::string(info ? info->name() : "test") + "-" +
        std::to_string(random()) + "-" + std::to_string(counter++) + suffix))
                   .string();
  }
  ~TempFile()
  {
    std::error_code ec;
    std::filesystem::remove(this->Path, ec);
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;

  const std::string& Write(const std::string& contents) const
  {
    std::ofstream out(this->Path, std::ios::binary);
    out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
    EXPECT_TRUE(out.good()) << "cannot write " << this->Path;
    return this->Path;
  }

  std::string Path;
};

std::string ReadBytes(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// Binary buffer with a chosen byte order.
class Bytes
{
public:
  explicit Bytes(bool bigEndian)
    : BigEndian(bigEndian)
  {
  }
  template <class T>
  Bytes& Put(T value)
  {
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    const uint16_t one = 1;
    unsigned char hostFirst;
    std::memcpy(&hostFirst, &one, 1);
    const bool hostLittle = hostFirst == 1;
    if (this->BigEndian == hostLittle)
    {
      std::reverse(raw, raw + sizeof(T));
    }
    this->Data.append(reinterpret_cast<const char*>(raw), sizeof(T));
    return *this;
  }
  bool BigEndian;
  std::string Data;
};

/// Runs `load` and checks that it throws std::runtime_error whose message
/// contains every one of `fragments`.
void ExpectLoadError(const std::function<void()>& load, const std::vector<std::string>& fragments)
{
  try
  {
    load();
    ADD_FAILURE() << "no exception thrown";
  }
  catch (const std::runtime_error& error)
  {
    const std::string message = error.what();
    for (const std::string& fragment : fragments)
    {
      EXPECT_NE(message.find(fragment), std::string::npos)
        << "message '" << message << "' lacks '" << fragment << "'";
    }
  }
}

using Triangle = std::array<uint32_t, 3>;

std::vector<Triangle> TrianglesOf(const TriangleMesh& mesh)
{
  std::vector<Triangle> triangles;
  for (std::size_t t = 0; t < mesh.NumberOfTriangles(); ++t)
  {
    triangles.push_back(
      { mesh.Triangles[3 * t], mesh.Triangles[3 * t + 1], mesh.Triangles[3 * t + 2] });
  }
  return triangles;
}

/// Independent check of a closed, consistently wound 2-manifold: every
/// directed edge occurs exactly once and its reverse occurs too.
void ExpectClosedAndConsistent(const TriangleMesh& mesh)
{
  std::vector<uint64_t> directed; // (from << 32) | to
  directed.reserve(3 * mesh.NumberOfTriangles());
  for (std::size_t t = 0; t < mesh.NumberOfTriangles(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const uint64_t a = mesh.Triangles[3 * t + k];
      const uint64_t b = mesh.Triangles[3 * t + (k + 1) % 3];
      directed.push_back((a << 32) | b);
    }
  }
  std::sort(directed.begin(), directed.end());
  std::size_t repeated = 0;
  std::size_t unmatched = 0;
  for (std::size_t i = 0; i < directed.size(); ++i)
  {
    if (i > 0 && directed[i] == directed[i - 1])
    {
      ++repeated;
    }
    const uint64_t reverse = (directed[i] << 32) | (directed[i] >> 32);
    if (!std::binary_search(directed.begin(), directed.end(), reverse))
    {
      ++unmatched;
    }
  }
  EXPECT_EQ(repeated, 0u) << "directed edges used twice (inconsistent winding or non-manifold)";
  EXPECT_EQ(unmatched, 0u) << "directed edges without an opposite (boundary or flipped triangle)";
}

/// Number of points whose position (equal coordinates) repeats an earlier point's.
std::size_t CountDuplicatePositions(const TriangleMesh& mesh)
{
  std::vector<std::array<double, 3>> positions(mesh.NumberOfPoints());
  for (std::size_t i = 0; i < positions.size(); ++i)
  {
    positions[i] = { mesh.Points[3 * i] + 0.0, mesh.Points[3 * i + 1] + 0.0,
      mesh.Points[3 * i + 2] + 0.0 }; // + 0.0 turns -0.0 into 0.0
  }
  std::sort(positions.begin(), positions.end());
  return static_cast<std::size_t>(
    positions.end() - std::unique(positions.begin(), positions.end()));
}

/// The loaders read through OpenMesh, in single precision.
TriangleMesh RoundedToFloat(TriangleMesh mesh)
{
  for (double& value : mesh.Points)
  {
    value = static_cast<float>(value);
  }
  return mesh;
}

void ExpectSameMesh(const TriangleMesh& expected, const TriangleMesh& actual)
{
  EXPECT_EQ(expected.Points, actual.Points);
  EXPECT_EQ(expected.Triangles, actual.Triangles);
}

/// Checks a clean closed outward-wound surface; returns its topology.
MeshTopology ExpectCleanClosed(const TriangleMesh& mesh, long long euler)
{
  const MeshTopology topology = ComputeTopology(mesh);
  EXPECT_EQ(topology.NumberOfUnusedPoints, 0u);
  EXPECT_EQ(topology.NumberOfDegenerateTriangles, 0u);
  EXPECT_EQ(topology.NumberOfBoundaryEdges, 0u);
  EXPECT_EQ(topology.NumberOfNonManifoldEdges, 0u);
  EXPECT_EQ(topology.NumberOfInconsistentEdges, 0u);
  EXPECT_EQ(topology.NumberOfNonManifoldVertices, 0u);
  EXPECT_EQ(topology.NumberOfComponents, 1u);
  EXPECT_TRUE(topology.IsClosed());
  EXPECT_TRUE(topology.IsConsistentlyOriented());
  EXPECT_EQ(topology.EulerCharacteristic, euler);
  EXPECT_EQ(topology.NumberOfEdges * 2, 3 * mesh.NumberOfTriangles());
  EXPECT_GT(SignedVolume(mesh), 0.0) << "winding must be outward";
  EXPECT_EQ(CountDuplicatePositions(mesh), 0u);
  ExpectClosedAndConsistent(mesh);
  return topology;
}

//------------------------------------------------------------------------------
// Shared meshes: the README table.

struct SharedMeshCase
{
  const char* Name;
  std::size_t Vertices;
  std::size_t Triangles;
  std::size_t UnusedVertices;
  std::size_t BoundaryEdges; // as loaded, before welding
};

std::ostream& operator<<(std::ostream& out, const SharedMeshCase& c)
{
  return out << c.Name;
}

class SharedMeshCounts : public ::testing::TestWithParam<SharedMeshCase>
{
};

TEST_P(SharedMeshCounts, MatchReadme)
{
  const SharedMeshCase& expected = GetParam();
  REQUIRE_SHARED_MESH(shared, expected.Name);
  const TriangleMesh mesh = LoadMesh(shared.Path);
  EXPECT_EQ(mesh.NumberOfPoints(), expected.Vertices);
  EXPECT_EQ(mesh.NumberOfTriangles(), expected.Triangles);
  EXPECT_EQ(mesh.Points.size(), 3 * mesh.NumberOfPoints());
  const MeshTopology topology = ComputeTopology(mesh);
  EXPECT_EQ(topology.NumberOfUnusedPoints, expected.UnusedVertices);
  EXPECT_EQ(topology.NumberOfBoundaryEdges, expected.BoundaryEdges);
  // README: "None has non-triangle faces or edges shared by more than two
  // triangles; winding is consistent."
  EXPECT_EQ(topology.NumberOfDegenerateTriangles, 0u);
  EXPECT_EQ(topology.NumberOfNonManifoldEdges, 0u);
  EXPECT_EQ(topology.NumberOfInconsistentEdges, 0u);
  for (double coordinate : mesh.Points)
  {
    ASSERT_TRUE(std::isfinite(coordinate));
  }
}

INSTANTIATE_TEST_SUITE_P(SharedData, SharedMeshCounts,
  ::testing::Values(SharedMeshCase{ "igea.ply", 134345, 268686, 0, 0 },
    SharedMeshCase{ "stanford-bunny.obj", 35947, 69451, 1113, 223 },
    SharedMeshCase{ "fandisk.obj", 6475, 12946, 0, 0 },
    SharedMeshCase{ "homer.obj", 6002, 12000, 0, 0 },
    SharedMeshCase{ "teapot.obj", 3644, 6320, 0, 1036 },
    SharedMeshCase{ "spot.obj", 2930, 5856, 0, 0 }, SharedMeshCase{ "cow.obj", 2903, 5804, 0, 0 }),
  [](const ::testing::TestParamInfo<SharedMeshCase>& paramInfo)
  {
    std::string name = paramInfo.param.Name;
    std::replace_if(
      name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); },
      '_');
    return name;
  });

TEST(SharedData, FolderLookup)
{
  EXPECT_FALSE(SharedDataDirectory().empty());
  const SharedMesh missing = FindSharedMesh("no-such-mesh.obj");
  EXPECT_FALSE(missing.Available);
  EXPECT_EQ(missing.Path, SharedDataDirectory() + "/no-such-mesh.obj");
  const SharedMesh igea = FindSharedMesh("igea.ply");
  EXPECT_EQ(igea.Available, std::filesystem::is_regular_file(igea.Path));
}

TEST(SharedData, IgeaStripsDecodeToClosedConsistentSurface)
{
  REQUIRE_SHARED_MESH(shared, "igea.ply");
  // The header really is a binary PLY with one tristrips element.
  const std::string bytes = ReadBytes(shared.Path);
  ASSERT_NE(bytes.find("format binary_little_endian 1.0"), std::string::npos);
  ASSERT_NE(bytes.find("element tristrips"), std::string::npos);
  ASSERT_EQ(bytes.find("element face"), std::string::npos);

  const TriangleMesh mesh = LoadMesh(shared.Path);
  ASSERT_EQ(mesh.NumberOfPoints(), 134345u);
  ASSERT_EQ(mesh.NumberOfTriangles(), 268686u);
  // Closed genus-0 surface, every vertex used, no degenerate joins left.
  const MeshTopology topology = ExpectCleanClosed(mesh, 2);
  EXPECT_EQ(topology.NumberOfEdges, 403029u);
  EXPECT_EQ(topology.NumberOfBoundaryLoops, 0u);
  // No triangle appears twice (with either winding).
  std::vector<Triangle> sorted = TrianglesOf(mesh);
  for (Triangle& t : sorted)
  {
    std::sort(t.begin(), t.end());
  }
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end());
}

TEST(SharedData, IgeaLoadsRepeatably)
{
  // Timing belongs to the benchmark; here the same file must load the same way twice.
  REQUIRE_SHARED_MESH(shared, "igea.ply");
  const TriangleMesh first = LoadMesh(shared.Path);
  const TriangleMesh second = LoadMesh(shared.Path);
  ASSERT_EQ(first.NumberOfTriangles(), 268686u);
  EXPECT_EQ(first.Triangles, second.Triangles);
  EXPECT_EQ(first.Points, second.Points);
}

TEST(SharedData, BunnyUnusedVerticesAndHoles)
{
  REQUIRE_SHARED_MESH(shared, "stanford-bunny.obj");
  const TriangleMesh mesh = LoadMesh(shared.Path);
  const MeshTopology topology = ComputeTopology(mesh);
  EXPECT_EQ(topology.NumberOfUnusedPoints, 1113u);
  EXPECT_EQ(topology.NumberOfUsedPoints, 35947u - 1113u);
  EXPECT_EQ(topology.NumberOfBoundaryEdges, 223u);
  EXPECT_EQ(topology.NumberOfBoundaryLoops, 5u);
  EXPECT_EQ(topology.NumberOfComponents, 1u);
  // Genus 0 with 5 holes.
  EXPECT_EQ(topology.EulerCharacteristic, 2 - 5);

  const TriangleMesh compact = RemoveUnusedPoints(mesh);
  EXPECT_EQ(compact.NumberOfPoints(), 35947u - 1113u);
  EXPECT_EQ(compact.NumberOfTriangles(), mesh.NumberOfTriangles());
  EXPECT_EQ(ComputeTopology(compact).NumberOfUnusedPoints, 0u);
  EXPECT_DOUBLE_EQ(SurfaceArea(compact), SurfaceArea(mesh));
}

TEST(SharedData, SpotWelds)
{
  REQUIRE_SHARED_MESH(shared, "spot.obj");
  const TriangleMesh mesh = LoadMesh(shared.Path);
  // f v/vt corners index positions, so the loader keeps the 2,930 positions.
  ASSERT_EQ(mesh.NumberOfPoints(), 2930u);
  ExpectCleanClosed(mesh, 2);
  ExpectSameMesh(mesh, WeldPoints(mesh));

  // What vtkOBJReader produces: one point per triangle corner (17,568),
  // every edge a boundary; welding restores the closed surface.
  TriangleMesh split;
  for (std::size_t t = 0; t < mesh.NumberOfTriangles(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const std::size_t id = mesh.Triangles[3 * t + k];
      split.Points.insert(
        split.Points.end(), mesh.Points.begin() + 3 * id, mesh.Points.begin() + 3 * id + 3);
      split.Triangles.push_back(static_cast<uint32_t>(3 * t + k));
    }
  }
  ASSERT_EQ(split.NumberOfPoints(), 17568u);
  EXPECT_EQ(ComputeTopology(split).NumberOfBoundaryEdges, 17568u);

  std::vector<uint32_t> oldToNew;
  const TriangleMesh welded = WeldPoints(split, 0.0, &oldToNew);
  EXPECT_EQ(welded.NumberOfPoints(), 2930u);
  EXPECT_EQ(welded.NumberOfTriangles(), 5856u);
  ASSERT_EQ(oldToNew.size(), split.NumberOfPoints());
  for (std::size_t i = 0; i < oldToNew.size(); ++i)
  {
    ASSERT_LT(oldToNew[i], welded.NumberOfPoints());
    for (int k = 0; k < 3; ++k)
    {
      ASSERT_EQ(welded.Points[3 * oldToNew[i] + k], split.Points[3 * i + k]);
    }
  }
  ExpectCleanClosed(welded, 2);
  EXPECT_NEAR(SignedVolume(welded), SignedVolume(mesh), 1e-12);
}

TEST(SharedData, TeapotDuplicatePositions)
{
  REQUIRE_SHARED_MESH(shared, "teapot.obj");
  const TriangleMesh mesh = LoadMesh(shared.Path);
  EXPECT_EQ(CountDuplicatePositions(mesh), 403u);
  const MeshTopology before = ComputeTopology(mesh);
  EXPECT_EQ(before.NumberOfBoundaryEdges, 1036u);
  EXPECT_EQ(before.NumberOfComponents, 4u);
  EXPECT_EQ(before.NumberOfNonManifoldVertices, 38u);

  const TriangleMesh welded = WeldPoints(mesh);
  EXPECT_EQ(welded.NumberOfPoints(), 3644u - 403u);
  EXPECT_EQ(welded.NumberOfTriangles(), 6320u); // no triangle collapses
  EXPECT_EQ(CountDuplicatePositions(welded), 0u);
  const MeshTopology after = ComputeTopology(welded);
  EXPECT_EQ(after.NumberOfBoundaryEdges, 160u);
  EXPECT_EQ(after.NumberOfNonManifoldEdges, 0u);
  EXPECT_EQ(after.NumberOfInconsistentEdges, 0u);
  // A tiny tolerance merges nothing more than the exact weld.
  EXPECT_EQ(WeldPoints(mesh, 1e-9).NumberOfPoints(), welded.NumberOfPoints());
}

TEST(SharedData, ClosedModels)
{
  for (const char* name : { "fandisk.obj", "homer.obj", "cow.obj" })
  {
    SCOPED_TRACE(name);
    const SharedMesh shared = FindSharedMesh(name);
    if (!shared.Available)
    {
      GTEST_SKIP() << "shared mesh not available: " << shared.Path;
    }
    const TriangleMesh mesh = LoadMesh(shared.Path);
    const MeshTopology topology = ComputeTopology(mesh);
    EXPECT_TRUE(topology.IsClosed());
    EXPECT_TRUE(topology.IsConsistentlyOriented());
    EXPECT_EQ(topology.NumberOfComponents, 1u);
    EXPECT_GT(SignedVolume(mesh), 0.0);
    ExpectClosedAndConsistent(mesh);
    // The cow has one pinch vertex (a pinched sphere: Euler characteristic 1).
    const bool cow = std::string(name) == "cow.obj";
    EXPECT_EQ(topology.NumberOfNonManifoldVertices, cow ? 1u : 0u);
    EXPECT_EQ(topology.EulerCharacteristic, cow ? 1 : 2);
  }
}

//------------------------------------------------------------------------------
// OBJ parsing

TEST(OBJ, CornerFormsNegativeIndicesPolygonsAndOtherLines)
{
  TempFile file(".obj");
  file.Write("# a comment\n"
             "mtllib scene.mtl\n"
             "o thing\n"
             "v 0 0 0\n"
             "v 1.5 0 0   # trailing comment\n"
             "v\t1 1e0 0\r\n"
             "v 0 +1 -0.25 1.0\n"
             "vt 0 0\n"
             "vt 1 0\n"
             "vn 0 0 1\n"
             "vp 0.5\n"
             "g group\n"
             "usemtl material\n"
             "s off\n"
             "\n"
             "f 1 2 3\n"
             "f 1/1 3/2 4/1\n"
             "f -4//1 -3//1 -2//1\n"
             "f 1/1/1 2/2/1 3/2/1 4/1/1\n"
             "l 1 2\n"
             "p 3\n"
             "v 2 0 0\n"
             "f -1 2 3\n"
             "f 1 2 3 4 5\n");
  const TriangleMesh mesh = LoadMesh(file.Path);
  ASSERT_EQ(mesh.NumberOfPoints(), 5u);
  const std::vector<double> points = { 0, 0, 0, 1.5, 0, 0, 1, 1, 0, 0, 1, -0.25, 2, 0, 0 };
  EXPECT_EQ(mesh.Points, points);
  const std::vector<Triangle> expected = { { 0, 1, 2 }, { 0, 2, 3 }, { 0, 1, 2 }, { 0, 1, 2 },
    { 0, 2, 3 }, { 4, 1, 2 }, { 0, 1, 2 }, { 0, 2, 3 }, { 0, 3, 4 } };
  EXPECT_EQ(TrianglesOf(mesh), expected);
}

TEST(OBJ, UppercaseExtensionAndEmptyFile)
{
  TempFile file(".OBJ");
  file.Write("");
  const TriangleMesh mesh = LoadMesh(file.Path);
  EXPECT_EQ(mesh.NumberOfPoints(), 0u);
  EXPECT_EQ(mesh.NumberOfTriangles(), 0u);
}

TEST(OBJ, RoundTrip)
{
  const TriangleMesh torus = MakeTorus(10, 7, 42);
  TempFile file(".obj");
  SaveOBJ(torus, file.Path);
  ExpectSameMesh(RoundedToFloat(torus), LoadMesh(file.Path));
}

//------------------------------------------------------------------------------
// PLY parsing

TEST(PLY, AsciiWithExtraPropertiesAndElements)
{
  TempFile file(".ply");
  file.Write("ply\r\n"
             "format ascii 1.0\r\n"
             "comment made by hand\r\n"
             "element vertex 4\r\n"
             "property float nx\r\n"
             "property double z\r\n"
             "property double x\r\n"
             "property uchar red\r\n"
             "property float y\r\n"
             "element face 2\r\n"
             "property list uchar int vertex_index\r\n"
             "property uchar flags\r\n"
             "element edge 1\r\n"
             "property int vertex1\r\n"
             "property int vertex2\r\n"
             "end_header\r\n"
             "0.5 3 0 255 1\r\n"
             "0.5 -3 2 12 +2\r\n"
             "0.5 1e-3 7 3 4\r\n"
             "0.5 0 8 1 5\r\n"
             "4 0 1 2 3 1\r\n"
             "3 3 2 1 0\r\n"
             "0 1\r\n");
  const TriangleMesh mesh = LoadMesh(file.Path);
  const std::vector<double> points = { 0, 1, 3, 2, 2, -3, 7, 4, double(1e-3f), 8, 5, 0 };
  EXPECT_EQ(mesh.Points, points);
  const std::vector<Triangle> expected = { { 0, 1, 2 }, { 0, 2, 3 }, { 3, 2, 1 } };
  EXPECT_EQ(TrianglesOf(mesh), expected);
}

TEST(PLY, BinaryBigEndianFaces)
{
  Bytes body(true);
  // vertex: short id, double x, float y, float z
  const double xs[] = { 0.0, 1.0, 1.0, 0.0, 0.5 };
  const float ys[] = { 0.0f, 0.0f, 1.0f, 1.0f, 0.5f };
  const float zs[] = { 0.0f, 0.0f, 0.0f, 0.0f, -2.0f };
  for (int i = 0; i < 5; ++i)
  {
    body.Put<int16_t>(static_cast<int16_t>(100 + i)).Put(xs[i]).Put(ys[i]).Put(zs[i]);
  }
  // face: list uchar uint vertex_indices, then a uchar flag
  body.Put<uint8_t>(4).Put<uint32_t>(0).Put<uint32_t>(1).Put<uint32_t>(2).Put<uint32_t>(3);
  body.Put<uint8_t>(9);
  body.Put<uint8_t>(3).Put<uint32_t>(4).Put<uint32_t>(1).Put<uint32_t>(0);
  body.Put<uint8_t>(9);
  TempFile file(".ply");
  file.Write("ply\nformat binary_big_endian 1.0\n"
             "element vertex 5\nproperty short id\nproperty double x\nproperty float y\n"
             "property float z\n"
             "element face 2\nproperty list uchar uint vertex_indices\nproperty uchar flag\n"
             "end_header\n" +
    body.Data);
  const TriangleMesh mesh = LoadMesh(file.Path);
  const std::vector<double> points = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, -2 };
  EXPECT_EQ(mesh.Points, points);
  const std::vector<Triangle> expected = { { 0, 1, 2 }, { 0, 2, 3 }, { 4, 1, 0 } };
  EXPECT_EQ(TrianglesOf(mesh), expected);
}

std::string StripPLY(bool bigEndian, const std::vector<std::vector<int32_t>>& strips)
{
  Bytes body(bigEndian);
  for (int i = 0; i < 7; ++i)
  {
    body.Put(static_cast<float>(i)).Put(static_cast<float>(i % 2)).Put(0.0f);
  }
  for (const auto& strip : strips)
  {
    body.Put(static_cast<int32_t>(strip.size()));
    for (const int32_t id : strip)
    {
      body.Put(id);
    }
  }
  return std::string("ply\nformat ") + (bigEndian ? "binary_big_endian" : "binary_little_endian") +
    " 1.0\nelement vertex 7\nproperty float x\nproperty float y\nproperty float z\n"
    "element tristrips " +
    std::to_string(strips.size()) + "\nproperty list int int vertex_indices\nend_header\n" +
    body.Data;
}

TEST(PLY, TriangleStripsAlternateWindingAndDropJoins)
{
  // Strip 0 1 2 3 -> (0 1 2) (2 1 3); strip 4 5 6 -> (4 5 6).
  const std::vector<Triangle> expected = { { 0, 1, 2 }, { 2, 1, 3 }, { 4, 5, 6 } };
  const std::vector<std::vector<std::vector<int32_t>>> variants = {
    { { 0, 1, 2, 3, -1, 4, 5, 6, -1 } },         // -1 restarts (igea's layout)
    { { 0, 1, 2, 3, -1, 4, 5, 6 } },             // no trailing -1
    { { 0, 1, 2, 3 }, { 4, 5, 6 } },             // one element per strip
    { { 0, 1, 2, 3, 3, 4, 4, 5, 6 } },           // one strip stitched by repeated vertices
    { { 0, 1, 2, 3, -1, -1, 4, 5, 6, -1 }, {} }, // empty runs and an empty list
  };
  for (const bool bigEndian : { false, true })
  {
    for (std::size_t v = 0; v < variants.size(); ++v)
    {
      SCOPED_TRACE("variant " + std::to_string(v) + (bigEndian ? " big endian" : " little endian"));
      TempFile file(".ply");
      file.Write(StripPLY(bigEndian, variants[v]));
      const TriangleMesh mesh = LoadMesh(file.Path);
      EXPECT_EQ(mesh.NumberOfPoints(), 7u);
      EXPECT_EQ(TrianglesOf(mesh), expected);
    }
  }
  // An odd-length stitch (one repeated vertex) flips the parity of what follows.
  TempFile file(".ply");
  file.Write(StripPLY(false, { { 0, 1, 2, 2, 3, 4 } }));
  const std::vector<Triangle> flipped = { { 0, 1, 2 }, { 3, 2, 4 } };
  EXPECT_EQ(TrianglesOf(LoadMesh(file.Path)), flipped);
}

TEST(PLY, RoundTripBinaryAndAscii)
{
  const TriangleMesh cube = MakeCube(3);
  for (const bool binary : { true, false })
  {
    TempFile file(".ply");
    SavePLY(cube, file.Path, binary);
    ExpectSameMesh(RoundedToFloat(cube), LoadMesh(file.Path));
  }
}

//------------------------------------------------------------------------------
// Errors

TEST(Errors, MissingFileAndUnknownExtension)
{
  ExpectLoadError([] { LoadMesh("/nonexistent/timecritical/mesh.obj"); },
    { "/nonexistent/timecritical/mesh.obj", "no such file" });
  ExpectLoadError([] { LoadMesh("/nonexistent/timecritical/mesh.ply"); }, { "no such file" });
  TempFile file(".stl");
  file.Write("solid x\nendsolid x\n");
  ExpectLoadError([&] { LoadMesh(file.Path); }, { file.Path, "unsupported extension '.stl'" });
  TempFile directory(".obj");
  ASSERT_TRUE(std::filesystem::create_directory(directory.Path));
  ExpectLoadError([&] { LoadMesh(directory.Path); }, { directory.Path, "not a regular file" });
}

TEST(Errors, OBJBadIndices)
{
  // The loader checks the `v` and `f` lines (OpenMesh's OBJ reader skips bad
  // ones silently, and aborts on some) and, after OpenMesh resolved relative
  // indices, the face corners (OpenMesh passes them through unchecked: those
  // messages name the face, not the line).
  struct Case
  {
    const char* Text;
    std::vector<std::string> Fragments;
  };
  const Case cases[] = {
    { "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 7\n",
      { "face #1", "vertex 7 out of range 1..3", "3 vertices" } },
    { "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", { "line 4", "index 0" } },
    { "v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 0 1 0\n", { "face #0", "vertex 0 out of range" } },
    { "v 0 0 0\nv 1 zero 0\n", { "line 2", "bad vertex coordinate 'zero'" } },
    { "v 0 0\n", { "line 1", "fewer than 3 coordinates" } },
    { "v 0 0 0\nv 1e39 0 0\nv 0 1 0\nf 1 2 3\n", { "line 2", "'1e39' beyond float range" } },
    { "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1 x/2 3\n", { "line 4", "bad face corner 'x/2'" } },
    { "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf /1 2/1 3/1\n", { "line 5", "bad face corner '/1'" } },
    { "v 0 0 0\nv 1 0 0\nf 1 2\n", { "accepted 0 of the 1 'f' lines", "fewer than 3" } },
    { "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 1 2\n", { "accepted 0 of the 1 'f' lines" } },
    { "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 \\\n  3\n", { "line 4", "continuation" } },
  };
  for (const Case& c : cases)
  {
    SCOPED_TRACE(c.Text);
    TempFile file(".obj");
    file.Write(c.Text);
    std::vector<std::string> fragments = c.Fragments;
    fragments.push_back(file.Path);
    ExpectLoadError([&] { LoadMesh(file.Path); }, fragments);
  }
}

TEST(Errors, PLYMalformed)
{
  const std::string vertices = "element vertex 3\nproperty float x\nproperty float y\n"
                               "property float z\n";
  const std::string faces = "element face 1\nproperty list uchar int vertex_indices\n";
  struct Case
  {
    std::string Text;
    std::vector<std::string> Fragments;
  };
  const Case cases[] = {
    { "plx\nformat ascii 1.0\nend_header\n", { "not a PLY file" } },
    // OpenMesh's reader would never return from this one.
    { "ply\nformat ascii 1.0\n" + vertices, { "no end_header" } },
    { "ply\nformat ascii 2.0\nend_header\n", { "header line 2", "format" } },
    { "ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n",
      { "header line 4", "unknown property type" } },
    { "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n"
      "0 0\n",
      { "element 'vertex'", "no 'z' property" } },
    { "ply\nformat ascii 1.0\n" + vertices + faces + "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n",
      { "face #0", "vertex index 3 out of range [0, 3)" } },
    { "ply\nformat ascii 1.0\n" + vertices +
        "element face 2\nproperty list uchar int vertex_indices\nend_header\n"
        "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 -1 2\n",
      { "face #1", "vertex index -1" } },
    { "ply\nformat ascii 1.0\n" + vertices + faces + "end_header\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n",
      { "face #0", "at least 3" } },
    // OpenMesh reads these ascii bodies without an error (0 for what is
    // missing or not a number); the loader checks the numbers.
    { "ply\nformat ascii 1.0\n" + vertices + "end_header\n0 0 0\n1 zero 0\n0 1 0\n",
      { "line 9", "number expected, got 'zero'" } },
    { "ply\nformat ascii 1.0\n" + vertices + "end_header\n0 0 0\n1 0 0\n",
      { "element 'vertex'", "unexpected end of file" } },
    // (OpenMesh would read a billion zero vertices.)
    { "ply\nformat ascii 1.0\nelement vertex 1000000000\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n0 0 0\n",
      { "element 'vertex'", "unexpected end of file", "declares 1000000000" } },
    { "ply\nformat ascii 1.0\n" + vertices + faces +
        "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 2\n",
      { "holds 14 numbers, the header declares 13" } },
    { "ply\nformat ascii 1.0\n" + vertices + "end_header\n0 0 0\n1 1e39 0\n0 1 0\n",
      { "line 9", "beyond float range" } },
    // Strips, decoded by the loader.
    { "ply\nformat ascii 1.0\n" + vertices +
        "element tristrips 1\nproperty list int int vertex_indices\nend_header\n"
        "0 0 0\n1 0 0\n0 1 0\n4 0 1 2 -2\n",
      { "element 'tristrips' #0", "strip vertex index -2" } },
    { "ply\nformat ascii 1.0\n" + vertices +
        "element tristrips 1\nproperty list int int vertex_indices\nend_header\n"
        "0 0 0\n1 0 0\n0 1 0\n5 0 1 2\n",
      { "element 'tristrips' #0", "unexpected end of file" } },
    { "ply\nformat ascii 1.0\n" + vertices +
        "element face 1\nproperty list uchar float vertex_indices\nend_header\n",
      { "must be a list of integers" } },
    { "ply\nformat ascii 1.0\nelement face 0\nproperty list uchar int vertex_indices\n"
      "end_header\n",
      { "no 'vertex' element" } },
    // Layouts OpenMesh 9's PLY reader misreads without an error.
    { "ply\nformat ascii 1.0\n" + vertices +
        "property list uchar float texture\nend_header\n0 0 0 0\n1 0 0 0\n0 1 0 0\n",
      { "element 'vertex'", "list property 'texture'" } },
    { "ply\nformat ascii 1.0\nelement vertex 3\nproperty int x\nproperty int y\n"
      "property int z\nend_header\n0 0 0\n1 0 0\n0 1 0\n",
      { "element 'vertex'", "'x' is int", "float or double" } },
    { "ply\nformat ascii 1.0\n" + vertices +
        "element face 1\nproperty uchar flags\nproperty list uchar int vertex_indices\n"
        "end_header\n0 0 0\n1 0 0\n0 1 0\n0 3 0 1 2\n",
      { "element 'face'", "first property is the vertex_indices list" } },
    { "ply\nformat ascii 1.0\n" + vertices + faces +
        "property list uchar float texcoord\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 0\n",
      { "element 'face'", "other properties are scalars" } },
    // And what it refuses itself, quoted.
    { "ply\nformat ascii 1.0\n" + vertices +
        "element face 1\nproperty list ushort int vertex_indices\nend_header\n"
        "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
      { "OpenMesh's PLY reader failed", "ushort" } },
  };
  for (const Case& c : cases)
  {
    SCOPED_TRACE(c.Text);
    TempFile file(".ply");
    file.Write(c.Text);
    std::vector<std::string> fragments = c.Fragments;
    fragments.push_back(file.Path);
    ExpectLoadError([&] { LoadMesh(file.Path); }, fragments);
  }
}

TEST(Errors, TruncatedBinaryPLY)
{
  const TriangleMesh grid = MakeGrid(4, 3); // 20 points, 24 triangles
  TempFile whole(".ply");
  SavePLY(grid, whole.Path, true);
  const std::string bytes = ReadBytes(whole.Path);
  const std::size_t bodyStart = bytes.find("end_header\n") + 11;
  ASSERT_EQ(bytes.size(), bodyStart + 20 * 24 + 24 * 13);

  TempFile truncated(".ply");
  // Cut inside the vertex data (point 10 is incomplete) or after the header:
  // the loader sees that the body is shorter than the header declares.
  for (const std::size_t size : { bodyStart + 10 * 24 + 5, bodyStart })
  {
    SCOPED_TRACE(size);
    truncated.Write(bytes.substr(0, size));
    ExpectLoadError([&] { LoadMesh(truncated.Path); },
      { truncated.Path, "element 'vertex'", "unexpected end of file" });
  }
  // Cut inside the faces (face 23 lacks its last index): OpenMesh's reader
  // notices, and its message is quoted.
  truncated.Write(bytes.substr(0, bytes.size() - 2));
  ExpectLoadError([&] { LoadMesh(truncated.Path); },
    { truncated.Path, "OpenMesh's PLY reader failed", "Unexpected end of file" });
}

TEST(Errors, TruncatedIgea)
{
  REQUIRE_SHARED_MESH(shared, "igea.ply");
  const std::string bytes = ReadBytes(shared.Path);
  TempFile truncated(".ply");
  // In the strips: the loader's decoder notices.
  truncated.Write(bytes.substr(0, bytes.size() - 100));
  ExpectLoadError([&] { LoadMesh(truncated.Path); },
    { truncated.Path, "element 'tristrips' #0", "unexpected end of file" });
  // In the vertices.
  truncated.Write(bytes.substr(0, bytes.size() / 4));
  ExpectLoadError(
    [&] { LoadMesh(truncated.Path); }, { "element 'vertex'", "unexpected end of file" });
}

//------------------------------------------------------------------------------
// WeldPoints

TEST(WeldPoints, ExactAndTolerance)
{
  TriangleMesh mesh;
  mesh.Points = { 0, 0, 0, 1, 0, 0, 0, 1,
    0, // 0 1 2
    -0.0, 0, 0, 1 + 1e-9, 0, 0, 0, 1,
    0,                                            // 3 == 0 (signed zero), 4 ~ 1, 5 == 2
    0.6, 0, 0, 1.2, 0, 0 };                       // 6, 7 (unused)
  mesh.Triangles = { 0, 1, 2, 3, 4, 5, 0, 5, 3 }; // last one collapses when welded
  std::vector<uint32_t> map;
  const TriangleMesh exact = WeldPoints(mesh, 0.0, &map);
  EXPECT_EQ(map, (std::vector<uint32_t>{ 0, 1, 2, 0, 3, 2, 4, 5 }));
  EXPECT_EQ(exact.NumberOfPoints(), 6u);
  EXPECT_EQ(TrianglesOf(exact), (std::vector<Triangle>{ { 0, 1, 2 }, { 0, 3, 2 } }));

  const TriangleMesh close = WeldPoints(mesh, 1e-6, &map);
  EXPECT_EQ(map, (std::vector<uint32_t>{ 0, 1, 2, 0, 1, 2, 3, 4 }));
  EXPECT_EQ(TrianglesOf(close), (std::vector<Triangle>{ { 0, 1, 2 }, { 0, 1, 2 } }));

  // Greedy clusters in point order, each point joining the nearest earlier
  // representative within the tolerance: 1 and 2 are 1.0 and more away from 0
  // and stay apart; 0.6 is within 0.7 of both 0 and 1 and joins the nearer,
  // 1 (0.4 away); 1.2 joins 1 (0.2 away).
  const TriangleMesh coarse = WeldPoints(mesh, 0.7, &map);
  EXPECT_EQ(map, (std::vector<uint32_t>{ 0, 1, 2, 0, 1, 2, 1, 1 }));
  EXPECT_EQ(coarse.NumberOfPoints(), 3u);

  EXPECT_THROW(WeldPoints(mesh, -1.0), std::invalid_argument);
  TriangleMesh bad = mesh;
  bad.Triangles.push_back(99);
  bad.Triangles.push_back(0);
  bad.Triangles.push_back(1);
  EXPECT_THROW(WeldPoints(bad), std::invalid_argument);
}

TEST(WeldPoints, LargeMeshIsFast)
{
  // Corner-split torus: 6 * 200 * 100 = 120,000 points weld back to 20,000.
  const TriangleMesh torus = MakeTorus(200, 100, 7);
  TriangleMesh split;
  for (std::size_t c = 0; c < torus.Triangles.size(); ++c)
  {
    const std::size_t id = torus.Triangles[c];
    split.Points.insert(
      split.Points.end(), torus.Points.begin() + 3 * id, torus.Points.begin() + 3 * id + 3);
    split.Triangles.push_back(static_cast<uint32_t>(c));
  }
  const TriangleMesh exact = WeldPoints(split);
  const TriangleMesh tolerant = WeldPoints(split, 1e-7);
  // Points come out in order of first use, so compare counts and shape.
  for (const TriangleMesh* welded : { &exact, &tolerant })
  {
    EXPECT_EQ(welded->NumberOfPoints(), torus.NumberOfPoints());
    EXPECT_EQ(welded->NumberOfTriangles(), torus.NumberOfTriangles());
    ExpectCleanClosed(*welded, 0);
    EXPECT_NEAR(SignedVolume(*welded), SignedVolume(torus), 1e-12);
  }
}

//------------------------------------------------------------------------------
// Generators

TEST(Generators, Grid)
{
  for (const auto& size : { std::pair<std::size_t, std::size_t>{ 1, 1 }, { 3, 5 }, { 40, 17 } })
  {
    const std::size_t nx = size.first;
    const std::size_t ny = size.second;
    SCOPED_TRACE(std::to_string(nx) + "x" + std::to_string(ny));
    const TriangleMesh grid = MakeGrid(nx, ny);
    EXPECT_EQ(grid.NumberOfPoints(), (nx + 1) * (ny + 1));
    EXPECT_EQ(grid.NumberOfTriangles(), 2 * nx * ny);
    const MeshTopology topology = ComputeTopology(grid);
    EXPECT_EQ(topology.EulerCharacteristic, 1);
    EXPECT_FALSE(topology.IsClosed());
    EXPECT_TRUE(topology.IsConsistentlyOriented());
    EXPECT_EQ(topology.NumberOfBoundaryEdges, 2 * (nx + ny));
    EXPECT_EQ(topology.NumberOfBoundaryLoops, 1u);
    EXPECT_EQ(topology.NumberOfComponents, 1u);
    EXPECT_EQ(topology.NumberOfNonManifoldVertices, 0u);
    EXPECT_EQ(topology.NumberOfUnusedPoints, 0u);
    EXPECT_EQ(CountDuplicatePositions(grid), 0u);
    EXPECT_NEAR(SurfaceArea(grid), 1.0, 1e-12);
    // Every triangle faces +z.
    for (std::size_t t = 0; t < grid.NumberOfTriangles(); ++t)
    {
      const double* a = &grid.Points[3 * grid.Triangles[3 * t]];
      const double* b = &grid.Points[3 * grid.Triangles[3 * t + 1]];
      const double* c = &grid.Points[3 * grid.Triangles[3 * t + 2]];
      EXPECT_EQ(a[2], 0.0);
      ASSERT_GT((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]), 0.0);
    }
  }
  EXPECT_THROW(MakeGrid(0, 3), std::invalid_argument);
}

TEST(Generators, IcoSphere)
{
  const double pi = 3.14159265358979323846;
  std::size_t scale = 1;
  for (std::size_t s = 0; s <= 5; ++s, scale *= 4)
  {
    SCOPED_TRACE("subdivisions " + std::to_string(s));
    const TriangleMesh sphere = MakeSphere(s);
    EXPECT_EQ(sphere.NumberOfPoints(), 10 * scale + 2);
    EXPECT_EQ(sphere.NumberOfTriangles(), 20 * scale);
    ExpectCleanClosed(sphere, 2);
    for (std::size_t i = 0; i < sphere.NumberOfPoints(); ++i)
    {
      const double* p = &sphere.Points[3 * i];
      ASSERT_NEAR(p[0] * p[0] + p[1] * p[1] + p[2] * p[2], 1.0, 1e-12);
    }
    if (s >= 4)
    {
      EXPECT_NEAR(SignedVolume(sphere), 4.0 / 3.0 * pi, 0.01 * 4.0 / 3.0 * pi);
    }
  }
}

TEST(Generators, UVSphere)
{
  const TriangleMesh sphere = MakeUVSphere(32, 64);
  EXPECT_EQ(sphere.NumberOfPoints(), 31u * 64u + 2u);
  EXPECT_EQ(sphere.NumberOfTriangles(), 2u * 31u * 64u);
  ExpectCleanClosed(sphere, 2);
  EXPECT_NEAR(SignedVolume(sphere), 4.0 / 3.0 * 3.14159265358979323846, 0.02 * 4.2);
  ExpectCleanClosed(MakeUVSphere(2, 3), 2); // triangular bipyramid
}

TEST(Generators, Torus)
{
  const double pi = 3.14159265358979323846;
  const TriangleMesh torus = MakeTorus(48, 24);
  EXPECT_EQ(torus.NumberOfPoints(), 48u * 24u);
  EXPECT_EQ(torus.NumberOfTriangles(), 2u * 48u * 24u);
  ExpectCleanClosed(torus, 0);
  // Volume 2 pi^2 R r^2 with R = 1, r = 0.35 (the polyhedron is slightly smaller).
  const double volume = 2.0 * pi * pi * 0.35 * 0.35;
  EXPECT_NEAR(SignedVolume(torus), volume, 0.02 * volume);
  ExpectCleanClosed(MakeTorus(3, 3), 0);

  // Noise: deterministic per seed, different across seeds, still clean.
  const TriangleMesh noisy = MakeTorus(48, 24, 1234);
  ExpectCleanClosed(noisy, 0);
  EXPECT_EQ(noisy.Triangles, torus.Triangles);
  EXPECT_NE(noisy.Points, torus.Points);
  ExpectSameMesh(noisy, MakeTorus(48, 24, 1234));
  EXPECT_NE(noisy.Points, MakeTorus(48, 24, 1235).Points);
  EXPECT_NE(noisy.Points, MakeTorus(48, 24, 1234, 0.2).Points);
  // Displacements stay within the amplitude (0.1 * minor radius).
  for (std::size_t i = 0; i < noisy.NumberOfPoints(); ++i)
  {
    const double* p = &noisy.Points[3 * i];
    const double* q = &torus.Points[3 * i];
    const double d = std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
      (p[2] - q[2]) * (p[2] - q[2]));
    ASSERT_LE(d, 0.035 + 1e-12);
  }
}

TEST(Generators, CubeHasSharpWeldedEdges)
{
  for (std::size_t n = 1; n <= 6; ++n)
  {
    SCOPED_TRACE("n = " + std::to_string(n));
    const TriangleMesh cube = MakeCube(n);
    EXPECT_EQ(cube.NumberOfPoints(), 6 * n * n + 2);
    EXPECT_EQ(cube.NumberOfTriangles(), 12 * n * n);
    ExpectCleanClosed(cube, 2);
    EXPECT_NEAR(SignedVolume(cube), 1.0, 1e-12);
    EXPECT_NEAR(SurfaceArea(cube), 6.0, 1e-12);
    // Already welded: welding changes nothing.
    ExpectSameMesh(cube, WeldPoints(cube));

    // Dihedral angles: 12 n edges of 90 degrees, all others flat.
    std::map<std::pair<uint32_t, uint32_t>, std::vector<std::array<double, 3>>> edgeNormals;
    for (std::size_t t = 0; t < cube.NumberOfTriangles(); ++t)
    {
      const double* a = &cube.Points[3 * cube.Triangles[3 * t]];
      const double* b = &cube.Points[3 * cube.Triangles[3 * t + 1]];
      const double* c = &cube.Points[3 * cube.Triangles[3 * t + 2]];
      const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
      const double v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
      std::array<double, 3> normal = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0] };
      const double length =
        std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
      for (double& x : normal)
      {
        x /= length;
      }
      // Outward: the normal points away from the center.
      EXPECT_GT(normal[0] * (a[0] + b[0] + c[0]) + normal[1] * (a[1] + b[1] + c[1]) +
          normal[2] * (a[2] + b[2] + c[2]),
        0.0);
      for (int k = 0; k < 3; ++k)
      {
        const uint32_t p = cube.Triangles[3 * t + k];
        const uint32_t q = cube.Triangles[3 * t + (k + 1) % 3];
        edgeNormals[{ std::min(p, q), std::max(p, q) }].push_back(normal);
      }
    }
    std::size_t sharp = 0;
    std::size_t flat = 0;
    for (const auto& entry : edgeNormals)
    {
      ASSERT_EQ(entry.second.size(), 2u);
      const auto& n0 = entry.second[0];
      const auto& n1 = entry.second[1];
      const double cosine = n0[0] * n1[0] + n0[1] * n1[1] + n0[2] * n1[2];
      if (std::abs(cosine) < 1e-12)
      {
        ++sharp;
      }
      else if (std::abs(cosine - 1.0) < 1e-12)
      {
        ++flat;
      }
    }
    EXPECT_EQ(sharp, 12 * n);
    EXPECT_EQ(sharp + flat, edgeNormals.size());
  }
}

TEST(Topology, DetectsDefects)
{
  // Two triangles sharing an edge in the same direction, one degenerate
  // triangle, one unused point, and a bow tie (pinch vertex 0).
  TriangleMesh mesh;
  mesh.Points = { 0, 0, 0, 1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0, 5, 5, 5 };
  mesh.Triangles = { 0, 1, 2, 0, 3, 4, 0, 0, 1 };
  MeshTopology topology = ComputeTopology(mesh);
  EXPECT_EQ(topology.NumberOfUnusedPoints, 1u);
  EXPECT_EQ(topology.NumberOfDegenerateTriangles, 1u);
  EXPECT_EQ(topology.NumberOfNonManifoldVertices, 1u);
  EXPECT_EQ(topology.NumberOfBoundaryEdges, 6u);
  EXPECT_EQ(topology.NumberOfBoundaryLoops, 1u); // the two loops touch at 0
  EXPECT_EQ(topology.NumberOfComponents, 1u);

  mesh.Triangles = { 0, 1, 2, 0, 1, 3 }; // edge 0->1 twice
  topology = ComputeTopology(mesh);
  EXPECT_EQ(topology.NumberOfInconsistentEdges, 1u);
  EXPECT_FALSE(topology.IsConsistentlyOriented());
  mesh.Triangles = { 0, 1, 2, 1, 0, 3, 0, 1, 4 }; // edge 0-1 three times
  topology = ComputeTopology(mesh);
  EXPECT_EQ(topology.NumberOfNonManifoldEdges, 1u);
  EXPECT_FALSE(topology.IsClosed());
  mesh.Triangles = { 0, 1, 7 };
  EXPECT_THROW(ComputeTopology(mesh), std::invalid_argument);
}
}
