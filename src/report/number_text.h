// The text of a result's numbers (core/result_number.h), made by the arithmetic's own
// formatter: exact "p/q", the shortest round-trip decimal of an IEEE value, every significant
// digit of a CLN float; a radius as a decimal that reads back to a bound ("2.5e-40", "inf").
#pragma once

#include <string>

#include "linkproof/core/result_number.h"

namespace linkproof {

std::string number_text(const ResultNumber& x);
std::string radius_text(const ResultRadius& r);
/// About 3 significant digits, for prose ("1.23e-1000"); not exact.
std::string radius_short_text(const ResultRadius& r);

}  // namespace linkproof
