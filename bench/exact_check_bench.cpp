// The library's main entry point, check_polygon over the whole Dijksman (1966) catalogue:
//   BM_ExactCheckAllClaims/n   exact, every comparison's evidence kept (as `check`), in polygons
//                              per second;
//   BM_CheckExact/n            one polygon, exact, verdicts and the headlines a sweep keeps as
//                              examples (Evidence::Examples, as `sweep`);
//   BM_CheckDouble/n           the same in `--arith double` (Tracked<double>): the ratio
//                              BM_CheckExact/n over BM_CheckDouble/n is the speed-up of double.
// Derivations (the n-side motion tape and the n = 4 tape used for each four-bar j) are made
// before timing: they are a once-per-process cost, measured by BM_SymbolicDerivation.
#include <benchmark/benchmark.h>

#include <algorithm>

#include "bench_cases.h"
#include "dijksman1966.h"
#include "check/check_polygon.h"

namespace linkproof::bench {
namespace {

void BM_ExactCheckAllClaims(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto& cases = make_cases(n, 64);
  state.SetLabel(families(cases));
  const auto& catalogue = dijksman1966::catalogue();
  GroundTruthEngine engine;
  engine.derivation(n);
  engine.derivation(4);

  size_t k = 0, unexpected = 0;
  for (auto _ : state) {
    const RandomPolygonCase& c = cases[k++ % cases.size()];
    PolygonCheck r = check_polygon(engine, catalogue, "bench", c.polygon, c.rates, Arithmetic::Exact);
    unexpected += std::any_of(r.claims.begin(), r.claims.end(), [](const ClaimOutcome& o) { return !o.is_as_expected(); });
    benchmark::DoNotOptimize(r);
  }
  // A timing of a check that went wrong would measure the wrong work: say so in the table.
  if (unexpected != 0) state.SkipWithError("a claim did not verify as expected on a benchmark case");
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
  state.counters["claims"] = benchmark::Counter(static_cast<double>(catalogue.size()));
}

/// One polygon (the first scattered case of the seed) checked in arithmetic a, as a sweep does.
void check_one(benchmark::State& state, Arithmetic a) {
  const int n = static_cast<int>(state.range(0));
  const RandomPolygonCase& c = make_cases(n, 1).front();
  state.SetLabel(c.family);
  const auto& catalogue = dijksman1966::catalogue();
  GroundTruthEngine engine;
  engine.derivation(n);
  engine.derivation(4);
  size_t unexpected = 0;
  for (auto _ : state) {
    PolygonCheck r = check_polygon(engine, catalogue, "bench", c.polygon, c.rates, a, Evidence::Examples);
    unexpected += std::any_of(r.claims.begin(), r.claims.end(), [](const ClaimOutcome& o) { return !o.is_as_expected(); });
    benchmark::DoNotOptimize(r);
  }
  // Double may be inconclusive where exact is not; only an error or a failed true claim is wrong.
  if (unexpected != 0 && a == Arithmetic::Exact) state.SkipWithError("a claim did not verify as expected");
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
  state.SetComplexityN(n);
}

void BM_CheckExact(benchmark::State& state) { check_one(state, Arithmetic::Exact); }
void BM_CheckDouble(benchmark::State& state) { check_one(state, Arithmetic::Double); }

/// The sizes; n = 1000 once (one iteration is seconds).
void check_sizes(benchmark::internal::Benchmark* b) {
  for (int n : {10, 20, 40, 100}) b->Arg(n);
  b->Unit(benchmark::kMillisecond);
}

BENCHMARK(BM_ExactCheckAllClaims)->Arg(5)->Arg(12)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CheckExact)->Apply(check_sizes);
BENCHMARK(BM_CheckExact)->Arg(1000)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CheckDouble)->Apply(check_sizes);
BENCHMARK(BM_CheckDouble)->Arg(1000)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace linkproof::bench
