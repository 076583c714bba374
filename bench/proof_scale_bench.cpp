// Issue 13 ("Scale"): the proofs, counts and exact mechanism solves at the sizes of the goals.
//   BM_ProveEq22AllN          `linkproof prove --claim eq22 --ladder-seconds 0`: per-n proofs at
//                             n = 4 and 5, the lift check at n = 6, the counterexample search
//                             n = 4..8 (goal < 1 s)
//   BM_ProvePerN/n            `prove --claim eq22 --n n`: the whole (22) in symbolic coordinates
//                             at one n (goal: n >= 12 within 60 s)
//   BM_ProveAllBundledClaims  `prove` on verify/claims/dijksman1966.yaml, default options: every
//                             proof, no per-n re-check of claims proved for every n (goal <= 10 s)
//   BM_CountRange/nmax        `count --n 3..nmax`, every claim of every n (goal <= 30 s at 200)
//   BM_MechanismChain/loops   the exact symbolic-closure solve of a chain of four-bar loops
//                             (mechanism_chain.h; goal <= 1 s at 100 loops)
// Heavy rows run once (Iterations(1)); compare rows of one run only.
#include <benchmark/benchmark.h>

#include "dijksman1966.h"
#include "dijksman1966_counting.h"
#include "mechanism/mechanism_catalogue.h"
#include "proof/prove.h"
#include "mechanism_chain.h"

namespace linkproof {
namespace {

const DataClaim& bundled_claim(const std::string& id) {
  for (const auto& c : dijksman1966::claim_file().claims)
    if (c.info.id == id) return c;
  throw std::runtime_error("no bundled claim " + id);
}

ProveOptions without_ladder() {
  ProveOptions o;
  o.ladder_seconds = 0;
  return o;
}

void BM_ProveEq22AllN(benchmark::State& state) {
  const DataClaim& c = bundled_claim("dijksman1966.eq22");
  for (auto _ : state) {
    GroundTruthEngine engine;
    const ProofResult r = prove_claim(engine, c, without_ladder());
    if (r.verdict != ProofVerdict::ProvedGenerically) state.SkipWithError("eq22 not proved for every n");
    benchmark::DoNotOptimize(r);
  }
}
BENCHMARK(BM_ProveEq22AllN)->Unit(benchmark::kMillisecond);

void BM_ProvePerN(benchmark::State& state) {
  const DataClaim& c = bundled_claim("dijksman1966.eq22");
  ProveOptions o = without_ladder();
  o.only_n = static_cast<int>(state.range(0));
  for (auto _ : state) {
    GroundTruthEngine engine;
    const ProofResult r = prove_claim(engine, c, o);
    if (r.verdict != ProofVerdict::ProvedFor) state.SkipWithError("eq22 not proved at this n");
    benchmark::DoNotOptimize(r);
  }
}
BENCHMARK(BM_ProvePerN)->Arg(6)->Arg(8)->Arg(10)->Arg(12)->Iterations(1)->Unit(benchmark::kSecond);

void BM_ProveAllBundledClaims(benchmark::State& state) {
  for (auto _ : state) {
    GroundTruthEngine engine;
    int not_as_expected = 0;
    for (const DataClaim& c : dijksman1966::claim_file().claims)
      not_as_expected += prove_claim(engine, c, ProveOptions{}).is_as_expected() ? 0 : 1;
    if (not_as_expected) state.SkipWithError("a bundled claim is not as expected");
  }
}
BENCHMARK(BM_ProveAllBundledClaims)->Iterations(1)->Unit(benchmark::kSecond);

void BM_CountRange(benchmark::State& state) {
  const int nmax = static_cast<int>(state.range(0));
  for (auto _ : state) {
    bool wrong = false;
    for (int n = 3; n <= nmax; ++n)
      for (const auto& c : dijksman1966::count_claims_for_n(n, 1)) wrong = wrong || !c.as_expected();
    if (wrong) state.SkipWithError("a counting claim is not as expected");
  }
}
BENCHMARK(BM_CountRange)->Arg(50)->Arg(100)->Arg(200)->Iterations(1)->Unit(benchmark::kSecond);

void BM_MechanismChain(benchmark::State& state) {
  const MechanismScene s = random_chain(chain_links_for_loops(static_cast<int>(state.range(0))), 7);
  for (auto _ : state) benchmark::DoNotOptimize(solve_mechanism_exact(s));
}
BENCHMARK(BM_MechanismChain)->Arg(10)->Arg(30)->Arg(59)->Arg(100)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace linkproof
