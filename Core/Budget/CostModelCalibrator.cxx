// SPDX-License-Identifier: BSD-3-Clause
#include "CostModelCalibrator.h"

#include <algorithm>
#include <limits>
#include <cmath>
#include <vector>

namespace timecritical
{
namespace
{
constexpr std::size_t MaxD = CostModelCalibrator::MaxFeatures;
using Matrix = std::array<double, MaxD * MaxD>;
using Vector = std::array<double, MaxD>;

/// Solve the m x m system a x = b (row-major, stride MaxD) in place by Gaussian
/// elimination with partial pivoting; near-singular pivots get a tiny ridge.
void SolveDense(Matrix a, Vector b, std::size_t m, double* x)
{
  double scale = 0.0;
  for (std::size_t i = 0; i < m; ++i)
  {
    scale = std::max(scale, std::abs(a[i * MaxD + i]));
  }
  const double tiny = std::max(scale, 1e-300) * 1e-13;
  for (std::size_t k = 0; k < m; ++k)
  {
    std::size_t pivot = k;
    for (std::size_t i = k + 1; i < m; ++i)
    {
      if (std::abs(a[i * MaxD + k]) > std::abs(a[pivot * MaxD + k]))
      {
        pivot = i;
      }
    }
    if (pivot != k)
    {
      for (std::size_t j = 0; j < m; ++j)
      {
        std::swap(a[k * MaxD + j], a[pivot * MaxD + j]);
      }
      std::swap(b[k], b[pivot]);
    }
    if (std::abs(a[k * MaxD + k]) < tiny)
    {
      a[k * MaxD + k] = a[k * MaxD + k] < 0.0 ? -tiny : tiny;
    }
    for (std::size_t i = k + 1; i < m; ++i)
    {
      const double f = a[i * MaxD + k] / a[k * MaxD + k];
      for (std::size_t j = k; j < m; ++j)
      {
        a[i * MaxD + j] -= f * a[k * MaxD + j];
      }
      b[i] -= f * b[k];
    }
  }
  for (std::size_t k = m; k-- > 0;)
  {
    double s = b[k];
    for (std::size_t j = k + 1; j < m; ++j)
    {
      s -= a[k * MaxD + j] * x[j];
    }
    x[k] = s / a[k * MaxD + k];
  }
}

/// Lawson-Hanson non-negative least squares on the normal equations g x = h.
void SolveNonNegative(const Matrix& g, const Vector& h, std::size_t d, double* x)
{
  std::array<bool, MaxD> passive{};
  std::fill(x, x + d, 0.0);
  double hMax = 0.0;
  for (std::size_t j = 0; j < d; ++j)
  {
    hMax = std::max(hMax, std::abs(h[j]));
  }
  const double tolerance = 1e-12 * std::max(hMax, 1e-300);
  auto solvePassive = [&](double* z) {
    std::array<std::size_t, MaxD> index{};
    std::size_t m = 0;
    for (std::size_t j = 0; j < d; ++j)
    {
      z[j] = 0.0;
      if (passive[j])
      {
        index[m++] = j;
      }
    }
    Matrix a{};
    Vector b{};
    for (std::size_t i = 0; i < m; ++i)
    {
      for (std::size_t j = 0; j < m; ++j)
      {
        a[i * MaxD + j] = g[index[i] * MaxD + index[j]];
      }
      b[i] = h[index[i]];
    }
    Vector s{};
    SolveDense(a, b, m, s.data());
    for (std::size_t i = 0; i < m; ++i)
    {
      z[index[i]] = s[i];
    }
  };
  for (std::size_t outer = 0; outer < 3 * d + 3; ++outer)
  {
    std::size_t best = d;
    double bestGradient = tolerance;
    for (std::size_t j = 0; j < d; ++j)
    {
      double w = h[j];
      for (std::size_t k = 0; k < d; ++k)
      {
        w -= g[j * MaxD + k] * x[k];
      }
      if (!passive[j] && w > bestGradient)
      {
        best = j;
        bestGradient = w;
      }
    }
    if (best == d)
    {
      break;
    }
    passive[best] = true;
    for (std::size_t inner = 0; inner < 3 * d + 3; ++inner)
    {
      Vector z{};
      solvePassive(z.data());
      bool positive = true;
      double step = 1.0;
      for (std::size_t j = 0; j < d; ++j)
      {
        if (passive[j] && z[j] <= 0.0)
        {
          positive = false;
          const double denominator = x[j] - z[j];
          if (denominator > 0.0)
          {
            step = std::min(step, x[j] / denominator);
          }
          else
          {
            step = 0.0;
          }
        }
      }
      if (positive)
      {
        std::copy(z.begin(), z.begin() + d, x);
        break;
      }
      for (std::size_t j = 0; j < d; ++j)
      {
        x[j] += step * (z[j] - x[j]);
        if (passive[j] && (x[j] <= 1e-15 * std::abs(z[j]) || z[j] <= 0.0) && x[j] <= 0.0 + 1e-300)
        {
          passive[j] = false;
          x[j] = 0.0;
        }
      }
      // Numerical safety: drop passive variables that reached zero.
      for (std::size_t j = 0; j < d; ++j)
      {
        if (passive[j] && x[j] <= 0.0)
        {
          passive[j] = false;
          x[j] = 0.0;
        }
      }
    }
  }
  for (std::size_t j = 0; j < d; ++j)
  {
    x[j] = std::isfinite(x[j]) && x[j] > 0.0 ? x[j] : 0.0;
  }
}

/// min x'gx - 2h'x subject to x >= lower (lower may be null: 0): the
/// non-negative problem in u = x - lower, whose linear term is h - g lower.
void SolveBounded(const Matrix& g, Vector h, std::size_t d, const double* lower, double* x)
{
  if (lower)
  {
    for (std::size_t i = 0; i < d; ++i)
    {
      for (std::size_t j = 0; j < d; ++j)
      {
        h[i] -= g[i * MaxD + j] * lower[j];
      }
    }
  }
  SolveNonNegative(g, h, d, x);
  if (lower)
  {
    for (std::size_t j = 0; j < d; ++j)
    {
      x[j] += lower[j];
    }
  }
}

double MedianOf(std::vector<double>& values)
{
  if (values.empty())
  {
    return 0.0;
  }
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

bool FiniteRow(const double* x, std::size_t d)
{
  for (std::size_t j = 0; j < d; ++j)
  {
    if (!std::isfinite(x[j]))
    {
      return false;
    }
  }
  return true;
}

/// The robust batch fit; also returns the feature scales and the final
/// weighted normal matrix of the scaled features (for the online state).
bool Fit(const double* x, const double* times, std::size_t samples, std::size_t d,
  const CostModelCalibrator::Options& options, const double* lower, double* theta, double* scales,
  Matrix* normal, double* residualScale)
{
  std::vector<std::size_t> rows;
  for (std::size_t s = 0; s < samples; ++s)
  {
    if (FiniteRow(x + s * d, d) && std::isfinite(times[s]) && times[s] > 0.0)
    {
      rows.push_back(s);
    }
  }
  std::fill(theta, theta + d, 0.0);
  for (std::size_t j = 0; j < d; ++j)
  {
    scales[j] = 0.0;
    for (std::size_t s : rows)
    {
      scales[j] = std::max(scales[j], std::abs(x[s * d + j]));
    }
    scales[j] = scales[j] > 0.0 ? scales[j] : 1.0;
  }
  if (rows.empty())
  {
    return false;
  }
  Vector scaledLower{};
  for (std::size_t j = 0; j < d; ++j)
  {
    scaledLower[j] = lower ? lower[j] * scales[j] : 0.0;
  }
  std::vector<double> weight(rows.size(), 1.0), residual(rows.size());
  std::vector<double> scratch;
  std::vector<double> timesCopy;
  for (std::size_t s : rows)
  {
    timesCopy.push_back(times[s]);
  }
  const double floor = std::max(options.MinimumScale,
    options.RelativeMinimumScale * MedianOf(timesCopy));
  Vector current{};
  double sigma = 0.0;
  Matrix g{};
  for (int iteration = 0; iteration < 50; ++iteration)
  {
    g.fill(0.0);
    Vector h{};
    for (std::size_t k = 0; k < rows.size(); ++k)
    {
      const double* row = x + rows[k] * d;
      for (std::size_t i = 0; i < d; ++i)
      {
        const double zi = row[i] / scales[i];
        h[i] += weight[k] * zi * times[rows[k]];
        for (std::size_t j = 0; j < d; ++j)
        {
          g[i * MaxD + j] += weight[k] * zi * row[j] / scales[j];
        }
      }
    }
    Vector next{};
    SolveBounded(g, h, d, scaledLower.data(), next.data());
    scratch.clear();
    for (std::size_t k = 0; k < rows.size(); ++k)
    {
      const double* row = x + rows[k] * d;
      double prediction = 0.0;
      for (std::size_t j = 0; j < d; ++j)
      {
        prediction += next[j] * row[j] / scales[j];
      }
      residual[k] = times[rows[k]] - prediction;
      scratch.push_back(std::abs(residual[k]));
    }
    sigma = std::max(floor, 1.4826 * MedianOf(scratch));
    for (std::size_t k = 0; k < rows.size(); ++k)
    {
      const double u = std::abs(residual[k]) / sigma;
      weight[k] = u > options.RejectThreshold
        ? 0.0
        : (u > options.OutlierThreshold ? options.OutlierThreshold / u : 1.0);
    }
    double change = 0.0, size = 0.0;
    for (std::size_t j = 0; j < d; ++j)
    {
      change = std::max(change, std::abs(next[j] - current[j]));
      size = std::max(size, std::abs(next[j]));
    }
    current = next;
    if (iteration > 0 && change <= 1e-10 * std::max(size, 1e-300))
    {
      break;
    }
  }
  for (std::size_t j = 0; j < d; ++j)
  {
    theta[j] = current[j] / scales[j];
  }
  if (normal)
  {
    *normal = g;
  }
  if (residualScale)
  {
    *residualScale = sigma;
  }
  return true;
}
}

namespace
{
double MedianOfFixed(const double* values, std::size_t count)
{
  std::array<double, 32> copy{};
  count = std::min<std::size_t>(count, copy.size());
  std::copy(values, values + count, copy.begin());
  const auto middle = copy.begin() + static_cast<std::ptrdiff_t>(count / 2);
  std::nth_element(copy.begin(), middle, copy.begin() + static_cast<std::ptrdiff_t>(count));
  return count > 0 ? *middle : 0.0;
}
}

CostModelCalibrator::CostModelCalibrator(
  std::size_t featureCount, const Options& options, const double* scales)
  : D(std::min(MaxFeatures, std::max<std::size_t>(1, featureCount)))
  , Opts(options)
{
  for (std::size_t j = 0; j < this->D; ++j)
  {
    const double s = scales ? std::abs(scales[j]) : 0.0;
    this->FeatureScale[j] = std::isfinite(s) && s > 0.0 ? s : 0.0; // 0: set by the first sample
  }
  this->Reset(this->Opts.PriorWeight);
}

void CostModelCalibrator::Reset(double priorWeight)
{
  // R = eps I, b = eps prior: the minimizer is the prior until data arrive.
  const double eps = priorWeight > 0.0 && std::isfinite(priorWeight) ? priorWeight : 1e-3;
  Estimator& e = this->Main;
  e.Prior = e.Theta;
  e.R.fill(0.0);
  e.B.fill(0.0);
  for (std::size_t j = 0; j < this->D; ++j)
  {
    e.R[j * MaxD + j] = eps;
    e.B[j] = eps * e.Prior[j];
  }
}

double CostModelCalibrator::Weight(double residual) const
{
  if (this->Main.Count < 5)
  {
    return 1.0;
  }
  const double floor =
    std::max(this->Opts.MinimumScale, this->Opts.RelativeMinimumScale * this->MeanTime);
  const double u = std::abs(residual) / std::max(this->Main.Scale, floor);
  return u > this->Opts.RejectThreshold
    ? 0.0
    : (u > this->Opts.OutlierThreshold ? this->Opts.OutlierThreshold / u : 1.0);
}

void CostModelCalibrator::Push(double residual)
{
  Estimator& e = this->Main;
  e.Residuals[e.Next] = std::abs(residual);
  e.Next = (e.Next + 1) % MaxWindow;
  e.Count = std::min(MaxWindow, e.Count + 1);
  e.Scale = 1.4826 * MedianOfFixed(e.Residuals.data(), e.Count);
}

void CostModelCalibrator::Accumulate(const double* z, double time, double weight)
{
  // Information-form RLS with forgetting and a constant ridge to the prior.
  Estimator& e = this->Main;
  const double lambda =
    this->Opts.Forgetting > 0.0 && this->Opts.Forgetting <= 1.0 ? this->Opts.Forgetting : 0.98;
  const double eps = this->Opts.PriorWeight > 0.0 ? this->Opts.PriorWeight : 1e-3;
  const double ridge = (1.0 - lambda) * eps;
  for (std::size_t i = 0; i < this->D; ++i)
  {
    for (std::size_t j = 0; j < this->D; ++j)
    {
      e.R[i * MaxD + j] = lambda * e.R[i * MaxD + j] + weight * z[i] * z[j];
    }
    e.R[i * MaxD + i] += ridge;
    e.B[i] = lambda * e.B[i] + weight * z[i] * time + ridge * e.Prior[i];
  }
}

void CostModelCalibrator::Solve()
{
  Estimator& e = this->Main;
  Matrix g{};
  Vector h{};
  bool finite = true;
  for (std::size_t i = 0; i < this->D; ++i)
  {
    h[i] = e.B[i];
    finite = finite && std::isfinite(h[i]);
    for (std::size_t j = 0; j < this->D; ++j)
    {
      g[i * MaxD + j] = 0.5 * (e.R[i * MaxD + j] + e.R[j * MaxD + i]);
      finite = finite && std::isfinite(g[i * MaxD + j]);
    }
  }
  if (!finite)
  {
    this->Reset(this->Opts.PriorWeight); // keeps Theta as the prior
    return;
  }
  Vector theta{}, lower{};
  for (std::size_t j = 0; j < this->D; ++j)
  {
    lower[j] = this->Lower[j] * (this->FeatureScale[j] > 0.0 ? this->FeatureScale[j] : 1.0);
  }
  SolveBounded(g, h, this->D, lower.data(), theta.data());
  std::copy(theta.begin(), theta.begin() + static_cast<std::ptrdiff_t>(this->D), e.Theta.begin());
}

void CostModelCalibrator::Rescale(const double* x)
{
  // A feature seen for the first time takes its magnitude as scale (its
  // prior was given with scale 1); one that grows past 4x its scale is
  // rescaled: z_j -> z_j / q, theta_j q, R_jk / (q_j q_k), b_j / q_j.
  Estimator& e = this->Main;
  for (std::size_t j = 0; j < this->D; ++j)
  {
    const double a = std::abs(x[j]);
    double& s = this->FeatureScale[j];
    if (!(a > 0.0) || (s > 0.0 && a <= 4.0 * s))
    {
      continue;
    }
    const double q = s > 0.0 ? a / s : a;
    e.Theta[j] *= q;
    e.Prior[j] *= q;
    for (std::size_t k = 0; k < this->D; ++k)
    {
      e.R[j * MaxD + k] /= q;
      e.R[k * MaxD + j] /= q;
    }
    e.B[j] /= q;
    s = a;
  }
}

void CostModelCalibrator::SetCoefficients(const double* theta, double frames)
{
  for (std::size_t j = 0; j < this->D; ++j)
  {
    const double t =
      std::max(this->Lower[j], std::isfinite(theta[j]) && theta[j] > 0.0 ? theta[j] : 0.0);
    this->Main.Theta[j] = t * (this->FeatureScale[j] > 0.0 ? this->FeatureScale[j] : 1.0);
  }
  // The extra weight decays with the forgetting factor like frames' worth of
  // data; only PriorWeight stays as the constant ridge.
  const double extra = std::isfinite(frames) && frames > 0.0 ? frames : 0.0;
  this->Reset(this->Opts.PriorWeight + extra);
}

void CostModelCalibrator::SetLowerBounds(const double* lower)
{
  for (std::size_t j = 0; j < this->D; ++j)
  {
    const double b = lower ? lower[j] : 0.0;
    this->Lower[j] = std::isfinite(b) && b > 0.0 ? b : 0.0;
    // Raise the estimate and the prior; the information stays (the next
    // solve honours the bound).
    const double scale = this->FeatureScale[j] > 0.0 ? this->FeatureScale[j] : 1.0;
    this->Main.Theta[j] = std::max(this->Main.Theta[j], this->Lower[j] * scale);
    this->Main.Prior[j] = std::max(this->Main.Prior[j], this->Lower[j] * scale);
  }
}

double CostModelCalibrator::GetLowerBound(std::size_t j) const
{
  return j < this->D ? this->Lower[j] : 0.0;
}

double CostModelCalibrator::GetCoefficient(std::size_t j) const
{
  if (j >= this->D)
  {
    return 0.0;
  }
  return this->Main.Theta[j] / (this->FeatureScale[j] > 0.0 ? this->FeatureScale[j] : 1.0);
}

void CostModelCalibrator::GetCoefficients(double* theta) const
{
  for (std::size_t j = 0; j < this->D; ++j)
  {
    theta[j] = this->GetCoefficient(j);
  }
}

double CostModelCalibrator::Predict(const double* x) const
{
  double y = 0.0;
  for (std::size_t j = 0; j < this->D; ++j)
  {
    y += this->GetCoefficient(j) * x[j];
  }
  return y;
}

bool CostModelCalibrator::Update(const double* x, double time)
{
  if (!x || !FiniteRow(x, this->D) || !std::isfinite(time) || !(time > 0.0))
  {
    ++this->Stats.Invalid;
    return false;
  }
  for (std::size_t j = 0; j < this->D; ++j)
  {
    if (std::abs(x[j]) > 1e150) // z z' would overflow
    {
      ++this->Stats.Invalid;
      return false;
    }
  }
  this->Rescale(x);
  std::array<double, MaxD> z{};
  double prediction = 0.0;
  for (std::size_t j = 0; j < this->D; ++j)
  {
    z[j] = this->FeatureScale[j] > 0.0 ? x[j] / this->FeatureScale[j] : 0.0;
    prediction += this->Main.Theta[j] * z[j];
  }
  ++this->Samples;
  this->MeanTime = this->Samples == 1 ? time : 0.95 * this->MeanTime + 0.05 * time;
  const double residual = time - prediction;
  const double weight = this->Weight(residual);

  const std::size_t window = static_cast<std::size_t>(
    std::max(1, std::min(static_cast<int>(MaxFrames), this->Opts.ChangeWindow)));
  const std::size_t at = this->FrameNext;
  std::copy(x, x + this->D, this->FrameFeatures[at].begin());
  this->FrameTimes[at] = time;
  this->FrameSide[at] = weight > 0.0 ? 0 : (residual > 0.0 ? 1 : -1);
  this->FrameNext = (this->FrameNext + 1) % window;
  this->FrameCount = std::min(window, this->FrameCount + 1);

  if (weight == 0.0)
  {
    // The recent block of rejected frames (either side: a poor model of a
    // new regime errs both ways), newest first, with at most one exception:
    // frames of the old regime are not in it.
    int same = 0, other = 0;
    const std::size_t scan = std::min(this->FrameCount, window);
    for (std::size_t age = 0; age < scan; ++age)
    {
      const std::size_t k = (at + window - age) % window;
      if (this->FrameSide[k] != 0)
      {
        ++same;
      }
      else if (++other > 1)
      {
        break;
      }
    }
    if (same >= std::max(static_cast<int>(this->D) + 1, this->Opts.ChangeCount) && this->Refit())
    {
      ++this->Stats.Changes;
      ++this->Stats.Accepted;
      return true;
    }
    ++this->Stats.Rejected;
    return false;
  }
  // The scale only counts frames that are used, so a change of regime keeps
  // being rejected (and detected) rather than slowly absorbed.
  this->Push(residual);
  (weight < 1.0 ? this->Stats.DownWeighted : this->Stats.Accepted)++;
  this->Accumulate(z.data(), time, weight);
  this->Solve();
  return true;
}

bool CostModelCalibrator::Refit()
{
  const Estimator saved = this->Main;
  // Most recent frames are off on the same side: the hardware changed. Fit
  // the new regime on those frames alone by Huber IRLS (a spike may be
  // among them), with the old coefficients as a weak prior, and make that
  // fit the new information (oldest frame first, so forgetting applies).
  std::array<std::size_t, MaxFrames> rows{};
  std::size_t m = 0;
  const std::size_t window = this->FrameCount;
  const std::size_t newest = (this->FrameNext + window - 1) % window;
  int other = 0;
  for (std::size_t age = 0; age < window; ++age) // the block that triggered, newest first
  {
    const std::size_t k = (newest + window - age) % window;
    if (this->FrameSide[k] == 0 && ++other > 1)
    {
      break;
    }
    rows[m++] = k;
  }
  std::reverse(rows.begin(), rows.begin() + static_cast<std::ptrdiff_t>(m)); // oldest first
  std::array<std::array<double, MaxFeatures>, MaxFrames> z{};
  for (std::size_t r = 0; r < m; ++r)
  {
    for (std::size_t j = 0; j < this->D; ++j)
    {
      const double s = this->FeatureScale[j];
      z[r][j] = s > 0.0 ? this->FrameFeatures[rows[r]][j] / s : 0.0;
    }
  }
  const double floor =
    std::max(this->Opts.MinimumScale, this->Opts.RelativeMinimumScale * this->MeanTime);
  std::array<double, MaxFrames> weight{}, residual{};
  auto fit = [&]() {
    this->Reset(this->Opts.PriorWeight);
    for (std::size_t r = 0; r < m; ++r)
    {
      if (weight[r] > 0.0)
      {
        this->Accumulate(z[r].data(), this->FrameTimes[rows[r]], weight[r]);
      }
    }
    this->Solve();
  };
  auto residuals = [&]() {
    for (std::size_t r = 0; r < m; ++r)
    {
      double fitted = 0.0;
      for (std::size_t j = 0; j < this->D; ++j)
      {
        fitted += this->Main.Theta[j] * z[r][j];
      }
      residual[r] = std::abs(this->FrameTimes[rows[r]] - fitted);
    }
  };
  // 1. Least absolute deviations (IRLS with weights 1 / |residual|): convex,
  //    so no local minima, and insensitive to how far off a spike is.
  std::fill(weight.begin(), weight.begin() + static_cast<std::ptrdiff_t>(m), 1.0);
  fit();
  // Smoothing delta shrinks from the residual scale (continuation), else the
  // first frames fitted exactly get huge weights and lock the fit.
  residuals();
  double delta = std::max(floor, 1.4826 * MedianOfFixed(residual.data(), m));
  for (int iteration = 0; iteration < 40; ++iteration)
  {
    for (std::size_t r = 0; r < m; ++r)
    {
      weight[r] = 1.0 / std::max(residual[r], delta);
    }
    fit();
    residuals();
    delta = std::max(0.1 * floor, 0.7 * delta);
  }
  // 2. Huber IRLS from there, with the scale of the LAD residuals.
  double sigma = floor;
  for (int iteration = 0; iteration < 10; ++iteration)
  {
    residuals();
    if (iteration == 0)
    {
      sigma = std::max(floor, 1.4826 * MedianOfFixed(residual.data(), m));
    }
    bool changed = false;
    for (std::size_t r = 0; r < m; ++r)
    {
      const double u = residual[r] / sigma;
      const double w = u > this->Opts.RejectThreshold
        ? 0.0
        : (u > this->Opts.OutlierThreshold ? this->Opts.OutlierThreshold / u : 1.0);
      changed = changed || std::abs(w - weight[r]) > 1e-6;
      weight[r] = w;
    }
    if (!changed)
    {
      break;
    }
    fit();
  }
  residuals();
  // Too many frames disagree with the fit (spikes by bad luck, or frames of
  // the old regime): keep the old state and retry on the next frame, when
  // the block holds one more frame of the new regime.
  // Judged against the old regime's relative noise (a poor fit's own scale
  // is inflated and would excuse it).
  const double relativeNoise = std::max(0.01,
    saved.Scale / std::max(this->MeanTime, std::numeric_limits<double>::min()));
  std::size_t consistent = 0;
  for (std::size_t r = 0; r < m; ++r)
  {
    consistent += residual[r] <= 4.0 * relativeNoise * this->FrameTimes[rows[r]] ? 1 : 0;
  }
  if (4 * consistent < 3 * m && m < static_cast<std::size_t>(this->Opts.ChangeWindow))
  {
    this->Main = saved;
    return false;
  }
  // New residual scale: the fit's, over the frames it used.
  std::array<double, MaxFrames> times{};
  for (std::size_t r = 0; r < m; ++r)
  {
    times[r] = this->FrameTimes[rows[r]];
  }
  this->MeanTime = MedianOfFixed(times.data(), m);
  this->Main.Count = 0;
  this->Main.Next = 0;
  for (std::size_t r = 0; r < m; ++r)
  {
    if (weight[r] > 0.0)
    {
      this->Push(residual[r]);
    }
  }
  std::fill(this->FrameSide.begin(), this->FrameSide.end(), 0);
  return true;
}

bool CostModelCalibrator::FitBatch(const double* x, const double* times, std::size_t samples,
  std::size_t featureCount, double* theta, const Options& options, double* residualScale,
  const double* lower)
{
  if (featureCount == 0 || featureCount > MaxFeatures || !x || !times || !theta)
  {
    return false;
  }
  std::array<double, MaxFeatures> scales{}, bounds{};
  for (std::size_t j = 0; j < featureCount; ++j)
  {
    const double b = lower ? lower[j] : 0.0;
    bounds[j] = std::isfinite(b) && b > 0.0 ? b : 0.0;
  }
  return Fit(x, times, samples, featureCount, options, bounds.data(), theta, scales.data(), nullptr,
    residualScale);
}

bool CostModelCalibrator::Calibrate(const double* x, const double* times, std::size_t samples)
{
  std::array<double, MaxFeatures> theta{}, scales{};
  Matrix normal{};
  double sigma = 0.0;
  if (!x || !times ||
    !Fit(x, times, samples, this->D, this->Opts, this->Lower.data(), theta.data(), scales.data(),
      &normal, &sigma))
  {
    return false;
  }
  // The fit's weighted normal equations become the information, with the fit
  // as prior: the online estimate starts exactly at the batch solution.
  const double eps = this->Opts.PriorWeight > 0.0 ? this->Opts.PriorWeight : 1e-3;
  for (std::size_t j = 0; j < this->D; ++j)
  {
    this->FeatureScale[j] = scales[j];
    this->Main.Theta[j] = this->Main.Prior[j] = theta[j] * scales[j];
  }
  for (std::size_t i = 0; i < this->D; ++i)
  {
    this->Main.B[i] = 0.0;
    for (std::size_t j = 0; j < this->D; ++j)
    {
      this->Main.R[i * MaxD + j] = normal[i * MaxD + j] + (i == j ? eps : 0.0);
      this->Main.B[i] += this->Main.R[i * MaxD + j] * this->Main.Theta[j];
    }
  }
  this->Main.Count = MaxWindow;
  this->Main.Next = 0;
  this->Main.Residuals.fill(sigma / 1.4826);
  this->Main.Scale = sigma;
  this->Samples = static_cast<long>(samples);
  this->MeanTime = 0.0;
  double count = 0.0;
  for (std::size_t s = 0; s < samples; ++s)
  {
    if (std::isfinite(times[s]) && times[s] > 0.0)
    {
      this->MeanTime += times[s];
      count += 1.0;
    }
  }
  this->MeanTime = count > 0.0 ? this->MeanTime / count : 0.0;
  return true;
}
}
