// SPDX-License-Identifier: BSD-3-Clause
// The O(n) passes of ActiveSetOptimizer over "lanes", included by
// ActiveSetOptimizer.cxx once per instruction set: inside a namespace that
// defines LaneN (the widest lane type of that set) after Lane1 and the plain
// data types, so that each inclusion compiles for its own target.
/// Cube roots over lanes (alpha = 2), to 5 ulp of std::cbrt at a quarter of
/// its cost: from L::CbrtEstimate (4 %), three Halley steps y (y^3 + 2x) /
/// (2y^3 + x). x = 0 gives 0; lanes outside the estimate's range (the
/// float's, taken as 2^-120 ... 2^120) take std::cbrt.
template <class L>
TIMECRITICAL_LANE_INLINE typename L::V CbrtLanes(typename L::V x)
{
  using V = typename L::V;
  if constexpr (L::Width == 1)
  {
    return std::cbrt(x);
  }
  else
  {
    V y = L::CbrtEstimate(x);
    for (int step = 0; step < 3; ++step)
    {
      const V y3 = y * y * y;
      y = y * ((y3 + x + x) / (y3 + y3 + x));
    }
    const V zero = L::Set(0.0);
    const typename L::M usual = L::And(L::Le(L::Set(0x1p-120), x), L::Le(x, L::Set(0x1p120)));
    if (L::Bits(L::Or(usual, L::Eq(x, zero))) != (1u << L::Width) - 1u)
    {
      return L::Select(usual, y, L::Map(x, [](double v) { return std::cbrt(v); }));
    }
    return L::Keep(L::Lt(zero, x), y);
  }
}

template <class L, int Kind>
TIMECRITICAL_LANE_INLINE typename L::V PowerLanes(typename L::V x, double gamma)
{
  if constexpr (Kind == 1)
  {
    return L::Sqrt(x);
  }
  else if constexpr (Kind == 2)
  {
    return CbrtLanes<L>(x);
  }
  else if constexpr (Kind == 3)
  {
    return x * x;
  }
  else
  {
    return L::Map(x, [gamma](double y) { return PowerOf<Kind>(y, gamma); });
  }
}

template <class L, int Kind>
TIMECRITICAL_LANE_INLINE typename L::V TermLanes(typename L::V c, double alpha, typename L::V r)
{
  if constexpr (Kind == 1)
  {
    return c / r;
  }
  else if constexpr (Kind == 2)
  {
    return L::Set(0.5) * c / (r * r);
  }
  else if constexpr (Kind == 3)
  {
    return L::Set(-2.0) * c * L::Sqrt(r);
  }
  else
  {
    alignas(16) double cs[L::Width], rs[L::Width], out[L::Width];
    L::Store(cs, c);
    L::Store(rs, r);
    for (std::size_t k = 0; k < L::Width; ++k)
    {
      out[k] = ResolutionProblem::Term(cs[k], alpha, rs[k]);
    }
    return L::Load(out);
  }
}

template <class L>
struct PrepareSums
{
  using V = typename L::V;
  // Explicit: an implicit constructor would not get the region's target.
  PrepareSums()
    : CostLow(L::Set(0.0))
    , CostHigh(L::Set(0.0))
    , CostTop(L::Set(0.0))
    , Cost(L::Set(0.0))
    , Objective(L::Set(0.0))
    , FixedCost(L::Set(0.0))
    , FreeWeight(L::Set(0.0))
    , Weight(L::Set(0.0))
  {
  }
  V CostLow, CostHigh, CostTop, Cost, Objective, FixedCost, FreeWeight, Weight;
  std::size_t Invalid = 0, Zero = 0;
};

