// Koshel's class-III plans for epsilon1 and epsilon2 (four dyads nested, residual numerators of
// millions of terms) are proved for every configuration of the eight-link topology. With
// GiNaC's expansion they passed its term limit and ended `holds_with_probability` (a randomized
// identity test); the packed polynomials of proof/packed_polynomial.h hold them. The
// superposition rules for epsilon3 and epsilon5 (the plan drawn twice, with epsilon5 = 0 and
// with the true one, and a ratio of rates) need the factored normal form of
// proof/packed_normalizer.h: the plan's divisors taken once, not once per level of nesting.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "linkproof/io/mechanism_scene.h"
#include "proof/mechanism_proof.h"
#include "support/topology_claims.h"

namespace linkproof {
namespace {

std::string class3_source(const std::string& rel) { return std::string(LINKPROOF_SOURCE_DIR) + "/" + rel; }

// Koshel's claims `ids` over the topology with `options`.
std::vector<TopologyProof> koshel_proofs(const std::vector<std::string>& ids, const TopologyProofOptions& options) {
  const MechanismScene scene = load_mechanism_scene(class3_source("verify/scenes/mechanisms/seed003_class3.yaml"));
  const std::vector<MechanismDataClaim> claims =
      test::bound_claims(scene, class3_source("verify/claims/mechanisms/koshel_class3.yaml"), ids);
  EXPECT_EQ(claims.size(), ids.size());
  return prove_topology(scene, claims, options).claims;
}

// Each of `ids` proved generically, the crank's dead centres among its exceptions.
void expect_proved_outside_dead_centres(const std::vector<std::string>& ids) {
  TopologyProofOptions options;
  options.seconds = 400;  // wall clock under a sanitizer on a loaded machine; 1-8 s each on an idle core
  const std::vector<TopologyProof> proofs = koshel_proofs(ids, options);
  ASSERT_EQ(proofs.size(), ids.size());
  for (const TopologyProof& p : proofs) {
    SCOPED_TRACE(p.info.id);
    EXPECT_EQ(p.verdict, ProofVerdict::ProvedGenerically) << p.error << (p.argument.empty() ? "" : p.argument.back());
    EXPECT_TRUE(test::names_dead_centre(p)) << "det A = 0 is where the proof does not reach";
  }
}

TEST(ClassThreeTopologyProof, TheNestedDyadPlansForEpsilonOneAndTwoAreProvedWithTheCranksDeadCentresAsExceptions) {
  expect_proved_outside_dead_centres({"koshel.driver5.epsilon1", "koshel.driver5.epsilon2"});
}

TEST(ClassThreeTopologyProof, TheSuperpositionRulesForEpsilonThreeAndFiveAreProvedWithTheCranksDeadCentresAsExceptions) {
  expect_proved_outside_dead_centres({"koshel.superposition.epsilon3", "koshel.superposition.epsilon5"});
}

// The plan for epsilon3 under a cap on the terms a normal form holds (PackedLimits::held): in
// link 3's motion it needs 2,200-2,400 terms, in link 5's 1,600-1,700 (both drivers split the
// system into groups of 1, 2, 2, 1, 2, 1; the plan is built from link 5).
TopologyProof epsilon_three_held_to(size_t held) {
  TopologyProofOptions options;
  options.seconds = 400;
  options.packed_limits.held = held;
  const std::vector<TopologyProof> proofs = koshel_proofs({"koshel.driver5.epsilon3"}, options);
  return proofs.at(0);
}

bool argues(const TopologyProof& p, const std::string& text) {
  return std::any_of(p.argument.begin(), p.argument.end(), [&](const std::string& a) { return a.find(text) != std::string::npos; });
}

TEST(ClassThreeTopologyProof, PastTheLimitsWithOneDriverTheNextDriverIsTried) {
  const TopologyProof p = epsilon_three_held_to(1950);
  EXPECT_EQ(p.verdict, ProofVerdict::ProvedGenerically) << p.error << testing::PrintToString(p.argument);
  EXPECT_TRUE(argues(p, "with link 3 as the driver: no symbolic normal form within the budget")) << testing::PrintToString(p.argument);
  EXPECT_TRUE(argues(p, "link 5 drives next"));
  EXPECT_TRUE(argues(p, "solved with link 5 as the driver"));
}

TEST(ClassThreeTopologyProof, PastTheLimitsWithEveryDriverTheIdentityTestDecides) {
  const TopologyProof p = epsilon_three_held_to(300);
  EXPECT_EQ(p.verdict, ProofVerdict::HoldsWithProbability) << p.error << testing::PrintToString(p.argument);
  EXPECT_TRUE(argues(p, "link 5 drives next")) << testing::PrintToString(p.argument);
  EXPECT_TRUE(argues(p, "randomized identity test"));
}

}  // namespace
}  // namespace linkproof
