// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_DegradationModel_h
#define timecritical_DegradationModel_h

#include "TimeCriticalBudgetCoreExport.h"

#include <cstddef>

namespace timecritical
{
/**
 * Image-degradation heuristic of Gobbetti & Bouvier section 4.2 (eq. 5-10):
 *
 *   degradation_i(r) = w_v w_e w_s * w_i / alpha * r^-alpha = c_i / alpha * r^-alpha
 *
 * It turns what the renderer measures per object (projected pixel coverage,
 * apparent velocity and eccentricity, user importance, mesh size) into the c_i
 * and alpha of the optimization problem (eq. 11), shared by every
 * ResolutionPolicy so that all of them are judged by the same objective.
 *
 * - w_v, w_e: Reddy's decline of visual acuity with velocity and eccentricity
 *   in visual degrees (eq. 7), or none, or a linear focus falloff (Funkhouser &
 *   Séquin's and Yang et al.'s "focus" factor);
 * - w_s: user importance;
 * - w_i, alpha: the three families of eq. 10, or Yang, Gu & Kang's
 *   representation model, which maximizes sum importance * sqrt(Nmaxvert r):
 *   that is the alpha = -1/2 family with w_i = Npix sqrt(Nmaxvert) / 2, for
 *   which the objective equals minus their representation.
 * Pixel distances and velocities convert to visual degrees with eq. 8.
 */
class TIMECRITICALBUDGETCORE_EXPORT DegradationModel
{
public:
  enum class Family
  {
    Hitchner,            ///< [20]: w_i = Npix / Nmaxtri, alpha = 1 (the paper's experiments)
    Funkhouser,          ///< [11]: w_i = Npix / Nmaxtri^2, alpha = 2
    GobbettiBouvier1999, ///< [5]: w_i = Npix sqrt(Nmaxtri), alpha = -1/2
    YangGuKang           ///< w_i = Npix sqrt(Nmaxvert) / 2, alpha = -1/2
  };
  enum class VelocityModel
  {
    None, ///< w_v = 1
    Reddy ///< eq. 7
  };
  enum class EccentricityModel
  {
    None,  ///< w_e = 1
    Reddy, ///< eq. 7
    Linear ///< 1 - E / LinearFalloffDegrees (Funkhouser & Séquin, Yang et al. "focus")
  };

  /// Physical display for eq. 8 (defaults: a 24" 1920x1080 monitor at 60 cm).
  struct DisplayParameters
  {
    double ResolutionX = 1920.0; ///< pixels
    double ResolutionY = 1080.0;
    double SizeX = 0.531; ///< metres (any unit, as long as ViewingDistance uses the same)
    double SizeY = 0.299;
    double ViewingDistance = 0.6;
  };

  struct Config
  {
    Family WeightFamily = Family::Hitchner;
    VelocityModel Velocity = VelocityModel::Reddy;
    EccentricityModel Eccentricity = EccentricityModel::Reddy;
    double LinearFalloffDegrees = 30.0; ///< Linear: eccentricity where the factor reaches MinimumFactor
    double MinimumFactor = 0.01;        ///< floor of w_v and w_e (Reddy's w_v turns negative)
  };

  /// What the renderer measures for one object.
  struct ObjectView
  {
    double Pixels = 0.0;              ///< Npix: projected coverage
    double VelocityDegrees = 0.0;     ///< apparent velocity of the bounding-box centre (deg/s)
    double EccentricityDegrees = 0.0; ///< distance of the projected box to the focus point (deg)
    double Importance = 1.0;          ///< w_s
    double MaxTriangles = 0.0;        ///< Nmaxtri
    double MaxVertices = 0.0;         ///< Nmaxvert (Yang et al.); 0: taken as Nmaxtri / 2
  };

  DegradationModel() = default;
  explicit DegradationModel(const Config& config);

  /// Defaults of each family: Reddy's factors for eq. 10, focus only for Yang et al.
  static Config MakeConfig(Family family);

  void SetConfig(const Config& config) { this->Settings = config; }
  const Config& GetConfig() const { return this->Settings; }
  void SetDisplay(const DisplayParameters& display) { this->Display = display; }
  const DisplayParameters& GetDisplay() const { return this->Display; }

  /// alpha of the configured family.
  double GetAlpha() const;
  static double GetAlpha(Family family);

  /// eq. 8: pixels per visual degree, p = 2 d tan(0.5 deg) min(Rx / Wx, Ry / Wy).
  static double PixelsPerDegree(const DisplayParameters& display);
  /// Pixels (or pixels per second) to visual degrees (per second) on the configured display.
  double PixelsToDegrees(double pixels) const;

  /// eq. 7, velocity in deg/s (log is decimal: it makes the two branches meet at 0.825).
  static double ReddyVelocityFactor(double degreesPerSecond);
  /// eq. 7, eccentricity in degrees.
  static double ReddyEccentricityFactor(double degrees);

  double VelocityFactor(double degreesPerSecond) const;
  double EccentricityFactor(double degrees) const;

  /// w_interest = w_v w_e w_s (eq. 6).
  double InterestWeight(const ObjectView& view) const;
  /// w_i of the family (eq. 10).
  double ResolutionWeight(const ObjectView& view) const;
  /// c_i = w_interest * w_i (eq. 11); 0 for an object that covers no pixel.
  double Weight(const ObjectView& view) const;
  /// c_i for n objects.
  void Evaluate(std::size_t n, const ObjectView* views, double* weights) const;
  /// Degradation of one object at resolution r (eq. 5, 9).
  double Degradation(const ObjectView& view, double r) const;

private:
  Config Settings;
  DisplayParameters Display;
};
}

#endif
