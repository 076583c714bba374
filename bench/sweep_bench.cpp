// BM_SweepThroughput/jobs: a whole exact sweep (every claim of the catalogue on 64 random
// polygons, n = 5..8, 16 per n) through run_batch_sweep with 1 or 2 worker processes, in cases
// per second of wall time (the work is in child processes, so CPU time of this process says
// nothing: real time is used). The ratio jobs=2 / jobs=1 is the parallel speed-up on this
// machine (at most the number of idle cores). Fork and engine set-up per worker are included.
#include <benchmark/benchmark.h>

#include "dijksman1966.h"
#include "batch/batch_sweep.h"

namespace linkproof::bench {
namespace {

void BM_SweepThroughput(benchmark::State& state) {
  BatchSweepOptions o;
  o.sweep.n_min = 5;
  o.sweep.n_max = 8;
  o.sweep.count = 16;
  o.sweep.seed = 3;
  o.jobs = static_cast<int>(state.range(0));
  const auto catalogue = dijksman1966::catalogue();
  long cases = 0;
  for (auto _ : state) {
    const BatchSweepResult r = run_batch_sweep(catalogue, o);
    if (r.status != BatchSweepResult::Status::Complete || r.report.errors() + r.report.unexpected_failures() != 0) {
      state.SkipWithError("the sweep did not complete as expected");
      break;
    }
    cases += r.report.cases;
  }
  state.counters["cases_per_s"] = benchmark::Counter(static_cast<double>(cases), benchmark::Counter::kIsRate);
}

BENCHMARK(BM_SweepThroughput)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace linkproof::bench
