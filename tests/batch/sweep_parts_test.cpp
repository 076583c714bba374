// The parts of a batch sweep: result-file lines, scenes of failing cases, a killed worker, the
// progress line, and the same bytes in floating-point arithmetic.
#include <gtest/gtest.h>

#include <csignal>

#include "batch/sweep_files.h"
#include "dijksman1966.h"
#include "batch/batch_sweep.h"
#include "batch/merge.h"
#include "batch/progress_bar.h"
#include "batch/worker_pool.h"
#include "exit_status.h"
#include "report/json_report.h"

namespace linkproof::test {
namespace {

/// The catalogue with one erratum reading marked as expected to hold: a catalogue that fails,
/// so the sweep has unexpected outcomes to keep, write as scenes and merge.
std::vector<Claim> failing_catalogue() {
  std::vector<Claim> c = dijksman1966::catalogue();
  for (Claim& claim : c)
    if (claim.info.id == "dijksman1966.eq9a.reversed_beta") claim.info.expected = Expectation::Holds;
  return c;
}

/// The program's exit status of a sweep, as the summary lines of result files record it.
const SweepExitStatus kExitStatus = [](const SweepReport& r) { return cli::exit_status(r); };

/// A batch sweep writing its result file to `out` (empty: none).
BatchSweepOptions batch_options(std::string out = "") {
  BatchSweepOptions o;
  o.out = std::move(out);
  o.exit_status = kExitStatus;
  return o;
}

SweepOptions small_sweep(Arithmetic a = Arithmetic::Exact) {
  SweepOptions o;
  o.n_min = 4, o.n_max = 6, o.count = 6, o.seed = 5, o.arithmetic = a;
  return o;
}

TEST(SweepLines, CaseLineReadsBackToTheSameBytes) {
  for (Arithmetic a : {Arithmetic::Exact, Arithmetic::Double}) {
    GroundTruthEngine engine;
    const std::vector<Claim> catalogue = failing_catalogue();
    for (long k : {0L, 7L, 17L}) {
      const SweepCase c = run_sweep_case(engine, catalogue, small_sweep(a), k);
      ASSERT_FALSE(c.examples.empty());
      const std::string line = sweep_case_line(c, a);
      const SweepLine back = parse_sweep_line(line, "<test>", 1);
      ASSERT_TRUE(back.sweep_case);
      EXPECT_EQ(sweep_case_line(*back.sweep_case, back.arithmetic), line) << to_string(a) << " case " << k;
    }
  }
}

TEST(SweepLines, BadLineNamesFileLineAndField) {
  try {
    parse_sweep_line(R"({"case":0,"seed":1,"n":5,"index":0,"family":"x","arithmetic":"exact"})", "r.jsonl", 4);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "r.jsonl");
    EXPECT_NE(e.field().find("line 4"), std::string::npos) << e.field();
  }
  EXPECT_THROW(parse_sweep_line("{\"case\": 0, trunc", "r.jsonl", 2), InputError);
}

TEST(BatchSweep, FailingCasesAreWrittenAsScenesThatCheckReads) {
  const std::string dir = fresh_dir("sweep_scenes");
  BatchSweepOptions o = batch_options();
  o.sweep = small_sweep();
  o.scenes_dir = dir + "/scenes";
  const BatchSweepResult r = run_batch_sweep(failing_catalogue(), o);
  ASSERT_EQ(r.status, BatchSweepResult::Status::Complete);
  EXPECT_EQ(cli::exit_status(r), 1);
  long scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(o.scenes_dir)) {
    ++scenes;
    // The bundled catalogue expects this reading to fail, so `check` of the scene says so.
    const auto check = run_cli({"check", entry.path().string(), "--json"});
    ASSERT_EQ(check.code, 0) << entry.path() << check.err;
    bool reversed_beta_fails = false;
    const nlohmann::json report = nlohmann::json::parse(check.out);  // named: the loop must not dangle
    for (const auto& c : report["claims"])
      if (c["id"] == "dijksman1966.eq9a.reversed_beta") reversed_beta_fails = c["verdict"] == "fails";
    EXPECT_TRUE(reversed_beta_fails) << entry.path();
  }
  long failing = 0;
  for (const auto& t : r.report.tallies)
    if (t.id == "dijksman1966.eq9a.reversed_beta") failing = t.fails + t.error;
  EXPECT_GT(failing, 3);  // more than the report keeps as examples: every one is a scene
  EXPECT_EQ(scenes, failing);
}

