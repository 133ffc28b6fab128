// SPDX-License-Identifier: BSD-3-Clause
#include "AccuracyCurveComposition.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace timecritical
{
namespace
{
using Piece = AccuracyCurve::Piece;
constexpr double Infinity = std::numeric_limits<double>::infinity();

/// Neumaier's compensated sum: the group's R and K stay exact to rounding
/// whatever the number of members and breakpoints.
struct CompensatedSum
{
  double Sum = 0.0;
  double Compensation = 0.0;

  void Add(double value)
  {
    const double t = this->Sum + value;
    if (std::abs(this->Sum) >= std::abs(value))
    {
      this->Compensation += (this->Sum - t) + value;
    }
    else
    {
      this->Compensation += (value - t) + this->Sum;
    }
    this->Sum = t;
  }
  double Get() const { return this->Sum + this->Compensation; }
};

/// A change of one member's line at an accuracy (the sweep of Sum).
struct Event
{
  double At;
  double RemoveR, RemoveK; // the line the member leaves
  double AddR, AddK;       // the line it takes
};

/// The line of a curve on the interval (from, ...]: constant left of the
/// curve, its piece inside, constant right of it.
Piece LineOn(const AccuracyCurve& curve, double from)
{
  const auto& pieces = curve.GetPieces();
  if (from < pieces.front().A)
  {
    return { from, curve.GetMinimumResources(), 0.0 };
  }
  if (from >= curve.GetMaximumAccuracy())
  {
    return { from, curve.GetMaximumResources(), 0.0 };
  }
  return pieces[curve.FindPiece(std::nextafter(from, Infinity))];
}

double ValueAt(const Piece& line, double a)
{
  return line.K == 0.0 ? line.R : line.R + line.K * a;
}

/// Appends a piece, merged into the last one when it continues the same line of the same child.
void Append(std::vector<Piece>& pieces, std::vector<std::size_t>* owners, const Piece& piece,
  std::size_t owner)
{
  if (!pieces.empty() && pieces.back().R == piece.R && pieces.back().K == piece.K &&
    (!owners || owners->back() == owner))
  {
    return;
  }
  pieces.push_back(piece);
  if (owners)
  {
    owners->push_back(owner);
  }
}

/// Candidate lines on one interval of the LOD node: (line, child).
using Candidates = std::vector<std::pair<Piece, std::size_t>>;

/// Appends the lower envelope of the candidates on (from, to]: the cheapest
/// line at `from` (the flatter one among equals), then at each crossing the
/// flatter line that crosses first.
void AppendEnvelope(const Candidates& lines, double from, double to, std::vector<Piece>& pieces,
  std::vector<std::size_t>& owners)
{
  auto better = [from](const std::pair<Piece, std::size_t>& x,
                  const std::pair<Piece, std::size_t>& y) {
    const double vx = ValueAt(x.first, from);
    const double vy = ValueAt(y.first, from);
    if (vx != vy)
    {
      return vx < vy;
    }
    if (x.first.K != y.first.K)
    {
      return x.first.K < y.first.K;
    }
    return x.second < y.second;
  };
  auto current = *std::min_element(lines.begin(), lines.end(), better);
  double x = from;
  for (;;)
  {
    Append(pieces, &owners, { x, current.first.R, current.first.K }, current.second);
    double next = to;
    const std::pair<Piece, std::size_t>* successor = nullptr;
    for (const auto& line : lines)
    {
      if (!(line.first.K < current.first.K))
      {
        continue;
      }
      const double crossing = (line.first.R - current.first.R) / (current.first.K - line.first.K);
      if (crossing > x && (crossing < next || (crossing == next && successor &&
                                                 line.first.K < successor->first.K)))
      {
        next = crossing;
        successor = &line;
      }
    }
    if (!successor)
    {
      return;
    }
    x = next;
    current = *successor;
  }
}

/**
 * The envelope's intervals are open at the left, so a child that reaches only
 * the first breakpoint (a single point there) is not among them; if it is the
 * cheapest there, the curve gets a constant first piece from accuracy 0 (a
 * constant extends to the left unchanged). At accuracy 0 there is no room:
 * such a child is then left out, which only overestimates.
 */
void PrependStartPoint(const std::vector<AccuracyCurve>& children, double start,
  std::vector<Piece>& pieces, std::vector<std::size_t>& owners)
{
  std::size_t best = AccuracyCurve::npos;
  double value = ValueAt(pieces.front(), start);
  for (std::size_t c = 0; c < children.size(); ++c)
  {
    if (!children[c].IsEmpty() && children[c].GetResources(start) < value)
    {
      value = children[c].GetResources(start);
      best = c;
    }
  }
  if (best != AccuracyCurve::npos && start > 0.0)
  {
    pieces.insert(pieces.begin(), { 0.0, value, 0.0 });
    owners.insert(owners.begin(), best);
  }
}

void CheckSizes(const std::vector<AccuracyCurve>& curves, const std::vector<double>& sizes)
{
  if (curves.size() != sizes.size())
  {
    throw std::invalid_argument("AccuracyCurveComposition: " + std::to_string(curves.size()) +
      " curves but " + std::to_string(sizes.size()) + " sizes");
  }
}
}

//------------------------------------------------------------------------------
std::size_t AccuracyCurveComposition::LODEnvelope::GetCheapestChild(double a) const
{
  const std::size_t piece = this->Curve.FindPiece(a); // throws on NaN or negative a
  return piece == AccuracyCurve::npos ? AccuracyCurve::npos : this->PieceChild[piece];
}

//------------------------------------------------------------------------------
std::size_t AccuracyCurveComposition::LODEnvelope::GetChildForQuota(double quota) const
{
  const double a = this->Curve.GetAccuracy(quota); // throws on NaN or negative quota
  if (this->Curve.IsEmpty() || quota < this->Curve.GetMinimumResources())
  {
    return AccuracyCurve::npos; // even the cheapest child does not fit
  }
  return this->GetCheapestChild(a);
}

//------------------------------------------------------------------------------
AccuracyCurve AccuracyCurveComposition::Sum(const std::vector<AccuracyCurve>& members)
{
  // Sweep over every breakpoint of every member, keeping the sum of the
  // members' current lines; each breakpoint swaps one member's line.
  std::vector<Event> events;
  CompensatedSum r;
  CompensatedSum k;
  double end = 0.0;
  for (const AccuracyCurve& member : members)
  {
    if (member.IsEmpty())
    {
      continue;
    }
    const auto& pieces = member.GetPieces();
    const double low = member.GetMinimumResources();
    r.Add(low); // left of its first accuracy: its cheapest representation
    end = std::max(end, member.GetMaximumAccuracy());
    events.push_back({ pieces.front().A, low, 0.0, pieces.front().R, pieces.front().K });
    for (size_t i = 1; i < pieces.size(); ++i)
    {
      events.push_back(
        { pieces[i].A, pieces[i - 1].R, pieces[i - 1].K, pieces[i].R, pieces[i].K });
    }
    if (std::isfinite(member.GetMaximumAccuracy()))
    {
      events.push_back({ member.GetMaximumAccuracy(), pieces.back().R, pieces.back().K,
        member.GetMaximumResources(), 0.0 });
    }
  }
  if (events.empty())
  {
    return {};
  }
  std::stable_sort(events.begin(), events.end(),
    [](const Event& x, const Event& y) { return x.At < y.At; });

  std::vector<Piece> pieces;
  for (size_t i = 0; i < events.size();)
  {
    const double at = events[i].At;
    for (; i < events.size() && events[i].At == at; ++i)
    {
      r.Add(-events[i].RemoveR);
      r.Add(events[i].AddR);
      k.Add(-events[i].RemoveK);
      k.Add(events[i].AddK);
    }
    if (at < end || pieces.empty())
    {
      // K is a sum of non-negative slopes: a negative value is rounding.
      Append(pieces, nullptr, { at, r.Get(), std::max(k.Get(), 0.0) }, 0);
    }
  }
  return AccuracyCurve(std::move(pieces), end);
}

//------------------------------------------------------------------------------
AccuracyCurve AccuracyCurveComposition::SumRelative(const std::vector<AccuracyCurve>& members,
  const std::vector<double>& memberSizes, double groupSize)
{
  return Sum(RescaleAll(members, memberSizes, groupSize));
}

//------------------------------------------------------------------------------
AccuracyCurveComposition::LODEnvelope AccuracyCurveComposition::Minimum(
  const std::vector<AccuracyCurve>& children)
{
  // Every breakpoint of every child; between two of them each child is one line.
  std::vector<double> breaks;
  double end = 0.0;
  for (const AccuracyCurve& child : children)
  {
    if (child.IsEmpty())
    {
      continue;
    }
    for (const Piece& p : child.GetPieces())
    {
      breaks.push_back(p.A);
    }
    end = std::max(end, child.GetMaximumAccuracy());
    if (std::isfinite(child.GetMaximumAccuracy()))
    {
      breaks.push_back(child.GetMaximumAccuracy());
    }
  }
  LODEnvelope result;
  if (breaks.empty())
  {
    return result;
  }
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());

  std::vector<Piece> pieces;
  Candidates lines;
  for (size_t j = 0; j < breaks.size() && (breaks[j] < end || j == 0); ++j)
  {
    const double from = breaks[j];
    const double to = j + 1 < breaks.size() ? breaks[j + 1] : end;
    lines.clear();
    for (size_t c = 0; c < children.size(); ++c)
    {
      // Never extended to the right: a child is a candidate only up to its maximum accuracy.
      if (!children[c].IsEmpty() && children[c].GetMaximumAccuracy() >= to)
      {
        lines.emplace_back(LineOn(children[c], from), c);
      }
    }
    AppendEnvelope(lines, from, to, pieces, result.PieceChild);
  }
  PrependStartPoint(children, breaks.front(), pieces, result.PieceChild);
  result.Curve = AccuracyCurve(std::move(pieces), end);
  return result;
}

//------------------------------------------------------------------------------
AccuracyCurveComposition::LODEnvelope AccuracyCurveComposition::MinimumRelative(
  const std::vector<AccuracyCurve>& children, const std::vector<double>& childSizes,
  double nodeSize)
{
  return Minimum(RescaleAll(children, childSizes, nodeSize));
}

//------------------------------------------------------------------------------
std::vector<AccuracyCurve> AccuracyCurveComposition::RescaleAll(
  const std::vector<AccuracyCurve>& curves, const std::vector<double>& sizes, double newSize)
{
  CheckSizes(curves, sizes);
  std::vector<AccuracyCurve> result;
  result.reserve(curves.size());
  for (size_t i = 0; i < curves.size(); ++i)
  {
    result.push_back(curves[i].IsEmpty() ? curves[i] : curves[i].Rescale(sizes[i], newSize));
  }
  return result;
}
}
