// One case of a sweep, and the order of all of them.
//
// A sweep over n = n_min..n_max with `count` cases per n numbers its cases k = 0, 1, ... in the
// order (n, index): k = (n - n_min) * count + index (with `only_index`, one case per n). Every
// case is a pure function of (seed, n, index), so a case can be computed in any process, in any
// order, and the results folded in k order (check/sweep_tally.h) give the same report as a
// single loop. That is what makes parallel workers, shards, resumed runs and MPI ranks agree
// byte for byte (batch/).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "check/sweep.h"

namespace linkproof {

/// The cases of a sweep in k order.
class SweepPlan {
 public:
  explicit SweepPlan(const SweepOptions& o) : o_(o) {}
  /// Number of cases: (n_max - n_min + 1) * (count, or 1 with only_index).
  long size() const;
  /// The (n, index) of case k, 0 <= k < size().
  std::pair<int, int> at(long k) const;
  /// The case number of (n, index), the inverse of at().
  long case_of(int n, int index) const;

 private:
  long per_n() const { return o_.only_index ? 1 : o_.count; }
  SweepOptions o_;
};

/// The result of one case, as much as a sweep keeps of it: every applicable claim's verdict,
/// the claims that do not apply at this n, and the evidence of the claims that may become
/// examples of the report (unexpected failures and errors; erratum readings that fail).
struct SweepCase {
  long k = 0;                                 ///< the case number (SweepPlan)
  RandomPolygonCase polygon;                  ///< regenerated from (seed, n, index)
  std::map<std::string, Verdict> verdicts;    ///< claim id -> verdict, applicable claims only
  std::vector<std::string> not_applicable;    ///< claim ids, catalogue order
  /// Candidate examples in catalogue order. A fresh case carries every candidate; a case read
  /// back from a result file carries only those the tally kept (SweepTally::add).
  std::vector<SweepExample> examples;

  const SweepExample* example_for(const std::string& claim_id) const;
};

/// Runs every claim of `catalogue` on case k of the sweep `o` in the sweep's arithmetic.
SweepCase run_sweep_case(GroundTruthEngine& engine, const std::vector<Claim>& catalogue, const SweepOptions& o,
                         long k);

}  // namespace linkproof
