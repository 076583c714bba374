// Issue 11: no "proved" or "holds" that the work behind it does not support. Each test is one
// finding of the review, reproduced; each failed before the fix.
#include <gtest/gtest.h>

#include "exit_status.h"
#include "io/claim_file.h"
#include "proof/lift.h"
#include "proof/prove.h"

namespace linkproof {
namespace {

DataClaim soundness_claim(const std::string& body) {
  const ClaimFile f = parse_claim_file("claims:\n" + body, "test.yaml");
  return f.claims.front();
}

ProveOptions no_ladder_options() {
  ProveOptions o;
  o.ladder_seconds = 0;
  return o;
}

// Finding 1: a bounded range was proved at its first n (4, where no pair terms exist), and the
// printed argument still said "At n = 5". (22) with j < l sums is false.
TEST(Soundness, BoundedRangeWrongClaimWithZeroLadderIsDisproved) {
  const DataClaim c = soundness_claim(R"Y(  - id: eq22.lt
    source: test
    statement: "(22) summed over j < l only"
    n: "4..100"
    lhs: omega_dot_out
    rhs: >-
      sum_j(lambda[j]*omega[j]^2 + i_out[j]*omega_dot[j])
      - cot_phi*sum_pairs_lt(i_out[j]*i_out[l]*omega[j]*omega[l])
      - rho*sum_pairs_lt(i_cpl[j]*i_cpl[l]*omega[j]*omega[l])
)Y");
  GroundTruthEngine engine;
  const ProofResult r = prove_claim(engine, c, no_ladder_options());
  EXPECT_EQ(r.verdict, ProofVerdict::Disproved) << to_string(r.verdict) << " " << r.scope << " " << r.error;
  ASSERT_TRUE(r.counterexample.has_value());
  EXPECT_GE(r.counterexample->polygon.n(), 5);
}

// Finding 2: a claim that is not local was "proved" from one n and a second of per-n checks.
TEST(Soundness, NonLocalClaimGetsProvedForWithTheExactListOfN) {
  const DataClaim c = soundness_claim(R"Y(  - id: first.input
    source: test
    statement: "side 1 turns at the first input's rate"
    lhs: side_omega[1]
    rhs: omega[1]
)Y");
  GroundTruthEngine engine;
  const ProofResult r = prove_claim(engine, c, no_ladder_options());
  EXPECT_EQ(r.verdict, ProofVerdict::ProvedFor) << to_string(r.verdict) << " " << r.error;
  EXPECT_FALSE(r.not_local.empty());
  EXPECT_EQ(r.proved_n, (std::vector<int>{4, 5}));
  EXPECT_EQ(r.scope.rfind("n = 4, 5 only", 0), 0u) << r.scope;
  EXPECT_TRUE(r.is_as_expected());
  EXPECT_FALSE(cli::is_as_expected(r, /*strict=*/true));
}

// Finding 2, second half: a claim true at n = 4, 5 but false from n = 6 on; before, it came
// back proved. Positive verdicts now run the counterexample search over n = 4..8 first.
TEST(Soundness, ClaimFalseOnlyFromN6IsDisprovedNotProved) {
  const DataClaim c = soundness_claim(R"Y(  - id: square.of.pairs
    source: test
    statement: "(sum of pair products)^2 = sum of squared pair products (true with <= 2 inputs)"
    lhs: sum_pairs_lt(omega[j]*omega[l])^2
    rhs: sum_pairs_lt(omega[j]^2*omega[l]^2)
)Y");
  GroundTruthEngine engine;
  const ProofResult r = prove_claim(engine, c, no_ladder_options());
  EXPECT_EQ(r.verdict, ProofVerdict::Disproved) << to_string(r.verdict) << " " << r.scope;
  ASSERT_TRUE(r.counterexample.has_value());
  EXPECT_GE(r.counterexample->polygon.n(), 6);
}

// Finding 4: indices are checked when the claim file is read, for every n of the range.
TEST(Soundness, OutOfRangeIndicesAreRefusedAtLoadNamingTheLineAndColumn) {
  for (const std::string lhs : {"omega[999]", "omega[0]", "omega[-1]", "side_omega[999]", "K[0]", "1000 + side_omega[0]",
                                 "omega[2]", "r[n+1]", "omega[n-2]"}) {
    SCOPED_TRACE(lhs);
    try {
      soundness_claim("  - id: x\n    source: t\n    statement: s\n    lhs: " + lhs + "\n    rhs: 1\n");
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("test.yaml:5:"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("outside"), std::string::npos) << e.what();
    }
  }
  // omega[2] exists from n = 5: with the range stated it is accepted.
  EXPECT_NO_THROW(soundness_claim("  - id: x\n    source: t\n    statement: s\n    n: 5..\n    lhs: omega[2]\n    rhs: omega[2]\n"));
  // An index that grows away from its range for large n is refused too.
  EXPECT_THROW(soundness_claim("  - id: x\n    source: t\n    statement: s\n    lhs: sum_j(r[2*j])\n    rhs: 1\n"), InputError);
  EXPECT_NO_THROW(soundness_claim("  - id: x\n    source: t\n    statement: s\n    lhs: sum_pairs_lt(r[l-j])\n    rhs: 1\n"));
}

TEST(Soundness, Section3FormulaWithoutItsRangeIsRefusedAtLoad) {
  EXPECT_THROW(soundness_claim(R"Y(  - id: sec3.any.n
    source: test
    statement: "the pentagon formula, but for every n"
    lhs: omega_dot_out
    rhs: >-
      i_out[1]*(1 - i_out[1])*omega[1]^2*cot_beta[1] + i_out[1]*omega_dot[1]
      + i_out[2]*(1 - i_out[2])*omega[2]^2*cot_beta[2] + i_out[2]*omega_dot[2]
)Y"),
               InputError);
}

// Finding 5: a reading that moves r_j's start to K_j (depending on every side after j) made a
// claim "local" by its index syntax alone.
TEST(Soundness, ReadingThatReadsOtherSidesIsNotLifted) {
  const std::string body = R"(  - id: kp.identity
    source: test
    statement: "K'_j = K'_j"
    for_each: j
    READING
    lhs: vx(Kp[j])
    rhs: vx(Kp[j])
)";
  GroundTruthEngine engine;
  std::string with_reading = body;
  with_reading.replace(with_reading.find("READING"), 7, "reading: [undisplaced_start]");
  const LiftCheck lift = check_lift_lemma(engine, soundness_claim(with_reading), 6);
  ASSERT_FALSE(lift.violations.empty());
  EXPECT_NE(lift.violations.front().find("depends on r_"), std::string::npos) << lift.violations.front();
  const ProofResult r = prove_claim(engine, soundness_claim(with_reading), no_ladder_options());
  EXPECT_EQ(r.verdict, ProofVerdict::ProvedFor) << to_string(r.verdict);

