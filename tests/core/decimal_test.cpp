// format_decimal and rational_from_double (core/decimal.h).
#include <gtest/gtest.h>

#include <limits>

#include "linkproof/core/exact.h"

namespace linkproof {
namespace {

Rational q(long p, long d = 1) { return Rational(p) / Rational(d); }

TEST(Decimal, FormatDecimalRoundsToTheRequestedDigits) {
  EXPECT_EQ(format_decimal(q(1, 3), 5), "0.33333");
  EXPECT_EQ(format_decimal(q(-2, 3), 4), "-0.6667");
  EXPECT_EQ(format_decimal(q(3755, 1331), 10), "2.821187077");
  EXPECT_EQ(format_decimal(q(12), 5), "12");
  EXPECT_EQ(format_decimal(q(1, 1000000000), 3), "1.00e-9");
  EXPECT_EQ(rational_from_double(0.1), Rational(3602879701896397) / cln::expt(Rational(2), 55));
  // Subnormals (CLN has none: cl_DF threw "floating point underflow" here before).
  EXPECT_EQ(rational_from_double(std::numeric_limits<double>::denorm_min()), Rational(1) / cln::expt(Rational(2), 1074));
  EXPECT_EQ(rational_from_double(-3 * std::numeric_limits<double>::denorm_min()), Rational(-3) / cln::expt(Rational(2), 1074));
}

}  // namespace
}  // namespace linkproof
