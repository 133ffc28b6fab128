// SPDX-License-Identifier: BSD-3-Clause
#include "ActiveSetOptimizer.h"

#include <algorithm>
#include <chrono>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
// AVX2 lanes, chosen at run time, where the compiler can target them per function.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(TIMECRITICAL_NO_AVX2)
#define TIMECRITICAL_AVX2 1
#include <immintrin.h>
#endif

// The lane helpers below run per pair of objects inside O(n) loops: a call
// there costs more than the work.
#if defined(__GNUC__)
#define TIMECRITICAL_LANE_INLINE inline __attribute__((always_inline))
#else
#define TIMECRITICAL_LANE_INLINE inline
#endif

namespace timecritical
{
namespace
{
constexpr double Infinity = std::numeric_limits<double>::infinity();
/// |d_i| below this (absolute + relative to r_i) counts as d = 0 (section 5.3.3).
constexpr double StepTolerance = 1e-12;
constexpr double StepRelativeTolerance = 1e-10;
/// A bound is released only when kappa g_i is beyond it by this relative margin.
constexpr double ReleaseTolerance = 1e-10;
/// Newton rounds of one projected step (the bracket halves at worst: ~60 suffice).
constexpr int MaxNewtonRounds = 200;

double Now()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
    .count();
}

double Clamp(double x, double lo, double hi)
{
  return x < lo ? lo : (x > hi ? hi : x);
}

/// Safeguard of a search for a root of phi in (lo, hi), phi(lo) <= budget
/// < phi(hi): bisection, geometric across orders of magnitude (rooted
/// separately: kappa spans 600 decades when gamma = 10), outward without hi.
double Bisect(double lo, double hi)
{
  if (!(hi < Infinity))
  {
    return lo > 0.0 ? std::min(4.0 * lo, DBL_MAX) : 1.0;
  }
  if (!(lo > 0.0))
  {
    return 0.25 * hi;
  }
  return hi > 4.0 * lo ? std::sqrt(lo) * std::sqrt(hi) : 0.5 * (lo + hi);
}

/// Half-octave bucket of a non-negative key, from its bits (exponent and
/// mantissa >= sqrt 2): order-preserving, in [0, KeyBuckets).
constexpr int KeyBuckets = 4096;
int Bucket(double key)
{
  std::uint64_t bits = 0;
  std::memcpy(&bits, &key, sizeof(bits));
  const int exponent = static_cast<int>((bits >> 52) & 0x7ff);
  return 2 * exponent + ((bits & 0xfffffffffffffull) >= 0x6a09e667f3bcdull ? 1 : 0);
}

/// x^gamma and one term of eq. 11 for the eq. 10 exponents (Kind = 1: alpha
/// = 1, 2: alpha = 2, 3: alpha = -1/2) without pow(); Kind 0 is any alpha.
template <int Kind>
TIMECRITICAL_LANE_INLINE double PowerOf(double x, double gamma)
{
  if constexpr (Kind == 1)
  {
    (void)gamma;
    return std::sqrt(x);
  }
  else if constexpr (Kind == 2)
  {
    (void)gamma;
    return std::cbrt(x);
  }
  else if constexpr (Kind == 3)
  {
    (void)gamma;
    return x * x;
  }
  else
  {
    return std::pow(x, gamma);
  }
}

template <int Kind>
TIMECRITICAL_LANE_INLINE double TermOf(double c, double alpha, double r)
{
  if constexpr (Kind == 1)
  {
    (void)alpha;
    return c / r;
  }
  else if constexpr (Kind == 2)
  {
    (void)alpha;
    return 0.5 * c / (r * r);
  }
  else if constexpr (Kind == 3)
  {
    (void)alpha;
    return -2.0 * c * std::sqrt(r);
  }
  else
  {
    return ResolutionProblem::Term(c, alpha, r);
  }
}

int KindOf(double alpha)
{
  return alpha == 1.0 ? 1 : (alpha == 2.0 ? 2 : (alpha == -0.5 ? 3 : 0));
}

/// f(std::integral_constant<int, KindOf(alpha)>()).
template <class F>
void WithKind(double alpha, F&& f)
{
  switch (KindOf(alpha))
  {
    case 1:
      f(std::integral_constant<int, 1>());
      break;
    case 2:
      f(std::integral_constant<int, 2>());
      break;
    case 3:
      f(std::integral_constant<int, 3>());
      break;
    default:
      f(std::integral_constant<int, 0>());
      break;
  }
}

// The O(n) passes of the multiplier search are written once over "lanes"
// (ActiveSetOptimizer.inl): Lane1 (one double: the portable code, and the
// tail of every loop), Lane2 with SSE2 and Lane4 with AVX2 (two and four
// doubles per instruction, branch-free: the bound tests are data-dependent
// and mispredict half the time as branches, and divisions and roots are what
// the passes spend). +, -, *, / work on every lane type.
struct Lane1
{
  using V = double;
  using M = bool;
  static constexpr std::size_t Width = 1;
  static V Load(const double* p) { return *p; }
  static void Store(double* p, V v) { *p = v; }
  static V Set(double x) { return x; }
  static V Min(V a, V b) { return b < a ? b : a; }
  static V Max(V a, V b) { return a < b ? b : a; }
  static V Sqrt(V a) { return std::sqrt(a); }
  static M Le(V a, V b) { return a <= b; }
  static M Lt(V a, V b) { return a < b; }
  static M Eq(V a, V b) { return a == b; }
  static M And(M a, M b) { return a && b; }
  static M Or(M a, M b) { return a || b; }
  static M AndNot(M a, M b) { return !a && b; } ///< (not a) and b
  static M Xor(M a, M b) { return a != b; }
  static V Select(M m, V a, V b) { return m ? a : b; }
  static V Keep(M m, V a) { return m ? a : 0.0; }
  static V KeepNot(M m, V a) { return m ? 0.0 : a; }
  static double Sum(V a) { return a; }
  static unsigned Bits(M m) { return m ? 1u : 0u; }
  template <class F>
  static V Map(V a, F f)
  {
    return f(a);
  }
};

/// The float bit pattern's third plus this estimates a cube root to 4 %.
constexpr int CbrtMagic = 0x2a5137a0;

#if defined(__SSE2__)
struct Lane2
{
  using V = __m128d;
  using M = __m128d;
  static constexpr std::size_t Width = 2;
  static V Load(const double* p) { return _mm_loadu_pd(p); }
  static void Store(double* p, V v) { _mm_storeu_pd(p, v); }
  static V Set(double x) { return _mm_set1_pd(x); }
  static V Min(V a, V b) { return _mm_min_pd(b, a); } // a when a is NaN, as Lane1
  static V Max(V a, V b) { return _mm_max_pd(b, a); }
  static V Sqrt(V a) { return _mm_sqrt_pd(a); }
  static V CbrtEstimate(V x)
  {
    const __m128i bits = _mm_castps_si128(_mm_cvtpd_ps(x));
    const __m128i third =
      _mm_cvttps_epi32(_mm_mul_ps(_mm_cvtepi32_ps(bits), _mm_set1_ps(1.0f / 3.0f)));
    return _mm_cvtps_pd(_mm_castsi128_ps(_mm_add_epi32(third, _mm_set1_epi32(CbrtMagic))));
  }
  static M Le(V a, V b) { return _mm_cmple_pd(a, b); }
  static M Lt(V a, V b) { return _mm_cmplt_pd(a, b); }
  static M Eq(V a, V b) { return _mm_cmpeq_pd(a, b); }
  static M And(M a, M b) { return _mm_and_pd(a, b); }
  static M Or(M a, M b) { return _mm_or_pd(a, b); }
  static M AndNot(M a, M b) { return _mm_andnot_pd(a, b); }
  static M Xor(M a, M b) { return _mm_xor_pd(a, b); }
  static V Select(M m, V a, V b) { return _mm_or_pd(_mm_and_pd(m, a), _mm_andnot_pd(m, b)); }
  static V Keep(M m, V a) { return _mm_and_pd(m, a); }
  static V KeepNot(M m, V a) { return _mm_andnot_pd(m, a); }
  static double Sum(V a) { return _mm_cvtsd_f64(a) + _mm_cvtsd_f64(_mm_unpackhi_pd(a, a)); }
  static unsigned Bits(M m) { return static_cast<unsigned>(_mm_movemask_pd(m)); }
  template <class F>
  static V Map(V a, F f)
  {
    alignas(16) double x[2];
    _mm_store_pd(x, a);
    return _mm_set_pd(f(x[1]), f(x[0]));
  }
};
#endif

/// Set lanes of a mask of at most four.
TIMECRITICAL_LANE_INLINE std::size_t CountBits(unsigned bits)
{
  return (bits & 1u) + ((bits >> 1) & 1u) + ((bits >> 2) & 1u) + ((bits >> 3) & 1u);
}

/// Widest lane type: the reduction's bucket table has one sub-table per lane.
constexpr std::size_t MaxLanes = 4;

/// Inputs and outputs of the preparation pass (see ActiveSetOptimizer::Prepare).
struct PrepareData
{
  const double *Weight, *MaxTime, *MinResolution;
  double *R, *T, *Lo, *C, *G;
  double Gamma, Alpha;
  bool Warm;
};

/// The warm-start reduction (section 5.3.1, see PlanReduction): objects in
/// buckets below Cut reduced by Beta, those in bucket Cut by the fraction
/// Theta of that; Cut = KeyBuckets reduces every reducible object.
struct ReductionPlan
{
  double Below = -1.0, Upper = -1.0; ///< bucket(v) < Cut iff v <= Below, <= Cut iff v <= Upper
  double Theta = 1.0, Beta = 0.8;
};

/// The largest value whose bucket is below b (-1: none): buckets are
/// intervals of the doubles, so the plan compares values, not keys.
double BucketFloor(int b)
{
  if (b <= 0)
  {
    return -1.0;
  }
  if (b >= KeyBuckets - 1)
  {
    return Infinity;
  }
  const std::uint64_t bits = (static_cast<std::uint64_t>(b / 2) << 52) |
    (b % 2 ? 0x6a09e667f3bcdull : 0ull);
  const std::uint64_t below = bits - 1;
  double value = 0.0;
  std::memcpy(&value, &below, sizeof(value));
  return value;
}

/// Objects of the multiplier search, structure of arrays.
struct Objects
{
  const double *T, *G, *Lo;
};
struct CandidateArrays
{
  double *T, *G, *Lo;
};
CandidateArrays CandidatesOf(std::vector<double>& storage)
{
  const std::size_t n = storage.size() / 3;
  return { storage.data(), storage.data() + n, storage.data() + 2 * n };
}

/// Sums of the preparation pass (see ActiveSetOptimizer::StartSums).
struct PrepareTotals
{
  double CostLow = 0.0, CostHigh = 0.0, CostTop = 0.0, Cost = 0.0, Objective = 0.0;
  double FixedCost = 0.0, FreeWeight = 0.0, Weight = 0.0;
  std::size_t Invalid = 0, Zero = 0;
};

/// phi = sum tmax clamp(kappa g, rmin, 1) and its slope at kappa and at another kappa.
struct PhiTotals
{
  double Phi = 0.0, Slope = 0.0, PhiOther = 0.0, SlopeOther = 0.0;
  std::size_t Moved = 0;
};

/// Sums of the answer pass.
struct FinishTotals
{
  double Objective = 0.0, Cost = 0.0, StartObjective = 0.0;
  std::size_t Free = 0, Lower = 0, Upper = 0;
};

/// The reduction's bucket sums: MaxLanes sub-tables of KeyBuckets, and the
/// range of buckets touched since they were last cleared.
struct BucketTable
{
  double* Cost = nullptr;
  int Low = KeyBuckets, High = -1;
};

// The kernels for the build's own target: SSE2 on x86-64, else scalar.
namespace base
{
#if defined(__SSE2__)
using LaneN = Lane2;
#else
using LaneN = Lane1;
#endif
#include "ActiveSetOptimizer.inl"
}

#if defined(TIMECRITICAL_AVX2)
#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx2")
#endif
namespace avx2
{
/// Four doubles per instruction: the divisions and roots of the passes
/// take half the time of Lane2's.
struct Lane4
{
  using V = __m256d;
  using M = __m256d;
  static constexpr std::size_t Width = 4;
  static TIMECRITICAL_LANE_INLINE V Load(const double* p) { return _mm256_loadu_pd(p); }
  static TIMECRITICAL_LANE_INLINE void Store(double* p, V v) { _mm256_storeu_pd(p, v); }
  static TIMECRITICAL_LANE_INLINE V Set(double x) { return _mm256_set1_pd(x); }
  static TIMECRITICAL_LANE_INLINE V Min(V a, V b) { return _mm256_min_pd(b, a); }
  static TIMECRITICAL_LANE_INLINE V Max(V a, V b) { return _mm256_max_pd(b, a); }
  static TIMECRITICAL_LANE_INLINE V Sqrt(V a) { return _mm256_sqrt_pd(a); }
  static TIMECRITICAL_LANE_INLINE V CbrtEstimate(V x)
  {
    const __m128i bits = _mm_castps_si128(_mm256_cvtpd_ps(x));
    const __m128i third =
      _mm_cvttps_epi32(_mm_mul_ps(_mm_cvtepi32_ps(bits), _mm_set1_ps(1.0f / 3.0f)));
    return _mm256_cvtps_pd(_mm_castsi128_ps(_mm_add_epi32(third, _mm_set1_epi32(CbrtMagic))));
  }
  static TIMECRITICAL_LANE_INLINE M Le(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_LE_OQ); }
  static TIMECRITICAL_LANE_INLINE M Lt(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_LT_OQ); }
  static TIMECRITICAL_LANE_INLINE M Eq(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_EQ_OQ); }
  static TIMECRITICAL_LANE_INLINE M And(M a, M b) { return _mm256_and_pd(a, b); }
  static TIMECRITICAL_LANE_INLINE M Or(M a, M b) { return _mm256_or_pd(a, b); }
  static TIMECRITICAL_LANE_INLINE M AndNot(M a, M b) { return _mm256_andnot_pd(a, b); }
  static TIMECRITICAL_LANE_INLINE M Xor(M a, M b) { return _mm256_xor_pd(a, b); }
  static TIMECRITICAL_LANE_INLINE V Select(M m, V a, V b) { return _mm256_blendv_pd(b, a, m); }
  static TIMECRITICAL_LANE_INLINE V Keep(M m, V a) { return _mm256_and_pd(m, a); }
  static TIMECRITICAL_LANE_INLINE V KeepNot(M m, V a) { return _mm256_andnot_pd(m, a); }
  static TIMECRITICAL_LANE_INLINE double Sum(V a)
  {
    const __m128d half = _mm_add_pd(_mm256_castpd256_pd128(a), _mm256_extractf128_pd(a, 1));
    return _mm_cvtsd_f64(half) + _mm_cvtsd_f64(_mm_unpackhi_pd(half, half));
  }
  static TIMECRITICAL_LANE_INLINE unsigned Bits(M m) { return static_cast<unsigned>(_mm256_movemask_pd(m)); }
  template <class F>
  static TIMECRITICAL_LANE_INLINE V Map(V a, F f)
  {
    alignas(32) double x[4];
    _mm256_store_pd(x, a);
    return _mm256_set_pd(f(x[3]), f(x[2]), f(x[1]), f(x[0]));
  }
};
using LaneN = Lane4;
#include "ActiveSetOptimizer.inl"
}
#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif
#endif

