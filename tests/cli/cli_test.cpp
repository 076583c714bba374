// The command line, run in-process: exit codes, the JSON contract, bad input.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>

#include "support/cli_run.h"

namespace linkproof {
namespace {

using test::CliRun;
using test::run_cli;

std::string scene(const std::string& name) { return std::string(LINKPROOF_SOURCE_DIR) + "/verify/scenes/" + name; }

std::string write_temp(const std::string& name, const std::string& text) {
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

TEST(Cli, MissingSceneFileIsBadInputNamingTheFile) {
  const CliRun r = run_cli({"check", "/nonexistent/scene.yaml"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("/nonexistent/scene.yaml"), std::string::npos);
}

TEST(Cli, MalformedSceneIsBadInputNamingTheField) {
  const std::string path = write_temp("bad_scene.yaml",
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