template <class L, int Kind>
void PrepareLanes(const PrepareData& d, std::size_t begin, std::size_t end, PrepareSums<L>& s)
{
  using V = typename L::V;
  using M = typename L::M;
  const V zero = L::Set(0.0), one = L::Set(1.0), largest = L::Set(DBL_MAX);
  const V tiny = L::Set(ResolutionProblem::TinyResolution);
  for (std::size_t i = begin; i < end; i += L::Width)
  {
    const V rawLo = d.MinResolution ? L::Load(d.MinResolution + i) : zero;
    const M finiteLo = L::And(L::Le(rawLo, largest), L::Le(L::Set(-DBL_MAX), rawLo));
    const V lo = L::Select(finiteLo, L::Min(L::Max(rawLo, tiny), one), tiny);
    const V rawC = L::Load(d.Weight + i);
    const V c = L::Keep(L::And(L::Lt(zero, rawC), L::Le(rawC, largest)), rawC);
    const V rawT = L::Load(d.MaxTime + i);
    const M valid = L::And(L::Lt(zero, rawT), L::Le(rawT, largest));
    const M nonNegative = L::And(L::Le(zero, rawT), L::Le(rawT, largest));
    s.Invalid += L::Width - CountBits(L::Bits(nonNegative));
    s.Zero += CountBits(L::Bits(L::Eq(rawT, zero)));
    const V t = L::Keep(valid, rawT);
    const V g = L::Min(PowerLanes<L, Kind>(L::Keep(valid, c / L::Select(valid, rawT, one)), d.Gamma), largest);
    L::Store(d.Lo + i, lo);
    L::Store(d.C + i, c);
    L::Store(d.T + i, t);
    L::Store(d.G + i, g);
    V x = lo;
    if (d.Warm)
    {
      const V previous = L::Load(d.R + i);
      const M usable =
        L::And(L::Lt(zero, g), L::And(L::Lt(zero, previous), L::Le(previous, largest)));
      x = L::Select(usable, L::Min(L::Max(previous, lo), one), lo);
    }
    L::Store(d.R + i, x);
    s.Objective = s.Objective + TermLanes<L, Kind>(c, d.Alpha, x);
    s.CostLow = s.CostLow + t * lo;
    s.CostHigh = s.CostHigh + t;
    s.CostTop = s.CostTop + t * L::Select(L::Lt(zero, g), one, lo);
    s.Cost = s.Cost + t * x;
    const M bound = L::Or(L::Le(x, lo), L::Le(one, x));
    const V tg = t * g;
    s.FixedCost = s.FixedCost + L::Keep(bound, t * x);
    s.FreeWeight = s.FreeWeight + L::KeepNot(bound, tg);
    s.Weight = s.Weight + tg;
  }
}

/// One object's start point after the reduction.
template <class L>
TIMECRITICAL_LANE_INLINE typename L::V ReducedLanes(typename L::V t, typename L::V g,
  typename L::V lo, typename L::V x, const ReductionPlan& plan)
{
  using V = typename L::V;
  using M = typename L::M;
  const V reduced = L::Max(lo, L::Set(plan.Beta) * x);
  const V value = g / x;
  const M reducible = L::And(L::Lt(L::Set(0.0), t), L::Lt(lo, x));
  const M below = L::Le(value, L::Set(plan.Below));
  const M inCut = L::AndNot(below, L::Le(value, L::Set(plan.Upper)));
  const V partial = x - L::Set(plan.Theta) * (x - reduced);
  return L::Select(L::And(reducible, below), reduced, L::Select(L::And(reducible, inCut), partial, x));
}

/// What each bucket of g_i / r_i gives when its objects are reduced by beta,
/// summed per lane (consecutive objects mostly share a bucket: one table
/// would chain every addition on the previous one).
template <class L>
TIMECRITICAL_LANE_INLINE void BucketLanes(typename L::V t, typename L::V g, typename L::V lo,
  typename L::V x, double beta, BucketTable& table)
{
  const unsigned reducible = L::Bits(L::And(L::Lt(L::Set(0.0), t), L::Lt(lo, x)));
  if (reducible == 0)
  {
    return;
  }
  alignas(16) double value[L::Width], saved[L::Width];
  L::Store(value, g / x);
  L::Store(saved, t * (x - L::Max(lo, L::Set(beta) * x)));
  for (std::size_t k = 0; k < L::Width; ++k)
  {
    if ((reducible >> k) & 1u)
    {
      const int key = Bucket(value[k]);
      table.Cost[k * KeyBuckets + static_cast<std::size_t>(key)] += saved[k];
      table.Low = std::min(table.Low, key);
      table.High = std::max(table.High, key);
    }
  }
}

