// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_BenchmarkArguments_h
#define timecritical_BenchmarkArguments_h

/**
 * The benchmarks' command lines, parsed by vtksys::CommandLineArguments
 * (ParaView's VTK ships it) with the checks the benchmarks share: options
 * are `--name VALUE` or `--name`, numbers must be whole and in range, and
 * every mistake is a std::runtime_error that names the option:
 *
 *   missing value after --frames
 *   bad value for --frames: 3x
 *   unknown option --frame (see --help)
 *
 * Options are registered with the variables they set; Parse() sets them in
 * command-line order. `given` (optional) reports whether an option was on
 * the command line, for defaults that depend on --quick.
 */
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace timecritical
{
namespace benchmark
{
class BenchmarkArguments
{
public:
  BenchmarkArguments(int argc, char* argv[]);
  ~BenchmarkArguments();
  BenchmarkArguments(const BenchmarkArguments&) = delete;
  BenchmarkArguments& operator=(const BenchmarkArguments&) = delete;

  /// `--name`: sets `flag` to `value`.
  void AddFlag(const std::string& name, bool& flag, bool value = true);
  /// `--name TEXT`.
  void AddText(const std::string& name, std::string& text, bool* given = nullptr);
  /// `--name TEXT`, repeatable: each occurrence appends to `texts`.
  void AddRepeatedText(const std::string& name, std::vector<std::string>& texts);
  /// `--name N`, a whole number in [minimum, maximum].
  void AddInteger(const std::string& name, int& value, int minimum, int maximum = 1000000,
    bool* given = nullptr);
  /// `--name N` as unsigned, a whole number in [minimum, maximum].
  void AddUnsigned(const std::string& name, unsigned& value, unsigned minimum = 0,
    unsigned maximum = 1000000, bool* given = nullptr);
  /// `--name X`, a finite number with accept(X) true.
  void AddNumber(const std::string& name, double& value,
    std::function<bool(double)> accept = nullptr, bool* given = nullptr);

  /// The one argument that is not an option (a file name), if given.
  void AddPositional(std::string& text);

  /// Parses the command line; throws std::runtime_error on any mistake.
  void Parse();

private:
  struct Option;
  static int Callback(const char* argument, const char* value, void* data);
  Option& Add(const std::string& name, bool takesValue, std::function<bool(const char*)> set,
    bool* given);

  int ArgumentCount;
  char** Arguments;
  std::vector<std::unique_ptr<Option>> Options;
  std::string* Positional = nullptr;
  std::string Error;
};
}
}

#endif