/// f(avx2::Api()) where the processor has AVX2, else f(base::Api()).
template <class F>
void WithLanes(F&& f)
{
#if defined(TIMECRITICAL_AVX2)
  // cpu_init first: a solve may run from another library's static constructor.
  static const bool avx2 = (__builtin_cpu_init(), __builtin_cpu_supports("avx2"));
  if (avx2)
  {
    f(avx2::Api());
    return;
  }
#endif
  f(base::Api());
}
}

ActiveSetOptimizer::ActiveSetOptimizer(const Options& options)
  : Opts(options)
{
}

const char* ActiveSetOptimizer::GetStatusName(Status status)
{
  switch (status)
  {
    case Status::Optimal:
      return "optimal";
    case Status::Unconstrained:
      return "unconstrained";
    case Status::Infeasible:
      return "infeasible";
    case Status::TimeLimit:
      return "time-limit";
    case Status::IterationLimit:
      return "iteration-limit";
    case Status::Empty:
      return "empty";
    case Status::InvalidInput:
      return "invalid-input";
  }
  return "unknown";
}

void ActiveSetOptimizer::Reserve(std::size_t n)
{
  if (n > this->T.size())
  {
    this->T.resize(n);
    this->Lo.resize(n);
    this->C.resize(n);
    this->G.resize(n);
    this->Scratch.resize(n);
    this->State.resize(n);
    this->Order.resize(n);
    this->Candidates.resize(3 * n);
  }
  if (this->BucketCost.empty())
  {
    this->BucketCost.resize(MaxLanes * KeyBuckets);
  }
}

