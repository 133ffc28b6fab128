// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_BenchmarkJson_h
#define timecritical_BenchmarkJson_h

/**
 * JSON output of the benchmarks. Two forms: text pieces (Number, Quoted,
 * Array) for the reports written as streams, and JsonValue, an ordered tree
 * for the reports built as data. Both write non-finite numbers as null, so
 * that a missing figure reads as None in the plot scripts.
 */
#include <cstddef>
#include <ostream>
#include <string>
#include <type_traits>
#include <vector>

namespace timecritical
{
namespace benchmark
{
/// `value` with `digits` significant digits, or null when it is not finite.
std::string Number(double value, int digits = 6);

/// `text` as a JSON string literal.
std::string Quoted(const std::string& text);

/// A JSON array of one value per record.
template <class Record, class Getter>
std::string Array(const std::vector<Record>& records, Getter get, int digits = 6)
{
  std::string out = "[";
  for (size_t i = 0; i < records.size(); ++i)
  {
    out += (i ? "," : "") + Number(get(records[i]), digits);
  }
  return out + "]";
}

/**
 * A JSON value whose objects keep their keys in insertion order, written
 * two-space indented with numbers at 12 significant digits.
 */
class JsonValue
{
public:
  JsonValue() = default;
  JsonValue(bool value);
  template <class T, std::enable_if_t<std::is_arithmetic<T>::value, int> = 0>
  JsonValue(T value)
    : Type(Kind::Number)
    , NumberValue(static_cast<double>(value))
  {
  }
  JsonValue(std::string value);
  JsonValue(const char* value);

  static JsonValue Object();
  static JsonValue Array();

  /// Appends `key` to an object (keys are not checked for repeats).
  JsonValue& Set(const std::string& key, JsonValue value);
  /// Appends to an array.
  JsonValue& Push(JsonValue value);

  void Write(std::ostream& os, int indent = 0) const;

private:
  enum class Kind
  {
    Null,
    Bool,
    Number,
    String,
    Array,
    Object
  };

  explicit JsonValue(Kind kind);
  void WriteContainer(std::ostream& os, int indent) const;

  Kind Type = Kind::Null;
  bool Flag = false;
  double NumberValue = 0.0;
  std::string Text;
  std::vector<std::string> Keys;
  std::vector<JsonValue> Items;
};
}
}

#endif
