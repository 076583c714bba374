// Tracked<F>: a floating-point number that carries a bound on its own error.
//
// A value x is represented by a midpoint v (computed in F) and a radius e such that the exact
// result of the same computation in real arithmetic lies in [v - e, v + e] (midpoint-radius
// arithmetic, as in Rump's INTLAB; Higham, "Accuracy and Stability of Numerical Algorithms",
// sec. 3.3 "running error analysis"). Each operation adds its own rounding error u|v|, where
// u = 2^-p is the unit roundoff of F (p mantissa bits, rounding to nearest), plus a tiny
// absolute term for underflow, and the radius computation itself is rounded upward.
//
// This is how linkproof derives floating-point tolerances: the tolerance of a comparison is the
// sum of the radii of its two sides, i.e. a condition estimate of the whole evaluation times u.
// A division by a number whose radius reaches its midpoint gives an unbounded radius: the
// verdict is then `inconclusive`, never a false `holds` or `fails`.
//
// What Tracked needs of F is in TrackedTraits<F> (one template for every F, no per-type copy):
//   Radius                  the type of e: F itself for IEEE types; WideBound for MpFloat<D>
//                           (core/multiprecision.h), whose radius needs the midpoint's exponent
//                           range but not its precision
//   unit_roundoff()         u = 2^-p, as a Radius
//   magnitude(v)            |v| as a Radius, never below |v|
//   underflow_term()        absolute error an operation can add by underflowing: denorm_min
//                           for IEEE (gradual underflow); for CLN, 0 while CLN throws on
//                           underflow (its default), least_positive_float otherwise
//   finish(r)               r made safe against the rounding of the radius computation: times
//                           (1 + 4u) for IEEE (computed in F, rounded to nearest); identity
//                           for a radius type that rounds every operation upward
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

#include "linkproof/core/exact.h"

namespace linkproof {

template <class F>
struct TrackedTraits;

/// IEEE float, double, long double: the radius is computed in F itself.
template <std::floating_point F>
struct TrackedTraits<F> {
  using Radius = F;
  static constexpr bool has_infinity = true;
  static constexpr int precision_bits() { return std::numeric_limits<F>::digits; }
  static constexpr F unit_roundoff() { return std::numeric_limits<F>::epsilon() / 2; }
  static F abs(F v) { return std::abs(v); }
  static F magnitude(F v) { return std::abs(v); }
  static constexpr F underflow_term() { return std::numeric_limits<F>::denorm_min(); }
  static F finish(F r) { return r * (F(1) + 4 * unit_roundoff()); }
  static F margin(F v, F e) { return std::abs(v) - e; }
  static bool is_positive(F r) { return r > 0; }
  static constexpr F unbounded() { return std::numeric_limits<F>::infinity(); }
  static bool is_unbounded(F r) { return !std::isfinite(r); }
  /// The least radius >= |q| (0 only for q = 0): q rounded to F, one ulp up (core/scalar.h).
  static F radius_up(const Rational& q);
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
/// The radius of a result v whose operands contribute exact_part_error: that error, plus v's
/// own rounding u|v|, plus underflow, made safe against the rounding of this computation.
template <class F>
typename TrackedTraits<F>::Radius rounded(const typename TrackedTraits<F>::Radius& exact_part_error, const F& value) {
  using T = TrackedTraits<F>;
  return T::finish(exact_part_error + T::unit_roundoff() * T::magnitude(value) + T::underflow_term());
}
}  // namespace tracked_detail

template <class F>
Tracked<F> operator+(const Tracked<F>& a, const Tracked<F>& b) {
  F v = a.v + b.v;
  auto e = tracked_detail::rounded(a.e + b.e, v);
  return {std::move(v), std::move(e)};
}
template <class F>
Tracked<F> operator-(const Tracked<F>& a, const Tracked<F>& b) {
  F v = a.v - b.v;
  auto e = tracked_detail::rounded(a.e + b.e, v);
  return {std::move(v), std::move(e)};
}
template <class F>
Tracked<F> operator-(const Tracked<F>& a) {
  return {-a.v, a.e};
}
template <class F>
Tracked<F> operator*(const Tracked<F>& a, const Tracked<F>& b) {
  using T = TrackedTraits<F>;
  F v = a.v * b.v;
  auto e = tracked_detail::rounded(T::magnitude(a.v) * b.e + T::magnitude(b.v) * a.e + a.e * b.e, v);
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
  auto e = tracked_detail::rounded((a.e + T::magnitude(v) * b.e) / margin, v);
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
