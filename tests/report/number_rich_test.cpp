// Numbers in the derivation reports (report/number_rich.h): every exact value typeset with its
// decimal beside it; a long fraction folded behind its decimal and size.
#include "report/number_rich.h"

#include <gtest/gtest.h>

namespace linkproof::report {
namespace {

TEST(NumberRich, ShortFractionIsMathWithItsDecimal) {
  const Rich r = number_rich(Rational(3755) / 1331);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_TRUE(r[0].math);
  EXPECT_EQ(r[0].text, "\\frac{3755}{1331} \\approx 2.821187077");
  EXPECT_EQ(number_rich(Rational(-7) / 20)[0].text, "-\\frac{7}{20} = -0.35");
  EXPECT_EQ(number_rich(Rational(22))[0].text, "22");
}

TEST(NumberRich, ExponentOfATinyDecimalIsTypesetAsAPowerOfTen) {
  EXPECT_EQ(decimal_tex("1.5e-40"), "1.5 \\times 10^{-40}");
  EXPECT_EQ(decimal_tex("3.3e+12"), "3.3 \\times 10^{12}");
  EXPECT_EQ(decimal_tex("0.35"), "0.35");
}

TEST(NumberRich, LongFractionIsFoldedBehindItsDecimalAndSize) {
  const Rational q = parse_rational("-209.4395102393195492308428922186335256131446266250070547316629");
  const Rich r = number_rich(q);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_FALSE(r[0].math);
  EXPECT_EQ(r[0].text, format_rational(q)) << "the fold opens to the exact fraction";
  EXPECT_EQ(r[0].fold, "≈ -209.4395102 (exact: 120 digits)");
  EXPECT_EQ(number_tex(q), "\\approx -209.4395102\\ (\\text{exact: 120 digits})");
}

TEST(NumberRich, PointHasBothCoordinatesWithTheirDecimals) {
  const Rich r = point_rich({Rational(26) / 5, Rational(23) / 5});
  std::string all;
  for (const Span& s : r) all += s.text;
  EXPECT_EQ(all, "(\\frac{26}{5} = 5.2, \\frac{23}{5} = 4.6)");
}

TEST(NumberRich, ValueTextIsReadOnlyWhenItIsANumber) {
  EXPECT_EQ(value_rich("3755/1331")[0].text, "\\frac{3755}{1331} \\approx 2.821187077");
  EXPECT_TRUE(value_rich("-2")[0].math);
  for (const char* other : {"links 1-2-3-4-0 (last side fixed)", "-", "1/", "/2", "1/2/3", "1.5", "\\input{x}", ""}) {
    const Rich r = value_rich(other);
    ASSERT_EQ(r.size(), 1u) << other;
    EXPECT_FALSE(r[0].math) << other;
    EXPECT_EQ(r[0].text, other);
  }
}

}  // namespace
}  // namespace linkproof::report
