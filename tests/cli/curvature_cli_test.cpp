// `linkproof curvature SCENE --json` and `check` on scenes that ask for the second-order work:
// known answers of the bundled scenes, every claim as expected, bad input named.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>

#include "support/cli_run.h"

namespace linkproof {
namespace {

using nlohmann::json;
using test::run_cli;

std::string curvature_scene(const std::string& name) {
  return std::string(LINKPROOF_SOURCE_DIR) + "/verify/scenes/mechanisms/" + name;
}

json run_json(const std::vector<std::string>& args, int expected_code = 0) {
  const auto r = run_cli(args);
  EXPECT_EQ(r.code, expected_code) << r.err << r.out.substr(0, 2000);
  return json::parse(r.out);
}

const json& claim(const json& j, const std::string& id) {
  for (const auto& c : j["claims"])
    if (c["id"] == id) return c;
  static const json none;
  ADD_FAILURE() << "no claim " << id;
  return none;
}

// Issue 27: decimals beside the exact values, in the JSON (additive) and the text.
TEST(CurvatureCli, PolesAndCentresHaveTheirDecimalsBesideTheExactValues) {
  const json j = run_json({"curvature", curvature_scene("seed001_fourbar_curvature.yaml"), "--json"});
  const json& c = j["curvature_centres"][0];
  EXPECT_EQ(c["at"], json::array({"10923/1222", "17083/1222"}));
  EXPECT_EQ(c["at_decimal"], json::array({"8.938625205", "13.97954173"}));
  EXPECT_EQ(c["radius"], "sqrt(3125/746642)");
  EXPECT_EQ(c["radius_decimal"], "0.06469471482");
  for (const auto& p : j["poles"]) {
    if (p["links"] == json::array({"1", "3"})) {
      EXPECT_EQ(p["at_decimal"], json::array({"11", "14.66666667"}));
    }
  }
  const auto r = run_cli({"curvature", curvature_scene("seed001_fourbar_curvature.yaml")});
  EXPECT_NE(r.out.find("P_1,3      (11, 44/3 ≈ 14.66666667)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("radius sqrt(3125/746642) ≈ 0.06469471482"), std::string::npos) << r.out;
}

TEST(CurvatureCli, Seed001CouplerPointCentreByTheAnalyticRouteAndByBobillier) {
  const json j = run_json({"curvature", curvature_scene("seed001_fourbar_curvature.yaml"), "--json"});
  const json& c = j["curvature_centres"][0];
  EXPECT_EQ(c["point"], "P");
  EXPECT_EQ(c["at"], json::array({"10923/1222", "17083/1222"}));
  EXPECT_EQ(c["bobillier"]["gamma"], json::array({"10923/1222", "17083/1222"}));
  EXPECT_EQ(c["bobillier"]["version"], "A");
  EXPECT_EQ(j["curvature_centres"][1]["bobillier"]["version"], "B");
  EXPECT_EQ(j["curvature_centres"][1]["at"], json::array({"0", "0"}));
  EXPECT_EQ(claim(j, "curvature.bobillier")["verdict"], "holds");
  EXPECT_EQ(claim(j, "curvature.bobillier.mirrored_step_c")["verdict"], "fails");
  EXPECT_EQ(j["poles"].size(), 6u);
  EXPECT_EQ(j["summary"]["unexpected_failures"], 0);
  EXPECT_EQ(j["exit_status"], 0);
}

TEST(CurvatureCli, EightBarGivesEveryClaimItsExpectedVerdict) {
  const json j = run_json({"curvature", curvature_scene("dijksman1984_eightbar.yaml"), "--json"});
  EXPECT_EQ(j["poles"].size(), 28u);
  for (const auto& c : j["claims"]) {
    EXPECT_EQ(c["verdict"], c["expected"]) << c["id"];
  }
  for (const char* id : {"dijksman1984.section3.poles", "dijksman1984.eq1p", "dijksman1984.eq3p", "dijksman1984.eq5p",
                         "dijksman1984.eq7p", "dijksman1984.eq1pp", "dijksman1984.eq7pp",
                         "joint_joining.second_order.accelerations_preserved", "curvature.aronhold_kennedy"})
    EXPECT_EQ(claim(j, id)["verdict"], "holds") << id;
  EXPECT_EQ(claim(j, "dijksman1984.eq5p.printed")["verdict"], "fails");
  EXPECT_EQ(claim(j, "dijksman1984.section3.P60.printed")["verdict"], "fails");
  ASSERT_EQ(j["reductions"].size(), 2u);
  for (const auto& r : j["reductions"]) {
    EXPECT_TRUE(r["velocities_preserved"].get<bool>());
    EXPECT_TRUE(r["accelerations_preserved"].get<bool>());
    EXPECT_EQ(r["order"], 2);
  }
  EXPECT_EQ(j["exit_status"], 0);
}

TEST(CurvatureCli, FirstOrderEightBarKeepsVelocitiesNotAccelerations) {
  const json j = run_json({"curvature", curvature_scene("dijksman1984_eightbar_first_order.yaml"), "--json"});
  ASSERT_EQ(j["reductions"].size(), 4u);
  EXPECT_TRUE(j["reductions"][0]["velocities_preserved"].get<bool>());
  EXPECT_FALSE(j["reductions"][0]["accelerations_preserved"].get<bool>());
  EXPECT_EQ(claim(j, "joint_joining.first_order.velocities_preserved")["verdict"], "holds");
  EXPECT_EQ(claim(j, "joint_joining.first_order.accelerations_preserved")["verdict"], "fails");
  EXPECT_EQ(j["exit_status"], 0);
}

TEST(CurvatureCli, CheckRunsTheSameWorkWhenTheSceneAsks) {
  const json j = run_json({"check", curvature_scene("dijksman1984_eightbar.yaml"), "--json"});
  EXPECT_TRUE(j.contains("links"));  // the mechanism check's keys stay
  const json c = run_json({"curvature", curvature_scene("dijksman1984_eightbar.yaml"), "--json"});
  EXPECT_EQ(j["poles"], c["poles"]);
  EXPECT_EQ(j["curvature_centres"], c["curvature_centres"]);
  EXPECT_EQ(j["reductions"], c["reductions"]);
  EXPECT_EQ(claim(j, "dijksman1984.eq5p.printed")["verdict"], "fails");
  EXPECT_EQ(j["exit_status"], 0);
}

// The bundled seed-001 four-bar with `extra` appended (top-level keys).
std::string write_scene(const std::string& name, const std::string& extra) {
  std::ifstream in(curvature_scene("seed001_fourbar.yaml"));
  std::stringstream text;
  text << in.rdbuf();
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text.str() << extra;
  return path;
}

TEST(CurvatureCli, BadRequestsNameFileFieldAndProblem) {
  const struct {
    const char* extra;
    const char* field;
    const char* problem;
  } cases[] = {
      {"curvature:\n  - {point: Z, moving: \"3\", fixed: \"1\"}\n", "curvature[0].point", "unknown point"},
      {"curvature:\n  - {point: A, moving: \"3\", fixed: \"3\"}\n", "curvature[0].fixed", "same link"},
      {"curvature:\n  - {point: A, moving: \"9\", fixed: \"1\"}\n", "curvature[0].moving", "unknown link"},
      {"joint_joining:\n  - {link: \"3\", bars: [\"2\", \"4\"], order: 3}\n", "joint_joining[0].order", "expected 1"},
      {"joint_joining:\n  - {link: \"3\", bars: [\"4\", \"1\"]}\n", "joint_joining[0].bars[1]", "exactly one joint"},
      {"joint_joining:\n  - {link: \"3\", bars: [\"2\"]}\n", "joint_joining[0].bars", "2 bar"},
      // The ground has two joints like a bar, but does not move (it was accepted, and the
      // reduction's true claims then failed).
      {"joint_joining:\n  - {link: \"4\", bars: [\"3\", \"1\"]}\n", "joint_joining[0].bars[1]", "is the ground"},
      {"curvature: 5\n", "curvature", "expected a list"},
  };
  int k = 0;
  for (const auto& c : cases) {
    const std::string path = write_scene("curv_bad_" + std::to_string(k++) + ".yaml", c.extra);
    const auto r = run_cli({"curvature", path});
    EXPECT_EQ(r.code, 2) << c.extra << r.out;
    EXPECT_NE(r.err.find(path), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(c.field), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(c.problem), std::string::npos) << r.err;
  }
}

TEST(CurvatureCli, DrivingABarThatJoiningReplacesIsBadInput) {
  const std::string path = write_scene("curv_bad_driver.yaml", "joint_joining:\n  - {link: \"3\", bars: [\"2\", \"4\"]}\n");
  const auto r = run_cli({"curvature", path});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("is the driver"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace linkproof
