// The text of a result's numbers (core/result_number.h), made by the arithmetic's own
// formatter: exact "p/q", the shortest round-trip decimal of an IEEE value, every significant
// digit of a CLN float; a radius as a decimal that reads back to a bound ("2.5e-40", "inf").
#pragma once

#include <cstddef>
#include <string>

#include "linkproof/core/result_number.h"

namespace linkproof {

std::string number_text(const ResultNumber& x);

/// The default number of significant digits of the decimal shown beside an exact value.
inline constexpr int kReadableDigits = 10;
/// Exact fractions longer than this many characters are shown by their decimal and size.
inline constexpr size_t kLongFraction = 40;
/// An exact value as a person reads it: an integer as it is; "7331/2662 ≈ 2.753944403" (the
/// decimal to `digits` significant digits, trailing zeros dropped; "=" where the decimal is the
/// value, "7/20 = 0.35"); a fraction longer than kLongFraction characters by its decimal and its
/// size, "≈ 157.0796327 (exact: a fraction of 412 digits, see --json)". A float: number_text.
std::string readable_number(const ResultNumber& x, int digits = kReadableDigits);
std::string radius_text(const ResultRadius& r);
/// About 3 significant digits, for prose ("1.23e-1000"); not exact.
std::string radius_short_text(const ResultRadius& r);

}  // namespace linkproof
