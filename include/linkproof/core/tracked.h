// Tracked<F>: a floating-point number that carries a bound on its own error.
//
// A value x is represented by a midpoint v (computed in F) and a radius e such that the exact
// result of the same computation in real arithmetic lies in [v - e, v + e] (midpoint-radius
// arithmetic, as in Rump's INTLAB; Higham, "Accuracy and Stability of Numerical Algorithms",
// sec. 3.3 "running error analysis"). Each operation adds its own rounding error u|v|, where
// u = epsilon/2 is the unit roundoff of F, plus denorm_min for underflow, and the radius is
// inflated by (1 + 4u) to absorb the rounding of the radius computation itself.
//
// This is how linkproof derives floating-point tolerances: the tolerance of a comparison is the
// sum of the radii of its two sides, i.e. a condition estimate of the whole evaluation times u.
// A division by a number whose radius reaches its midpoint gives an infinite radius: the
// verdict is then `inconclusive`, never a false `holds` or `fails`.
#pragma once

#include <cmath>
#include <limits>

namespace linkproof {

template <class F>
struct Tracked {
  F v{};  ///< midpoint: the value computed in F
  F e{};  ///< radius: bound on |exact - v|

  static constexpr F unit_roundoff() { return std::numeric_limits<F>::epsilon() / 2; }

  Tracked() = default;
  Tracked(F value, F radius) : v(value), e(radius) {}
  /// A constant known exactly in F (e.g. small integers): radius 0.
  explicit Tracked(int exact_integer) : v(F(exact_integer)), e(0) {}

  /// Relative error bound e/|v| (infinite for v = 0 unless e = 0).
  F relative_bound() const {
    if (e == 0) return 0;
    return e / std::abs(v);
  }
  /// Condition estimate of the computation that produced this value: e / (u |v|).
  F condition_estimate() const { return relative_bound() / unit_roundoff(); }
};

namespace tracked_detail {
template <class F>
F rounded(F exact_part_error, F value) {
  const F u = Tracked<F>::unit_roundoff();
  return (exact_part_error + u * std::abs(value) + std::numeric_limits<F>::denorm_min()) *
         (F(1) + 4 * u);
}
}  // namespace tracked_detail

template <class F>
Tracked<F> operator+(const Tracked<F>& a, const Tracked<F>& b) {
  const F v = a.v + b.v;
  return {v, tracked_detail::rounded(a.e + b.e, v)};
}
template <class F>
Tracked<F> operator-(const Tracked<F>& a, const Tracked<F>& b) {
  const F v = a.v - b.v;
  return {v, tracked_detail::rounded(a.e + b.e, v)};
}
template <class F>
Tracked<F> operator-(const Tracked<F>& a) {
  return {-a.v, a.e};
}
template <class F>
Tracked<F> operator*(const Tracked<F>& a, const Tracked<F>& b) {
  const F v = a.v * b.v;
  return {v, tracked_detail::rounded(std::abs(a.v) * b.e + std::abs(b.v) * a.e + a.e * b.e, v)};
}
/// |a/b - va/vb| <= (ea + |va/vb| eb) / (|vb| - eb) when eb < |vb|; otherwise unbounded.
template <class F>
Tracked<F> operator/(const Tracked<F>& a, const Tracked<F>& b) {
  const F v = a.v / b.v;
  const F margin = std::abs(b.v) - b.e;
  if (!(margin > 0)) return {v, std::numeric_limits<F>::infinity()};
  return {v, tracked_detail::rounded((a.e + std::abs(v) * b.e) / margin, v)};
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
  return {std::abs(a.v), a.e};
}

}  // namespace linkproof
