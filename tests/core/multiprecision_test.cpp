#include "core/multiprecision.h"

#include <gtest/gtest.h>

#include <cln/integer.h>

namespace linkproof {
namespace {

TEST(MpFloat, PrecisionIsAtLeastTheRequestedDigits) {
  EXPECT_GE(MpFloat<30>::precision_bits(), 100);   // 30 digits need 99.7 bits
  EXPECT_GE(MpFloat<50>::precision_bits(), 167);
  EXPECT_GE(MpFloat<100>::precision_bits(), 333);
  EXPECT_GE(MpFloat<1000>::precision_bits(), 3322);
}

TEST(MpFloat, RationalIsRoundedOnceAtTheTargetPrecision) {
  const Rational third = Rational(1) / 3;
  const MpFloat<100> x(third);
  const Rational err = cln::abs(ScalarTraits<MpFloat<100>>::to_rational(x) - third);
  // Correct rounding: |err| <= 2^-p |1/3| (half an ulp of a number in [1/4, 1/2)).
  const int p = MpFloat<100>::precision_bits();
  EXPECT_LE(err, third / cln::expt_pos(cln::cl_I(2), p));
  EXPECT_FALSE(cln::zerop(err));
}

TEST(MpFloat, OperationsKeepThePrecisionOfTheType) {
  const MpFloat<1000> a(Rational(1) / 7), b(Rational(2) / 3);
  const MpFloat<1000> c = a * b + a / b - b;
  EXPECT_EQ(static_cast<int>(cln::float_digits(c.value())), MpFloat<1000>::precision_bits());
  const Rational exact = Rational(1) / 7 * (Rational(2) / 3) + (Rational(1) / 7) / (Rational(2) / 3) - Rational(2) / 3;
  const Rational err = cln::abs(ScalarTraits<MpFloat<1000>>::to_rational(c) - exact);
  EXPECT_LT(err, Rational(1) / cln::expt_pos(cln::cl_I(10), 990));
}

TEST(MpFloat, DefaultIsZeroAndPrintsWithDecimalExponent) {
  EXPECT_TRUE(is_zero(MpFloat<30>()));
  EXPECT_EQ(to_text(MpFloat<30>(Rational(5) / 2)), "2.5");
  const std::string small = to_text(MpFloat<30>(Rational(1) / cln::expt_pos(cln::cl_I(10), 40)));
  EXPECT_NE(small.find("e-"), std::string::npos) << small;
  EXPECT_EQ(small.find('L'), std::string::npos) << small;
}

}  // namespace
}  // namespace linkproof

namespace linkproof {
namespace {

TEST(ExactValueOf, ReturnsForDoublesWhoseExponentShiftIsZero) {
  // Every double in [2^52, 2^53) is an integer with shift 0 (this once hung in cln::expt_pos).
  EXPECT_EQ(exact_value_of(4832323065636672.0), Rational(4832323065636672LL));
  EXPECT_EQ(exact_value_of(0.375), Rational(3) / 8);
  EXPECT_EQ(exact_value_of(0.0), Rational(0));
}

}  // namespace
}  // namespace linkproof
