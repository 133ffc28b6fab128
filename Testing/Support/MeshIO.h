// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_MeshIO_h
#define timecritical_MeshIO_h

/**
 * VTK-free triangle mesh loading, welding, checking and generation for the
 * GoogleTest tests and C++ benchmarks of the algorithm cores.
 *
 * LoadMesh() reads Wavefront OBJ and PLY through OpenMesh's readers: an
 * OpenMesh::IO::BaseImporter collects the points and faces into
 * plain arrays (no halfedge mesh, so non-manifold input, duplicate and unused
 * points stay exactly as in the file; polygons are fan-triangulated).
 *
 * Precision: OpenMesh 9's readers are single precision (libopenmesh-dev
 * 9.0: its OBJ reader parses floats and calls
 * add_vertex(Vec3f), its PLY reader calls set_point(Vec3f) even for double
 * properties), so every loaded coordinate is a float: an OBJ coordinate is
 * the file's decimal rounded to float (docs/testing.md says how far that
 * moves the shared meshes), igea's float coordinates are unchanged. A coordinate beyond float range is
 * an error. Testing/Support/TestMeshIOLoaders.cxx pins the loaded meshes
 * (counts, bounding boxes, coordinate and triangle hashes) and these facts.
 *
 * By hand, because OpenMesh lacks it:
 * - PLY `tristrips` (igea.ply): OpenMesh's PLY reader skips the element; the
 *   loader finds it from the header and decodes it (a -1 entry restarts the
 *   strip, winding alternates, degenerate joins are dropped). Its triangles
 *   follow those of a `face` element. vtkPLYReader cannot decode strips either.
 * - Checks of what OpenMesh accepts silently or crashes on (measured):
 *   out-of-range face indices (passed through: checked in the importer); OBJ
 *   `v` and `f` lines it skips (a malformed or out-of-float-range coordinate,
 *   a `\` continuation: the lines are checked, with line numbers; a face
 *   with fewer than 3 distinct vertices: the lines are counted) or aborts on
 *   (an assertion for a corner without a vertex index: checked); a PLY header
 *   without end_header (its reader never returns); PLY layouts it misreads
 *   into garbage (a list property in the vertex element, integer
 *   coordinates, a face element whose first property is not the vertex list
 *   or that has another list: rejected); malformed or missing numbers in an
 *   ascii PLY body (read as 0: the body is checked to hold exactly the
 *   numbers the header declares) and a header declaring more elements than
 *   the file holds (its ascii reader would read that many zeros). Errors
 *   throw std::runtime_error naming the file and what is wrong (OpenMesh's
 *   own messages quoted when its reader fails).
 *
 * SaveOBJ and SavePLY stay hand-written (about 90 lines of printf): OpenMesh's
 * writers need a BaseExporter of some 50 methods or a copy into a halfedge
 * mesh (which splits the cow's pinch vertex), and its PLY writer writes float
 * properties where SavePLY writes the doubles exactly.
 *
 * The real meshes of the project live outside the repository in the shared
 * data folder (see ../shared/data/README.md); FindSharedMesh() says whether
 * one is available so that tests can skip when the folder is absent.
 */

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

// CMake defines this (absolute path) for every target linking
// TimeCriticalTestSupport; the fallback is relative to the working directory.
#ifndef TIMECRITICAL_SHARED_DATA_DIR
#define TIMECRITICAL_SHARED_DATA_DIR "../shared/data"
#endif

namespace timecritical
{
namespace testing
{
/// Indexed triangle mesh in plain arrays.
struct TriangleMesh
{
  std::vector<double> Points;      ///< x, y, z per point
  std::vector<uint32_t> Triangles; ///< three point ids per triangle

