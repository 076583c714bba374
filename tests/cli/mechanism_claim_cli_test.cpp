// `check-claim CLAIMS --scene MECHANISM_SCENE` and `--topology MECHANISM_SCENE`: a user's
// claim files about a four-bar, an inverted slider-crank, a slider-crank and a Watt six-bar
// (verify/claims/mechanisms/), true claims and wrong variants, in text and JSON; the
// counterexample of every wrong variant re-fails when checked as a scene.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <iostream>
#include <string>

#include "support/cli_run.h"
#include "support/topology_claims.h"
#include "support/counterexample_replay.h"

namespace linkproof {
namespace {

using test::CliRun;
using test::run_cli;

struct Pair {
  std::string claims, scene;
};

const std::vector<Pair>& pairs() {
  static const std::vector<Pair> p = {
      {"verify/claims/mechanisms/fourbar.yaml", "verify/scenes/mechanisms/seed001_fourbar.yaml"},
      {"verify/claims/mechanisms/inverted_slider_crank.yaml", "verify/scenes/mechanisms/inverted_slider_crank.yaml"},
      {"verify/claims/mechanisms/slider_crank.yaml", "verify/scenes/mechanisms/dimensions_slider_crank.yaml"},
      {"verify/claims/mechanisms/sixbar_watt.yaml", "verify/scenes/mechanisms/pmks_watt_i_0.yaml"},
      {"verify/claims/mechanisms/sixbar_stephenson.yaml", "verify/scenes/mechanisms/pmks_stephenson_iii_example_2_0.yaml"}};
  return p;
}

TEST(MechanismClaimCli, TrueClaimsHoldOnTheirSceneAndWrongOnesFailUnlessTrueThere) {
  for (const Pair& p : pairs()) {
    const CliRun r = run_cli({"check-claim", test::source_path(p.claims), "--scene", test::source_path(p.scene), "--json"});
    EXPECT_EQ(r.code, 0) << p.claims << "\n" << r.out << r.err;
    const auto j = nlohmann::json::parse(r.out);
    for (const auto& c : j["claims"]) {
      const std::string id = c["id"];
      if (c["expected"] == "holds")
        EXPECT_EQ(c["verdict"], "holds") << id;
      else if (id != "fourbar.alpha3_at_this_configuration")
        EXPECT_EQ(c["verdict"], "fails") << id;
      else
        EXPECT_EQ(c["verdict"], "holds") << id << ": true at the scene's configuration only";
    }
    const CliRun text = run_cli({"check-claim", test::source_path(p.claims), "--scene", test::source_path(p.scene)});
    EXPECT_EQ(text.code, 0) << text.out << text.err;
  }
}

TEST(MechanismClaimCli, TopologyHoldsOnSamplesOrDisprovesWithAReplayableCounterexample) {
  for (const Pair& p : pairs()) {
    std::cout << p.claims << ": seed 5, count 10\n";
    const CliRun r = run_cli({"check-claim", test::source_path(p.claims), "--topology", test::source_path(p.scene), "--count", "10",
                              "--seed", "5", "--json"});
    ASSERT_EQ(r.code, 0) << p.claims << "\n" << r.out.substr(0, 4000) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["mode"], "topology");
    EXPECT_NE(j["rests_on"].get<std::string>().find("NOT a proof"), std::string::npos);
    EXPECT_GE(j["seconds"].get<double>(), 0.0);
    for (const auto& c : j["claims"]) {
      const std::string id = c["id"];
      EXPECT_NE(c["verdict"], "proved") << id;
      if (c["expected"] == "holds") {
        EXPECT_EQ(c["verdict"], "holds_on_samples") << id;
        EXPECT_EQ(c["compared"], 10) << id;
        EXPECT_NE(c["scope"].get<std::string>().find("not a proof"), std::string::npos) << id;
        continue;
      }
      ASSERT_EQ(c["verdict"], "disproved") << id;
      test::expect_counterexample_refails(test::source_path(p.claims), id, c["counterexample"]["scene_yaml"], "cx_");
    }
  }
}

TEST(MechanismClaimCli, TopologyTextSaysWhatTheVerdictRestsOn) {
  const Pair& p = pairs()[1];
  const CliRun r = run_cli({"check-claim", test::source_path(p.claims), "--topology", test::source_path(p.scene), "--count", "5"});
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("NOT a proof"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("holds_on_samples"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("disproved"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("counterexample scene"), std::string::npos) << r.out;
}

std::string claim_file(const std::string& name, const std::string& lhs, const std::string& rhs,
                       const std::string& expected = "holds") {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << "claims:\n  - id: mine\n    source: test\n    statement: s\n    expected: " << expected
                      << "\n    lhs: '" << lhs << "'\n    rhs: '" << rhs << "'\n";
  return path;
}

TEST(MechanismClaimCli, ATrueClaimThatFailsIsExitOneAndUndefinedIsNamed) {
  const std::string scene = test::source_path("verify/scenes/mechanisms/seed001_fourbar.yaml");
  const CliRun wrong = run_cli({"check-claim", claim_file("m1.yaml", "alpha(\"3\")", "1"), "--scene", scene, "--json"});
  EXPECT_EQ(wrong.code, 1) << wrong.out << wrong.err;
  const CliRun undef =
      run_cli({"check-claim", claim_file("m2.yaml", "pole(\"2\", \"2\")", "pos(A)"), "--scene", scene, "--json"});
  EXPECT_EQ(undef.code, 0) << undef.out << undef.err;
  const auto j = nlohmann::json::parse(undef.out);
  EXPECT_EQ(j["claims"][0]["verdict"], "undefined");
  EXPECT_NE(undef.out.find("pole(\\\"2\\\", \\\"2\\\")"), std::string::npos) << undef.out;
  const CliRun strict = run_cli({"check-claim", claim_file("m3.yaml", "pole(\"2\", \"2\")", "pos(A)"), "--scene", scene,
                                 "--strict"});
  EXPECT_EQ(strict.code, 1) << strict.out;
  // holds_on_samples is no proof: with --strict it is not as expected.
  const std::string true_claim = claim_file("m4.yaml", "omega(\"3\", \"1\")", "omega(\"3\")");
  EXPECT_EQ(run_cli({"check-claim", true_claim, "--topology", scene, "--count", "3"}).code, 0);
  const CliRun samples = run_cli({"check-claim", true_claim, "--topology", scene, "--count", "3", "--strict"});
  EXPECT_EQ(samples.code, 1) << samples.out << samples.err;
}

TEST(MechanismClaimCli, VocabularyListsTheMechanismWords) {
  const CliRun r = run_cli({"check-claim", "--vocabulary"});
  EXPECT_EQ(r.code, 0);
  for (const char* w : {"omega(L, M)", "alpha(L)", "pos(P)", "vel(P, L, M)", "acc(P, L, M)", "pole(L, M)",
                        "centre(P, L, M)", "centre_at(X, L, M)", "sliding_v(J)", "sliding_a(J)", "axis(J)",
                        "meet(A, B, C, D)", "norm2(a)", "vx(a)"})
    EXPECT_NE(r.out.find(w), std::string::npos) << w;
  EXPECT_NE(r.out.find("omega_dot_out"), std::string::npos) << "the polygon words are still listed";
}

// One table: a word of both languages is listed in each with one signature and meaning, and every
// polygon word as it is written (omega[j], r[k], sum_j(e)), not as a form the checker refuses.
TEST(MechanismClaimCli, VocabularyListsEachWordAsItIsWritten) {
  const CliRun r = run_cli({"check-claim", "--vocabulary"});
  EXPECT_EQ(r.code, 0);
  EXPECT_EQ(r.out.find("[.]"), std::string::npos) << r.out;
  for (const char* line : {"omega[j]                 omega[j] = omega_{j,n}", "r[k]                     r[k] = K_{k+1}",
                           "sum_pairs(e)             sum over ordered pairs", "norm2(a)                 a . a\n"}) {
    const std::size_t first = r.out.find(line);
    EXPECT_NE(first, std::string::npos) << line;
    if (std::string(line).starts_with("norm2")) {
      EXPECT_NE(r.out.find(line, first + 1), std::string::npos) << "norm2 is listed in both languages";
    }
  }
}

}  // namespace
}  // namespace linkproof
