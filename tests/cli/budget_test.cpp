// The resource budgets of a run (--max-seconds, --max-memory-mb; issue 12, "time budgets that
// hold"): a run past its budget ends with exit 2 and an error naming the option, never with a
// pass or a half report; in the program a watchdog stops a step that never reaches a check point.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>

#include <chrono>
#include <cstdio>
#include <fstream>

#include "batch/sweep_files.h"
#include "dijksman1966.h"
#include "budget_watchdog.h"
#include "support/cli_run.h"

namespace linkproof {
namespace {

using test::CliRun;
using test::run_cli;

std::string write_claim(const std::string& name, const std::string& lhs, const std::string& rhs) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << "claims:\n  - id: heavy\n    source: test\n    statement: s\n    lhs: " << lhs
                      << "\n    rhs: " << rhs << "\n";
  return path;
}

// A true claim whose zero test is one enormous normalisation: (X + Y)^30 = X (X + Y)^29 + Y (X + Y)^29
// with X, Y sums of four coordinates (about 10^7 terms expanded). No check point is reached
// inside it: only the watchdog ends it.
std::string heavy_claim() {
  const std::string x = "vx(r[1]) + vy(r[1]) + vx(r[2]) + vy(r[2])";
  const std::string y = "vx(r[n-2]) + vy(r[n-2]) + vx(r[n-1]) + vy(r[n-1])";
  return write_claim("heavy_claim.yaml", "(" + x + " + " + y + ")^30",
                     "(" + x + ")*(" + x + " + " + y + ")^29 + (" + y + ")*(" + x + " + " + y + ")^29");
}

struct ProgramRun {
  int code = 0;
  std::string out, err;
  double seconds = 0;
};

// The command line run as the program runs it (RunMode::Program: watchdog and memory limit) in a
// forked child whose stdout and stderr go to files, as the watchdog writes to the descriptors.
ProgramRun run_program(const std::vector<std::string>& args) {
  // Named for this process: ctest runs tests in parallel processes that share TempDir().
  const std::string tag = std::to_string(::getpid());
  const std::string out_path = ::testing::TempDir() + "budget_out_" + tag + ".txt",
                    err_path = ::testing::TempDir() + "budget_err_" + tag + ".txt";
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int o = ::open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    const int e = ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    ::dup2(o, STDOUT_FILENO);
    ::dup2(e, STDERR_FILENO);
    std::ostringstream out, err;
    const int code = cli::run(args, out, err, cli::RunMode::Program);
    const std::string o_text = out.str(), e_text = err.str();
    (void)!::write(STDOUT_FILENO, o_text.data(), o_text.size());
    (void)!::write(STDERR_FILENO, e_text.data(), e_text.size());
    ::_exit(code);
  }
  ProgramRun r;
  r.code = test::wait_child(pid);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.out = test::read_file(out_path);
  r.err = test::read_file(err_path);
  return r;
}

TEST(Budget, MaxSecondsMustBeAFiniteNumberOfSeconds) {
  for (const std::string bad : {"nan", "inf", "-1", "1e9", "soon"}) {
    const CliRun r = run_cli({"count", "--n", "4", "--max-seconds", bad});
    EXPECT_EQ(r.code, 2) << bad;
    EXPECT_NE(r.err.find("--max-seconds"), std::string::npos) << bad << ": " << r.err;
  }
}

TEST(Budget, OptionsAreAcceptedBeforeAndAfterTheSubcommand) {
  EXPECT_EQ(run_cli({"--max-seconds", "600", "count", "--n", "4"}).code, 0);
  EXPECT_EQ(run_cli({"count", "--n", "4", "--max-seconds", "600", "--max-memory-mb", "4096"}).code, 0);
}

TEST(Budget, ProveOutOfTimeIsExitTwoNamingTheOptionNeverAProof) {
  const CliRun r = run_cli({"prove", "--claim", "eq22", "--max-seconds", "1e-9", "--json"});
  EXPECT_EQ(r.code, 2) << r.out << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["error"]["field"], "--max-seconds") << r.out;
  EXPECT_NE(j["error"]["message"].get<std::string>().find("per-n proof of dijksman1966.eq22"), std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("proved"), std::string::npos) << r.out;
}

TEST(Budget, CountOutOfTimeIsExitTwo) {
  const CliRun r = run_cli({"count", "--n", "3..60", "--max-seconds", "1e-9"});
  EXPECT_EQ(r.code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("the count at n = 3"), std::string::npos) << r.err;
}

