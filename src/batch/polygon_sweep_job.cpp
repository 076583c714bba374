#include "batch/polygon_sweep_job.h"

#include <fmt/format.h>

namespace linkproof {

PolygonSweepJob::PolygonSweepJob(const std::vector<Claim>& catalogue, const BatchSweepOptions& o)
    : catalogue_(catalogue), o_(o), sink_(catalogue, o.sweep, nullptr, o.scenes_dir) {}

SweepCase PolygonSweepJob::compute(long k) {
  if (!engine_) engine_.emplace();
  return run_sweep_case(*engine_, catalogue_, o_.sweep, k);
}

void PolygonSweepJob::take(SweepCase& c) { sink_.add(c, true, "<sweep>", fmt::format("case {}", c.k)); }

void PolygonSweepJob::run_case(long k) {
  SweepCase c = compute(k);
  take(c);
}

std::string PolygonSweepJob::case_line(long k) { return sweep_case_line(compute(k), o_.sweep.arithmetic); }

void PolygonSweepJob::take_worker_line(const std::string& line, long, long i) {
  SweepLine parsed = parse_sweep_line(line, "<worker>", i);
  take(*parsed.sweep_case);
}

bool PolygonSweepJob::read(const std::string& line, const std::string& file, long number) {
  pending_ = parse_sweep_line(line, file, number);
  return pending_.summary.has_value();
}

void PolygonSweepJob::take_read_back(const std::string& text, long k, const std::string& file, long number) {
  const std::string where = fmt::format("line {}", number);
  check_case_identity(pending_, k, o_.sweep, catalogue_, file, where);
  sink_.add(*pending_.sweep_case, false, file, where);
  // The line must be the very line this run writes for the case: the evidence the report keeps
  // and no other (add() trimmed the case to it), nothing added or reordered.
  if (sweep_case_line(*pending_.sweep_case, o_.sweep.arithmetic) != text)
    throw InputError(file, where,
                     fmt::format("is not the line this sweep writes for case {}: it holds evidence the report "
                                 "does not keep (a line of another shard or sweep, or edited)",
                                 pending_.sweep_case->k));
}

void PolygonSweepJob::take_merged(long k, const std::string& file, const std::string& where) {
  check_case_identity(pending_, k, o_.sweep, catalogue_, file, where);
  sink_.add(*pending_.sweep_case, true, file, where);
}

std::string PolygonSweepJob::summary_line(const Shard& shard) const {
  const SweepReport r = sink_.tally().report();
  return sweep_summary_line(r, shard, o_.exit_status(r));
}

}  // namespace linkproof
