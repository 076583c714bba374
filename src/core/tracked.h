// Tracked<F>: a floating-point number that carries a bound on its own error.
//
// A value x is represented by a midpoint v (computed in F) and a radius e such that the exact
// result of the same computation in real arithmetic lies in [v - e, v + e] (midpoint-radius
// arithmetic, as in Rump's INTLAB; Higham, "Accuracy and Stability of Numerical Algorithms",
// sec. 3.3 "running error analysis"). This is a theorem, not an estimate: every radius is
// computed with upward rounding (each operation on radii is rounded to nearest and then moved
// one float up, core/directed_rounding.h, or kept in WideBound, which rounds upward itself),
// and every rule below bounds the error of its operation on the exact operands plus the
// rounding of the midpoint. The argument, rule by rule, with underflow, overflow and the
// conversion of rational inputs, is in docs/verdicts.md, "Why the bound is rigorous".
//
// This is how linkproof derives floating-point tolerances: the tolerance of a comparison is the
// sum of the radii of its two sides, i.e. a condition estimate of the whole evaluation times u.
// A division by a number whose radius reaches its midpoint gives an unbounded radius: the
// verdict is then `inconclusive`, never a false `holds` or `fails`.
//
// The rules (a = va +- ea, b = vb +- eb, v the midpoint computed in F, every radius operation
// rounded upward):
//   a + b, a - b   e = (ea + eb) + sum_rounding_error(v)
//   a * b          e = |va| eb + (|vb| + eb) ea + rounding_error(v)       (exact: |ab - va vb|
//                      = |va db + (vb + db) da| with |da| <= ea, |db| <= eb)
//   a / b          e = (ea + quotient_magnitude(v) eb) / margin(vb, eb) + rounding_error(v),
//                      unbounded unless margin > 0                         (exact: |a/b - va/vb|
//                      <= (ea + |va/vb| eb) / (|vb| - eb))
//   -a, |a|        e = ea (exact)
// where a zero factor (va = 0 or vb = 0 in a * b, va = 0 in a / b) makes the midpoint an exact
// 0: its rounding_error, and the quotient's magnitude, are then 0.
// For IEEE F, + - and * first compute their radius in round-to-nearest and, where it is at least
// the least normal number, step up once for the whole rule (fast_radius: the rule's roundings
// are bounded a priori); only smaller radii take one upward step per operation.
//
// What Tracked needs of F is in TrackedTraits<F> (one template for every F, no per-type copy):
//   Radius                  the type of e: F itself for IEEE types; WideBound for MpFloat<D>
//                           (core/multiprecision.h), whose radius needs the midpoint's exponent
//                           range but not its precision
//   add_up, mul_up, div_up  radius operations rounded upward (never below the exact result)
//   unit_roundoff()         u = 2^-p, as a Radius
//   magnitude(v)            a Radius >= |v|
//   rounding_error(v)       a Radius >= |x - v| for v = F's rounding of any real x: u|v| rounded
//                           up, which also covers underflow (IEEE: next_up(RN(u|v|)) >= the least
//                           subnormal; CLN throws on underflow instead)
//   quotient_magnitude(v)   a Radius >= |x| for v = F's rounding of any real x (IEEE: next_up |v|)
//   margin(v, e)            a lower bound on |v| - e (a divisor's distance from zero)
//   is_positive(r)          r > 0
//   sum_rounding_error(v)   the same for v = F's rounding of a sum or difference (IEEE: 0 for
//                           v = 0, which is then exact; otherwise rounding_error(v))
//   is_zero(v)              v == 0 (a product with a zero factor, or a quotient of 0, is an
//                           exact 0 in every F)
//   unbounded(), is_unbounded(r)   the infinite radius (IEEE: +inf, also NaN from inf * 0)
//   has_infinity            whether F itself has inf/NaN (false for CLN: x / 0 throws)
//   abs(v)                  |v| in F, exact
//   radius_up(q)            a radius >= |q| for an exact rational q (an input's rounding error)
#pragma once

#include <cmath>
#include <concepts>
#include <limits>
#include <utility>

#include "core/directed_rounding.h"
#include "linkproof/core/exact.h"

