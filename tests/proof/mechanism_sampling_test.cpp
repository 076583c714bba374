// Random configurations of a topology: reproducible from (seed, index), true claims hold on
// them, wrong ones are disproved with a shrunk counterexample that re-fails on its own scene.
#include "proof/mechanism_sampling.h"

#include <gtest/gtest.h>

#include <iostream>

#include "io/claim_file.h"
#include "linkproof/io/mechanism_scene.h"
#include "mechanism/mechanism_data_claim.h"

namespace linkproof {
namespace {

std::string sampling_source(const std::string& rel) { return std::string(LINKPROOF_SOURCE_DIR) + "/" + rel; }

std::vector<MechanismDataClaim> bound_claims(const std::string& file, const MechanismScene& scene) {
  MechanismClaimFile f = load_mechanism_claim_file(sampling_source(file));
  for (MechanismDataClaim& c : f.claims) bind_mechanism_claim(c, scene);
  return f.claims;
}

TEST(MechanismSampling, ConfigurationsReplayFromSeedAndIndexAndKeepTheTopology) {
  const MechanismScene s = load_mechanism_scene(sampling_source("verify/scenes/mechanisms/inverted_slider_crank.yaml"));
  constexpr std::uint64_t kSeed = 7;
  std::cout << "seed " << kSeed << "\n";
  for (int i = 0; i < 20; ++i) {
    const MechanismScene a = random_topology_configuration(s, kSeed, i);
    const MechanismScene b = random_topology_configuration(s, kSeed, i);
    EXPECT_EQ(mechanism_scene_to_yaml(a), mechanism_scene_to_yaml(b)) << "configuration " << i;
    ASSERT_EQ(a.linkage.joint_count(), s.linkage.joint_count());
    for (int j = 0; j < s.linkage.joint_count(); ++j) {
      EXPECT_EQ(a.linkage.joint(j).name, s.linkage.joint(j).name);
      EXPECT_EQ(a.linkage.joint(j).type, s.linkage.joint(j).type);
    }
    // A and S coincide in the scene, so in every configuration; S's axis is a unit vector.
    EXPECT_EQ(a.linkage.joint(1).at.x, a.linkage.joint(2).at.x);
    EXPECT_EQ(a.linkage.joint(1).at.y, a.linkage.joint(2).at.y);
    EXPECT_EQ(norm2(a.linkage.joint(2).axis), Rational(1)) << "configuration " << i;
  }
}

TEST(MechanismSampling, TrueClaimsHoldAndWrongOnesAreDisprovedWithAReplayableCounterexample) {
  for (const auto& [claims_file, scene_file] :
       std::vector<std::pair<std::string, std::string>>{
           {"verify/claims/mechanisms/fourbar.yaml", "verify/scenes/mechanisms/seed001_fourbar.yaml"},
           {"verify/claims/mechanisms/inverted_slider_crank.yaml", "verify/scenes/mechanisms/inverted_slider_crank.yaml"},
           {"verify/claims/mechanisms/slider_crank.yaml", "verify/scenes/mechanisms/dimensions_slider_crank.yaml"},
           {"verify/claims/mechanisms/sixbar_watt.yaml", "verify/scenes/mechanisms/pmks_watt_i_0.yaml"},
           {"verify/claims/mechanisms/sixbar_stephenson.yaml",
            "verify/scenes/mechanisms/pmks_stephenson_iii_example_2_0.yaml"}}) {
    const MechanismScene s = load_mechanism_scene(sampling_source(scene_file));
    const std::vector<MechanismDataClaim> claims = bound_claims(claims_file, s);
    TopologySampling o;
    o.count = 12;
    o.seed = 3;
    std::cout << claims_file << ": seed " << o.seed << ", count " << o.count << "\n";
    const TopologySampleRun run = sample_topology(s, claims, o);
    ASSERT_EQ(run.claims.size(), claims.size());
    for (size_t k = 0; k < claims.size(); ++k) {
      const SampleResult& r = run.claims[k];
      if (r.info.expected == Expectation::Holds) {
        EXPECT_EQ(r.verdict, TopologyVerdict::HoldsOnSamples) << r.info.id;
        EXPECT_EQ(r.compared, o.count) << r.info.id;
        continue;
      }
      ASSERT_EQ(r.verdict, TopologyVerdict::Disproved) << r.info.id;
      ASSERT_TRUE(r.counterexample.has_value());
      EXPECT_EQ(r.counterexample->outcome.verdict, Verdict::Fails) << r.info.id;
      // Replay: the scene as written, read back and solved by the symbolic route, still fails.
      const MechanismScene replay = parse_mechanism_scene(r.counterexample->scene_yaml, "replay.yaml");
      const MechanismSolution<Rational> truth = solve_mechanism_exact(replay);
      const ClaimOutcome o2 = run_mechanism_claim(to_mechanism_claim(claims[k]), MechanismContext{replay, truth});
      EXPECT_EQ(o2.verdict, Verdict::Fails) << r.info.id << "\n" << r.counterexample->scene_yaml;
    }
  }
}

TEST(MechanismSampling, ShrinkingMovesTowardSmallIntegers) {
  const MechanismScene s = load_mechanism_scene(sampling_source("verify/scenes/mechanisms/seed001_fourbar.yaml"));
  std::vector<MechanismDataClaim> claims = bound_claims("verify/claims/mechanisms/fourbar.yaml", s);
  std::erase_if(claims, [](const MechanismDataClaim& c) { return c.info.id != "fourbar.alpha3_at_this_configuration"; });
  ASSERT_EQ(claims.size(), 1u);
  TopologySampling o;
  o.count = 5;
  o.seed = 11;
  std::cout << "seed " << o.seed << "\n";
  const TopologySampleRun run = sample_topology(s, claims, o);
  ASSERT_TRUE(run.claims[0].counterexample.has_value());
  const MechanismScene& cx = run.claims[0].counterexample->scene;
  EXPECT_GT(run.claims[0].counterexample->shrink_steps, 0);
  // The driver's rates shrink to omega 1 or -1 (or stay small) and omega-dot to 0 or +-1.
  EXPECT_LE(cln::abs(cx.inputs[0].rate), Rational(9)) << run.claims[0].counterexample->scene_yaml;
  for (const LinkageJoint& j : cx.linkage.joints()) {
    EXPECT_EQ(cln::denominator(j.at.x), 1);
    EXPECT_LE(cln::abs(j.at.x), Rational(10));
  }
}

TEST(MechanismSampling, AClaimUndefinedEverywhereIsUndefinedNotAPass) {
  const MechanismScene s = load_mechanism_scene(sampling_source("verify/scenes/mechanisms/seed001_fourbar.yaml"));
  MechanismDataClaim c;
  c.info.id = "self_pole";
  c.lhs = MechanismExpression::parse("pole(\"3\", \"3\")");
  c.rhs = MechanismExpression::parse("pos(A)");
  bind_mechanism_claim(c, s);
  TopologySampling o;
  o.count = 4;
  const TopologySampleRun run = sample_topology(s, {c}, o);
  EXPECT_EQ(run.claims[0].verdict, TopologyVerdict::Undefined);
  EXPECT_EQ(run.claims[0].compared, 0);
  EXPECT_EQ(run.claims[0].undefined_quantity, "pole(\"3\", \"3\")");
}

}  // namespace
}  // namespace linkproof
