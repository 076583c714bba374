// The numbers of a result, as values: an exact rational, or a floating-point midpoint in the
// precision that computed it, with its rigorous radius kept apart (core/tracked.h). Results
// carry these instead of text; report/number_text.h makes their text (the same text the
// arithmetic's own formatter makes: exact "p/q", shortest round-trip decimals for IEEE types,
// every significant digit of a CLN float).
#pragma once

#include <cln/float.h>

#include <variant>

#include "linkproof/core/exact.h"
#include "linkproof/core/wide_bound.h"

namespace linkproof {

template <class F>
struct Tracked;  // midpoint-radius arithmetic (inside the library): {v, e} with |exact - v| <= e

/// A number of a result: exact (Rational), or the midpoint of a floating-point value in its own
/// type (double, long double, a CLN float of the multiprecision arithmetic's format).
using ResultNumber = std::variant<Rational, double, long double, cln::cl_F>;

/// A rigorous bound on a floating-point value's distance to the exact one, in the radius type of
/// its arithmetic (double and long double for IEEE types, WideBound for multiprecision).
using ResultRadius = std::variant<double, long double, WideBound>;

/// True for an exact rational.
inline bool is_exact(const ResultNumber& x) { return std::holds_alternative<Rational>(x); }

/// The result number of a value of an arithmetic: the rational itself, or a Tracked value's
/// midpoint (its radius is evidence, kept apart where it is needed).
inline ResultNumber result_number(const Rational& x) { return x; }
inline ResultNumber result_number(double x) { return x; }
inline ResultNumber result_number(long double x) { return x; }
/// A multiprecision float (MpFloat<D>): its CLN float, in its own format.
template <class M>
  requires requires(const M& m) { cln::cl_F(m.value()); }
ResultNumber result_number(const M& x) {
  return cln::cl_F(x.value());
}
template <class F>
ResultNumber result_number(const Tracked<F>& x) {
  if constexpr (requires { x.v.value(); }) {
    return cln::cl_F(x.v.value());  // MpFloat<D>: its CLN float, in its own format
  } else {
    return x.v;
  }
}

/// The value as the nearest double (a rational or a CLN float out of double's range: +-inf or 0).
double to_double(const ResultNumber& x);
/// The radius as a double rounded upward (+inf where it exceeds double's range or is unbounded).
double to_double_up(const ResultRadius& r);

}  // namespace linkproof
