// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_PolicySelection_h
#define timecritical_PolicySelection_h

/**
 * The `--policies` option of the policy-comparison benchmarks (W1, W2).
 */
#include <algorithm>
#include <cstddef>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace timecritical
{
namespace benchmark
{
/**
 * The policies a comma list names, in the order of `all` whatever the order
 * given (so that the full-resolution reference runs first), or all of them
 * for an empty list. `canonical` maps an alias to a policy's Name. Throws
 * std::runtime_error on an unknown name or an empty selection.
 */
template <class Info, size_t N, class Canonical>
std::vector<const Info*> SelectPolicies(
  const Info (&all)[N], const std::string& list, Canonical canonical)
{
  std::vector<bool> wanted(N, list.empty());
  std::stringstream names(list);
  for (std::string name; std::getline(names, name, ',');)
  {
    if (name.empty())
    {
      continue;
    }
    const std::string key = canonical(name);
    const auto found =
      std::find_if(all, all + N, [&key](const Info& info) { return key == info.Name; });
    if (found == all + N)
    {
      throw std::runtime_error("unknown policy '" + name + "' (see --help)");
    }
    wanted[static_cast<size_t>(found - all)] = true;
  }
  std::vector<const Info*> selected;
  for (size_t i = 0; i < N; ++i)
  {
    if (wanted[i])
    {
      selected.push_back(&all[i]);
    }
  }
  if (selected.empty())
  {
    throw std::runtime_error("no policy selected");
  }
  return selected;
}
}
}

#endif
