// linkproof check-data: exit codes 0 (agrees), 1 (differs), 2 (bad CSV, naming line and column),
// and the JSON contract's keys.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/cli_run.h"

namespace linkproof {
namespace {

using test::run_cli;

std::string path(const std::string& rel) { return std::string(LINKPROOF_SOURCE_DIR) + "/" + rel; }
const std::string kScene = path("verify/scenes/mechanisms/pmks_stephenson_iii_example_2_0.yaml");

TEST(CheckDataCli, MatlabDataAgreesAndOldPmksDataDiffers) {
  const auto ok = run_cli({"check-data", kScene, path("verify/data/pmks_stephenson_iii_example_2_matlab.csv")});
  EXPECT_EQ(ok.code, 0) << ok.out << ok.err;
  EXPECT_NE(ok.out.find("agree"), std::string::npos);
  const auto bad = run_cli({"check-data", kScene, path("verify/data/pmks_stephenson_iii_example_2_pmks.csv"), "--json"});
  EXPECT_EQ(bad.code, 1) << bad.err;
  const auto j = nlohmann::json::parse(bad.out);
  for (const char* key : {"scene", "data", "links", "tolerance_rule", "samples", "summary", "exit_status"})
    EXPECT_TRUE(j.contains(key)) << key;
  const auto& s = j["samples"][0];
  for (const char* key : {"line", "sample", "verdict", "consistent", "closure", "exact", "checks"})
    EXPECT_TRUE(s.contains(key)) << key;
  EXPECT_EQ(s["sample"], "matlab_0141");
  EXPECT_EQ(s["verdict"], "differs");
  EXPECT_EQ(s["exact"]["EF"]["alpha_decimal"], "-413.3350918640589130382471");
  EXPECT_GT(j["summary"]["differing"].get<int>(), 0);
  EXPECT_EQ(j["exit_status"], 1);
}

TEST(CheckDataCli, BadCsvIsExitCode2NamingLineAndColumn) {
  const auto r = run_cli({"check-data", kScene, path("verify/scenes/mechanisms/fig5_eightbar.yaml")});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("line"), std::string::npos) << r.err;
  const auto missing = run_cli({"check-data", kScene, "/nonexistent.csv"});
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.err.find("/nonexistent.csv"), std::string::npos) << missing.err;
  const auto polygon = run_cli({"check-data", path("verify/scenes/pentagon.yaml"), path("verify/data/pmks_watt_i_matlab.csv")});
  EXPECT_EQ(polygon.code, 2) << polygon.err;
  EXPECT_NE(polygon.err.find("got a polygon scene"), std::string::npos) << polygon.err;
}

// Every command that needs a mechanism refuses a polygon scene with the same message.
TEST(CheckDataCli, PolygonSceneIsRefusedAlikeByEveryMechanismCommand) {
  for (const std::string command : {"check-data", "curvature"}) {
    std::vector<std::string> args = {command, path("verify/scenes/pentagon.yaml")};
    if (command == "check-data") args.push_back(path("verify/data/pmks_watt_i_matlab.csv"));
    const auto r = run_cli(args);
    EXPECT_EQ(r.code, 2) << command;
    EXPECT_NE(r.err.find("pentagon.yaml: mechanism: expected a mechanism scene"), std::string::npos) << r.err;
  }
}

}  // namespace
}  // namespace linkproof
