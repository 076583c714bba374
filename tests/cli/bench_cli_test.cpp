// `linkproof bench`, run in-process on a tiny study: files written, JSON keys, bad options.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/cli_run.h"

namespace linkproof {
namespace {

using test::run_cli;

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(BenchCli, TinyBenchWritesTableJsonAndPlotsIntoTheOutputDirectory) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "linkproof_bench_cli";
  std::filesystem::remove_all(dir);
  const test::CliRun r = run_cli({"bench", "--families", "q_infinity,dead_centre", "--cases", "1", "--time-budget-ms",
                              "0.05", "--adaptive-cases", "5", "--out", dir.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* f : {"bench.md", "bench.json", "pareto.svg", "family_q_infinity.svg", "family_dead_centre.svg"})
    EXPECT_TRUE(std::filesystem::exists(dir / f)) << f;
  EXPECT_FALSE(std::filesystem::exists(dir / "family_beta_zero.svg"));

  const nlohmann::json j = nlohmann::json::parse(slurp(dir / "bench.json"));
  for (const char* k : {"seed", "n", "full", "pareto", "families", "adaptive"}) EXPECT_TRUE(j.contains(k)) << k;
  // 4 routes x 7 arithmetics.
  ASSERT_EQ(j["pareto"].size(), 28u);
  for (const char* k : {"route", "arithmetic", "precision_bits", "median_relative_error", "max_log2_relative_error",
                        "median_error_bits", "median_ns_per_eval", "on_front"})
    EXPECT_TRUE(j["pareto"][0].contains(k)) << k;
  ASSERT_EQ(j["families"].size(), 2u);
  const nlohmann::json& fam = j["families"][0];
  for (const char* k : {"name", "parameter", "degenerate_quantity", "singular", "trust_route", "findings", "points"})
    EXPECT_TRUE(fam.contains(k)) << k;
  ASSERT_EQ(j["adaptive"].size(), 4u);  // random pentagons at three requests; extreme families
  for (const char* k : {"corpus", "request", "cases", "by_stage", "by_level", "escalation_rate", "cost_ratio",
                        "fraction_within_2x"})
    EXPECT_TRUE(j["adaptive"][0].contains(k)) << k;

  const std::string svg = slurp(dir / "family_q_infinity.svg");
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_NE(svg.find("<path"), std::string::npos);
  EXPECT_NE(slurp(dir / "bench.md").find("| direct-solve | mp1000 |"), std::string::npos);
}

TEST(BenchCli, UnknownFamilyIsBadInputNamingTheOption) {
  const test::CliRun r = run_cli({"bench", "--families", "no_such_family", "--cases", "1"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--families"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no_such_family"), std::string::npos) << r.err;
}

TEST(BenchCli, OutOfRangeOptionsAreBadInput) {
  EXPECT_EQ(run_cli({"bench", "--cases", "0"}).code, 2);
  EXPECT_EQ(run_cli({"bench", "--n", "3"}).code, 2);
  EXPECT_EQ(run_cli({"bench", "--time-budget-ms", "-1"}).code, 2);
}

}  // namespace
}  // namespace linkproof
