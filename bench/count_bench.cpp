// BM_CountTriangleRank/n: exact rank of the C(n,3) triangle relations of n bodies in the
// n(n-1)/2 relative rates (core/row_echelon.h), ranked afresh each time (`count` keeps its
// basis between calls, so count_triangle_relations would measure a lookup).
// BM_CountClaims/n: every counting claim for n (triangle rank, balance, and the three rank-2
// families over all n choices of the fixed side on an exact random polygon), as `linkproof
// count --n n` computes them, polygon drawing included.
#include <benchmark/benchmark.h>

#include "bench_cases.h"
#include "dijksman1966_counting.h"
#include "count/counting.h"

namespace linkproof::bench {
namespace {

void BM_CountTriangleRank(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  bool wrong = false;
  for (auto _ : state) {
    const RelativeRates rates(n);
    RowEchelon<Rational> e(rates.columns());
    const RankResult r = add_and_rank(e, triangle_relations(rates));
    wrong = wrong || r.rank != (n - 1) * (n - 2) / 2;
    benchmark::DoNotOptimize(r);
  }
  if (wrong) state.SkipWithError("the triangle rank is not (n-1)(n-2)/2");
  state.counters["relations"] = benchmark::Counter(static_cast<double>(n) * (n - 1) * (n - 2) / 6);
}

void BM_CountClaims(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  bool wrong = false;
  for (auto _ : state) {
    const auto claims = dijksman1966::count_claims_for_n(n, kSeed);
    for (const auto& c : claims) wrong = wrong || !c.as_expected();
    benchmark::DoNotOptimize(claims);
  }
  if (wrong) state.SkipWithError("a counting claim was not proved");
}

BENCHMARK(BM_CountTriangleRank)->Arg(10)->Arg(30)->Arg(60)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CountClaims)->Arg(10)->Arg(30)->Arg(60)->Arg(200)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace linkproof::bench
