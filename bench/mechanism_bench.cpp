// Mechanism engine timings (issue 4): the Fig. 5 eight-bar solved exactly by the symbolic loop
// closure (goal < 5 ms for all 28 relative omega-dot), by the rigid-body route, and by Dijksman's
// multi-polygon method; a random 30-link chain of RRR dyads (exact and double).
#include <benchmark/benchmark.h>

#include "linkproof/io/mechanism_scene.h"
#include "mechanism_chain.h"
#include "mechanism/dijksman_compound.h"
#include "mechanism/mechanism_catalogue.h"
#include "mechanism/mechanism_vector_route.h"
#include "mechanism/mechanism_closure.h"

namespace linkproof {
namespace {

MechanismScene eightbar() {
  return load_mechanism_scene(std::string(LINKPROOF_BENCH_SOURCE_DIR) + "/verify/scenes/mechanisms/fig5_eightbar.yaml");
}

void BM_EightBarExactSymbolic(benchmark::State& st) {
  const MechanismScene s = eightbar();
  for (auto _ : st) benchmark::DoNotOptimize(solve_mechanism_exact(s));
}
BENCHMARK(BM_EightBarExactSymbolic)->Unit(benchmark::kMillisecond);

template <class T>
MechanismSolution<T> vector_solve(const MechanismScene& s) {
  return solve_mechanism<T>(
      s.linkage, s.inputs, rigid_body_constraint_matrix<T>(s.linkage),
      [&](const std::vector<T>& qd) { return rigid_body_acceleration_rhs<T>(s.linkage, qd); }, s.source);
}

void BM_EightBarExactVectorRoute(benchmark::State& st) {
  const MechanismScene s = eightbar();
  for (auto _ : st) benchmark::DoNotOptimize(vector_solve<Rational>(s));
}
BENCHMARK(BM_EightBarExactVectorRoute)->Unit(benchmark::kMillisecond);

void BM_EightBarExactDijksmanPolygons(benchmark::State& st) {
  const MechanismScene s = eightbar();
  for (auto _ : st) benchmark::DoNotOptimize(solve_dijksman_compound<Rational>(s.linkage, s.inputs[0]));
}
BENCHMARK(BM_EightBarExactDijksmanPolygons)->Unit(benchmark::kMillisecond);

void BM_ChainExactSymbolic(benchmark::State& st) {
  const MechanismScene s = random_chain(static_cast<int>(st.range(0)), 7);
  for (auto _ : st) benchmark::DoNotOptimize(solve_mechanism_exact(s));
}
BENCHMARK(BM_ChainExactSymbolic)->Arg(10)->Arg(20)->Arg(30)->Unit(benchmark::kMillisecond);

void BM_ChainExactVectorRoute(benchmark::State& st) {
  const MechanismScene s = random_chain(static_cast<int>(st.range(0)), 7);
  for (auto _ : st) benchmark::DoNotOptimize(vector_solve<Rational>(s));
}
BENCHMARK(BM_ChainExactVectorRoute)->Arg(10)->Arg(20)->Arg(30)->Unit(benchmark::kMillisecond);

void BM_ChainDouble(benchmark::State& st) {
  const MechanismScene s = random_chain(static_cast<int>(st.range(0)), 7);
  for (auto _ : st) benchmark::DoNotOptimize(vector_solve<double>(s));
}
BENCHMARK(BM_ChainDouble)->Arg(30)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace linkproof