bool ActiveSetOptimizer::TimeUp()
{
  if (!this->Expired && this->Work >= this->Opts.ClockCheckWork)
  {
    this->Work = 0;
    this->Expired = Now() > this->Deadline;
  }
  return this->Expired;
}

template <int Kind>
void ActiveSetOptimizer::Prepare(
  const ResolutionProblem& problem, double* r, bool warmStart, StartSums& sums)
{
  // One pass: sanitized copies, g_i = (c_i / tmax_i)^gamma (the only root per
  // object), the start point (rmin, or the previous resolution clamped to the
  // bounds), and every sum the rest needs. Invalid or zero tmax: T = G = 0,
  // which keeps the object at rmin in every formula below.
  const PrepareData data{ problem.Weight, problem.MaxTime, problem.MinResolution, r,
    this->T.data(), this->Lo.data(), this->C.data(), this->G.data(), this->Gamma, this->Alpha,
    warmStart };
  PrepareTotals totals;
  WithLanes([&](auto api) { decltype(api)::template Prepare<Kind>(data, this->N, totals); });
  sums.CostLow = totals.CostLow;
  sums.CostHigh = totals.CostHigh;
  sums.CostTop = totals.CostTop;
  sums.Cost = totals.Cost;
  sums.Objective = totals.Objective;
  sums.FixedCost = totals.FixedCost;
  sums.FreeWeight = totals.FreeWeight;
  sums.Weight = totals.Weight;
  sums.Invalid = totals.Invalid;
  sums.Zero = totals.Zero;
}

void ActiveSetOptimizer::BucketPass(const double* r, double beta)
{
  const Objects all{ this->T.data(), this->G.data(), this->Lo.data() };
  BucketTable table{ this->BucketCost.data(), this->BucketLow, this->BucketHigh };
  WithLanes([&](auto api) { decltype(api)::Buckets(all, r, beta, this->N, table); });
  this->BucketLow = table.Low;
  this->BucketHigh = table.High;
  this->Work += this->N;
}

ActiveSetOptimizer::Reduction ActiveSetOptimizer::PlanReduction(
  double* r, double budget, StartSums& sums, bool bucketsSummed)
{
  // Section 5.3.1: reduce resolutions by Beta, least valuable objects first,
  // until the time constraint holds. "Value" is the marginal benefit per unit
  // of time, rho_i = -f_i'(r_i) / tmax_i = (g_i / r_i)^(alpha+1); ordering by
  // g_i / r_i is the same and needs no pow(). The objects are bucketed (half
  // octaves) with what each bucket gives (BucketPass, or the first
  // classification pass of the multiplier search, which reads the same
  // data); the buckets below the one that covers the excess are reduced by
  // Beta, that one by the fraction of it that spends the budget exactly (an
  // order within a half octave would be arbitrary). No sort, and the plan is
  // applied in the pass that needs the start point. When every reducible
  // object reduced once is not enough, the round is applied and repeated.
  Reduction plan;
  plan.Beta = this->Opts.Beta > 0.0 && this->Opts.Beta < 1.0 ? this->Opts.Beta : 0.8;
  double* bucketCost = this->BucketCost.data();
  const double rounding = 4.0 * static_cast<double>(this->N) * DBL_EPSILON * sums.Cost;
  for (int round = 0; sums.Cost > budget && round < 1000; ++round)
  {
    if (!bucketsSummed)
    {
      this->BucketPass(r, plan.Beta);
    }
    bucketsSummed = false;
    // Merge the lanes' sub-tables over the touched buckets, and clear them
    // (the table is all zero between uses).
    double total = 0.0;
    const int low = this->BucketLow, high = this->BucketHigh;
    for (int b = low; b <= high; ++b)
    {
      const std::size_t at = static_cast<std::size_t>(b);
      for (std::size_t k = 1; k < MaxLanes; ++k)
      {
        bucketCost[at] += bucketCost[k * KeyBuckets + at];
        bucketCost[k * KeyBuckets + at] = 0.0;
      }
      total += bucketCost[at];
    }
    this->BucketLow = KeyBuckets;
    this->BucketHigh = -1;
    auto clear = [&]() {
      std::fill(bucketCost + std::max(low, 0), bucketCost + std::max(low, high + 1), 0.0);
    };
    if (!(total > 0.0))
    {
      clear();
      break;
    }
    const double excess = sums.Cost - budget;
    double below = 0.0;
    plan.Cut = std::max(low, 0);
    for (; plan.Cut <= high && below + bucketCost[plan.Cut] < excess; ++plan.Cut)
    {
      below += bucketCost[plan.Cut];
    }
    plan.Active = true;
    if (plan.Cut <= high)
    {
      // Rounded up so that the start's cost cannot land above the budget.
      plan.Theta = std::min(1.0, (excess - below + rounding) / bucketCost[plan.Cut]);
      clear();
      return plan;
    }
    clear();
    plan.Cut = KeyBuckets;
    plan.Theta = 1.0;
    WithKind(this->Alpha, [&](auto kind) { this->ApplyReduction<decltype(kind)::value>(r, plan, sums); });
    plan.Active = false;
  }
  if (sums.Cost > budget) // rounding only: rmin is feasible
  {
    sums.Cost = sums.Objective = 0.0;
    for (std::size_t i = 0; i < this->N; ++i)
    {
      r[i] = this->Lo[i];
      sums.Cost += this->T[i] * r[i];
      sums.Objective += ResolutionProblem::Term(this->C[i], this->Alpha, r[i]);
    }
  }
  return plan;
}

