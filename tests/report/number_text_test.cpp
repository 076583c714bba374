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

TEST(DecimalText, IsTheDecimalReadableNumberShows) {
  EXPECT_EQ(decimal_text(Rational(3755) / 1331), "2.821187077");
  EXPECT_EQ(decimal_text(Rational(7) / 20), "0.35");
  EXPECT_EQ(decimal_text(Rational(-22)), "-22");
  EXPECT_EQ(decimal_text(Rational(0)), "0");
  EXPECT_EQ(decimal_text(Rational(3755) / 1331, 4), "2.821");
  EXPECT_EQ(decimal_text(ResultNumber(0.1)), number_text(ResultNumber(0.1)));
}

TEST(CompactNumber, KeepsShortExactValuesAndMarksALongFraction) {
  EXPECT_EQ(compact_number(Rational(3755) / 1331), "3755/1331 ≈ 2.821187077");
  EXPECT_EQ(compact_number(Rational(-3)), "-3");
  const Rational q = parse_rational("-209.4395102393195492308428922186335256131446266250070547316629");
  EXPECT_TRUE(is_long_fraction(q));
  EXPECT_FALSE(is_long_fraction(Rational(3755) / 1331));
  EXPECT_EQ(compact_number(q), std::string("≈ -209.4395102") + kLongFractionMark);
  EXPECT_EQ(fraction_digits(q), 61u + 59u);  // p of 61 digits over 10^58
}

TEST(CompactNumber, TheNoteNamesTheMarkTheThresholdAndWhereTheExactValuesAre) {
  const std::string note = long_fraction_note(10, "--json");
  EXPECT_EQ(note.rfind(kLongFractionMark, 0), 0u) << note;
  EXPECT_NE(note.find("40 characters"), std::string::npos) << note;
  EXPECT_NE(note.find("10 significant digits"), std::string::npos) << note;
  EXPECT_NE(note.find("--json"), std::string::npos) << note;
}

TEST(CompactCells, RemembersWhetherATableNeedsTheLongFractionNote) {
  CompactCells cells{10};
  EXPECT_EQ(cells.text(Rational(7) / 20), "7/20 = 0.35");
  EXPECT_FALSE(cells.any_long);
  EXPECT_EQ(cells.text(parse_rational("1.00000000000000000000000000000000000000000000001")),
            std::string("≈ 1") + kLongFractionMark);
  EXPECT_TRUE(cells.any_long);
}

}  // namespace
}  // namespace linkproof