  std::size_t NumberOfPoints() const { return this->Points.size() / 3; }
  std::size_t NumberOfTriangles() const { return this->Triangles.size() / 3; }
};

//------------------------------------------------------------------------------
// Shared data folder

/// Location of a mesh of the shared data folder.
struct SharedMesh
{
  std::string Path;       ///< TIMECRITICAL_SHARED_DATA_DIR + "/" + name
  bool Available = false; ///< true when that path is a readable regular file
};

/// The shared data folder (TIMECRITICAL_SHARED_DATA_DIR).
std::string SharedDataDirectory();

/// Path of a named shared mesh (e.g. "igea.ply") and whether it exists.
SharedMesh FindSharedMesh(const std::string& name);

//------------------------------------------------------------------------------
// Reading and writing

/**
 * Load a triangle mesh, dispatching on the (case-insensitive) extension:
 * `.obj` -> LoadOBJ(), `.ply` -> LoadPLY(). Throws std::runtime_error on an
 * unknown extension, a missing or unreadable file, malformed data or
 * out-of-range indices. Polygons are fan-triangulated; points are kept as in
 * the file (unused and duplicate points included, nothing is welded).
 */
TriangleMesh LoadMesh(const std::string& path);

/**
 * Wavefront OBJ, read by OpenMesh: `v x y z [w ...]` and `f` lines with `v`,
 * `v/vt`, `v//vn` or `v/vt/vn` corners, 1-based or negative (relative to the
 * vertices read so far) position indices; repeated corners of a face are
 * merged by OpenMesh. Other statements (vt, vn, g, o, s, usemtl, l, p, ...)
 * and `#` comments are ignored; `\` line continuations are not supported
 * (an error).
 */
TriangleMesh LoadOBJ(const std::string& path);

/**
 * PLY (ascii, binary_little_endian, binary_big_endian), read by OpenMesh:
 * `vertex` x, y, z of type float or double (other scalar properties skipped);
 * `face` with a first property `list <uchar|uint8|int> <int|uint|...>
 * vertex_indices` (or vertex_index) and scalar properties after it
 * (fan-triangulated); decoded here: `tristrips` with one property, a list of
 * integers named vertex_indices (a -1 entry restarts the strip; winding
 * alternates along a strip; degenerate triangles are dropped). Other
 * elements are skipped.
 */
TriangleMesh LoadPLY(const std::string& path);

/// Write `v` and `f` lines (17 significant digits: the exact doubles; LoadMesh
/// reads them back rounded to float).
void SaveOBJ(const TriangleMesh& mesh, const std::string& path);

/// Write a PLY with double x, y, z and `property list uchar int vertex_indices`
/// faces, binary little endian or ascii.
void SavePLY(const TriangleMesh& mesh, const std::string& path, bool binary = true);

//------------------------------------------------------------------------------
// Cleaning

/**
 * Merge points with coincident positions (bitwise equal up to the sign of
 * zero when tolerance is 0; otherwise within Euclidean distance `tolerance`
 * of a representative, greedily in point order, using a hash grid). The
 * output keeps the first point of each cluster, in input order (unused points
 * included), and drops triangles that become degenerate (two equal ids).
 * When oldToNew is given it receives the new id of each input point.
 */
TriangleMesh WeldPoints(
  const TriangleMesh& mesh, double tolerance = 0.0, std::vector<uint32_t>* oldToNew = nullptr);

/// Drop points no triangle uses (order of the others kept).
TriangleMesh RemoveUnusedPoints(const TriangleMesh& mesh);

//------------------------------------------------------------------------------
// Checking

/// Combinatorial summary of a mesh, for assertions in tests.
struct MeshTopology
{
  std::size_t NumberOfPoints = 0;
  std::size_t NumberOfUsedPoints = 0;
  std::size_t NumberOfUnusedPoints = 0;
  std::size_t NumberOfTriangles = 0;
  std::size_t NumberOfDegenerateTriangles = 0; ///< two or three equal ids
  std::size_t NumberOfEdges = 0;               ///< distinct undirected edges
  std::size_t NumberOfBoundaryEdges = 0;       ///< used by one triangle
  std::size_t NumberOfNonManifoldEdges = 0;    ///< used by more than two triangles
  std::size_t NumberOfInconsistentEdges = 0;   ///< used twice in the same direction
  std::size_t NumberOfNonManifoldVertices = 0; ///< pinch vertices: >1 triangle fan
  std::size_t NumberOfBoundaryLoops = 0;       ///< components of the boundary edges
  std::size_t NumberOfComponents = 0;          ///< components of the used points
  long long EulerCharacteristic = 0;           ///< used points - edges + triangles

