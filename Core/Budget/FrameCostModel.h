// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_FrameCostModel_h
#define timecritical_FrameCostModel_h

#include "TimeCriticalBudgetCoreExport.h"

#include <cstddef>

namespace timecritical
{
/**
 * Frame time prediction of Gobbetti & Bouvier section 4.1 (eq. 2-4), extended
 * for the platforms this project runs on.
 *
 * Paper: t_object = t_setup + max(t_tri r Nmaxtri, t_pix Npix) (eq. 2), which
 * gives rmin = t_pix Npix / (t_tri Nmaxtri) (eq. 3) and the linear model
 * cost(r) = t_fixed + tmax^T r, rmin <= r <= 1 (eq. 4).
 *
 * Extensions:
 * - a per-draw-call term: with a software rasterizer (Mesa llvmpipe) a draw
 *   call costs far more than an object's setup, and a multiresolution mapper
 *   draws many objects in one call, so the per-object setup is optional (0 by
 *   default) and the draw calls are counted separately;
 * - PixelMode::Additive: a software rasterizer does not overlap geometry and
 *   fill the way a hardware pipeline does, so the fill time adds to the
 *   triangle time; it then is resolution-independent and goes to t_fixed, and
 *   rmin is only the coarsest resolution the mesh can give;
 * - the cost of ordinary (non-multiresolution) actors drawn in the same frame,
 *   and a safety margin (the paper's "worst case estimate of the impact of the
 *   system", section 4.1), both part of t_fixed.
 * Times are in seconds.
 */
class TIMECRITICALBUDGETCORE_EXPORT FrameCostModel
{
public:
  enum class PixelMode
  {
    Overlapped, ///< eq. 2: the slower of geometry and fill (pipelined hardware)
    Additive    ///< geometry + fill (software rasterizer)
  };

  struct Coefficients
  {
    double Frame = 0.0;    ///< t_init + t_final per frame (clears, swap)
    double DrawCall = 0.0; ///< per draw call (state validation, shader setup)
    double Object = 0.0;   ///< t_setup per object (eq. 2), 0 when objects share draw calls
    double Triangle = 0.0; ///< t_tri per triangle
    double Pixel = 0.0;    ///< t_pix per covered pixel
    double Margin = 0.0;   ///< allowance for the system, added to t_fixed
  };

  /// What a frame contains besides the multiresolution objects' triangles.
  struct FrameLoad
  {
    double DrawCalls = 0.0;      ///< all draw calls, multiresolution and ordinary
    double Objects = 0.0;        ///< multiresolution objects drawn (t_setup each)
    double OtherTriangles = 0.0; ///< triangles of ordinary actors
    double OtherPixels = 0.0;    ///< pixels covered by ordinary actors
    double OtherTime = 0.0;      ///< any further time known to be spent (e.g. measured)
  };

  /// Features of a frame for CostModelCalibrator, in the order of the coefficients.
  enum Feature : std::size_t
  {
    FeatureFrame = 0,
    FeatureDrawCalls,
    FeatureObjects,
    FeatureTriangles,
    FeaturePixels,
    FeatureCount
  };

  static constexpr double TinyResolution = 1e-6;

  FrameCostModel() = default;
  explicit FrameCostModel(const Coefficients& coefficients, PixelMode mode = PixelMode::Overlapped);

  /// Coefficients, each raised to its minimum (see SetMinimumCoefficients).
  void SetCoefficients(const Coefficients& coefficients);
  const Coefficients& GetCoefficients() const { return this->Coeffs; }

  /**
   * Lower bounds of the coefficients (default all 0: the model as given).
   * A model fitted to measured frames can trade one term for another when
   * features move together (a time-critical renderer keeps the frame time
   * constant by trading triangles against fill), down to a triangle that
   * costs nothing; with positive bounds every object with triangles has a
   * positive tmax and every frame a positive time. The current coefficients
   * are raised to the new bounds; Margin has none.
   */
  void SetMinimumCoefficients(const Coefficients& minimum);
  const Coefficients& GetMinimumCoefficients() const { return this->Minimum; }

  /**
   * Bounds no hardware beats, for SetMinimumCoefficients(): 10 us per frame
   * (clear and swap), 0.1 us per draw call, 10 ps per triangle (100 G/s) and
   * 1 ps per pixel (1 T/s), no per-object term. They keep predictions
   * positive; a bound relative to a calibration on the machine is what keeps
   * a fit from collapsing in practice.
   */
  static Coefficients PhysicalMinimum();
  void SetPixelMode(PixelMode mode) { this->Mode = mode; }
  PixelMode GetPixelMode() const { return this->Mode; }

  /// eq. 2 for one object at resolution r (including its t_setup).
  double ObjectCost(double maxTriangles, double pixels, double r) const;

  /// tmax = t_tri Nmaxtri (eq. 4).
  double MaxTime(double maxTriangles) const;

  /**
   * eq. 3, clamped to [max(TinyResolution, coarsest), 1]: reducing an object
   * below it saves no time (fill-bound), and a mesh cannot go below its
   * coarsest resolution. 1 when triangles cost nothing.
   */
  double MinimumResolution(double maxTriangles, double pixels, double coarsest) const;

  /**
   * t_fixed of eq. 4 plus the extensions: frame, draw calls, per-object setup,
   * margin, ordinary actors, and in Additive mode the fill of the
   * multiresolution objects (totalPixels = sum of their Npix).
   */
  double FixedTime(const FrameLoad& load, double totalPixels) const;

  /// Per-object tmax and rmin (coarsest may be null: no coarsest resolution).
  void Evaluate(std::size_t n, const double* maxTriangles, const double* pixels,
    const double* coarsest, double* maxTime, double* minResolution) const;

  /// Predicted frame time with the exact (non-linearized) per-object terms.
  double PredictFrameTime(const FrameLoad& load, std::size_t n, const double* maxTriangles,
    const double* pixels, const double* r) const;

  /// Calibration features x of a frame: cost = coefficients . x (additive form).
  void GetFeatures(const FrameLoad& load, double triangles, double pixels, double* x) const;

  /// Coefficients as a FeatureCount vector (Margin excluded) and back.
  void GetFeatureWeights(double* w) const;
  void SetFeatureWeights(const double* w);

private:
  Coefficients Coeffs;
  Coefficients Minimum;
  PixelMode Mode = PixelMode::Overlapped;
};
}

#endif
