// `linkproof merge`: the result files of the N shards of a sweep (`sweep --shard K/N --out ...`)
// combined into the result file and report of the whole sweep, the same bytes a single run
// writes. Shard K holds the cases k with k mod N = K - 1, so case k is the next line of shard
// (k mod N) + 1: the merge streams, holding one line per shard at a time.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "batch/batch_job.h"
#include "check/sweep.h"
#include "report/sweep_lines.h"

namespace linkproof {

/// The sweep a summary line describes (seed, n range, count per n, arithmetic) and its shard.
/// InputError naming `file` and the field when something is missing or malformed.
std::pair<SweepOptions, Shard> sweep_of_summary(const nlohmann::json& summary, const std::string& file);

/// The shard a summary line names ("shard": "K/N"; absent: the whole sweep), or an InputError
/// naming `file` and summary.shard.
Shard shard_of_summary(const nlohmann::json& summary, const std::string& file);

/// Folds the `size` cases of the `shards` shards of a sweep into `job` in case order:
/// `next_line(s)` returns the next line of shard s + 1 (nullopt at its end) and `source(s)` names
/// it for errors. Writes the whole sweep's result file to `out` (must not exist, or be empty;
/// "": no file). Each shard must end with its summary line; every case line is checked by the
/// job (BatchJob::take_merged).
void merge_batch_lines(BatchJob& job, long size, int shards,
                       const std::function<std::optional<std::string>(int)>& next_line,
                       const std::function<std::string(int)>& source, const std::string& out);

/// The last line of a shard's file parsed: its summary object, or nullopt if it is a case line
/// (InputError naming the file if it is neither).
using SummaryOf = std::function<std::optional<nlohmann::json>(const std::string& line, const std::string& file)>;
/// The sweep a summary describes, as a key equal for the shards of one sweep, and its shard.
using SweepOf = std::function<std::pair<std::string, Shard>(const nlohmann::json& summary, const std::string& file)>;
/// The files of shards 1..N of one sweep, given in any order, in shard order. InputError naming
/// the file for an incomplete shard (no summary line), a shard of another sweep, a shard given
/// twice, or a missing shard.
std::vector<std::string> shard_files_in_order(const std::vector<std::string>& files, const SummaryOf& summary_of,
                                              const SweepOf& sweep_of);
/// merge_batch_lines over `shard_files` (in shard order).
void merge_batch_files(BatchJob& job, long size, const std::vector<std::string>& shard_files, const std::string& out);

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
