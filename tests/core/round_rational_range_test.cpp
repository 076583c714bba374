// round_rational<long double> over the whole long double range: values beyond the range of
// double (1e400, 1e-400) used to throw CLN's floating_point_overflow, which `check --arith
// long-double` reported as an internal error (exit 3).
#include <gtest/gtest.h>

#include <cln/integer.h>

#include <cfloat>
#include <cmath>

#include "core/scalar.h"

namespace linkproof {
namespace {

Rational power_of_ten(int e) {
  const Rational p = cln::expt_pos(cln::cl_I(10), static_cast<unsigned long>(std::abs(e)));
  return e >= 0 ? p : Rational(1) / p;
}

TEST(RoundRational, LongDoubleCarriesValuesBeyondTheDoubleRange) {
  for (const auto& [e, expected] : {std::pair{400, 1e400L}, std::pair{-400, 1e-400L}, std::pair{4000, 1e4000L}}) {
    for (const int sign : {1, -1}) {
      const long double x = round_rational<long double>(sign * power_of_ten(e));
      EXPECT_LE(std::fabs(x / (sign * expected) - 1), 2 * LDBL_EPSILON) << "10^" << e << " sign " << sign;
    }
  }
}

TEST(RoundRational, LongDoubleIsExactOnSmallIntegersAndZero) {
  EXPECT_EQ(round_rational<long double>(Rational(0)), 0.0L);
  EXPECT_EQ(round_rational<long double>(Rational(-12345)), -12345.0L);
  EXPECT_EQ(round_rational<long double>(Rational(3) / Rational(4)), 0.75L);
}

}  // namespace
}  // namespace linkproof