  std::string plain = body;
  plain.replace(plain.find("READING"), 7, "note: displaced");
  EXPECT_TRUE(check_lift_lemma(engine, soundness_claim(plain), 6).violations.empty());
  EXPECT_EQ(prove_claim(engine, soundness_claim(plain), no_ladder_options()).verdict, ProofVerdict::Proved);
}

// Finding 6: a polynomial identity came back with 17 exceptions it never touches.
TEST(Soundness, PolynomialIdentityIsProvedWithNoExceptions) {
  const DataClaim c = soundness_claim(R"Y(  - id: kp.translation
    source: test
    statement: "K'_j = K_{n-2} - r_j"
    for_each: j
    lhs: vx(Kp[j]) + vy(Kp[j])
    rhs: vx(K[n-2] - r[j]) + vy(K[n-2] - r[j])
)Y");
  GroundTruthEngine engine;
  const ProofResult r = prove_claim(engine, c, no_ladder_options());
  EXPECT_EQ(r.verdict, ProofVerdict::Proved) << to_string(r.verdict) << " " << r.error;
  EXPECT_TRUE(r.except.empty()) << r.except.size() << " exceptions, first: " << r.except.front().meaning;
}

// Finding 6: a divisor inside the claim's own expression, cancelled by normal(), made "proved"
// where the claim is undefined (at the dead centre).
TEST(Soundness, CancelledDivisorOfTheClaimIsInTheExceptionalSet) {
  const DataClaim c = soundness_claim(R"Y(  - id: d.over.d
    source: test
    statement: "D / D = 1"
    lhs: D / cross(r[n-2], r[n-1])
    rhs: 1
)Y");
  GroundTruthEngine engine;
  const ProofResult r = prove_claim(engine, c, no_ladder_options());
  EXPECT_EQ(r.verdict, ProofVerdict::ProvedGenerically) << to_string(r.verdict) << " " << r.error;
  ASSERT_EQ(r.except.size(), 1u);
  EXPECT_NE(r.except.front().meaning.find("dead centre"), std::string::npos) << r.except.front().meaning;
}

// Finding 3: ProofResult::is_as_expected accepted anything but disproved and error.
TEST(Soundness, OnlyProofsOfTheWholeRangeAreAsExpectedWhenStrict) {
  ProofResult r;
  r.expected = Expectation::Holds;
  for (auto [v, loose, strict] : {std::tuple{ProofVerdict::Proved, true, true},
                                  std::tuple{ProofVerdict::ProvedGenerically, true, true},
                                  std::tuple{ProofVerdict::ProvedFor, true, false},
                                  std::tuple{ProofVerdict::HoldsOnSamples, true, false},
                                  std::tuple{ProofVerdict::Disproved, false, false},
                                  std::tuple{ProofVerdict::Error, false, false}}) {
    r.verdict = v;
    EXPECT_EQ(r.is_as_expected(), loose) << to_string(v);
    EXPECT_EQ(cli::is_as_expected(r, true), strict) << to_string(v);
  }
  r.expected = Expectation::Fails;
  r.verdict = ProofVerdict::Error;
  EXPECT_FALSE(r.is_as_expected());
}

}  // namespace
}  // namespace linkproof
