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
//   a + b, a - b   e = (ea + eb) + rounding_error(v)
//   a * b          e = |va| eb + (|vb| + eb) ea + rounding_error(v)       (exact: |ab - va vb|
//                      = |va db + (vb + db) da| with |da| <= ea, |db| <= eb)
//   a / b          e = (ea + quotient_magnitude(v) eb) / margin(vb, eb) + rounding_error(v),
//                      unbounded unless margin > 0                         (exact: |a/b - va/vb|
//                      <= (ea + |va/vb| eb) / (|vb| - eb))
//   -a, |a|        e = ea (exact)
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
  static F add_up(F a, F b) { return next_up(a + b); }
  static F mul_up(F a, F b) { return next_up(a * b); }
  static F div_up(F a, F b) { return next_up(a / b); }
  /// |x - RN(x)| <= u |RN(x)| for a normal result, <= half the least subnormal otherwise; u|v|
  /// is exact unless it underflows, and next_up of it is >= both (next_up(0) = denorm_min).
  static F rounding_error(F v) { return next_up(unit_roundoff() * std::abs(v)); }
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
/// The radius of a result v whose operands contribute exact_part_error (already rounded up):
/// that error plus v's own rounding error, rounded up.
template <class F>
typename TrackedTraits<F>::Radius rounded(const typename TrackedTraits<F>::Radius& exact_part_error, const F& value) {
  using T = TrackedTraits<F>;
  return T::add_up(exact_part_error, T::rounding_error(value));
}
}  // namespace tracked_detail

template <class F>
Tracked<F> operator+(const Tracked<F>& a, const Tracked<F>& b) {
  using T = TrackedTraits<F>;
  F v = a.v + b.v;
  auto e = tracked_detail::rounded(T::add_up(a.e, b.e), v);
  return {std::move(v), std::move(e)};
}
template <class F>
Tracked<F> operator-(const Tracked<F>& a, const Tracked<F>& b) {
  using T = TrackedTraits<F>;
  F v = a.v - b.v;
  auto e = tracked_detail::rounded(T::add_up(a.e, b.e), v);
  return {std::move(v), std::move(e)};
}
template <class F>
Tracked<F> operator-(const Tracked<F>& a) {
  return {-a.v, a.e};
}
/// |ab - va vb| = |va db + (vb + db) da| <= |va| eb + (|vb| + eb) ea.
template <class F>
Tracked<F> operator*(const Tracked<F>& a, const Tracked<F>& b) {
  using T = TrackedTraits<F>;
  F v = a.v * b.v;
  auto e = tracked_detail::rounded(
      T::add_up(T::mul_up(T::magnitude(a.v), b.e), T::mul_up(T::add_up(T::magnitude(b.v), b.e), a.e)), v);
  return {std::move(v), std::move(e)};
}
/// |a/b - va/vb| <= (ea + |va/vb| eb) / (|vb| - eb) when eb < |vb|; otherwise unbounded.
template <class F>
Tracked<F> operator/(const Tracked<F>& a, const Tracked<F>& b) {
  using T = TrackedTraits<F>;
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
  auto e = tracked_detail::rounded(T::div_up(T::add_up(a.e, T::mul_up(T::quotient_magnitude(v), b.e)), margin), v);
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
