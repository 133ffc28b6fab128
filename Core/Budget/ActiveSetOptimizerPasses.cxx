// SPDX-License-Identifier: BSD-3-Clause
// The O(n) passes of ActiveSetOptimizer (the start, the warm-start
// reduction, the multiplier search's classification and phi, the answer),
// compiled over lanes for the build's target and, where the processor has it,
// AVX2; ActiveSetOptimizer.inl holds the lane kernels.
#include "ActiveSetOptimizerInternals.h"

#include <cstdint>
#include <cstring>
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
/// Half-octave bucket of a non-negative key, from its bits (exponent and
/// mantissa >= sqrt 2): order-preserving, in [0, KeyBuckets).
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

// The other ActiveSetOptimizer files call these for every exponent kind.
template void ActiveSetOptimizer::Prepare<0>(const ResolutionProblem&, double*, bool, StartSums&);
template void ActiveSetOptimizer::Prepare<1>(const ResolutionProblem&, double*, bool, StartSums&);
template void ActiveSetOptimizer::Prepare<2>(const ResolutionProblem&, double*, bool, StartSums&);
template void ActiveSetOptimizer::Prepare<3>(const ResolutionProblem&, double*, bool, StartSums&);
template void ActiveSetOptimizer::ApplyReduction<0>(double*, const Reduction&, StartSums&);
template void ActiveSetOptimizer::ApplyReduction<1>(double*, const Reduction&, StartSums&);
template void ActiveSetOptimizer::ApplyReduction<2>(double*, const Reduction&, StartSums&);
template void ActiveSetOptimizer::ApplyReduction<3>(double*, const Reduction&, StartSums&);
template void ActiveSetOptimizer::Finish<0>(double*, double, double, const Reduction&, Result&);
template void ActiveSetOptimizer::Finish<1>(double*, double, double, const Reduction&, Result&);
template void ActiveSetOptimizer::Finish<2>(double*, double, double, const Reduction&, Result&);
template void ActiveSetOptimizer::Finish<3>(double*, double, double, const Reduction&, Result&);
template void ActiveSetOptimizer::CandidatePhi<true, false>(
  std::size_t, double, double, double&, double&, double&, double&, std::size_t&);
template void ActiveSetOptimizer::CandidatePhi<false, true>(
  std::size_t, double, double, double&, double&, double&, double&, std::size_t&);
template void ActiveSetOptimizer::CandidatePhi<false, false>(
  std::size_t, double, double, double&, double&, double&, double&, std::size_t&);
}
