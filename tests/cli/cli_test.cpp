// The command line, run in-process: exit codes, the JSON contract, bad input.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/stat.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <thread>

#include "support/cli_run.h"

namespace linkproof {
namespace {

using test::CliRun;
using test::run_cli;

std::string scene(const std::string& name) { return std::string(LINKPROOF_SOURCE_DIR) + "/verify/scenes/" + name; }

std::string cli_write_temp(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

TEST(Cli, CheckPentagonPrintsTableAndExitsZero) {
  const CliRun r = run_cli({"check", scene("pentagon.yaml")});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("dijksman1966.eq22"), std::string::npos);
  EXPECT_NE(r.out.find("3755/1331"), std::string::npos);
}

// A pipe can be read only once: `check` must read the scene file once (it used to read it twice,
// once to choose the reader and once to parse, and a pipe gave an empty second read).
TEST(Cli, CheckReadsASceneFromAPipe) {
  const std::string fifo = ::testing::TempDir() + "linkproof_scene_fifo";
  std::remove(fifo.c_str());
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  std::ifstream in(scene("pentagon.yaml"));
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  std::thread writer([&] { std::ofstream(fifo) << text; });
  const CliRun r = run_cli({"check", fifo, "--json"});
  writer.join();
  std::remove(fifo.c_str());
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("3755/1331"), std::string::npos) << r.out;
}

TEST(Cli, CheckJsonHonoursTheContract) {
  const CliRun r = run_cli({"check", scene("pentagon.yaml"), "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["scene"], "pentagon");
  EXPECT_EQ(j["arithmetic"], "exact");
  EXPECT_EQ(j["polygon"]["n"], 5);
  EXPECT_EQ(j["polygon"]["omega"]["3"], "17/11");
  EXPECT_EQ(j["polygon"]["omega"]["5"], "0");
  EXPECT_EQ(j["polygon"]["omega_dot"]["3"], "7331/2662");
  EXPECT_EQ(j["polygon"]["omega_dot"]["4"], "3755/1331");
  bool found = false;
  for (const auto& c : j["claims"]) {
    ASSERT_TRUE(c.contains("id") && c.contains("verdict"));
    if (c["id"] == "dijksman1966.eq22") {
      found = true;
      EXPECT_EQ(c["verdict"], "holds");
      EXPECT_EQ(c["residual"], "0");
      EXPECT_EQ(c["lhs"], "3755/1331");
      EXPECT_EQ(c["rhs"], "3755/1331");
      ASSERT_EQ(c["terms"].size(), 5u);
      for (const auto& t : c["terms"]) EXPECT_EQ(t["verdict"], "holds") << t.dump();
    }
  }
  EXPECT_TRUE(found);
}

// Issue 27: beside every exact value of check --json, its decimal under "<key>_decimal"
// (additive: the exact strings are unchanged).
TEST(Cli, CheckJsonAddsTheDecimalBesideEachExactValue) {
  const CliRun r = run_cli({"check", scene("pentagon.yaml"), "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["polygon"]["omega_decimal"]["3"], "1.545454545");
  EXPECT_EQ(j["polygon"]["omega_dot_decimal"]["4"], "2.821187077");
  EXPECT_EQ(j["polygon"]["omega_dot_decimal"]["5"], "0");
  EXPECT_EQ(j["polygon"]["D_decimal"], "-22");
  for (const auto& c : j["claims"]) {
    if (c["id"] != "dijksman1966.eq22") continue;
    EXPECT_EQ(c["lhs"], "3755/1331");
    EXPECT_EQ(c["lhs_decimal"], "2.821187077");
    EXPECT_EQ(c["rhs_decimal"], "2.821187077");
    EXPECT_EQ(c["residual_decimal"], "0");
    EXPECT_EQ(c["terms"][0]["lhs_decimal"].is_string(), true) << c["terms"][0].dump();
    EXPECT_EQ(c["instances"][0]["rhs_decimal"].is_string(), true) << c["instances"][0].dump();
  }
}

TEST(Cli, CheckInDoubleStatesItsToleranceRule) {
  const CliRun r = run_cli({"check", scene("pentagon.yaml"), "--arith", "double", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["arithmetic"], "double");
  EXPECT_NE(j["tolerance_rule"].get<std::string>().find("tolerance"), std::string::npos);
  for (const auto& c : j["claims"])
    if (c["expected"] == "holds") {
      EXPECT_EQ(c["verdict"], "holds") << c["id"];
      EXPECT_TRUE(c.contains("tolerance")) << c["id"];
    }
}

TEST(Cli, UnknownArithmeticIsBadInput) {
  const CliRun r = run_cli({"check", scene("pentagon.yaml"), "--arith", "float"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--arith"), std::string::npos);
}

TEST(Cli, EveryMultiprecisionArithmeticIsAcceptedAndNamedInTheJson) {
  for (const std::string arith : {"mp30", "mp50", "mp100", "mp1000"}) {
    const CliRun r = run_cli({"check", scene("pentagon.yaml"), "--arith", arith, "--json"});
    ASSERT_EQ(r.code, 0) << arith << ": " << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["arithmetic"], arith);
    EXPECT_EQ(j["summary"]["holds"], 18) << arith;  // as exact: 17 true claims + eq4.unsigned_ratio
    EXPECT_EQ(j["summary"]["fails"], 12) << arith;
    for (const auto& c : j["claims"]) {
      ASSERT_TRUE(c.contains("tolerance") && c.contains("relative_error_bound") && c.contains("tolerance_derivation"))
          << arith << " " << c["id"];
    }
  }
  const auto j = nlohmann::json::parse(run_cli({"check", scene("pentagon.yaml"), "--arith", "mp100", "--json"}).out);
  EXPECT_NE(j["tolerance_rule"].get<std::string>().find("u = 2^-384"), std::string::npos);
  EXPECT_NE(j["claims"][0]["tolerance_derivation"].get<std::string>().find("u = 2^-384"), std::string::npos);
  EXPECT_EQ(j["polygon"]["omega_dot"]["4"].get<std::string>().substr(0, 20), "2.821187077385424492");
}

TEST(Cli, SweepAndCheckClaimTakeTheMultiprecisionArithmetics) {
  const CliRun sweep = run_cli({"sweep", "--n", "5..6", "--count", "2", "--seed", "3", "--arith", "mp50", "--json"});
  ASSERT_EQ(sweep.code, 0) << sweep.err;
  EXPECT_EQ(nlohmann::json::parse(sweep.out)["arithmetic"], "mp50");
  const std::string catalogue = std::string(LINKPROOF_SOURCE_DIR) + "/verify/claims/dijksman1966.yaml";
  const CliRun on_scene =
      run_cli({"check-claim", catalogue, "--scene", scene("pentagon.yaml"), "--arith", "mp1000", "--json"});
  ASSERT_EQ(on_scene.code, 0) << on_scene.err;
  const auto j = nlohmann::json::parse(on_scene.out);
  EXPECT_EQ(j["arithmetic"], "mp1000");
  EXPECT_EQ(j["summary"]["unexpected_failures"], 0);
  // Without --scene: the proof is symbolic whatever the arithmetic.
  const std::string mine = cli_write_temp("mine_eq5.yaml", R"yaml(claims:
  - id: mine.eq5
    source: "test"
    statement: "eq. (5)"
    n: "4"
    lhs: omega_out
    rhs: sum_j(i_out[j]*omega[j])
)yaml");
  const CliRun proved = run_cli({"check-claim", mine, "--n", "4", "--arith", "mp1000", "--json"});
  ASSERT_EQ(proved.code, 0) << proved.err << proved.out;
  EXPECT_EQ(nlohmann::json::parse(proved.out)["claims"][0]["verdict"], "proved_generically");
}

TEST(Cli, UnknownArithmeticIsRejectedByEveryCommandNamingTheOptionAndTheChoices) {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"check", scene("pentagon.yaml"), "--arith", "mp31"},
        std::vector<std::string>{"sweep", "--n", "5", "--count", "1", "--arith", "MP30"},
        std::vector<std::string>{"check-claim", std::string(LINKPROOF_SOURCE_DIR) + "/verify/claims/dijksman1966.yaml",
                                 "--scene", scene("pentagon.yaml"), "--arith", "mp"}}) {
    const CliRun r = run_cli(args);
    EXPECT_EQ(r.code, 2) << args[0];
    EXPECT_NE(r.err.find("--arith"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("mp1000"), std::string::npos) << r.err;
  }
}

TEST(Cli, CheckHelpListsTheArithmetics) {
  const CliRun r = run_cli({"check", "--help"});
  EXPECT_EQ(r.code, 0);
  const std::string text = r.out + r.err;
  for (const char* name : {"long-double", "mp30", "mp50", "mp100", "mp1000"}) EXPECT_NE(text.find(name), std::string::npos) << name;
}

TEST(Cli, MissingSceneFileIsBadInputNamingTheFile) {
  const CliRun r = run_cli({"check", "/nonexistent/scene.yaml"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("/nonexistent/scene.yaml"), std::string::npos);
}

TEST(Cli, MalformedSceneIsBadInputNamingTheField) {
  const std::string path = cli_write_temp("bad_scene.yaml",
                                      "name: bad\npolygon:\n  joints: [[0,0],[1,0],[1,1],[0,1]]\n  omega: [1, 2]\n  omega_dot: [0]\n");
  const CliRun r = run_cli({"check", path});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("polygon.omega"), std::string::npos) << r.err;
}

TEST(Cli, DeadCentreSceneReportsUndefinedNotAVerdict) {
  const CliRun r = run_cli({"check", scene("pentagon_dead_centre.yaml"), "--json"});
  EXPECT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["polygon"]["dead_centre"].get<bool>());
  EXPECT_TRUE(j["polygon"]["omega"]["3"].is_null());
  for (const auto& c : j["claims"]) EXPECT_EQ(c["verdict"], "undefined") << c["id"];
}

// --strict was read and then ignored on mechanism scenes: a true claim left undefined (the
// curvature centre of a coupler point at the coupler's pole, where v x a = 0) exited 0.
TEST(Cli, CheckStrictOnAMechanismSceneCountsAnUndefinedTrueClaim) {
  std::ifstream in(scene("mechanisms/seed001_fourbar.yaml"));
  std::stringstream text;
  text << in.rdbuf();
  std::string yaml = text.str();
  const std::string point = "at: [9, 14]";  // P, moved to the pole (11, 44/3) of the coupler
  ASSERT_NE(yaml.find(point), std::string::npos);
  yaml.replace(yaml.find(point), point.size(), "at: [11, 44/3]");
  const std::string path = cli_write_temp("strict_pole.yaml", yaml);
  const CliRun plain = run_cli({"check", path});
  EXPECT_EQ(plain.code, 0) << plain.out;
  EXPECT_NE(plain.out.find("undefined"), std::string::npos);
  const CliRun strict = run_cli({"check", path, "--strict"});
  EXPECT_EQ(strict.code, 1) << strict.out;
  EXPECT_NE(strict.out.find("NOT AS EXPECTED (strict)"), std::string::npos) << strict.out;
  const CliRun json = run_cli({"check", path, "--strict", "--json"});
  EXPECT_EQ(json.code, 1);
  const auto j = nlohmann::json::parse(json.out);
  EXPECT_EQ(j["summary"]["not_as_expected"], 1);
  EXPECT_EQ(j["summary"]["strict"], true);
  EXPECT_EQ(j["exit_status"], 1);
}

// The version was written into the CLI twice by hand; it is the project's (CMakeLists.txt).
TEST(Cli, VersionIsTheProjectVersionOfCMakeLists) {
  std::ifstream in(std::string(LINKPROOF_SOURCE_DIR) + "/CMakeLists.txt");
  std::stringstream text;
  text << in.rdbuf();
  const std::string key = "project(linkproof VERSION ";
  const auto at = text.str().find(key);
  ASSERT_NE(at, std::string::npos);
  const std::string version = text.str().substr(at + key.size(), text.str().find(' ', at + key.size()) - at - key.size());
  const CliRun r = run_cli({"--version"});
  EXPECT_EQ(r.code, 0);
  EXPECT_EQ(r.out, "linkproof " + version + "\n");
}

TEST(Cli, SweepRunsAndReplaysACaseBySeedAndIndex) {
  const CliRun all = run_cli({"sweep", "--n", "5..6", "--count", "4", "--seed", "3", "--json"});
  ASSERT_EQ(all.code, 0) << all.err;
  const auto j = nlohmann::json::parse(all.out);
  EXPECT_EQ(j["cases"], 8);
  const CliRun one = run_cli({"sweep", "--n", "6", "--count", "4", "--seed", "3", "--index", "2", "--json"});
  ASSERT_EQ(one.code, 0);
  EXPECT_EQ(nlohmann::json::parse(one.out)["cases"], 1);
}

TEST(Cli, SweepRejectsABadRange) {
  EXPECT_EQ(run_cli({"sweep", "--n", "3..5"}).code, 2);
  EXPECT_EQ(run_cli({"sweep", "--n", "9..5"}).code, 2);
  EXPECT_EQ(run_cli({"sweep", "--n", "x"}).code, 2);
  EXPECT_EQ(run_cli({"sweep", "--count", "0"}).code, 2);
}

TEST(Cli, NoSubcommandIsBadInputAndHelpIsNot) {
  EXPECT_EQ(run_cli({}).code, 2);
  EXPECT_EQ(run_cli({"--help"}).code, 0);
}

}  // namespace
}  // namespace linkproof

namespace linkproof {
namespace {

// The JSON example in docs/check.md is the program's own output for the pentagon, at least in
// its summary (issue 11: the documented counts had drifted from the program's).
TEST(Cli, DocumentedPentagonSummaryIsTheProgramsSummary) {
  std::ifstream in(std::string(LINKPROOF_SOURCE_DIR) + "/docs/check.md");
  const std::string doc{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const size_t at = doc.find("\"summary\": {");
  ASSERT_NE(at, std::string::npos);
  const size_t open = doc.find('{', at), close = doc.find('}', open);
  const auto documented = nlohmann::json::parse(doc.substr(open, close - open + 1));
  const CliRun r = test::run_cli({"check", std::string(LINKPROOF_SOURCE_DIR) + "/verify/scenes/pentagon.yaml", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["summary"], documented);
}

}  // namespace
}  // namespace linkproof
