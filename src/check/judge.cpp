#include "check/judge.h"

#include "check/arithmetic_types.h"
#include "core/exact_sum.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace linkproof {

namespace {

template <class T>
bool undefined_side(const Comparison<T>& c, ComparisonOutcome& out) {
  for (const Defined<T>* side : {&c.lhs, &c.rhs}) {
    if (!side->has_value()) {
      out.verdict = Verdict::Undefined;
      out.undefined_quantity = side->quantity();
      out.reason = side->reason();
      return true;
    }
  }
  return false;
}

template <class T>
ComparisonOutcome judge_exact(const Comparison<T>& c) {
  ComparisonOutcome out;
  out.label = c.full_label();
  if (undefined_side(c, out)) return out;
  const T& l = c.lhs.get();
  const T& r = c.rhs.get();
  const T res = l - r;
  const bool holds = is_zero(res);
  out.lhs = result_number(l);
  // Equal exact values have one reduced form: a side that holds is read once (reading a
  // value as a cl_RA reduces it, a gcd).
  out.rhs = holds ? *out.lhs : result_number(r);
  out.residual = result_number(res);
  out.verdict = holds ? Verdict::Holds : Verdict::Fails;
  return out;
}

// What the judge needs beyond TrackedTraits: exact comparisons of a radius with a midpoint,
// the threshold sqrt(u) scale, radii as result values, relative bounds and conditions as doubles. IEEE types keep
// their former plain-double formulas (the radius is an F); MpFloat compares exactly in F (a
// WideBound is exact in any CLN format of >= 53 bits).
template <class F>
struct JudgeOps {
  static_assert(std::is_floating_point_v<F>);
  using Radius = F;
  static bool any_non_finite(const F& a, const F& b, const F& c) {
    return !std::isfinite(a) || !std::isfinite(b) || !std::isfinite(c);
  }
  static F from_double(double x) { return static_cast<F>(x); }
  static bool magnitude_exceeds(const F& x, const F& e) { return std::abs(x) > e; }
  static bool radius_exceeds(const F& e, const F& t) { return e > t; }
  static F sqrt_u_times(const F& scale) { return std::sqrt(TrackedTraits<F>::unit_roundoff()) * scale; }
  static ResultRadius radius(const F& e) { return e; }
  static ResultNumber number(const F& x) { return x; }
  /// e / scale rounded upward, then to a double rounded upward (docs/check.md promises a bound).
  static double relative(const F& e, const F& scale) {
    if (!(scale > 0)) return e == 0 ? 0.0 : HUGE_VAL;
    return round_up_to_double(TrackedTraits<F>::div_up(e, scale));
  }
  /// bound / |value| (display; +inf for an unbounded or non-finite side or a zero midpoint).
  static double relative_to_own(const Tracked<F>& x) {
    if (!std::isfinite(x.v) || !std::isfinite(x.e)) return HUGE_VAL;
    return x.e == 0 ? 0.0 : x.v == 0 ? HUGE_VAL : static_cast<double>(x.e / std::abs(x.v));
  }
  static double condition(const Tracked<F>& x) {
    const F u = TrackedTraits<F>::unit_roundoff();
    return x.e == 0 ? 0.0 : (x.v == 0 ? HUGE_VAL : static_cast<double>(x.e / (u * std::abs(x.v))));
  }
};

template <int D>
struct JudgeOps<MpFloat<D>> {
  using F = MpFloat<D>;
  using TT = TrackedTraits<F>;
  static bool any_non_finite(const F&, const F&, const F&) { return false; }  // CLN has no inf/NaN
  static F from_double(double x) { return F(exact_value_of(x)); }
  /// Exact in F; never called on an unbounded radius (the judge tests that first).
  static cln::cl_F exact(const WideBound& e) { return e.to_float(F::format()); }
  static bool magnitude_exceeds(const F& x, const WideBound& e) { return cln::abs(x.value()) > exact(e); }
  static bool radius_exceeds(const WideBound& e, const F& t) { return exact(e) > t.value(); }
  /// u = 2^-p with p even (a whole number of 64-bit words): sqrt(u) = 2^-(p/2), scaled exactly.
  static F sqrt_u_times(const F& scale) {
    return F(cln::scale_float(scale.value(), -static_cast<long>(F::precision_bits() / 2)));
  }
  static ResultRadius radius(const WideBound& e) { return e; }
  static ResultNumber number(const F& x) { return x.value(); }
  static double relative(const WideBound& e, const F& scale) {
    if (cln::zerop(scale.value())) return e.is_zero() ? 0.0 : HUGE_VAL;
    return (e / WideBound::from_float_down(scale.value())).to_double_up();
  }
  static double relative_to_own(const Tracked<F>& x) {
    if (x.e.is_infinite()) return HUGE_VAL;
    if (x.e.is_zero()) return 0.0;
    const WideBound m = WideBound::from_float_down(x.v.value());
    return m.is_zero() ? HUGE_VAL : (x.e / m).to_double_up();
  }
  static double condition(const Tracked<F>& x) {
    if (x.e.is_zero()) return 0.0;
    if (cln::zerop(x.v.value())) return HUGE_VAL;
    return (x.e / (TT::unit_roundoff() * WideBound::from_float_down(x.v.value()))).to_double_up();
  }
};

/// How a floating-point comparison ends (the rule of judge.h), without any text.
enum class TrackedCase { NonFinite, Unbounded, Fails, TooWide, Holds };

template <class F>
F judge_scale(const Tracked<F>& l, const Tracked<F>& r, double extra) {
  using Ops = JudgeOps<F>;
  using TT = TrackedTraits<F>;
  F scale = TT::abs(l.v);
  for (const F& x : {TT::abs(r.v), Ops::from_double(std::abs(extra))})
    if (ScalarTraits<F>::less(scale, x)) scale = x;
  return scale;
}

template <class F>
TrackedCase decide_tracked(const Tracked<F>& l, const Tracked<F>& r, const Tracked<F>& res, const F& scale) {
  using Ops = JudgeOps<F>;
  if (Ops::any_non_finite(l.v, r.v, res.v)) return TrackedCase::NonFinite;
  if (TrackedTraits<F>::is_unbounded(res.e)) return TrackedCase::Unbounded;
  if (Ops::magnitude_exceeds(res.v, res.e)) return TrackedCase::Fails;
  if (Ops::radius_exceeds(res.e, Ops::sqrt_u_times(scale))) return TrackedCase::TooWide;
  return TrackedCase::Holds;
}

Verdict verdict_of(TrackedCase k) {
  switch (k) {
    case TrackedCase::Fails: return Verdict::Fails;
    case TrackedCase::Holds: return Verdict::Holds;
    default: return Verdict::Inconclusive;
  }
}

template <class F>
ComparisonOutcome judge_tracked(const Comparison<Tracked<F>>& c) {
  using Ops = JudgeOps<F>;
  using TT = TrackedTraits<F>;
  ComparisonOutcome out;
  out.label = c.full_label();
  if (undefined_side(c, out)) return out;
  const Tracked<F>& l = c.lhs.get();
  const Tracked<F>& r = c.rhs.get();
  const Tracked<F> res = l - r;  // its radius is e_l + e_r plus the subtraction's rounding
  out.lhs = Ops::number(l.v);
  out.rhs = Ops::number(r.v);
  out.residual = Ops::number(res.v);
  FloatEvidence f{Ops::radius(res.e), Ops::radius(l.e), Ops::radius(r.e)};
  const F scale = judge_scale(l, r, c.scale);
  f.relative_error_bound = Ops::relative(res.e, scale);
  f.condition_lhs = Ops::condition(l);
  f.condition_rhs = Ops::condition(r);
  f.precision_bits = TT::precision_bits();
  const TrackedCase k = decide_tracked(l, r, res, scale);
  out.verdict = verdict_of(k);
  f.undecided = k == TrackedCase::NonFinite   ? Undecided::NonFinite
                : k == TrackedCase::Unbounded ? Undecided::Unbounded
                : k == TrackedCase::TooWide   ? Undecided::TooWide
                                              : Undecided::None;
  if (f.undecided != Undecided::None) {
    // The side whose bound is the wider relative to its own magnitude (an unbounded or
    // non-finite side is the widest); the claim runner adds the quantity (check/inconclusive_cause.h).
    const double rel_l = Ops::relative_to_own(l), rel_r = Ops::relative_to_own(r);
    f.wider_side = rel_l == rel_r ? Side::Both : rel_l > rel_r ? Side::Lhs : Side::Rhs;
    f.relative_wide = std::max(rel_l, rel_r);
    f.relative_narrow = std::min(rel_l, rel_r);
  }
  out.floating = std::move(f);
  return out;
}

}  // namespace

