// The cases of a polygon sweep (`linkproof sweep --n A..B`) as a batch job (batch/batch_job.h):
// case k is the random polygon (seed, n, index) of case number k (check/sweep.h, SweepPlan),
// checked against every claim of the catalogue that applies at n; its line is
// report/sweep_lines.h's, and the cases go to a CaseSink (the report, the result file, the
// scenes of unexpected outcomes).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "batch/batch_job.h"
#include "batch/batch_sweep.h"
#include "batch/case_sink.h"

namespace linkproof {

class PolygonSweepJob final : public BatchJob {
 public:
  /// `catalogue` and `o` must outlive the job. Only o.sweep, o.scenes_dir and o.exit_status are
  /// used.
  PolygonSweepJob(const std::vector<Claim>& catalogue, const BatchSweepOptions& o);

  void set_file(ResultFile* file) override { sink_.set_file(file); }
  void run_case(long k) override;
  std::string case_line(long k) override;
  void take_worker_line(const std::string& line, long k, long i) override;
  bool read(const std::string& line, const std::string& file, long number) override;
  void take_read_back(const std::string& line, long k, const std::string& file, long number) override;
  void take_merged(long k, const std::string& file, const std::string& where) override;
  std::string summary_line(const Shard& shard) const override;
  long cases_done() const override { return sink_.tally().cases(); }
  long unexpected_cases() const override { return sink_.tally().unexpected_cases(); }

  /// The report of the cases taken (its `seconds` 0).
  SweepReport report() const { return sink_.tally().report(); }

 private:
  SweepCase compute(long k);
  void take(SweepCase& c);

  const std::vector<Claim>& catalogue_;
  const BatchSweepOptions& o_;
  CaseSink sink_;
  std::optional<GroundTruthEngine> engine_;  // in a worker: built after fork()
  SweepLine pending_;                        // the line read() parsed
};

}  // namespace linkproof
