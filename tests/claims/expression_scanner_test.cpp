// One scanner for both claim languages (claims/expression_scanner.h): the same text is refused
// alike by the polygon and the mechanism parser, and what differs is a rule.
#include "claims/expression_scanner.h"

#include <gtest/gtest.h>

#include "claims/claim_expression.h"
#include "claims/mechanism_expression.h"
#include "linkproof/core/error.h"

namespace linkproof {
namespace {

std::string polygon_error(const std::string& text) {
  try {
    ClaimExpression::parse(text, ExpressionContext{"c.yaml", "claims[0].lhs", false});
  } catch (const InputError& e) {
    return e.source() + ": " + e.problem();
  }
  return "no error";
}

std::string mechanism_error(const std::string& text) {
  try {
    MechanismExpression::parse(text, ExpressionContext{"c.yaml", "claims[0].lhs", false});
  } catch (const InputError& e) {
    return e.source() + ": " + e.problem();
  }
  return "no error";
}

TEST(ExpressionScanner, BothLanguagesRefuseTheSameTextWithTheSameMessageAndPlace) {
  // Each is refused by the scanner, before either language reads a word.
  for (const std::string& text : std::vector<std::string>{"2*0.5", "1e-3 + 1", "2.5E+4", "1 # 2", "1 \x01 2", std::string(20001, '1')}) {
    const std::string p = polygon_error(text), m = mechanism_error(text);
    EXPECT_NE(p, "no error") << text;
    EXPECT_EQ(p, m) << text;
  }
  EXPECT_EQ(polygon_error("2*0.5"), "c.yaml:1:3: '0.5' is a decimal number: claims are exact, write a fraction such as 1/2");
  EXPECT_EQ(mechanism_error("1e-3*omega(L)"),
            "c.yaml:1:1: '1e-3' is a decimal number: claims are exact, write a fraction such as 1/2");
}

TEST(ExpressionScanner, QuotesAndSquareBracketsAreRulesOfALanguage) {
  const std::vector<ExpressionToken> m = scan_expression("omega(\"3\")", ScanRules{.quoted_names = true});
  ASSERT_EQ(m.size(), 5u);
  EXPECT_EQ(m[2].kind, TokenKind::Quoted);
  EXPECT_EQ(m[2].text, "3");
  EXPECT_THROW(scan_expression("omega(\"3\")", ScanRules{}), ScanError);
  const std::vector<ExpressionToken> p = scan_expression("r[1]", ScanRules{.square_brackets = true});
  ASSERT_EQ(p.size(), 5u);
  EXPECT_EQ(p[1].kind, TokenKind::Open);
  EXPECT_EQ(p[3].kind, TokenKind::Close);
  EXPECT_THROW(scan_expression("r[1]", ScanRules{}), ScanError);
  EXPECT_EQ(p.back().kind, TokenKind::End);
  EXPECT_EQ(p.back().offset, 4u);
}

TEST(ExpressionScanner, AnIntegerOverTheLimitIsRefusedWhereTheLanguageHasOne) {
  const std::string big(201, '7');
  EXPECT_NE(mechanism_error(big).find("an integer of 201 digits; the limit is 200"), std::string::npos);
  EXPECT_NO_THROW(scan_expression(big, ScanRules{}));
  try {
    scan_expression("\"abc", ScanRules{.quoted_names = true});
    ADD_FAILURE() << "an unclosed quote was accepted";
  } catch (const ScanError& e) {
    EXPECT_EQ(e.offset, 0u);
    EXPECT_EQ(e.problem, "this \" is never closed");
  }
}

}  // namespace
}  // namespace linkproof
