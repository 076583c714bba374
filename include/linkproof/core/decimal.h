// Between exact rationals and decimal text or doubles, for reports and comparisons with data.
#pragma once

#include <string>

#include "linkproof/core/exact.h"

namespace linkproof {

/// q as a decimal with `digits` significant digits, rounded to nearest (e.g.
/// "-8.934593051317962575840725"; "1.00e-9" below 1e-5), or exactly when q is an integer.
/// For reports and messages.
std::string format_decimal(const Rational& q, int digits = 25);

/// The exact value of a finite double (a dyadic rational).
Rational rational_from_double(double x);

}  // namespace linkproof
