// SPDX-License-Identifier: BSD-3-Clause
#include "TOMErrorCurve.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

namespace timecritical
{
namespace
{
using Sample = TOMErrorCurve::Sample;

/**
 * Error at triangle count t on the segment [p, p+1]. Shared by the forward and
 * inverse lookups so that both agree to the last bit.
 */
double Interpolate(const Sample& p, const Sample& q, uint32_t t)
{
  if (q.Triangles <= p.Triangles || t <= p.Triangles)
  {
    return p.Error;
  }
  if (t >= q.Triangles)
  {
    return q.Error;
  }
  const double f =
    static_cast<double>(t - p.Triangles) / static_cast<double>(q.Triangles - p.Triangles);
  return p.Error + (static_cast<double>(q.Error) - p.Error) * f;
}

/// Distance of candidate k from the chord between candidates p and q.
double Deviation(const std::vector<Sample>& c, size_t p, size_t q, size_t k)
{
  return std::abs(Interpolate(c[p], c[q], c[k].Triangles) - c[k].Error);
}

/// Worst candidate strictly inside (p, q): (deviation, index), index 0 when none.
std::pair<double, size_t> WorstInside(const std::vector<Sample>& c, size_t p, size_t q)
{
  std::pair<double, size_t> worst{ 0.0, 0 };
  for (size_t k = p + 1; k < q; ++k)
  {
    const double d = Deviation(c, p, q, k);
    if (d > worst.first)
    {
      worst = { d, k };
    }
  }
  return worst;
}

template <typename... Args>
std::string Message(const Args&... args)
{
  std::ostringstream stream;
  (stream << ... << args);
  return stream.str();
}
}

//------------------------------------------------------------------------------
TOMErrorCurve::TOMErrorCurve(std::vector<Sample> samples)
  : Samples(std::move(samples))
{
}

//------------------------------------------------------------------------------
TOMErrorCurve TOMErrorCurve::FromVertexErrors(const float* vertexError,
  const uint32_t* trianglesAtVertexCount, uint32_t numberOfVertices, uint32_t baseVertexCount,
  unsigned maxSamples)
{
  if (!vertexError || !trianglesAtVertexCount)
  {
    return {};
  }
  baseVertexCount = std::min(baseVertexCount, numberOfVertices);
  maxSamples = std::max(maxSamples, 2u); // the base and the full mesh

  // Candidates: one per distinct triangle count, from the finest vertex count
  // that has it (the one traversal picks for that count). Inputs that break
  // the documented monotonicity are repaired rather than trusted, so the
  // curve always passes Check: a running minimum for the error (NaN keeps the
  // previous value) and a monotone stack for the triangle counts.
  std::vector<Sample> candidates;
  float previous = std::numeric_limits<float>::max();
  for (uint64_t i = baseVertexCount; i <= numberOfVertices; ++i)
  {
    float error = vertexError[i];
    if (i == numberOfVertices)
    {
      error = 0.f; // the full mesh is the reference
    }
    else if (std::isnan(error))
    {
      error = previous;
    }
    error = std::min(std::max(error, 0.f), previous);
    previous = error;
    const uint32_t triangles = trianglesAtVertexCount[i];
    while (!candidates.empty() && candidates.back().Triangles >= triangles)
    {
      candidates.pop_back();
    }
    candidates.push_back({ triangles, error });
  }

  const size_t count = candidates.size();
  if (count <= maxSamples)
  {
    return TOMErrorCurve(std::move(candidates));
  }

  std::vector<char> selected(count, 0);
  selected.front() = 1;
  selected.back() = 1;
  size_t numberSelected = 2;

  // Half of the budget: geometric spacing in triangle count, which keeps the
  // fine end (tiny errors, most of the triangle range) covered.
  const unsigned geometric = maxSamples / 2;
  const double first = std::max(1.0, static_cast<double>(candidates.front().Triangles));
  const double last = std::max(first, static_cast<double>(candidates.back().Triangles));
  for (unsigned j = 1; j + 1 < geometric; ++j)
  {
    const double target = first * std::pow(last / first, double(j) / double(geometric - 1));
    // Last candidate not above the target.
    const auto it = std::upper_bound(candidates.begin(), candidates.end(), target,
      [](double value, const Sample& s) { return value < static_cast<double>(s.Triangles); });
    const size_t k = static_cast<size_t>(std::max<std::ptrdiff_t>(it - candidates.begin() - 1, 0));
    if (!selected[k])
    {
      selected[k] = 1;
      ++numberSelected;
    }
  }

  // The rest: greedy refinement where the polyline misses the error most
  // (Douglas-Peucker style), i.e. where the error changes fast. Each split
  // only rescans the two new segments.
  struct Segment
  {
    size_t Begin;
    size_t End;
    double Deviation;
    size_t Worst;
  };
  std::vector<Segment> segments;
  for (size_t p = 0, q = 1; q < count; ++q)
  {
    if (selected[q])
    {
      const auto worst = WorstInside(candidates, p, q);
      segments.push_back({ p, q, worst.first, worst.second });
      p = q;
    }
  }
  while (numberSelected < maxSamples)
  {
    auto split = std::max_element(segments.begin(), segments.end(),
      [](const Segment& a, const Segment& b) { return a.Deviation < b.Deviation; });
    if (split == segments.end() || !(split->Deviation > 0.0))
    {
      break; // the polyline is already exact
    }
    const Segment s = *split;
    selected[s.Worst] = 1;
    ++numberSelected;
    const auto left = WorstInside(candidates, s.Begin, s.Worst);
    const auto right = WorstInside(candidates, s.Worst, s.End);
    *split = { s.Begin, s.Worst, left.first, left.second };
    segments.push_back({ s.Worst, s.End, right.first, right.second });
  }

  std::vector<Sample> samples;
  samples.reserve(numberSelected);
  for (size_t k = 0; k < count; ++k)
  {
    if (selected[k])
    {
      samples.push_back(candidates[k]);
    }
  }
  return TOMErrorCurve(std::move(samples));
}

//------------------------------------------------------------------------------
double TOMErrorCurve::GetErrorForTriangles(uint32_t triangles) const
{
  if (this->Samples.empty())
  {
    return 0.0;
  }
  const auto it = std::upper_bound(this->Samples.begin(), this->Samples.end(), triangles,
    [](uint32_t value, const Sample& s) { return value < s.Triangles; });
  if (it == this->Samples.begin())
  {
    return this->Samples.front().Error;
  }
  if (it == this->Samples.end())
  {
    return this->Samples.back().Error;
  }
  return Interpolate(*(it - 1), *it, triangles);
}

//------------------------------------------------------------------------------
uint32_t TOMErrorCurve::GetTrianglesForError(double maxError) const
{
  if (this->Samples.empty())
  {
    return 0;
  }
  const Sample& front = this->Samples.front();
  const Sample& back = this->Samples.back();
  if (std::isnan(maxError) || maxError < 0.0)
  {
    return back.Triangles;
  }
  if (maxError >= front.Error)
  {
    return front.Triangles;
  }
  // First sample within the bound; every sample before it, and hence the
  // whole polyline before it, is above the bound.
  const auto it = std::partition_point(this->Samples.begin(), this->Samples.end(),
    [maxError](const Sample& s) { return s.Error > maxError; });
  if (it == this->Samples.end())
  {
    return back.Triangles; // malformed curve (last error above 0)
  }
  const Sample& q = *it;
  const Sample& p = *(it - 1);
  if (q.Triangles <= p.Triangles)
  {
    return q.Triangles; // malformed curve (unsorted)
  }
  // Solve the segment's linear equation, then settle the rounding against
  // Interpolate itself so the answer is exactly the smallest count that fits.
  const double span = static_cast<double>(q.Triangles - p.Triangles);
  const double x = std::ceil((p.Error - maxError) / (static_cast<double>(p.Error) - q.Error) * span);
  uint32_t t = p.Triangles + static_cast<uint32_t>(std::min(std::max(x, 1.0), span));
  while (t > p.Triangles + 1 && Interpolate(p, q, t - 1) <= maxError)
  {
    --t;
  }
  while (t < q.Triangles && Interpolate(p, q, t) > maxError)
  {
    ++t;
  }
  return t;
}

//------------------------------------------------------------------------------
std::string TOMErrorCurve::Check(uint32_t numberOfTriangles) const
{
  const size_t count = this->Samples.size();
  for (size_t i = 0; i < count; ++i)
  {
    const Sample& s = this->Samples[i];
    if (!std::isfinite(s.Error) || s.Error < 0.f)
    {
      return Message("sample ", i, " has error ", s.Error, ", not a finite non-negative value");
    }
    if (s.Triangles > numberOfTriangles)
    {
      return Message("sample ", i, " has ", s.Triangles, " triangles, more than the mesh's ",
        numberOfTriangles);
    }
    if (i > 0)
    {
      const Sample& previous = this->Samples[i - 1];
      if (s.Triangles <= previous.Triangles)
      {
        return Message("sample ", i, " triangle count ", s.Triangles,
          " does not increase (sample ", i - 1, " has ", previous.Triangles, ")");
      }
      if (s.Error > previous.Error)
      {
        return Message("sample ", i, " error ", s.Error, " increases (sample ", i - 1, " has ",
          previous.Error, ")");
      }
    }
  }
  if (count > 0)
  {
    const Sample& last = this->Samples.back();
    if (last.Triangles != numberOfTriangles)
    {
      return Message("last sample ", count - 1, " has ", last.Triangles,
        " triangles, not the full mesh's ", numberOfTriangles);
    }
    if (last.Error != 0.f)
    {
      return Message(
        "last sample ", count - 1, " (the full mesh) has error ", last.Error, ", not 0");
    }
  }
  return {};
}
}
