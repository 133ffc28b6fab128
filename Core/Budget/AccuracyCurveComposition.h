// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_AccuracyCurveComposition_h
#define timecritical_AccuracyCurveComposition_h

#include "AccuracyCurve.h"
#include "TimeCriticalBudgetCoreExport.h"

#include <cstddef>
#include <vector>

namespace timecritical
{
/**
 * Propagation of accuracy curves up a scene graph (Pasman & Jansen, section
 * 3.2): the two node kinds of the paper.
 *
 * - A group renders all its members: its curve ADDS their resources at equal
 *   accuracy (Figure 5). Each member extends horizontally on both sides: below
 *   its first accuracy it renders its cheapest representation, above its
 *   maximum accuracy its finest one. The group reaches every accuracy of any
 *   member.
 * - An LOD node renders one of its children, the cheapest that reaches the
 *   accuracy: its curve is the pointwise MINIMUM (Figure 6). A child extends
 *   to the left (rendering more accurately than asked is allowed) but never
 *   to the right of its maximum accuracy (Figure 7): there it is not a
 *   candidate. Where two children's pieces cross, the piece is split at the
 *   crossing; every piece of the result is a line of one child, unchanged
 *   (only start accuracies are computed), so the result has no cracks.
 *
 * Relative curves (section 3.4) are first rescaled to the node's size
 * (AccuracyCurve::Rescale); absolute curves compose as they are. Empty
 * curves (no representation) are ignored; composing none gives an empty curve.
 */
class TIMECRITICALBUDGETCORE_EXPORT AccuracyCurveComposition
{
public:
  /// The LOD node's curve and, for each of its pieces, the child that gives it.
  struct LODEnvelope
  {
    AccuracyCurve Curve;
    std::vector<std::size_t> PieceChild;

    /**
     * The child an LOD node renders for accuracy a: the cheapest that reaches
     * it (the first child among equals); AccuracyCurve::npos above every
     * child's maximum accuracy or for an empty node. Throws on NaN or negative a.
     */
    std::size_t GetCheapestChild(double a) const;

    /// The child for a resource quota: the one rendered at the best accuracy the quota reaches.
    std::size_t GetChildForQuota(double quota) const;
  };

  /// Group node: resources added at equal accuracy (absolute curves, or relative ones of one size).
  static AccuracyCurve Sum(const std::vector<AccuracyCurve>& members);

  /**
   * Group node of relative curves: each member, of size memberSizes[i], is
   * rescaled to groupSize first (all sizes > 0; one size per member).
   */
  static AccuracyCurve SumRelative(const std::vector<AccuracyCurve>& members,
    const std::vector<double>& memberSizes, double groupSize);

  /// LOD node: the cheapest sufficient child at each accuracy.
  static LODEnvelope Minimum(const std::vector<AccuracyCurve>& children);

  /// LOD node of relative curves: each child rescaled from childSizes[i] to nodeSize first.
  static LODEnvelope MinimumRelative(const std::vector<AccuracyCurve>& children,
    const std::vector<double>& childSizes, double nodeSize);

  /// Relative curves rescaled from their sizes to one size (the sizes checked as in Rescale).
  static std::vector<AccuracyCurve> RescaleAll(
    const std::vector<AccuracyCurve>& curves, const std::vector<double>& sizes, double newSize);
};
}

#endif
