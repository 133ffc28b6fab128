// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_FuzzFormat_h
#define timecritical_FuzzFormat_h

/**
 * Byte formats of the fuzz targets' inputs, shared by the targets (decoding)
 * and by the seed generator (encoding), so that seeds always mean what the
 * targets read.
 *
 * Every value is little endian; reading past the end yields zero bytes, so
 * any byte string decodes to something. Array lengths announced in a header
 * are cut to what the remaining bytes can hold, which keeps the work per
 * input proportional to its size.
 *
 * TOM input (fuzz_tom):
 *   u32 vertices, u32 triangles, u32 base vertices, u32 base triangles,
 *   u8 error-curve samples, then vertices x u32 substitution,
 *   3 triangles x u32 ids, samples x (u32 triangles, f32 error),
 *   then queries (u8 kind, u32 a, u32 b, f64 x) to the end.
 *
 * Mesh input (fuzz_builder, fuzz_refine):
 *   u8 flags (MeshFlags), u8 option bytes x 4, u16 points, u16 triangles,
 *   points x 3 x (f32, or f64 with DoubleCoordinates),
 *   3 triangles x (u16, or u32 with WideIds) point ids,
 *   then the target's own tail (views, resolutions) to the end.
 */

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

namespace timecritical
{
namespace fuzz
{
/// Sequential little-endian reader over the fuzzer's bytes.
class Reader
{
public:
  Reader(const uint8_t* data, size_t size)
    : Data(data)
    , Size(size)
  {
  }

  size_t Remaining() const { return this->Size - this->Position; }
  bool AtEnd() const { return this->Position >= this->Size; }

  /// The next sizeof(T) bytes as a T (zero bytes past the end).
  template <typename T>
  T Read()
  {
    static_assert(std::is_trivially_copyable<T>::value, "plain values only");
    uint8_t bytes[sizeof(T)] = {};
    const size_t n = sizeof(T) < this->Remaining() ? sizeof(T) : this->Remaining();
    if (n > 0)
    {
      std::memcpy(bytes, this->Data + this->Position, n);
    }
    this->Position += n;
    T value;
    std::memcpy(&value, bytes, sizeof(T));
    return value;
  }

