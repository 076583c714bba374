// `ask` through the program: the scene's arithmetic and --arith's precedence, the JSON of an
// asked check, and a report that leaves out the sections of what was not asked.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "support/cli_run.h"
#include "support/temp_dir.h"

namespace linkproof {
namespace {

using test::run_cli;

std::string write_scene(const test::TempDir& dir, const std::string& ask) {
  const auto path = (dir.path / "asked.yaml").string();
  std::ofstream(path) << "name: asked\npolygon:\n  joints: [[0, 0], [1, 4], [5, 5], [7, 1], [3, -2]]\n"
                         "  omega: [2, -1]\n  omega_dot: [1, 3]\nask: "
                      << ask << "\n";
  return path;
}

TEST(AskCli, TheScenesArithmeticIsUsedUnlessArithIsGiven) {
  const test::TempDir dir("ask_arith");
  const std::string scene = write_scene(dir, "[omega_dot(4), claims: [eq22], arithmetic: double]");
  const auto asked = run_cli({"check", scene, "--json"});
  ASSERT_EQ(asked.code, 0) << asked.err;
  const auto j = nlohmann::json::parse(asked.out);
  EXPECT_EQ(j["arithmetic"], "double");
  EXPECT_EQ(j["ask"], (nlohmann::json{"omega_dot(4)", "claims: eq22", "arithmetic: double"}));
  EXPECT_EQ(j["claims"].size(), 1u);
  EXPECT_EQ(j["polygon"]["omega_dot"].size(), 1u);
  EXPECT_TRUE(j["polygon"]["omega"].empty());
  const auto exact = run_cli({"check", scene, "--json", "--arith", "exact"});
  ASSERT_EQ(exact.code, 0) << exact.err;
  const auto e = nlohmann::json::parse(exact.out);
  EXPECT_EQ(e["arithmetic"], "exact");
  EXPECT_EQ(e["polygon"]["omega_dot"]["4"], "3755/1331");
}

TEST(AskCli, AnUnknownClaimIsExit2NamingTheField) {
  const test::TempDir dir("ask_claim");
  const auto r = run_cli({"check", write_scene(dir, "[claims: [eq99]]")});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("ask[0].claims[0]"), std::string::npos) << r.err;
}

TEST(AskCli, TheReportLeavesOutTheSectionsOfWhatWasNotAsked) {
  const test::TempDir dir("ask_report");
  const std::string asked = write_scene(dir, "[omega(1)]");
  const auto r = run_cli({"report", asked, "--format", "md", "--out", dir.path.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string md = test::slurp(dir.path / "asked.md");
  EXPECT_NE(md.find("The scene asks for omega(1)"), std::string::npos);
  EXPECT_EQ(md.find("## Construction"), std::string::npos);  // no claim read the construction
  EXPECT_EQ(md.find("## Derivation"), std::string::npos);    // an input's rate needs no ground truth
  const std::string full = (dir.path / "full.yaml").string();
  std::ofstream(full) << "name: full\npolygon:\n  joints: [[0, 0], [1, 4], [5, 5], [7, 1], [3, -2]]\n"
                         "  omega: [2, -1]\n  omega_dot: [1, 3]\n";
  ASSERT_EQ(run_cli({"report", full, "--format", "md", "--out", dir.path.string()}).code, 0);
  const std::string all = test::slurp(dir.path / "full.md");
  EXPECT_NE(all.find("## Construction"), std::string::npos);
  EXPECT_NE(all.find("## Derivation"), std::string::npos);
}

}  // namespace
}  // namespace linkproof
