// SPDX-License-Identifier: BSD-3-Clause
#include "TestMeshIO.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numeric>
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
  std::string message = "TestMeshIO: " + path;
  if (!where.empty())
  {
    message += ", " + where;
  }
  message += ": " + what;
  throw std::runtime_error(message);
}

std::string LineWhere(std::size_t line)
{
  return "line " + std::to_string(line);
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
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0)
  {
    Fail(path, "", "cannot determine the file size");
  }
  in.seekg(0, std::ios::beg);
  std::string data(static_cast<std::size_t>(size), '\0');
  if (size > 0 && !in.read(&data[0], size))
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

inline bool IsBlank(char c)
{
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

// from_chars rejects a leading '+'; OBJ/PLY writers occasionally emit one.
bool ParseDouble(const char* first, const char* last, double& value)
{
  if (first < last && *first == '+')
  {
    ++first;
  }
  const std::from_chars_result result = std::from_chars(first, last, value);
  return result.ec == std::errc() && result.ptr == last;
}

bool ParseInt(const char* first, const char* last, int64_t& value)
{
  if (first < last && *first == '+')
  {
    ++first;
  }
  const std::from_chars_result result = std::from_chars(first, last, value);
  return result.ec == std::errc() && result.ptr == last;
}

void FanTriangulate(const std::vector<uint32_t>& polygon, std::vector<uint32_t>& triangles)
{
  for (std::size_t k = 1; k + 1 < polygon.size(); ++k)
  {
    triangles.push_back(polygon[0]);
    triangles.push_back(polygon[k]);
    triangles.push_back(polygon[k + 1]);
  }
}

//------------------------------------------------------------------------------
// OBJ

void ParseOBJLine(const std::string& path, std::size_t lineNumber, const char* p, const char* end,
  TriangleMesh& mesh, std::vector<uint32_t>& polygon, uint64_t& maxPositive,
  std::size_t& maxPositiveLine)
{
  auto skipBlanks = [&]()
  {
    while (p < end && IsBlank(*p))
    {
      ++p;
    }
  };
  auto nextToken = [&](const char*& first, const char*& last)
  {
    skipBlanks();
    first = p;
    while (p < end && !IsBlank(*p))
    {
      ++p;
    }
    last = p;
    return first < last;
  };

  const char* keyFirst;
  const char* keyLast;
  if (!nextToken(keyFirst, keyLast))
  {
    return; // empty line
  }
  const std::size_t keyLength = static_cast<std::size_t>(keyLast - keyFirst);
  if (keyLength != 1 || (*keyFirst != 'v' && *keyFirst != 'f'))
  {
    return; // vt, vn, vp, g, o, s, usemtl, mtllib, l, p, ...
  }

  const char* first;
  const char* last;
  if (*keyFirst == 'v')
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      if (!nextToken(first, last))
      {
        Fail(path, LineWhere(lineNumber), "vertex with fewer than 3 coordinates");
      }
      double value;
      if (!ParseDouble(first, last, value))
      {
        Fail(
          path, LineWhere(lineNumber), "bad vertex coordinate '" + std::string(first, last) + "'");
      }
      mesh.Points.push_back(value);
    }
    if (mesh.Points.size() / 3 > MaxPointId)
    {
      Fail(path, LineWhere(lineNumber), "more than 2^32-1 vertices");
    }
    return; // w and vertex colors are ignored
  }

  // Face: corners v, v/vt, v//vn, v/vt/vn; only v matters.
  polygon.clear();
  const int64_t vertexCount = static_cast<int64_t>(mesh.Points.size() / 3);
  while (nextToken(first, last))
  {
    const char* slash = static_cast<const char*>(std::memchr(first, '/', last - first));
    const char* indexLast = slash ? slash : last;
    int64_t index;
    if (!ParseInt(first, indexLast, index))
    {
      Fail(path, LineWhere(lineNumber), "bad face corner '" + std::string(first, last) + "'");
    }
    if (index == 0)
    {
      Fail(path, LineWhere(lineNumber), "vertex index 0 (OBJ indices start at 1)");
    }
    uint64_t id;
    if (index < 0)
    {
      if (-index > vertexCount)
      {
        Fail(path, LineWhere(lineNumber),
          "relative vertex index " + std::to_string(index) + " before the first vertex (" +
            std::to_string(vertexCount) + " vertices read so far)");
      }
      id = static_cast<uint64_t>(vertexCount + index);
    }
    else
    {
      id = static_cast<uint64_t>(index - 1);
      if (id >= MaxPointId)
      {
        Fail(path, LineWhere(lineNumber), "vertex index " + std::to_string(index) + " too large");
      }
      // Positive indices are checked once all vertices are known.
      if (id >= maxPositive)
      {
        if (id > maxPositive || maxPositiveLine == 0)
        {
          maxPositiveLine = lineNumber;
        }
        maxPositive = id;
      }
    }
    polygon.push_back(static_cast<uint32_t>(id));
  }
  if (polygon.size() < 3)
  {
    Fail(path, LineWhere(lineNumber),
      "face with " + std::to_string(polygon.size()) + " vertices (at least 3 needed)");
  }
  FanTriangulate(polygon, mesh.Triangles);
}