template <class T>
ComparisonOutcome judge(const Comparison<T>& c) {
  if constexpr (ScalarTraits<T>::is_exact) {
    if (c.same_value) {  // both sides one polynomial: their common value, made now
      Comparison<T> made = c;
      made.make_same_value();
      return judge_exact(made);
    }
    return judge_exact(c);
  } else {
    return judge_tracked(c);
  }
}

template <class T>
Verdict judge_verdict(const Comparison<T>& c) {
  if (c.same_value) return Verdict::Holds;  // one polynomial on both sides: equal at any rates
  if (!c.lhs.has_value() || !c.rhs.has_value()) return Verdict::Undefined;
  if constexpr (GrowingExactNumber<T>) {
    // Equality, not a zero difference: the difference of two large rationals is a bignum sum
    // and a gcd; equal values have one reduced form (5 % of an exact check at n = 1000, perf).
    return c.lhs.get() == c.rhs.get() ? Verdict::Holds : Verdict::Fails;
  } else if constexpr (ScalarTraits<T>::is_exact) {
    return is_zero(c.lhs.get() - c.rhs.get()) ? Verdict::Holds : Verdict::Fails;
  } else {
    const auto& l = c.lhs.get();
    const auto& r = c.rhs.get();
    return verdict_of(decide_tracked(l, r, l - r, judge_scale(l, r, c.scale)));
  }
}

std::string_view to_string(Side s) {
  switch (s) {
    case Side::Lhs: return "lhs";
    case Side::Rhs: return "rhs";
    case Side::Both: return "both";
    case Side::None: break;
  }
  return "";
}

// One instantiation per arithmetic (check/arithmetic_types.h).
#define LINKPROOF_INSTANTIATE_JUDGE(enumerator, name, T)          \
  template ComparisonOutcome judge<T>(const Comparison<T>&);        \
  template Verdict judge_verdict<T>(const Comparison<T>&);
LINKPROOF_FOR_EACH_ARITHMETIC(LINKPROOF_INSTANTIATE_JUDGE)
// The exact mechanism check (mechanism/mechanism_check.cpp) computes in CLN rationals.
LINKPROOF_INSTANTIATE_JUDGE(Exact, "exact", ::linkproof::Rational)
#undef LINKPROOF_INSTANTIATE_JUDGE

}  // namespace linkproof