  /// A count announced as `announced` of items of `itemSize` bytes, cut to what is left.
  size_t Count(uint64_t announced, size_t itemSize) const
  {
    const uint64_t fits = this->Remaining() / itemSize;
    return static_cast<size_t>(announced < fits ? announced : fits);
  }

private:
  const uint8_t* Data;
  size_t Size;
  size_t Position = 0;
};

/// Little-endian writer for the seed generator.
class Writer
{
public:
  template <typename T>
  void Write(T value)
  {
    static_assert(std::is_trivially_copyable<T>::value, "plain values only");
    uint8_t bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    this->Bytes.insert(this->Bytes.end(), bytes, bytes + sizeof(T));
  }
  const std::vector<uint8_t>& GetBytes() const { return this->Bytes; }

private:
  std::vector<uint8_t> Bytes;
};

//------------------------------------------------------------------------------
// TOM input

/// What fuzz_tom asks of a TOM that passed validation.
enum class TOMQuery : uint8_t
{
  Extract = 0,            ///< Extract(a) into a vector, against a reference walk
  ExtractCapacity = 1,    ///< Extract(a) into exactly b triangles of room
  Resolution = 2,         ///< GetTrianglesForResolution(x), then its vertex count and mesh
  ActiveVertex = 3,       ///< GetActiveVertex(a, b)
  Geomorph = 4,           ///< Geomorph(a, x) on 1 + b % 4 components
  ErrorCurve = 5,         ///< GetErrorForTriangles(a), GetTrianglesForError(x)
  VertexForTriangles = 6, ///< GetVertexCountForTriangles(a)
  Count = 7
};

struct TOMQueryInput
{
  TOMQuery Kind = TOMQuery::Extract;
  uint32_t A = 0;
  uint32_t B = 0;
  double X = 0.0;
};

struct TOMInput
{
  std::vector<uint32_t> Substitution;
  std::vector<uint32_t> Triangles;
  uint32_t BaseVertexCount = 0;
  uint32_t BaseTriangleCount = 0;
  std::vector<uint32_t> SampleTriangles;
  std::vector<float> SampleErrors;
  std::vector<TOMQueryInput> Queries;
};

inline TOMInput DecodeTOM(const uint8_t* data, size_t size)
{
  Reader in(data, size);
  TOMInput tom;
  const uint32_t vertices = in.Read<uint32_t>();
  const uint32_t triangles = in.Read<uint32_t>();
  tom.BaseVertexCount = in.Read<uint32_t>();
  tom.BaseTriangleCount = in.Read<uint32_t>();
  const uint8_t samples = in.Read<uint8_t>();
  tom.Substitution.resize(in.Count(vertices, 4));
  for (uint32_t& s : tom.Substitution)
  {
    s = in.Read<uint32_t>();
  }
  tom.Triangles.resize(3 * in.Count(triangles, 12));
  for (uint32_t& id : tom.Triangles)
  {
    id = in.Read<uint32_t>();
  }
  const size_t sampleCount = in.Count(samples, 8);
  for (size_t i = 0; i < sampleCount; ++i)
  {
    tom.SampleTriangles.push_back(in.Read<uint32_t>());
    tom.SampleErrors.push_back(in.Read<float>());
  }
  while (!in.AtEnd())
  {
    TOMQueryInput q;
    q.Kind = static_cast<TOMQuery>(in.Read<uint8_t>() % static_cast<uint8_t>(TOMQuery::Count));
    q.A = in.Read<uint32_t>();
    q.B = in.Read<uint32_t>();
    q.X = in.Read<double>();
    tom.Queries.push_back(q);
  }
  return tom;
}

inline std::vector<uint8_t> EncodeTOM(const TOMInput& tom)
{
  Writer out;
  out.Write<uint32_t>(static_cast<uint32_t>(tom.Substitution.size()));
  out.Write<uint32_t>(static_cast<uint32_t>(tom.Triangles.size() / 3));
  out.Write<uint32_t>(tom.BaseVertexCount);
  out.Write<uint32_t>(tom.BaseTriangleCount);
  out.Write<uint8_t>(static_cast<uint8_t>(tom.SampleTriangles.size()));
  for (uint32_t s : tom.Substitution)
  {
    out.Write<uint32_t>(s);
  }
  for (uint32_t id : tom.Triangles)
  {
    out.Write<uint32_t>(id);
  }
  for (size_t i = 0; i < tom.SampleTriangles.size(); ++i)
  {
    out.Write<uint32_t>(tom.SampleTriangles[i]);
    out.Write<float>(tom.SampleErrors[i]);
  }
  for (const TOMQueryInput& q : tom.Queries)
  {
    out.Write<uint8_t>(static_cast<uint8_t>(q.Kind));
    out.Write<uint32_t>(q.A);
    out.Write<uint32_t>(q.B);
    out.Write<double>(q.X);
  }
  return out.GetBytes();
}

//------------------------------------------------------------------------------
// Mesh input

/// Bits of the mesh input's first byte.
enum MeshFlags : uint8_t
{
  WideIds = 1 << 0,           ///< point ids as u32 (else u16)
  DoubleCoordinates = 1 << 1, ///< coordinates as f64 (else f32)
  PreserveBoundaries = 1 << 2,
  PreserveFeatureEdges = 1 << 3,
  SliverRejection = 1 << 4,
  // Bits 5-7 belong to the target (which builder, corrupted merge trees, ...).
  TargetBit0 = 1 << 5,
  TargetBit1 = 1 << 6,
  TargetBit2 = 1 << 7
};

struct MeshInput
{
  uint8_t Flags = PreserveBoundaries | PreserveFeatureEdges;
  /// Builder settings, one byte each (mapped to their ranges by the targets).
  uint8_t Options[4] = { 64, 128, 0, 64 };
  std::vector<double> Points; ///< 3 per point
  std::vector<uint32_t> Triangles;
  /// The target's own bytes.
  std::vector<uint8_t> Tail;

