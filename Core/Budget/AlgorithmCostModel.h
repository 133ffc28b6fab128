// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_AlgorithmCostModel_h
#define timecritical_AlgorithmCostModel_h

#include "FrameCostModel.h"
#include "RenderingAlgorithm.h"
#include "TimeCriticalBudgetCoreExport.h"

#include <array>
#include <cstddef>

namespace timecritical
{
/**
 * Funkhouser & Séquin's cost of an object tuple (O, L, R) with coefficients
 * per rendering algorithm:
 *
 *   Cost(O, L, R) = max(C1_R Poly(O, L) + C2_R Vert(O, L), C3_R Pix(O))   (Overlapped)
 *   Cost(O, L, R) = C1_R Poly(O, L) + C2_R Vert(O, L) + C3_R Pix(O)        (Additive)
 *
 * plus a draw call per algorithm in use (a multiresolution mapper draws the
 * objects of one algorithm together). For a TOM, Poly and Vert at resolution
 * r are r Nmaxtri and r Nmaxvert (prefixes), so each tuple has the linear
 * form of TupleProblem: C = F + T r on [lo, 1], with T = C1 Nmaxtri +
 * C2 Nmaxvert, and, as in FrameCostModel, lo from eq. 3 and F = 0 when
 * geometry and fill overlap, or F = C3 Npix and lo the coarsest resolution
 * when they add up.
 *
 * Draw calls: which algorithms end up in use is only known after the
 * choice, so DrawCallTime() counts every allowed algorithm (an upper bound,
 * by at most the draw calls of the algorithms left unused).
 *
 * Calibration: GetFeatures() gives a frame's features for CostModelCalibrator
 * (1, then per algorithm in the order of the set: draw calls, triangles,
 * vertices, pixels; at most 1 + 4 x 4 = 17), SetFeatureWeights() takes the
 * fitted coefficients back: the calibrator fits every algorithm's
 * coefficients online from frames that mix them.
 *
 * The default model has no algorithm; AlgorithmCostModel(FrameCostModel)
 * is today's single algorithm (per-fragment lit, no per-vertex term).
 * Coefficients must be finite and non-negative (std::invalid_argument).
 */
class TIMECRITICALBUDGETCORE_EXPORT AlgorithmCostModel
{
public:
  struct Coefficients
  {
    double DrawCall = 0.0; ///< per draw call of this algorithm (s)
    double Triangle = 0.0; ///< C1: per triangle (s)
    double Vertex = 0.0;   ///< C2: per vertex (s)
    double Pixel = 0.0;    ///< C3: per covered pixel (s)
  };

  static constexpr std::size_t FeaturesPerAlgorithm = 4;
  static constexpr std::size_t MaxFeatureCount = 1 + FeaturesPerAlgorithm * RenderingAlgorithmCount;

  AlgorithmCostModel() = default;
  /// Today's model as one algorithm (PerFragmentLit): its Frame, DrawCall, Triangle, Pixel and mode.
  explicit AlgorithmCostModel(const FrameCostModel& model);

  /// Adds the algorithm (at the end of the set) or replaces its coefficients.
  void SetAlgorithm(RenderingAlgorithm algorithm, const Coefficients& coefficients);
  void RemoveAlgorithm(RenderingAlgorithm algorithm);
  std::size_t GetAlgorithmCount() const { return this->Count; }
  RenderingAlgorithm GetAlgorithm(std::size_t index) const { return this->Algorithms[index]; }
  /// Index of the algorithm in the set, -1 when absent.
  int IndexOf(RenderingAlgorithm algorithm) const;
  const Coefficients& GetCoefficients(std::size_t index) const { return this->Coeffs[index]; }

  /// Per frame (clears, swap), shared by all algorithms; >= 0.
  void SetFrameTime(double seconds);
  double GetFrameTime() const { return this->Frame; }
  void SetPixelMode(FrameCostModel::PixelMode mode) { this->Mode = mode; }
  FrameCostModel::PixelMode GetPixelMode() const { return this->Mode; }

  /// The exact tuple cost for the algorithm at this index.
  double TupleCost(std::size_t index, double triangles, double vertices, double pixels) const;

  /**
   * The TupleProblem terms of n objects: T, F and lo, n x AlgorithmCount
   * each, row-major. maxVertices null: Nmaxtri / 2; coarsest null: none.
   * Throws std::invalid_argument when the set is empty.
   */
  void Evaluate(std::size_t n, const double* maxTriangles, const double* maxVertices,
    const double* pixels, const double* coarsest, double* maxTime, double* fixedCost,
    double* minResolution) const;

  /// Frame + one draw call per allowed algorithm (drawCallsPerAlgorithm of them).
  double DrawCallTime(double drawCallsPerAlgorithm = 1.0) const;

  std::size_t GetFeatureCount() const { return 1 + FeaturesPerAlgorithm * this->Count; }
  /**
   * x (GetFeatureCount() values) of a frame from its load per algorithm
   * (AlgorithmCount values each): time = weights . x in the additive form.
   */
  void GetFeatures(const double* drawCalls, const double* triangles, const double* vertices,
    const double* pixels, double* x) const;
  void GetFeatureWeights(double* w) const;
  /// Fitted weights back; negative or non-finite ones become 0 (a fit, not a caller's error).
  void SetFeatureWeights(const double* w);

private:
  std::array<RenderingAlgorithm, RenderingAlgorithmCount> Algorithms{};
  std::array<Coefficients, RenderingAlgorithmCount> Coeffs{};
  std::size_t Count = 0;
  double Frame = 0.0;
  FrameCostModel::PixelMode Mode = FrameCostModel::PixelMode::Overlapped;
};
}

#endif