  /// Every edge shared by exactly two triangles.
  bool IsClosed() const
  {
    return this->NumberOfBoundaryEdges == 0 && this->NumberOfNonManifoldEdges == 0;
  }
  /// Every two-triangle edge is traversed once in each direction.
  bool IsConsistentlyOriented() const { return this->NumberOfInconsistentEdges == 0; }
};

/// Compute the MeshTopology of a mesh (degenerate triangles are counted but
/// contribute no edges). O(T log T).
MeshTopology ComputeTopology(const TriangleMesh& mesh);

/// Signed enclosed volume (positive for a closed mesh wound counter-clockwise
/// seen from outside).
double SignedVolume(const TriangleMesh& mesh);

/// Sum of the triangle areas.
double SurfaceArea(const TriangleMesh& mesh);

//------------------------------------------------------------------------------
// Generators: clean meshes (no duplicate points, no degenerate triangles,
// consistent counter-clockwise winding seen from outside / from +z).

/// Open planar grid of nx x ny quads (two triangles each) over [0,1]^2 in the
/// z = 0 plane, normals +z: (nx+1)(ny+1) points, 2 nx ny triangles, one
/// boundary loop, Euler characteristic 1. Requires nx, ny >= 1.
TriangleMesh MakeGrid(std::size_t nx, std::size_t ny);

/// Closed unit icosphere: the icosahedron with each triangle split into four
/// `subdivisions` times, points projected on the sphere:
/// 10 * 4^s + 2 points, 20 * 4^s triangles, Euler characteristic 2.
TriangleMesh MakeSphere(std::size_t subdivisions);

/// Closed unit latitude/longitude sphere with single pole points:
/// (latitudes - 1) * longitudes + 2 points, 2 (latitudes - 1) longitudes
/// triangles. Requires latitudes >= 2, longitudes >= 3.
TriangleMesh MakeUVSphere(std::size_t latitudes, std::size_t longitudes);

/// Closed torus around the z axis (major radius 1, minor radius 0.35) with
/// n segments around the axis and m around the tube: n m points, 2 n m
/// triangles, Euler characteristic 0. A non-zero noiseSeed displaces every
/// point along its normal by a deterministic pseudo-random amount in
/// [-noiseAmplitude, noiseAmplitude] * minor radius (amplitude < 1 keeps the
/// surface embedded). Requires n, m >= 3.
TriangleMesh MakeTorus(
  std::size_t n, std::size_t m, uint32_t noiseSeed = 0, double noiseAmplitude = 0.1);

/// Closed cube [-0.5, 0.5]^3 with each face split into n x n quads (two
/// triangles each); points on edges and corners are shared by the faces, so
/// the 12 cube edges are sharp 90-degree creases of a single closed surface:
/// 6 n^2 + 2 points, 12 n^2 triangles, Euler characteristic 2. Requires n >= 1.
TriangleMesh MakeCube(std::size_t n);

/// MakeCube(n) with every face-interior point moved along its face normal by
/// a fixed pseudo-random amount in [-noise/2, noise/2]; edges and corners
/// stay exact. Bumpy faces make the collapse order depend on how the creases
/// are held (flat ones would leave many ties): the feature-edge tests' mesh.
TriangleMesh MakeNoisyCube(std::size_t n, double noise);

/// n triangles around point 0, their other corners on the unit circle (flat)
/// or scattered over the unit sphere by a fixed pseudo-random sequence
/// (crumpled: neighbours far apart, most collapses fold something): the
/// builders' work-bound tests. Requires n >= 3.
TriangleMesh MakeFan(uint32_t n, bool crumpled);
}
}

#endif