namespace linkproof {

template <class F>
struct TrackedTraits;

/// Shared by the float and Tracked traits (core/scalar.h): IEEE types rounded from exact rationals.
template <class F>
F round_rational(const Rational& q);
template <>
double round_rational<double>(const Rational& q);
template <>
long double round_rational<long double>(const Rational& q);

/// IEEE double and long double: the radius is an F, every radius operation is rounded to
/// nearest by the hardware and then moved one float up (next_up), the margin one float down.
template <std::floating_point F>
struct TrackedTraits<F> {
  using Radius = F;
  static constexpr bool has_infinity = true;
  static constexpr int precision_bits() { return std::numeric_limits<F>::digits; }
  static constexpr F unit_roundoff() { return std::numeric_limits<F>::epsilon() / 2; }
  static F abs(F v) { return std::abs(v); }
  static F magnitude(F v) { return std::abs(v); }
  // An operand 0 makes the result exact (a + 0 = a, a * 0 = 0, 0 / b = 0), and then it is
  // returned as it is: next_up(0) would be the least subnormal, and arithmetic on subnormal
  // radii takes a microcode assist on x86 (about 70 ns an operation here, a dozen times a
  // normal one). Exact zeros are the common case: exact inputs carry the radius 0. A NaN
  // (inf * 0) is not 0 and still goes through next_up, which keeps it.
  static F add_up(F a, F b) {
    const F s = a + b;
    return (a == 0 || b == 0) ? s : next_up(s);
  }
  static F mul_up(F a, F b) {
    const F p = a * b;
    return (p == 0 && (a == 0 || b == 0)) ? F(0) : next_up(p);
  }
  static F div_up(F a, F b) {
    const F q = a / b;
    return (q == 0 && a == 0) ? F(0) : next_up(q);
  }
  /// |x - RN(x)| <= u |RN(x)| for a normal result, <= half the least subnormal otherwise; u|v|
  /// is exact unless it underflows, and next_up of it is >= both (next_up(0) = denorm_min).
  static F rounding_error(F v) { return next_up(unit_roundoff() * std::abs(v)); }
  /// With gradual underflow an IEEE sum or difference that rounds to 0 is exactly 0 (an
  /// underflowing sum is exact: Hauser, "Handling floating-point exceptions", 1996).
  static F sum_rounding_error(F v) { return v == 0 ? F(0) : rounding_error(v); }
  static bool is_zero(F v) { return v == 0; }
  /// The fast path of + - * (docs/verdicts.md, "One step up for a whole rule"): h is a rule's
  /// radius computed in round-to-nearest alone, from non-negative terms, with at most four
  /// roundings on any path and at most 2 denorm_min lost to underflow. If h is at least the
  /// least normal number, the exact radius is at most h (1 + 10u), so one step up from
  /// RN(h (1 + 16u)) bounds it: one next_up for the rule instead of one per operation.
  static bool fast_radius_applies(F h) { return h >= std::numeric_limits<F>::min(); }
  static F fast_radius(F h) { return next_up(h * (F(1) + 16 * unit_roundoff())); }
  /// No float lies strictly between RN(x) and x: |x| <= next_up(|RN(x)|).
  static F quotient_magnitude(F v) { return next_up(std::abs(v)); }
  /// |v| - e rounded down; 0 (not positive) when v is not finite.
  static F margin(F v, F e) { return std::isfinite(v) ? next_down(std::abs(v) - e) : F(0); }
  static bool is_positive(F r) { return r > 0; }
  static constexpr F unbounded() { return std::numeric_limits<F>::infinity(); }
  static bool is_unbounded(F r) { return !std::isfinite(r); }
  /// The least radius >= |q| (0 only for q = 0): q correctly rounded to F, one step up.
  /// Defined in the class: clang 14 rejects an out-of-line member of this constrained partial
  /// specialization (the fuzz build, docs/fuzzing.md).
  static F radius_up(const Rational& q) {
    if (cln::zerop(q)) return 0;
    return std::nextafter(round_rational<F>(cln::abs(q)), std::numeric_limits<F>::infinity());
  }
};

template <class F>
struct Tracked {
  using Traits = TrackedTraits<F>;
  using Radius = typename Traits::Radius;

  F v{};       ///< midpoint: the value computed in F
  Radius e{};  ///< radius: bound on |exact - v|

  static constexpr Radius unit_roundoff() { return Traits::unit_roundoff(); }

