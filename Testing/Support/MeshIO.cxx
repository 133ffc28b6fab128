// SPDX-License-Identifier: BSD-3-Clause
#include "MeshIO.h"

// OpenMesh's VectorT leaves its coordinates uninitialised by design, which
// GCC 12 reports (maybe-uninitialized) where they are copied.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <OpenMesh/Core/IO/IOManager.hh>
#include <OpenMesh/Core/IO/importer/BaseImporter.hh>
#include <OpenMesh/Core/System/omstream.hh>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>
#include <mutex>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <unordered_map>
#include <utility>

namespace timecritical
{
namespace testing
{
namespace
{
constexpr uint64_t MaxPointId = std::numeric_limits<uint32_t>::max();

[[noreturn]] void Fail(const std::string& path, const std::string& where, const std::string& what)
{
  std::string message = "MeshIO: " + path;
  if (!where.empty())
  {
    message += ", " + where;
  }
  message += ": " + what;
  throw std::runtime_error(message);
}

std::string ReadWholeFile(const std::string& path)
{
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status))
  {
    Fail(path, "", "no such file");
  }
  if (!std::filesystem::is_regular_file(status))
  {
    Fail(path, "", "not a regular file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    Fail(path, "", "cannot open file for reading");
  }
  std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad())
  {
    Fail(path, "", "read error");
  }
  return data;
}

std::string Lower(std::string text)
{
  for (char& c : text)
  {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return text;
}

bool HostIsLittleEndian()
{
  const uint16_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

inline bool IsBlank(char c)
{
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

/// Whitespace-separated words of one line.
std::vector<std::string> SplitWords(const std::string& line)
{
  std::vector<std::string> words;
  std::size_t i = 0;
  while (i < line.size())
  {
    while (i < line.size() && IsBlank(line[i]))
    {
      ++i;
    }
    const std::size_t start = i;
    while (i < line.size() && !IsBlank(line[i]))
    {
      ++i;
    }
    if (i > start)
    {
      words.push_back(line.substr(start, i - start));
    }
  }
  return words;
}

//------------------------------------------------------------------------------
// OpenMesh's readers into plain arrays

/**
 * Receives what OpenMesh's OBJ and PLY readers report. No halfedge structure
 * (an OpenMesh TriMesh would reject or split non-manifold input such as the
 * cow's pinch vertex), so every point of the file is kept, in file order,
 * used or not, and every face is fan-triangulated in file order. OpenMesh
 * passes face corners through without checking them, so they are checked
 * here; the first problem is kept in Error (no exception is thrown through
 * OpenMesh's code).
 */
class ArrayImporter final : public OpenMesh::IO::BaseImporter
{
public:
  using VertexHandle = OpenMesh::VertexHandle;
  using FaceHandle = OpenMesh::FaceHandle;
  using HalfedgeHandle = OpenMesh::HalfedgeHandle;
  using EdgeHandle = OpenMesh::EdgeHandle;
  using Status = OpenMesh::Attributes::StatusInfo;

  ArrayImporter(TriangleMesh& mesh, bool oneBased)
    : Mesh(mesh)
    , OneBased(oneBased)
  {
  }

  std::size_t Faces = 0;   ///< add_face calls
  std::size_t Corners = 0; ///< their corners, all together
  std::string Error;       ///< first problem found

  // OpenMesh 9's OBJ reader calls add_vertex(Vec3f); its PLY reader calls
  // add_vertex() then set_point(Vec3f). The double overload is taken too, for
  // a reader that would pass doubles.
  VertexHandle add_vertex(const OpenMesh::Vec3f& point) override
  {
    return this->AddPoint(point[0], point[1], point[2]);
  }
  VertexHandle add_vertex(const OpenMesh::Vec3d& point) override
  {
    return this->AddPoint(point[0], point[1], point[2]);
  }
  VertexHandle add_vertex() override { return this->AddPoint(0.0, 0.0, 0.0); }
  void set_point(VertexHandle vertex, const OpenMesh::Vec3f& point) override
  {
    const std::size_t id = static_cast<std::size_t>(vertex.idx());
    if (vertex.idx() < 0 || id >= this->Mesh.NumberOfPoints())
    {
      this->Note("OpenMesh set the point of vertex " + std::to_string(vertex.idx()) + " of " +
        std::to_string(this->Mesh.NumberOfPoints()));
      return;
    }
    for (int axis = 0; axis < 3; ++axis)
    {
      this->Mesh.Points[3 * id + axis] = point[axis];
    }
    this->CheckFinite(id);
  }

  FaceHandle add_face(const VHandles& corners) override
  {
    const std::size_t face = this->Faces++;
    this->Corners += corners.size();
    const std::string where = "face #" + std::to_string(face) + " (in file order): ";
    if (corners.size() < 3)
    {
      this->Note(
        where + std::to_string(corners.size()) + " distinct vertices (at least 3 needed)");
      return FaceHandle(static_cast<int>(face));
    }
    const int64_t n = static_cast<int64_t>(this->Mesh.NumberOfPoints());
    for (const VertexHandle corner : corners)
    {
      if (corner.idx() < 0 || corner.idx() >= n)
      {
        const std::string count = std::to_string(n);
        this->Note(this->OneBased
            ? where + "vertex " + std::to_string(corner.idx() + 1) + " out of range 1.." + count +
              " (1-based, relative indices resolved by OpenMesh; the file has " + count +
              " vertices)"
            : where + "vertex index " + std::to_string(corner.idx()) + " out of range [0, " +
              count + ")");
        return FaceHandle(static_cast<int>(face));
      }
    }
    for (std::size_t k = 1; k + 1 < corners.size(); ++k)
    {
      for (const std::size_t c : { std::size_t(0), k, k + 1 })
      {
        this->Mesh.Triangles.push_back(static_cast<uint32_t>(corners[c].idx()));
      }
    }
    return FaceHandle(static_cast<int>(face));
  }

  std::size_t n_vertices() const override { return this->Mesh.NumberOfPoints(); }
  std::size_t n_faces() const override { return this->Faces; }
  std::size_t n_edges() const override { return 0; }

  // What the loaders do not keep.
  HalfedgeHandle add_edge(VertexHandle, VertexHandle) override { return HalfedgeHandle(); }
  FaceHandle add_face(HalfedgeHandle) override { return FaceHandle(); }
  void add_face_texcoords(FaceHandle, VertexHandle, const std::vector<OpenMesh::Vec2f>&) override
  {
  }
  void add_face_texcoords(FaceHandle, VertexHandle, const std::vector<OpenMesh::Vec3f>&) override
  {
  }
  void set_face_texindex(FaceHandle, int) override {}
  void set_halfedge(VertexHandle, HalfedgeHandle) override {}
  void set_normal(VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(VertexHandle, const OpenMesh::Vec3d&) override {}
  void set_color(VertexHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(VertexHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_color(VertexHandle, const OpenMesh::Vec4f&) override {}
  void set_texcoord(VertexHandle, const OpenMesh::Vec2f&) override {}
  void set_status(VertexHandle, const Status&) override {}
  void set_next(HalfedgeHandle, HalfedgeHandle) override {}
  void set_face(HalfedgeHandle, FaceHandle) override {}
  void request_face_texcoords2D() override {}
  void set_texcoord(HalfedgeHandle, const OpenMesh::Vec2f&) override {}
  void set_texcoord(VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_texcoord(HalfedgeHandle, const OpenMesh::Vec3f&) override {}
  void set_status(HalfedgeHandle, const Status&) override {}
  void set_color(EdgeHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(EdgeHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(EdgeHandle, const OpenMesh::Vec3f&) override {}
  void set_color(EdgeHandle, const OpenMesh::Vec4f&) override {}
  void set_status(EdgeHandle, const Status&) override {}
  void set_normal(FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(FaceHandle, const OpenMesh::Vec3d&) override {}
  void set_color(FaceHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(FaceHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_color(FaceHandle, const OpenMesh::Vec4f&) override {}
  void set_status(FaceHandle, const Status&) override {}
  void add_texture_information(int, std::string) override {}

private:
  VertexHandle AddPoint(double x, double y, double z)
  {
    if (this->Mesh.NumberOfPoints() >= MaxPointId)
    {
      this->Note("more than 2^32-1 vertices");
      return VertexHandle();
    }
    this->Mesh.Points.insert(this->Mesh.Points.end(), { x, y, z });
    this->CheckFinite(this->Mesh.NumberOfPoints() - 1);
    return VertexHandle(static_cast<int>(this->Mesh.NumberOfPoints() - 1));
  }

  void CheckFinite(std::size_t id)
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      if (!std::isfinite(this->Mesh.Points[3 * id + axis]))
      {
        this->Note("vertex #" + std::to_string(id) +
          ": non-finite coordinate (OpenMesh reads coordinates as float: values beyond "
          "float range, 3.4e38, overflow)");
        return;
      }
    }
  }

  void Note(const std::string& problem)
  {
    if (this->Error.empty())
    {
      this->Error = problem;
    }
  }

  TriangleMesh& Mesh;
  bool OneBased;
};

/// Captures what OpenMesh writes to omerr and omlog (connected to std::cerr
/// and std::clog by default) while alive, for the exception of a failed read.
/// It swaps the streams' buffers rather than reconnecting OpenMesh's
/// multiplexers, whose connect() leaks a small object each time.
class CaptureOpenMeshLog
{
public:
  CaptureOpenMeshLog()
    : Err(std::cerr.rdbuf(this->Text.rdbuf()))
    , Log(std::clog.rdbuf(this->Text.rdbuf()))
  {
  }
  ~CaptureOpenMeshLog()
  {
    ::omerr().flush();
    ::omlog().flush();
    std::cerr.rdbuf(this->Err);
    std::clog.rdbuf(this->Log);
  }
  CaptureOpenMeshLog(const CaptureOpenMeshLog&) = delete;
  CaptureOpenMeshLog& operator=(const CaptureOpenMeshLog&) = delete;

  /// What OpenMesh wrote so far, lines joined by "; ".
  std::string Messages()
  {
    ::omerr().flush();
    ::omlog().flush();
    std::string text = this->Text.str();
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r'))
    {
      text.pop_back();
    }
    std::string joined;
    for (const char c : text)
    {
      joined += c == '\n' ? std::string("; ") : std::string(1, c);
    }
    return joined.empty() ? std::string("no message") : joined;
  }

private:
  std::ostringstream Text;
  std::streambuf* Err;
  std::streambuf* Log;
};

/// Reads `data` with OpenMesh's reader for `format` ("OBJ", "PLY") into the
/// importer; throws (naming the file and quoting OpenMesh) when it fails.
void ReadWithOpenMesh(const std::string& path, const std::string& data, const char* format,
  ArrayImporter& importer)
{
  // OpenMesh's log streams and std::cerr are process-wide.
  static std::mutex mutex;
  const std::lock_guard<std::mutex> lock(mutex);
  CaptureOpenMeshLog log;
  std::istringstream in(data);
  OpenMesh::IO::Options options;
  if (!OpenMesh::IO::IOManager().read(in, format, importer, options))
  {
    Fail(path, "", std::string("OpenMesh's ") + format + " reader failed (" + log.Messages() + ")");
  }
}

//------------------------------------------------------------------------------
// OBJ: OpenMesh's reader skips malformed `v` and `f` lines without a word (a
// vertex with a bad, missing or out-of-float-range coordinate, a face with
// fewer than 3 distinct corners, a `\` continuation) and aborts on an
// assertion for a face corner without a vertex index (`f /1 2/1 3/1`, Debian's
// build keeps assertions), so the `v` and `f` statements are checked here
// first (with line numbers), and counted to catch what is still skipped.

struct OBJStatements
{
  std::size_t Vertices = 0;
  std::size_t Faces = 0;
};

OBJStatements CheckOBJStatements(const std::string& path, const std::string& data)
{
  OBJStatements counts;
  std::size_t lineNumber = 0;
  for (std::size_t i = 0; i < data.size();)
  {
    ++lineNumber;
    std::size_t end = data.find('\n', i);
    end = end == std::string::npos ? data.size() : end;
    std::vector<std::string> words = SplitWords(data.substr(i, end - i));
    i = end + 1;
    const auto comment = std::find_if(
      words.begin(), words.end(), [](const std::string& word) { return word[0] == '#'; });
    words.erase(comment, words.end());
    if (words.empty() || (words[0] != "v" && words[0] != "f"))
    {
      continue;
    }
    const std::string where = "line " + std::to_string(lineNumber);
    if (words[0] == "v" && words.size() < 4)
    {
      Fail(path, where, "vertex with fewer than 3 coordinates");
    }
    if (words.back().back() == '\\')
    {
      Fail(path, where, "'\\' line continuation (OpenMesh's OBJ reader does not join lines)");
    }
    for (std::size_t k = 1; k < words.size() && (words[0] == "f" || k < 4); ++k)
    {
      const std::string& word = words[k];
      const char* first = word.data() + (word[0] == '+');
      const char* last = word.data() + word.size();
      double value = 0.0;
      int64_t index = 0;
      if (words[0] == "v" && std::from_chars(first, last, value).ptr != last)
      {
        Fail(path, where, "bad vertex coordinate '" + word + "'");
      }
      if (words[0] == "v" && std::fabs(value) > std::numeric_limits<float>::max())
      {
        Fail(path, where,
          "vertex coordinate '" + word +
            "' beyond float range (OpenMesh's OBJ reader reads float)");
      }
      if (words[0] == "f" && std::from_chars(first, last, index).ptr == first)
      {
        Fail(path, where, "bad face corner '" + word + "'");
      }
      if (words[0] == "f" && index == 0)
      {
        Fail(path, where, "vertex index 0 (OBJ indices start at 1)");
      }
    }
    ++(words[0] == "v" ? counts.Vertices : counts.Faces);
  }
  return counts;
}

//------------------------------------------------------------------------------
// PLY: the header is read here to check that the file is in the part of the
// format OpenMesh 9's PLY reader reads correctly (measured: it loops forever
// without end_header, and reads garbage without an error from vertex elements
// with list properties, from integer coordinates in binary files, and from
// faces whose vertex list is not their first property or that have another
// list), and for the `tristrips` element, which it skips and which is decoded
// here. In ascii bodies it also reads a malformed number or a missing value as
// 0 without an error, so ascii bodies are checked to hold numbers and exactly
// the values the header declares.

struct PLYProperty
{
  std::string Name;
  std::string Type; ///< of the items for a list
  bool IsList = false;
  std::string CountType;
};

struct PLYElement
{
  std::string Name;
  uint64_t Count = 0;
  std::vector<PLYProperty> Properties;
};

struct PLYHeader
{
  std::string Format;
  std::vector<PLYElement> Elements;
  std::size_t BodyOffset = 0; ///< first byte after the end_header line
  std::size_t BodyLine = 0;   ///< line number of the first body line
};

/// Size in bytes of a PLY scalar type; 0 if unknown.
std::size_t ScalarSize(const std::string& type)
{
  static const std::pair<const char*, std::size_t> sizes[] = { { "char", 1 }, { "int8", 1 },
    { "uchar", 1 }, { "uint8", 1 }, { "short", 2 }, { "int16", 2 }, { "ushort", 2 },
    { "uint16", 2 }, { "int", 4 }, { "int32", 4 }, { "uint", 4 }, { "uint32", 4 }, { "float", 4 },
    { "float32", 4 }, { "double", 8 }, { "float64", 8 } };
  for (const auto& entry : sizes)
  {
    if (type == entry.first)
    {
      return entry.second;
    }
  }
  return 0;
}

bool IsFloatingPoint(const std::string& type)
{
  return type == "float" || type == "float32" || type == "double" || type == "float64";
}

bool IsIntegral(const std::string& type)
{
  return ScalarSize(type) != 0 && !IsFloatingPoint(type);
}

PLYHeader ParsePLYHeader(const std::string& path, const std::string& data)
{
  PLYHeader header;
  std::size_t offset = 0;
  std::size_t lineNumber = 0;
  while (true)
  {
    if (offset >= data.size())
    {
      Fail(path, "header", "no end_header line (OpenMesh's PLY reader would never return)");
    }
    ++lineNumber;
    const std::size_t newline = data.find('\n', offset);
    const std::size_t lineEnd = newline == std::string::npos ? data.size() : newline;
    const std::vector<std::string> words = SplitWords(data.substr(offset, lineEnd - offset));
    offset = newline == std::string::npos ? data.size() : newline + 1;
    const std::string where = "header line " + std::to_string(lineNumber);
    if (lineNumber == 1 && (words.size() != 1 || words[0] != "ply"))
    {
      Fail(path, where, "not a PLY file (first line is not 'ply')");
    }
    if (words.empty())
    {
      continue;
    }
    if (words[0] == "end_header")
    {
      break;
    }
    if (words[0] == "format")
    {
      if (words.size() != 3 || words[2] != "1.0")
      {
        Fail(path, where, "unsupported format line (expected 'format <ascii|binary_...> 1.0')");
      }
      header.Format = words[1];
    }
    else if (words[0] == "element")
    {
      PLYElement element;
      uint64_t count = 0;
      if (words.size() != 3 ||
        std::from_chars(words[2].data(), words[2].data() + words[2].size(), count).ptr !=
          words[2].data() + words[2].size())
      {
        Fail(path, where, "malformed element line");
      }
      element.Name = words[1];
      element.Count = count;
      header.Elements.push_back(element);
    }
    else if (words[0] == "property")
    {
      PLYProperty property;
      property.IsList = words.size() == 5 && words[1] == "list";
      if (header.Elements.empty() || (!property.IsList && words.size() != 3))
      {
        Fail(path, where, "malformed property line");
      }
      property.Name = words.back();
      property.Type = words[words.size() - 2];
      property.CountType = property.IsList ? words[2] : std::string();
      if (ScalarSize(property.Type) == 0 ||
        (property.IsList && !IsIntegral(property.CountType)))
      {
        Fail(path, where, "unknown property type in '" + property.Name + "'");
      }
      header.Elements.back().Properties.push_back(property);
    }
  }
  if (header.Format != "ascii" && header.Format != "binary_little_endian" &&
    header.Format != "binary_big_endian")
  {
    Fail(path, "header", "no known format line");
  }
  header.BodyOffset = offset;
  header.BodyLine = lineNumber + 1;
  return header;
}

/// Rejects what OpenMesh 9's PLY reader would misread (see above).
void CheckOpenMeshReadsPLY(const std::string& path, const PLYHeader& header)
{
  bool haveVertices = false;
  for (const PLYElement& element : header.Elements)
  {
    const std::string where = "element '" + element.Name + "'";
    if (element.Name == "vertex")
    {
      haveVertices = true;
      for (const PLYProperty& property : element.Properties)
      {
        if (property.IsList)
        {
          Fail(path, where,
            "list property '" + property.Name + "' (OpenMesh's PLY reader misreads those)");
        }
      }
      for (const char* axis : { "x", "y", "z" })
      {
        auto found = std::find_if(element.Properties.begin(), element.Properties.end(),
          [&](const PLYProperty& property) { return property.Name == axis; });
        if (found == element.Properties.end())
        {
          Fail(path, where, std::string("no '") + axis + "' property");
        }
        if (!IsFloatingPoint(found->Type))
        {
          Fail(path, where,
            std::string("'") + axis + "' is " + found->Type +
              " (OpenMesh's PLY reader reads float or double coordinates)");
        }
      }
    }
    else if (element.Name == "face")
    {
      for (std::size_t p = 0; p < element.Properties.size(); ++p)
      {
        const PLYProperty& property = element.Properties[p];
        const bool indices = property.Name == "vertex_indices" || property.Name == "vertex_index";
        if ((p == 0) != (indices && property.IsList) || (p > 0 && property.IsList))
        {
          Fail(path, where,
            "OpenMesh's PLY reader reads faces whose first property is the vertex_indices list "
            "and whose other properties are scalars");
        }
        if (indices && !IsIntegral(property.Type))
        {
          Fail(path, where, "property '" + property.Name + "' must be a list of integers");
        }
      }
    }
  }
  if (!haveVertices)
  {
    Fail(path, "header", "no 'vertex' element");
  }
}

/// The body of a PLY file as a sequence of integer reads: bytes of a binary
/// body, numbers of an ascii body (tokenised and checked to be numbers once).
class PLYBody
{
public:
  PLYBody(const std::string& path, const std::string& data, const PLYHeader& header)
    : Data(data)
    , Offset(header.BodyOffset)
    , Ascii(header.Format == "ascii")
  {
    this->Swap = (header.Format == "binary_big_endian") == HostIsLittleEndian();
    if (!this->Ascii)
    {
      return;
    }
    std::size_t line = header.BodyLine;
    for (std::size_t i = header.BodyOffset; i < data.size();)
    {
      if (IsBlank(data[i]) || data[i] == '\n')
      {
        line += data[i++] == '\n';
        continue;
      }
      const std::size_t start = i;
      while (i < data.size() && !IsBlank(data[i]) && data[i] != '\n')
      {
        ++i;
      }
      const char* first = data.data() + start + (data[start] == '+');
      double value;
      if (std::from_chars(first, data.data() + i, value).ptr != data.data() + i)
      {
        Fail(path, "line " + std::to_string(line),
          "number expected, got '" + data.substr(start, i - start) + "'");
      }
      if (std::fabs(value) > std::numeric_limits<float>::max())
      {
        // OpenMesh reads with `>> float`, which fails there and reads 0s after.
        Fail(path, "line " + std::to_string(line),
          "'" + data.substr(start, i - start) +
            "' is beyond float range (OpenMesh's PLY reader reads float)");
      }
      this->Tokens.emplace_back(start, i);
    }
  }

  /// Numbers (ascii) or bytes (binary) in the body.
  uint64_t Size() const
  {
    return this->Ascii ? this->Tokens.size() : this->Data.size() - this->Offset;
  }

  /// Units one value of `type` takes.
  uint64_t Units(const std::string& type) const { return this->Ascii ? 1 : ScalarSize(type); }

  /// Reads the integer of `type` at `position` and advances it; false at the end.
  bool ReadInt(const std::string& type, uint64_t& position, int64_t& value) const
  {
    if (position + this->Units(type) > this->Size())
    {
      return false;
    }
    if (this->Ascii)
    {
      const auto [start, end] = this->Tokens[static_cast<std::size_t>(position++)];
      const char* first = this->Data.data() + start + (this->Data[start] == '+');
      if (std::from_chars(first, this->Data.data() + end, value).ptr != this->Data.data() + end)
      {
        value = std::numeric_limits<int64_t>::min(); // not an integer: out of any range
      }
      return true;
    }
    const std::size_t size = ScalarSize(type);
    unsigned char bytes[4] = { 0, 0, 0, 0 };
    std::memcpy(bytes, this->Data.data() + this->Offset + position, size);
    position += size;
    if (this->Swap)
    {
      std::reverse(bytes, bytes + size);
    }
    const bool isSigned = type == "char" || type == "int8" || type == "short" ||
      type == "int16" || type == "int" || type == "int32";
    if (size == 1)
    {
      value = isSigned ? int64_t(int8_t(bytes[0])) : int64_t(bytes[0]);
    }
    else if (size == 2)
    {
      uint16_t raw;
      std::memcpy(&raw, bytes, 2);
      value = isSigned ? int64_t(int16_t(raw)) : int64_t(raw);
    }
    else
    {
      uint32_t raw;
      std::memcpy(&raw, bytes, 4);
      value = isSigned ? int64_t(int32_t(raw)) : int64_t(raw);
    }
    return true;
  }

private:
  const std::string& Data;
  std::size_t Offset;
  bool Ascii;
  bool Swap = false;
  std::vector<std::pair<std::size_t, std::size_t>> Tokens; ///< [start, end) of each number
};

// Append the triangles of one strip (entries of `strip`; -1 restarts).
// Triangle k of a run s0 s1 s2 ... is (s_k, s_k+1, s_k+2) for even k and
// (s_k+1, s_k, s_k+2) for odd k; triangles with two equal ids (the joins of
// strips stitched with repeated vertices) are dropped but keep the parity.
template <class FailFunction>
void DecodeStrip(const std::vector<int64_t>& strip, uint64_t vertexCount,
  std::vector<uint32_t>& triangles, FailFunction&& fail)
{
  std::size_t runStart = 0;
  for (std::size_t k = 0; k < strip.size(); ++k)
  {
    const int64_t id = strip[k];
    if (id == -1)
    {
      runStart = k + 1;
      continue;
    }
    if (id < 0 || static_cast<uint64_t>(id) >= vertexCount)
    {
      fail("strip vertex index " +
        (id == std::numeric_limits<int64_t>::min() ? std::string("not an integer")
                                                   : std::to_string(id)) +
        " out of range [0, " + std::to_string(vertexCount) + ")");
    }
    const std::size_t position = k - runStart;
    if (position < 2)
    {
      continue;
    }
    uint32_t a = static_cast<uint32_t>(strip[k - 2]);
    uint32_t b = static_cast<uint32_t>(strip[k - 1]);
    const uint32_t c = static_cast<uint32_t>(id);
    if ((position - 2) % 2 == 1)
    {
      std::swap(a, b);
    }
    if (a == b || b == c || a == c)
    {
      continue;
    }
    triangles.push_back(a);
    triangles.push_back(b);
    triangles.push_back(c);
  }
}

/**
 * Walks the body element by element: decodes `tristrips` (OpenMesh skips
 * them) into mesh.Triangles, and returns where the body should end (numbers
 * for ascii, bytes for binary) from the header and the face corners OpenMesh
 * reported, or -1 when an element of unknown layout (a list in an element
 * other than face and tristrips) makes that unknowable.
 */
int64_t DecodeStripsAndMeasureBody(const std::string& path, const PLYHeader& header,
  const PLYBody& body, std::size_t faceCorners, TriangleMesh& mesh)
{
  uint64_t vertexCount = 0;
  for (const PLYElement& element : header.Elements)
  {
    vertexCount = element.Name == "vertex" ? element.Count : vertexCount;
  }
  uint64_t position = 0;
  std::vector<int64_t> strip;
  for (const PLYElement& element : header.Elements)
  {
    if (element.Name == "tristrips")
    {
      if (element.Properties.size() != 1 || !element.Properties[0].IsList ||
        element.Properties[0].Name != "vertex_indices" ||
        !IsIntegral(element.Properties[0].Type))
      {
        Fail(path, "element 'tristrips'", "expected one property: a vertex_indices integer list");
      }
      const PLYProperty& list = element.Properties[0];
      for (uint64_t i = 0; i < element.Count; ++i)
      {
        const std::string where = "element 'tristrips' #" + std::to_string(i);
        int64_t count = 0;
        if (!body.ReadInt(list.CountType, position, count))
        {
          Fail(path, where, "unexpected end of file");
        }
        if (count < 0)
        {
          Fail(path, where, "negative list count " + std::to_string(count));
        }
        if (static_cast<uint64_t>(count) > body.Size())
        {
          Fail(path, where, "unexpected end of file");
        }
        strip.resize(static_cast<std::size_t>(count));
        for (int64_t& id : strip)
        {
          if (!body.ReadInt(list.Type, position, id))
          {
            Fail(path, where, "unexpected end of file");
          }
        }
        DecodeStrip(strip, vertexCount, mesh.Triangles,
          [&](const std::string& what) { Fail(path, where, what); });
      }
      continue;
    }
    uint64_t rowUnits = 0;
    for (const PLYProperty& property : element.Properties)
    {
      if (property.IsList && element.Name != "face")
      {
        // Unknown layout: the strips must come before this element.
        for (auto later = &element; later != header.Elements.data() + header.Elements.size();
             ++later)
        {
          if (later->Name == "tristrips")
          {
            Fail(path, "element 'tristrips'",
              "comes after element '" + element.Name + "' with a list property");
          }
        }
        return -1;
      }
      rowUnits += property.IsList ? body.Units(property.CountType) : body.Units(property.Type);
    }
    position += element.Count * rowUnits;
    if (element.Name == "face" && !element.Properties.empty())
    {
      position += faceCorners * body.Units(element.Properties[0].Type);
    }
  }
  return static_cast<int64_t>(position);
}

//------------------------------------------------------------------------------
// Hashing

inline uint64_t Mix(uint64_t x)
{
  // splitmix64 finalizer
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

struct Key3
{
  uint64_t V[3];
  bool operator==(const Key3& other) const
  {
    return this->V[0] == other.V[0] && this->V[1] == other.V[1] && this->V[2] == other.V[2];
  }
};

struct Key3Hash
{
  std::size_t operator()(const Key3& key) const
  {
    return static_cast<std::size_t>(Mix(key.V[0] ^ Mix(key.V[1] ^ Mix(key.V[2]))));
  }
};

uint64_t DoubleBits(double value)
{
  if (value == 0.0)
  {
    value = 0.0; // -0.0 and +0.0 are the same position
  }
  uint64_t bits;
  std::memcpy(&bits, &value, sizeof(bits));
  return bits;
}

struct UnionFind
{
  explicit UnionFind(std::size_t n)
    : Parent(n)
  {
    std::iota(this->Parent.begin(), this->Parent.end(), std::size_t(0));
  }
  std::size_t Find(std::size_t x)
  {
    while (this->Parent[x] != x)
    {
      this->Parent[x] = this->Parent[this->Parent[x]];
      x = this->Parent[x];
    }
    return x;
  }
  void Unite(std::size_t a, std::size_t b)
  {
    a = this->Find(a);
    b = this->Find(b);
    if (a != b)
    {
      this->Parent[std::max(a, b)] = std::min(a, b);
    }
  }
  std::vector<std::size_t> Parent;
};

void CheckTriangleIds(const TriangleMesh& mesh, const char* function)
{
  const std::size_t n = mesh.NumberOfPoints();
  for (std::size_t i = 0; i < mesh.Triangles.size(); ++i)
  {
    if (mesh.Triangles[i] >= n)
    {
      throw std::invalid_argument(std::string(function) + ": triangle " + std::to_string(i / 3) +
        " uses point " + std::to_string(mesh.Triangles[i]) + " of " + std::to_string(n));
    }
  }
}

std::array<double, 3> PointAt(const TriangleMesh& mesh, uint32_t id)
{
  return { mesh.Points[3 * std::size_t(id)], mesh.Points[3 * std::size_t(id) + 1],
    mesh.Points[3 * std::size_t(id) + 2] };
}

void Require(bool condition, const char* message)
{
  if (!condition)
  {
    throw std::invalid_argument(message);
  }
}

// Deterministic uniform value in [-1, 1] for (seed, index).
double SignedNoise(uint32_t seed, std::size_t index)
{
  const uint64_t bits = Mix(Mix(seed) ^ static_cast<uint64_t>(index));
  return static_cast<double>(bits >> 11) * (2.0 / 9007199254740992.0) - 1.0;
}
}

//------------------------------------------------------------------------------
std::string SharedDataDirectory()
{
  return TIMECRITICAL_SHARED_DATA_DIR;
}

//------------------------------------------------------------------------------
SharedMesh FindSharedMesh(const std::string& name)
{
  SharedMesh result;
  result.Path = SharedDataDirectory() + "/" + name;
  std::error_code ec;
  result.Available = std::filesystem::is_regular_file(result.Path, ec) && !ec &&
    std::ifstream(result.Path, std::ios::binary).good();
  return result;
}

//------------------------------------------------------------------------------
TriangleMesh LoadMesh(const std::string& path)
{
  const std::string extension = Lower(std::filesystem::path(path).extension().string());
  if (extension == ".obj")
  {
    return LoadOBJ(path);
  }
  if (extension == ".ply")
  {
    return LoadPLY(path);
  }
  Fail(path, "", "unsupported extension '" + extension + "' (expected .obj or .ply)");
}

//------------------------------------------------------------------------------
TriangleMesh LoadOBJ(const std::string& path)
{
  const std::string data = ReadWholeFile(path);
  const OBJStatements statements = CheckOBJStatements(path, data);
  const std::size_t vertexLines = statements.Vertices;
  const std::size_t faceLines = statements.Faces;
  TriangleMesh mesh;
  ArrayImporter importer(mesh, true);
  ReadWithOpenMesh(path, data, "OBJ", importer);
  if (mesh.NumberOfPoints() != vertexLines)
  {
    Fail(path, "",
      "OpenMesh's OBJ reader accepted " + std::to_string(mesh.NumberOfPoints()) + " of the " +
        std::to_string(vertexLines) +
        " 'v' lines");
  }
  if (!importer.Error.empty())
  {
    Fail(path, "", importer.Error);
  }
  if (importer.Faces != faceLines)
  {
    Fail(path, "",
      "OpenMesh's OBJ reader accepted " + std::to_string(importer.Faces) + " of the " +
        std::to_string(faceLines) +
        " 'f' lines (it skips a face with fewer than 3 distinct vertices)");
  }
  return mesh;
}

//------------------------------------------------------------------------------
TriangleMesh LoadPLY(const std::string& path)
{
  const std::string data = ReadWholeFile(path);
  const PLYHeader header = ParsePLYHeader(path, data);
  CheckOpenMeshReadsPLY(path, header);
  const PLYBody body(path, data, header); // checks that an ascii body holds numbers
  // OpenMesh's ascii reader goes on past the end of the data (reading 0s), so
  // a header declaring more than the file holds would make it loop that long.
  uint64_t least = 0;
  for (const PLYElement& element : header.Elements)
  {
    uint64_t row = 0;
    for (const PLYProperty& property : element.Properties)
    {
      row += body.Units(property.IsList ? property.CountType : property.Type);
    }
    least += std::min<uint64_t>(element.Count, body.Size() + 1) * row;
    if (least > body.Size())
    {
      Fail(path, "element '" + element.Name + "'",
        "unexpected end of file (the header declares " + std::to_string(element.Count) +
          " of them)");
    }
  }
  TriangleMesh mesh;
  ArrayImporter importer(mesh, false);
  ReadWithOpenMesh(path, data, "PLY", importer);
  if (!importer.Error.empty())
  {
    Fail(path, "", importer.Error);
  }
  uint64_t faceCount = 0;
  for (const PLYElement& element : header.Elements)
  {
    if (element.Name == "vertex" && element.Count != mesh.NumberOfPoints())
    {
      Fail(path, "element 'vertex'",
        "OpenMesh's PLY reader returned " + std::to_string(mesh.NumberOfPoints()) + " of " +
          std::to_string(element.Count) + " vertices");
    }
    faceCount += element.Name == "face" ? element.Count : 0;
  }
  if (importer.Faces != faceCount)
  {
    Fail(path, "element 'face'",
      "OpenMesh's PLY reader returned " + std::to_string(importer.Faces) + " of " +
        std::to_string(faceCount) + " faces");
  }
  // The strips (by hand: OpenMesh skips them) and the length of the body.
  const int64_t end = DecodeStripsAndMeasureBody(path, header, body, importer.Corners, mesh);
  if (end >= 0 && static_cast<uint64_t>(end) > body.Size())
  {
    Fail(path, "", "unexpected end of file (the header declares more data)");
  }
  if (end >= 0 && header.Format == "ascii" && static_cast<uint64_t>(end) != body.Size())
  {
    Fail(path, "",
      "the body holds " + std::to_string(body.Size()) + " numbers, the header declares " +
        std::to_string(end) + " (a list longer than its count?)");
  }
  return mesh;
}

//------------------------------------------------------------------------------
void SaveOBJ(const TriangleMesh& mesh, const std::string& path)
{
  CheckTriangleIds(mesh, "SaveOBJ");
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file)
  {
    Fail(path, "", "cannot open file for writing");
  }
  bool ok = true;
  for (std::size_t i = 0; i < mesh.NumberOfPoints() && ok; ++i)
  {
    ok = std::fprintf(file, "v %.17g %.17g %.17g\n", mesh.Points[3 * i], mesh.Points[3 * i + 1],
           mesh.Points[3 * i + 2]) > 0;
  }
  for (std::size_t t = 0; t < mesh.NumberOfTriangles() && ok; ++t)
  {
    ok =
      std::fprintf(file, "f %lu %lu %lu\n", static_cast<unsigned long>(mesh.Triangles[3 * t]) + 1,
        static_cast<unsigned long>(mesh.Triangles[3 * t + 1]) + 1,
        static_cast<unsigned long>(mesh.Triangles[3 * t + 2]) + 1) > 0;
  }
  ok = std::fclose(file) == 0 && ok;
  if (!ok)
  {
    Fail(path, "", "write error");
  }
}

//------------------------------------------------------------------------------
void SavePLY(const TriangleMesh& mesh, const std::string& path, bool binary)
{
  CheckTriangleIds(mesh, "SavePLY");
  std::string out = "ply\nformat ";
  out += binary ? "binary_little_endian" : "ascii";
  out += " 1.0\ncomment written by timecritical::testing::SavePLY\nelement vertex " +
    std::to_string(mesh.NumberOfPoints()) +
    "\nproperty double x\nproperty double y\nproperty double z\nelement face " +
    std::to_string(mesh.NumberOfTriangles()) +
    "\nproperty list uchar int vertex_indices\nend_header\n";
  const bool swap = !HostIsLittleEndian();
  auto append = [&](const void* value, std::size_t size)
  {
    unsigned char bytes[8];
    std::memcpy(bytes, value, size);
    if (swap)
    {
      std::reverse(bytes, bytes + size);
    }
    out.append(reinterpret_cast<const char*>(bytes), size);
  };
  char buffer[128];
  for (std::size_t i = 0; i < mesh.NumberOfPoints(); ++i)
  {
    if (binary)
    {
      append(&mesh.Points[3 * i], 8);
      append(&mesh.Points[3 * i + 1], 8);
      append(&mesh.Points[3 * i + 2], 8);
    }
    else
    {
      std::snprintf(buffer, sizeof(buffer), "%.17g %.17g %.17g\n", mesh.Points[3 * i],
        mesh.Points[3 * i + 1], mesh.Points[3 * i + 2]);
      out += buffer;
    }
  }
  for (std::size_t t = 0; t < mesh.NumberOfTriangles(); ++t)
  {
    if (binary)
    {
      const uint8_t three = 3;
      out.push_back(static_cast<char>(three));
      for (int k = 0; k < 3; ++k)
      {
        const int32_t id = static_cast<int32_t>(mesh.Triangles[3 * t + k]);
        append(&id, 4);
      }
    }
    else
    {
      std::snprintf(buffer, sizeof(buffer), "3 %lu %lu %lu\n",
        static_cast<unsigned long>(mesh.Triangles[3 * t]),
        static_cast<unsigned long>(mesh.Triangles[3 * t + 1]),
        static_cast<unsigned long>(mesh.Triangles[3 * t + 2]));
      out += buffer;
    }
  }
  std::ofstream file(path, std::ios::binary);
  if (!file || !file.write(out.data(), static_cast<std::streamsize>(out.size())) || !file.flush())
  {
    Fail(path, "", "cannot write file");
  }
}

//------------------------------------------------------------------------------
TriangleMesh WeldPoints(const TriangleMesh& mesh, double tolerance, std::vector<uint32_t>* oldToNew)
{
  CheckTriangleIds(mesh, "WeldPoints");
  if (!(tolerance >= 0.0))
  {
    throw std::invalid_argument("WeldPoints: tolerance must be >= 0");
  }
  const std::size_t n = mesh.NumberOfPoints();
  std::vector<uint32_t> map(n);
  TriangleMesh result;
  result.Points.reserve(mesh.Points.size());

  auto addPoint = [&](std::size_t i)
  {
    const uint32_t id = static_cast<uint32_t>(result.NumberOfPoints());
    result.Points.insert(result.Points.end(),
      mesh.Points.begin() + static_cast<std::ptrdiff_t>(3 * i),
      mesh.Points.begin() + static_cast<std::ptrdiff_t>(3 * i + 3));
    return id;
  };

  if (tolerance == 0.0)
  {
    std::unordered_map<Key3, uint32_t, Key3Hash> unique;
    unique.reserve(n);
    for (std::size_t i = 0; i < n; ++i)
    {
      const Key3 key = { { DoubleBits(mesh.Points[3 * i]), DoubleBits(mesh.Points[3 * i + 1]),
        DoubleBits(mesh.Points[3 * i + 2]) } };
      const auto found = unique.find(key);
      if (found != unique.end())
      {
        map[i] = found->second;
      }
      else
      {
        map[i] = addPoint(i);
        unique.emplace(key, map[i]);
      }
    }
  }
  else
  {
    // Hash grid of cell size `tolerance`: every representative within the
    // tolerance lies in one of the 27 cells around the point's cell.
    const double limit = 4.0e18;
    auto cellOf = [&](double x)
    {
      const double c = std::floor(x / tolerance);
      return static_cast<int64_t>(std::max(-limit, std::min(limit, c)));
    };
    std::unordered_map<Key3, uint32_t, Key3Hash> heads; // cell -> last representative
    std::vector<uint32_t> next;                         // representative -> previous in cell
    std::vector<std::array<int64_t, 3>> cells;
    heads.reserve(n);
    const uint32_t none = std::numeric_limits<uint32_t>::max();
    const double tolerance2 = tolerance * tolerance;
    for (std::size_t i = 0; i < n; ++i)
    {
      const double* q = &mesh.Points[3 * i];
      if (!std::isfinite(q[0]) || !std::isfinite(q[1]) || !std::isfinite(q[2]))
      {
        map[i] = addPoint(i); // never merged
        next.push_back(none);
        continue;
      }
      const int64_t c[3] = { cellOf(q[0]), cellOf(q[1]), cellOf(q[2]) };
      uint32_t best = none;
      double bestDistance2 = tolerance2;
      for (int dx = -1; dx <= 1; ++dx)
      {
        for (int dy = -1; dy <= 1; ++dy)
        {
          for (int dz = -1; dz <= 1; ++dz)
          {
            const Key3 key = { { static_cast<uint64_t>(c[0] + dx), static_cast<uint64_t>(c[1] + dy),
              static_cast<uint64_t>(c[2] + dz) } };
            const auto found = heads.find(key);
            if (found == heads.end())
            {
              continue;
            }
            for (uint32_t r = found->second; r != none; r = next[r])
            {
              const double* s = &result.Points[3 * std::size_t(r)];
              const double d2 = (s[0] - q[0]) * (s[0] - q[0]) + (s[1] - q[1]) * (s[1] - q[1]) +
                (s[2] - q[2]) * (s[2] - q[2]);
              if (d2 < bestDistance2 || (d2 == bestDistance2 && (best == none || r < best)))
              {
                best = r;
                bestDistance2 = d2;
              }
            }
          }
        }
      }
      if (best != none)
      {
        map[i] = best;
        continue;
      }
      map[i] = addPoint(i);
      const Key3 key = { { static_cast<uint64_t>(c[0]), static_cast<uint64_t>(c[1]),
        static_cast<uint64_t>(c[2]) } };
      auto inserted = heads.emplace(key, map[i]);
      next.push_back(inserted.second ? none : inserted.first->second);
      inserted.first->second = map[i];
    }
  }

  result.Points.shrink_to_fit();
  result.Triangles.reserve(mesh.Triangles.size());
  for (std::size_t t = 0; t < mesh.NumberOfTriangles(); ++t)
  {
    const uint32_t a = map[mesh.Triangles[3 * t]];
    const uint32_t b = map[mesh.Triangles[3 * t + 1]];
    const uint32_t c = map[mesh.Triangles[3 * t + 2]];
    if (a != b && b != c && a != c)
    {
      result.Triangles.insert(result.Triangles.end(), { a, b, c });
    }
  }
  if (oldToNew)
  {
    *oldToNew = std::move(map);
  }
  return result;
}

//------------------------------------------------------------------------------
TriangleMesh RemoveUnusedPoints(const TriangleMesh& mesh)
{
  CheckTriangleIds(mesh, "RemoveUnusedPoints");
  const uint32_t none = std::numeric_limits<uint32_t>::max();
  std::vector<uint32_t> map(mesh.NumberOfPoints(), none);
  for (const uint32_t id : mesh.Triangles)
  {
    map[id] = 0;
  }
  TriangleMesh result;
  for (std::size_t i = 0; i < map.size(); ++i)
  {
    if (map[i] != none)
    {
      map[i] = static_cast<uint32_t>(result.NumberOfPoints());
      result.Points.insert(result.Points.end(),
        mesh.Points.begin() + static_cast<std::ptrdiff_t>(3 * i),
        mesh.Points.begin() + static_cast<std::ptrdiff_t>(3 * i + 3));
    }
  }
  result.Triangles.reserve(mesh.Triangles.size());
  for (const uint32_t id : mesh.Triangles)
  {
    result.Triangles.push_back(map[id]);
  }
  return result;
}

//------------------------------------------------------------------------------
MeshTopology ComputeTopology(const TriangleMesh& mesh)
{
  CheckTriangleIds(mesh, "ComputeTopology");
  MeshTopology topology;
  const std::size_t n = mesh.NumberOfPoints();
  const std::size_t triangleCount = mesh.NumberOfTriangles();
  topology.NumberOfPoints = n;
  topology.NumberOfTriangles = triangleCount;

  std::vector<char> used(n, 0);
  UnionFind components(n);
  struct DirectedEdge
  {
    uint64_t Key; // (min << 32) | max
    bool Forward; // min -> max in the triangle
    bool operator<(const DirectedEdge& other) const { return this->Key < other.Key; }
  };
  std::vector<DirectedEdge> edges;
  edges.reserve(3 * triangleCount);
  std::vector<uint32_t> incidentCount(n + 1, 0);
  for (std::size_t t = 0; t < triangleCount; ++t)
  {
    const uint32_t* v = &mesh.Triangles[3 * t];
    for (int k = 0; k < 3; ++k)
    {
      used[v[k]] = 1;
    }
    components.Unite(v[0], v[1]);
    components.Unite(v[0], v[2]);
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2])
    {
      ++topology.NumberOfDegenerateTriangles;
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      const uint32_t a = v[k];
      const uint32_t b = v[(k + 1) % 3];
      edges.push_back({ (uint64_t(std::min(a, b)) << 32) | std::max(a, b), a < b });
      ++incidentCount[a + 1];
    }
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    if (used[i])
    {
      ++topology.NumberOfUsedPoints;
      if (components.Find(i) == i)
      {
        ++topology.NumberOfComponents;
      }
    }
  }
  topology.NumberOfUnusedPoints = n - topology.NumberOfUsedPoints;

  // Edges: group equal keys after sorting.
  std::sort(edges.begin(), edges.end());
  UnionFind loops(n);
  std::vector<char> onBoundary(n, 0);
  for (std::size_t i = 0; i < edges.size();)
  {
    std::size_t j = i;
    std::size_t forward = 0;
    while (j < edges.size() && edges[j].Key == edges[i].Key)
    {
      forward += edges[j].Forward ? 1 : 0;
      ++j;
    }
    const std::size_t count = j - i;
    ++topology.NumberOfEdges;
    if (count == 1)
    {
      ++topology.NumberOfBoundaryEdges;
      const std::size_t a = static_cast<std::size_t>(edges[i].Key >> 32);
      const std::size_t b = static_cast<std::size_t>(edges[i].Key & 0xffffffffULL);
      onBoundary[a] = onBoundary[b] = 1;
      loops.Unite(a, b);
    }
    else if (count > 2)
    {
      ++topology.NumberOfNonManifoldEdges;
    }
    else if (forward != 1)
    {
      ++topology.NumberOfInconsistentEdges;
    }
    i = j;
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    if (onBoundary[i] && loops.Find(i) == i)
    {
      ++topology.NumberOfBoundaryLoops;
    }
  }
  topology.EulerCharacteristic = static_cast<long long>(topology.NumberOfUsedPoints) -
    static_cast<long long>(topology.NumberOfEdges) +
    static_cast<long long>(triangleCount - topology.NumberOfDegenerateTriangles);

  // Pinch vertices: the link (opposite edges of the incident triangles) of a
  // manifold vertex is one path or cycle; count vertices whose link is not
  // connected.
  for (std::size_t i = 0; i < n; ++i)
  {
    incidentCount[i + 1] += incidentCount[i];
  }
  std::vector<uint32_t> incident(incidentCount[n]);
  {
    std::vector<uint32_t> fill(incidentCount.begin(), incidentCount.end() - 1);
    for (std::size_t t = 0; t < triangleCount; ++t)
    {
      const uint32_t* v = &mesh.Triangles[3 * t];
      if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2])
      {
        continue;
      }
      for (int k = 0; k < 3; ++k)
      {
        incident[fill[v[k]]++] = static_cast<uint32_t>(t);
      }
    }
  }
  std::vector<uint32_t> linkVertices;
  std::vector<uint32_t> linkParent;
  auto localFind = [&](uint32_t x)
  {
    while (linkParent[x] != x)
    {
      linkParent[x] = linkParent[linkParent[x]];
      x = linkParent[x];
    }
    return x;
  };
  for (std::size_t i = 0; i < n; ++i)
  {
    const uint32_t begin = incidentCount[i];
    const uint32_t end = incidentCount[i + 1];
    if (end - begin < 2)
    {
      continue;
    }
    linkVertices.clear();
    for (uint32_t k = begin; k < end; ++k)
    {
      const uint32_t* v = &mesh.Triangles[3 * std::size_t(incident[k])];
      for (int c = 0; c < 3; ++c)
      {
        if (v[c] != i)
        {
          linkVertices.push_back(v[c]);
        }
      }
    }
    std::sort(linkVertices.begin(), linkVertices.end());
    linkVertices.erase(std::unique(linkVertices.begin(), linkVertices.end()), linkVertices.end());
    linkParent.resize(linkVertices.size());
    std::iota(linkParent.begin(), linkParent.end(), 0u);
    std::size_t groups = linkVertices.size();
    for (uint32_t k = begin; k < end; ++k)
    {
      const uint32_t* v = &mesh.Triangles[3 * std::size_t(incident[k])];
      uint32_t ends[2];
      int e = 0;
      for (int c = 0; c < 3; ++c)
      {
        if (v[c] != i)
        {
          ends[e++] =
            static_cast<uint32_t>(std::lower_bound(linkVertices.begin(), linkVertices.end(), v[c]) -
              linkVertices.begin());
        }
      }
      const uint32_t ra = localFind(ends[0]);
      const uint32_t rb = localFind(ends[1]);
      if (ra != rb)
      {
        linkParent[std::max(ra, rb)] = std::min(ra, rb);
        --groups;
      }
    }
    if (groups > 1)
    {
      ++topology.NumberOfNonManifoldVertices;
    }
  }
  return topology;
}

//------------------------------------------------------------------------------
double SignedVolume(const TriangleMesh& mesh)
{
  CheckTriangleIds(mesh, "SignedVolume");
  double volume = 0.0;
  for (std::size_t t = 0; t < mesh.NumberOfTriangles(); ++t)
  {
    const auto a = PointAt(mesh, mesh.Triangles[3 * t]);
    const auto b = PointAt(mesh, mesh.Triangles[3 * t + 1]);
    const auto c = PointAt(mesh, mesh.Triangles[3 * t + 2]);
    volume += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
      a[2] * (b[0] * c[1] - b[1] * c[0]);
  }
  return volume / 6.0;
}

//------------------------------------------------------------------------------
double SurfaceArea(const TriangleMesh& mesh)
{
  CheckTriangleIds(mesh, "SurfaceArea");
  double area = 0.0;
  for (std::size_t t = 0; t < mesh.NumberOfTriangles(); ++t)
  {
    const auto a = PointAt(mesh, mesh.Triangles[3 * t]);
    const auto b = PointAt(mesh, mesh.Triangles[3 * t + 1]);
    const auto c = PointAt(mesh, mesh.Triangles[3 * t + 2]);
    const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    const double v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
    const double cross[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
      u[0] * v[1] - u[1] * v[0] };
    area += 0.5 * std::sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]);
  }
  return area;
}

//------------------------------------------------------------------------------
TriangleMesh MakeGrid(std::size_t nx, std::size_t ny)
{
  Require(nx >= 1 && ny >= 1, "MakeGrid: nx and ny must be >= 1");
  Require((nx + 1) * (ny + 1) <= MaxPointId, "MakeGrid: too many points");
  TriangleMesh mesh;
  mesh.Points.reserve(3 * (nx + 1) * (ny + 1));
  for (std::size_t j = 0; j <= ny; ++j)
  {
    for (std::size_t i = 0; i <= nx; ++i)
    {
      mesh.Points.insert(mesh.Points.end(),
        { static_cast<double>(i) / static_cast<double>(nx),
          static_cast<double>(j) / static_cast<double>(ny), 0.0 });
    }
  }
  mesh.Triangles.reserve(6 * nx * ny);
  for (std::size_t j = 0; j < ny; ++j)
  {
    for (std::size_t i = 0; i < nx; ++i)
    {
      const uint32_t a = static_cast<uint32_t>(j * (nx + 1) + i);
      const uint32_t b = a + 1;
      const uint32_t d = static_cast<uint32_t>(a + nx + 1);
      const uint32_t c = d + 1;
      mesh.Triangles.insert(mesh.Triangles.end(), { a, b, c, a, c, d });
    }
  }
  return mesh;
}

//------------------------------------------------------------------------------
TriangleMesh MakeSphere(std::size_t subdivisions)
{
  Require(subdivisions <= 12, "MakeSphere: at most 12 subdivisions");
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  TriangleMesh mesh;
  mesh.Points = { -1, g, 0, 1, g, 0, -1, -g, 0, 1, -g, 0, 0, -1, g, 0, 1, g, 0, -1, -g, 0, 1, -g, g,
    0, -1, g, 0, 1, -g, 0, -1, -g, 0, 1 };
  mesh.Triangles = { 0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4, 11, 10, 2,
    10, 7, 6, 7, 1, 8, 3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8,
    6, 7, 9, 8, 1 };
  auto normalize = [](double* p)
  {
    const double length = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    p[0] /= length;
    p[1] /= length;
    p[2] /= length;
  };
  for (std::size_t i = 0; i < 12; ++i)
  {
    normalize(&mesh.Points[3 * i]);
  }
  for (std::size_t level = 0; level < subdivisions; ++level)
  {
    std::unordered_map<uint64_t, uint32_t> midpoints;
    midpoints.reserve(mesh.Triangles.size());
    auto midpoint = [&](uint32_t a, uint32_t b)
    {
      const uint64_t key = (uint64_t(std::min(a, b)) << 32) | std::max(a, b);
      const auto found = midpoints.find(key);
      if (found != midpoints.end())
      {
        return found->second;
      }
      const uint32_t id = static_cast<uint32_t>(mesh.NumberOfPoints());
      double p[3];
      for (int k = 0; k < 3; ++k)
      {
        p[k] = 0.5 * (mesh.Points[3 * std::size_t(a) + k] + mesh.Points[3 * std::size_t(b) + k]);
      }
      normalize(p);
      mesh.Points.insert(mesh.Points.end(), p, p + 3);
      midpoints.emplace(key, id);
      return id;
    };
    std::vector<uint32_t> refined;
    refined.reserve(4 * mesh.Triangles.size());
    for (std::size_t t = 0; t < mesh.NumberOfTriangles(); ++t)
    {
      const uint32_t a = mesh.Triangles[3 * t];
      const uint32_t b = mesh.Triangles[3 * t + 1];
      const uint32_t c = mesh.Triangles[3 * t + 2];
      const uint32_t ab = midpoint(a, b);
      const uint32_t bc = midpoint(b, c);
      const uint32_t ca = midpoint(c, a);
      refined.insert(refined.end(), { a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca });
    }
    mesh.Triangles = std::move(refined);
  }
  return mesh;
}

//------------------------------------------------------------------------------
TriangleMesh MakeUVSphere(std::size_t latitudes, std::size_t longitudes)
{
  Require(latitudes >= 2 && longitudes >= 3, "MakeUVSphere: latitudes >= 2, longitudes >= 3");
  Require((latitudes - 1) * longitudes + 2 <= MaxPointId, "MakeUVSphere: too many points");
  const double pi = 3.14159265358979323846;
  TriangleMesh mesh;
  mesh.Points = { 0.0, 0.0, 1.0 }; // north pole (assignment: GCC 12 -O3 misreads insert into an empty vector)
  for (std::size_t k = 1; k < latitudes; ++k)
  {
    const double theta = pi * static_cast<double>(k) / static_cast<double>(latitudes);
    for (std::size_t j = 0; j < longitudes; ++j)
    {
      const double phi = 2.0 * pi * static_cast<double>(j) / static_cast<double>(longitudes);
      mesh.Points.insert(mesh.Points.end(),
        { std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta) });
    }
  }
  mesh.Points.insert(mesh.Points.end(), { 0.0, 0.0, -1.0 });
  const uint32_t north = 0;
  const uint32_t south = static_cast<uint32_t>(mesh.NumberOfPoints() - 1);
  auto ring = [&](std::size_t k, std::size_t j)
  { return static_cast<uint32_t>(1 + (k - 1) * longitudes + j % longitudes); };
  for (std::size_t j = 0; j < longitudes; ++j)
  {
    mesh.Triangles.insert(mesh.Triangles.end(), { north, ring(1, j), ring(1, j + 1) });
  }
  for (std::size_t k = 1; k + 1 < latitudes; ++k)
  {
    for (std::size_t j = 0; j < longitudes; ++j)
    {
      const uint32_t a = ring(k, j);
      const uint32_t b = ring(k, j + 1);
      const uint32_t c = ring(k + 1, j + 1);
      const uint32_t d = ring(k + 1, j);
      mesh.Triangles.insert(mesh.Triangles.end(), { a, d, c, a, c, b });
    }
  }
  for (std::size_t j = 0; j < longitudes; ++j)
  {
    mesh.Triangles.insert(
      mesh.Triangles.end(), { ring(latitudes - 1, j), south, ring(latitudes - 1, j + 1) });
  }
  return mesh;
}

//------------------------------------------------------------------------------
TriangleMesh MakeFan(uint32_t n, bool crumpled)
{
  Require(n >= 3, "MakeFan: n must be >= 3");
  constexpr double TwoPi = 6.283185307179586;
  TriangleMesh mesh;
  mesh.Points = { 0, 0, 0 };
  uint64_t state = 12345;
  auto random = [&state]() {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return double(state >> 11) / double(uint64_t(1) << 53);
  };
  for (uint32_t i = 0; i < n; ++i)
  {
    const double z = crumpled ? 2 * random() - 1 : 0.0;
    const double a = crumpled ? TwoPi * random() : TwoPi * i / n;
    const double r = std::sqrt(1 - z * z);
    mesh.Points.insert(mesh.Points.end(), { r * std::cos(a), r * std::sin(a), z });
    mesh.Triangles.insert(mesh.Triangles.end(), { 0, 1 + i, 1 + (i + 1) % n });
  }
  return mesh;
}

TriangleMesh MakeTorus(std::size_t n, std::size_t m, uint32_t noiseSeed, double noiseAmplitude)
{
  Require(n >= 3 && m >= 3, "MakeTorus: n and m must be >= 3");
  Require(n * m <= MaxPointId, "MakeTorus: too many points");
  const double pi = 3.14159265358979323846;
  const double majorRadius = 1.0;
  const double minorRadius = 0.35;
  TriangleMesh mesh;
  mesh.Points.reserve(3 * n * m);
  for (std::size_t i = 0; i < n; ++i)
  {
    const double u = 2.0 * pi * static_cast<double>(i) / static_cast<double>(n);
    for (std::size_t j = 0; j < m; ++j)
    {
      const double v = 2.0 * pi * static_cast<double>(j) / static_cast<double>(m);
      const double normal[3] = { std::cos(v) * std::cos(u), std::cos(v) * std::sin(u),
        std::sin(v) };
      double r = minorRadius;
      if (noiseSeed != 0)
      {
        r += noiseAmplitude * minorRadius * SignedNoise(noiseSeed, i * m + j);
      }
      mesh.Points.insert(mesh.Points.end(),
        { majorRadius * std::cos(u) + r * normal[0], majorRadius * std::sin(u) + r * normal[1],
          r * normal[2] });
    }
  }
  mesh.Triangles.reserve(6 * n * m);
  for (std::size_t i = 0; i < n; ++i)
  {
    for (std::size_t j = 0; j < m; ++j)
    {
      const uint32_t a = static_cast<uint32_t>(i * m + j);
      const uint32_t b = static_cast<uint32_t>(((i + 1) % n) * m + j);
      const uint32_t c = static_cast<uint32_t>(((i + 1) % n) * m + (j + 1) % m);
      const uint32_t d = static_cast<uint32_t>(i * m + (j + 1) % m);
      mesh.Triangles.insert(mesh.Triangles.end(), { a, b, c, a, c, d });
    }
  }
  return mesh;
}

//------------------------------------------------------------------------------
TriangleMesh MakeCube(std::size_t n)
{
  Require(n >= 1, "MakeCube: n must be >= 1");
  Require(n < (std::size_t(1) << 20) && 6 * n * n + 2 <= MaxPointId, "MakeCube: n too large");
  TriangleMesh mesh;
  mesh.Points.reserve(3 * (6 * n * n + 2));
  mesh.Triangles.reserve(36 * n * n);
  // Lattice points (i, j, k) in [0, n]^3, shared between faces.
  std::unordered_map<uint64_t, uint32_t> ids;
  ids.reserve(6 * n * n + 2);
  auto pointId = [&](const std::size_t(&lattice)[3])
  {
    const uint64_t key = (uint64_t(lattice[0]) << 42) | (uint64_t(lattice[1]) << 21) | lattice[2];
    const auto found = ids.find(key);
    if (found != ids.end())
    {
      return found->second;
    }
    const uint32_t id = static_cast<uint32_t>(mesh.NumberOfPoints());
    for (int axis = 0; axis < 3; ++axis)
    {
      mesh.Points.push_back(static_cast<double>(lattice[axis]) / static_cast<double>(n) - 0.5);
    }
    ids.emplace(key, id);
    return id;
  };
  for (int axis = 0; axis < 3; ++axis)
  {
    const int uAxis = (axis + 1) % 3; // e_u x e_v = e_axis
    const int vAxis = (axis + 2) % 3;
    for (int side = 0; side < 2; ++side)
    {
      for (std::size_t v = 0; v < n; ++v)
      {
        for (std::size_t u = 0; u < n; ++u)
        {
          uint32_t corner[4];
          const std::size_t du[4] = { 0, 1, 1, 0 };
          const std::size_t dv[4] = { 0, 0, 1, 1 };
          for (int q = 0; q < 4; ++q)
          {
            std::size_t lattice[3];
            lattice[axis] = side ? n : 0;
            lattice[uAxis] = u + du[q];
            lattice[vAxis] = v + dv[q];
            corner[q] = pointId(lattice);
          }
          if (side)
          {
            mesh.Triangles.insert(mesh.Triangles.end(),
              { corner[0], corner[1], corner[2], corner[0], corner[2], corner[3] });
          }
          else
          {
            mesh.Triangles.insert(mesh.Triangles.end(),
              { corner[0], corner[2], corner[1], corner[0], corner[3], corner[2] });
          }
        }
      }
    }
  }
  return mesh;
}

//------------------------------------------------------------------------------
TriangleMesh MakeNoisyCube(std::size_t n, double noise)
{
  TriangleMesh mesh = MakeCube(n);
  uint32_t state = 12345;
  for (std::size_t i = 0; i < mesh.NumberOfPoints(); ++i)
  {
    double* p = &mesh.Points[3 * i];
    int faces = 0, axis = 0;
    for (int k = 0; k < 3; ++k)
    {
      if (std::abs(p[k]) == 0.5)
      {
        ++faces;
        axis = k;
      }
    }
    state = state * 1664525u + 1013904223u;
    if (faces == 1)
    {
      p[axis] += (p[axis] > 0 ? 1.0 : -1.0) * noise * ((state >> 8) / double(1 << 24) - 0.5);
    }
  }
  return mesh;
}
}
}
