// A sweep as a batch job over numbered cases, whatever its cases are (random polygons:
// batch/batch_sweep.h; configurations of a mechanism topology: batch/topology_batch.h).
//
// run_batch (batch/batch_run.h) and merge_batch_lines (batch/merge.h) do what every sweep does
// with its cases: read a result file back (--resume), compute the rest in this process or in
// worker processes, take the cases in case order, stop on SIGINT/SIGTERM or the time budget,
// draw a progress bar, write the summary line; merge the shards' files. A BatchJob says what a
// case is: how it is computed, written as a line, read back from one and counted.
//
// Reading a line back goes in two steps, so that run_batch can check the line's position first:
// read() parses it (a summary line or a case line, kept as the pending case), then one of
// take_read_back() or take_merged() checks the pending case against the case expected and counts
// it.
#pragma once

#include <string>

#include "batch/result_file.h"
#include "report/sweep_lines.h"

namespace linkproof {

class BatchJob {
 public:
  virtual ~BatchJob() = default;

  /// From now on, write the cases taken to `file` (null: nowhere).
  virtual void set_file(ResultFile* file) = 0;

  /// Computes case k and takes it (counts it, writes its line): the one-process path.
  virtual void run_case(long k) = 0;
  /// Computes case k and returns its line: the worker-process path (after fork(); must not write
  /// to the parent's files).
  virtual std::string case_line(long k) = 0;
  /// Takes the line a worker computed for case k, the i-th line (1-based) read from the workers.
  virtual void take_worker_line(const std::string& line, long k, long i) = 0;

  /// Parses a line read from `file` at line `number`: true if it is a summary line (then nothing
  /// is pending), false if a case line (now pending). InputError if it is neither.
  virtual bool read(const std::string& line, const std::string& file, long number) = 0;
  /// The pending case line, read back from this run's own result file (`line`, `file` at
  /// `number`): it must be case k of this sweep and exactly the line this run writes for it;
  /// counted, not written again.
  virtual void take_read_back(const std::string& line, long k, const std::string& file, long number) = 0;
  /// The pending case line, read from a shard's file (`file`, `where`): it must be case k of this
  /// sweep; counted and written.
  virtual void take_merged(long k, const std::string& file, const std::string& where) = 0;

  /// The summary line of the cases taken, for a file of `shard`.
  virtual std::string summary_line(const Shard& shard) const = 0;
  /// Cases taken, and those of them with an unexpected outcome (for the progress bar).
  virtual long cases_done() const = 0;
  virtual long unexpected_cases() const = 0;
};

}  // namespace linkproof
