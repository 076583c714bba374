// `linkproof check` on a mechanism given by dimensions states which positions and rates it runs
// on as rationals, and within what, in text and JSON, whatever the arithmetic; never silently
// (docs/mechanisms.md, "Mechanisms from dimensions").
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <string>

#include "support/cli_run.h"

namespace linkproof {
namespace {

std::string bundled(const std::string& name) {
  return std::string(LINKPROOF_SOURCE_DIR) + "/verify/scenes/mechanisms/" + name;
}

const std::string kStatement =
    "runs on rationalised positions: joints A, B within 1e-58; input rates inputs[0].omega within 1e-58";

TEST(DimensionsCli, CheckTextStatesTheRationalisedPositionsAndRates) {
  const test::CliRun r = test::run_cli({"check", bundled("dimensions_fourbar.yaml")});
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  EXPECT_EQ(r.out.rfind(kStatement, 0), 0u) << "the statement comes first:\n" << r.out;
  EXPECT_NE(r.out.find("exact for these rationals"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\nO2               at                   exact\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\nA                polar                rationalised, within 1e-58\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\nB                dyad                 rationalised, within 1e-58\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\ninputs[0].omega  1500rpm              rationalised, within 1e-58\n"), std::string::npos) << r.out;
}

TEST(DimensionsCli, ArithExactRunsOnTheStatedRationalisedPositions) {
  for (const std::string arith : {"exact", "double", "mp100"}) {
    SCOPED_TRACE(arith);
    const test::CliRun r = test::run_cli({"check", bundled("dimensions_fourbar.yaml"), "--arith", arith});
    ASSERT_EQ(r.code, 0) << r.err << r.out;
    EXPECT_NE(r.out.find(kStatement), std::string::npos) << r.out;
  }
}

TEST(DimensionsCli, CheckJsonCarriesPositionsRatesAndTheStatement) {
  const test::CliRun r = test::run_cli({"check", bundled("dimensions_slider_crank.yaml"), "--json", "--arith", "exact"});
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["positions"]["O2"], (nlohmann::json{{"given_by", "at"}, {"exact", true}, {"bound", "0"}}));
  EXPECT_EQ(j["positions"]["A"]["given_by"], "polar");
  EXPECT_EQ(j["positions"]["A"]["exact"], false);
  EXPECT_EQ(j["positions"]["A"]["bound"], "1e-58");
  EXPECT_EQ(j["positions"]["B"]["given_by"], "slide");
  EXPECT_EQ(j["positions"]["D"]["given_by"], "at joint");
  EXPECT_EQ(j["positions"]["D"]["axis"]["exact"], true);  // 0deg: (1, 0) exactly
  EXPECT_EQ(j["input_rates"]["inputs[0].omega"]["given"], "-2000rpm");
  EXPECT_EQ(j["input_rates"]["inputs[0].omega"]["exact"], false);
  // Each joint's own certified bound, rounded up to a power of ten: B and D are sharper than A.
  EXPECT_EQ(j["positions"]["B"]["bound"], "1e-59");
  EXPECT_EQ(j["rationalised"], "runs on rationalised positions: joints A within 1e-58, B, D within 1e-59; input rates "
                               "inputs[0].omega within 1e-58");
  // The check's own keys are all still there.
  for (const char* key : {"scene", "arithmetic", "mobility", "links", "joints", "claims", "summary", "exit_status"})
    EXPECT_TRUE(j.contains(key)) << key;
}

TEST(DimensionsCli, ASceneOfGivenPositionsSaysNothingInTextAndAllExactInJson) {
  const test::CliRun text = test::run_cli({"check", bundled("seed001_fourbar.yaml")});
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_EQ(text.out.find("rationalised"), std::string::npos) << text.out;
  EXPECT_EQ(text.out.rfind("scene ", 0), 0u) << text.out;
  const test::CliRun json_run = test::run_cli({"check", bundled("seed001_fourbar.yaml"), "--json"});
  const auto j = nlohmann::json::parse(json_run.out);
  EXPECT_TRUE(j["rationalised"].is_null());
  EXPECT_EQ(j["positions"]["B"]["exact"], true);
  EXPECT_TRUE(j["input_rates"].empty());
}

TEST(DimensionsCli, OtherCommandsNoteTheRationalisedPositionsOnStandardError) {
  const test::CliRun r = test::run_cli({"curvature", bundled("dimensions_fourbar.yaml")});
  EXPECT_NE(r.err.find("note: " + bundled("dimensions_fourbar.yaml") + ": " + kStatement), std::string::npos) << r.err;
}

// check-claim --scene judges claims at the rationalised positions: a claim about the lengths
// themselves failed there (|O2A|^2 = 1600 off by 1e-57) with nothing said about why.
TEST(DimensionsCli, CheckClaimOnAScenePlacedFromDimensionsStatesTheRationalisedPositions) {
  const std::string claims = ::testing::TempDir() + "dimension_claims.yaml";
  {
    std::ofstream(claims) << "claims:\n  - id: crank_length\n    source: test\n    statement: s\n"
                             "    lhs: norm2(pos(A) - pos(O2))\n    rhs: 1600\n";
  }
  const test::CliRun text = test::run_cli({"check-claim", claims, "--scene", bundled("dimensions_fourbar.yaml")});
  EXPECT_EQ(text.out.rfind(kStatement, 0), 0u) << "the statement comes first:\n" << text.out;
  const test::CliRun as_json = test::run_cli({"check-claim", claims, "--scene", bundled("dimensions_fourbar.yaml"), "--json"});
  const nlohmann::json j = nlohmann::json::parse(as_json.out);
  EXPECT_EQ(j["rationalised"], kStatement) << as_json.out;
  EXPECT_EQ(j["positions"]["A"]["exact"], false) << as_json.out;
}

// A slot is one joint to its reader (report/slot_rows.h): the statement names P, not the pin
// joint P.pin that the engine adds at the same point.
TEST(DimensionsCli, TheStatementNamesASlotOnceNotItsPinJoint) {
  const test::CliRun r = test::run_cli({"check", bundled("geneva.yaml")});
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  EXPECT_EQ(r.out.rfind("runs on rationalised positions: joints P within 1e-58; input rates inputs[0].omega "
                        "within 1e-59\n",
                        0),
            0u)
      << r.out;
  EXPECT_EQ(r.out.find("P.pin"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace linkproof
