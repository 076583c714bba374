// The per-n ladder of `prove` (proof/prove.h, ProveOptions::recheck_proved): by default it adds
// per-n proofs only where the proofs so far leave part of a claim's range uncovered, so a claim
// proved for every n gets the same result on every machine; re-checks of such a claim run when
// asked (--ladder-seconds or --n-max given).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "io/claim_file.h"
#include "proof/prove.h"
#include "support/cli_run.h"

namespace linkproof {
namespace {

using test::run_cli;

DataClaim one_claim(const std::string& body) { return parse_claim_file("claims:\n" + body, "test.yaml").claims.front(); }

// eq. (5) of the catalogue, written out: proved for every n >= 4 by the proofs at n = 4 and 5
// and the lift lemma.
const char* const kEq5 = R"Y(  - id: eq5.copy
    source: test
    statement: "omega of the output side, as eq. (5) gives it"
    lhs: omega_out
    rhs: sum_j(i_out[j]*omega[j])
)Y";

TEST(ProveLadder, AClaimProvedForEveryNIsNotReprovedPerNByDefault) {
  GroundTruthEngine engine;
  const ProofResult r = prove_claim(engine, one_claim(kEq5), ProveOptions{});
  ASSERT_EQ(r.verdict, ProofVerdict::ProvedGenerically) << to_string(r.verdict) << " " << r.error;
  EXPECT_EQ(r.proved_n, (std::vector<int>{4, 5}));  // the argument's proofs only, whatever the budget
  ASSERT_EQ(r.per_n.size(), 2u);
}

TEST(ProveLadder, ReChecksOfAClaimProvedForEveryNRunWhenAsked) {
  GroundTruthEngine engine;
  ProveOptions o;
  o.recheck_proved = true;
  o.ladder_seconds = 600;  // bounded by n_max, not by time
  o.n_max = 7;
  const ProofResult r = prove_claim(engine, one_claim(kEq5), o);
  ASSERT_EQ(r.verdict, ProofVerdict::ProvedGenerically) << to_string(r.verdict) << " " << r.error;
  EXPECT_EQ(r.proved_n, (std::vector<int>{4, 5, 6, 7}));
}

TEST(ProveLadder, AClaimTheLiftDoesNotCoverStillGetsPerNProofsByDefault) {
  // Not local (side 1 at every n): no proof for every n; the default ladder adds coverage.
  GroundTruthEngine engine;
  ProveOptions o;
  o.n_max = 6;  // what the ladder would reach given time; the default budget of 1 s suffices here
  const ProofResult r = prove_claim(engine, one_claim(R"Y(  - id: first.input
    source: test
    statement: "side 1 turns at the first input's rate"
    lhs: side_omega[1]
    rhs: omega[1]
)Y"),
                                    o);
  EXPECT_EQ(r.verdict, ProofVerdict::ProvedFor) << to_string(r.verdict) << " " << r.error;
  EXPECT_EQ(r.proved_n, (std::vector<int>{4, 5, 6}));
}

std::vector<int> per_n_of(const std::string& json_text) {
  const nlohmann::json j = nlohmann::json::parse(json_text);
  std::vector<int> out;
  for (const auto& p : j.at("claims").at(0).at("per_n")) out.push_back(p.at("n").get<int>());
  return out;
}

TEST(ProveLadder, TheCommandLineReChecksOnlyWhenALadderOptionIsGiven) {
  const auto plain = run_cli({"prove", "--claim", "eq5", "--json"});
  ASSERT_EQ(plain.code, 0) << plain.err;
  EXPECT_EQ(per_n_of(plain.out), (std::vector<int>{4, 5}));
  const auto bounded = run_cli({"prove", "--claim", "eq5", "--n-max", "6", "--ladder-seconds", "600", "--json"});
  ASSERT_EQ(bounded.code, 0) << bounded.err;
  EXPECT_EQ(per_n_of(bounded.out), (std::vector<int>{4, 5, 6}));
  const auto by_n_max = run_cli({"prove", "--claim", "eq5", "--n-max", "5", "--json"});
  ASSERT_EQ(by_n_max.code, 0) << by_n_max.err;
  EXPECT_EQ(per_n_of(by_n_max.out), (std::vector<int>{4, 5}));
}

}  // namespace
}  // namespace linkproof