template <int Kind>
void ActiveSetOptimizer::ApplyReduction(double* r, const Reduction& plan, StartSums& sums)
{
  const Objects all{ this->T.data(), this->G.data(), this->Lo.data() };
  const ReductionPlan lanes{ BucketFloor(plan.Cut), BucketFloor(plan.Cut + 1), plan.Theta, plan.Beta };
  WithLanes([&](auto api) {
    decltype(api)::template Apply<Kind>(
      all, this->C.data(), r, lanes, this->Alpha, this->N, sums.Cost, sums.Objective);
  });
  this->Work += this->N;
}

double ActiveSetOptimizer::Classify(
  double low, double high, double& slope, std::size_t& count, const double* bucketsOf, double beta)
{
  // Every object whose clamp(kappa g_i, rmin_i, 1) has the same form over
  // [low, high] goes into an affine sum, fixed + kappa slope; the others
  // (a breakpoint rmin_i / g_i or 1 / g_i inside) are the candidates.
  // Objects out of the problem have T = G = 0: at rmin, costing nothing.
  // With bucketsOf, the same pass does the warm-start reduction's BucketPass.
  const std::size_t n = this->N;
  const Objects all{ this->T.data(), this->G.data(), this->Lo.data() };
  std::uint32_t* candidates = this->Order.data();
  BucketTable table{ this->BucketCost.data(), this->BucketLow, this->BucketHigh };
  double fixed = 0.0;
  WithLanes([&](auto api) {
    fixed = decltype(api)::Classify(all, n, low, high, slope, candidates, count, bucketsOf, beta, table);
  });
  this->BucketLow = table.Low;
  this->BucketHigh = table.High;
  // Their data side by side, for the lane passes of the search.
  const CandidateArrays out = CandidatesOf(this->Candidates);
  for (std::size_t j = 0; j < count; ++j)
  {
    const std::uint32_t i = candidates[j];
    out.T[j] = all.T[i];
    out.G[j] = all.G[i];
    out.Lo[j] = all.Lo[i];
  }
  this->Work += n + count;
  return fixed;
}

template <bool Two, bool Track>
void ActiveSetOptimizer::CandidatePhi(
  std::size_t count, double kappa, double other, double& phi, double& slope, double& phiOther,
  double& slopeOther, std::size_t& moved)
{
  const CandidateArrays c = CandidatesOf(this->Candidates);
  const Objects o{ c.T, c.G, c.Lo };
  PhiTotals totals;
  WithLanes([&](auto api) { decltype(api)::template Phi<Two, Track>(o, count, kappa, other, totals); });
  this->Work += count;
  phi += totals.Phi;
  slope += totals.Slope;
  phiOther += totals.PhiOther;
  slopeOther += totals.SlopeOther;
  moved = totals.Moved;
}

bool ActiveSetOptimizer::SolveCandidates(double& low, double& high, double fixedCost,
  double slope, std::size_t count, double budget, double& kappa)
{
  // phi(kappa) = fixedCost + kappa slope + sum over the candidates of
  // tmax_i clamp(kappa g_i) on [low, high], phi(low) <= budget <= phi(high):
  // a safeguarded Newton iteration over the candidates only. Exact when phi
  // meets the budget, a Newton step crossed no breakpoint (it then solved
  // the linear piece it is on) or the bracket is down to rounding; otherwise
  // false with the bracket narrowed.
  const double tolerance = std::max(1e-13, 2.0 * static_cast<double>(this->N) * DBL_EPSILON);
  double k = low;
  double previous = -1.0;
  for (int round = 0; round < MaxNewtonRounds; ++round)
  {
    double phi = fixedCost + k * slope, d = slope, unused = 0.0;
    std::size_t moved = 0;
    if (previous >= 0.0)
    {
      this->CandidatePhi<false, true>(count, k, previous, phi, d, unused, unused, moved);
    }
    else
    {
      this->CandidatePhi<false, false>(count, k, 0.0, phi, d, unused, unused, moved);
    }
    if (std::abs(phi - budget) <= tolerance * budget || (previous >= 0.0 && moved == 0))
    {
      kappa = k;
      return true;
    }
    (phi < budget ? low : high) = k;
    if (high - low <= 1e-15 * high)
    {
      kappa = low; // within rounding of the root, on its feasible side
      return true;
    }
    double next = d > 0.0 ? k + (budget - phi) / d : -1.0;
    previous = k;
    if (!(next > low && next < high))
    {
      previous = -1.0;
      next = Bisect(low, high);
    }
    k = next;
  }
  return false;
}

template <int Kind>
void ActiveSetOptimizer::Finish(
  double* r, double kappa, double rawBudget, const Reduction& plan, Result& result)
{
  // r_i = clamp(kappa g_i, rmin_i, 1) and the report, in one pass: every
  // multiplier of eq. 16 is non-negative at such a point by construction.
  // A planned warm-start reduction is applied here only to report f at the
  // start point: the pass reads r anyway, and nothing else needs that point.
  const double alpha = this->Alpha;
  const ReductionPlan lanes{ BucketFloor(plan.Cut), BucketFloor(plan.Cut + 1), plan.Theta, plan.Beta };
  const Objects all{ this->T.data(), this->G.data(), this->Lo.data() };
  FinishTotals totals;
  WithLanes([&](auto api) {
    using Api = decltype(api);
    if (plan.Active)
    {
      Api::template Finish<Kind, true>(all, this->C.data(), r, kappa, alpha, lanes, this->N, totals);
    }
    else
    {
      Api::template Finish<Kind, false>(all, this->C.data(), r, kappa, alpha, lanes, this->N, totals);
    }
  });
  this->Work += this->N;
  if (plan.Active)
  {
    result.InitialObjective = totals.StartObjective;
  }
  const double cost = totals.Cost;
  result.Objective = totals.Objective;
  result.Cost = cost;
  result.FreeCount = totals.Free;
  result.LowerCount = totals.Lower;
  result.UpperCount = totals.Upper;
  // The time constraint is tight unless nothing can rise above rmin (kappa
  // 0) or every object that can is at 1 (kappa infinite).
  const double violation = (cost - rawBudget) / rawBudget;
  const bool tight = kappa > 0.0 && kappa < Infinity;
  result.Multiplier = tight ? std::pow(kappa, -(alpha + 1.0)) : 0.0;
  result.KKTResidual = tight ? std::abs(violation) : std::max(0.0, violation);
}

