// SPDX-License-Identifier: BSD-3-Clause
#include "PlotScript.h"

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <stdexcept>

namespace timecritical
{
namespace benchmark
{
std::string ShellQuoted(const std::string& text)
{
  std::string out = "'";
  for (char c : text)
  {
    out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  }
  return out + "'";
}

void RunPlotScript(const std::string& script, const std::string& json, const std::string& png)
{
  if (script.empty() || !std::filesystem::is_regular_file(script))
  {
    std::cerr << "plot: script not found, skipped\n";
    return;
  }
  if (std::system("/usr/bin/python3 -c 'import matplotlib' >/dev/null 2>&1") != 0)
  {
    std::cerr << "plot: /usr/bin/python3 with matplotlib not available, skipped\n";
    return;
  }
  const std::string command = "/usr/bin/python3 " + ShellQuoted(script) + " " +
    ShellQuoted(json) + " --output " + ShellQuoted(png);
  if (std::system(command.c_str()) != 0)
  {
    throw std::runtime_error("the plot script failed: " + command);
  }
  std::cerr << "plot: " << png << "\n";
}
}
}
