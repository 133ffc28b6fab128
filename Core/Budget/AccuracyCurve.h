// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_AccuracyCurve_h
#define timecritical_AccuracyCurve_h

#include "TimeCriticalBudgetCoreExport.h"

#include <cstddef>
#include <vector>

namespace timecritical
{
/**
 * Pasman & Jansen's accuracy curve (section 3.1): the least resources r (for
 * instance triangles) that reach an accuracy a = 1/d, where d is the
 * distortion, as pieces r = R + K a stored as the paper's (A, R, K) triples.
 *
 * Pieces are sorted by strictly increasing start accuracy A; piece i holds
 * from its A to the next piece's A, and the last one up to the curve's
 * maximum accuracy (which may be +infinity, as for a full mesh, whose
 * distortion is 0). At a breakpoint the value is the one of the piece that
 * ends there: r(a) is the least resource whose accuracy is AT LEAST a, so a
 * representation reaches the accuracy at the end of its piece (the paper
 * gives the breakpoint to the next piece; only the value exactly at a jump
 * differs). The curve is non-decreasing and may jump up at breakpoints. A
 * curve with one piece starting at its maximum accuracy is a single point:
 * a representation with one accuracy and one cost.
 *
 * Below the first A the curve extends horizontally (a representation more
 * accurate than asked may always be used); above the maximum accuracy it has
 * no value (GetResources gives +infinity, GetSaturatedResources the value at
 * the end, which is how a group extends its members, section 3.2.1).
 *
 * Two kinds of accuracy (section 3.1): relative, the object's size over the
 * distortion, and absolute, one over the angular distortion in radians seen
 * from a viewpoint. An object of size S whose nearest point is at distance D
 * converts with a_absolute = a_relative * D / S (a distortion S / a_relative
 * seen at distance D subtends S / (a_relative D) radians).
 *
 * Bad input (NaN, negative accuracies or resources, a decreasing curve)
 * throws std::invalid_argument with the reason.
 */
class TIMECRITICALBUDGETCORE_EXPORT AccuracyCurve
{
public:
  /// One (A, R, K) triple: r = R + K a from accuracy A on.
  struct Piece
  {
    double A = 0.0;
    double R = 0.0;
    double K = 0.0;
  };

  /// A point (accuracy, resources), for curves given by their knees.
  struct Point
  {
    double Accuracy = 0.0;
    double Resources = 0.0;
  };

  /// (resources, distortion) of a representation, e.g. a TOM's error curve sample.
  struct ErrorSample
  {
    double Resources = 0.0;
    double Error = 0.0;
  };

  /// Relative rounding allowed where one piece ends and the next starts.
  static constexpr double Tolerance = 1e-9;

  /// The empty curve: no representation at all.
  AccuracyCurve() = default;

  /// A curve from its triples and maximum accuracy (checked: throws std::invalid_argument).
  AccuracyCurve(std::vector<Piece> pieces, double maximumAccuracy);

  /// A single point: one representation reaching `accuracy` for `resources`.
  static AccuracyCurve SinglePoint(double accuracy, double resources);

  /**
   * The polyline through points of strictly increasing accuracy and
   * non-decreasing resources (the paper's "few points on major knicks"),
   * ending at the last point. One point gives a single-point curve.
   */
  static AccuracyCurve FromPoints(const std::vector<Point>& points);

  /**
   * The relative curve of representations given by (resources, distortion)
   * samples in increasing resources and non-increasing distortion (a
   * TOMErrorCurve's samples), distortions in the units of `size`:
   * accuracy = size / distortion, the polyline through the samples with a
   * positive distortion, the cheapest sample at each distortion. A sample
   * with distortion 0 (the full mesh) reaches every accuracy: the curve then
   * steps up to its resources after the last positive distortion and never
   * ends (maximum accuracy +infinity).
   */
  static AccuracyCurve FromErrorSamples(const std::vector<ErrorSample>& samples, double size);

  const std::vector<Piece>& GetPieces() const { return this->Pieces; }
  bool IsEmpty() const { return this->Pieces.empty(); }
  /// The first A (0 for an empty curve).
  double GetMinimumAccuracy() const;
  /// The last accuracy the curve reaches (+infinity when unbounded, 0 when empty).
  double GetMaximumAccuracy() const { return this->MaximumAccuracy; }
  /// Resources at the minimum accuracy: the cheapest representation (0 when empty).
  double GetMinimumResources() const;
  /// Resources at the maximum accuracy (may be +infinity; 0 when empty).
  double GetMaximumResources() const;

  /**
   * Resources needed for accuracy a: the value at the minimum accuracy below
   * it, +infinity above the maximum accuracy or for an empty curve.
   * Throws on NaN or negative a.
   */
  double GetResources(double a) const;

  /// As GetResources, but the value at the maximum accuracy above it (0 for an empty curve).
  double GetSaturatedResources(double a) const;

  /**
   * Best accuracy for a resource quota: the largest a with
   * GetResources(a) <= quota (the maximum accuracy, possibly +infinity, when
   * the quota reaches it); 0 when even the cheapest representation does not
   * fit or the curve is empty. Throws on NaN or negative quota.
   */
  double GetAccuracy(double quota) const;

  /// Index of the piece that holds accuracy a (0 below the curve), or npos above
  /// it or for an empty curve. Throws on NaN or negative a.
  std::size_t FindPiece(double a) const;
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);

  /**
   * The curve with accuracies multiplied by factor (> 0, finite): r'(a) =
   * r(a / factor), i.e. pieces (A f, R, K / f), maximum accuracy times f.
   */
  AccuracyCurve ScaleAccuracy(double factor) const;

  /**
   * A relative curve measured against another size (section 3.4): a member of
   * size `ownSize` in a group of size `newSize` reaches group accuracy
   * a newSize / ownSize where it reaches a, so accuracies scale by newSize / ownSize.
   */
  AccuracyCurve Rescale(double ownSize, double newSize) const;

  ///@{
  /**
   * Relative <-> absolute (angular) accuracy of an object of size `size`
   * whose nearest point is at `distance` (both > 0, finite, same units).
   */
  static double RelativeToAbsolute(double relative, double size, double distance);
  static double AbsoluteToRelative(double absolute, double size, double distance);
  AccuracyCurve ToAbsolute(double size, double distance) const;
  AccuracyCurve ToRelative(double size, double distance) const;
  ///@}

  /**
   * Worst-case (smallest) distance from a viewpoint to an object bounded by a
   * sphere: the distance to its centre less its radius, never below
   * minimumDistance (> 0), which keeps a viewer inside the sphere from
   * driving the accuracy to 0 (section 3.2).
   */
  static double NearestDistance(double centreDistance, double radius, double minimumDistance);

  /// True when both curves have the same triples and maximum accuracy, to relative tolerance.
  bool IsNear(const AccuracyCurve& other, double relativeTolerance = Tolerance) const;

private:
  std::vector<Piece> Pieces;
  double MaximumAccuracy = 0.0;
};
}

#endif