  size_t NumberOfPoints() const { return this->Points.size() / 3; }
  size_t NumberOfTriangles() const { return this->Triangles.size() / 3; }
};

inline MeshInput DecodeMesh(const uint8_t* data, size_t size)
{
  Reader in(data, size);
  MeshInput mesh;
  mesh.Flags = in.Read<uint8_t>();
  for (uint8_t& option : mesh.Options)
  {
    option = in.Read<uint8_t>();
  }
  const uint16_t points = in.Read<uint16_t>();
  const uint16_t triangles = in.Read<uint16_t>();
  const bool doubles = (mesh.Flags & DoubleCoordinates) != 0;
  mesh.Points.resize(3 * in.Count(points, doubles ? 24 : 12));
  for (double& x : mesh.Points)
  {
    x = doubles ? in.Read<double>() : static_cast<double>(in.Read<float>());
  }
  const bool wide = (mesh.Flags & WideIds) != 0;
  mesh.Triangles.resize(3 * in.Count(triangles, wide ? 12 : 6));
  for (uint32_t& id : mesh.Triangles)
  {
    id = wide ? in.Read<uint32_t>() : in.Read<uint16_t>();
  }
  while (!in.AtEnd())
  {
    mesh.Tail.push_back(in.Read<uint8_t>());
  }
  return mesh;
}

inline std::vector<uint8_t> EncodeMesh(const MeshInput& mesh)
{
  Writer out;
  out.Write<uint8_t>(mesh.Flags);
  for (uint8_t option : mesh.Options)
  {
    out.Write<uint8_t>(option);
  }
  out.Write<uint16_t>(static_cast<uint16_t>(mesh.NumberOfPoints()));
  out.Write<uint16_t>(static_cast<uint16_t>(mesh.NumberOfTriangles()));
  for (double x : mesh.Points)
  {
    if (mesh.Flags & DoubleCoordinates)
    {
      out.Write<double>(x);
    }
    else
    {
      out.Write<float>(static_cast<float>(x));
    }
  }
  for (uint32_t id : mesh.Triangles)
  {
    if (mesh.Flags & WideIds)
    {
      out.Write<uint32_t>(id);
    }
    else
    {
      out.Write<uint16_t>(static_cast<uint16_t>(id));
    }
  }
  std::vector<uint8_t> bytes = out.GetBytes();
  bytes.insert(bytes.end(), mesh.Tail.begin(), mesh.Tail.end());
  return bytes;
}

//------------------------------------------------------------------------------
// Views (fuzz_refine's tail)

/// One update of fuzz_refine: a view and how to update
/// (3 u8, u32, u16, 13 f32, then 4 f32 per frustum plane).
struct ViewInput
{
  uint8_t Mode = 0;   ///< bit 0: budget update (else fixed accuracy); bit 1: parallel projection
  uint8_t Planes = 0; ///< number of frustum planes (taken modulo 7)
  uint8_t Reset = 0;  ///< bit 0: Reset() before the update
  uint32_t Budget = 0;
  uint16_t OperationLimit = 0;
  float Eye[3] = { 0.f, 0.f, 3.f };
  float Direction[3] = { 0.f, 0.f, -1.f };
  float ViewportHeight = 256.f;
  float ViewAngle = 30.f;
  float ParallelScale = 1.f;
  float Light[3] = { 0.f, 0.f, 1.f };
  float NearDistance = 0.f;
  float PlaneValues[6][3] = {}; ///< normal of each plane; its offset is the next value
  float PlaneOffsets[6] = {};
};

inline ViewInput DecodeView(Reader& in)
{
  ViewInput v;
  v.Mode = in.Read<uint8_t>();
  v.Planes = in.Read<uint8_t>();
  v.Reset = in.Read<uint8_t>();
  v.Budget = in.Read<uint32_t>();
  v.OperationLimit = in.Read<uint16_t>();
  for (float& x : v.Eye)
  {
    x = in.Read<float>();
  }
  for (float& x : v.Direction)
  {
    x = in.Read<float>();
  }
  v.ViewportHeight = in.Read<float>();
  v.ViewAngle = in.Read<float>();
  v.ParallelScale = in.Read<float>();
  for (float& x : v.Light)
  {
    x = in.Read<float>();
  }
  v.NearDistance = in.Read<float>();
  const int planes = v.Planes % 7;
  for (int p = 0; p < planes; ++p)
  {
    for (float& x : v.PlaneValues[p])
    {
      x = in.Read<float>();
    }
    v.PlaneOffsets[p] = in.Read<float>();
  }
  return v;
}

inline void EncodeView(const ViewInput& v, std::vector<uint8_t>& bytes)
{
  Writer out;
  out.Write<uint8_t>(v.Mode);
  out.Write<uint8_t>(v.Planes);
  out.Write<uint8_t>(v.Reset);
  out.Write<uint32_t>(v.Budget);
  out.Write<uint16_t>(v.OperationLimit);
  for (float x : v.Eye)
  {
    out.Write<float>(x);
  }
  for (float x : v.Direction)
  {
    out.Write<float>(x);
  }
  out.Write<float>(v.ViewportHeight);
  out.Write<float>(v.ViewAngle);
  out.Write<float>(v.ParallelScale);
  for (float x : v.Light)
  {
    out.Write<float>(x);
  }
  out.Write<float>(v.NearDistance);
  const int planes = v.Planes % 7;
  for (int p = 0; p < planes; ++p)
  {
    for (float x : v.PlaneValues[p])
    {
      out.Write<float>(x);
    }
    out.Write<float>(v.PlaneOffsets[p]);
  }
  bytes.insert(bytes.end(), out.GetBytes().begin(), out.GetBytes().end());
}
}
}

#endif
