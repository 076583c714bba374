#include "linkproof/check/judge.h"

#include <fmt/format.h>

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

ComparisonOutcome judge_exact(const Comparison<Rational>& c) {
  ComparisonOutcome out;
  out.label = c.full_label();
  if (undefined_side(c, out)) return out;
  const Rational& l = c.lhs.get();
  const Rational& r = c.rhs.get();
  const Rational res = l - r;
  out.lhs = format_rational(l);
  out.rhs = format_rational(r);
  out.residual = format_rational(res);
  out.verdict = cln::zerop(res) ? Verdict::Holds : Verdict::Fails;
  return out;
}

// What the judge needs beyond TrackedTraits: exact comparisons of a radius with a midpoint,
// the threshold sqrt(u) scale, radii as text, relative bounds and conditions as doubles. IEEE types keep
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
  static std::string radius_text(const F& e) { return format_float(e); }
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
  static std::string radius_text(const WideBound& e) { return e.to_string(); }
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

template <class Radius>
std::string short_text(const Radius& e) {
  if constexpr (std::is_floating_point_v<Radius>) {
    return fmt::format("{:.3g}", static_cast<double>(e));
  } else {
    return e.to_short_string();
  }
}

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
  out.lhs = ScalarTraits<F>::to_string(l.v);
  out.rhs = ScalarTraits<F>::to_string(r.v);
  out.residual = ScalarTraits<F>::to_string(res.v);
  out.tolerance = Ops::radius_text(res.e);
  const F scale = judge_scale(l, r, c.scale);
  out.relative_error_bound = Ops::relative(res.e, scale);
  const double cond_l = Ops::condition(l), cond_r = Ops::condition(r);
  out.tolerance_derivation = fmt::format(
      "tolerance {} = bound(lhs) {} + bound(rhs) {} + rounding of lhs - rhs; each bound is a running "
      "error bound (inputs rounded from the exact scene, every operation's rounding), i.e. u times the "
      "evaluation's condition: condition(lhs) = {:.3g}, condition(rhs) = {:.3g}, u = 2^-{}",
      out.tolerance, short_text(l.e), short_text(r.e), cond_l, cond_r, TT::precision_bits());
  // The side whose bound is the wider relative to its own magnitude (an unbounded or
  // non-finite side is the widest); the claim runner adds the quantity (check/inconclusive_cause.h).
  const auto set_trust = [&] {
    const double rel_l = Ops::relative_to_own(l), rel_r = Ops::relative_to_own(r);
    out.inconclusive_side = rel_l == rel_r ? "both" : rel_l > rel_r ? "lhs" : "rhs";
    out.trust_route = fmt::format(
        "{}: {} (bound {:.3g} of its magnitude against {:.3g}); exact arithmetic (--arith exact) decides this "
        "comparison",
        out.inconclusive_side,
        out.inconclusive_side == "both" ? "both sides' bounds are as wide" : "its error bound is the wider one",
        std::max(rel_l, rel_r), std::min(rel_l, rel_r));
  };
  const TrackedCase k = decide_tracked(l, r, res, scale);
  out.verdict = verdict_of(k);
  switch (k) {
    case TrackedCase::NonFinite:
      out.reason = "a side overflowed or is not a number in this precision";
      set_trust();
      break;
    case TrackedCase::Unbounded:
      out.reason = "the error bound is unbounded: a divisor is not distinguishable from zero in this precision";
      set_trust();
      break;
    case TrackedCase::TooWide:
      out.reason = fmt::format("agreement within the error bound, but the bound is {:.3g} relative: too wide to confirm",
                               out.relative_error_bound);
      set_trust();
      break;
    default: break;
  }
  return out;
}

}  // namespace

template <class T>
ComparisonOutcome judge(const Comparison<T>& c) {
  if constexpr (ScalarTraits<T>::is_exact) {
    return judge_exact(c);
  } else {
    return judge_tracked(c);
  }
}

