// The angular accelerations of sides n-1 and n-2 as fractions of polynomials,
//     omega-dot_{n-1,n} = P_{n-1} / D^3,   omega-dot_{n-2,n} = P_{n-2} / D^3,   D = r_{n-2} x r_{n-1},
// written division-free. The adaptive mode's first stage (numerics/adaptive.h) bounds the O(n) sums
// (the parts below) a priori (core/a_priori_bound.h), where the bound is tight, and combines the
// eight parts in running-error arithmetic (core/tracked.h), where an a priori bound of a product
// of nearly cancelling factors would be far too wide (it multiplies the factors' shadows).
//
// Derivation (docs/conventions.md §A2, sides r_j, a = r_{n-2}, b = r_{n-1}, J the rotation by +90 degrees,
// J^-1 = -J). Velocities: sum_j omega_j J r_j = 0 gives a w_{n-2} + b w_{n-1} = s with
//     s = -sum_{j<=n-3} w_j r_j,   so  w_{n-2} = X0 / D, w_{n-1} = X1 / D,  X0 = s x b, X1 = a x s.
// Accelerations: sum_j (omegadot_j J r_j - omega_j^2 r_j) = 0 gives
//     a wd_{n-2} + b wd_{n-1} = t = h - J (g + w_{n-2}^2 a + w_{n-1}^2 b),
//     g = sum_{j<=n-3} w_j^2 r_j,   h = -sum_{j<=n-3} wd_j r_j,
// and with a x (J v) = a . v, (J v) x b = -(v . b), Cramer's rule, multiplied through by D^3:
//     P_{n-1} = D^2 (a x h - a . g) - X0^2 |a|^2 - X1^2 (a . b)
//     P_{n-2} = D^2 (h x b + g . b) + X0^2 (a . b) + X1^2 |b|^2.
// These are eq. (22) and its companion with the closed-form coefficients of docs/conventions.md §A3 multiplied by
// D^3; tests check them exactly against the direct solve of the loop closure.
#pragma once

#include "linkproof/geometry/vec2.h"

namespace linkproof {

/// The O(n) sums reduced to eight numbers, from which the fraction takes O(1) more operations:
/// D, X0, X1, A_{n-1} = a x h - a . g, A_{n-2} = h x b + g . b, |a|^2, |b|^2, a . b.
template <class T>
struct OmegaDotParts {
  T d, x0, x1, a_n1, a_n2, norm_a, norm_b, a_dot_b;
};

/// Numerators and the common denominator D^3 (see the file comment).
template <class T>
struct OmegaDotFraction {
  T numerator_n1;  ///< P_{n-1} = D^2 A_{n-1} - X0^2 |a|^2 - X1^2 (a . b)
  T numerator_n2;  ///< P_{n-2} = D^2 A_{n-2} + X0^2 (a . b) + X1^2 |b|^2
  T denominator;   ///< D^3
};

/// The parts from any source of data: side(j) gives r_j (j = 1..n-1) and rates(k, w, wd) sets
/// omega_{k+1,n}, omega-dot_{k+1,n} (k = 0..n-4), as for direct_solve_core (numerics/routes.h).
/// Only +, -, * on T; zero is T{} (see core/a_priori_bound.h for why no constant is rounded).
template <class T, class SideFn, class RatesFn>
OmegaDotParts<T> compute_omega_dot_parts(int n, const SideFn& side, const RatesFn& rates) {
  Vec2<T> s{T{}, T{}}, g = s, h = s;
  for (int j = 1; j <= n - 3; ++j) {
    const Vec2<T> r = side(j);
    T w, wd;
    rates(j - 1, w, wd);
    s = s - w * r;
    g = g + (w * w) * r;
    h = h - wd * r;
  }
  const Vec2<T> a = side(n - 2), b = side(n - 1);
  return {cross(a, b),         cross(s, b), cross(a, s), cross(a, h) - dot(a, g), cross(h, b) + dot(g, b),
          norm2(a),            norm2(b),    dot(a, b)};
}

/// The fraction from its parts: O(1) operations.
template <class T>
OmegaDotFraction<T> combine_omega_dot_parts(const OmegaDotParts<T>& p) {
  const T d2 = p.d * p.d, x0_2 = p.x0 * p.x0, x1_2 = p.x1 * p.x1;
  return {d2 * p.a_n1 - (x0_2 * p.norm_a + x1_2 * p.a_dot_b), d2 * p.a_n2 + (x0_2 * p.a_dot_b + x1_2 * p.norm_b),
          d2 * p.d};
}

/// The whole fraction (parts, then combined).
template <class T, class SideFn, class RatesFn>
OmegaDotFraction<T> compute_omega_dot_fraction(int n, const SideFn& side, const RatesFn& rates) {
  return combine_omega_dot_parts(compute_omega_dot_parts<T>(n, side, rates));
}

}  // namespace linkproof
