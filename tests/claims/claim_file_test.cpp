// Claim files: the expression language, its parse errors (with file, line and column) and the
// round trip of a user's claim through the parser and the checker.
#include <gtest/gtest.h>

#include "dijksman1966.h"
#include "check/check_polygon.h"
#include "report/comparison_text.h"
#include "io/claim_file.h"
#include "support/polygons.h"

namespace linkproof {
namespace {

std::string error_of(const std::string& yaml) {
  try {
    parse_claim_file(yaml, "user.yaml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const char* kHeader = "claims:\n  - id: mine\n    source: notes\n    statement: s\n    lhs: omega_dot_out\n";

TEST(ClaimFile, BundledCatalogueParsesWithEveryEquation) {
  const auto& f = dijksman1966::claim_file();
  EXPECT_EQ(f.claims.size(), 30u);
  int errata = 0;
  for (const auto& c : f.claims) errata += c.info.expected == Expectation::Fails;
  EXPECT_EQ(errata, 13);
}

TEST(ClaimFile, ParseErrorPointsAtLineAndColumnOfTheBadName) {
  const std::string e = error_of(std::string(kHeader) + "    rhs: sum_j(lambda[j]*omega[j]^2 + i_outt[j])\n");
  EXPECT_NE(e.find("user.yaml:6:39"), std::string::npos) << e;
  EXPECT_NE(e.find("unknown name 'i_outt'"), std::string::npos) << e;
  EXPECT_NE(e.find("claims[0].rhs"), std::string::npos) << e;
}

TEST(ClaimFile, ParseErrorInAFoldedScalarPointsAtItsOwnLine) {
  const std::string e = error_of(std::string(kHeader) + "    rhs: >-\n      sum_j(lambda[j]*omega[j]^2)\n      + omega[l]\n");
  EXPECT_NE(e.find("user.yaml:8:15"), std::string::npos) << e;
  EXPECT_NE(e.find("'l' is not bound"), std::string::npos) << e;
}

TEST(ClaimFile, StructuralErrorsAreNamed) {
  EXPECT_NE(error_of(std::string(kHeader) + "    rhs: sum_j(omega[j\n").find("never closed"), std::string::npos);
  EXPECT_NE(error_of(std::string(kHeader) + "    rhs: 0.5*omega_dot_out\n").find("decimal"), std::string::npos);
  // The number is quoted as written (it used to print '0....').
  EXPECT_NE(error_of(std::string(kHeader) + "    rhs: 0.5*omega_dot_out\n").find("'0.5' is a decimal"), std::string::npos);
  EXPECT_NE(error_of(std::string(kHeader) + "    rhs: 2e-3*omega_dot_out\n").find("'2e-3' is a decimal"), std::string::npos);
  EXPECT_NE(error_of(std::string(kHeader) + "    rhs: omega_dot_out * * 2\n").find("operand is missing"), std::string::npos);
  EXPECT_NE(error_of(std::string(kHeader) + "    rhs: i_out\n").find("needs an index"), std::string::npos);
  EXPECT_NE(error_of(std::string(kHeader) + "    rhs: dot(r[1])\n").find("takes 2 argument"), std::string::npos);
  EXPECT_NE(error_of(std::string(kHeader) + "    rhs: r[n-1](2)\n").find("operator is missing"), std::string::npos);
  EXPECT_NE(error_of(std::string(kHeader) + "    rhs: x\n    colour: red\n").find("unknown field"), std::string::npos);
  EXPECT_NE(error_of(std::string(kHeader) + "    rhs: 1\n    reading: [upside_down]\n").find("unknown reading"), std::string::npos);
  EXPECT_NE(error_of("claims: []\n").find("non-empty"), std::string::npos);
}

TEST(ClaimFile, UserClaimRoundTripsThroughParserAndChecker) {
  // eq. (5) written by a user with the closed-form ratios: holds exactly on the pentagon of conventions §A8.
  const ClaimFile f = parse_claim_file(
      "claims:\n  - id: mine.eq5\n    source: notes\n    statement: s\n    lhs: omega_out\n"
      "    rhs: sum_j(i_out_closed[j]*omega[j])\n",
      "user.yaml");
  ASSERT_EQ(f.claims.size(), 1u);
  EXPECT_EQ(f.claims[0].rhs.text(), "sum_j(i_out_closed[j]*omega[j])");
  GroundTruthEngine engine;
  const auto ex = test::spec_pentagon();
  const auto check = check_polygon(engine, {to_claim(f.claims[0])}, "p", ex.polygon, ex.rates, Arithmetic::Exact);
  ASSERT_EQ(check.claims.size(), 1u);
  EXPECT_EQ(check.claims[0].verdict, Verdict::Holds);
  EXPECT_EQ(lhs_text(check.claims[0].headline), "3/11");
}

}  // namespace
}  // namespace linkproof
