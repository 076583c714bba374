// Exact rational numbers (CLN cl_RA): parsing from scene text and printing as "p/q".
#pragma once

#include <cln/rational.h>
#include <string>
#include <string_view>

namespace linkproof {

using Rational = cln::cl_RA;

/// Parses an exact number. Accepted forms: an integer ("-12"), a fraction ("-7/3"), a decimal
/// read as the exact decimal fraction ("0.1" is 1/10, "2.5e-3" is 1/400).
/// Throws std::invalid_argument with a short description of what is wrong (the caller adds
/// file and field). NaN, infinities, hexadecimal and exponents beyond +-4000 are rejected.
Rational parse_rational(std::string_view text);

/// Reduced "p/q"; integers without "/1" (the JSON contract's spelling).
std::string format_rational(const Rational& q);

/// q as a decimal with `digits` significant digits, rounded to nearest (e.g.
/// "-8.934593051317962575840725"; "1.00e-9" below 1e-5), or exactly when q is an integer.
std::string format_decimal(const Rational& q, int digits = 25);

/// The exact value of a finite double (a dyadic rational).
Rational rational_from_double(double x);

/// The double nearest to q (ties to even); +-inf beyond double's range. For callers that want
/// plain doubles of exact values without CLN's API.
double nearest_double(const Rational& q);

}  // namespace linkproof
