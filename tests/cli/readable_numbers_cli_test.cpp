// Numbers people read in `check`'s text report (issue "For the people who read it"): each exact
// rate with its decimal beside it, `--digits N` significant digits, a long fraction by its
// decimal and size; JSON keeps the exact p/q.
#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "support/cli_run.h"

namespace linkproof {
namespace {

std::string scene(const std::string& rel) { return std::string(LINKPROOF_SOURCE_DIR) + "/verify/scenes/" + rel; }

TEST(ReadableNumbersCli, PolygonRatesCarryTheirDecimal) {
  const test::CliRun r = test::run_cli({"check", scene("pentagon.yaml")});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("omega-dot = 3755/1331 ≈ 2.821187077"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("omega = 17/11 ≈ 1.545454545"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("D = r_3 x r_4 = -22\n"), std::string::npos) << r.out;
}

TEST(ReadableNumbersCli, DigitsSetsTheSignificantDigits) {
  const test::CliRun r = test::run_cli({"check", scene("pentagon.yaml"), "--digits", "4"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("omega-dot = 3755/1331 ≈ 2.821\n"), std::string::npos) << r.out;
}

TEST(ReadableNumbersCli, MechanismRatesCarryTheirDecimal) {
  const test::CliRun r = test::run_cli({"check", scene("mechanisms/seed001_fourbar.yaml")});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("-3/4 = -0.75"), std::string::npos) << r.out;  // omega of the coupler, exactly a decimal
  EXPECT_NE(r.out.find("63/160 = 0.39375"), std::string::npos) << r.out;
}

TEST(ReadableNumbersCli, LongFractionsAreShownByDecimalAndSize) {
  const test::CliRun r = test::run_cli({"check", scene("mechanisms/dimensions_fourbar.yaml")});
  ASSERT_EQ(r.code, 0) << r.err;
  // Table cells: a long fraction by its decimal and a mark, explained once under the table.
  EXPECT_NE(r.out.find("* a long exact fraction (more than 40 characters)"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("(exact: a fraction of "), std::string::npos) << "too wide for a table cell\n" << r.out;
  // No run of 60 digits anywhere, the claims' evidence included (the old report printed
  // 400-digit fractions in the tables, 60-digit ones in the evidence).
  EXPECT_FALSE(std::regex_search(r.out, std::regex("[0-9]{60}"))) << r.out;
  // JSON keeps the exact values.
  const test::CliRun j = test::run_cli({"check", scene("mechanisms/dimensions_fourbar.yaml"), "--json"});
  ASSERT_EQ(j.code, 0) << j.err;
  EXPECT_TRUE(std::regex_search(j.out, std::regex("[0-9]{60}")));
  EXPECT_NE(j.out.find("\"omega_decimal\""), std::string::npos);
  EXPECT_NE(j.out.find("\"v_decimal\""), std::string::npos);
}

TEST(ReadableNumbersCli, DigitsOutOfRangeOrWithJsonIsRefused) {
  EXPECT_EQ(test::run_cli({"check", scene("pentagon.yaml"), "--digits", "0"}).code, 2);
  EXPECT_EQ(test::run_cli({"check", scene("pentagon.yaml"), "--digits", "101"}).code, 2);
  const test::CliRun r = test::run_cli({"check", scene("pentagon.yaml"), "--digits", "5", "--json"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--digits"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace linkproof
