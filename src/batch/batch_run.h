// Runs (or continues) a batch job (batch/batch_job.h) over the cases of one shard: what
// `linkproof sweep` does for polygons and for mechanism topologies alike.
//
// The result file is read back first (every line checked by the job; a partial last line cut
// off), then the remaining cases are computed, in this process (`jobs` 1) or by worker processes
// (batch/worker_pool.h), and taken in case order: the file and the job's tally are those of one
// uninterrupted single-process run. SIGINT/SIGTERM and the time budget stop the run after the
// line being written; the summary line is written only when every case is done.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "batch/batch_job.h"

namespace linkproof {

/// How a batch job is run, whatever its cases are: the options every sweep (polygons, a
/// topology) takes, extended by each sweep's own (batch/batch_sweep.h, batch/topology_sweep_job.h).
struct BatchRunOptions {
  int jobs = 1;                      ///< worker processes; 1 runs in this process
  Shard shard;                       ///< run only this shard's cases; written into the summary line
  std::string out;                   ///< result file (JSON Lines); empty: none
  bool resume = false;               ///< continue `out` from its last complete case
  std::ostream* progress = nullptr;  ///< progress bar target (a terminal), or null
};

struct BatchRun {
  enum class Status { Complete, Interrupted, OutOfTime, WorkerFailed };
  Status status = Status::Complete;
  int signal = 0;          ///< Interrupted: the signal
  std::string message;     ///< not Complete: what happened (how to continue is the caller's to say)
  long cases_resumed = 0;  ///< cases read back from the result file
  long cases_run = 0;      ///< cases computed by this run
  bool already_complete = false;  ///< the result file already held the summary line
};

/// Runs the job. InputError for a bad `out` (field "result file"), a line the job refuses, a
/// line after the summary, more cases than the shard has, or a summary line that does not match
/// the cases above it; ResultFileExists for a non-empty `out` without `resume`; std::bad_alloc
/// when an allocation fails in this process or in a worker.
/// `cases`: those of options.shard, in case order.
BatchRun run_batch(BatchJob& job, const BatchRunOptions& options, const std::vector<long>& cases);

/// The cases k of `shard` among 0..size-1 (k mod N = K - 1), in case order.
std::vector<long> shard_case_numbers(long size, const Shard& shard);

}  // namespace linkproof