template <class L>
void BucketPassLanes(const double* t, const double* g, const double* lo, const double* r,
  double beta, std::size_t begin, std::size_t end, BucketTable& table)
{
  for (std::size_t i = begin; i < end; i += L::Width)
  {
    BucketLanes<L>(L::Load(t + i), L::Load(g + i), L::Load(lo + i), L::Load(r + i), beta, table);
  }
}

/// Applies a reduction: r becomes the start point; its cost and objective.
template <class L, int Kind>
void ApplyLanes(const double* t, const double* g, const double* lo, const double* c, double* r,
  const ReductionPlan& plan, double alpha, std::size_t begin, std::size_t end, typename L::V& cost,
  typename L::V& objective)
{
  for (std::size_t i = begin; i < end; i += L::Width)
  {
    const typename L::V ti = L::Load(t + i);
    const typename L::V y = ReducedLanes<L>(ti, L::Load(g + i), L::Load(lo + i), L::Load(r + i), plan);
    L::Store(r + i, y);
    cost = cost + ti * y;
    objective = objective + TermLanes<L, Kind>(L::Load(c + i), alpha, y);
  }
}

/// Classification of the objects over [low, high] (see ActiveSetOptimizer::Classify).
template <class L, bool Buckets>
void ClassifyLanes(const Objects& o, double low, double high, std::size_t begin, std::size_t end,
  typename L::V& fixed, typename L::V& slope, std::uint32_t* candidates, std::size_t& count,
  const double* r, double beta, BucketTable& table)
{
  using V = typename L::V;
  using M = typename L::M;
  const V one = L::Set(1.0), vLow = L::Set(low), vHigh = L::Set(high);
  std::size_t m = count;
  for (std::size_t i = begin; i < end; i += L::Width)
  {
    const V ti = L::Load(o.T + i), gi = L::Load(o.G + i), loi = L::Load(o.Lo + i);
    const V yLow = vLow * gi, yHigh = vHigh * gi;
    const M upper = L::Le(one, yLow);
    const M lower = L::AndNot(upper, L::Le(yHigh, loi));
    const M free = L::AndNot(L::Or(upper, lower), L::And(L::Le(loi, yLow), L::Le(yHigh, one)));
    fixed = fixed + L::Select(upper, ti, L::Keep(lower, ti * loi));
    slope = slope + L::Keep(free, ti * gi);
    const unsigned settled = L::Bits(L::Or(L::Or(upper, lower), free));
    // Written always, kept when unsettled: no branch on the data.
    for (std::size_t k = 0; k < L::Width; ++k)
    {
      candidates[m] = static_cast<std::uint32_t>(i + k);
      m += ((settled >> k) & 1u) ^ 1u;
    }
    if constexpr (Buckets)
    {
      BucketLanes<L>(ti, gi, loi, L::Load(r + i), beta, table);
    }
  }
  count = m;
}

/// Sum over objects of tmax clamp(kappa g, rmin, 1) and of its slope at one
/// or two kappas; moved: objects whose clamp changes form from previous.
template <class L>
struct PhiSums
{
  PhiSums()
    : Phi(L::Set(0.0))
    , Slope(L::Set(0.0))
    , PhiHigh(L::Set(0.0))
    , SlopeHigh(L::Set(0.0))
  {
  }
  typename L::V Phi, Slope, PhiHigh, SlopeHigh;
  std::size_t Moved = 0;
};

template <class L, bool Two, bool Track>
void PhiLanes(const Objects& o, double kappa, double other, std::size_t begin, std::size_t end,
  PhiSums<L>& s)
{
  using V = typename L::V;
  using M = typename L::M;
  const V one = L::Set(1.0), k = L::Set(kappa), k2 = L::Set(other);
  for (std::size_t i = begin; i < end; i += L::Width)
  {
    const V ti = L::Load(o.T + i), gi = L::Load(o.G + i), loi = L::Load(o.Lo + i);
    const V y = k * gi;
    const M lower = L::Le(y, loi), upper = L::AndNot(lower, L::Le(one, y));
    s.Phi = s.Phi + ti * L::Min(L::Max(y, loi), one);
    s.Slope = s.Slope + L::KeepNot(L::Or(lower, upper), ti * gi);
    if constexpr (Two || Track)
    {
      const V y2 = k2 * gi;
      const M lower2 = L::Le(y2, loi), upper2 = L::AndNot(lower2, L::Le(one, y2));
      if constexpr (Two)
      {
        s.PhiHigh = s.PhiHigh + ti * L::Min(L::Max(y2, loi), one);
        s.SlopeHigh = s.SlopeHigh + L::KeepNot(L::Or(lower2, upper2), ti * gi);
      }
      if constexpr (Track)
      {
        s.Moved += CountBits(L::Bits(L::Or(L::Xor(lower, lower2), L::Xor(upper, upper2))));
      }
    }
  }
}