TEST(BatchSweep, ShardsOfAFailingSweepMergeToTheExamplesOfOneRun) {
  // Each shard keeps its own first examples; the merge must pick the whole sweep's first ones.
  const std::string dir = fresh_dir("sweep_merge_examples");
  const auto catalogue = failing_catalogue();
  BatchSweepOptions whole = batch_options(dir + "/whole.jsonl");
  whole.sweep = small_sweep();
  const BatchSweepResult one = run_batch_sweep(catalogue, whole);
  std::vector<std::string> files;
  for (int k = 1; k <= 4; ++k) {
    BatchSweepOptions s = whole;
    s.shard = {k, 4};
    s.jobs = 2;
    s.out = dir + "/s" + std::to_string(k) + ".jsonl";
    files.push_back(s.out);
    ASSERT_EQ(run_batch_sweep(catalogue, s).status, BatchSweepResult::Status::Complete);
  }
  const SweepReport merged = merge_sweep_files(catalogue, files, dir + "/merged.jsonl", "", kExitStatus);
  EXPECT_EQ(read_file(dir + "/merged.jsonl"), read_file(whole.out));
  SweepReport a = one.report, b = merged;
  a.seconds = b.seconds = 0;
  EXPECT_EQ(to_json(a, 1), to_json(b, 1));
  EXPECT_EQ(a.unexpected.size(), 3u);
}

TEST(BatchSweep, KilledWorkerStopsTheRunAndResumeCompletes) {
  const std::string dir = fresh_dir("sweep_worker_kill");
  BatchSweepOptions o = batch_options(dir + "/r.jsonl");
  o.sweep = small_sweep();
  o.sweep.n_max = 8;
  o.jobs = 2;
  // A worker killed before it writes anything: the parent gets the first case from worker 1,
  // then learns how worker 2 ended.
  const std::vector<long> cases = shard_cases(o.sweep, o.shard);
  {
    WorkerPool pool(2, cases, [&](long k) {
      if (k != cases[0]) ::pause();  // only the first case ever finishes
      return std::to_string(k);
    });
    ::kill(pool.pids()[1], SIGKILL);
    EXPECT_EQ(*pool.next().line, "0");
    const WorkerPool::Next second = pool.next();
    EXPECT_FALSE(second.line);
    EXPECT_NE(second.failure.find("killed by signal 9"), std::string::npos) << second.failure;
  }
  const auto catalogue = dijksman1966::catalogue();
  BatchSweepOptions ref = o;
  ref.jobs = 1;
  ref.out = dir + "/ref.jsonl";
  ASSERT_EQ(run_batch_sweep(catalogue, ref).status, BatchSweepResult::Status::Complete);
  // A file cut after 4 cases, as a dead worker leaves it, resumes to the reference bytes.
  const std::string full = read_file(ref.out);
  size_t cut = 0;
  for (int i = 0; i < 4; ++i) cut = full.find('\n', cut) + 1;
  std::ofstream(o.out, std::ios::binary) << full.substr(0, cut);
  o.resume = true;
  const BatchSweepResult r = run_batch_sweep(catalogue, o);
  EXPECT_EQ(r.cases_resumed, 4);
  EXPECT_EQ(read_file(o.out), full);
}

TEST(BatchSweep, DoubleArithmeticGivesTheBytesOfOneRun) {
  const std::string dir = fresh_dir("sweep_double");
  const auto catalogue = dijksman1966::catalogue();
  BatchSweepOptions one = batch_options(dir + "/one.jsonl");
  one.sweep = small_sweep(Arithmetic::Double);
  ASSERT_EQ(run_batch_sweep(catalogue, one).status, BatchSweepResult::Status::Complete);
  BatchSweepOptions two = one;
  two.jobs = 2;
  two.out = dir + "/two.jsonl";
  ASSERT_EQ(run_batch_sweep(catalogue, two).status, BatchSweepResult::Status::Complete);
  // Every process compiles the same tape and evaluates claims in the same canonical form
  // (symbolic/canonical_form.h; GiNaC's own trees depend on addresses and on the symbol serials
  // of the process), so double evidence (values, tolerances, bounds) is the same bytes whatever
  // the number of workers.
  EXPECT_EQ(read_file(one.out), read_file(two.out));
}

TEST(ProgressBar, ShowsCasesRateEtaAndFailures) {
  const std::string line = ProgressBar::render(25, 100, 5.0, 2);
  EXPECT_NE(line.find("25/100 cases"), std::string::npos) << line;
  EXPECT_NE(line.find("25%"), std::string::npos) << line;
  EXPECT_NE(line.find("5.0 cases/s"), std::string::npos) << line;
  EXPECT_NE(line.find("ETA 0:00:15"), std::string::npos) << line;
  EXPECT_NE(line.find("failures 2"), std::string::npos) << line;
  EXPECT_NE(line.find("|#####               |"), std::string::npos) << line;
}

}  // namespace
}  // namespace linkproof::test
