// Mechanism scenes: bad input is InputError naming the field (exit code 2 from the CLI), and the
// JSON contract of `check --json` on a mechanism scene.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <limits>
#include <sstream>

#include "support/cli_run.h"
#include "linkproof/io/mechanism_scene.h"
#include "mechanism/mechanism_catalogue.h"
#include "mechanism/mechanism_test_support.h"

namespace linkproof {
namespace {

const std::string kFourBar = R"(name: fb
mechanism:
  ground: "1"
  links: ["1", "2", "3", "4"]
  joints:
    - {name: O2, type: revolute, links: ["1", "2"], at: [0, 0]}
    - {name: A,  type: revolute, links: ["2", "3"], at: [3, 4]}
    - {name: B,  type: revolute, links: ["3", "4"], at: [11, 10]}
    - {name: O4, type: revolute, links: ["4", "1"], at: [11, 0]}
  inputs:
    - {link: "2", omega: 2, omega_dot: 5}
)";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

// Parses and solves; returns "field: problem" of the InputError, or "" if none.
std::string input_error(const std::string& text) {
  try {
    const MechanismScene s = parse_mechanism_scene(text, "test.yaml");
    solve_mechanism_exact(s);
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "test.yaml");
    return e.field() + ": " + e.problem();
  }
  return "";
}

TEST(MechanismScene, ValidFourBarParsesAndSolves) { EXPECT_EQ(input_error(kFourBar), ""); }

TEST(MechanismScene, BadInputIsRefusedNamingFieldAndProblem) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {replaced(kFourBar, "links: [\"2\", \"3\"]", "links: [\"2\", \"9\"]"), "mechanism.joints[1].links[1]: unknown link"},
      {replaced(kFourBar, "links: [\"2\", \"3\"]", "links: [\"2\"]"), "exactly two links"},
      {replaced(kFourBar, "links: [\"2\", \"3\"]", "links: [\"3\", \"3\"]"), "same link twice"},
      {replaced(kFourBar, "links: [\"1\", \"2\", \"3\", \"4\"]", "links: [\"1\", \"2\", \"3\", \"4\", \"5\"]"),
       "link `5` is not connected"},
      {replaced(kFourBar, "type: revolute, links: [\"3\", \"4\"], at: [11, 10]",
                "type: prismatic, links: [\"3\", \"4\"], at: [11, 10], axis: [0, 0]"),
       "mechanism.joints[2].axis: zero axis"},
      {replaced(kFourBar, "    - {link: \"2\", omega: 2, omega_dot: 5}\n", "    []\n"), "needs 1 input(s), got 0"},
      {replaced(kFourBar, "omega_dot: 5}", "omega_dot: 5}\n    - {link: \"3\", omega: 1, omega_dot: 0}"),
       "needs 1 input(s), got 2"},
      {replaced(kFourBar, "omega: 2,", "omega: .nan,"), "mechanism.inputs[0].omega: expected an exact number"},
      {replaced(kFourBar, "  inputs:", "  dimensions:\n    - {joints: [O2, A], length: 6}\n  inputs:"),
       "mechanism.dimensions[0]: the linkage does not close at the given positions"},
      {replaced(kFourBar, "  inputs:", "  catalogue: [nonsense]\n  inputs:"), ""},  // checked by the CLI
      {replaced(kFourBar, "type: revolute, links: [\"1\", \"2\"]", "type: hinge, links: [\"1\", \"2\"]"),
       "mechanism.joints[0].type: expected `revolute` or `prismatic`"},
      {replaced(kFourBar, "  ground: \"1\"", "  ground: \"1\"\n  colour: red"), "mechanism.colour: unknown field"},
      {"name: x\nmechanism: [1, 2\n", "malformed YAML"},
  };
  for (const auto& [text, expected] : cases) {
    const std::string e = input_error(text);
    if (expected.empty()) continue;
    EXPECT_NE(e.find(expected), std::string::npos) << "expected `" << expected << "` in `" << e << "`\n" << text;
  }
}

TEST(MechanismScene, LockedLinkageIsRefused) {
  // A four-bar plus a fifth bar between coupler and frame: a rigid structure (mobility 0).
  const std::string locked = replaced(kFourBar, "  inputs:",
                                      "    - {name: X, type: revolute, links: [\"3\", \"5\"], at: [9, 14]}\n"
                                      "    - {name: Y, type: revolute, links: [\"5\", \"1\"], at: [20, 14]}\n  inputs:");
  const std::string with_link = replaced(locked, "[\"1\", \"2\", \"3\", \"4\"]", "[\"1\", \"2\", \"3\", \"4\", \"5\"]");
  EXPECT_NE(input_error(with_link).find("locked: mobility 0"), std::string::npos) << input_error(with_link);
}