/// r = clamp(kappa g, rmin, 1) and its sums (see ActiveSetOptimizer::Finish);
/// with Start, also the objective of the start point: r reduced by plan.
template <class L>
struct FinishSums
{
  FinishSums()
    : Objective(L::Set(0.0))
    , Cost(L::Set(0.0))
    , StartObjective(L::Set(0.0))
  {
  }
  typename L::V Objective, Cost, StartObjective;
  std::size_t Free = 0, Lower = 0, Upper = 0;
};

template <class L, int Kind, bool Start>
void FinishLanes(const double* t, const double* g, const double* lo, const double* c, double* r,
  double kappa, double alpha, const ReductionPlan& plan, std::size_t begin, std::size_t end,
  FinishSums<L>& s)
{
  using V = typename L::V;
  using M = typename L::M;
  const V zero = L::Set(0.0), one = L::Set(1.0), k = L::Set(kappa);
  for (std::size_t i = begin; i < end; i += L::Width)
  {
    const V ti = L::Load(t + i), loi = L::Load(lo + i), ci = L::Load(c + i);
    // kappa = infinity (time not binding): g = 0 stays at rmin, not NaN.
    const V gi = L::Load(g + i);
    if constexpr (Start)
    {
      // As ApplyLanes sums it, so that both report the same f.
      const V y = ReducedLanes<L>(ti, gi, loi, L::Load(r + i), plan);
      s.StartObjective = s.StartObjective + TermLanes<L, Kind>(ci, alpha, y);
    }
    const V x = L::Min(L::Max(L::Keep(L::Lt(zero, gi), k * gi), loi), one);
    L::Store(r + i, x);
    s.Objective = s.Objective + TermLanes<L, Kind>(ci, alpha, x);
    s.Cost = s.Cost + ti * x;
    const M inProblem = L::Lt(zero, ti);
    const M lower = L::Le(x, loi);
    const M upper = L::AndNot(lower, L::Le(one, x));
    const unsigned in = L::Bits(inProblem);
    const unsigned lowerBits = L::Bits(lower) & in, upperBits = L::Bits(upper) & in;
    s.Lower += CountBits(lowerBits);
    s.Upper += CountBits(upperBits);
    s.Free += CountBits(in & ~(lowerBits | upperBits));
  }
}

/// The passes over whole arrays: lanes of LaneN, the last objects one by one.
struct Api
{
  template <int Kind>
  static void Prepare(const PrepareData& d, std::size_t n, PrepareTotals& out)
  {
    const std::size_t body = n - n % LaneN::Width;
    PrepareSums<LaneN> wide;
    PrepareLanes<LaneN, Kind>(d, 0, body, wide);
    PrepareSums<Lane1> tail;
    PrepareLanes<Lane1, Kind>(d, body, n, tail);
    out.CostLow = LaneN::Sum(wide.CostLow) + tail.CostLow;
    out.CostHigh = LaneN::Sum(wide.CostHigh) + tail.CostHigh;
    out.CostTop = LaneN::Sum(wide.CostTop) + tail.CostTop;
    out.Cost = LaneN::Sum(wide.Cost) + tail.Cost;
    out.Objective = LaneN::Sum(wide.Objective) + tail.Objective;
    out.FixedCost = LaneN::Sum(wide.FixedCost) + tail.FixedCost;
    out.FreeWeight = LaneN::Sum(wide.FreeWeight) + tail.FreeWeight;
    out.Weight = LaneN::Sum(wide.Weight) + tail.Weight;
    out.Invalid = wide.Invalid + tail.Invalid;
    out.Zero = wide.Zero + tail.Zero;
  }

