// BM_SymbolicDerivation/n: what a check derives once per n (GroundTruthEngine::Derivation): the
// canonical form of the solved loop closure assembled from the closed form of its two time
// derivatives, and the compiled motion tape (symbolic/motion_tape.h). It is meant to be O(n):
// Complexity() fits the growth across n.
// BM_GiNaCDerivation/n: GiNaC's derivation of the same tape (the reference, SymbolicDerivation
// and its motion_tape()): symbols, loop closure, its two time derivatives by the product rule, the
// exact solve by Cramer's rule written structurally, and the compilation of GiNaC's trees.
// BM_LoopSolution/n times the symbols and derive_loop_solution alone.
#include <benchmark/benchmark.h>

#include <memory>

#include "symbolic/ground_truth.h"

namespace linkproof::bench {
namespace {

void BM_SymbolicDerivation(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  std::unique_ptr<GroundTruthEngine::Derivation> last;
  for (auto _ : state) {
    // Assigning destroys the previous derivation inside the loop: the time per iteration is a
    // full build-and-release, as in a process that derives each n once.
    last = std::make_unique<GroundTruthEngine::Derivation>(n);
    benchmark::DoNotOptimize(last.get());
  }
  // Measured after the timed loop, on the last derivation.
  state.counters["tape"] = benchmark::Counter(static_cast<double>(last->motion.size()));
  state.SetComplexityN(n);
}

void BM_GiNaCDerivation(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  std::unique_ptr<GroundTruthEngine::SymbolicDerivation> last;
  for (auto _ : state) {
    last = std::make_unique<GroundTruthEngine::SymbolicDerivation>(n);
    const Tape motion = last->motion_tape();
    benchmark::DoNotOptimize(motion.size());
  }
  state.counters["tree_omega_dot_n1"] =
      benchmark::Counter(static_cast<double>(expression_tree_size(last->solution.omega_dot_n1)));
  state.SetComplexityN(n);
}

void BM_LoopSolution(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  for (auto _ : state) {
    const PolygonSymbols s(n);
    LoopSolution solution = derive_loop_solution(s);
    benchmark::DoNotOptimize(solution);
  }
  state.SetComplexityN(n);
}

/// The sizes n = 4, 8, 24, 100, 1000, with a complexity fit over them.
void derivation_sizes(benchmark::internal::Benchmark* b) {
  for (int n : {4, 8, 24, 100, 1000}) b->Arg(n);
  b->Unit(benchmark::kMillisecond)->Complexity();
}

BENCHMARK(BM_SymbolicDerivation)->Apply(derivation_sizes);
BENCHMARK(BM_GiNaCDerivation)->Apply(derivation_sizes);
BENCHMARK(BM_LoopSolution)->Apply(derivation_sizes);

}  // namespace
}  // namespace linkproof::bench
