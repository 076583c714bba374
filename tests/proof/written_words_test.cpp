// A claim is undefined where a quantity it is written with is undefined, also when GiNaC cancels
// the quantity as it builds the expression (0*X = 0, X - X = 0, X^0 = 1) or cancels the
// quantity's divisor against a factor (D*omega_out = N, omega_out = N/D). Before, each case below
// held at a dead centre or where beta is undefined, or was proved with no exception.
#include <gtest/gtest.h>

#include <string>

#include "check/check_polygon.h"
#include "io/claim_file.h"
#include "proof/prove.h"

namespace linkproof {
namespace {

DataClaim one_claim(const std::string& lhs, const std::string& rhs, bool for_each_j = false) {
  const std::string text = "claims:\n  - id: c\n    source: test\n    statement: s\n" +
                           std::string(for_each_j ? "    for_each: j\n" : "") + "    lhs: \"" + lhs + "\"\n    rhs: \"" +
                           rhs + "\"\n";
  return parse_claim_file(text, "words.yaml").claims.front();
}

TEST(WrittenWords, EveryQuantityWordIsRecordedWithItsBindingAndWhetherTheExpressionReadsIt) {
  const DataClaim c = one_claim("0*omega_dot_out + D*omega_out + sum_j(cot_beta[j] - cot_beta[j]) + Q[1]*0", "0");
  const auto& w = c.lhs.words();
  ASSERT_EQ(w.size(), 6u);
  EXPECT_EQ(w[0].text, "omega_dot_out");
  EXPECT_TRUE(w[0].cancelled);
  EXPECT_EQ(w[1].text, "D");
  EXPECT_FALSE(w[1].cancelled);
  EXPECT_EQ(w[2].text, "omega_out");
  EXPECT_FALSE(w[2].cancelled);
  for (size_t k : {3u, 4u}) {
    EXPECT_EQ(w[k].text, "cot_beta[j]");
    EXPECT_EQ(w[k].binding, IndexBinding::SumJ);
    EXPECT_TRUE(w[k].cancelled);
  }
  EXPECT_EQ(w[5].text, "Q[1]");
  EXPECT_TRUE(w[5].cancelled);
  EXPECT_NE(w[0].where.find("words.yaml:"), std::string::npos) << w[0].where;
}

// The same word read under one binding and cancelled under another: only the cancelled reading
// is marked (a sum reads every j, the for_each claim only its own).
TEST(WrittenWords, AWordIsCancelledPerBinding) {
  const DataClaim c = one_claim("sum_j(cot_beta[j]) + sum_pairs(cot_beta[j]) - sum_pairs(cot_beta[j])", "cot_beta[1]");
  const auto& w = c.lhs.words();
  ASSERT_EQ(w.size(), 3u);
  EXPECT_EQ(w[0].binding, IndexBinding::SumJ);
  EXPECT_FALSE(w[0].cancelled);
  EXPECT_EQ(w[1].binding, IndexBinding::SumPairs);
  EXPECT_TRUE(w[1].cancelled);
  EXPECT_TRUE(w[2].cancelled);
  ASSERT_EQ(c.rhs.words().size(), 1u);
  EXPECT_FALSE(c.rhs.words()[0].cancelled);
}

// Checked where the word is undefined: undefined exactly; in double undefined or, where the
// word is only not distinguishable from undefined, inconclusive; never holds.
TEST(WrittenWords, ACancelledWordThatIsUndefinedMakesTheCheckUndefinedNotHolds) {
  GroundTruthEngine engine;
  // D = r_4 x r_5 = 0 (verify/scenes/degenerate/dead_centre.yaml).
  const Polygon<Rational> dead({{0, 0}, {0, 4}, {3, 6}, {7, 5}, {8, 1}, {Rational(17) / 2, -1}});
  const InputRates<Rational> dead_rates{{1, -2, 3}, {Rational(1) / 2, -1, 2}};
  // beta_1 undefined (verify/scenes/degenerate/beta_undefined.yaml).
  const Polygon<Rational> flat_beta({{0, 0}, {-1, 2}, {5, 5}, {7, 1}, {3, -2}});
  const InputRates<Rational> beta_rates{{2, -1}, {1, 3}};
  const std::vector<Claim> at_dead{to_claim(one_claim("0*omega_dot_out", "0")), to_claim(one_claim("D^0", "1")),
                                   to_claim(one_claim("omega_out - omega_out", "0"))};
  const std::vector<Claim> at_beta{to_claim(one_claim("cot_beta[j] - cot_beta[j]", "0", true)),
                                   to_claim(one_claim("0", "sum_j(0*cot_beta[j])"))};
  for (Arithmetic a : {Arithmetic::Exact, Arithmetic::Double, Arithmetic::Mp30}) {
    const auto expect_not_decided = [&](const ClaimOutcome& o) {
      if (a == Arithmetic::Exact) {
        EXPECT_EQ(o.verdict, Verdict::Undefined) << to_string(o.verdict) << " " << o.headline.label;
      } else {
        EXPECT_TRUE(o.verdict == Verdict::Undefined || o.verdict == Verdict::Inconclusive)
            << to_string(a) << " " << to_string(o.verdict) << " " << o.headline.label;
      }
    };
    for (const ClaimOutcome& o : check_polygon(engine, at_dead, "dead", dead, dead_rates, a).claims) expect_not_decided(o);
    for (const ClaimOutcome& o : check_polygon(engine, at_beta, "beta", flat_beta, beta_rates, a).claims) expect_not_decided(o);
  }
  // Where the words are defined the same claims hold.
  const Polygon<Rational> fine({{0, 0}, {1, 4}, {5, 5}, {7, 1}, {3, -2}});
  for (const auto* claims : {&at_dead, &at_beta})
    for (const ClaimOutcome& o : check_polygon(engine, *claims, "fine", fine, beta_rates, Arithmetic::Exact).claims)
      EXPECT_EQ(o.verdict, Verdict::Holds) << to_string(o.verdict);
}

bool lists_dead_centre(const ProofResult& r) {
  for (const auto& e : r.except)
    if (e.meaning.find("dead centre") != std::string::npos) return true;
  return false;
}

// Proved with no exception before: each is undefined at the dead centre.
TEST(WrittenWords, AWordWhoseDivisorCancelsPutsItInTheExceptionalSet) {
  GroundTruthEngine engine;
  ProveOptions o;
  o.ladder_seconds = 0;
  for (const auto& [lhs, rhs] : {std::pair<std::string, std::string>{"D*omega_out", "sum_j(cross(r[j], r[n-2])*omega[j])"},
                                 {"0*omega_dot_out", "0"},
                                 {"omega_out - omega_out", "0"}}) {
    const ProofResult r = prove_claim(engine, one_claim(lhs, rhs), o);
    EXPECT_EQ(r.verdict, ProofVerdict::ProvedGenerically) << lhs << " = " << rhs << ": " << to_string(r.verdict) << " " << r.error;
    EXPECT_TRUE(lists_dead_centre(r)) << lhs << " = " << rhs << ": " << r.except.size() << " exceptions";
  }
}

}  // namespace
}  // namespace linkproof
