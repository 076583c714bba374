// A sweep run as a batch job: worker processes, a streaming result file that survives
// interruption, shards, replayable scenes of failing cases, a progress bar.
//
//   BatchSweepOptions o;  o.sweep = ...;  o.jobs = 4;  o.out = "sweep.jsonl";  o.resume = true;
//   BatchSweepResult r = run_batch_sweep(dijksman1966::catalogue(), o);
//
// Whatever the number of jobs, the shard, or how often the run was interrupted and resumed,
// the cases are folded in case order (check/sweep_tally.h), so the report and the result file
// are the same bytes as those of one uninterrupted single-process run (the report's `seconds`
// excepted: it is the time of this run). Result file format: report/sweep_lines.h. The batch
// machinery is batch/batch_run.h's; the polygon cases are batch/polygon_sweep_job.h's.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "batch/batch_run.h"
#include "check/sweep.h"
#include "report/sweep_lines.h"

namespace linkproof {

struct BatchSweepOptions : BatchRunOptions {
  SweepOptions sweep;
  std::string scenes_dir;     ///< write each case with an unexpected outcome here as a scene
  /// The exit status the result file's summary line records (report/sweep_lines.h): required
  /// with `out`.
  SweepExitStatus exit_status;
};

/// How the run ended (batch/batch_run.h) and the report of every case done, read back or
/// computed.
struct BatchSweepResult : BatchRun {
  SweepReport report;
};

/// Runs (or continues) the sweep. InputError for a bad `out` or `scenes_dir` path (fields "result
/// file" and "scene directory": the quantities; the command line names its options), or a result file that
/// belongs to another sweep (different seed, n, count, arithmetic or shard), is corrupt or was
/// edited (every line read back is checked: report/sweep_lines.h, check_case_identity); a
/// ResultFileExists for a non-empty `out` without `resume`. std::bad_alloc when an allocation
/// fails, in this process or in a worker (the result file keeps every completed case).
BatchSweepResult run_batch_sweep(const std::vector<Claim>& catalogue, const BatchSweepOptions& options);

/// The cases of `shard` in case order.
std::vector<long> shard_cases(const SweepOptions& o, const Shard& shard);

/// Writes case c as a scene `<dir>/<name>.yaml` (io/sweep_scene.h); InputError on failure.
void write_sweep_scene(const std::string& dir, const SweepCase& c);

}  // namespace linkproof
