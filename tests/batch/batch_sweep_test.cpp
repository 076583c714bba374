// Sweeps as batch jobs: --jobs, --shard + merge, --resume after a kill all give the bytes of one
// plain single-process run (the result file, and the report but for its run time).
#include <gtest/gtest.h>

#include <csignal>

#include "batch/sweep_files.h"
#include "dijksman1966.h"
#include "exit_status.h"
#include "report/json_report.h"

namespace linkproof::test {
namespace {

// 5 values of n x 10 cases: long enough to be killed mid-run, short enough for the unit suite.
const std::vector<std::string> kSweep = {"sweep", "--n", "4..8", "--count", "10", "--seed", "11"};

std::vector<std::string> sweep_args(std::vector<std::string> extra) {
  std::vector<std::string> a = kSweep;
  a.insert(a.end(), extra.begin(), extra.end());
  return a;
}

/// The reference: one plain single-process run, computed once.
const Reference& reference() {
  static const Reference r = reference_run("sweep_reference", sweep_args({"--jobs", "1"}));
  return r;
}

TEST(BatchSweep, ResultFileHasOneLinePerCaseThenASummary) {
  const std::string& file = reference().file;
  std::istringstream in(file);
  std::string line;
  long cases = 0;
  nlohmann::json last;
  while (std::getline(in, line)) {
    last = nlohmann::json::parse(line);
    if (!last.contains("summary")) {
      EXPECT_EQ(last["case"].get<long>(), cases++);
    }
  }
  EXPECT_EQ(cases, 50);
  ASSERT_TRUE(last.contains("summary"));
  EXPECT_EQ(last["summary"]["cases"], 50);
  EXPECT_FALSE(last["summary"].contains("seconds"));
}

TEST(BatchSweep, OutputWithoutNewOptionsIsTheOldSingleLoop) {
  // The plain `sweep --json` (default --jobs: every core) against the library's single loop.
  const auto plain = run_cli(sweep_args({"--json"}));
  ASSERT_EQ(plain.code, 0) << plain.err;
  SweepOptions o;
  o.n_min = 4, o.n_max = 8, o.count = 10, o.seed = 11;
  GroundTruthEngine engine;
  const SweepReport report = run_sweep(engine, dijksman1966::catalogue(), o);
  const std::string loop = to_json(report, cli::exit_status(report)).dump(2);
  EXPECT_EQ(without_seconds(plain.out), without_seconds(loop));
  EXPECT_EQ(reference().json, without_seconds(loop));
  const auto text1 = run_cli(sweep_args({"--jobs", "1"}));
  const auto text2 = run_cli(sweep_args({"--jobs", "2"}));
  auto strip_time = [](std::string s) { return s.substr(s.find('\n')); };  // first line has the seconds
  EXPECT_EQ(strip_time(text1.out), strip_time(text2.out));
}

TEST(BatchSweep, JobsTwoGivesTheBytesOfJobsOne) {
  const std::string dir = fresh_dir("sweep_jobs2");
  const auto run = run_cli(sweep_args({"--jobs", "2", "--out", dir + "/j2.jsonl", "--json"}));
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(read_file(dir + "/j2.jsonl"), reference().file);
  EXPECT_EQ(without_seconds(run.out), reference().json);
}

TEST(BatchSweep, ShardsMergedGiveTheBytesOfOneRun) {
  const std::string dir = fresh_dir("sweep_shards");
  std::vector<std::string> files;
  for (int k : {3, 1, 2}) {  // any order
    files.push_back(dir + "/shard" + std::to_string(k) + ".jsonl");
    const auto run = run_cli(sweep_args({"--shard", std::to_string(k) + "/3", "--out", files.back()}));
    ASSERT_EQ(run.code, 0) << run.err;
  }
  std::vector<std::string> merge = {"merge", "--out", dir + "/merged.jsonl", "--json"};
  merge.insert(merge.end(), files.begin(), files.end());
  const auto run = run_cli(merge);
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(read_file(dir + "/merged.jsonl"), reference().file);
  EXPECT_EQ(without_seconds(run.out), reference().json);
}

TEST(BatchSweep, MergeRejectsAMissingOrRepeatedShard) {
  const std::string dir = fresh_dir("sweep_merge_bad");
  const std::string s1 = dir + "/s1.jsonl", s2 = dir + "/s2.jsonl";
  ASSERT_EQ(run_cli(sweep_args({"--shard", "1/3", "--out", s1})).code, 0);
  ASSERT_EQ(run_cli(sweep_args({"--shard", "2/3", "--out", s2})).code, 0);
  const auto missing = run_cli({"merge", "--out", dir + "/m1.jsonl", s1, s2});
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.err.find("2 of 3 shards"), std::string::npos) << missing.err;
  const auto twice = run_cli({"merge", "--out", dir + "/m2.jsonl", s1, s1, s2});
  EXPECT_EQ(twice.code, 2);
  EXPECT_NE(twice.err.find("shard given twice"), std::string::npos) << twice.err;
}

TEST(BatchSweep, MergeRejectsAnIncompleteShard) {
  const std::string dir = fresh_dir("sweep_merge_incomplete");
  const std::string s1 = dir + "/s1.jsonl", s2 = dir + "/s2.jsonl";
  ASSERT_EQ(run_cli(sweep_args({"--shard", "1/2", "--out", s1})).code, 0);
  ASSERT_EQ(run_cli(sweep_args({"--shard", "2/2", "--out", s2})).code, 0);
  std::string text = read_file(s2);
  text.erase(text.rfind('\n', text.size() - 2) + 1);  // drop the summary line
  std::ofstream(s2, std::ios::binary | std::ios::trunc) << text;
  const auto r = run_cli({"merge", "--out", dir + "/m.jsonl", s1, s2});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find(s2), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no summary line"), std::string::npos) << r.err;
}

TEST(BatchSweep, ResumeAfterACutLineGivesTheBytesOfOneRun) {
  // A crash in the middle of a write leaves a partial last line: resume cuts it and continues.
  const std::string dir = fresh_dir("sweep_cut");
  const std::string& ref = reference().file;
  size_t cut = 0;
  for (int i = 0; i < 7; ++i) cut = ref.find('\n', cut) + 1;
  cut += 40;  // into the 8th line
  std::ofstream(dir + "/r.jsonl", std::ios::binary) << ref.substr(0, cut);
  const auto run = run_cli(sweep_args({"--jobs", "2", "--out", dir + "/r.jsonl", "--resume", "--json"}));
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(read_file(dir + "/r.jsonl"), ref);
  EXPECT_EQ(without_seconds(run.out), reference().json);
}

/// Runs the sweep in a child process, sends `sig` once the result file holds `lines` lines, and
/// returns the child's exit code (128 + signal if the signal killed it).
int sweep_killed_after(const std::string& file, long lines, int sig, const std::vector<std::string>& extra) {
  std::vector<std::string> args = sweep_args({"--out", file});
  args.insert(args.end(), extra.begin(), extra.end());
  const pid_t child = test::spawn_cli(args);
  int code = 0;
  if (!test::wait_for_lines(file, lines, child, code)) return code;  // ended before the signal
  ::kill(child, sig);
  return test::wait_child(child);
}

TEST(BatchSweep, ResumeAfterSigkillGivesTheBytesOfOneRun) {
  const std::string dir = fresh_dir("sweep_sigkill");
  const std::string file = dir + "/r.jsonl";
  EXPECT_EQ(sweep_killed_after(file, 5, SIGKILL, {"--jobs", "2"}), 128 + SIGKILL);
  const std::string killed = read_file(file);
  ASSERT_EQ(killed.find("\"summary\""), std::string::npos) << "the sweep finished before it was killed";
  const auto run = run_cli(sweep_args({"--jobs", "2", "--out", file, "--resume", "--json"}));
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(read_file(file), reference().file);
  EXPECT_EQ(without_seconds(run.out), reference().json);
}

TEST(BatchSweep, SigtermStopsCleanlyAndResumeGivesTheBytesOfOneRun) {
  for (const char* jobs : {"1", "2"}) {
    const std::string dir = fresh_dir(std::string("sweep_sigterm") + jobs);
    const std::string file = dir + "/r.jsonl";
    EXPECT_EQ(sweep_killed_after(file, 5, SIGTERM, {"--jobs", jobs}), 128 + SIGTERM) << "jobs " << jobs;
    const std::string stopped = read_file(file);
    ASSERT_EQ(stopped.find("\"summary\""), std::string::npos) << "the sweep finished before SIGTERM";
    ASSERT_EQ(stopped.back(), '\n') << "a clean stop leaves only complete lines";
    const auto run = run_cli(sweep_args({"--jobs", "1", "--out", file, "--resume", "--json"}));
    ASSERT_EQ(run.code, 0) << run.err;
    EXPECT_EQ(read_file(file), reference().file) << "jobs " << jobs;
  }
}

TEST(BatchSweep, KilledWorkerEndsTheRunWithExitThreeAndResumeCompletes) {
  const std::string dir = fresh_dir("sweep_kill_worker");
  const std::string file = dir + "/r.jsonl";
  const pid_t child = test::spawn_cli(sweep_args({"--jobs", "2", "--out", file}));
  int code = 0;
  ASSERT_TRUE(test::wait_for_lines(file, 3, child, code)) << "the sweep ended (exit " << code << ") too early";
  const std::string children = read_file("/proc/" + std::to_string(child) + "/task/" + std::to_string(child) + "/children");
  std::istringstream pids(children);
  pid_t worker = 0;
  if (!(pids >> worker)) {
    ::kill(child, SIGKILL);
    test::wait_child(child);
    GTEST_SKIP() << "/proc/PID/task/PID/children is not available on this kernel";
  }
  ::kill(worker, SIGKILL);
  EXPECT_EQ(test::wait_child(child), 3);
  const std::string stopped = read_file(file);
  ASSERT_EQ(stopped.find("\"summary\""), std::string::npos) << "the sweep finished before its worker was killed";
  EXPECT_EQ(stopped.back(), '\n');
  const auto run = run_cli(sweep_args({"--jobs", "2", "--out", file, "--resume"}));
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(read_file(file), reference().file);
}

TEST(BatchSweep, ResumeOfACompleteFileChangesNothing) {
  const std::string dir = fresh_dir("sweep_complete");
  std::ofstream(dir + "/r.jsonl", std::ios::binary) << reference().file;
  const auto run = run_cli(sweep_args({"--out", dir + "/r.jsonl", "--resume", "--json"}));
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(read_file(dir + "/r.jsonl"), reference().file);
  EXPECT_EQ(without_seconds(run.out), reference().json);
}

TEST(BatchSweep, ResumeRejectsTheFileOfAnotherSweep) {
  const std::string dir = fresh_dir("sweep_other");
  std::ofstream(dir + "/r.jsonl", std::ios::binary) << reference().file.substr(0, reference().file.find('\n') + 1);
  const auto run = run_cli({"sweep", "--n", "4..8", "--count", "10", "--seed", "12", "--out", dir + "/r.jsonl",
                            "--resume"});
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find(dir + "/r.jsonl"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("line 1"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("another sweep"), std::string::npos) << run.err;
}

TEST(BatchSweep, OutRefusesToOverwriteWithoutResume) {
  const std::string dir = fresh_dir("sweep_overwrite");
  std::ofstream(dir + "/r.jsonl") << "precious\n";
  const auto run = run_cli(sweep_args({"--out", dir + "/r.jsonl"}));
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find("--resume"), std::string::npos) << run.err;
  EXPECT_EQ(read_file(dir + "/r.jsonl"), "precious\n");
}

TEST(BatchSweep, BadOptionsAreInputErrors) {
  for (const auto& extra : std::vector<std::vector<std::string>>{
           {"--shard", "0/2"}, {"--shard", "3/2"}, {"--shard", "x"}, {"--jobs", "0"}, {"--resume"},
           {"--index", "1", "--out", "x.jsonl"}}) {
    const auto run = run_cli(sweep_args(extra));
    EXPECT_EQ(run.code, 2) << extra.front() << ": " << run.err;
  }
}

TEST(BatchSweep, ProgressIsSilentWhenStderrIsNotATerminal) {
  const auto run = run_cli(sweep_args({"--jobs", "2"}));
  EXPECT_EQ(run.err, "");
}

}  // namespace
}  // namespace linkproof::test
