// Mechanism claims proved over every configuration of a topology (proof/mechanism_proof.h):
// true claims are proved (with the exceptional set they divide by), wrong ones disproved with a
// counterexample, a claim true only on unit axes is proved through the relation c^2 + s^2 = 1,
// a claim undefined everywhere is an error, and a proof out of its budget says it rests on
// samples.
#include "proof/mechanism_proof.h"

#include <gtest/gtest.h>

#include <iostream>

#include "io/claim_file.h"
#include "linkproof/core/error.h"
#include "linkproof/io/mechanism_scene.h"
#include "mechanism/mechanism_data_claim.h"
#include "support/topology_claims.h"

namespace linkproof {
namespace {


MechanismScene scene(const std::string& rel) { return load_mechanism_scene(test::source_path(rel)); }

std::vector<MechanismDataClaim> claims_in(const std::string& rel, const MechanismScene& s) {
  return test::bind_all(load_mechanism_claim_file(test::source_path(rel)), s);
}

std::vector<MechanismDataClaim> claims_from(const std::string& yaml, const MechanismScene& s) {
  return test::bind_all(parse_mechanism_claim_file(yaml, "test.yaml"), s);
}

const TopologyProof& find(const TopologyProofRun& run, const std::string& id) {
  for (const TopologyProof& p : run.claims)
    if (p.info.id == id) return p;
  throw std::runtime_error("no claim " + id);
}

bool mentions(const std::vector<ExceptionalSet>& except, const std::string& words) {
  for (const ExceptionalSet& e : except)
    if (e.meaning.find(words) != std::string::npos) return true;
  return false;
}

TEST(MechanismProof, FourBarClaimsAreProvedForEveryConfigurationAndWrongVariantsDisproved) {
  const MechanismScene s = scene("verify/scenes/mechanisms/seed001_fourbar.yaml");
  const TopologyProofRun run = prove_topology(s, claims_in("verify/claims/mechanisms/fourbar.yaml", s), {});
  EXPECT_EQ(run.symbols.size(), 12u) << "4 joints and P: 10 coordinates; the input's two rates";
  for (const TopologyProof& p : run.claims) {
    std::cout << p.info.id << ": " << to_string(p.verdict) << " in " << p.seconds << " s\n";
    EXPECT_TRUE(p.is_as_expected()) << p.info.id << ": " << to_string(p.verdict) << " " << p.error;
    if (p.info.expected == Expectation::Holds) {
      EXPECT_TRUE(p.verdict == ProofVerdict::Proved || p.verdict == ProofVerdict::ProvedGenerically) << p.info.id;
    } else {
      ASSERT_EQ(p.verdict, ProofVerdict::Disproved) << p.info.id;
      ASSERT_TRUE(p.counterexample.has_value());
      EXPECT_EQ(p.counterexample->outcome.verdict, Verdict::Fails) << p.counterexample->scene_yaml;
    }
  }
  // Rigid-body identities hold for any rates: proved with no exception, dead centres included.
  EXPECT_EQ(find(run, "fourbar.coupler_velocity").verdict, ProofVerdict::Proved);
  EXPECT_EQ(find(run, "fourbar.coupler_point_acceleration").verdict, ProofVerdict::Proved);
  // The closed form of alpha_3 needs the loop closure: it divides by det A.
  const TopologyProof& alpha3 = find(run, "fourbar.alpha3_closed_form");
  EXPECT_EQ(alpha3.verdict, ProofVerdict::ProvedGenerically);
  EXPECT_TRUE(mentions(alpha3.except, "dead centre")) << "the motion divides by det A";
  const TopologyProof& pole = find(run, "fourbar.coupler_pole");
  EXPECT_TRUE(mentions(pole.except, "omega(\"3\") = omega(\"1\")")) << "pole(3, 1) divides by omega_3 - omega_1";
  EXPECT_TRUE(mentions(pole.except, "parallel")) << "meet divides by the cross product of its lines";
}

// A dyad pinned to the frame at both ends does not turn, except where its two pins and their
// joint are collinear: there the velocity system is singular (the scene has mobility 2) and
// omega_5 = 1, omega_6 = -1 satisfies every constraint. Its solved rate has the numerator 0,
// so the residual showed no det A and the claim was proved "on every configuration".
TEST(MechanismProof, AClaimOnASolvedRateWhoseNumeratorIsZeroListsTheDeterminant) {
  const MechanismScene s = parse_mechanism_scene(R"yaml(name: fourbar-with-ground-truss
mechanism:
  ground: "1"
  links: ["1", "2", "3", "4", "5", "6"]
  joints:
    - {name: O2, type: revolute, links: ["1", "2"], at: [0, 0]}
    - {name: A,  type: revolute, links: ["2", "3"], at: [3, 4]}
    - {name: B,  type: revolute, links: ["3", "4"], at: [11, 10]}
    - {name: O4, type: revolute, links: ["4", "1"], at: [11, 0]}
    - {name: G1, type: revolute, links: ["1", "5"], at: [20, 0]}
    - {name: C,  type: revolute, links: ["5", "6"], at: [25, 5]}
    - {name: G2, type: revolute, links: ["6", "1"], at: [30, 0]}
  inputs:
    - {link: "2", omega: 2, omega_dot: 5}
)yaml", "truss.yaml");
  const TopologyProofRun run = prove_topology(s, claims_from(R"yaml(claims:
  - id: truss_at_rest
    source: test
    statement: "omega(5) = 0"
    lhs: omega("5")
    rhs: 0
  - id: truss_joint_at_rest
    source: test
    statement: "vel(C, 5) = 0"
    lhs: vel(C, "5")
    rhs: vec(0, 0)
)yaml", s), {});
  for (const TopologyProof& p : run.claims) {
    EXPECT_EQ(p.verdict, ProofVerdict::ProvedGenerically) << p.info.id << ": " << to_string(p.verdict) << " " << p.error;
    EXPECT_TRUE(mentions(p.except, "det A = 0")) << p.info.id << ": " << p.except.size() << " exceptions";
  }
}

TEST(MechanismProof, AClaimAboutPositionsAloneIsProvedWithNoException) {
  const MechanismScene s = scene("verify/scenes/mechanisms/seed001_fourbar.yaml");
  const TopologyProofRun run = prove_topology(s, claims_from(R"yaml(claims:
  - id: law_of_cosines
    source: test
    statement: "|B - O2|^2 = |A - O2|^2 + |B - A|^2 + 2 (A - O2).(B - A)"
    lhs: norm2(pos(B) - pos(O2))
    rhs: norm2(pos(A) - pos(O2)) + norm2(pos(B) - pos(A)) + 2*dot(pos(A) - pos(O2), pos(B) - pos(A))
)yaml", s), {});
  ASSERT_EQ(run.claims.size(), 1u);
  EXPECT_EQ(run.claims[0].verdict, ProofVerdict::Proved) << run.claims[0].error;
  EXPECT_TRUE(run.claims[0].except.empty());
}

TEST(MechanismProof, AClaimTrueOnlyForUnitAxesIsProvedThroughTheRelation) {
  // |v_rel|^2 = sigma-dot^2 |u|^2: the sliding speed squared only where |u| = 1, which the
  // topology's axes are (c^2 + s^2 = 1). Without the reduction the numerator is not zero.
  const MechanismScene s = scene("verify/scenes/mechanisms/inverted_slider_crank.yaml");
  const TopologyProofRun run = prove_topology(s, claims_from(R"yaml(claims:
  - id: sliding_speed
    source: test
    statement: "|v_S(block) - v_S(rocker)|^2 = sliding_v(S)^2"
    lhs: norm2(vel(S, block, rocker))
    rhs: sliding_v(S)^2
  - id: sliding_speed_doubled
    source: test
    statement: "wrong: twice the square"
    expected: fails
    lhs: norm2(vel(S, block, rocker))
    rhs: 2*sliding_v(S)^2
)yaml", s), {});
  ASSERT_EQ(run.relations.size(), 1u);
  EXPECT_EQ(run.relations[0], "c_S^2 + s_S^2 = 1");
  // No division, and true for any rates: proved, through the relation.
  EXPECT_EQ(find(run, "sliding_speed").verdict, ProofVerdict::Proved) << find(run, "sliding_speed").error;
  EXPECT_EQ(find(run, "sliding_speed_doubled").verdict, ProofVerdict::Disproved);
}

TEST(MechanismProof, ANonIdentityFoundSymbolicallyIsDisprovedWithACounterexample) {
  const MechanismScene s = scene("verify/scenes/mechanisms/seed001_fourbar.yaml");
  TopologyProofOptions o;
  o.quick_samples = 0;  // no sampling first: the symbolic residual must find it
  std::vector<MechanismDataClaim> claims = claims_in("verify/claims/mechanisms/fourbar.yaml", s);
  std::erase_if(claims, [](const MechanismDataClaim& c) { return c.info.id != "fourbar.alpha3_closed_form_sign_flip"; });
  const TopologyProofRun run = prove_topology(s, claims, o);
  ASSERT_EQ(run.claims.size(), 1u);
  const TopologyProof& p = run.claims[0];
  EXPECT_EQ(p.verdict, ProofVerdict::Disproved);
  ASSERT_FALSE(p.argument.empty());
  EXPECT_NE(p.argument[0].find("not identically zero"), std::string::npos) << p.argument[0];
  EXPECT_GT(p.numerator_terms, 0);
}

TEST(MechanismProof, AClaimUndefinedOnEveryConfigurationIsAnErrorNotAProof) {
  const MechanismScene s = scene("verify/scenes/mechanisms/seed001_fourbar.yaml");
  const TopologyProofRun run = prove_topology(s, claims_from(R"yaml(claims:
  - id: pole_of_a_link_with_itself
    source: test
    statement: "the pole of the coupler relative to itself"
    lhs: pole("3", "3")
    rhs: pos(A)
  - id: divide_by_zero
    source: test
    statement: "omega_3 / (omega_2 - omega_2)"
    lhs: omega("3") / (omega("2") - omega("2"))
    rhs: 1
  - id: zero_over_zero_by_the_loop_closure
    source: test
    statement: "x / x = 1 with x = 0 on every configuration (v_B of the coupler and of the rocker agree)"
    lhs: vx(vel(B, "3") - vel(B, "4")) / vx(vel(B, "3") - vel(B, "4"))
    rhs: 1
)yaml", s), {});
  ASSERT_EQ(run.claims.size(), 3u);
  for (const TopologyProof& p : run.claims) {
    EXPECT_EQ(p.verdict, ProofVerdict::Error) << p.info.id;
    EXPECT_FALSE(p.is_as_expected()) << p.info.id;
    EXPECT_NE(p.error.find("undefined"), std::string::npos) << p.error;
  }
}

// Read from a claim file (check-claim, prove --file), the same claim is bad input naming the
// file and the claim, as a polygon claim with an identically zero divisor is: it exited 3, the
// status of an internal error.
TEST(MechanismProof, AUserClaimUndefinedOnEveryConfigurationIsBadInput) {
  const MechanismScene s = scene("verify/scenes/mechanisms/seed001_fourbar.yaml");
  std::vector<MechanismDataClaim> claims = claims_from(R"yaml(claims:
  - id: pole_of_a_link_with_itself
    source: test
    statement: "the pole of the coupler relative to itself"
    lhs: pole("3", "3")
    rhs: pos(A)
)yaml", s);
  claims[0].info.file = "mine.yaml";
  try {
    (void)prove_topology(s, claims, {});
    FAIL() << "proved or judged";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("mine.yaml"), std::string::npos) << m;
    EXPECT_NE(m.find("claim 'pole_of_a_link_with_itself'"), std::string::npos) << m;
    EXPECT_NE(m.find("undefined on every configuration"), std::string::npos) << m;
  }
}

TEST(MechanismProof, AProofOutOfItsBudgetFallsBackToAnIdentityTestThatStatesItsFailureBound) {
  const MechanismScene s = scene("verify/scenes/mechanisms/seed001_fourbar.yaml");
  TopologyProofOptions o;
  o.seconds = 0;
  std::vector<MechanismDataClaim> claims = claims_in("verify/claims/mechanisms/fourbar.yaml", s);
  std::erase_if(claims, [](const MechanismDataClaim& c) { return c.info.id != "fourbar.alpha3_closed_form"; });
  const TopologyProofRun run = prove_topology(s, claims, o);
  ASSERT_EQ(run.claims.size(), 1u);
  const TopologyProof& p = run.claims[0];
  EXPECT_EQ(p.verdict, ProofVerdict::HoldsWithProbability);
  EXPECT_EQ(p.trials, 3);
  EXPECT_GT(p.degree_bound, 0);
  EXPECT_GT(p.failure_bound, 0);
  EXPECT_LT(p.failure_bound, 1e-20);
  ASSERT_FALSE(p.argument.empty());
  EXPECT_NE(p.argument.front().find("budget"), std::string::npos) << p.argument.front();
  EXPECT_NE(p.argument.back().find("NOT a proof"), std::string::npos) << p.argument.back();
}

TEST(MechanismProof, TheIdentityTestDisprovesAWrongClaimWithACounterexample) {
  const MechanismScene s = scene("verify/scenes/mechanisms/seed001_fourbar.yaml");
  TopologyProofOptions o;
  o.seconds = 0;
  o.quick_samples = 0;
  std::vector<MechanismDataClaim> claims = claims_in("verify/claims/mechanisms/fourbar.yaml", s);
  std::erase_if(claims, [](const MechanismDataClaim& c) { return c.info.id != "fourbar.alpha3_closed_form_sign_flip"; });
  const TopologyProofRun run = prove_topology(s, claims, o);
  ASSERT_EQ(run.claims.size(), 1u);
  EXPECT_EQ(run.claims[0].verdict, ProofVerdict::Disproved);
  ASSERT_TRUE(run.claims[0].counterexample.has_value());
  EXPECT_EQ(run.claims[0].counterexample->outcome.verdict, Verdict::Fails);
}

}  // namespace
}  // namespace linkproof
