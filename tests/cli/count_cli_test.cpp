// `linkproof count` run in-process: exit codes, the JSON keys, bad input.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sstream>

#include "support/cli_run.h"

namespace linkproof {
namespace {

using test::CliRun;
using test::run_cli;

TEST(CountCli, RangeOfNPrintsATableAndExitsZero) {
  const CliRun r = run_cli({"count", "--n", "3..7"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("dijksman1966.A7.triangle_rank[n=7]"), std::string::npos);
  EXPECT_NE(r.out.find("25 claims, 0 not as expected"), std::string::npos) << r.out;
}

TEST(CountCli, JsonCarriesIdVerdictSizesAndTimes) {
  const CliRun r = run_cli({"count", "--n", "6", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["exit_status"], 0);
  ASSERT_EQ(j["claims"].size(), 5u);
  for (const auto& c : j["claims"]) {
    for (const char* key : {"id", "verdict", "expected", "as_expected", "statement", "expected_value",
                            "observed_value", "reason"})
      EXPECT_TRUE(c.contains(key)) << key << " in " << c.dump();
    // Triangle rank and balance are proved; the geometric rank-2 families rest on samples.
    const bool geometric = c["id"].get<std::string>().find("rank2") != std::string::npos;
    EXPECT_EQ(c["verdict"], geometric ? "holds_on_samples" : "proved") << c.dump();
    EXPECT_TRUE(c["as_expected"].get<bool>()) << c.dump();
  }
  const auto& tri = j["claims"][0];
  EXPECT_EQ(tri["id"], "dijksman1966.A7.triangle_rank[n=6]");
  EXPECT_EQ(tri["relations"], 20);
  EXPECT_EQ(tri["unknowns"], 15);
  EXPECT_EQ(tri["rank"], 10);
  EXPECT_EQ(tri["observed_value"], "10");
  EXPECT_TRUE(tri["consistent"].get<bool>());
  EXPECT_TRUE(tri["seconds"].is_number());
  EXPECT_EQ(j["summary"]["proved"], 2);
  EXPECT_EQ(j["summary"]["holds_on_samples"], 3);
}

TEST(CountCli, EightBarReportsRanksValuesAndTheErratum) {
  const CliRun r = run_cli({"count", "--eightbar", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  std::map<std::string, nlohmann::json> by_id;
  for (const auto& c : j["claims"]) by_id[c["id"]] = c;
  EXPECT_EQ(by_id.at("dijksman1966.fig5.triangle_rank")["observed_value"], "21");
  EXPECT_EQ(by_id.at("dijksman1966.fig5.with_input")["observed_value"], "22");
  EXPECT_EQ(by_id.at("dijksman1966.fig5.with_polygons")["observed_value"], "28");
  EXPECT_EQ(by_id.at("dijksman1966.fig5.with_polygons")["unknowns"], 28);
  EXPECT_EQ(by_id.at("dijksman1966.fig5.omega_dot_4_0")["observed_value"], "171151479/318550130");
  EXPECT_EQ(by_id.at("dijksman1966.fig5.omega_dot_1_2")["observed_value"], "8471254/159275065");
  EXPECT_EQ(by_id.at("dijksman1966.sec3.count.printed")["verdict"], "disproved");
  EXPECT_EQ(by_id.at("dijksman1966.sec3.count.printed")["as_expected"], true);
  ASSERT_EQ(j["notes"].size(), 1u);
  const CliRun text = run_cli({"count", "--eightbar"});
  EXPECT_NE(text.out.find("A5.5"), std::string::npos);
}

TEST(CountCli, TooFewLoopsExitOne) {
  const CliRun r = run_cli({"count", "--eightbar", "--polygons", "1-2-3-4-0,1-5-7-4-0"});
  EXPECT_EQ(r.code, 1) << r.out;
}

TEST(CountCli, BadInputExitsTwoNamingTheOption) {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"count", "--n", "2"}, {"count", "--n", "abc"}, {"count", "--n", "9..5"},
        {"count", "--n", "3..201"}, {"count"}, {"count", "--n", "5", "--eightbar"},
        {"count", "--n", "5", "--polygons", "1-2-3"}, {"count", "--eightbar", "--polygons", "1-2-x"},
        {"count", "--eightbar", "--polygons", "1-2-7-4-0"}}) {
    const CliRun r = run_cli(args);
    EXPECT_EQ(r.code, 2) << args.back();
    EXPECT_NE(r.err.find("bad input"), std::string::npos) << r.err;
  }
}

}  // namespace
}  // namespace linkproof
