// Numbers people read (report/number_text.h): an exact value with its decimal beside it, a long
// fraction by its decimal and size; floats as they are.
#include "report/number_text.h"

#include <cln/integer.h>
#include <gtest/gtest.h>

#include "linkproof/core/exact.h"

namespace linkproof {
namespace {

TEST(ReadableNumber, ShowsTheDecimalBesideAFraction) {
  EXPECT_EQ(readable_number(Rational(3755) / 1331), "3755/1331 ≈ 2.821187077");
  EXPECT_EQ(readable_number(Rational(-684) / 1331), "-684/1331 ≈ -0.5138993238");
  EXPECT_EQ(readable_number(Rational(3755) / 1331, 4), "3755/1331 ≈ 2.821");
}

TEST(ReadableNumber, SaysEqualsWhereTheDecimalIsTheValue) {
  EXPECT_EQ(readable_number(Rational(7) / 20), "7/20 = 0.35");
  EXPECT_EQ(readable_number(Rational(-3) / 4), "-3/4 = -0.75");
  EXPECT_EQ(readable_number(Rational(0)), "0");
  EXPECT_EQ(readable_number(Rational(-22)), "-22");
}

TEST(ReadableNumber, ShowsALongFractionByItsDecimalAndSize) {
  // pi to 60 digits over 10^59: a fraction of 120 digits.
  const Rational q = parse_rational("3.14159265358979323846264338327950288419716939937510582097494");
  const std::string s = readable_number(q);
  EXPECT_EQ(s.rfind("≈ 3.141592654 (exact: a fraction of ", 0), 0u) << s;
  EXPECT_NE(s.find("see --json)"), std::string::npos) << s;
  EXPECT_EQ(s.find('/'), std::string::npos) << s;
}

TEST(ReadableNumber, ShowsAHugeValueInScientificForm) {
  const Rational big = Rational(cln::expt_pos(cln::cl_I(10), 400)) / Rational(3);
  const std::string s = readable_number(big);
  EXPECT_EQ(s.rfind("≈ 3.333333333e399 (exact: a fraction of 402 digits", 0), 0u) << s;
}

TEST(ReadableNumber, LeavesFloatsAsTheirOwnFormatterPrintsThem) {
  EXPECT_EQ(readable_number(ResultNumber(0.1)), number_text(ResultNumber(0.1)));
}

}  // namespace
}  // namespace linkproof
