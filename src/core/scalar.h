// Arithmetic as a parameter: what generic evaluation code needs to know about a number type.
//
// Every algorithm in linkproof that computes with numbers is a template over a scalar T and
// uses only +, -, *, / and the functions below; ScalarTraits<T> supplies the rest.
// Supported now:
//   Rational          exact (CLN cl_RA): a residual is zero or it is not;
//   InlineRational    the same values, held in two machine words while they fit
//                     (inline_rational.h): the scalar of the exact arithmetic;
//   double, long double  plain IEEE, for speed (no verdicts are drawn from these);
//   Tracked<double>, Tracked<long double>, Tracked<MpFloat<D>>  with a running error bound
//                     (see tracked.h), used for floating-point verdicts;
//   MpFloat<Digits>   CLN long floats at a fixed precision (multiprecision.h).
// Besides conversion and printing, every trait has less(a, b) (an order, for pivoting; Tracked
// compares midpoints) and to_rational(x) (the exact value of a float, for measuring errors).
#pragma once

#include <cmath>
#include <concepts>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>

#include "linkproof/core/exact.h"
#include "core/tracked.h"

namespace linkproof {

template <class T>
struct ScalarTraits;

template <>
struct ScalarTraits<Rational> {
  static constexpr bool is_exact = true;
  static constexpr bool has_error_bound = false;
  static constexpr std::string_view name = "exact";
  static Rational from_rational(const Rational& q) { return q; }
  static bool is_zero(const Rational& x) { return cln::zerop(x); }
  static Rational abs(const Rational& x) { return cln::abs(x); }
  static bool less(const Rational& a, const Rational& b) { return a < b; }
  static Rational to_rational(const Rational& x) { return x; }
  static double to_double(const Rational& x) { return cln::double_approx(x); }
  static std::string to_string(const Rational& x) { return format_rational(x); }
};

/// The exact rational value of a finite IEEE number (every binary float is a dyadic rational).
template <class F>
Rational exact_value_of(F x);

/// Shortest decimal form that reads back to the same F ("%.17g" for double).
template <class F>
std::string format_float(F x);

template <std::floating_point F>
struct ScalarTraits<F> {
  static constexpr bool is_exact = false;
  static constexpr bool has_error_bound = false;
  static constexpr std::string_view name = sizeof(F) == sizeof(double) ? "double" : "long double";
  static F from_rational(const Rational& q) { return round_rational<F>(q); }
  static bool is_zero(F x) { return x == 0; }
  static F abs(F x) { return std::abs(x); }
  static bool less(F a, F b) { return a < b; }
  static Rational to_rational(F x) { return exact_value_of(x); }
  static double to_double(F x) { return static_cast<double>(x); }
  static std::string to_string(F x) { return format_float(x); }
};

/// Any Tracked<F> whose F has ScalarTraits: values are those of the midpoint.
template <class F>
struct ScalarTraits<Tracked<F>> {
  using Traits = TrackedTraits<F>;
  static constexpr bool is_exact = false;
  static constexpr bool has_error_bound = true;
  static constexpr std::string_view name = ScalarTraits<F>::name;
  /// The midpoint is q rounded to F; the radius is the exact rounding error |q - v|, rounded up.
  static Tracked<F> from_rational(const Rational& q);
  /// Only an exactly zero midpoint with zero radius counts as zero: a construction divides by
  /// anything else and lets the radius say how much the result can be trusted.
  static bool is_zero(const Tracked<F>& x) { return ScalarTraits<F>::is_zero(x.v) && x.e == typename Traits::Radius{}; }
  static Tracked<F> abs(const Tracked<F>& x) { return linkproof::abs(x); }
  static bool less(const Tracked<F>& a, const Tracked<F>& b) { return ScalarTraits<F>::less(a.v, b.v); }
  static Rational to_rational(const Tracked<F>& x) { return ScalarTraits<F>::to_rational(x.v); }
  static double to_double(const Tracked<F>& x) { return ScalarTraits<F>::to_double(x.v); }
  static std::string to_string(const Tracked<F>& x) { return ScalarTraits<F>::to_string(x.v); }
};

/// q = p/d with |p|, d < 2^53 (both exact in double), or false: the fast path of from_rational.
bool as_small_fraction(const Rational& q, double& p, double& d);

/// p/d (|p|, d < 2^53, d > 0, both exact in double) as a Tracked<double>. The IEEE quotient is
/// correctly rounded; the remainder p - v d of a correctly rounded quotient is a double (no
/// underflow: |v| >= 2^-53) and fma computes it exactly, so |p/d - v| = |r| / d, rounded up.
inline Tracked<double> tracked_from_small_fraction(double p, double d) {
  if (d == 1) return {p, 0.0};  // an integer (most sampled coordinates): no division to wait for
  const double v = p / d;
  const double r = std::fma(-v, d, p);
  return {v, r == 0 ? 0.0 : next_up(std::abs(r) / d)};
}

template <class F>
Tracked<F> ScalarTraits<Tracked<F>>::from_rational(const Rational& q) {
  if constexpr (std::is_same_v<F, double>) {
    // Coordinates and rates of scenes are mostly such fractions: no exact arithmetic.
    double p = 0, d = 1;
    if (as_small_fraction(q, p, d)) return tracked_from_small_fraction(p, d);
  }
  F v = ScalarTraits<F>::from_rational(q);
  if constexpr (Traits::has_infinity) {
    if (!std::isfinite(v)) return {v, Traits::unbounded()};
  }
  const Rational err = cln::abs(q - ScalarTraits<F>::to_rational(v));
  auto e = Traits::radius_up(err);
  return {std::move(v), std::move(e)};
}

/// Shorthands used by generic code.
template <class T>
T from_rational(const Rational& q) { return ScalarTraits<T>::from_rational(q); }

/// True for Tracked<double> and Tracked<long double>.
template <class T>
inline constexpr bool is_tracked_ieee = false;
template <std::floating_point F>
inline constexpr bool is_tracked_ieee<Tracked<F>> = true;

/// k in T. In an IEEE type, bare or tracked, an integer of at most 53 bits (every constant
/// linkproof uses) is exact and converted directly, to the same value (and, tracked, the same
/// zero radius) as through a Rational but without its cost: the claim evaluator makes a 1 for
/// every rate variable it reads, and the exact conversion (a rational division, then the
/// exact value of the result to bound its error) was half of a `check --arith double`.
template <class T>
T from_int(long k) {
  constexpr long exact = 1L << 53;
  if constexpr (std::floating_point<T>) {
    if (-exact <= k && k <= exact) return static_cast<T>(k);
  } else if constexpr (is_tracked_ieee<T>) {
    if (-exact <= k && k <= exact) return T(static_cast<decltype(T{}.v)>(k), typename T::Radius{});
  } else if constexpr (requires { ScalarTraits<T>::from_int64(k); }) {
    return ScalarTraits<T>::from_int64(k);
  }
  return ScalarTraits<T>::from_rational(Rational(k));
}
/// p/d in T (d > 0), the same value as from_rational<T>(Rational(p) / d); for Tracked<double>
/// without exact arithmetic (random configurations draw such fractions by the thousand).
template <class T>
T from_fraction(long p, long d) {
  constexpr long exact = 1L << 53;
  if constexpr (std::is_same_v<T, Tracked<double>>) {
    if (-exact < p && p < exact && 0 < d && d < exact)
      return tracked_from_small_fraction(static_cast<double>(p), static_cast<double>(d));
  }
  if constexpr (requires { ScalarTraits<T>::from_fraction(p, d); }) return ScalarTraits<T>::from_fraction(p, d);
  if (d == 1) return from_int<T>(p);
  return ScalarTraits<T>::from_rational(Rational(p) / Rational(d));
}
template <class T>
bool is_zero(const T& x) { return ScalarTraits<T>::is_zero(x); }
template <class T>
T abs_value(const T& x) { return ScalarTraits<T>::abs(x); }
template <class T>
std::string to_text(const T& x) { return ScalarTraits<T>::to_string(x); }
template <class T>
bool is_less(const T& a, const T& b) { return ScalarTraits<T>::less(a, b); }
template <class T>
Rational to_exact(const T& x) { return ScalarTraits<T>::to_rational(x); }

}  // namespace linkproof
