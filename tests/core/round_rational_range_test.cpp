// round_rational<long double> over the whole long double range: values beyond the range of
// double (1e400, 1e-400) used to throw CLN's floating_point_overflow, which `check --arith
// long-double` reported as an internal error (exit 3).
#include <gtest/gtest.h>

#include <cln/integer.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <vector>

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

// The fast paths (an integer of <= 53 bits; p/q with |p|, q < 2^53 by one IEEE division) must
// round exactly as the definition says: to the nearest double, ties to even. Checked against the
// two neighbours in exact arithmetic, on small fractions, on ties, and at the 53-bit edge where
// the fast path stops.
template <class F>
void expect_nearest_ties_to_even(const Rational& q) {
  const F x = round_rational<F>(q);
  const Rational err = cln::abs(q - exact_value_of(x));
  for (const F n : {std::nextafter(x, -std::numeric_limits<F>::infinity()), std::nextafter(x, std::numeric_limits<F>::infinity())}) {
    const Rational other = cln::abs(q - exact_value_of(n));
    EXPECT_LE(err, other) << format_rational(q);
    if (err == other) {  // a tie: x has the even mantissa
      int e = 0;
      EXPECT_EQ(std::fmod(std::ldexp(std::frexp(x, &e), std::numeric_limits<F>::digits), F(2)), F(0)) << format_rational(q);
    }
  }
}

TEST(RoundRational, SmallIntegersAndFractionsRoundToNearestTiesToEven) {
  const cln::cl_I two53 = cln::ash(cln::cl_I(1), 53);
  std::vector<Rational> cases;
  for (int p = -40; p <= 40; ++p)
    for (int q = 1; q <= 40; ++q) cases.push_back(Rational(p) / Rational(q));
  for (const cln::cl_I& k : {two53 - 1, two53, two53 + 1, two53 + 3, 2 * two53 + 2, -(two53 + 1)}) {
    cases.push_back(k);                     // integers around 2^53: 2^53 + 1 is a tie
    cases.push_back(Rational(k) / 3);       // fractions at the fast path's edge
    cases.push_back(Rational(1) / Rational(k));
  }
  cases.push_back(Rational(two53 + 1) / 2);  // (2^53 + 1)/2: exact in double
  cases.push_back(Rational(1) / 3);
  for (const Rational& q : cases) {
    expect_nearest_ties_to_even<double>(q);
    expect_nearest_ties_to_even<long double>(q);
  }
}

TEST(ExactValueOf, IntegersAndFractionsConvertExactly) {
  for (const double x : {0.0, -0.0, 1.0, -7.0, 4503599627370497.0, 9007199254740992.0, 0.5, -0.1, 1e300, 1e-300,
                         4611686018427387904.0, 9.3e18})
    EXPECT_EQ(cln::double_approx(exact_value_of(x)), x) << x;
  EXPECT_EQ(exact_value_of(-0.1), Rational(-3602879701896397) / Rational(cln::ash(cln::cl_I(1), 55)));
  EXPECT_EQ(exact_value_of(9.3e18), Rational(cln::cl_I("9300000000000000000")));
}

}  // namespace
}  // namespace linkproof
