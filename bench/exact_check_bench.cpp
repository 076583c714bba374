// BM_ExactCheckAllClaims/n: the library's main entry point, check_polygon over the whole
// Dijksman (1966) catalogue in exact arithmetic, in polygons per second. Derivations (n-side
// motion and coefficient tapes, and the n = 4 tape used for each four-bar j) are made before
// timing: they are a once-per-process cost, measured by BM_SymbolicDerivation.
#include <benchmark/benchmark.h>

#include "bench_cases.h"
#include "dijksman1966.h"
#include "linkproof/check/check.h"

namespace linkproof::bench {
namespace {

void BM_ExactCheckAllClaims(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto& cases = make_cases(n, 64);
  state.SetLabel(families(cases));
  const auto& catalogue = dijksman1966::catalogue();
  GroundTruthEngine engine;
  engine.derivation(n);
  engine.coefficient_tape(n);
  engine.derivation(4);

  size_t k = 0, unexpected = 0;
  for (auto _ : state) {
    const RandomPolygonCase& c = cases[k++ % cases.size()];
    PolygonCheck r = check_polygon(engine, catalogue, "bench", c.polygon, c.rates, Arithmetic::Exact);
    unexpected += exit_status(r) != 0;
    benchmark::DoNotOptimize(r);
  }
  // A timing of a check that went wrong would measure the wrong work: say so in the table.
  if (unexpected != 0) state.SkipWithError("a claim did not verify as expected on a benchmark case");
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
  state.counters["claims"] = benchmark::Counter(static_cast<double>(catalogue.size()));
}

BENCHMARK(BM_ExactCheckAllClaims)->Arg(5)->Arg(12)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace linkproof::bench
