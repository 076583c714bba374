// The routes of numerics/routes.h across the arithmetic ladder, and the adaptive mode, on the same
// random polygons (bench_cases.h, seed printed in the context):
//   BM_Route<T>/route/n   one evaluation of omega-dot_{n-1,n} and omega-dot_{n-2,n} by a route
//                         (0 construction, 1 closed forms, 2 direct solve, 3 symbolic tape) in T;
//   BM_Adaptive/n         the certified adaptive mode (numerics/adaptive.h) on doubles;
// Counter per_side = time / (n-3 inputs). Cases on which the construction is undefined are left
// out for every route, so that all routes time the same configurations.
#include <benchmark/benchmark.h>

#include "bench_cases.h"
#include "numerics/adaptive.h"
#include "numerics/ladder.h"
#include "numerics/routes.h"

namespace linkproof::bench {
namespace {

template <class T>
struct LadderCase {
  Polygon<T> polygon;
  InputRates<T> rates;
};

template <class T>
std::vector<LadderCase<T>> ladder_cases(benchmark::State& state, int n) {
  const std::vector<RandomPolygonCase>& drawn = make_cases(n, 16);
  state.SetLabel(families(drawn));
  std::vector<LadderCase<T>> out;
  for (const RandomPolygonCase& c : drawn) {
    try {
      (void)compute_by_construction(c.polygon, c.rates);
    } catch (const UndefinedQuantity&) {
      continue;
    }
    out.push_back({c.polygon.template convert<T>(), c.rates.template convert<T>()});
  }
  return out;
}

void set_ladder_per_side(benchmark::State& state, int n) {
  state.counters["per_side"] =
      benchmark::Counter(n - 3, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

template <class T>
void BM_Route(benchmark::State& state) {
  const auto route = static_cast<Route>(state.range(0));
  const int n = static_cast<int>(state.range(1));
  const auto cases = ladder_cases<T>(state, n);
  GroundTruthEngine engine;
  if (route == Route::SymbolicTape) engine.derivation(n);
  size_t k = 0;
  for (auto _ : state) {
    const LadderCase<T>& c = cases[k++ % cases.size()];
    RouteValue<T> v = compute_by_route(route, engine, c.polygon, c.rates);
    benchmark::DoNotOptimize(v);
  }
  state.SetLabel(std::string(to_string(route)) + " " + arithmetic_name<T>() + " " + families(make_cases(n, 16)));
  set_ladder_per_side(state, n);
}

void BM_Adaptive(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto cases = ladder_cases<double>(state, n);
  size_t k = 0;
  for (auto _ : state) {
    const LadderCase<double>& c = cases[k++ % cases.size()];
    AdaptiveResult r = compute_omega_dot_adaptive(c.polygon, c.rates);
    benchmark::DoNotOptimize(r);
  }
  set_ladder_per_side(state, n);
}

void route_args(benchmark::internal::Benchmark* b) {
  for (int r = 0; r < 4; ++r)
    for (int n : {5, 100}) b->Args({r, n});
}

/// In double also n = 1000 (scattered polygons only, see bench_cases.h), for the routes that
/// run in O(n) per evaluation: the per-side cost without the per-polygon overhead.
void route_args_double(benchmark::internal::Benchmark* b) {
  route_args(b);
  for (int r = 0; r < 3; ++r) b->Args({r, 1000});
}

using Mp30 = MpFloat<30>;
using Mp1000 = MpFloat<1000>;
BENCHMARK_TEMPLATE(BM_Route, double)->Apply(route_args_double)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(BM_Route, long double)->Apply(route_args)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(BM_Route, Mp30)->Apply(route_args)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(BM_Route, Mp1000)->Apply(route_args)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(BM_Route, Rational)->Apply(route_args)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Adaptive)->Arg(5)->Arg(100)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace linkproof::bench
