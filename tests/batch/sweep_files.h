// Test support for sweeps that run as batch jobs: fresh directories, files read whole, reports
// without their run time, and the CLI run in a child process that a test can signal.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "support/cli_run.h"

namespace linkproof::test {

/// A fresh, empty directory under the test temp dir, private to this process (ctest runs tests
/// in parallel processes that would otherwise share it).
inline std::string fresh_dir(const std::string& name) {
  const auto dir =
      std::filesystem::path(::testing::TempDir()) / ("linkproof_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

inline std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline long count_lines(const std::string& path) {
  const std::string s = read_file(path);
  return static_cast<long>(std::count(s.begin(), s.end(), '\n'));
}

/// `sweep --json` output without the run time, the one field that differs between equal runs.
inline std::string without_seconds(const std::string& json_text) {
  nlohmann::json j = nlohmann::json::parse(json_text);
  j.erase("seconds");
  return j.dump(2);
}

/// A plain single-process run: its result file and its JSON report without the run time, what
/// the other runs of a test must give.
struct Reference {
  std::string file, json;
};
/// Runs the sweep `args` with "--out DIR/ref.jsonl --json" (DIR a fresh directory `name`).
inline Reference reference_run(const std::string& name, std::vector<std::string> args) {
  const std::string dir = fresh_dir(name);
  args.insert(args.end(), {"--out", dir + "/ref.jsonl", "--json"});
  const auto run = run_cli(args);
  EXPECT_EQ(run.code, 0) << run.err;
  return Reference{read_file(dir + "/ref.jsonl"), without_seconds(run.out)};
}

/// The CLI in a forked child (its output discarded); returns the child's pid.
inline pid_t spawn_cli(const std::vector<std::string>& args) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    std::ostringstream out, err;
    const int code = cli::run(args, out, err);
    ::_exit(code);
  }
  return pid;
}

/// Waits for a child; its exit code, or 128 + the signal that killed it.
inline int wait_child(pid_t pid) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFSIGNALED(status) ? 128 + WTERMSIG(status) : WEXITSTATUS(status);
}

/// Waits until `file` holds at least `lines` lines; false if the child `pid` ended first (it is
/// then reaped, and `code` is its exit code).
inline bool wait_for_lines(const std::string& file, long lines, pid_t pid, int& code) {
  while (count_lines(file) < lines) {
    int status = 0;
    if (::waitpid(pid, &status, WNOHANG) == pid) {
      code = WIFSIGNALED(status) ? 128 + WTERMSIG(status) : WEXITSTATUS(status);
      return false;
    }
    ::usleep(1000);
  }
  return true;
}

}  // namespace linkproof::test
