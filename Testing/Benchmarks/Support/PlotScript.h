// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_PlotScript_h
#define timecritical_PlotScript_h

/**
 * The call of a benchmark's matplotlib script (scripts/plot_*.py) on the
 * JSON file it has just written.
 */
#include <string>

namespace timecritical
{
namespace benchmark
{
/// `text` in single quotes for /bin/sh.
std::string ShellQuoted(const std::string& text);

/// Runs /usr/bin/python3 `script` `json` --output `png`; skips (with a
/// message) when the script or matplotlib is missing, throws when the script
/// fails.
void RunPlotScript(const std::string& script, const std::string& json, const std::string& png);
}
}

#endif
