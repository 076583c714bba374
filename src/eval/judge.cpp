#include <algorithm>
#include "linkproof/eval/judge.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>

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
  out.label = c.label;
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

template <class F>
ComparisonOutcome judge_tracked(const Comparison<Tracked<F>>& c) {
  ComparisonOutcome out;
  out.label = c.label;
  if (undefined_side(c, out)) return out;
  const Tracked<F>& l = c.lhs.get();
  const Tracked<F>& r = c.rhs.get();
  const Tracked<F> res = l - r;  // its radius is e_l + e_r plus the subtraction's rounding
  out.lhs = format_float(l.v);
  out.rhs = format_float(r.v);
  out.residual = format_float(res.v);
  out.tolerance = format_float(res.e);
  const F scale = std::max({std::abs(l.v), std::abs(r.v), static_cast<F>(c.scale)});
  out.relative_error_bound = scale > 0 ? static_cast<double>(res.e / scale) : (res.e == 0 ? 0.0 : HUGE_VAL);
  const F u = Tracked<F>::unit_roundoff();
  const auto condition = [u](const Tracked<F>& x) {
    return x.e == 0 ? 0.0 : (x.v == 0 ? HUGE_VAL : static_cast<double>(x.e / (u * std::abs(x.v))));
  };
  const double cond_l = condition(l), cond_r = condition(r);
  out.tolerance_derivation = fmt::format(
      "tolerance {} = bound(lhs) {:.3g} + bound(rhs) {:.3g} + rounding of lhs - rhs; each bound is a running "
      "error bound (inputs rounded from the exact scene, every operation's rounding), i.e. u times the "
      "evaluation's condition: condition(lhs) = {:.3g}, condition(rhs) = {:.3g}, u = 2^-{}",
      out.tolerance, static_cast<double>(l.e), static_cast<double>(r.e), cond_l, cond_r,
      std::numeric_limits<F>::digits);
  const auto set_trust = [&] {
    out.trust_route = fmt::format(
        "exact arithmetic (--arith exact) decides this comparison; in floating point trust the {} side "
        "(condition {:.3g} against {:.3g}): near a pole of the construction the closed forms and the direct "
        "solve keep full accuracy while the construction loses digits (SPEC A6)",
        cond_l <= cond_r ? "lhs" : "rhs", std::min(cond_l, cond_r), std::max(cond_l, cond_r));
  };
  if (!std::isfinite(l.v) || !std::isfinite(r.v) || !std::isfinite(res.v)) {
    out.verdict = Verdict::Inconclusive;
    out.reason = "a side overflowed or is not a number in this precision";
    set_trust();
  } else if (!std::isfinite(res.e)) {
    out.verdict = Verdict::Inconclusive;
    out.reason = "the error bound is unbounded: a divisor is not distinguishable from zero in this precision";
    set_trust();
  } else if (std::abs(res.v) > res.e) {
    out.verdict = Verdict::Fails;
  } else if (res.e > std::sqrt(u) * scale) {
    out.verdict = Verdict::Inconclusive;
    out.reason = fmt::format("agreement within the error bound, but the bound is {:.3g} relative: too wide to confirm",
                             out.relative_error_bound);
    set_trust();
  } else {
    out.verdict = Verdict::Holds;
  }
  return out;
}

}  // namespace

template <>
ComparisonOutcome judge<Rational>(const Comparison<Rational>& c) { return judge_exact(c); }
template <>
ComparisonOutcome judge<Tracked<double>>(const Comparison<Tracked<double>>& c) { return judge_tracked(c); }
template <>
ComparisonOutcome judge<Tracked<long double>>(const Comparison<Tracked<long double>>& c) { return judge_tracked(c); }

template <>
std::string tolerance_rule<Rational>() {
  return "exact rational arithmetic: a claim holds iff lhs - rhs is exactly 0";
}

namespace {
template <class F>
std::string tracked_rule(const char* name, int bits) {
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

template <>
std::string tolerance_rule<Tracked<double>>() { return tracked_rule<double>("IEEE double", 53); }
template <>
std::string tolerance_rule<Tracked<long double>>() {
  return tracked_rule<long double>("x87 long double", std::numeric_limits<long double>::digits);
}

}  // namespace linkproof