  /// Returns the fixed cost; with r, also sums the reduction's buckets.
  static double Classify(const Objects& o, std::size_t n, double low, double high, double& slope,
    std::uint32_t* candidates, std::size_t& count, const double* r, double beta, BucketTable& table)
  {
    const std::size_t body = n - n % LaneN::Width;
    typename LaneN::V wideFixed = LaneN::Set(0.0), wideSlope = LaneN::Set(0.0);
    double fixed = 0.0;
    slope = 0.0;
    count = 0;
    if (r)
    {
      ClassifyLanes<LaneN, true>(o, low, high, 0, body, wideFixed, wideSlope, candidates, count, r, beta, table);
      ClassifyLanes<Lane1, true>(o, low, high, body, n, fixed, slope, candidates, count, r, beta, table);
    }
    else
    {
      ClassifyLanes<LaneN, false>(o, low, high, 0, body, wideFixed, wideSlope, candidates, count, r, beta, table);
      ClassifyLanes<Lane1, false>(o, low, high, body, n, fixed, slope, candidates, count, r, beta, table);
    }
    slope += LaneN::Sum(wideSlope);
    return fixed + LaneN::Sum(wideFixed);
  }

  template <bool Two, bool Track>
  static void Phi(const Objects& o, std::size_t count, double kappa, double other, PhiTotals& out)
  {
    const std::size_t body = count - count % LaneN::Width;
    PhiSums<LaneN> wide;
    PhiLanes<LaneN, Two, Track>(o, kappa, other, 0, body, wide);
    PhiSums<Lane1> tail;
    PhiLanes<Lane1, Two, Track>(o, kappa, other, body, count, tail);
    out.Phi = LaneN::Sum(wide.Phi) + tail.Phi;
    out.Slope = LaneN::Sum(wide.Slope) + tail.Slope;
    out.PhiOther = LaneN::Sum(wide.PhiHigh) + tail.PhiHigh;
    out.SlopeOther = LaneN::Sum(wide.SlopeHigh) + tail.SlopeHigh;
    out.Moved = wide.Moved + tail.Moved;
  }

  static void Buckets(const Objects& o, const double* r, double beta, std::size_t n, BucketTable& table)
  {
    const std::size_t body = n - n % LaneN::Width;
    BucketPassLanes<LaneN>(o.T, o.G, o.Lo, r, beta, 0, body, table);
    BucketPassLanes<Lane1>(o.T, o.G, o.Lo, r, beta, body, n, table);
  }

  template <int Kind>
  static void Apply(const Objects& o, const double* c, double* r, const ReductionPlan& plan,
    double alpha, std::size_t n, double& cost, double& objective)
  {
    const std::size_t body = n - n % LaneN::Width;
    typename LaneN::V wideCost = LaneN::Set(0.0), wideObjective = LaneN::Set(0.0);
    double tailCost = 0.0, tailObjective = 0.0;
    ApplyLanes<LaneN, Kind>(o.T, o.G, o.Lo, c, r, plan, alpha, 0, body, wideCost, wideObjective);
    ApplyLanes<Lane1, Kind>(o.T, o.G, o.Lo, c, r, plan, alpha, body, n, tailCost, tailObjective);
    cost = LaneN::Sum(wideCost) + tailCost;
    objective = LaneN::Sum(wideObjective) + tailObjective;
  }

  template <int Kind, bool Start>
  static void Finish(const Objects& o, const double* c, double* r, double kappa, double alpha,
    const ReductionPlan& plan, std::size_t n, FinishTotals& out)
  {
    const std::size_t body = n - n % LaneN::Width;
    FinishSums<LaneN> wide;
    FinishLanes<LaneN, Kind, Start>(o.T, o.G, o.Lo, c, r, kappa, alpha, plan, 0, body, wide);
    FinishSums<Lane1> tail;
    FinishLanes<Lane1, Kind, Start>(o.T, o.G, o.Lo, c, r, kappa, alpha, plan, body, n, tail);
    out.Objective = LaneN::Sum(wide.Objective) + tail.Objective;
    out.Cost = LaneN::Sum(wide.Cost) + tail.Cost;
    out.StartObjective = LaneN::Sum(wide.StartObjective) + tail.StartObjective;
    out.Free = wide.Free + tail.Free;
    out.Lower = wide.Lower + tail.Lower;
    out.Upper = wide.Upper + tail.Upper;
  }
};