template <class T>
Verdict judge_verdict(const Comparison<T>& c) {
  if (!c.lhs.has_value() || !c.rhs.has_value()) return Verdict::Undefined;
  if constexpr (ScalarTraits<T>::is_exact) {
    return cln::zerop(c.lhs.get() - c.rhs.get()) ? Verdict::Holds : Verdict::Fails;
  } else {
    const auto& l = c.lhs.get();
    const auto& r = c.rhs.get();
    return verdict_of(decide_tracked(l, r, l - r, judge_scale(l, r, c.scale)));
  }
}

namespace {
std::string tracked_rule(const std::string& name, int bits) {
  return fmt::format(
      "{} (unit roundoff u = 2^-{}) with running error bounds: every value carries a bound on its "
      "distance to the exact result (midpoint-radius arithmetic; inputs rounded from the exact scene). "
      "tolerance = bound(lhs) + bound(rhs), i.e. u times the condition of both evaluations. "
      "fails iff |lhs - rhs| > tolerance; inconclusive if tolerance > sqrt(u) max(|lhs|, |rhs|) (for one coefficient of a polynomial in "
      "the rates: its largest coefficient) or a "
      "bound is unbounded; holds otherwise",
      name, bits);
}
}  // namespace

template <class T>
std::string tolerance_rule() {
  if constexpr (ScalarTraits<T>::is_exact) {
    return "exact rational arithmetic: a claim holds iff lhs - rhs is exactly 0";
  } else {
    using F = decltype(T::v);
    const int p = TrackedTraits<F>::precision_bits();
    if constexpr (std::is_same_v<F, double>) {
      return tracked_rule("IEEE double", p);
    } else if constexpr (std::is_same_v<F, long double>) {
      return tracked_rule("x87 long double", p);
    } else {
      return tracked_rule(fmt::format("{} (CLN long float, {} bits, correctly rounded; error bounds kept with a "
                                      "wide exponent and rounded upward)",
                                      ScalarTraits<F>::name, p),
                          p);
    }
  }
}

// One instantiation per arithmetic of the claim tuple (claims/claim.h).
template ComparisonOutcome judge<Rational>(const Comparison<Rational>&);
template ComparisonOutcome judge<Tracked<double>>(const Comparison<Tracked<double>>&);
template ComparisonOutcome judge<Tracked<long double>>(const Comparison<Tracked<long double>>&);
template ComparisonOutcome judge<Tracked<MpFloat<30>>>(const Comparison<Tracked<MpFloat<30>>>&);
template ComparisonOutcome judge<Tracked<MpFloat<50>>>(const Comparison<Tracked<MpFloat<50>>>&);
template ComparisonOutcome judge<Tracked<MpFloat<100>>>(const Comparison<Tracked<MpFloat<100>>>&);
template ComparisonOutcome judge<Tracked<MpFloat<1000>>>(const Comparison<Tracked<MpFloat<1000>>>&);
template Verdict judge_verdict<Rational>(const Comparison<Rational>&);
template Verdict judge_verdict<Tracked<double>>(const Comparison<Tracked<double>>&);
template Verdict judge_verdict<Tracked<long double>>(const Comparison<Tracked<long double>>&);
template Verdict judge_verdict<Tracked<MpFloat<30>>>(const Comparison<Tracked<MpFloat<30>>>&);
template Verdict judge_verdict<Tracked<MpFloat<50>>>(const Comparison<Tracked<MpFloat<50>>>&);
template Verdict judge_verdict<Tracked<MpFloat<100>>>(const Comparison<Tracked<MpFloat<100>>>&);
template Verdict judge_verdict<Tracked<MpFloat<1000>>>(const Comparison<Tracked<MpFloat<1000>>>&);
template std::string tolerance_rule<Rational>();
template std::string tolerance_rule<Tracked<double>>();
template std::string tolerance_rule<Tracked<long double>>();
template std::string tolerance_rule<Tracked<MpFloat<30>>>();
template std::string tolerance_rule<Tracked<MpFloat<50>>>();
template std::string tolerance_rule<Tracked<MpFloat<100>>>();
template std::string tolerance_rule<Tracked<MpFloat<1000>>>();

}  // namespace linkproof
