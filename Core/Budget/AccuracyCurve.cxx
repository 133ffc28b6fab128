// SPDX-License-Identifier: BSD-3-Clause
#include "AccuracyCurve.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace timecritical
{
namespace
{
using Piece = AccuracyCurve::Piece;
constexpr double Infinity = std::numeric_limits<double>::infinity();

template <typename... Args>
[[noreturn]] void Fail(const Args&... args)
{
  std::ostringstream stream;
  stream << "AccuracyCurve: ";
  (stream << ... << args);
  throw std::invalid_argument(stream.str());
}

/// Value of a piece's line at a; K = 0 lines stay finite at a = +infinity.
double LineAt(const Piece& p, double a)
{
  return p.K == 0.0 ? p.R : p.R + p.K * a;
}

/// a <= b up to the relative tolerance (rounding where pieces meet).
bool NotAbove(double a, double b)
{
  return a <= b + AccuracyCurve::Tolerance * std::max({ std::abs(a), std::abs(b), 1.0 });
}

bool Near(double a, double b, double tolerance)
{
  if (a == b)
  {
    return true; // also equal infinities
  }
  return std::abs(a - b) <= tolerance * std::max({ std::abs(a), std::abs(b), 1.0 });
}

void CheckPositive(double value, const char* what)
{
  if (!std::isfinite(value) || !(value > 0.0))
  {
    Fail(what, " must be finite and positive, not ", value);
  }
}

void CheckQuery(double value, const char* what)
{
  if (std::isnan(value) || value < 0.0)
  {
    Fail(what, " must be a non-negative number, not ", value);
  }
}

void CheckPieces(const std::vector<Piece>& pieces, double maximumAccuracy)
{
  const size_t n = pieces.size();
  for (size_t i = 0; i < n; ++i)
  {
    const Piece& p = pieces[i];
    if (!std::isfinite(p.A) || p.A < 0.0)
    {
      Fail("piece ", i, " starts at accuracy ", p.A, ", not a finite non-negative value");
    }
    if (!std::isfinite(p.R) || !std::isfinite(p.K))
    {
      Fail("piece ", i, " has R = ", p.R, " and K = ", p.K, ", not finite values");
    }
    if (p.K < 0.0)
    {
      Fail("piece ", i, " has slope K = ", p.K, ": resources must not decrease with accuracy");
    }
    if (!NotAbove(0.0, LineAt(p, p.A)))
    {
      Fail("piece ", i, " starts at negative resources ", LineAt(p, p.A));
    }
    if (i > 0)
    {
      const Piece& q = pieces[i - 1];
      if (!(p.A > q.A))
      {
        Fail("piece ", i, " starts at accuracy ", p.A, ", not after piece ", i - 1, " (", q.A, ")");
      }
      if (!NotAbove(LineAt(q, p.A), LineAt(p, p.A)))
      {
        Fail("the curve decreases at accuracy ", p.A, " from ", LineAt(q, p.A), " to ",
          LineAt(p, p.A));
      }
    }
  }
  if (n == 0)
  {
    if (maximumAccuracy != 0.0)
    {
      Fail("an empty curve has maximum accuracy 0, not ", maximumAccuracy);
    }
    return;
  }
  const double last = pieces.back().A;
  if (std::isnan(maximumAccuracy) || maximumAccuracy < last || (n > 1 && maximumAccuracy == last))
  {
    Fail("maximum accuracy ", maximumAccuracy, " does not end the last piece (starting at ", last,
      ")");
  }
}
}

//------------------------------------------------------------------------------
AccuracyCurve::AccuracyCurve(std::vector<Piece> pieces, double maximumAccuracy)
  : Pieces(std::move(pieces))
  , MaximumAccuracy(maximumAccuracy)
{
  CheckPieces(this->Pieces, this->MaximumAccuracy);
}

//------------------------------------------------------------------------------
AccuracyCurve AccuracyCurve::SinglePoint(double accuracy, double resources)
{
  return AccuracyCurve({ { accuracy, resources, 0.0 } }, accuracy);
}

//------------------------------------------------------------------------------
AccuracyCurve AccuracyCurve::FromPoints(const std::vector<Point>& points)
{
  if (points.empty())
  {
    return {};
  }
  std::vector<Piece> pieces;
  pieces.reserve(points.size());
  for (size_t i = 0; i + 1 < points.size(); ++i)
  {
    const Point& p = points[i];
    const Point& q = points[i + 1];
    if (!(q.Accuracy > p.Accuracy) || !std::isfinite(q.Accuracy))
    {
      Fail("point ", i + 1, " has accuracy ", q.Accuracy, ", not finite and after point ", i, " (",
        p.Accuracy, ")");
    }
    if (!(q.Resources >= p.Resources) || !std::isfinite(q.Resources))
    {
      Fail("point ", i + 1, " has resources ", q.Resources, ", not finite and at least point ", i,
        "'s ", p.Resources);
    }
    const double k = (q.Resources - p.Resources) / (q.Accuracy - p.Accuracy);
    pieces.push_back({ p.Accuracy, p.Resources - k * p.Accuracy, k });
  }
  if (points.size() == 1)
  {
    return SinglePoint(points[0].Accuracy, points[0].Resources);
  }
  return AccuracyCurve(std::move(pieces), points.back().Accuracy);
}

//------------------------------------------------------------------------------
AccuracyCurve AccuracyCurve::FromErrorSamples(const std::vector<ErrorSample>& samples, double size)
{
  CheckPositive(size, "the object size");
  std::vector<Point> points;
  double exactResources = -1.0; // resources of the first sample with distortion 0
  for (size_t i = 0; i < samples.size(); ++i)
  {
    const ErrorSample& s = samples[i];
    if (!std::isfinite(s.Resources) || s.Resources < 0.0 || !std::isfinite(s.Error) ||
      s.Error < 0.0)
    {
      Fail("sample ", i, " (", s.Resources, ", ", s.Error,
        ") is not a finite non-negative (resources, distortion) pair");
    }
    if (i > 0 && (s.Resources < samples[i - 1].Resources || s.Error > samples[i - 1].Error))
    {
      Fail("sample ", i, " (", s.Resources, ", ", s.Error,
        ") does not follow sample ", i - 1, ": resources must not decrease, nor distortions increase");
    }
    if (s.Error == 0.0)
    {
      exactResources = s.Resources;
      break;
    }
    const double accuracy = size / s.Error;
    if (!points.empty() && !(accuracy > points.back().Accuracy))
    {
      continue; // same distortion, more resources: never the cheapest
    }
    points.push_back({ accuracy, s.Resources });
  }
  if (exactResources < 0.0)
  {
    return FromPoints(points);
  }
  if (points.empty())
  {
    return AccuracyCurve({ { 0.0, exactResources, 0.0 } }, Infinity);
  }
  AccuracyCurve curve = FromPoints(points);
  const double last = curve.MaximumAccuracy;
  if (curve.Pieces.size() == 1 && curve.Pieces[0].A == last)
  {
    curve.Pieces.clear(); // the single point becomes the first piece's end
    curve.Pieces.push_back({ 0.0, points[0].Resources, 0.0 });
  }
  curve.Pieces.push_back({ last, exactResources, 0.0 });
  return AccuracyCurve(std::move(curve.Pieces), Infinity);
}

//------------------------------------------------------------------------------
double AccuracyCurve::GetMinimumAccuracy() const
{
  return this->Pieces.empty() ? 0.0 : this->Pieces.front().A;
}

//------------------------------------------------------------------------------
double AccuracyCurve::GetMinimumResources() const
{
  return this->Pieces.empty() ? 0.0 : LineAt(this->Pieces.front(), this->Pieces.front().A);
}

//------------------------------------------------------------------------------
double AccuracyCurve::GetMaximumResources() const
{
  return this->Pieces.empty() ? 0.0 : LineAt(this->Pieces.back(), this->MaximumAccuracy);
}

//------------------------------------------------------------------------------
std::size_t AccuracyCurve::FindPiece(double a) const
{
  CheckQuery(a, "the accuracy");
  if (this->Pieces.empty() || a > this->MaximumAccuracy)
  {
    return npos;
  }
  // First piece starting at or after a; a belongs to the one before (a
  // breakpoint to the piece that ends there), or to piece 0 below the curve.
  const auto it = std::lower_bound(this->Pieces.begin(), this->Pieces.end(), a,
    [](const Piece& p, double value) { return p.A < value; });
  const auto index = static_cast<std::size_t>(it - this->Pieces.begin());
  return index == 0 ? 0 : index - 1;
}

//------------------------------------------------------------------------------
double AccuracyCurve::GetResources(double a) const
{
  const std::size_t i = this->FindPiece(a);
  if (i == npos)
  {
    return Infinity;
  }
  const Piece& p = this->Pieces[i];
  return LineAt(p, std::max(a, p.A));
}

//------------------------------------------------------------------------------
double AccuracyCurve::GetSaturatedResources(double a) const
{
  CheckQuery(a, "the accuracy");
  if (this->Pieces.empty())
  {
    return 0.0;
  }
  return this->GetResources(std::min(a, this->MaximumAccuracy));
}

//------------------------------------------------------------------------------
double AccuracyCurve::GetAccuracy(double quota) const
{
  CheckQuery(quota, "the resource quota");
  // Start values are non-decreasing: the last piece whose start fits holds the answer.
  const auto it = std::partition_point(this->Pieces.begin(), this->Pieces.end(),
    [quota](const Piece& p) { return LineAt(p, p.A) <= quota; });
  if (it == this->Pieces.begin())
  {
    return 0.0;
  }
  const Piece& p = *(it - 1);
  const double end = it == this->Pieces.end() ? this->MaximumAccuracy : it->A;
  if (p.K == 0.0 || LineAt(p, end) <= quota)
  {
    return end;
  }
  double a = std::min(std::max((quota - p.R) / p.K, p.A), end);
  // Settle the rounding so that the round trip GetResources(a) <= quota holds.
  while (a > p.A && p.R + p.K * a > quota)
  {
    a = std::nextafter(a, -Infinity);
  }
  return a;
}

//------------------------------------------------------------------------------
AccuracyCurve AccuracyCurve::ScaleAccuracy(double factor) const
{
  CheckPositive(factor, "the accuracy factor");
  std::vector<Piece> pieces = this->Pieces;
  for (Piece& p : pieces)
  {
    p.A *= factor;
    p.K /= factor;
  }
  return AccuracyCurve(std::move(pieces), this->MaximumAccuracy * factor);
}

//------------------------------------------------------------------------------
AccuracyCurve AccuracyCurve::Rescale(double ownSize, double newSize) const
{
  CheckPositive(ownSize, "the member's size");
  CheckPositive(newSize, "the group's size");
  return this->ScaleAccuracy(newSize / ownSize);
}

//------------------------------------------------------------------------------
double AccuracyCurve::RelativeToAbsolute(double relative, double size, double distance)
{
  CheckQuery(relative, "the relative accuracy");
  CheckPositive(size, "the object size");
  CheckPositive(distance, "the distance");
  return relative * (distance / size);
}

//------------------------------------------------------------------------------
double AccuracyCurve::AbsoluteToRelative(double absolute, double size, double distance)
{
  CheckQuery(absolute, "the absolute accuracy");
  CheckPositive(size, "the object size");
  CheckPositive(distance, "the distance");
  return absolute * (size / distance);
}

//------------------------------------------------------------------------------
AccuracyCurve AccuracyCurve::ToAbsolute(double size, double distance) const
{
  CheckPositive(size, "the object size");
  CheckPositive(distance, "the distance");
  return this->ScaleAccuracy(distance / size);
}

//------------------------------------------------------------------------------
AccuracyCurve AccuracyCurve::ToRelative(double size, double distance) const
{
  CheckPositive(size, "the object size");
  CheckPositive(distance, "the distance");
  return this->ScaleAccuracy(size / distance);
}

//------------------------------------------------------------------------------
double AccuracyCurve::NearestDistance(double centreDistance, double radius, double minimumDistance)
{
  CheckQuery(centreDistance, "the distance to the centre");
  CheckQuery(radius, "the radius");
  CheckPositive(minimumDistance, "the minimum distance");
  if (std::isinf(centreDistance))
  {
    Fail("the distance to the centre must be finite");
  }
  return std::max(centreDistance - radius, minimumDistance);
}

//------------------------------------------------------------------------------
bool AccuracyCurve::IsNear(const AccuracyCurve& other, double relativeTolerance) const
{
  if (this->Pieces.size() != other.Pieces.size() ||
    !Near(this->MaximumAccuracy, other.MaximumAccuracy, relativeTolerance))
  {
    return false;
  }
  for (size_t i = 0; i < this->Pieces.size(); ++i)
  {
    const Piece& p = this->Pieces[i];
    const Piece& q = other.Pieces[i];
    // Compare the lines where they start, so that large R and K that nearly
    // cancel (a steep piece far from 0) are judged by the resources they give.
    if (!Near(p.A, q.A, relativeTolerance) || !Near(p.K, q.K, relativeTolerance) ||
      !Near(LineAt(p, p.A), LineAt(q, q.A), relativeTolerance))
    {
      return false;
    }
  }
  return true;
}
}
