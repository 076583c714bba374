// `sweep --topology SCENE --claims CLAIMS --count K`: mechanism claims on the configurations
// 0..K-1 of a topology as a batch job (issue 26). --jobs, shards + merge and a killed run
// resumed give the bytes of one plain single-process run (the report but for its run time).
#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <map>

#include "batch/sweep_files.h"
#include "support/counterexample_replay.h"

namespace linkproof::test {
namespace {

std::string source(const std::string& rel) { return std::string(LINKPROOF_SOURCE_DIR) + "/" + rel; }

const std::string kFourbar = source("verify/scenes/mechanisms/seed001_fourbar.yaml");
// True claims and wrong variants (expected: fails) of the seed-001 four-bar.
const std::string kFourbarClaims = source("verify/claims/mechanisms/fourbar.yaml");

/// The sweep of the four-bar's claims, `count` configurations of seed `seed`, and `extra`.
std::vector<std::string> sweep_of(const std::string& count, const std::string& seed, std::vector<std::string> extra) {
  std::vector<std::string> a = {"sweep", "--topology", kFourbar, "--claims", kFourbarClaims, "--count", count,
                                "--seed", seed};
  a.insert(a.end(), extra.begin(), extra.end());
  return a;
}
std::vector<std::string> topology_sweep_args(std::vector<std::string> extra) { return sweep_of("60", "3", std::move(extra)); }

/// The reference: one plain single-process run, computed once.
const Reference& topology_reference() {
  static const Reference r = reference_run("topology_sweep_reference", topology_sweep_args({"--jobs", "1"}));
  return r;
}

TEST(SweepTopology, ResultFileHasOneLineNamingItsSweepPerConfigurationThenASummary) {
  std::istringstream in(topology_reference().file);
  std::string line;
  long cases = 0;
  nlohmann::json last;
  while (std::getline(in, line)) {
    last = nlohmann::json::parse(line);
    if (last.contains("summary")) break;
    EXPECT_EQ(last["case"].get<long>(), cases++);
    EXPECT_EQ(last["topology"], "fourbar-seed001");
    EXPECT_EQ(last["seed"], 3);
    EXPECT_EQ(last["count"], 60);
    EXPECT_EQ(last["arithmetic"], "exact");
    EXPECT_EQ(last["scene_digest"].get<std::string>().size(), 16u);
    EXPECT_EQ(last["claims_digest"].get<std::string>().size(), 16u);
  }
  EXPECT_EQ(cases, 60);
  ASSERT_TRUE(last.contains("summary"));
  EXPECT_EQ(last["summary"]["mode"], "topology_sweep");
  EXPECT_EQ(last["summary"]["configurations"]["generated"], 60) << "--count is the number of configurations drawn";
  EXPECT_FALSE(last["summary"].contains("seconds"));
  EXPECT_EQ(nlohmann::json::parse(topology_reference().json), last["summary"]) << "the summary is the report without seconds";
}

TEST(SweepTopology, SameReportWhateverTheJobs) {
  const std::string dir = fresh_dir("topology_sweep_jobs");
  const auto two = run_cli(topology_sweep_args({"--jobs", "2", "--out", dir + "/j2.jsonl", "--json"}));
  ASSERT_EQ(two.code, 0) << two.err;
  EXPECT_EQ(read_file(dir + "/j2.jsonl"), topology_reference().file);
  EXPECT_EQ(without_seconds(two.out), topology_reference().json);
  const auto text1 = run_cli(topology_sweep_args({"--jobs", "1"}));
  const auto text2 = run_cli(topology_sweep_args({"--jobs", "2"}));
  auto strip_time = [](std::string s) { return s.substr(s.find("rests on:")); };  // line 2 has the seconds
  EXPECT_EQ(strip_time(text1.out), strip_time(text2.out));
  EXPECT_NE(text1.out.find("--count is the number of configurations drawn"), std::string::npos) << text1.out;
}

TEST(SweepTopology, ShardsMergedEqualTheWholeRun) {
  const std::string dir = fresh_dir("topology_sweep_shards");
  std::vector<std::string> files;
  for (const char* shard : {"3/3", "1/3", "2/3"}) {
    const std::string f = dir + "/s" + std::string(1, shard[0]) + ".jsonl";
    const auto run = run_cli(topology_sweep_args({"--jobs", "2", "--shard", shard, "--out", f}));
    ASSERT_EQ(run.code, 0) << shard << ": " << run.err;
    files.push_back(f);
  }
  std::vector<std::string> merge = {"merge", "--topology", kFourbar, "--claims", kFourbarClaims, "--out",
                                    dir + "/merged.jsonl", "--json"};
  merge.insert(merge.end(), files.begin(), files.end());
  const auto merged = run_cli(merge);
  ASSERT_EQ(merged.code, 0) << merged.err;
  EXPECT_EQ(read_file(dir + "/merged.jsonl"), topology_reference().file);
  EXPECT_EQ(without_seconds(merged.out), topology_reference().json);
  // Without --topology and --claims, merge says what it needs.
  std::vector<std::string> bare = {"merge", "--out", dir + "/bare.jsonl"};
  bare.insert(bare.end(), files.begin(), files.end());
  const auto refused = run_cli(bare);
  EXPECT_EQ(refused.code, 2);
  EXPECT_NE(refused.err.find("--topology"), std::string::npos) << refused.err;
}

TEST(SweepTopology, ResumeAfterAKilledRunGivesTheSameReport) {
  // SIGKILL in the middle of a write leaves complete lines and a partial last one: resume cuts
  // it and continues (the cut is made here, so the test does not race a fast run).
  const std::string& ref = topology_reference().file;
  for (const char* jobs : {"1", "2"}) {
    const std::string dir = fresh_dir(std::string("topology_sweep_cut") + jobs);
    size_t cut = 0;
    for (int i = 0; i < 17; ++i) cut = ref.find('\n', cut) + 1;
    cut += 50;  // into the 18th line
    std::ofstream(dir + "/r.jsonl", std::ios::binary) << ref.substr(0, cut);
    const auto run = run_cli(topology_sweep_args({"--jobs", jobs, "--out", dir + "/r.jsonl", "--resume", "--json"}));
    ASSERT_EQ(run.code, 0) << run.err;
    EXPECT_EQ(read_file(dir + "/r.jsonl"), ref) << "jobs " << jobs;
    EXPECT_EQ(without_seconds(run.out), topology_reference().json) << "jobs " << jobs;
  }
  // A complete file is left as it is, and its report printed.
  const std::string dir = fresh_dir("topology_sweep_complete");
  std::ofstream(dir + "/r.jsonl", std::ios::binary) << ref;
  const auto again = run_cli(topology_sweep_args({"--out", dir + "/r.jsonl", "--resume", "--json"}));
  ASSERT_EQ(again.code, 0) << again.err;
  EXPECT_EQ(read_file(dir + "/r.jsonl"), ref);
  EXPECT_EQ(without_seconds(again.out), topology_reference().json);
}

TEST(SweepTopology, ResumeAfterSigkillOfALongerRunGivesTheBytesOfOneRun) {
  const std::string dir = fresh_dir("topology_sweep_sigkill");
  const std::string ref_file = dir + "/ref.jsonl", file = dir + "/r.jsonl";
  const pid_t child = test::spawn_cli(sweep_of("600", "5", {"--jobs", "2", "--out", file}));
  int code = 0;
  if (!test::wait_for_lines(file, 20, child, code)) GTEST_SKIP() << "the sweep ended (exit " << code << ") first";
  ::kill(child, SIGKILL);
  EXPECT_EQ(test::wait_child(child), 128 + SIGKILL);
  if (read_file(file).find("\"summary\"") != std::string::npos) GTEST_SKIP() << "the sweep finished before SIGKILL";
  const auto resumed = run_cli(sweep_of("600", "5", {"--jobs", "2", "--out", file, "--resume", "--json"}));
  ASSERT_EQ(resumed.code, 0) << resumed.err;
  const auto one = run_cli(sweep_of("600", "5", {"--jobs", "1", "--out", ref_file, "--json"}));
  ASSERT_EQ(one.code, 0) << one.err;
  EXPECT_EQ(read_file(file), read_file(ref_file));
  EXPECT_EQ(without_seconds(resumed.out), without_seconds(one.out));
}

TEST(SweepTopology, AWrongClaimIsDisprovedWithTheSameShrunkSceneAsCheckClaim) {
  const auto sweep = nlohmann::json::parse(topology_reference().json);
  const auto check = run_cli({"check-claim", kFourbarClaims, "--topology", kFourbar, "--count", "60", "--seed", "3",
                              "--json"});
  ASSERT_EQ(check.code, 0) << check.err;
  const auto sampled = nlohmann::json::parse(check.out);
  int disproved = 0;
  ASSERT_EQ(sweep["claims"].size(), sampled["claims"].size());
  for (size_t k = 0; k < sweep["claims"].size(); ++k) {
    const auto& c = sweep["claims"][k];
    const auto& s = sampled["claims"][k];
    ASSERT_EQ(c["id"], s["id"]);
    EXPECT_EQ(c["verdict"], s["verdict"]) << c["id"];
    if (c["verdict"] != "disproved") continue;
    ++disproved;
    EXPECT_EQ(c["first_failing_configuration"], c["counterexample"]["configuration"]);
    EXPECT_EQ(c["counterexample"], s["counterexample"]) << c["id"];
    test::expect_counterexample_refails(kFourbarClaims, c["id"], c["counterexample"]["scene_yaml"], "topology_sweep_");
  }
  EXPECT_EQ(disproved, 3);
}

/// The scene files in `dir`, by file name, with their text.
std::map<std::string, std::string> scene_files(const std::string& dir) {
  std::map<std::string, std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    files[entry.path().filename().string()] = read_file(entry.path().string());
  return files;
}

TEST(SweepTopology, ScenesWritesEachDisprovedClaimsCounterexampleAsASceneCheckClaimRefails) {
  const std::string dir = fresh_dir("topology_sweep_scenes");
  const auto run = run_cli(topology_sweep_args({"--jobs", "2", "--scenes", dir + "/scenes", "--json"}));
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(without_seconds(run.out), topology_reference().json) << "--scenes changes nothing in the report";
  const auto files = scene_files(dir + "/scenes");
  const auto report = nlohmann::json::parse(topology_reference().json);
  size_t disproved = 0;
  for (const auto& c : report["claims"]) {
    if (c["verdict"] != "disproved") continue;
    ++disproved;
    const std::string id = c["id"];
    const std::string name = "counterexample-" + id + ".yaml";
    ASSERT_EQ(files.count(name), 1u) << name;
    EXPECT_EQ(files.at(name), c["counterexample"]["scene_yaml"].get<std::string>()) << name;
    const auto replay = run_cli({"check-claim", kFourbarClaims, "--scene", dir + "/scenes/" + name, "--json"});
    const auto replayed = nlohmann::json::parse(replay.out);
    bool refailed = false;
    for (const auto& rc : replayed["claims"])
      if (rc["id"] == id) refailed = rc["verdict"] == "fails";
    EXPECT_TRUE(refailed) << name << ":\n" << replay.out;
  }
  EXPECT_EQ(disproved, 3u);
  EXPECT_EQ(files.size(), disproved) << "one scene a disproved claim, and nothing else";
}

TEST(SweepTopology, MergeScenesWritesTheScenesOfTheWholeRun) {
  const std::string dir = fresh_dir("topology_sweep_merge_scenes");
  ASSERT_EQ(run_cli(topology_sweep_args({"--jobs", "1", "--scenes", dir + "/whole"})).code, 0);
  std::vector<std::string> merge = {"merge", "--topology", kFourbar, "--claims", kFourbarClaims, "--out",
                                    dir + "/merged.jsonl", "--scenes", dir + "/merged"};
  for (const char* shard : {"1/2", "2/2"}) {
    const std::string f = dir + "/s" + std::string(1, shard[0]) + ".jsonl";
    ASSERT_EQ(run_cli(topology_sweep_args({"--jobs", "1", "--shard", shard, "--out", f})).code, 0) << shard;
    merge.push_back(f);
  }
  const auto merged = run_cli(merge);
  ASSERT_EQ(merged.code, 0) << merged.err;
  EXPECT_EQ(read_file(dir + "/merged.jsonl"), topology_reference().file);
  EXPECT_EQ(scene_files(dir + "/merged"), scene_files(dir + "/whole"));
  EXPECT_FALSE(scene_files(dir + "/whole").empty());
}

TEST(SweepTopology, TrueFourBarClaimsHoldOnSamplesInDoubleAndExact) {
  for (const std::string arith : {"exact", "double"}) {
    const auto run = run_cli(topology_sweep_args({"--arith", arith, "--jobs", "1", "--json"}));
    ASSERT_EQ(run.code, 0) << arith << ": " << run.err;
    const auto j = nlohmann::json::parse(run.out);
    EXPECT_EQ(j["arithmetic"], arith);
    for (const auto& c : j["claims"]) {
      EXPECT_TRUE(c["as_expected"].get<bool>()) << arith << " " << c["id"];
      if (c["expected"] == "holds") {
        EXPECT_EQ(c["verdict"], "holds_on_samples") << arith << " " << c["id"];
        EXPECT_GT(c["compared"].get<int>(), 0);
        EXPECT_EQ(c["failing_configurations"], 0);
        EXPECT_TRUE(c["first_failing_configuration"].is_null());
      } else {
        EXPECT_EQ(c["verdict"], "disproved") << arith << " " << c["id"];
      }
    }
  }
}

TEST(SweepTopology, RefusesAResultFileOfAnotherSweep) {
  const std::string dir = fresh_dir("topology_sweep_other");
  const std::string& ref = topology_reference().file;
  const std::string first_lines = ref.substr(0, ref.find('\n', ref.find('\n') + 1) + 1);
  const auto refused = [&](std::vector<std::string> args, const std::string& field) {
    std::ofstream(dir + "/r.jsonl", std::ios::binary) << first_lines;
    args.insert(args.end(), {"--out", dir + "/r.jsonl", "--resume"});
    const auto run = run_cli(args);
    EXPECT_EQ(run.code, 2) << field << ": " << run.err;
    EXPECT_NE(run.err.find(dir + "/r.jsonl"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("line 1"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find(field), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("another sweep"), std::string::npos) << run.err;
  };
  refused(sweep_of("60", "4", {}), "seed");
  refused(sweep_of("61", "3", {}), "count");
  refused(topology_sweep_args({"--arith", "double"}), "arithmetic");
  refused(topology_sweep_args({"--shard", "2/2"}), "case");
  // Other claims on the same scene: the claim file's digest differs.
  const std::string claims = dir + "/claims.yaml";
  std::ofstream(claims) << read_file(kFourbarClaims) << "# edited\n";
  refused({"sweep", "--topology", kFourbar, "--claims", claims, "--count", "60", "--seed", "3"}, "claims_digest");
  // A polygon sweep's file.
  const auto polygon = run_cli({"sweep", "--n", "4", "--count", "2", "--jobs", "1", "--out", dir + "/p.jsonl"});
  ASSERT_EQ(polygon.code, 0) << polygon.err;
  auto run = run_cli(topology_sweep_args({"--out", dir + "/p.jsonl", "--resume"}));
  EXPECT_EQ(run.code, 2) << run.err;
  EXPECT_NE(run.err.find(dir + "/p.jsonl"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("line 1"), std::string::npos) << run.err;
}

TEST(SweepTopology, BadOptionsNameTheOption) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"sweep", "--topology", kFourbar, "--count", "5"}, "--claims"},
      {{"sweep", "--claims", kFourbarClaims, "--count", "5"}, "--topology"},
      {topology_sweep_args({"--n", "4..6"}), "--n"},
      {topology_sweep_args({"--arith", "quad"}), "--arith"},
      {sweep_of("0", "3", {}), "--count"},
      {topology_sweep_args({"--index", "2"}), "--index"},
      {topology_sweep_args({"--scenes", kFourbar + "/scenes"}), "--scenes"},  // under a regular file: cannot be made
      {topology_sweep_args({"--shard", "4/3"}), "--shard"},
      {topology_sweep_args({"--jobs", "0"}), "--jobs"},
      {topology_sweep_args({"--resume"}), "--resume"},
      {{"sweep", "--topology", kFourbar, "--claims", source("verify/claims/wrong_variants.yaml"), "--count", "5"},
       "wrong_variants.yaml"},
      {{"sweep", "--topology", source("verify/scenes/pentagon.yaml"), "--claims", kFourbarClaims, "--count", "5"},
       "pentagon.yaml"},
  };
  for (const auto& [args, named] : cases) {
    const auto run = run_cli(args);
    EXPECT_EQ(run.code, 2) << named << ": " << run.err;
    EXPECT_NE(run.err.find(named), std::string::npos) << named << ": " << run.err;
  }
}

}  // namespace
}  // namespace linkproof::test