void ActiveSetOptimizer::SolveMultiplier(
  double* r, double budget, double rawBudget, StartSums& sums, Result& result)
{
  // Algorithm 1 with both options on: W = {time constraint}, every bound
  // resolved inside one projected step, so the answer is r_i = clamp(kappa
  // g_i, rmin_i, 1) with phi(kappa) = sum tmax_i r_i = budget, a root of a
  // non-decreasing piecewise-linear function. The start's eq. 14 kappa (the
  // previous frame's multiplier when warm) centres an interval; one pass sums
  // the objects whose form is fixed on it and lists the others (those with a
  // breakpoint inside: a few hundred of 100,000 for a frame-to-frame change),
  // and the root is found among those. When the interval misses the root, a
  // Newton step from its near end centres the next one, wider.
  // The start point (with its warm-start reduction) is not needed for that:
  // its reduction is planned in the first pass and applied only to report f
  // there, or when the search stops early and the start may be the answer.
  const std::size_t n = this->N;
  result.InitialObjective = sums.Objective;
  result.State = Status::IterationLimit;
  Reduction plan;
  bool reduce = sums.Cost > budget;
  const double beta = this->Opts.Beta > 0.0 && this->Opts.Beta < 1.0 ? this->Opts.Beta : 0.8;
  double kLo = 0.0, kHi = Infinity; // phi(kLo) <= budget < phi(kHi)
  double solution = -1.0;
  if (this->Opts.MaxIterations > 0 && this->Opts.MaxSteps > 0)
  {
    ++result.Iterations;
    if (!(sums.Weight > 0.0))
    {
      solution = 0.0; // nothing can rise above rmin
    }
    else if (sums.CostTop <= budget)
    {
      solution = Infinity; // objects with c = 0 stay at rmin: the time is not binding
    }
    // The start's free set: the previous frame's when warm (taken before the
    // reduction, which only scales it), else none.
    double kappa = sums.FreeWeight > 0.0 && budget > sums.FixedCost
      ? (budget - sums.FixedCost) / sums.FreeWeight
      : budget / sums.Weight;
    double spread = sums.FreeWeight > 0.0 ? 1.0 + 1.0 / 64.0 : 1.5; // interval: kappa / spread ... kappa spread
    while (solution < 0.0)
    {
      if (this->StepCount >= this->Opts.MaxSteps || this->TimeUp())
      {
        result.State = this->Expired ? Status::TimeLimit : Status::IterationLimit;
        break;
      }
      if (!(kLo < DBL_MAX))
      {
        // The root is beyond the largest kappa (g_i near the underflow: gamma
        // = 10 spans 600 decades): the best representable point, feasible.
        solution = DBL_MAX;
        break;
      }
      ++this->StepCount;
      if (!(kappa > kLo && kappa < kHi))
      {
        kappa = Bisect(kLo, kHi);
      }
      const double low = std::max(kLo, kappa / spread);
      const double high = std::min({ kHi, kappa * spread, DBL_MAX });
      double slope = 0.0;
      std::size_t count = 0;
      const double fixedCost = this->Classify(low, high, slope, count, reduce ? r : nullptr, beta);
      if (reduce)
      {
        plan = this->PlanReduction(r, budget, sums, true);
        result.InitialObjective = sums.Objective;
        reduce = false;
      }
      // phi and its slope at both ends from the affine part and the candidates.
      double phiLow = fixedCost + low * slope, phiHigh = fixedCost + high * slope;
      double dLow = slope, dHigh = slope;
      std::size_t unused = 0;
      this->CandidatePhi<true, false>(count, low, high, phiLow, dLow, phiHigh, dHigh, unused);
      if (phiLow <= budget && budget <= phiHigh)
      {
        double root = low, rootLow = low, rootHigh = high;
        if (this->SolveCandidates(rootLow, rootHigh, fixedCost, slope, count, budget, root))
        {
          solution = root;
          break;
        }
        kLo = rootLow; // out of rounds: search on with the narrower bracket
        kHi = rootHigh;
        kappa = Bisect(kLo, kHi);
        spread = std::max(kappa / kLo, kHi / kappa);
        continue;
      }
      // Missed: a Newton step from the near end centres the next interval,
      // at least twice as wide in log scale.
      const bool above = phiLow > budget;
      const double from = above ? low : high;
      (above ? kHi : kLo) = from;
      const double d = above ? dLow : dHigh;
      const double next = d > 0.0 ? from + (budget - (above ? phiLow : phiHigh)) / d : -1.0;
      spread = std::min(1e300, std::max(spread * spread, 1.0 + 2.0 * std::abs(next - from) / from));
      kappa = next;
    }
  }
  if (solution < 0.0)
  {
    // Stopped: the start point, or the bracket's feasible end if it is
    // better (anytime).
    if (reduce)
    {
      plan = this->PlanReduction(r, budget, sums, false);
    }
    if (plan.Active)
    {
      WithKind(this->Alpha, [&](auto kind) { this->ApplyReduction<decltype(kind)::value>(r, plan, sums); });
    }
    result.InitialObjective = sums.Objective;
    bool moved = false;
    if (kLo > 0.0)
    {
      double objective = 0.0;
      for (std::size_t i = 0; i < n; ++i)
      {
        objective += ResolutionProblem::Term(
          this->C[i], this->Alpha, Clamp(kLo * this->G[i], this->Lo[i], 1.0));
      }
      if (objective < sums.Objective)
      {
        moved = true;
        for (std::size_t i = 0; i < n; ++i)
        {
          r[i] = Clamp(kLo * this->G[i], this->Lo[i], 1.0);
        }
      }
    }
    for (std::size_t i = 0; i < n; ++i)
    {
      this->State[i] = !(this->T[i] > 0.0)
        ? PinnedLow
        : (r[i] <= this->Lo[i] ? Lower : (r[i] >= 1.0 ? Upper : Free));
    }
    this->Report(r, budget, rawBudget, result);
    if (!moved) // the start, whose f was summed in another order
    {
      result.Objective = sums.Objective;
    }
    return;
  }
  if (reduce) // no search pass (the solution was known): plan it for f at the start
  {
    plan = this->PlanReduction(r, budget, sums, false);
    result.InitialObjective = sums.Objective;
  }
  WithKind(this->Alpha, [&](auto kind) {
    this->Finish<decltype(kind)::value>(r, solution, rawBudget, plan, result);
  });
  result.State = solution < DBL_MAX || result.KKTResidual <= 1e-8 ? Status::Optimal
                                                                 : Status::IterationLimit;
}

double ActiveSetOptimizer::ClosedForm(double* r, double budget)
{
  // Every object free: r_i = clamp(kappa g_i, rmin_i, 1), the optimum's form,
  // with kappa from eq. 14, then a few safeguarded Newton corrections on
  // phi(kappa) = sum tmax_i clamp(kappa g_i) = budget (as in ProjectedStep),
  // keeping a bracket [kLo, kHi] with phi(kLo) <= budget < phi(kHi) (at
  // worst kappa = 0: rmin, and kappa = inf: every object in full, which is
  // over budget or Solve() would not get here). The answer is the point on
  // the segment between the bracket's two allocations that spends the
  // budget exactly: within the bounds, feasible, and the optimum whenever a
  // correction lands on it. A fixed number of O(n) passes; none repeats.
  constexpr int Passes = 6;
  const std::size_t n = this->N;
  auto clampAt = [this](double kappa, std::size_t i) {
    const double y = kappa * this->G[i];
    return std::isfinite(y) ? Clamp(y, this->Lo[i], 1.0) : (this->G[i] > 0.0 ? 1.0 : this->Lo[i]);
  };
  double weightSum = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    weightSum += this->State[i] == Free ? this->T[i] * this->G[i] : 0.0;
  }
  double kLo = 0.0, kHi = Infinity;
  double kappa = weightSum > 0.0 ? budget / weightSum : Infinity;
  for (int pass = 0; pass < Passes && kappa > kLo && kappa < kHi; ++pass)
  {
    double clamped = 0.0, interior = 0.0, phi = 0.0;
    for (std::size_t i = 0; i < n; ++i)
    {
      if (this->State[i] != Free)
      {
        continue;
      }
      const double y = kappa * this->G[i];
      if (y <= this->Lo[i])
      {
        clamped += this->T[i] * this->Lo[i];
      }
      else if (y >= 1.0)
      {
        clamped += this->T[i];
      }
      else
      {
        interior += this->T[i] * this->G[i];
        phi += this->T[i] * y;
      }
    }
    phi += clamped;
    (phi <= budget ? kLo : kHi) = kappa;
    if (phi == budget)
    {
      kHi = kappa;
      break;
    }
    double next = interior > 0.0 ? (budget - clamped) / interior : -1.0;
    if (!(next > kLo && next < kHi))
    {
      next = !std::isfinite(kHi) ? 4.0 * std::max(kLo, kappa)
                                 : (kLo > 0.0 ? std::sqrt(kLo) * std::sqrt(kHi) : 0.25 * kHi);
    }
    kappa = next;
  }
  // The segment from the feasible allocation at kLo to the one at kHi.
  double costBelow = 0.0, costAbove = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (this->State[i] == Free)
    {
      costBelow += this->T[i] * clampAt(kLo, i);
      costAbove += this->T[i] * clampAt(kHi, i);
    }
  }
  const double s = costAbove > costBelow
    ? Clamp((budget - costBelow) / (costAbove - costBelow), 0.0, 1.0)
    : 0.0;
  double cost = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (this->State[i] == Free)
    {
      const double below = clampAt(kLo, i);
      r[i] = Clamp(below + s * (clampAt(kHi, i) - below), this->Lo[i], 1.0);
      cost += this->T[i] * r[i];
    }
  }
  if (cost > budget) // rounding: fall back to the feasible end
  {
    cost = 0.0;
    for (std::size_t i = 0; i < n; ++i)
    {
      if (this->State[i] == Free)
      {
        r[i] = clampAt(kLo, i);
        cost += this->T[i] * r[i];
      }
    }
  }
  this->Work += static_cast<std::size_t>(Passes + 3) * n;
  return cost;
}

