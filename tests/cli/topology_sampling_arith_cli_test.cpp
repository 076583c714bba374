// `check-claim CLAIMS --topology SCENE --count K --arith A`: random configurations of a topology
// judged in floating point with derived error bounds (issue 26), and what a sampled verdict may
// count as a pass.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <string>

#include "support/cli_run.h"
#include "support/counterexample_replay.h"

namespace linkproof {
namespace {

using test::CliRun;
using test::run_cli;

std::string sampling_arith_source(const std::string& rel) { return std::string(LINKPROOF_SOURCE_DIR) + "/" + rel; }

const std::string kFourbarClaims = sampling_arith_source("verify/claims/mechanisms/fourbar.yaml");
const std::string kFourbar = sampling_arith_source("verify/scenes/mechanisms/seed001_fourbar.yaml");

nlohmann::json sample_json(const std::string& claims, const std::string& scene, const std::string& arith, int count,
                           int expected_code = 0) {
  const CliRun r = run_cli({"check-claim", claims, "--topology", scene, "--count", std::to_string(count), "--arith",
                            arith, "--json"});
  EXPECT_EQ(r.code, expected_code) << r.out << r.err;
  return nlohmann::json::parse(r.out);
}

TEST(TopologySamplingArith, EveryFloatingArithmeticHoldsTheTrueClaimsAndDisprovesTheWrongOnesExactly) {
  for (const std::string arith : {"double", "long-double", "mp30"}) {
    const nlohmann::json j = sample_json(kFourbarClaims, kFourbar, arith, 30);
    EXPECT_EQ(j["mode"], "topology");
    EXPECT_EQ(j["arithmetic"], arith);
    EXPECT_NE(std::string(j["rests_on"]).find("derived error bounds"), std::string::npos);
    for (const auto& c : j["claims"]) {
      const std::string id = c["id"];
      EXPECT_TRUE(c["as_expected"].get<bool>()) << arith << " " << id;
      if (c["expected"] == "holds") {
        EXPECT_EQ(c["verdict"], "holds_on_samples") << arith << " " << id;
        EXPECT_EQ(c["compared"], 30) << arith << " " << id;
        EXPECT_TRUE(c.contains("inconclusive_configurations"));
      } else {
        ASSERT_EQ(c["verdict"], "disproved") << arith << " " << id;
        // The counterexample is exact: it re-fails when checked as a scene.
        test::expect_counterexample_refails(kFourbarClaims, id, c["counterexample"]["scene_yaml"], "arith-" + arith);
      }
    }
  }
}

TEST(TopologySamplingArith, TheSameSeedFindsTheSameCounterexampleInDoubleAsExactly) {
  const nlohmann::json exact = sample_json(kFourbarClaims, kFourbar, "exact", 20);
  const nlohmann::json dbl = sample_json(kFourbarClaims, kFourbar, "double", 20);
  ASSERT_EQ(exact["claims"].size(), dbl["claims"].size());
  for (size_t k = 0; k < exact["claims"].size(); ++k) {
    if (exact["claims"][k]["verdict"] != "disproved") continue;
    EXPECT_EQ(exact["claims"][k]["counterexample"]["scene_yaml"], dbl["claims"][k]["counterexample"]["scene_yaml"])
        << exact["claims"][k]["id"];
  }
}

// A closed velocity polygon (a sum of terms = the zero vector): its sides are exactly 0, so the
// bound is judged against the terms' magnitude, not against 0 (where no bound could confirm it).
TEST(TopologySamplingArith, AClaimWhoseSidesAreZeroHoldsToTheAccuracyOfItsTerms) {
  const nlohmann::json j = sample_json(sampling_arith_source("verify/claims/mechanisms/fourbar_acceleration_polygon.yaml"), kFourbar,
                                       "double", 20);
  for (const auto& c : j["claims"])
    if (c["id"] == "seed001.velocity_polygon") {
      EXPECT_EQ(c["verdict"], "holds_on_samples") << c.dump(1);
      EXPECT_EQ(c["compared"], 20);
      return;
    }
  ADD_FAILURE() << "seed001.velocity_polygon not found";
}

TEST(TopologySamplingArith, TextNamesTheArithmeticAndWhatHoldsRestsOn) {
  const CliRun r = run_cli({"check-claim", kFourbarClaims, "--topology", kFourbar, "--count", "10", "--arith", "double"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("arithmetic double"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("equal within the derived error bound in double on 10 random configurations"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("a failure confirmed exactly"), std::string::npos) << r.out;
}

TEST(TopologySamplingArith, AnArithmeticIsRefusedWhereTheEvaluationIsExact) {
  for (const std::vector<std::string>& where :
       {std::vector<std::string>{"--scene", kFourbar}, std::vector<std::string>{"--topology", kFourbar}}) {
    std::vector<std::string> args{"check-claim", kFourbarClaims};
    args.insert(args.end(), where.begin(), where.end());
    args.insert(args.end(), {"--arith", "double"});
    const CliRun r = run_cli(args);
    EXPECT_EQ(r.code, 2) << where[0] << "\n" << r.out << r.err;
    EXPECT_NE(r.err.find("--arith"), std::string::npos) << r.err;
  }
  const CliRun bad = run_cli({"check-claim", kFourbarClaims, "--topology", kFourbar, "--count", "5", "--arith", "quad"});
  EXPECT_EQ(bad.code, 2) << bad.err;
}

// A true claim that is undefined on every configuration drawn was counted as a pass (exit 0):
// nothing was compared, so nothing supports "holds".
TEST(TopologySamplingArith, ATrueClaimUndefinedOnEverySampleIsNotAPass) {
  const std::string path = ::testing::TempDir() + "undefined_everywhere.yaml";
  std::ofstream(path) << R"yaml(claims:
  - id: pole_of_a_link_with_itself
    source: test
    statement: the pole of the coupler relative to itself
    lhs: pole("3", "3")
    rhs: pos(A)
)yaml";
  // Exactly, omega_3 - omega_3 is 0: undefined. In double it is 0 with a radius (the bound cannot
  // tell it from a small number), so the division's bound is unbounded: inconclusive; except
  // where omega_3 was computed exactly (radius 0): then omega_3 - omega_3 is an exact 0 in
  // double too, undefined (two of this seed's configurations), and the claim is undefined.
  for (const auto& [arith, verdict] : {std::pair{"exact", "undefined"}, std::pair{"double", "undefined"}}) {
    const nlohmann::json j = sample_json(path, kFourbar, arith, 5, 1);
    EXPECT_EQ(j["claims"][0]["verdict"], verdict) << arith;
    EXPECT_FALSE(j["claims"][0]["as_expected"].get<bool>()) << arith;
  }
}

}  // namespace
}  // namespace linkproof