//------------------------------------------------------------------------------
// PLY

enum class ScalarType
{
  Int8,
  UInt8,
  Int16,
  UInt16,
  Int32,
  UInt32,
  Float32,
  Float64
};

bool ParseScalarType(const std::string& name, ScalarType& type)
{
  static const std::pair<const char*, ScalarType> names[] = { { "char", ScalarType::Int8 },
    { "int8", ScalarType::Int8 }, { "uchar", ScalarType::UInt8 }, { "uint8", ScalarType::UInt8 },
    { "short", ScalarType::Int16 }, { "int16", ScalarType::Int16 },
    { "ushort", ScalarType::UInt16 }, { "uint16", ScalarType::UInt16 },
    { "int", ScalarType::Int32 }, { "int32", ScalarType::Int32 }, { "uint", ScalarType::UInt32 },
    { "uint32", ScalarType::UInt32 }, { "float", ScalarType::Float32 },
    { "float32", ScalarType::Float32 }, { "double", ScalarType::Float64 },
    { "float64", ScalarType::Float64 } };
  for (const auto& entry : names)
  {
    if (name == entry.first)
    {
      type = entry.second;
      return true;
    }
  }
  return false;
}

std::size_t ScalarSize(ScalarType type)
{
  switch (type)
  {
    case ScalarType::Int8:
    case ScalarType::UInt8:
      return 1;
    case ScalarType::Int16:
    case ScalarType::UInt16:
      return 2;
    case ScalarType::Int32:
    case ScalarType::UInt32:
    case ScalarType::Float32:
      return 4;
    case ScalarType::Float64:
      return 8;
  }
  return 0;
}

bool IsIntegral(ScalarType type)
{
  return type != ScalarType::Float32 && type != ScalarType::Float64;
}

struct PLYProperty
{
  std::string Name;
  ScalarType Type = ScalarType::Float32; // of the items for a list
  bool IsList = false;
  ScalarType CountType = ScalarType::UInt8;
};

struct PLYElement
{
  std::string Name;
  uint64_t Count = 0;
  std::vector<PLYProperty> Properties;
  std::size_t HeaderLine = 0;
};

enum class PLYFormat
{
  Ascii,
  BinaryLittleEndian,
  BinaryBigEndian
};

struct PLYHeader
{
  PLYFormat Format = PLYFormat::Ascii;
  std::vector<PLYElement> Elements;
  std::size_t BodyOffset = 0; // first byte after the end_header line
  std::size_t BodyLine = 0;   // line number of the first body line (ascii)
};