bool ActiveSetOptimizer::ProjectedStep(
  double* r, double slack, double kappa0, double& objective, std::size_t& changes)
{
  // Minimize f over the free variables within their bounds, the working
  // set's bounds fixed, on sum_F tmax_i r_i = slack. Its solution is
  // r_i = clamp(kappa g_i, rmin_i, 1) where phi(kappa) = sum_F tmax_i
  // clamp(kappa g_i) = slack; phi is non-decreasing and piecewise linear, so a
  // Newton iteration (each round = the eq. 14 solution for the bounds the last
  // round hit) safeguarded by a bracket finds the root exactly in a few
  // rounds. kappa below the root is feasible, so the bracket's lower end is a
  // feasible fall-back when the round or time limit stops the iteration.
  const std::size_t n = this->N;
  double kLo = 0.0, kHi = Infinity;
  double kappa = kappa0;
  double previous = -1.0; // kappa of the last round, when this one is its Newton step
  double solution = 0.0;
  bool exact = false;
  // Relative rounding of a sum of n terms.
  const double tolerance = std::max(1e-13, 2.0 * static_cast<double>(n) * DBL_EPSILON);
  for (int round = 0; round < MaxNewtonRounds; ++round)
  {
    if (round > 0)
    {
      ++this->StepCount;
      if (this->StepCount >= this->Opts.MaxSteps || this->TimeUp())
      {
        break;
      }
    }
    double phi = 0.0, slope = 0.0, clampedCost = 0.0;
    std::size_t freeCount = 0, upperCount = 0, moved = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
      if (this->State[i] != Free)
      {
        continue;
      }
      ++freeCount;
      const double t = this->T[i];
      const double y = kappa * this->G[i];
      if (previous >= 0.0)
      {
        // Did a bound change between the last round and this Newton step?
        const double x = previous * this->G[i];
        moved += (x <= this->Lo[i]) != (y <= this->Lo[i]) || (x >= 1.0) != (y >= 1.0);
      }
      if (y <= this->Lo[i])
      {
        phi += t * this->Lo[i];
        clampedCost += t * this->Lo[i];
      }
      else if (y >= 1.0)
      {
        phi += t;
        clampedCost += t;
        ++upperCount;
      }
      else
      {
        phi += t * y;
        slope += t * this->G[i];
      }
    }
    this->Work += n;
    // Exact: phi meets the slack, or a Newton step kept every bound, so it
    // solved the linear piece it is on (up to the rounding of the sums).
    if (std::abs(phi - slack) <= tolerance * slack || (previous >= 0.0 && moved == 0))
    {
      exact = true;
      solution = kappa;
      break;
    }
    if (phi < slack)
    {
      if (upperCount == freeCount) // time is not binding on F: all to full
      {
        exact = true;
        solution = Infinity;
        break;
      }
      kLo = std::max(kLo, kappa);
    }
    else
    {
      kHi = std::min(kHi, kappa);
    }
    double next = slope > 0.0 ? (slack - clampedCost) / slope : -1.0;
    previous = kappa;
    if (!(next > kLo && next < kHi))
    {
      // Safeguard: bisection (geometric across orders of magnitude).
      previous = -1.0;
      next = !std::isfinite(kHi) ? 4.0 * std::max(kLo, kappa)
        : (kLo > 0.0 && kHi > 4.0 * kLo ? std::sqrt(kLo) * std::sqrt(kHi) : 0.5 * (kLo + kHi));
    }
    if (std::isfinite(kHi) && kHi - kLo <= 1e-15 * kHi)
    {
      break;
    }
    kappa = next;
  }
  if (!exact)
  {
    if (!(kLo > 0.0))
    {
      return false;
    }
    solution = kLo;
  }

  // Accept only an improvement: f is monotone along the returned points.
  double delta = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (this->State[i] == Free)
    {
      const double y = Clamp(solution * this->G[i], this->Lo[i], 1.0);
      delta += ResolutionProblem::Term(this->C[i], this->Alpha, y) -
        ResolutionProblem::Term(this->C[i], this->Alpha, r[i]);
    }
  }
  this->Work += n;
  if (!(delta <= 0.0))
  {
    return false;
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    if (this->State[i] == Free)
    {
      const double y = solution * this->G[i];
      if (y <= this->Lo[i])
      {
        r[i] = this->Lo[i];
        this->State[i] = Lower;
        ++changes;
      }
      else if (y >= 1.0)
      {
        r[i] = 1.0;
        this->State[i] = Upper;
        ++changes;
      }
      else
      {
        r[i] = y;
      }
    }
  }
  objective += delta;
  return true;
}

std::size_t ActiveSetOptimizer::LineStep(double* r, double kappa, double& objective)
{
  // Algorithm 1: the largest step mu <= 1 along d = kappa g - r (free
  // variables) that keeps every bound, then every bound reached joins the
  // working set. Along d the time constraint's left side moves linearly from
  // cost(r) <= Budget to Budget, so it holds for every mu in [0, 1].
  const std::size_t n = this->N;
  double mu = 1.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (this->State[i] == Free)
    {
      const double d = kappa * this->G[i] - r[i];
      if (d > 0.0)
      {
        mu = std::min(mu, (1.0 - r[i]) / d);
      }
      else if (d < 0.0)
      {
        mu = std::min(mu, (this->Lo[i] - r[i]) / d);
      }
    }
  }
  mu = std::max(0.0, mu);
  double delta = 0.0;
  std::size_t changes = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (this->State[i] == Free)
    {
      const double d = kappa * this->G[i] - r[i];
      double y = r[i] + mu * d;
      if (d > 0.0 && y >= 1.0 - 1e-14)
      {
        y = 1.0;
        this->State[i] = Upper;
        ++changes;
      }
      else if (d < 0.0 && y <= this->Lo[i] * (1.0 + 1e-14))
      {
        y = this->Lo[i];
        this->State[i] = Lower;
        ++changes;
      }
      delta += ResolutionProblem::Term(this->C[i], this->Alpha, y) -
        ResolutionProblem::Term(this->C[i], this->Alpha, r[i]);
      r[i] = y;
    }
  }
  this->Work += 2 * n;
  objective += delta;
  return changes;
}

