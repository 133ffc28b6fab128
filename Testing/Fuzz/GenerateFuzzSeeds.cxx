// SPDX-License-Identifier: BSD-3-Clause
// Writes the seed corpus of the fuzz targets (formats in FuzzFormat.h):
// small connected pieces (tens to a few hundred triangles) cut out of the
// shared meshes, plus a few generated meshes so that there are seeds without
// the shared folder. The meshes themselves never enter the repository.
//
//   GenerateFuzzSeeds <output folder> [<shared data folder>]
//
// writes <output>/fuzz_tom, <output>/fuzz_builder and <output>/fuzz_refine.
#include "FuzzFormat.h"
#include "TOMBuilder.h"
#include "MeshIO.h"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <fstream>
#include <map>
#include <stdexcept>
#include <unordered_map>
#include <string>
#include <sys/stat.h>
#include <utility>
#include <vector>

using namespace timecritical;
using namespace timecritical::fuzz;
using timecritical::testing::TriangleMesh;

namespace
{
void MakeFolder(const std::string& path)
{
  if (mkdir(path.c_str(), 0755) != 0 && errno != EEXIST)
  {
    throw std::runtime_error("cannot create " + path);
  }
}

void WriteSeed(const std::string& path, const std::vector<uint8_t>& bytes)
{
  std::ofstream out(path, std::ios::binary);
  out.write(
    reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (!out)
  {
    throw std::runtime_error("cannot write " + path);
  }
}

/// Triangles around each undirected edge.
using EdgeMap = std::unordered_map<uint64_t, std::vector<uint32_t>>;

uint64_t EdgeKey(uint32_t a, uint32_t b)
{
  return (uint64_t(std::min(a, b)) << 32) | std::max(a, b);
}

EdgeMap MapEdges(const TriangleMesh& mesh)
{
  EdgeMap edges;
  for (size_t t = 0; t < mesh.NumberOfTriangles(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      edges[EdgeKey(mesh.Triangles[3 * t + k], mesh.Triangles[3 * t + (k + 1) % 3])].push_back(
        static_cast<uint32_t>(t));
    }
  }
  return edges;
}

/// The connected piece of at most `size` triangles grown breadth-first (across
/// shared edges) from triangle `start`, with its points renumbered.
TriangleMesh CutPiece(const TriangleMesh& mesh, const EdgeMap& edges, size_t start, size_t size)
{
  const size_t triangles = mesh.NumberOfTriangles();
  std::vector<char> taken(triangles, 0);
  std::vector<uint32_t> order{ static_cast<uint32_t>(start % triangles) };
  taken[order[0]] = 1;
  for (size_t i = 0; i < order.size() && order.size() < size; ++i)
  {
    const uint32_t t = order[i];
    for (int k = 0; k < 3 && order.size() < size; ++k)
    {
      const auto around =
        edges.find(EdgeKey(mesh.Triangles[3 * t + k], mesh.Triangles[3 * t + (k + 1) % 3]));
      for (uint32_t u : around->second)
      {
        if (!taken[u] && order.size() < size)
        {
          taken[u] = 1;
          order.push_back(u);
        }
      }
    }
  }
  std::sort(order.begin(), order.end()); // keep the file's triangle order
  TriangleMesh piece;
  std::map<uint32_t, uint32_t> ids;
  for (uint32_t t : order)
  {
    for (int k = 0; k < 3; ++k)
    {
      const uint32_t p = mesh.Triangles[3 * t + k];
      auto it = ids.find(p);
      if (it == ids.end())
      {
        it = ids.emplace(p, static_cast<uint32_t>(ids.size())).first;
        const double* xyz = &mesh.Points[3 * size_t(p)];
        piece.Points.insert(piece.Points.end(), xyz, xyz + 3);
      }
      piece.Triangles.push_back(it->second);
    }
  }
  return piece;
}

MeshInput ToMeshInput(const TriangleMesh& piece, uint8_t flags)
{
  MeshInput input;
  input.Flags = flags;
  input.Points = piece.Points;
  input.Triangles = piece.Triangles;
  return input;
}

/// Views around the piece: perspective from +z and from the side, a budget
/// update, a parallel one, one from inside.
std::vector<uint8_t> RefineTail(const TriangleMesh& piece)
{
  double lo[3] = { 1e300, 1e300, 1e300 }, hi[3] = { -1e300, -1e300, -1e300 };
  for (size_t i = 0; i < piece.Points.size(); ++i)
  {
    lo[i % 3] = std::min(lo[i % 3], piece.Points[i]);
    hi[i % 3] = std::max(hi[i % 3], piece.Points[i]);
  }
  float center[3], extent = 0.f;
  for (int i = 0; i < 3; ++i)
  {
    center[i] = static_cast<float>(0.5 * (lo[i] + hi[i]));
    extent = std::max(extent, static_cast<float>(hi[i] - lo[i]));
  }
  std::vector<uint8_t> tail;
  Writer head;
  head.Write<uint8_t>(2);     // two uniform resolutions
  head.Write<float>(0.25f);
  head.Write<float>(0.75f);
  head.Write<uint8_t>(16);    // tau = 1 px
  head.Write<uint8_t>(1 | 2 | 4);
  head.Write<uint8_t>(63);    // silhouette factor 0.25
  head.Write<uint8_t>(127);   // highlight factor 0.5
  tail = head.GetBytes();

  ViewInput front;
  front.Eye[0] = center[0];
  front.Eye[1] = center[1];
  front.Eye[2] = center[2] + 2.f * extent;
  EncodeView(front, tail);
  ViewInput side = front;
  side.Eye[0] = center[0] + 3.f * extent;
  side.Eye[2] = center[2];
  side.Direction[0] = -1.f;
  side.Direction[2] = 0.f;
  side.Planes = 1;
  side.PlaneValues[0][0] = -1.f;
  side.PlaneOffsets[0] = center[0];
  EncodeView(side, tail);
  ViewInput budget = front;
  budget.Mode = 1;
  budget.Budget = static_cast<uint32_t>(piece.NumberOfTriangles() / 2);
  EncodeView(budget, tail);
  ViewInput parallel = front;
  parallel.Mode = 2;
  parallel.ParallelScale = 0.5f * extent;
  EncodeView(parallel, tail);
  ViewInput inside = front;
  inside.Eye[2] = center[2];
  inside.Reset = 1;
  EncodeView(inside, tail);
  return tail;
}

/// A TOM of the piece (separate parts joined within `pairDistance` of the
/// diagonal; 0: not) with queries at a few resolutions.
std::vector<uint8_t> TOMSeed(const TriangleMesh& piece, double pairDistance = 0.0)
{
  TOMBuildOptions options;
  options.PairContractionDistance = pairDistance;
  const TOMBuildResult built =
    TOMBuilder(options).Build(piece.Points.data(), piece.NumberOfPoints(), piece.Triangles.data(),
      piece.NumberOfTriangles());
  TOMInput tom;
  tom.Substitution = built.Mesh.Substitution;
  tom.Triangles = built.Mesh.Triangles;
  tom.BaseVertexCount = built.Mesh.BaseVertexCount;
  tom.BaseTriangleCount = built.Mesh.BaseTriangleCount;
  for (const TOMErrorCurve::Sample& s : built.Mesh.ErrorCurve.GetSamples())
  {
    tom.SampleTriangles.push_back(s.Triangles);
    tom.SampleErrors.push_back(s.Error);
  }
  const uint32_t n = built.Mesh.GetNumberOfVertices();
  const uint32_t t = built.Mesh.GetNumberOfTriangles();
  tom.Queries = {
    { TOMQuery::Extract, n / 2, 0, 0.0 },
    { TOMQuery::ExtractCapacity, n / 3, 2 * (t / 4), 0.0 },
    { TOMQuery::Resolution, 0, 0, 0.3 },
    { TOMQuery::ActiveVertex, n - 1, 2 * (n / 4), 0.0 },
    { TOMQuery::Geomorph, n / 2, 2, 0.5 },
    { TOMQuery::ErrorCurve, t / 2, 0, 0.5 * built.Mesh.ErrorCurve.GetErrorForTriangles(0) },
    { TOMQuery::VertexForTriangles, t / 3, 0, 0.0 },
  };
  return EncodeTOM(tom);
}

struct Counts
{
  int Pieces = 0;
  size_t Bytes = 0;
};

void WritePiece(
  const std::string& output, const std::string& name, const TriangleMesh& piece, Counts& counts)
{
  const uint8_t base = PreserveBoundaries | PreserveFeatureEdges;
  const std::vector<std::pair<std::string, std::vector<uint8_t>>> seeds = {
    { "fuzz_builder/" + name + "-tom", EncodeMesh(ToMeshInput(piece, base)) },
    { "fuzz_builder/" + name + "-merge",
      EncodeMesh(ToMeshInput(piece, base | SliverRejection | TargetBit0)) },
    { "fuzz_tom/" + name, TOMSeed(piece) },
  };
  for (const auto& seed : seeds)
  {
    WriteSeed(output + "/" + seed.first, seed.second);
    counts.Bytes += seed.second.size();
  }
  MeshInput refine = ToMeshInput(piece, base);
  refine.Tail = RefineTail(piece);
  const std::vector<uint8_t> bytes = EncodeMesh(refine);
  WriteSeed(output + "/fuzz_refine/" + name, bytes);
  counts.Bytes += bytes.size();
  ++counts.Pieces;
}

/// `parts` copies of a piece side by side along x, `spacing` apart.
TriangleMesh Copies(const TriangleMesh& piece, int parts, double spacing)
{
  TriangleMesh out;
  for (int c = 0; c < parts; ++c)
  {
    const uint32_t offset = static_cast<uint32_t>(out.NumberOfPoints());
    for (size_t p = 0; p < piece.NumberOfPoints(); ++p)
    {
      out.Points.insert(out.Points.end(), { piece.Points[3 * p] + spacing * c,
                                            piece.Points[3 * p + 1], piece.Points[3 * p + 2] });
    }
    for (uint32_t id : piece.Triangles)
    {
      out.Triangles.push_back(id + offset);
    }
  }
  return out;
}

/// A piece of separate parts, with pair contraction on: the builder's input
/// (tail byte 6, fuzz_builder.cxx) and the TOM it makes.
void WritePairPiece(
  const std::string& output, const std::string& name, const TriangleMesh& piece, Counts& counts)
{
  MeshInput input = ToMeshInput(piece, PreserveBoundaries | PreserveFeatureEdges);
  input.Tail = { 48, 0, 0, 0, 0, 0, 32 }; // pairs within half the diagonal
  const std::vector<std::pair<std::string, std::vector<uint8_t>>> seeds = {
    { "fuzz_builder/" + name + "-pairs", EncodeMesh(input) },
    { "fuzz_tom/" + name + "-pairs", TOMSeed(piece, 0.5) },
  };
  for (const auto& seed : seeds)
  {
    WriteSeed(output + "/" + seed.first, seed.second);
    counts.Bytes += seed.second.size();
  }
}
}

int main(int argc, char* argv[])
{
  if (argc < 2 || argc > 3)
  {
    std::fprintf(stderr, "usage: %s <output folder> [<shared data folder>]\n", argv[0]);
    return 2;
  }
  const std::string output = argv[1];
  const std::string data = argc > 2 ? argv[2] : testing::SharedDataDirectory();
  try
  {
    MakeFolder(output);
    for (const char* target : { "fuzz_tom", "fuzz_builder", "fuzz_refine" })
    {
      MakeFolder(output + "/" + target);
    }
    Counts counts;
    // Generated meshes: closed, open, creased, tiny.
    WritePiece(output, "grid", testing::MakeGrid(4, 3), counts);
    WritePiece(output, "sphere", testing::MakeSphere(1), counts);
    WritePiece(output, "torus", testing::MakeTorus(6, 4, 7, 0.2), counts);
    WritePiece(output, "cube", testing::MakeCube(1), counts);
    const TriangleMesh sphere = testing::MakeSphere(0);
    WritePiece(output, "patch", CutPiece(sphere, MapEdges(sphere), 0, 5), counts);
    // Separate parts for pair contraction: closed spheres, open patches.
    WritePairPiece(output, "spheres", Copies(testing::MakeSphere(1), 5, 2.5), counts);
    WritePairPiece(output, "patches", Copies(testing::MakeGrid(3, 3), 4, 1.5), counts);

    // Pieces of the shared meshes.
    int meshes = 0;
    for (const char* name : { "cow.obj", "spot.obj", "fandisk.obj", "teapot.obj", "homer.obj",
           "stanford-bunny.obj", "igea.ply" })
    {
      const std::string path = data + "/" + name;
      std::ifstream probe(path);
      if (!probe)
      {
        std::fprintf(stderr, "GenerateFuzzSeeds: %s not found, skipped\n", path.c_str());
        continue;
      }
      const TriangleMesh mesh = testing::WeldPoints(testing::LoadMesh(path));
      const std::string stem = std::string(name).substr(0, std::string(name).find('.'));
      const size_t triangles = mesh.NumberOfTriangles();
      const EdgeMap edges = MapEdges(mesh);
      const size_t sizes[] = { 30, 120, 300 };
      for (size_t i = 0; i < 3; ++i)
      {
        const size_t start = (triangles * (2 * i + 1)) / 6;
        WritePiece(output, stem + "-" + std::to_string(sizes[i]),
          CutPiece(mesh, edges, start, sizes[i]), counts);
      }
      ++meshes;
    }
    std::printf("GenerateFuzzSeeds: %d pieces (%d shared meshes), %zu bytes of seeds in %s\n",
      counts.Pieces, meshes, counts.Bytes, output.c_str());
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "GenerateFuzzSeeds: %s\n", e.what());
    return 1;
  }
  return 0;
}
