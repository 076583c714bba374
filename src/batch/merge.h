// `linkproof merge`: the result files of the N shards of a sweep (`sweep --shard K/N --out ...`)
// combined into the result file and report of the whole sweep, the same bytes a single run
// writes. Shard K holds the cases k with k mod N = K - 1, so case k is the next line of shard
// (k mod N) + 1: the merge streams, holding one line per shard at a time.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "check/sweep.h"
#include "report/sweep_lines.h"

namespace linkproof {

/// The sweep a summary line describes (seed, n range, count per n, arithmetic) and its shard.
/// InputError naming `file` and the field when something is missing or malformed.
std::pair<SweepOptions, Shard> sweep_of_summary(const nlohmann::json& summary, const std::string& file);

/// Folds the cases of `shards` shards of sweep `o` in case order. `next_line(s)` returns the
/// next line of shard s + 1 (nullopt at its end) and `source(s)` names it for errors. Writes the
/// whole sweep's result file to `out` (must not exist, or be empty; "": no file) and the scenes of cases with
/// unexpected outcomes to `scenes_dir` (empty: none). Each shard must end with its summary line.
/// `exit_status`: what the written summary line records (report/sweep_lines.h).
SweepReport merge_shard_lines(const std::vector<Claim>& catalogue, const SweepOptions& o, int shards,
                              const std::function<std::optional<std::string>(int)>& next_line,
                              const std::function<std::string(int)>& source, const std::string& out,
                              const std::string& scenes_dir, const SweepExitStatus& exit_status);

/// merge_shard_lines over the result files of every shard, in any order: they must be the
/// complete shards 1..N of one sweep.
SweepReport merge_sweep_files(const std::vector<Claim>& catalogue, const std::vector<std::string>& files,
                              const std::string& out, const std::string& scenes_dir, const SweepExitStatus& exit_status);

}  // namespace linkproof
