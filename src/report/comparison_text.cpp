#include "report/comparison_text.h"

#include <fmt/format.h>

#include <algorithm>

#include "report/number_text.h"
#include "check/arithmetic_types.h"

namespace linkproof {

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

std::string side_sentence(Side s) {
  return s == Side::Both ? "both sides' error bounds are as wide" : "its error bound is the wider one";
}

std::string text_or_empty(const std::optional<ResultNumber>& x, NumberStyle style, int digits) {
  return x ? styled_number(*x, style, digits) : "";
}

}  // namespace

std::string styled_number(const ResultNumber& x, NumberStyle style, int digits) {
  switch (style) {
    case NumberStyle::Readable: return readable_number(x, digits);
    case NumberStyle::Compact: return compact_number(x, digits);
    case NumberStyle::Exact: break;
  }
  return number_text(x);
}

std::string lhs_text(const ComparisonOutcome& c, NumberStyle style, int digits) {
  return text_or_empty(c.lhs, style, digits);
}
std::string rhs_text(const ComparisonOutcome& c, NumberStyle style, int digits) {
  return text_or_empty(c.rhs, style, digits);
}
std::string residual_text(const ComparisonOutcome& c, NumberStyle style, int digits) {
  return text_or_empty(c.residual, style, digits);
}
std::string tolerance_text(const ComparisonOutcome& c) { return c.floating ? radius_text(c.floating->tolerance) : ""; }

std::string tolerance_rule(Arithmetic a) {
  return with_scalar_type(a, []<class T>() -> std::string {
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
  });
}

std::string tolerance_derivation_text(const ComparisonOutcome& c) {
  if (!c.floating) return "";
  const FloatEvidence& f = *c.floating;
  return fmt::format(
      "tolerance {} = bound(lhs) {} + bound(rhs) {} + rounding of lhs - rhs; each bound is a running "
      "error bound (inputs rounded from the exact scene, every operation's rounding), i.e. u times the "
      "evaluation's condition: condition(lhs) = {:.3g}, condition(rhs) = {:.3g}, u = 2^-{}",
      radius_text(f.tolerance), radius_short_text(f.bound_lhs), radius_short_text(f.bound_rhs), f.condition_lhs,
      f.condition_rhs, f.precision_bits);
}

std::string reason_text(const ComparisonOutcome& c) {
  if (!c.reason.empty() || !c.floating) return c.reason;
  switch (c.floating->undecided) {
    case Undecided::NonFinite: return "a side overflowed or is not a number in this precision";
    case Undecided::Unbounded:
      return "the error bound is unbounded: a divisor is not distinguishable from zero in this precision";
    case Undecided::TooWide:
      return fmt::format("agreement within the error bound, but the bound is {:.3g} relative: too wide to confirm",
                         c.floating->relative_error_bound);
    case Undecided::None: break;
  }
  return "";
}

std::string trust_route_text(const ComparisonOutcome& c) {
  if (!c.floating || c.floating->wider_side == Side::None) return "";
  const FloatEvidence& f = *c.floating;
  const std::string side(to_string(f.wider_side));
  if (c.cause) return side + ": " + side_sentence(f.wider_side) + "; " + cause_text(*c.cause);
  return fmt::format(
      "{}: {} (bound {:.3g} of its magnitude against {:.3g}); exact arithmetic (--arith exact) decides this comparison",
      side, side_sentence(f.wider_side), f.relative_wide, f.relative_narrow);
}

std::string inconclusive_quantity(const ComparisonOutcome& c) {
  return c.cause && c.cause->kind != InconclusiveCause::Kind::OwnArithmetic ? c.cause->quantity : "";
}

std::string cause_text(const InconclusiveCause& cause) {
  if (cause.kind != InconclusiveCause::Kind::OwnArithmetic) {
    const std::string quantity = fmt::format(
        "the quantity: {}, whose error bound is {:.3g} of its magnitude (beyond sqrt(u), the judge's limit): ",
        cause.quantity, cause.relative_bound);
    if (cause.kind == InconclusiveCause::Kind::DeadCentre)
      return quantity +
             "near the dead centre every route divides by D (omega ~ 1/D, omega-dot ~ 1/D^3, docs/conventions.md §A6), "
             "so no floating-point route is better; exact arithmetic (--arith exact) or a longer precision (--arith "
             "mp1000) decides";
    return quantity +
           "the construction loses digits near its pole (docs/conventions.md §A6) while the closed forms and the engine "
           "keep full accuracy; exact arithmetic (--arith exact) decides";
  }
  return fmt::format(
      "no quantity the claim reads has an error bound beyond sqrt(u) of its magnitude{}: the digits were lost in the claim's "
      "own arithmetic (cancellation between its terms); exact arithmetic (--arith exact) or a longer precision decides",
      cause.quantity.empty() ? std::string() : fmt::format(" (the widest is {}, {:.3g} of it)", cause.quantity, cause.relative_bound));
}

}  // namespace linkproof
