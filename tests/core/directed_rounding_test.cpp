// next_up / next_down (core/directed_rounding.h) against std::nextafter, and the correct
// rounding of rationals to long double over its whole range, decided in exact rationals.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cln/integer.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "core/directed_rounding.h"
#include "core/scalar.h"

namespace linkproof {
namespace {

template <class F>
std::vector<F> edge_values() {
  using L = std::numeric_limits<F>;
  std::vector<F> v{F(0), L::denorm_min(), 2 * L::denorm_min(), L::min() - L::denorm_min(), L::min(),
                   std::nextafter(L::min(), L::infinity()), F(0.5), F(1), std::nextafter(F(1), F(0)), F(3),
                   L::max(), std::nextafter(L::max(), F(0))};
  std::mt19937_64 g(20261124);
  for (int i = 0; i < 2000; ++i) {
    const int k = static_cast<int>(g() % static_cast<unsigned>(L::max_exponent - L::min_exponent + L::digits)) +
                  L::min_exponent - L::digits;
    v.push_back(std::ldexp(F(1) + static_cast<F>(g() % 1000000) / F(1000000), k));
  }
  return v;
}

template <class F>
class DirectedRoundingTyped : public ::testing::Test {};
using IeeeTypes = ::testing::Types<double, long double>;
TYPED_TEST_SUITE(DirectedRoundingTyped, IeeeTypes);

TYPED_TEST(DirectedRoundingTyped, StepsAreTheNeighboursOfNextafterOverTheWholeRange) {
  using F = TypeParam;
  const F inf = std::numeric_limits<F>::infinity();
  for (const F x : edge_values<F>()) {
    if (!std::isfinite(x)) continue;
    EXPECT_EQ(next_up(x), std::nextafter(x, inf)) << static_cast<double>(x);
    if (x > 0) {
      EXPECT_EQ(next_down(x), std::nextafter(x, F(0))) << static_cast<double>(x);
    }
  }
  EXPECT_EQ(next_up(std::numeric_limits<F>::max()), inf);
  EXPECT_EQ(next_up(inf), inf);
  EXPECT_EQ(next_down(F(0)), F(0));
  EXPECT_EQ(next_down(inf), inf);
  EXPECT_TRUE(std::isnan(next_up(std::numeric_limits<F>::quiet_NaN())));
  EXPECT_FALSE(next_down(F(-1)) > 0);
  EXPECT_EQ(round_up_to_double(static_cast<F>(0.1)), 0.1);
}

TEST(DirectedRounding, RoundUpToDoubleNeverRoundsDown) {
  const long double third = 1.0L / 3;
  EXPECT_GE(static_cast<long double>(round_up_to_double(third)), third);
  EXPECT_GE(static_cast<long double>(round_up_to_double(-third)), -third);
  EXPECT_EQ(round_up_to_double(1e4000L), std::numeric_limits<double>::infinity());
  EXPECT_EQ(round_up_to_double(1e-4000L), std::numeric_limits<double>::denorm_min());
}

// The long double conversion is correct to nearest, ties to even, from 2^-16445 to overflow:
// no nearer long double exists (decided exactly against both neighbours).
RC_GTEST_PROP(RoundRational, LongDoubleIsTheNearestOverTheWholeRange, ()) {
  const long p = *rc::gen::inRange<long>(1, 1L << 62);
  const long q = *rc::gen::inRange<long>(1, 1L << 40);
  const int k = *rc::gen::inRange(-16520, 16420);
  const Rational x = Rational(p) / q * (k >= 0 ? Rational(cln::ash(cln::cl_I(1), k)) : 1 / Rational(cln::ash(cln::cl_I(1), -k)));
  const long double v = round_rational<long double>(x);
  if (!std::isfinite(v)) {
    RC_ASSERT(x >= exact_value_of(std::numeric_limits<long double>::max()));
    return;
  }
  const Rational err = cln::abs(x - exact_value_of(v));
  for (const long double n : {next_up(v), next_down(v)})
    if (std::isfinite(n) && n != v) RC_ASSERT(err <= cln::abs(x - exact_value_of(n)));
  RC_ASSERT(exact_value_of(round_rational<long double>(-x)) == -exact_value_of(v));
}

TEST(RoundRational, LongDoubleTiesGoToEvenAndTheExtremesAreExact) {
  const auto two_to = [](long k) { return k >= 0 ? Rational(cln::ash(cln::cl_I(1), k)) : 1 / Rational(cln::ash(cln::cl_I(1), -k)); };
  EXPECT_EQ(round_rational<long double>(two_to(-16445)), std::numeric_limits<long double>::denorm_min());
  EXPECT_EQ(round_rational<long double>(two_to(-16446)), 0.0L);  // a tie between 0 and the least: even
  EXPECT_EQ(round_rational<long double>(two_to(-16446) * 3), 2 * std::numeric_limits<long double>::denorm_min());
  EXPECT_EQ(round_rational<long double>(1 + two_to(-64)), 1.0L);  // tie: even
  EXPECT_EQ(round_rational<long double>(1 + 3 * two_to(-64)), 1.0L + 2 * std::numeric_limits<long double>::epsilon());
  EXPECT_EQ(exact_value_of(round_rational<long double>(exact_value_of(std::numeric_limits<long double>::max()))),
            exact_value_of(std::numeric_limits<long double>::max()));
  EXPECT_EQ(round_rational<long double>(two_to(16384)), std::numeric_limits<long double>::infinity());
  EXPECT_EQ(round_rational<long double>(Rational(1) / 3 * two_to(-1100)) * 3 * 0x1p1100L, 1.0L);
}

}  // namespace
}  // namespace linkproof