TEST(MechanismScene, ToleranceAdmitsApproximatelyClosedData) {
  const std::string text = replaced(kFourBar, "  inputs:",
                                    "  dimensions:\n    - {joints: [O2, A], length: 5.001}\n  tolerance: 0.01\n  inputs:");
  EXPECT_EQ(input_error(text), "");
  const std::string tight = replaced(text, "tolerance: 0.01", "tolerance: 0.0001");
  EXPECT_NE(input_error(tight).find("does not close"), std::string::npos);
}

using test::CliRun;
using test::run_cli;

TEST(MechanismCli, BadMechanismSceneExitsTwo) {
  const std::string path = ::testing::TempDir() + "bad_mechanism.yaml";
  std::ofstream(path) << replaced(kFourBar, "  inputs:", "  catalogue: [nonsense]\n  inputs:");
  const CliRun r = run_cli({"check", path});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("unknown catalogue"), std::string::npos) << r.err;
}

TEST(MechanismCli, EightBarJsonHonoursTheContract) {
  const CliRun r = run_cli({"check", testing::mechanism_scene_path("fig5_eightbar.yaml"), "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["scene"], "eightbar-fig5");
  EXPECT_EQ(j["arithmetic"], "exact");
  EXPECT_EQ(j["mobility"], 1);
  EXPECT_EQ(j["links"]["4"]["omega"], "159/317");
  EXPECT_EQ(j["links"]["4"]["omega_dot"], "171151479/318550130");
  EXPECT_EQ(j["links"]["0"]["omega"], "0");
  EXPECT_EQ(j["relative"]["1,2"]["omega_dot"], "8471254/159275065");
  EXPECT_EQ(j["joints"]["12"]["v"], nlohmann::json::array({"-4", "0"}));
  EXPECT_EQ(j["joints"]["12"]["a"], nlohmann::json::array({"-2", "-4"}));
  ASSERT_TRUE(j["claims"].is_array());
  for (const auto& c : j["claims"]) {
    EXPECT_TRUE(c.contains("id"));
    EXPECT_EQ(c["verdict"], "holds") << c["id"];
  }
}

TEST(MechanismCli, BundledScenesRunWithEveryClaimAsExpected) {
  for (const char* name : {"fig5_eightbar.yaml", "seed001_fourbar.yaml", "seed003_class3.yaml", "pmks_watt_i_0.yaml"}) {
    const CliRun r = run_cli({"check", testing::mechanism_scene_path(name), "--json"});
    EXPECT_EQ(r.code, 0) << name << r.err;
    const auto j = nlohmann::json::parse(r.out);
    for (const auto& c : j["claims"]) EXPECT_TRUE(c["as_expected"].get<bool>()) << name << " " << c["id"];
  }
}

TEST(MechanismCli, DoubleArithmeticReportsDecimalsAndCondition) {
  const CliRun r = run_cli({"check", testing::mechanism_scene_path("seed001_fourbar.yaml"), "--json", "--arith", "double"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["arithmetic"], "double");
  const double condition = j["condition"].get<double>();
  EXPECT_GT(condition, 1.0);
  // Forward error of the double solve: a few units of the condition times the unit roundoff.
  EXPECT_NEAR(std::stod(j["links"]["3"]["omega_dot"].get<std::string>()), 63.0 / 160,
              16 * condition * std::numeric_limits<double>::epsilon());
}

}  // namespace
}  // namespace linkproof

namespace linkproof {
namespace {

TEST(MechanismCli, FourBarAtDeadCentreIsRefusedAsBadInputNotAnInternalError) {
  // B on the line O4-A extended... coupler A-B parallel to rocker O4-B: A = (11, 5), B = (11, 10).
  std::string text = kFourBar;
  text = replaced(text, "at: [3, 4]", "at: [11, 5]");
  text = replaced(text, "  inputs:", "  catalogue: [fourbar_polygon]\n  inputs:");
  const std::string path = ::testing::TempDir() + "dead_centre_fourbar.yaml";
  std::ofstream(path) << text;
  const CliRun r = run_cli({"check", path});
  EXPECT_EQ(r.code, 2) << r.err;  // the crank input does not fix the motion there
  EXPECT_NE(r.err.find("do not fix the motion"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace linkproof
