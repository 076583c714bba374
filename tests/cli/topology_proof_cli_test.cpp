// `prove --file CLAIMS --topology SCENE` and `check-claim CLAIMS --topology SCENE` (no --count):
// a user's claims about a four-bar, an inverted slider-crank, a slider-crank and the notes'
// four-bar acceleration polygon are proved for every configuration of the topology, the wrong
// variants disproved with counterexample scenes that `check-claim --scene` re-fails; a proof out
// of its budget is a randomized identity test with its failure bound, not a proof (--strict).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <iostream>

#include "support/cli_run.h"
#include "support/topology_claims.h"
#include "support/counterexample_replay.h"

namespace linkproof {
namespace {

using test::CliRun;
using test::run_cli;

struct ClaimsAndScene {
  std::string claims, scene;
};

TEST(TopologyProofCli, TrueClaimsAreProvedAndWrongOnesDisprovedWithReplayableCounterexamples) {
  const std::vector<ClaimsAndScene> pairs = {
      {"verify/claims/mechanisms/fourbar.yaml", "verify/scenes/mechanisms/seed001_fourbar.yaml"},
      {"verify/claims/mechanisms/fourbar_acceleration_polygon.yaml", "verify/scenes/mechanisms/seed001_fourbar.yaml"},
      {"verify/claims/mechanisms/inverted_slider_crank.yaml", "verify/scenes/mechanisms/inverted_slider_crank.yaml"},
      {"verify/claims/mechanisms/slider_crank.yaml", "verify/scenes/mechanisms/dimensions_slider_crank.yaml"}};
  for (const ClaimsAndScene& p : pairs) {
    const CliRun r = run_cli({"prove", "--file", test::source_path(p.claims), "--topology", test::source_path(p.scene), "--json"});
    ASSERT_EQ(r.code, 0) << p.claims << "\n" << r.out.substr(0, 4000) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["mode"], "topology_proof");
    for (const auto& c : j["claims"]) {
      const std::string id = c["id"];
      std::cout << id << ": " << c["verdict"].get<std::string>() << " (" << c["seconds"].get<double>() << " s)\n";
      if (c["expected"] == "holds") {
        EXPECT_TRUE(c["verdict"] == "proved" || c["verdict"] == "proved_generically") << id << ": " << c.dump(2);
        continue;
      }
      ASSERT_EQ(c["verdict"], "disproved") << id;
      test::expect_counterexample_refails(test::source_path(p.claims), id, c["counterexample"]["scene_yaml"], "tp_");
    }
  }
}

// The papers' claims as data on the eight-link topologies (docs/claims.md, "The papers' mechanism
// claims as data"): every erratum disproved with a counterexample that re-fails, and the claims
// whose proof is quick proved. The true claims whose normal form does not finish in the budget
// are measured by the documented commands, not here (minutes each).
TEST(TopologyProofCli, ThePapersErrataOnTheEightLinkTopologiesAreDisprovedWithReplayableCounterexamples) {
  struct Case {
    std::string claims, scene;
    std::vector<std::string> ids;
  };
  const std::vector<Case> cases = {
      {"verify/claims/mechanisms/koshel_class3.yaml", "verify/scenes/mechanisms/seed003_class3.yaml",
       {"eq15.rescaled_epsilon2", "eq15.rescaled_epsilon3", "eq15.rescaled_epsilon5", "eq15.rescaled_epsilon6",
        "prismatic_pair.coriolis_dropped", "prismatic_pair.coriolis"}},
      {"verify/claims/mechanisms/dijksman1984_eightbar.yaml", "verify/scenes/mechanisms/dijksman1984_eightbar.yaml",
       {"section3.P60.printed", "eq5p.printed"}}};
  for (const Case& k : cases) {
    std::vector<std::string> args = {"prove", "--file", test::source_path(k.claims), "--topology", test::source_path(k.scene), "--json"};
    for (const std::string& id : k.ids) args.insert(args.end(), {"--claim", id});
    const CliRun r = run_cli(args);
    ASSERT_EQ(r.code, 0) << k.claims << "\n" << r.out.substr(0, 4000) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    ASSERT_EQ(j["claims"].size(), k.ids.size());
    for (const auto& c : j["claims"]) {
      const std::string id = c["id"];
      if (c["expected"] == "holds") {
        EXPECT_EQ(c["verdict"], "proved") << id;  // the prismatic pair: a rigid-body identity
        continue;
      }
      ASSERT_EQ(c["verdict"], "disproved") << id;
      test::expect_counterexample_refails(test::source_path(k.claims), id, c["counterexample"]["scene_yaml"], "papers_");
    }
  }
}

TEST(TopologyProofCli, AProofNamesItsExceptionalSetInTextAndJson) {
  const std::string claims = test::source_path("verify/claims/mechanisms/fourbar.yaml");
  const std::string scene = test::source_path("verify/scenes/mechanisms/seed001_fourbar.yaml");
  const CliRun r = run_cli({"prove", "--file", claims, "--topology", scene, "--claim", "coupler_pole", "--json"});
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["claims"].size(), 1u);
  const auto& c = j["claims"][0];
  EXPECT_EQ(c["verdict"], "proved_generically");
  std::string meanings;
  for (const auto& e : c["except"]) meanings += e["meaning"].get<std::string>() + "\n";
  EXPECT_NE(meanings.find("dead centre"), std::string::npos) << meanings;
  EXPECT_NE(meanings.find("parallel"), std::string::npos) << meanings;
  const CliRun text = run_cli({"prove", "--file", claims, "--topology", scene, "--claim", "coupler_pole"});
  EXPECT_EQ(text.code, 0);
  EXPECT_NE(text.out.find("except where:"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("x_O2, y_O2"), std::string::npos) << text.out;
}

TEST(TopologyProofCli, CheckClaimOnATopologyProvesUnlessACountIsGiven) {
  const std::string claims = test::source_path("verify/claims/mechanisms/fourbar.yaml");
  const std::string scene = test::source_path("verify/scenes/mechanisms/seed001_fourbar.yaml");
  const CliRun proof = run_cli({"check-claim", claims, "--topology", scene, "--json"});
  ASSERT_EQ(proof.code, 0) << proof.err;
  EXPECT_EQ(nlohmann::json::parse(proof.out)["mode"], "topology_proof");
  const CliRun samples = run_cli({"check-claim", claims, "--topology", scene, "--count", "5", "--json"});
  ASSERT_EQ(samples.code, 0) << samples.err;
  EXPECT_EQ(nlohmann::json::parse(samples.out)["mode"], "topology");
}

TEST(TopologyProofCli, WithoutTimeForAProofTheIdentityTestIsNotAProofUnderStrict) {
  const std::string claims = test::source_path("verify/claims/mechanisms/fourbar.yaml");
  const std::string scene = test::source_path("verify/scenes/mechanisms/seed001_fourbar.yaml");
  const std::vector<std::string> args = {"prove", "--file", claims, "--topology", scene, "--claim", "alpha3_closed_form",
                                         "--proof-seconds", "0", "--json"};
  const CliRun r = run_cli(args);
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  const auto c = nlohmann::json::parse(r.out)["claims"][0];
  EXPECT_EQ(c["verdict"], "holds_with_probability");
  EXPECT_LT(c["identity_test"]["failure_bound"].get<double>(), 1e-20);
  std::vector<std::string> strict = args;
  strict.push_back("--strict");
  EXPECT_EQ(run_cli(strict).code, 1);
}

TEST(TopologyProofCli, ProveOnATopologyRefusesMissingOrPolygonOptions) {
  const std::string scene = test::source_path("verify/scenes/mechanisms/seed001_fourbar.yaml");
  const CliRun no_file = run_cli({"prove", "--topology", scene});
  EXPECT_EQ(no_file.code, 2);
  EXPECT_NE(no_file.err.find("--topology"), std::string::npos) << no_file.err;
  const CliRun with_n =
      run_cli({"prove", "--file", test::source_path("verify/claims/mechanisms/fourbar.yaml"), "--topology", scene, "--n", "5"});
  EXPECT_EQ(with_n.code, 2);
  EXPECT_NE(with_n.err.find("--n"), std::string::npos) << with_n.err;
  const CliRun unknown = run_cli(
      {"prove", "--file", test::source_path("verify/claims/mechanisms/fourbar.yaml"), "--topology", scene, "--claim", "nope"});
  EXPECT_EQ(unknown.code, 2);
  EXPECT_NE(unknown.err.find("nope"), std::string::npos) << unknown.err;
}

}  // namespace
}  // namespace linkproof