PLYHeader ParsePLYHeader(const std::string& path, const std::string& data)
{
  PLYHeader header;
  std::size_t offset = 0;
  std::size_t lineNumber = 0;
  bool haveFormat = false;
  bool done = false;
  while (!done)
  {
    if (offset >= data.size())
    {
      Fail(path, LineWhere(lineNumber), "header without end_header");
    }
    ++lineNumber;
    std::size_t lineEnd = data.find('\n', offset);
    const bool lastLine = lineEnd == std::string::npos;
    if (lastLine)
    {
      lineEnd = data.size();
    }
    const std::string line = data.substr(offset, lineEnd - offset);
    offset = lastLine ? data.size() : lineEnd + 1;

    std::vector<std::string> words;
    {
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
    }
    const std::string where = "header line " + std::to_string(lineNumber);
    if (lineNumber == 1)
    {
      if (words.size() != 1 || words[0] != "ply")
      {
        Fail(path, where, "not a PLY file (first line is not 'ply')");
      }
      continue;
    }
    if (words.empty())
    {
      continue;
    }
    const std::string& keyword = words[0];
    if (keyword == "comment" || keyword == "obj_info")
    {
      continue;
    }
    if (keyword == "format")
    {
      if (words.size() != 3)
      {
        Fail(path, where, "malformed format line");
      }
      if (words[1] == "ascii")
      {
        header.Format = PLYFormat::Ascii;
      }
      else if (words[1] == "binary_little_endian")
      {
        header.Format = PLYFormat::BinaryLittleEndian;
      }
      else if (words[1] == "binary_big_endian")
      {
        header.Format = PLYFormat::BinaryBigEndian;
      }
      else
      {
        Fail(path, where, "unknown format '" + words[1] + "'");
      }
      if (words[2] != "1.0")
      {
        Fail(path, where, "unsupported PLY version '" + words[2] + "'");
      }
      haveFormat = true;
    }
    else if (keyword == "element")
    {
      int64_t count = -1;
      if (words.size() != 3 ||
        !ParseInt(words[2].data(), words[2].data() + words[2].size(), count) || count < 0)
      {
        Fail(path, where, "malformed element line");
      }
      PLYElement element;
      element.Name = words[1];
      element.Count = static_cast<uint64_t>(count);
      element.HeaderLine = lineNumber;
      header.Elements.push_back(element);
    }
    else if (keyword == "property")
    {
      if (header.Elements.empty())
      {
        Fail(path, where, "property before any element");
      }
      PLYProperty property;
      if (words.size() == 5 && words[1] == "list")
      {
        property.IsList = true;
        if (!ParseScalarType(words[2], property.CountType) ||
          !ParseScalarType(words[3], property.Type))
        {
          Fail(path, where, "unknown list type in '" + line + "'");
        }
        if (!IsIntegral(property.CountType))
        {
          Fail(path, where, "list count type must be integral");
        }
        property.Name = words[4];
      }
      else if (words.size() == 3)
      {
        if (!ParseScalarType(words[1], property.Type))
        {
          Fail(path, where, "unknown property type '" + words[1] + "'");
        }
        property.Name = words[2];
      }
      else
      {
        Fail(path, where, "malformed property line");
      }
      header.Elements.back().Properties.push_back(property);
    }
    else if (keyword == "end_header")
    {
      done = true;
    }
    else
    {
      Fail(path, where, "unknown header keyword '" + keyword + "'");
    }
  }
  if (!haveFormat)
  {
    Fail(path, "header", "no format line");
  }
  header.BodyOffset = offset;
  header.BodyLine = lineNumber + 1;
  return header;
}

