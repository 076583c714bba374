// How far a computed value is from the exact one, in the units a numerical analyst reads:
// relative error, correct bits, and error in ulps of the arithmetic that computed it
// (Herbie's "bits of error" = log2(1 + ulps)).
//
// Everything is computed exactly from the computed value's exact rational value
// (ScalarTraits<T>::to_rational), then logarithms are taken, so errors far below double's
// range (a 1000-digit evaluation errs by ~1e-1000) are measured, not flushed to zero.
#pragma once

#include <limits>
#include <string>

#include "core/scalar.h"
#include "linkproof/core/exact.h"

namespace linkproof {

struct ErrorMeasure {
  /// log2 |computed - exact| / |exact|: -infinity if exact; for exact = 0, the absolute error.
  double log2_relative_error = -std::numeric_limits<double>::infinity();
  /// -log2 of the relative error, capped at the arithmetic's precision p (p for an exact result).
  double correct_bits = 0;
  /// log2(1 + |computed - exact| / ulp_p(exact)): 0 when the result is exact, about 1 when it is
  /// within an ulp of the arithmetic, p when no digit is right. 0 for exact arithmetic (p = 0).
  double error_bits = 0;
};

/// log2 |q| for a nonzero rational, accurate to double precision whatever the size of q;
/// -infinity for q = 0.
double log2_abs(const Rational& q);

/// Measures `computed` (an exact rational value of a float of p bits; p = 0 for exact
/// arithmetic) against `exact`.
ErrorMeasure measure_error(const Rational& computed, const Rational& exact, int precision_bits);

/// "3.2e-17", "1.0e-1002", "0": a relative error given by its log2, in decimal scientific form
/// (works below double's range).
std::string format_log2_as_decimal(double log2_value);

}  // namespace linkproof
