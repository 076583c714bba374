// The linkproof command line, callable in-process (the tests run it this way).
//   linkproof check SCENE [--arith exact|double|long-double] [--json] [--no-terms]
//   linkproof sweep --n 4..12 --count N --seed S [--arith ...] [--index I] [--json]
//                   [--jobs N] [--out FILE [--resume]] [--shard K/N] [--scenes DIR]
//   linkproof merge --out FILE SHARD_FILE... [--scenes DIR] [--json]
//   linkproof count --n N|A..B [--json]   |   linkproof count --eightbar [--polygons ...] [--json]
// Exit codes: 0 every claim as expected, 1 a claim expected to hold failed, 2 bad input,
// 3 internal error.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace linkproof::cli {

enum ExitCode { kAsExpected = 0, kClaimFailed = 1, kBadInput = 2, kInternalError = 3 };

/// How run() enforces the resource budgets (--max-seconds, --max-memory-mb; docs/limits.md).
///   InProcess  the time budget is cooperative (TimeBudget::check); no memory limit and no
///              watchdog, so a test or a library caller is never killed;
///   Program    the linkproof executable: also a watchdog thread that ends the process (exit 2,
///              the error printed) shortly after the deadline, and RLIMIT_AS for the memory.
enum class RunMode { InProcess, Program };

/// args excludes the program name.
int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
        RunMode mode = RunMode::InProcess);

/// The command line parsed and validated without running the work (what the CLI fuzz target
/// exercises): the exit code run() would return for a bad or finished command line (help,
/// version, unknown subcommand, invalid option), or nullopt when the subcommand would run.
std::optional<int> parse_only(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace linkproof::cli