bool ActiveSetOptimizer::Release(double kappa, bool slackTime)
{
  // eq. 16: a lower bound's multiplier lambda tmax_i - c_i rmin_i^-(alpha+1)
  // is negative iff kappa g_i > rmin_i, an upper bound's c_i - lambda tmax_i
  // iff kappa g_i < 1. With the time constraint slack, lambda = 0.
  const std::size_t n = this->N;
  const double lambda = slackTime || !std::isfinite(kappa) ? 0.0 : std::pow(kappa, -(this->Alpha + 1.0));
  std::size_t best = n;
  double bestValue = 0.0;
  bool released = false;
  for (std::size_t i = 0; i < n; ++i)
  {
    const std::uint8_t s = this->State[i];
    bool negative = false;
    double multiplier = 0.0;
    if (s == Lower && this->G[i] > 0.0)
    {
      negative = slackTime || kappa * this->G[i] > this->Lo[i] * (1.0 + ReleaseTolerance);
      if (negative && !this->Opts.BlockRelease)
      {
        multiplier = this->T[i] * lambda -
          this->C[i] * std::pow(this->Lo[i], -(this->Alpha + 1.0));
      }
    }
    else if (s == Upper && !slackTime)
    {
      negative = kappa * this->G[i] < 1.0 - ReleaseTolerance;
      if (negative && !this->Opts.BlockRelease)
      {
        multiplier = this->C[i] - lambda * this->T[i];
      }
    }
    if (!negative)
    {
      continue;
    }
    if (this->Opts.BlockRelease)
    {
      this->State[i] = Free;
      released = true;
    }
    else if (best == n || multiplier < bestValue)
    {
      best = i;
      bestValue = multiplier;
    }
  }
  this->Work += n;
  if (!this->Opts.BlockRelease && best < n)
  {
    this->State[best] = Free;
    released = true;
  }
  return released;
}

double ActiveSetOptimizer::BoundKappa() const
{
  // Multiplier kappa when no variable is free: any kappa between the bounds'
  // limits satisfies eq. 16; -1 when none does.
  const std::size_t n = this->N;
  double lowest = 0.0, highest = Infinity;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (this->State[i] == Upper)
    {
      lowest = std::max(lowest, 1.0 / this->G[i]);
    }
    else if (this->State[i] == Lower && this->G[i] > 0.0)
    {
      highest = std::min(highest, this->Lo[i] / this->G[i]);
    }
  }
  if (lowest > highest * (1.0 + ReleaseTolerance))
  {
    return -1.0;
  }
  return std::isfinite(highest) ? (lowest > 0.0 ? std::sqrt(lowest * highest) : highest)
                                : std::max(lowest, 1.0);
}

void ActiveSetOptimizer::Report(const double* r, double budget, double rawBudget, Result& result)
{
  // Objective, cost, multiplier and KKT residual at r for the working set in
  // State: kappa from eq. 14 on its free variables.
  const std::size_t n = this->N;
  double objective = 0.0, cost = 0.0, fixedCost = 0.0, weightSum = 0.0;
  std::size_t freeCount = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    objective += ResolutionProblem::Term(this->C[i], this->Alpha, r[i]);
    cost += this->T[i] * r[i];
    const std::uint8_t s = this->State[i];
    if (s == Free)
    {
      weightSum += this->T[i] * this->G[i];
      ++freeCount;
    }
    else if (s <= Upper)
    {
      fixedCost += this->T[i] * r[i];
    }
  }
  result.Objective = objective;
  result.Cost = cost;
  double kappa = Infinity;
  if (freeCount > 0)
  {
    kappa = (budget - fixedCost) / weightSum;
  }
  else if (budget - fixedCost <= 1e-12 * std::abs(budget))
  {
    kappa = this->BoundKappa();
    kappa = kappa < 0.0 ? Infinity : kappa;
  }
  double residual = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    const std::uint8_t s = this->State[i];
    if (s > Upper)
    {
      continue;
    }
    const double target = this->G[i] > 0.0 ? Clamp(kappa * this->G[i], this->Lo[i], 1.0) : this->Lo[i];
    residual = std::max(residual, std::abs(r[i] - target));
    result.FreeCount += s == Free;
    result.LowerCount += s == Lower;
    result.UpperCount += s == Upper;
  }
  const double violation = (result.Cost - rawBudget) / rawBudget;
  residual = std::max(residual, violation);
  if (std::isfinite(kappa))
  {
    residual = std::max(residual, std::abs(violation));
    result.Multiplier = std::pow(kappa, -(this->Alpha + 1.0));
  }
  result.KKTResidual = residual;
}

