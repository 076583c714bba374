#include "linkproof/core/exact.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cln/integer.h>
#include <cln/rational_io.h>

#include <sstream>
#include <stdexcept>
#include <string>

namespace linkproof {
namespace {

Rational exact_q(long p, long d) { return Rational(cln::cl_I(p)) / cln::cl_I(d); }

TEST(ParseRational, ReadsIntegers) {
  EXPECT_EQ(parse_rational("0"), exact_q(0, 1));
  EXPECT_EQ(parse_rational("42"), exact_q(42, 1));
  EXPECT_EQ(parse_rational("123456789012345678901234567890"),
            Rational(cln::cl_I("123456789012345678901234567890")));
}

TEST(ParseRational, ReadsSigns) {
  EXPECT_EQ(parse_rational("-12"), exact_q(-12, 1));
  EXPECT_EQ(parse_rational("+7"), exact_q(7, 1));
  EXPECT_EQ(parse_rational("-7/3"), exact_q(-7, 3));
  EXPECT_EQ(parse_rational("-0"), exact_q(0, 1));
}

TEST(ParseRational, ReadsFractionsReduced) {
  EXPECT_EQ(parse_rational("6/4"), exact_q(3, 2));
  EXPECT_EQ(parse_rational("4/2"), exact_q(2, 1));
  EXPECT_EQ(parse_rational("1/3"), exact_q(1, 3));
}

TEST(ParseRational, ReadsDecimalAsExactDecimalFraction) {
  EXPECT_EQ(parse_rational("0.1"), exact_q(1, 10));
  EXPECT_EQ(parse_rational("-2.50"), exact_q(-5, 2));
  EXPECT_EQ(parse_rational(".5"), exact_q(1, 2));
  EXPECT_EQ(parse_rational("5."), exact_q(5, 1));
}

TEST(ParseRational, ReadsExponentsExactly) {
  EXPECT_EQ(parse_rational("1e3"), exact_q(1000, 1));
  EXPECT_EQ(parse_rational("2.5e-3"), exact_q(1, 400));
  EXPECT_EQ(parse_rational("1E+2"), exact_q(100, 1));
}

TEST(ParseRational, IgnoresSurroundingWhitespace) { EXPECT_EQ(parse_rational(" 3/4 "), exact_q(3, 4)); }

TEST(ParseRational, RejectsTextThatIsNotAnExactNumber) {
  for (const char* bad : {"", "   ", "abc", "1/0", "nan", "NaN", ".nan", "inf", "-inf", ".inf",
                          "1e99999999", "1e5000", "0x10", "1/2/3", "--1", "1.2.3", "-", "1/",
                          "/2", "1e", "1.5/2", "1 2", "true"}) {
    EXPECT_THROW(parse_rational(bad), std::invalid_argument) << "input: '" << bad << "'";
  }
}

TEST(ParseRational, ExplainsZeroDenominator) {
  try {
    parse_rational("1/0");
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("denominator 0"), std::string::npos) << e.what();
  }
}

TEST(ParseRational, ExplainsExponentOutOfRange) {
  try {
    parse_rational("1e99999999");
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("exponent"), std::string::npos) << e.what();
  }
}

TEST(FormatRational, PrintsReducedFraction) {
  EXPECT_EQ(format_rational(exact_q(6, 4)), "3/2");
  EXPECT_EQ(format_rational(exact_q(-7, 3)), "-7/3");
  EXPECT_EQ(format_rational(parse_rational("6/4")), "3/2");
}

TEST(FormatRational, PrintsIntegersWithoutDenominator) {
  EXPECT_EQ(format_rational(exact_q(4, 2)), "2");
  EXPECT_EQ(format_rational(parse_rational("4/2")), "2");
  EXPECT_EQ(format_rational(exact_q(0, 5)), "0");
  EXPECT_EQ(format_rational(exact_q(-3, 1)), "-3");
}

TEST(FormatRational, PrintsDecimalInputAsExactFraction) {
  EXPECT_EQ(format_rational(parse_rational("0.1")), "1/10");
  EXPECT_EQ(format_rational(parse_rational("2.5e-3")), "1/400");
}

// Numbers that fit a machine word are printed without CLN's printer; on both sides of that
// boundary the text is CLN's.
TEST(FormatRational, PrintsAsClnDoesOnBothSidesOfTheMachineWord) {
  const auto cln_text = [](const Rational& x) {
    std::ostringstream out;
    cln::fprint(out, x);
    return out.str();
  };
  const cln::cl_I big = cln::expt_pos(cln::cl_I(2), 62);
  for (const cln::cl_I& p : {cln::cl_I(0), cln::cl_I(1), cln::cl_I(-1), big - 1, big, -big, -big + 1, 2 * big, -2 * big + 1,
                             big * big + 7})
    for (const cln::cl_I& d : {cln::cl_I(1), cln::cl_I(3), big - 1, big + 1, 4 * big + 1}) {
      const Rational x = Rational(p) / d;
      EXPECT_EQ(format_rational(x), cln_text(x)) << cln_text(x);
    }
}

// format_rational is the inverse of parse_rational on every rational p/q.
RC_GTEST_PROP(FormatRational, RoundTripsThroughParseRational, (long p, long d)) {
  RC_PRE(d != 0L);
  const Rational value = Rational(cln::cl_I(p)) / cln::cl_I(d);
  const std::string text = format_rational(value);
  RC_ASSERT(parse_rational(text) == value);
}

}  // namespace
}  // namespace linkproof
