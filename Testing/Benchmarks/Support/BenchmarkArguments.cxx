// SPDX-License-Identifier: BSD-3-Clause
#include "BenchmarkArguments.h"

#include <vtksys/CommandLineArguments.hxx>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>

namespace timecritical
{
namespace benchmark
{
struct BenchmarkArguments::Option
{
  BenchmarkArguments* Owner = nullptr;
  std::string Name;
  bool TakesValue = false;
  std::function<bool(const char*)> Set; ///< false: the value is bad
  bool* Given = nullptr;
};

namespace
{
/// `text` as a whole number, or false when it is not one entirely.
bool ParseWhole(const char* text, long long& value)
{
  if (!text || !*text)
  {
    return false;
  }
  char* end = nullptr;
  errno = 0;
  value = std::strtoll(text, &end, 10);
  return end != text && *end == '\0' && errno == 0;
}
}

BenchmarkArguments::BenchmarkArguments(int argc, char* argv[])
  : ArgumentCount(argc)
  , Arguments(argv)
{
}

BenchmarkArguments::~BenchmarkArguments() = default;

BenchmarkArguments::Option& BenchmarkArguments::Add(
  const std::string& name, bool takesValue, std::function<bool(const char*)> set, bool* given)
{
  auto option = std::make_unique<Option>();
  option->Owner = this;
  option->Name = name;
  option->TakesValue = takesValue;
  option->Set = std::move(set);
  option->Given = given;
  this->Options.push_back(std::move(option));
  return *this->Options.back();
}

void BenchmarkArguments::AddFlag(const std::string& name, bool& flag, bool value)
{
  this->Add(
    name, false,
    [&flag, value](const char*) {
      flag = value;
      return true;
    },
    nullptr);
}

void BenchmarkArguments::AddText(const std::string& name, std::string& text, bool* given)
{
  this->Add(
    name, true,
    [&text](const char* value) {
      text = value ? value : "";
      return true;
    },
    given);
}

void BenchmarkArguments::AddRepeatedText(const std::string& name, std::vector<std::string>& texts)
{
  this->Add(
    name, true,
    [&texts](const char* value) {
      texts.emplace_back(value ? value : "");
      return true;
    },
    nullptr);
}

void BenchmarkArguments::AddInteger(
  const std::string& name, int& value, int minimum, int maximum, bool* given)
{
  this->Add(
    name, true,
    [&value, minimum, maximum](const char* text) {
      long long parsed = 0;
      if (!ParseWhole(text, parsed) || parsed < minimum || parsed > maximum)
      {
        return false;
      }
      value = static_cast<int>(parsed);
      return true;
    },
    given);
}

void BenchmarkArguments::AddUnsigned(
  const std::string& name, unsigned& value, unsigned minimum, unsigned maximum, bool* given)
{
  this->Add(
    name, true,
    [&value, minimum, maximum](const char* text) {
      long long parsed = 0;
      if (!ParseWhole(text, parsed) || parsed < static_cast<long long>(minimum) ||
        parsed > static_cast<long long>(maximum))
      {
        return false;
      }
      value = static_cast<unsigned>(parsed);
      return true;
    },
    given);
}

void BenchmarkArguments::AddNumber(
  const std::string& name, double& value, std::function<bool(double)> accept, bool* given)
{
  this->Add(
    name, true,
    [&value, accept](const char* text) {
      if (!text || !*text)
      {
        return false;
      }
      char* end = nullptr;
      const double parsed = std::strtod(text, &end);
      if (end == text || *end != '\0' || !std::isfinite(parsed) || (accept && !accept(parsed)))
      {
        return false;
      }
      value = parsed;
      return true;
    },
    given);
}

void BenchmarkArguments::AddPositional(std::string& text)
{
  this->Positional = &text;
}

int BenchmarkArguments::Callback(const char*, const char* value, void* data)
{
  Option& option = *static_cast<Option*>(data);
  if (!option.Set(value))
  {
    option.Owner->Error =
      "bad value for " + option.Name + ": " + std::string(value ? value : "");
    return 0;
  }
  if (option.Given)
  {
    *option.Given = true;
  }
  return 1;
}

void BenchmarkArguments::Parse()
{
  vtksys::CommandLineArguments parser;
  parser.Initialize(this->ArgumentCount, this->Arguments);
  parser.StoreUnusedArguments(true);
  for (const auto& option : this->Options)
  {
    parser.AddCallback(option->Name.c_str(),
      option->TakesValue ? vtksys::CommandLineArguments::SPACE_ARGUMENT
                         : vtksys::CommandLineArguments::NO_ARGUMENT,
      &BenchmarkArguments::Callback, option.get(), "");
  }
  this->Error.clear();
  if (!parser.Parse())
  {
    // Without a callback's message, the parser stopped at an option whose
    // value is missing: that can only be the last argument.
    throw std::runtime_error(!this->Error.empty()
        ? this->Error
        : "missing value after " + std::string(this->Arguments[this->ArgumentCount - 1]));
  }
  int count = 0;
  char** unused = nullptr;
  parser.GetUnusedArguments(&count, &unused);
  // The first unused argument is the program's name.
  std::vector<std::string> rest(unused + std::min(count, 1), unused + count);
  parser.DeleteRemainingArguments(count, &unused);
  bool positionalTaken = false;
  for (const std::string& argument : rest)
  {
    if (this->Positional && !positionalTaken && !argument.empty() && argument[0] != '-')
    {
      *this->Positional = argument;
      positionalTaken = true;
      continue;
    }
    throw std::runtime_error("unknown option " + argument + " (see --help)");
  }
}
}
}