bool HostIsLittleEndian()
{
  const uint16_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

/// Position in the body, for messages.
struct PLYContext
{
  const std::string* Path = nullptr;
  const PLYElement* Element = nullptr;
  uint64_t Index = 0;

  std::string Where(const std::string& extra = std::string()) const
  {
    std::string where = "element '" + this->Element->Name + "' #" + std::to_string(this->Index);
    if (!extra.empty())
    {
      where += " (" + extra + ")";
    }
    return where;
  }
};

class PLYBinaryReader
{
public:
  PLYBinaryReader(const std::string& data, std::size_t offset, bool bigEndian, PLYContext& context)
    : Cursor(reinterpret_cast<const unsigned char*>(data.data()) + offset)
    , End(reinterpret_cast<const unsigned char*>(data.data()) + data.size())
    , Swap(bigEndian == HostIsLittleEndian())
    , Context(context)
  {
  }

  double ReadDouble(ScalarType type)
  {
    switch (type)
    {
      case ScalarType::Int8:
        return static_cast<double>(this->Read<int8_t>());
      case ScalarType::UInt8:
        return static_cast<double>(this->Read<uint8_t>());
      case ScalarType::Int16:
        return static_cast<double>(this->Read<int16_t>());
      case ScalarType::UInt16:
        return static_cast<double>(this->Read<uint16_t>());
      case ScalarType::Int32:
        return static_cast<double>(this->Read<int32_t>());
      case ScalarType::UInt32:
        return static_cast<double>(this->Read<uint32_t>());
      case ScalarType::Float32:
        return static_cast<double>(this->Read<float>());
      case ScalarType::Float64:
        return this->Read<double>();
    }
    return 0.0;
  }

  int64_t ReadInt(ScalarType type)
  {
    switch (type)
    {
      case ScalarType::Int8:
        return this->Read<int8_t>();
      case ScalarType::UInt8:
        return this->Read<uint8_t>();
      case ScalarType::Int16:
        return this->Read<int16_t>();
      case ScalarType::UInt16:
        return this->Read<uint16_t>();
      case ScalarType::Int32:
        return this->Read<int32_t>();
      case ScalarType::UInt32:
        return this->Read<uint32_t>();
      case ScalarType::Float32:
      case ScalarType::Float64:
        break;
    }
    Fail(*this->Context.Path, this->Context.Where(), "integer expected");
  }

  void Skip(ScalarType type, uint64_t count = 1)
  {
    const uint64_t bytes = ScalarSize(type) * count;
    if (count > static_cast<uint64_t>(this->End - this->Cursor) ||
      bytes > static_cast<uint64_t>(this->End - this->Cursor))
    {
      this->Truncated();
    }
    this->Cursor += bytes;
  }

private:
  template <class T>
  T Read()
  {
    if (static_cast<std::size_t>(this->End - this->Cursor) < sizeof(T))
    {
      this->Truncated();
    }
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, this->Cursor, sizeof(T));
    if (this->Swap)
    {
      std::reverse(bytes, bytes + sizeof(T));
    }
    this->Cursor += sizeof(T);
    T value;
    std::memcpy(&value, bytes, sizeof(T));
    return value;
  }

  [[noreturn]] void Truncated() const
  {
    Fail(*this->Context.Path, this->Context.Where(),
      "unexpected end of file (truncated binary data; header declares " +
        std::to_string(this->Context.Element->Count) + " '" + this->Context.Element->Name +
        "' elements)");
  }

  const unsigned char* Cursor;
  const unsigned char* End;
  bool Swap;
  PLYContext& Context;
};

class PLYAsciiReader
{
public:
  PLYAsciiReader(const std::string& data, std::size_t offset, std::size_t line, PLYContext& context)
    : Cursor(data.data() + offset)
    , End(data.data() + data.size())
    , Line(line)
    , Context(context)
  {
  }

  double ReadDouble(ScalarType)
  {
    this->NextToken();
    double value;
    if (!ParseDouble(this->First, this->Last, value))
    {
      this->Bad("number");
    }
    return value;
  }

  int64_t ReadInt(ScalarType type)
  {
    this->NextToken();
    int64_t value;
    if (!IsIntegral(type) || !ParseInt(this->First, this->Last, value))
    {
      this->Bad("integer");
    }
    return value;
  }

  void Skip(ScalarType, uint64_t count = 1)
  {
    for (uint64_t i = 0; i < count; ++i)
    {
      this->NextToken();
    }
  }

private:
  void NextToken()
  {
    while (this->Cursor < this->End && (IsBlank(*this->Cursor) || *this->Cursor == '\n'))
    {
      if (*this->Cursor == '\n')
      {
        ++this->Line;
      }
      ++this->Cursor;
    }
    if (this->Cursor == this->End)
    {
      Fail(*this->Context.Path, this->Context.Where(LineWhere(this->Line)),
        "unexpected end of file (header declares " + std::to_string(this->Context.Element->Count) +
          " '" + this->Context.Element->Name + "' elements)");
    }
    this->First = this->Cursor;
    while (this->Cursor < this->End && !IsBlank(*this->Cursor) && *this->Cursor != '\n')
    {
      ++this->Cursor;
    }
    this->Last = this->Cursor;
  }

  [[noreturn]] void Bad(const char* expected) const
  {
    Fail(*this->Context.Path, this->Context.Where(LineWhere(this->Line)),
      std::string(expected) + " expected, got '" + std::string(this->First, this->Last) + "'");
  }

