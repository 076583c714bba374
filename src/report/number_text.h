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

/// The decimal alone, as readable_number shows it: `digits` significant digits, rounded to
/// nearest, trailing zeros dropped ("2.821187077", "0.35", "-22", "3.333333333e399"). A float:
/// number_text. The JSON's `<key>_decimal` members beside exact values are this text.
std::string decimal_text(const ResultNumber& x, int digits = kReadableDigits);

/// Whether x is an exact fraction longer than kLongFraction characters (readable_number shows it
/// by its decimal and size).
bool is_long_fraction(const ResultNumber& x);

/// The count of decimal digits of an exact value's "p/q" text (numerator and denominator).
size_t fraction_digits(const ResultNumber& x);

/// The mark a table cell puts after a long fraction's decimal (compact_number).
inline constexpr const char* kLongFractionMark = "*";

/// A table cell's form of readable_number: the same for integers and short fractions
/// ("3755/1331 ≈ 2.821187077"); a long exact fraction by its decimal and a mark,
/// "≈ -209.4395102*", so that the columns stay narrow. A table with marked cells puts
/// long_fraction_note under it once. A float: number_text.
std::string compact_number(const ResultNumber& x, int digits = kReadableDigits);

/// The note under a table that has marked cells: "* a long exact fraction (more than 40
/// characters), shown by its decimal to 10 significant digits; every exact value: <where>".
/// `where` names how to get them ("--json", "linkproof check SCENE --json").
std::string long_fraction_note(int digits = kReadableDigits, const std::string& where = "--json");

/// The cells of one text table: compact_number for each value, remembering whether any was a
/// long fraction, so that the table's note is printed once under it, and only when needed:
///   CompactCells cells{digits};
///   for (...) print(cells.text(omega));
///   if (cells.any_long) print(long_fraction_note(digits));
struct CompactCells {
  int digits = kReadableDigits;
  bool any_long = false;
  std::string text(const ResultNumber& x) {
    any_long = any_long || is_long_fraction(x);
    return compact_number(x, digits);
  }
};
std::string radius_text(const ResultRadius& r);
/// About 3 significant digits, for prose ("1.23e-1000"); not exact.
std::string radius_short_text(const ResultRadius& r);

}  // namespace linkproof