ActiveSetOptimizer::Result ActiveSetOptimizer::Solve(
  const ResolutionProblem& problem, double* r, bool warmStart)
{
  const double start = Now();
  Result result;
  const std::size_t n = problem.Count;
  this->N = n;
  this->StepCount = 0;
  this->Work = 0;
  const double timeLimit = this->Opts.TimeLimit;
  this->Expired = !(timeLimit > 0.0);
  this->Deadline = start + (this->Expired ? 0.0 : timeLimit);
  auto finish = [&]() -> Result {
    result.Converged = result.State == Status::Optimal ||
      result.State == Status::Unconstrained || result.State == Status::Empty;
    result.Infeasible = result.State == Status::Infeasible;
    result.Steps = this->StepCount;
    result.Seconds = Now() - start;
    return result;
  };
  if (n == 0)
  {
    result.State = Status::Empty;
    return finish();
  }
  if (!r || !problem.Weight || !problem.MaxTime ||
    !ResolutionProblem::IsValidAlpha(problem.Alpha))
  {
    if (r)
    {
      for (std::size_t i = 0; i < n; ++i)
      {
        const double lo = problem.MinResolution ? problem.MinResolution[i] : 0.0;
        r[i] = std::isfinite(lo) ? Clamp(lo, ResolutionProblem::TinyResolution, 1.0) : 1.0;
      }
    }
    result.State = Status::InvalidInput;
    return finish();
  }
  this->Reserve(n);
  this->Alpha = problem.Alpha;
  this->Gamma = 1.0 / (problem.Alpha + 1.0);

  // Sanitized copies, the start point and its sums in one pass.
  StartSums sums;
  switch (KindOf(this->Alpha))
  {
    case 1:
      this->Prepare<1>(problem, r, warmStart, sums);
      break;
    case 2:
      this->Prepare<2>(problem, r, warmStart, sums);
      break;
    case 3:
      this->Prepare<3>(problem, r, warmStart, sums);
      break;
    default:
      this->Prepare<0>(problem, r, warmStart, sums);
      break;
  }
  this->Work += n;
  result.InvalidCount = sums.Invalid;
  result.ZeroCostCount = sums.Zero;
  // The lane sums differ from a sequential sum by rounding: where that
  // could decide a comparison with the budget, the sequential sum decides
  // (a caller that sets the budget to cost(rmin) or cost(1) gets that case).
  const double rawBudget = problem.Budget;
  const double rounding = 4.0 * static_cast<double>(n) * DBL_EPSILON;
  if (std::abs(sums.CostLow - rawBudget) <= rounding * sums.CostLow ||
    std::abs(sums.CostHigh - rawBudget) <= rounding * sums.CostHigh)
  {
    sums.CostLow = sums.CostHigh = 0.0;
    for (std::size_t i = 0; i < n; ++i)
    {
      sums.CostLow += this->T[i] * this->Lo[i];
      sums.CostHigh += this->T[i];
    }
  }
  const double costLow = sums.CostLow, costHigh = sums.CostHigh;

  auto inProblem = [&](std::size_t i) { return this->T[i] > 0.0; };
  auto objectiveOf = [&]() {
    double f = 0.0;
    for (std::size_t i = 0; i < n; ++i)
    {
      f += ResolutionProblem::Term(this->C[i], this->Alpha, r[i]);
    }
    return f;
  };
  auto costOf = [&]() {
    double cost = 0.0;
    for (std::size_t i = 0; i < n; ++i)
    {
      cost += this->T[i] * r[i];
    }
    return cost;
  };

  // Section 5.3.1: infeasible and all-full cases terminate at once.
  if (!std::isfinite(rawBudget) || costLow > rawBudget || costHigh <= rawBudget)
  {
    const bool full = std::isfinite(rawBudget) && costHigh <= rawBudget;
    for (std::size_t i = 0; i < n; ++i)
    {
      r[i] = inProblem(i) && full ? 1.0 : this->Lo[i];
      result.UpperCount += inProblem(i) && full;
      result.LowerCount += inProblem(i) && !full;
    }
    result.State = full ? Status::Unconstrained : Status::Infeasible;
    result.Objective = result.InitialObjective = objectiveOf();
    result.Cost = costOf();
    result.KKTResidual = full ? 0.0
                              : (std::isfinite(rawBudget) && rawBudget != 0.0
                                    ? (result.Cost - rawBudget) / std::abs(rawBudget)
                                    : Infinity);
    return finish();
  }
  // Solve against a budget shaved by the rounding of O(n)-term sums (at
  // least 1e-12), so that it cannot push a returned cost above the caller's.
  const double budget =
    rawBudget * (1.0 - std::max(1e-12, 4.0 * static_cast<double>(n) * DBL_EPSILON));
  if (costLow > budget) // within rounding of rmin: rmin is the answer
  {
    for (std::size_t i = 0; i < n; ++i)
    {
      r[i] = this->Lo[i];
      result.LowerCount += inProblem(i);
    }
    result.State = Status::Optimal;
    result.Objective = result.InitialObjective = objectiveOf();
    result.Cost = costOf();
    return finish();
  }

  // Start point: rmin, or the previous resolutions reduced until feasible
  // (applied in SolveMultiplier's passes when it runs).
  const bool noIteration = !(timeLimit > 0.0);
  if (!noIteration && this->Opts.ProjectedSteps && this->Opts.BlockRelease)
  {
    this->SolveMultiplier(r, budget, rawBudget, sums, result);
    return finish();
  }
  if (sums.Cost > budget)
  {
    const Reduction plan = this->PlanReduction(r, budget, sums, false);
    if (plan.Active)
    {
      WithKind(this->Alpha, [&](auto kind) { this->ApplyReduction<decltype(kind)::value>(r, plan, sums); });
    }
  }

  // The paper's iteration (or one option off); without time to iterate, the
  // closed form (or the warm start if better).
  for (std::size_t i = 0; i < n; ++i)
  {
    this->State[i] = inProblem(i) ? Free : PinnedLow;
  }
  if (noIteration)
  {
    double* closed = warmStart ? this->Scratch.data() : r;
    if (warmStart)
    {
      std::copy(r, r + n, closed);
    }
    this->ClosedForm(closed, budget);
    if (warmStart)
    {
      double closedObjective = 0.0, warmObjective = 0.0;
      for (std::size_t i = 0; i < n; ++i)
      {
        closedObjective += ResolutionProblem::Term(this->C[i], this->Alpha, closed[i]);
        warmObjective += ResolutionProblem::Term(this->C[i], this->Alpha, r[i]);
      }
      if (closedObjective < warmObjective)
      {
        std::copy(closed, closed + n, r);
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    if (this->State[i] == Free)
    {
      // Algorithm 1: W(0) = the time constraint (section 5.3.1) + active bounds.
      this->State[i] = r[i] <= this->Lo[i] ? Lower : (r[i] >= 1.0 ? Upper : Free);
    }
  }
  double objective = objectiveOf();
  result.InitialObjective = objective;
  this->Work += 2 * n;

  // Subspace data of the working set: sum of tmax_i g_i over F, fixed cost.
  auto subspace = [&](double& fixedCost, double& weightSum) {
    std::size_t freeCount = 0;
    fixedCost = 0.0;
    weightSum = 0.0;
    for (std::size_t i = 0; i < n; ++i)
    {
      const std::uint8_t s = this->State[i];
      if (s == Free)
      {
        weightSum += this->T[i] * this->G[i];
        ++freeCount;
      }
      else if (s <= Upper)
      {
        fixedCost += this->T[i] * r[i];
      }
    }
    this->Work += n;
    return freeCount;
  };
  result.State = Status::IterationLimit;
  int stalls = 0;
  int fullReleases = 0;
  while (true)
  {
    if (result.Iterations >= this->Opts.MaxIterations || this->StepCount >= this->Opts.MaxSteps)
    {
      result.State = Status::IterationLimit;
      break;
    }
    if (this->TimeUp())
    {
      result.State = Status::TimeLimit;
      break;
    }
    ++result.Iterations;
    ++this->StepCount;

    double fixedCost = 0.0, weightSum = 0.0;
    const std::size_t freeCount = subspace(fixedCost, weightSum);
    const double slack = budget - fixedCost;
    double kappa = Infinity;
    if (freeCount > 0)
    {
      kappa = slack / weightSum; // eq. 14
      bool moving = false;
      for (std::size_t i = 0; i < n && !moving; ++i)
      {
        if (this->State[i] == Free)
        {
          moving = std::abs(kappa * this->G[i] - r[i]) >
            StepTolerance + StepRelativeTolerance * r[i];
        }
      }
      this->Work += n;
      if (moving)
      {
        const double before = objective;
        std::size_t changes = 0;
        double stepSlack = slack, stepKappa = kappa;
        if (this->Opts.ProjectedSteps && this->Opts.BlockRelease && this->Release(kappa, false))
        {
          // Released now the bounds whose multiplier estimate at this kappa
          // is negative, so that one projected step covers them too (a warm
          // start would otherwise need a second one after the d = 0 test).
          // The free set changed: its slack and eq. 14 kappa with it.
          double releasedFixed = 0.0, releasedSum = 0.0;
          subspace(releasedFixed, releasedSum);
          stepSlack = budget - releasedFixed;
          stepKappa = stepSlack / releasedSum;
          changes = 1;
        }
        if (!this->Opts.ProjectedSteps ||
          !this->ProjectedStep(r, stepSlack, stepKappa, objective, changes))
        {
          changes += this->LineStep(r, stepKappa, objective);
        }
        // A step that changes neither f nor the working set would repeat.
        stalls = objective < before || changes > 0 ? 0 : stalls + 1;
        if (stalls >= 2)
        {
          break;
        }
        continue;
      }
    }
    // d = 0: multipliers (eq. 16).
    bool slackTime = false;
    if (freeCount == 0)
    {
      slackTime = slack > 1e-12 * std::abs(budget);
      if (!slackTime)
      {
        kappa = this->BoundKappa();
        if (kappa < 0.0)
        {
          // Degenerate vertex (everything at a bound, time tight) whose
          // multipliers are not unique: free every bound and let the
          // projected step solve the whole problem.
          if (++fullReleases > 2)
          {
            break;
          }
          for (std::size_t i = 0; i < n; ++i)
          {
            if ((this->State[i] == Lower && this->G[i] > 0.0) || this->State[i] == Upper)
            {
              this->State[i] = Free;
            }
          }
          continue;
        }
      }
    }
    if (!this->Release(kappa, slackTime))
    {
      result.State = Status::Optimal;
      break;
    }
  }

  this->Report(r, budget, rawBudget, result);
  if (result.State == Status::IterationLimit && stalls >= 2 && result.KKTResidual <= 1e-8)
  {
    result.State = Status::Optimal;
  }
  return finish();
}
}