  const char* Cursor;
  const char* End;
  const char* First = nullptr;
  const char* Last = nullptr;
  std::size_t Line;
  PLYContext& Context;
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
      fail("strip vertex index " + std::to_string(id) + " out of range [0, " +
        std::to_string(vertexCount) + ")");
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

template <class Reader>
void ReadPLYBody(const std::string& path, const PLYHeader& header, Reader& reader,
  PLYContext& context, TriangleMesh& mesh)
{
  uint64_t vertexCount = 0;
  bool haveVertices = false;
  for (const PLYElement& element : header.Elements)
  {
    if (element.Name == "vertex")
    {
      vertexCount = element.Count;
      haveVertices = true;
    }
  }
  if (!haveVertices)
  {
    Fail(path, "header", "no 'vertex' element");
  }
  if (vertexCount > MaxPointId)
  {
    Fail(path, "header", "more than 2^32-1 vertices");
  }

  // Validate the layout of every element before reading any data.
  enum class Kind
  {
    Vertex,
    Face,
    Strips,
    Other
  };
  struct Plan
  {
    Kind ElementKind = Kind::Other;
    // Role of each property: 0..2 = x, y, z; 3 = index list; -1 = skipped.
    std::vector<int> Role;
  };
  std::vector<Plan> plans(header.Elements.size());
  for (std::size_t e = 0; e < header.Elements.size(); ++e)
  {
    const PLYElement& element = header.Elements[e];
    const std::string headerWhere = "header line " + std::to_string(element.HeaderLine);
    const std::size_t propertyCount = element.Properties.size();
    std::vector<int>& role = plans[e].Role;
    role.assign(propertyCount, -1);
    Kind& kind = plans[e].ElementKind;
    if (element.Name == "vertex")
    {
      kind = Kind::Vertex;
      const char* axes[3] = { "x", "y", "z" };
      for (int axis = 0; axis < 3; ++axis)
      {
        bool found = false;
        for (std::size_t p = 0; p < propertyCount; ++p)
        {
          if (element.Properties[p].Name == axes[axis])
          {
            if (element.Properties[p].IsList)
            {
              Fail(
                path, headerWhere, std::string("vertex property '") + axes[axis] + "' is a list");
            }
            role[p] = axis;
            found = true;
            break;
          }
        }
        if (!found)
        {
          Fail(
            path, headerWhere, std::string("vertex element has no '") + axes[axis] + "' property");
        }
      }
    }
    else if (element.Name == "face" || element.Name == "tristrips")
    {
      kind = element.Name == "face" ? Kind::Face : Kind::Strips;
      bool found = false;
      for (std::size_t p = 0; p < propertyCount && !found; ++p)
      {
        const PLYProperty& property = element.Properties[p];
        if (property.Name == "vertex_indices" ||
          (kind == Kind::Face && property.Name == "vertex_index"))
        {
          if (!property.IsList || !IsIntegral(property.Type))
          {
            Fail(path, headerWhere, "property '" + property.Name + "' must be a list of integers");
          }
          role[p] = 3;
          found = true;
        }
      }
      if (!found)
      {
        Fail(
          path, headerWhere, "element '" + element.Name + "' has no vertex_indices list property");
      }
    }
  }

  std::vector<int64_t> list;
  std::vector<uint32_t> polygon;
  for (std::size_t e = 0; e < header.Elements.size(); ++e)
  {
    const PLYElement& element = header.Elements[e];
    const std::vector<int>& role = plans[e].Role;
    const Kind kind = plans[e].ElementKind;
    const std::size_t propertyCount = element.Properties.size();
    context.Element = &element;
    context.Index = 0;
    if (kind == Kind::Vertex)
    {
      // Capped: a corrupt header must not trigger a huge allocation.
      mesh.Points.reserve(
        static_cast<std::size_t>(3 * std::min<uint64_t>(element.Count, 1u << 24)));
    }
    else if (kind == Kind::Face)
    {
      mesh.Triangles.reserve(mesh.Triangles.size() +
        static_cast<std::size_t>(3 * std::min<uint64_t>(element.Count, 1u << 24)));
    }

    for (uint64_t i = 0; i < element.Count; ++i)
    {
      context.Index = i;
      double xyz[3] = { 0.0, 0.0, 0.0 };
      for (std::size_t p = 0; p < propertyCount; ++p)
      {
        const PLYProperty& property = element.Properties[p];
        const int r = role[p];
        if (property.IsList)
        {
          const int64_t count = reader.ReadInt(property.CountType);
          if (count < 0)
          {
            Fail(path, context.Where(), "negative list count " + std::to_string(count));
          }
          if (r != 3)
          {
            reader.Skip(property.Type, static_cast<uint64_t>(count));
            continue;
          }
          list.resize(static_cast<std::size_t>(count));
          for (int64_t k = 0; k < count; ++k)
          {
            list[static_cast<std::size_t>(k)] = reader.ReadInt(property.Type);
          }
          if (kind == Kind::Face)
          {
            if (count < 3)
            {
              Fail(path, context.Where(),
                "face with " + std::to_string(count) + " vertices (at least 3 needed)");
            }
            polygon.clear();
            for (const int64_t id : list)
            {
              if (id < 0 || static_cast<uint64_t>(id) >= vertexCount)
              {
                Fail(path, context.Where(),
                  "vertex index " + std::to_string(id) + " out of range [0, " +
                    std::to_string(vertexCount) + ")");
              }
              polygon.push_back(static_cast<uint32_t>(id));
            }
            FanTriangulate(polygon, mesh.Triangles);
          }
          else
          {
            DecodeStrip(list, vertexCount, mesh.Triangles,
              [&](const std::string& what) { Fail(path, context.Where(), what); });
          }
        }
        else if (r >= 0 && r < 3)
        {
          xyz[r] = reader.ReadDouble(property.Type);
        }
        else
        {
          reader.Skip(property.Type);
        }
      }
      if (kind == Kind::Vertex)
      {
        mesh.Points.insert(mesh.Points.end(), xyz, xyz + 3);
      }
    }
  }
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
  TriangleMesh mesh;
  // Rough preallocation: ~30 bytes per vertex line, ~2 faces per vertex.
  mesh.Points.reserve(data.size() / 30);
  mesh.Triangles.reserve(data.size() / 15);

  std::vector<uint32_t> polygon;
  std::string joined;
  uint64_t maxPositive = 0;
  std::size_t maxPositiveLine = 0;
  std::size_t lineNumber = 0;
  const char* p = data.data();
  const char* const end = p + data.size();
  while (p < end)
  {
    auto takeLine = [&](const char*& first, const char*& last)
    {
      ++lineNumber;
      first = p;
      const void* newline = std::memchr(p, '\n', static_cast<std::size_t>(end - p));
      last = newline ? static_cast<const char*>(newline) : end;
      p = newline ? last + 1 : end;
      const char* comment =
        static_cast<const char*>(std::memchr(first, '#', static_cast<std::size_t>(last - first)));
      if (comment)
      {
        last = comment;
      }
      while (last > first && IsBlank(last[-1]))
      {
        --last;
      }
    };
    const char* first;
    const char* last;
    takeLine(first, last);
    const std::size_t statementLine = lineNumber;
    if (last > first && last[-1] == '\\')
    {
      // Line continuation: join with the following lines.
      joined.assign(first, last - 1);
      while (p < end)
      {
        takeLine(first, last);
        const bool more = last > first && last[-1] == '\\';
        joined.push_back(' ');
        joined.append(first, more ? last - 1 : last);
        if (!more)
        {
          break;
        }
      }
      ParseOBJLine(path, statementLine, joined.data(), joined.data() + joined.size(), mesh, polygon,
        maxPositive, maxPositiveLine);
    }
    else
    {
      ParseOBJLine(path, statementLine, first, last, mesh, polygon, maxPositive, maxPositiveLine);
    }
  }
  const uint64_t vertexCount = mesh.Points.size() / 3;
  if (maxPositiveLine != 0 && maxPositive >= vertexCount)
  {
    Fail(path, LineWhere(maxPositiveLine),
      "vertex index " + std::to_string(maxPositive + 1) + " out of range (file has " +
        std::to_string(vertexCount) + " vertices)");
  }
  mesh.Points.shrink_to_fit();
  mesh.Triangles.shrink_to_fit();
  return mesh;
}

//------------------------------------------------------------------------------
TriangleMesh LoadPLY(const std::string& path)
{
  const std::string data = ReadWholeFile(path);
  const PLYHeader header = ParsePLYHeader(path, data);
  TriangleMesh mesh;
  PLYContext context;
  context.Path = &path;
  if (header.Format == PLYFormat::Ascii)
  {
    PLYAsciiReader reader(data, header.BodyOffset, header.BodyLine, context);
    ReadPLYBody(path, header, reader, context, mesh);
  }
  else
  {
    PLYBinaryReader reader(
      data, header.BodyOffset, header.Format == PLYFormat::BinaryBigEndian, context);
    ReadPLYBody(path, header, reader, context, mesh);
  }
  mesh.Triangles.shrink_to_fit();
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
}
}
