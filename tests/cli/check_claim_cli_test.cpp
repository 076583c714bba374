// `check-claim` on claims that cannot be evaluated: never a pass (issue 11, findings 3 and 4).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>

#include "support/cli_run.h"

namespace linkproof {
namespace {

using test::CliRun;
using test::run_cli;

std::string claim_file(const std::string& name, const std::string& lhs, const std::string& rhs) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << "claims:\n  - id: mine\n    source: test\n    statement: s\n    lhs: " << lhs
                      << "\n    rhs: " << rhs << "\n";
  return path;
}

TEST(CheckClaimCli, IndexOutOfRangeIsBadInputNotHoldsOnSamples) {
  const CliRun r = run_cli({"check-claim", claim_file("c1.yaml", "omega[100]", "12345"), "--json"});
  EXPECT_EQ(r.code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("c1.yaml:5:"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("holds_on_samples"), std::string::npos) << r.out;
}

TEST(CheckClaimCli, SideZeroIsBadInput) {
  const CliRun r = run_cli({"check-claim", claim_file("c2.yaml", "1000 + side_omega[0]", "1000")});
  EXPECT_EQ(r.code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("side_omega[0]"), std::string::npos) << r.err;
}

// A term that always divides by zero: no evaluation can produce a comparison, so the result is
// an error (exit 3), never holds_on_samples with not one evaluation done.
TEST(CheckClaimCli, AlwaysUndefinedClaimIsBadInputNotAPass) {
  // 1/(r_{n-1} x r_{n-1}): the divisor is identically zero, the claim undefined at every
  // configuration. It was the verdict error with exit 3 (an internal error) before; it is the
  // user's ill-formed claim: exit 2, naming the divisor.
  const CliRun r = run_cli({"check-claim", claim_file("c3.yaml", "1/cross(r[n-1], r[n-1])", "1"), "--json", "--n", "4..5",
                            "--count", "3"});
  EXPECT_EQ(r.code, 2) << r.out << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["error"]["kind"], "input") << r.out;
  EXPECT_NE(j["error"]["message"].get<std::string>().find("cross(r[n-1], r[n-1]) ("), std::string::npos) << r.out;
  EXPECT_EQ(j["exit_status"], 2) << r.out;
}

// --scene: a user's claim that is not well formed is bad input, refused the same way in text
// and JSON (it was the verdict error, exit 3, as if linkproof had a bug).
TEST(CheckClaimCli, SceneCheckRefusesAnIllFormedClaimInTextAndJson) {
  const std::string scene = std::string(LINKPROOF_SOURCE_DIR) + "/verify/scenes/pentagon.yaml";
  const std::string file = claim_file("c4.yaml", "r[n-1]", "1");  // a vector where a number is expected
  const CliRun json = run_cli({"check-claim", file, "--scene", scene, "--json"});
  const CliRun text = run_cli({"check-claim", file, "--scene", scene});
  EXPECT_EQ(text.code, 2) << text.out << text.err;
  EXPECT_EQ(json.code, 2) << json.out << json.err;
  EXPECT_NE(text.err.find("claim 'mine'"), std::string::npos) << text.err;
  EXPECT_NE(text.err.find("a vector where a number is expected"), std::string::npos) << text.err;
  const auto j = nlohmann::json::parse(json.out);
  EXPECT_EQ(j["error"]["kind"], "input") << json.out;
  EXPECT_EQ(j["error"]["file"], file) << json.out;
  EXPECT_EQ(j["exit_status"], 2) << json.out;
}

TEST(CheckClaimCli, StrictMakesProvedForNotAsExpected) {
  const std::string file = claim_file("c5.yaml", "side_omega[1]", "omega[1]");
  const CliRun loose = run_cli({"check-claim", file, "--ladder-seconds", "0", "--json"});
  EXPECT_EQ(loose.code, 0) << loose.out << loose.err;
  EXPECT_EQ(nlohmann::json::parse(loose.out)["claims"][0]["verdict"], "proved_for");
  const CliRun strict = run_cli({"check-claim", file, "--ladder-seconds", "0", "--json", "--strict"});
  EXPECT_EQ(strict.code, 1) << strict.out;
  EXPECT_EQ(nlohmann::json::parse(strict.out)["claims"][0]["as_expected"], false);
}

}  // namespace
}  // namespace linkproof
