// SPDX-License-Identifier: BSD-3-Clause
#include "BenchmarkJson.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace timecritical
{
namespace benchmark
{
std::string Number(double value, int digits)
{
  if (!std::isfinite(value))
  {
    return "null";
  }
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*g", digits, value);
  return buffer;
}

std::string Quoted(const std::string& text)
{
  std::string out = "\"";
  for (char c : text)
  {
    if (c == '"' || c == '\\')
    {
      out += '\\';
      out += c;
    }
    else if (static_cast<unsigned char>(c) < 0x20)
    {
      char buffer[8];
      std::snprintf(buffer, sizeof(buffer), "\\u%04x", static_cast<unsigned>(c));
      out += buffer;
    }
    else
    {
      out += c;
    }
  }
  return out + "\"";
}

JsonValue::JsonValue(bool value)
  : Type(Kind::Bool)
  , Flag(value)
{
}

JsonValue::JsonValue(std::string value)
  : Type(Kind::String)
  , Text(std::move(value))
{
}

JsonValue::JsonValue(const char* value)
  : JsonValue(std::string(value))
{
}

JsonValue::JsonValue(Kind kind)
  : Type(kind)
{
}

JsonValue JsonValue::Object()
{
  return JsonValue(Kind::Object);
}

JsonValue JsonValue::Array()
{
  return JsonValue(Kind::Array);
}

JsonValue& JsonValue::Set(const std::string& key, JsonValue value)
{
  if (this->Type != Kind::Object)
  {
    throw std::logic_error("JsonValue::Set on a value that is not an object");
  }
  this->Keys.push_back(key);
  this->Items.push_back(std::move(value));
  return *this;
}

JsonValue& JsonValue::Push(JsonValue value)
{
  if (this->Type != Kind::Array)
  {
    throw std::logic_error("JsonValue::Push on a value that is not an array");
  }
  this->Items.push_back(std::move(value));
  return *this;
}

void JsonValue::Write(std::ostream& os, int indent) const
{
  switch (this->Type)
  {
    case Kind::Null:
      os << "null";
      break;
    case Kind::Bool:
      os << (this->Flag ? "true" : "false");
      break;
    case Kind::Number:
      os << Number(this->NumberValue, 12);
      break;
    case Kind::String:
      os << Quoted(this->Text);
      break;
    case Kind::Array:
    case Kind::Object:
      this->WriteContainer(os, indent);
      break;
  }
}

void JsonValue::WriteContainer(std::ostream& os, int indent) const
{
  const bool object = this->Type == Kind::Object;
  os << (object ? '{' : '[');
  for (size_t i = 0; i < this->Items.size(); ++i)
  {
    os << (i ? ",\n" : "\n") << std::string(indent + 2, ' ');
    if (object)
    {
      os << Quoted(this->Keys[i]) << ": ";
    }
    this->Items[i].Write(os, indent + 2);
  }
  if (!this->Items.empty())
  {
    os << "\n" << std::string(indent, ' ');
  }
  os << (object ? '}' : ']');
}
}
}
