// WideBound: every operation and conversion rounds upward (or downward where asked), checked
// exactly against rationals, far outside double's exponent range too.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cln/integer.h>

#include "core/multiprecision.h"
#include "linkproof/core/wide_bound.h"

namespace linkproof {
namespace {

Rational two_to(long k) {
  const Rational p = cln::ash(cln::cl_I(1), cln::cl_I(std::labs(k)));
  return k >= 0 ? p : 1 / p;
}

TEST(WideBound, ExactValuesAndPowersOfTwo) {
  EXPECT_TRUE(WideBound().is_zero());
  EXPECT_EQ(WideBound(0.75).to_rational(), Rational(3) / 4);
  EXPECT_EQ(WideBound::power_of_two(-3392).to_rational(), two_to(-3392));
  EXPECT_EQ(WideBound::power_of_two(5000).to_rational(), two_to(5000));
  EXPECT_TRUE(WideBound::infinity().is_infinite());
  EXPECT_LT(WideBound(1.0), WideBound::infinity());
  EXPECT_LT(WideBound::power_of_two(-5000), WideBound::power_of_two(-4999));
}

TEST(WideBound, InfinityAndZeroPropagateConservatively) {
  const WideBound inf = WideBound::infinity(), one(1.0), zero;
  EXPECT_TRUE((inf + one).is_infinite());
  EXPECT_TRUE((inf * zero).is_infinite());  // 0 * unbounded stays unbounded
  EXPECT_TRUE((one / zero).is_infinite());
  EXPECT_TRUE((zero * one).is_zero());
  EXPECT_TRUE((zero / one).is_zero());
}

TEST(WideBound, ExponentsAreClampedUpward) {
  const WideBound tiny = WideBound::power_of_two(WideBound::kMinExponent + 10);
  EXPECT_FALSE((tiny * tiny).is_zero());  // never rounded down to 0
  const WideBound huge = WideBound::power_of_two(WideBound::kMaxExponent - 10);
  EXPECT_TRUE((huge * huge).is_infinite());
}

TEST(WideBound, ToDoubleUpIsStillABound) {
  EXPECT_EQ(WideBound(0.1).to_double_up(), 0.1);
  EXPECT_EQ(WideBound::power_of_two(-2000).to_double_up(), std::numeric_limits<double>::denorm_min());
  EXPECT_EQ(WideBound::power_of_two(2000).to_double_up(), HUGE_VAL);
  EXPECT_EQ(WideBound().to_double_up(), 0.0);
}

TEST(WideBound, TextReadsBackAndShortTextHasTheDecimalExponent) {
  EXPECT_EQ(WideBound(2.5).to_string(), "2.5");
  EXPECT_EQ(WideBound::infinity().to_string(), "inf");
  EXPECT_EQ(WideBound::power_of_two(-3392).to_short_string(), "8.06e-1022");
  EXPECT_EQ(WideBound(0.00125).to_short_string(), "0.00125");
}

// Random operands m 2^k over a wide exponent range: a + b, a * b, a / b are >= the exact
// results and within 2^-50 relative of them; conversions from rationals and floats bound them.
RC_GTEST_PROP(WideBound, OperationsRoundUpwardAndStayTight, ()) {
  const auto draw = [] {
    const long m = *rc::gen::inRange<long>(1, 1L << 53);
    const long k = *rc::gen::inRange<long>(-4000, 4000);
    return Rational(m) * two_to(k);
  };
  const Rational a = draw(), b = draw();
  const WideBound wa = WideBound::from_rational_up(a), wb = WideBound::from_rational_up(b);
  RC_ASSERT(wa.to_rational() >= a);
  RC_ASSERT(wa.to_rational() <= a * (1 + two_to(-50)));
  const Rational sa = wa.to_rational(), sb = wb.to_rational();
  const auto tight = [](const WideBound& w, const Rational& exact) {
    return w.to_rational() >= exact && w.to_rational() <= exact * (1 + two_to(-50));
  };
  RC_ASSERT(tight(wa + wb, sa + sb));
  RC_ASSERT(tight(wa * wb, sa * sb));
  RC_ASSERT(tight(wa / wb, sa / sb));
  // From a 384-bit float: up >= |x| >= down.
  const cln::cl_F x = cln::cl_float(-a / b, MpFloat<100>::format());
  const Rational rx = cln::abs(cln::rational(x));
  RC_ASSERT(WideBound::from_float_up(x).to_rational() >= rx);
  RC_ASSERT(WideBound::from_float_down(x).to_rational() <= rx);
  RC_ASSERT(WideBound::from_float_down(x).to_rational() >= rx * (1 - two_to(-50)));
}

}  // namespace
}  // namespace linkproof
