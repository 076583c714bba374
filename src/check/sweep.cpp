#include "check/sweep.h"

#include <chrono>

#include "check/sweep_tally.h"

namespace linkproof {

long SweepReport::errors() const {
  long n = 0;
  for (const auto& t : tallies) n += t.error;
  return n;
}

long SweepReport::unexpected_failures() const {
  long n = 0;
  for (const auto& t : tallies)
    if (t.expected == Expectation::Holds) n += t.fails;
  return n;
}

SweepReport run_sweep(GroundTruthEngine& engine, const std::vector<Claim>& catalogue, const SweepOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  SweepTally tally(catalogue, o);
  const SweepPlan plan(o);
  for (long k = 0; k < plan.size(); ++k) {
    SweepCase c = run_sweep_case(engine, catalogue, o, k);
    const auto missing = tally.add(c);
    LINKPROOF_ASSERT(!missing, "a fresh sweep case carries every candidate example");
  }
  SweepReport r = tally.report();
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace linkproof
