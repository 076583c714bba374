// ClaimProgram: a claim expression is compiled once per process, and whether it is well formed
// (numbers and vectors where each is allowed) is decided then, for every n, not per evaluated
// term.
#include <gtest/gtest.h>

#include <string>

#include "check/check_polygon.h"
#include "claims/claim_program.h"
#include "io/claim_file.h"
#include "support/polygons.h"

namespace linkproof {
namespace {

TEST(ClaimProgram, AnExpressionIsCompiledOncePerProcess) {
  // Two parses of one text are two GiNaC trees; they share one program.
  const ClaimExpression a = ClaimExpression::parse("sum_pairs(i_out[j]*i_out[l]*omega[j]*omega[l])");
  const ClaimExpression b = ClaimExpression::parse("sum_pairs(i_out[j]*i_out[l]*omega[j]*omega[l])");
  const ClaimProgram& p = compiled_claim(a.expression());
  EXPECT_EQ(&p, &compiled_claim(b.expression()));
  EXPECT_NE(&p, &compiled_claim(ClaimExpression::parse("sum_j(omega[j])").expression()));
  // One sum over pairs of one product of four indexed words, each index read once.
  EXPECT_EQ(p.nodes[static_cast<size_t>(p.root)].op, ClaimProgram::Op::IndexSum);
  EXPECT_EQ(p.nodes[static_cast<size_t>(p.root)].evaluation, Evaluation::SumPairs);
  EXPECT_EQ(p.indexes.size(), 4u);
  for (const auto& index : p.indexes) EXPECT_TRUE(index.affine) << index.written;
}

TEST(ClaimProgram, IndicesAreAffineFormsInNJAndL) {
  const ClaimProgram& p = compiled_claim(ClaimExpression::parse("sum_j(dot(r[n-1], r[j+1])*omega[j])").expression());
  ASSERT_EQ(p.indexes.size(), 3u);
  const auto find = [&](const std::string& written) {
    for (const auto& i : p.indexes)
      if (i.written == written) return i;
    ADD_FAILURE() << "no index " << written;
    return ClaimProgram::Index{};
  };
  const auto last = find("r[-1+n]");
  EXPECT_TRUE(last.affine);
  EXPECT_EQ(last.c0, -1);
  EXPECT_EQ(last.cn, 1);
  EXPECT_EQ(last.cj, 0);
  const auto next = find("r[1+j]");
  EXPECT_TRUE(next.affine);
  EXPECT_EQ(next.c0, 1);
  EXPECT_EQ(next.cj, 1);
  EXPECT_NE(next.bound_note.find("an index other than j, l"), std::string::npos) << next.bound_note;
  EXPECT_TRUE(find("omega[j]").bare_bound);
}

// On a four-bar there are no pairs: the interpreter never evaluated the body of sum_pairs, so a
// product of two vectors there was a sum of nothing and the claim "held" (0 = 0). The claim is
// ill formed at every n and is now refused as such.
TEST(ClaimProgram, AnIllFormedTermIsRefusedEvenWhereNoTermIsEvaluated) {
  const std::string yaml =
      "claims:\n  - id: vectors\n    source: notes\n    statement: s\n    lhs: 0\n"
      "    rhs: sum_pairs(r[j]*r[l])\n";
  GroundTruthEngine engine;
  const Polygon<Rational> four_bar({{0, 0}, {1, 3}, {4, 4}, {5, 0}});
  const InputRates<Rational> rates{{2}, {1}};
  // As a catalogue claim: the verdict error, with the reason.
  const ClaimFile catalogue = parse_claim_file(yaml, "catalogue.yaml");
  const auto check = check_polygon(engine, {to_claim(catalogue.claims.at(0))}, "four-bar", four_bar, rates, Arithmetic::Exact);
  ASSERT_EQ(check.claims.size(), 1u);
  EXPECT_EQ(check.claims[0].verdict, Verdict::Error);
  EXPECT_NE(check.claims[0].error.find("product of two vectors"), std::string::npos) << check.claims[0].error;
  // As a user's claim: bad input naming the file and the claim.
  const ClaimFile user = parse_user_claim_file(yaml, "user.yaml");
  try {
    (void)check_polygon(engine, {to_claim(user.claims.at(0))}, "four-bar", four_bar, rates, Arithmetic::Exact);
    FAIL() << "an ill-formed user claim was checked";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("user.yaml: claim 'vectors'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("product of two vectors"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace linkproof
