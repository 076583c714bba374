#include "batch/batch_sweep.h"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <new>
#include <optional>

#include <fmt/format.h>

#include "batch/case_sink.h"
#include "batch/interrupt.h"
#include "core/time_budget.h"
#include "batch/progress_bar.h"
#include "batch/worker_pool.h"
#include "io/sweep_scene.h"

namespace linkproof {

std::vector<long> shard_cases(const SweepOptions& o, const Shard& shard) {
  std::vector<long> cases;
  const long size = SweepPlan(o).size();
  for (long k = shard.k - 1; k < size; k += shard.n) cases.push_back(k);
  return cases;
}

void write_sweep_scene(const std::string& dir, const SweepCase& c) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  const std::string path = (std::filesystem::path(dir) / (sweep_scene_name(c.polygon) + ".yaml")).string();
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  f << sweep_scene_yaml(c.polygon);
  f.close();
  if (!f) throw InputError(path, "scene directory", "cannot write the scene file");
}


BatchSweepResult run_batch_sweep(const std::vector<Claim>& catalogue, const BatchSweepOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  BatchSweepResult result;
  const std::vector<long> cases = shard_cases(o.sweep, o.shard);
  if (!o.scenes_dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(o.scenes_dir, ec);
    if (ec) throw InputError(o.scenes_dir, "scene directory", "cannot create the directory: " + ec.message());
  }

  // Read back what an earlier run completed, then append.
  std::unique_ptr<ResultFile> file;
  auto sink = std::make_unique<CaseSink>(catalogue, o.sweep, nullptr, o.scenes_dir);
  size_t position = 0;
  std::optional<std::string> summary;
  long summary_number = 0;
  LINKPROOF_ASSERT(o.out.empty() || o.exit_status, "a result file's summary line needs the exit status");
  if (!o.out.empty()) {
    file = std::make_unique<ResultFile>(o.out, o.resume, [&](const std::string& text, long number) {
      if (summary) throw InputError(o.out, fmt::format("line {}", number), "follows the summary line");
      SweepLine line = parse_sweep_line(text, o.out, number);
      if (line.summary) {
        summary = text;
        summary_number = number;
        return;
      }
      if (position >= cases.size())
        throw InputError(o.out, fmt::format("line {}", number), "more cases than this sweep has");
      check_case_identity(line, cases[position], o.sweep, catalogue, o.out, fmt::format("line {}", number));
      sink->add(*line.sweep_case, false, o.out, fmt::format("line {}", number));
      // The line must be the very line this run writes for the case: the evidence the report
      // keeps and no other (add() trimmed the case to it), nothing added or reordered.
      if (sweep_case_line(*line.sweep_case, o.sweep.arithmetic) != text)
        throw InputError(o.out, fmt::format("line {}", number),
                         fmt::format("is not the line this sweep writes for case {}: it holds evidence the report "
                                     "does not keep (a line of another shard or sweep, or edited)",
                                     line.sweep_case->k));
      ++position;
    });
    result.cases_resumed = static_cast<long>(position);
  }
  sink->set_file(file.get());
  if (summary) {
    if (position != cases.size() || *summary != sweep_summary_line(sink->tally().report(), o.shard, o.exit_status(sink->tally().report())))
      throw InputError(o.out, fmt::format("line {}", summary_number),
                       "the summary line does not match the cases above it (a file of another sweep, or edited)");
    result.already_complete = true;
  }

  // Compute the rest, in this process or in workers, and take the cases in case order.
  const std::vector<long> rest(cases.begin() + static_cast<long>(position), cases.end());
  ProgressBar bar(o.progress, static_cast<long>(cases.size()), static_cast<long>(position));
  const InterruptGuard guard;
  auto take = [&](SweepCase& c) {
    sink->add(c, true, "<sweep>", fmt::format("case {}", c.k));
    ++result.cases_run;
    bar.update(sink->tally().cases(), sink->tally().unexpected_cases());
  };
  if (o.jobs <= 1 || rest.size() <= 1) {
    std::optional<GroundTruthEngine> engine;
    for (long k : rest) {
      if (interrupt_signal() != 0 || TimeBudget::expired()) break;
      if (!engine) engine.emplace();
      SweepCase c = run_sweep_case(*engine, catalogue, o.sweep, k);
      take(c);
    }
  } else if (!rest.empty()) {
    std::optional<GroundTruthEngine> engine;  // built in each worker, after fork()
    WorkerPool pool(o.jobs, rest, [&](long k) {
      if (!engine) engine.emplace();
      SweepCase c = run_sweep_case(*engine, catalogue, o.sweep, k);
      return sweep_case_line(c, o.sweep.arithmetic);
    });
    for (size_t i = 0; i < rest.size(); ++i) {
      if (TimeBudget::expired()) break;
      WorkerPool::Next next = pool.next();
      // A worker's allocation failure is the run's, as in one process: the caller reports the
      // memory budget (every completed case is in the result file).
      if (next.out_of_memory) throw std::bad_alloc();
      if (!next.line) {
        if (next.signal == 0) {
          result.status = BatchSweepResult::Status::WorkerFailed;
          result.message = next.failure;
        }
        break;
      }
      SweepLine line = parse_sweep_line(*next.line, "<worker>", static_cast<long>(i + 1));
      take(*line.sweep_case);
    }
  }
  bar.finish(sink->tally().cases(), sink->tally().unexpected_cases());

  const long done = sink->tally().cases();
  if (result.status == BatchSweepResult::Status::Complete && interrupt_signal() != 0 &&
      done < static_cast<long>(cases.size())) {
    result.status = BatchSweepResult::Status::Interrupted;
    result.signal = interrupt_signal();
    result.message = fmt::format("interrupted by signal {} after {} of {} cases", result.signal, done, cases.size());
  }
  if (result.status == BatchSweepResult::Status::Complete && TimeBudget::expired() &&
      done < static_cast<long>(cases.size())) {
    result.status = BatchSweepResult::Status::OutOfTime;
    result.message = fmt::format("stopped by the time budget of {} s after {} of {} cases",
                                 TimeBudget::limit_seconds(), done, cases.size());
  }
  if (result.status == BatchSweepResult::Status::Complete && file && !summary)
    file->append(sweep_summary_line(sink->tally().report(), o.shard, o.exit_status(sink->tally().report())));
  result.report = sink->tally().report();
  result.report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace linkproof
