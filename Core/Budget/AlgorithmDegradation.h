// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_AlgorithmDegradation_h
#define timecritical_AlgorithmDegradation_h

#include "RenderingAlgorithm.h"
#include "TimeCriticalBudgetCoreExport.h"

#include <array>
#include <cstddef>

namespace timecritical
{
/**
 * The degradation of an object tuple (O, L, R), per rendering algorithm, in
 * the form TupleProblem takes (D = c / alpha min(r, hi)^-alpha + E), in two
 * families:
 *
 * - Funkhouser: Funkhouser & Séquin's accuracy factor,
 *     Accuracy = 1 - BaseError / Samples(L, R)^m,
 *   Samples = triangles (flat) or vertices (Gouraud) at the resolution, never
 *   more than the covered pixels; the degradation is what the benefit
 *   Size * Interest * Accuracy loses: D = Interest Npix BaseError (S r)^-m,
 *   i.e. alpha = m, c = m Interest Npix BaseError / S^m, hi = Npix / S.
 *   Defaults: flat (triangles, m = 1, 0.5) and per-vertex lit (vertices,
 *   m = 2, 0.5) are the paper's; per-fragment lit (vertices, m = 2, 0.25:
 *   normals rather than colours interpolated, half the error) and unlit
 *   (triangles, m = 1, 1.0: no lighting, twice flat's error) are this
 *   project's choice. Each can be set.
 * - Measured: the geometric degradation of DegradationModel (the caller's
 *   c_i and alpha, the same for every algorithm) plus Interest Npix times a
 *   measured image error per algorithm (the mean error of its image against
 *   the ideal one, a fraction in [0, 1], from calibration renders), the
 *   table set with SetMeasuredError(). Every algorithm used must have one.
 *
 * Below the coarsest mesh (both families): a bounding-box outline loses
 * Interest Npix BoxError (default 0.9: it shows where the object is, not
 * what), an object not drawn loses Interest Npix (accuracy 0, benefit 0).
 * Bad settings (negative, NaN, out of range, an algorithm without its
 * measured error) throw std::invalid_argument.
 */
class TIMECRITICALBUDGETCORE_EXPORT AlgorithmDegradation
{
public:
  enum class Family
  {
    Funkhouser, ///< 1 - BaseError / Samples^m per algorithm
    Measured    ///< geometric degradation + measured image error per algorithm
  };
  enum class SampleKind
  {
    Triangles,
    Vertices
  };
  /// Funkhouser's accuracy of one algorithm: 1 - BaseError / Samples^Exponent.
  struct Accuracy
  {
    SampleKind Samples = SampleKind::Vertices;
    double Exponent = 2.0;  ///< m > 0
    double BaseError = 0.5; ///< in (0, 1]
  };
  /// What the renderer knows of one object.
  struct ObjectInput
  {
    double Interest = 1.0;        ///< w_v w_e w_s (DegradationModel::InterestWeight)
    double Pixels = 0.0;          ///< Npix
    double MaxTriangles = 0.0;    ///< Nmaxtri
    double MaxVertices = 0.0;     ///< Nmaxvert; 0: Nmaxtri / 2
    double GeometricWeight = 0.0; ///< c_i of DegradationModel (Measured family)
  };

  explicit AlgorithmDegradation(Family family = Family::Funkhouser);

  void SetFamily(Family family) { this->Kind = family; }
  Family GetFamily() const { return this->Kind; }

  static Accuracy DefaultAccuracy(RenderingAlgorithm algorithm);
  void SetAccuracy(RenderingAlgorithm algorithm, const Accuracy& accuracy);
  const Accuracy& GetAccuracy(RenderingAlgorithm algorithm) const;

  /// The measured table (Measured family): error in [0, 1].
  void SetMeasuredError(RenderingAlgorithm algorithm, double error);
  bool HasMeasuredError(RenderingAlgorithm algorithm) const;
  /// alpha of the geometric degradation (Measured family), as DegradationModel::GetAlpha().
  void SetGeometricAlpha(double alpha);
  double GetGeometricAlpha() const { return this->GeometricAlpha; }
  /// Fraction of an object's benefit a bounding-box outline loses, in [0, 1].
  void SetBoxError(double error);
  double GetBoxError() const { return this->BoxError; }

  /// Funkhouser's accuracy of an object drawn with the algorithm at resolution r.
  double FunkhouserAccuracy(RenderingAlgorithm algorithm, const ObjectInput& object, double r) const;

  /**
   * The degradation arrays of a TupleProblem for n objects and the
   * algorithms (count of them, in the order of the problem's tuples): alpha
   * (count values), weight, offset and maxResolution (n x count each,
   * row-major), box and drop degradations (n each; either may be null).
   */
  void Evaluate(std::size_t n, const ObjectInput* objects, const RenderingAlgorithm* algorithms,
    std::size_t count, double* alpha, double* weight, double* offset, double* maxResolution,
    double* boxDegradation, double* dropDegradation) const;

private:
  static std::size_t Index(RenderingAlgorithm algorithm);

  Family Kind = Family::Funkhouser;
  std::array<Accuracy, RenderingAlgorithmCount> Accuracies{};
  std::array<double, RenderingAlgorithmCount> Measured{};
  std::array<bool, RenderingAlgorithmCount> MeasuredSet{};
  double GeometricAlpha = 1.0;
  double BoxError = 0.9;
};
}

#endif
