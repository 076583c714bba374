#include "batch/batch_run.h"

#include <memory>
#include <new>
#include <optional>

#include <fmt/format.h>

#include "batch/interrupt.h"
#include "batch/progress_bar.h"
#include "batch/worker_pool.h"
#include "core/time_budget.h"

namespace linkproof {

std::vector<long> shard_case_numbers(long size, const Shard& shard) {
  std::vector<long> cases;
  for (long k = shard.k - 1; k < size; k += shard.n) cases.push_back(k);
  return cases;
}

BatchRun run_batch(BatchJob& job, const BatchRunOptions& o, const std::vector<long>& cases) {
  BatchRun result;

  // Read back what an earlier run completed, then append.
  std::unique_ptr<ResultFile> file;
  size_t position = 0;
  std::optional<std::string> summary;
  long summary_number = 0;
  if (!o.out.empty()) {
    file = std::make_unique<ResultFile>(o.out, o.resume, [&](const std::string& text, long number) {
      if (summary) throw InputError(o.out, fmt::format("line {}", number), "follows the summary line");
      if (job.read(text, o.out, number)) {
        summary = text;
        summary_number = number;
        return;
      }
      if (position >= cases.size())
        throw InputError(o.out, fmt::format("line {}", number), "more cases than this sweep has");
      job.take_read_back(text, cases[position], o.out, number);
      ++position;
    });
    result.cases_resumed = static_cast<long>(position);
  }
  job.set_file(file.get());
  if (summary) {
    if (position != cases.size() || *summary != job.summary_line(o.shard))
      throw InputError(o.out, fmt::format("line {}", summary_number),
                       "the summary line does not match the cases above it (a file of another sweep, or edited)");
    result.already_complete = true;
  }

  // Compute the rest, in this process or in workers, and take the cases in case order.
  const std::vector<long> rest(cases.begin() + static_cast<long>(position), cases.end());
  ProgressBar bar(o.progress, static_cast<long>(cases.size()), static_cast<long>(position));
  const InterruptGuard guard;
  const auto taken = [&] {
    ++result.cases_run;
    bar.update(job.cases_done(), job.unexpected_cases());
  };
  if (o.jobs <= 1 || rest.size() <= 1) {
    for (long k : rest) {
      if (interrupt_signal() != 0 || TimeBudget::expired()) break;
      job.run_case(k);
      taken();
    }
  } else if (!rest.empty()) {
    WorkerPool pool(o.jobs, rest, [&](long k) { return job.case_line(k); });
    for (size_t i = 0; i < rest.size(); ++i) {
      if (TimeBudget::expired()) break;
      WorkerPool::Next next = pool.next();
      // A worker's allocation failure is the run's, as in one process: the caller reports the
      // memory budget (every completed case is in the result file).
      if (next.out_of_memory) throw std::bad_alloc();
      if (!next.line) {
        if (next.signal == 0) {
          result.status = BatchRun::Status::WorkerFailed;
          result.message = next.failure;
        }
        break;
      }
      job.take_worker_line(*next.line, rest[i], static_cast<long>(i + 1));
      taken();
    }
  }
  bar.finish(job.cases_done(), job.unexpected_cases());

  const long done = job.cases_done();
  if (result.status == BatchRun::Status::Complete && interrupt_signal() != 0 && done < static_cast<long>(cases.size())) {
    result.status = BatchRun::Status::Interrupted;
    result.signal = interrupt_signal();
    result.message = fmt::format("interrupted by signal {} after {} of {} cases", result.signal, done, cases.size());
  }
  if (result.status == BatchRun::Status::Complete && TimeBudget::expired() && done < static_cast<long>(cases.size())) {
    result.status = BatchRun::Status::OutOfTime;
    result.message = fmt::format("stopped by the time budget of {} s after {} of {} cases",
                                 TimeBudget::limit_seconds(), done, cases.size());
  }
  if (result.status == BatchRun::Status::Complete && file && !summary) file->append(job.summary_line(o.shard));
  return result;
}

}  // namespace linkproof