  Tracked() = default;
  Tracked(F value, Radius radius) : v(std::move(value)), e(std::move(radius)) {}
  /// A constant known exactly in F (e.g. small integers): radius 0.
  explicit Tracked(int exact_integer) : v(F(exact_integer)), e{} {}
};

namespace tracked_detail {
// The rules with one upward step per radius operation: every radius for CLN, and IEEE radii
// below the least normal number (rare). Kept out of line so that the fast path inlines.
template <class F>
[[gnu::noinline]] typename TrackedTraits<F>::Radius sum_radius(const Tracked<F>& a, const Tracked<F>& b, const F& v) {
  using T = TrackedTraits<F>;
  return T::add_up(T::add_up(a.e, b.e), T::sum_rounding_error(v));
}
template <class F>
[[gnu::noinline]] typename TrackedTraits<F>::Radius product_radius(const Tracked<F>& a, const Tracked<F>& b, const F& v) {
  using T = TrackedTraits<F>;
  // A zero factor makes the midpoint's product an exact 0.
  const bool exact = T::is_zero(a.v) || T::is_zero(b.v);
  return T::add_up(T::add_up(T::mul_up(T::magnitude(a.v), b.e), T::mul_up(T::add_up(T::magnitude(b.v), b.e), a.e)),
                   exact ? typename T::Radius{} : T::rounding_error(v));
}
}  // namespace tracked_detail

template <class F>
[[gnu::always_inline]] inline Tracked<F> operator+(const Tracked<F>& a, const Tracked<F>& b) {
  using T = TrackedTraits<F>;
  F v = a.v + b.v;
  if constexpr (std::floating_point<F>) {
    const F h = (a.e + b.e) + T::unit_roundoff() * std::abs(v);
    if (T::fast_radius_applies(h)) [[likely]] return {v, T::fast_radius(h)};  // a NaN falls through
    if (h == 0 && v == 0) return {v, F(0)};  // exact operands whose sum is an exact 0 (see sum_rounding_error)
  }
  auto e = tracked_detail::sum_radius(a, b, v);
  return {std::move(v), std::move(e)};
}
template <class F>
[[gnu::always_inline]] inline Tracked<F> operator-(const Tracked<F>& a) {
  return {-a.v, a.e};
}
/// a + (-b): negation is exact, and a - b and a + (-b) round to the same F.
template <class F>
[[gnu::always_inline]] inline Tracked<F> operator-(const Tracked<F>& a, const Tracked<F>& b) {
  return a + -b;
}
/// |ab - va vb| = |va db + (vb + db) da| <= |va| eb + (|vb| + eb) ea.
template <class F>
[[gnu::always_inline]] inline Tracked<F> operator*(const Tracked<F>& a, const Tracked<F>& b) {
  using T = TrackedTraits<F>;
  F v = a.v * b.v;
  if constexpr (std::floating_point<F>) {
    const F h = (std::abs(a.v) * b.e + (std::abs(b.v) + b.e) * a.e) + T::unit_roundoff() * std::abs(v);
    if (T::fast_radius_applies(h)) [[likely]] return {v, T::fast_radius(h)};
    // An exact 0 factor (radius 0) and a finite other one (h is then 0, not NaN): an exact 0.
    if (h == 0 && ((a.v == 0 && a.e == 0) || (b.v == 0 && b.e == 0))) return {v, F(0)};
  }
  auto e = tracked_detail::product_radius(a, b, v);
  return {std::move(v), std::move(e)};
}
/// |a/b - va/vb| <= (ea + |va/vb| eb) / (|vb| - eb) when eb < |vb|; otherwise unbounded.
template <class F>
Tracked<F> operator/(const Tracked<F>& a, const Tracked<F>& b) {
  using T = TrackedTraits<F>;
  using Radius = typename T::Radius;
  const auto margin = T::margin(b.v, b.e);
  if (!T::is_positive(margin)) {
    // The midpoint means nothing here; without infinities it must not divide by an exact 0.
    if constexpr (T::has_infinity) {
      return {a.v / b.v, T::unbounded()};
    } else {
      return {T::is_positive(T::magnitude(b.v)) ? a.v / b.v : F{}, T::unbounded()};
    }
  }
  F v = a.v / b.v;
  // 0 / b is an exact 0 (b's margin is positive, so b is not 0).
  const bool exact = T::is_zero(a.v);
  const auto spread = T::add_up(a.e, T::mul_up(exact ? Radius{} : T::quotient_magnitude(v), b.e));
  // Exact operands (IEEE; the common case of sampled coordinates) spread nothing: div_up would
  // return the 0 as it is, after a second division to wait for. A NaN spread is not 0.
  bool spreads = true;
  if constexpr (std::floating_point<F>) spreads = spread != 0;
  auto e = T::add_up(spreads ? T::div_up(spread, margin) : Radius{}, exact ? Radius{} : T::rounding_error(v));
  return {std::move(v), std::move(e)};
}
template <class F>
Tracked<F>& operator+=(Tracked<F>& a, const Tracked<F>& b) { return a = a + b; }
template <class F>
Tracked<F>& operator-=(Tracked<F>& a, const Tracked<F>& b) { return a = a - b; }
template <class F>
Tracked<F>& operator*=(Tracked<F>& a, const Tracked<F>& b) { return a = a * b; }
template <class F>
Tracked<F>& operator/=(Tracked<F>& a, const Tracked<F>& b) { return a = a / b; }

template <class F>
Tracked<F> abs(const Tracked<F>& a) {
  return {TrackedTraits<F>::abs(a.v), a.e};
}

}  // namespace linkproof