// A sweep stops between cases, keeps every complete case in its result file, and --resume (no
// budget) finishes it with nothing lost and nothing counted twice.
TEST(Budget, SweepStopsBetweenCasesAndResumes) {
  const std::string out = ::testing::TempDir() + "budget_sweep.jsonl";
  std::remove(out.c_str());
  const std::vector<std::string> sweep = {"sweep", "--n", "5", "--count", "400", "--jobs", "1", "--out", out};
  std::vector<std::string> first = sweep;
  first.insert(first.end(), {"--max-seconds", "0.05", "--json"});
  const CliRun stopped = run_cli(first);
  EXPECT_EQ(stopped.code, 2) << stopped.err;
  EXPECT_NE(stopped.err.find("stopped by the time budget"), std::string::npos) << stopped.err;
  EXPECT_EQ(nlohmann::json::parse(stopped.out)["error"]["field"], "--max-seconds") << stopped.out;
  const long kept = test::count_lines(out);
  EXPECT_LT(kept, 400);

  std::vector<std::string> resume = sweep;
  resume.insert(resume.end(), {"--resume", "--json"});
  const CliRun resumed = run_cli(resume);
  EXPECT_EQ(resumed.code, 0) << resumed.err;
  EXPECT_EQ(test::count_lines(out), 401);  // 400 cases and the summary
}

TEST(Budget, WatchdogGraceIsFivePercentBetweenOneAndThirtySeconds) {
  EXPECT_EQ(cli::watchdog_grace_seconds(2), 1.0);
  EXPECT_EQ(cli::watchdog_grace_seconds(100), 5.0);
  EXPECT_EQ(cli::watchdog_grace_seconds(3600), 30.0);
}

// The heavy claim's first symbolic step never reaches a check point: the watchdog ends the
// program 1 s (the grace) after a 1 s budget with the error as one JSON object, exit 2.
TEST(Budget, WatchdogStopsAStepThatNeverReachesACheckPoint) {
  const ProgramRun r = run_program({"check-claim", heavy_claim(), "--max-seconds", "1", "--max-memory-mb", "0", "--json"});
  EXPECT_EQ(r.code, 2) << r.out << r.err;
  EXPECT_LT(r.seconds, 10.0);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["error"]["field"], "--max-seconds") << r.out;
  EXPECT_EQ(j["exit_status"], 2);
  EXPECT_NE(r.err.find("time budget of 1 s exceeded"), std::string::npos) << r.err;
}

// Under a 1 MiB address-space limit (below what the program already maps) the first large
// allocation fails: it is reported as the memory budget (exit 2, one JSON object), not a crash
// and not an internal error. The check is of a 40-gon, not of a small bundled scene: run after
// other tests in the same process (a gtest filter), the forked child inherits their freed heap,
// which served a hexagon's few allocations without growing the address space (exit 0).
TEST(Budget, MemoryLimitEndsTheRunWithExitTwo) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space: no RLIMIT_AS under it";
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space: no RLIMIT_AS under it";
#endif
#endif
  std::string joints, rates;
  for (int i = 0; i < 40; ++i) joints += (i ? ", [" : "[") + std::to_string(i) + ", " + std::to_string(i * i) + "]";
  for (int j = 0; j < 37; ++j) rates += (j ? ", " : "") + std::string("1");
  const std::string scene = ::testing::TempDir() + "budget_40gon.yaml";
  std::ofstream(scene) << "name: big\npolygon:\n  joints: [" << joints << "]\n  omega: [" << rates
                       << "]\n  omega_dot: [" << rates << "]\n";
  const ProgramRun r = run_program({"check", scene, "--max-memory-mb", "1", "--json"});
  EXPECT_EQ(r.code, 2) << r.out << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["error"]["field"], "--max-memory-mb") << r.out;
  EXPECT_NE(r.err.find("memory budget of 1 MiB exceeded"), std::string::npos) << r.err;
}

// The address space of this process in MiB (VmSize), what a forked child starts with.
long address_space_mib() {
  std::ifstream status("/proc/self/status");
  std::string key;
  long kib = 0;
  while (status >> key) {
    if (key == "VmSize:") {
      status >> kib;
      break;
    }
  }
  return kib / 1024;
}

// A sweep worker inherits the memory budget; an allocation past it failed the run as an
// internal error (exit 3, "worker 1 failed on case 0: std::bad_alloc") where one process
// reports the budget (exit 2). The budget leaves the parent room for its own small work (the
// catalogue is built before the limit) but not a case at n = kHeavyN.
TEST(Budget, SweepWorkerPastTheMemoryBudgetIsExitTwoAsInOneProcess) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space: no RLIMIT_AS under it";
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space: no RLIMIT_AS under it";
#endif
#endif
  constexpr int kHeavyN = 200;
  (void)dijksman1966::catalogue();
  const std::string budget = std::to_string(address_space_mib() + 16);
  for (const char* jobs : {"1", "2"}) {
    SCOPED_TRACE(std::string("--jobs ") + jobs);
    const ProgramRun r = run_program({"sweep", "--n", std::to_string(kHeavyN), "--count", "2", "--jobs", jobs,
                                      "--max-memory-mb", budget, "--json"});
    EXPECT_EQ(r.code, 2) << r.out << r.err;
    const auto j = nlohmann::json::parse(r.out, nullptr, false);
    ASSERT_FALSE(j.is_discarded()) << r.out << r.err;
    EXPECT_EQ(j["error"]["field"], "--max-memory-mb") << r.out;
    EXPECT_NE(r.err.find("memory budget of " + budget + " MiB exceeded"), std::string::npos) << r.err;
  }
}

}  // namespace
}  // namespace linkproof
