// Mechanism claims on the configurations 0..K-1 of a scene's topology, as the cases of a sweep
// (`linkproof sweep --topology SCENE --claims CLAIMS --count K`; docs/sweeps.md, "Sweeps of a
// mechanism topology").
//
// Unlike `check-claim --topology --count K`, where K is the number of configurations on which
// each claim must be compared (drawing more until it is, and stopping a claim once decided),
// here K is the number of configurations drawn: case i is configuration i
// (random_topology_configuration(scene, seed, i)), every claim is judged on every case, and a
// case is a pure function of (scene, claims, seed, arithmetic, i). The cases are folded in case
// order (TopologySweepTally), so however they are computed (worker processes, shards, resumed
// runs) the counts are the same; the verdicts and the counterexamples are drawn from the counts
// and the first failing case afterwards, once (finish_topology_sweep):
//   holds_on_samples  compared on at least one case and failing on none (NOT a proof)
//   disproved         failing on some case: the first (lowest index) replayable one, shrunk
//   undefined / inconclusive   as in proof/mechanism_sampling.h
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "proof/mechanism_sampling.h"
#include "proof/topology_configurations.h"

namespace linkproof {

/// What one case gives: the configuration's index, whether its velocity system is singular
/// (then no verdicts), whether it is degenerate (a claim fails on it and the scene reader refuses
/// it: its failures are skipped, as check-claim skips them), and each claim's verdict on it
/// (Holds, Fails, Undefined, Inconclusive), in the claims' order.
struct TopologySweepCase {
  long index = 0;
  bool singular = false;
  bool degenerate = false;
  std::vector<Verdict> verdicts;
};

/// Computes case `index` (every claim judged).
TopologySweepCase run_topology_sweep_case(const TopologyConfigurations& configurations, long index);

/// Per claim, beyond a SampleResult's counts: the failures and the first of them.
struct TopologySweepClaim {
  int fails = 0;                          ///< cases on which the claim fails (replayable ones)
  std::optional<long> first_failing_case;       ///< the lowest of them
  std::optional<long> first_undefined_case;     ///< the lowest case on which it is undefined
  std::optional<long> first_inconclusive_case;  ///< ... undecided (floating point)
};

/// The whole sweep: the counts of a TopologySampleRun (its `options.count` is K, the cases
/// drawn; `generated` the cases folded in), plus the failures of each claim.
struct TopologySweepReport {
  TopologySampleRun run;
  std::vector<TopologySweepClaim> claims;  ///< parallel to run.claims
};

/// Folds cases in case order into the counts of a report.
class TopologySweepTally {
 public:
  TopologySweepTally(const MechanismScene& scene, const std::vector<MechanismDataClaim>& claims,
                     const TopologySampling& options);
  /// Counts case c (a later case than the last one counted: the cases of the sweep or of one of
  /// its shards, in case order; its verdicts one per claim unless singular).
  void add(const TopologySweepCase& c);
  long cases() const { return report_.run.generated; }
  /// Cases on which a claim expected to hold failed (for a progress bar).
  long unexpected_cases() const { return unexpected_; }
  /// The counts so far: verdicts not drawn, no counterexample (finish_topology_sweep).
  const TopologySweepReport& counts() const { return report_; }

 private:
  TopologySweepReport report_;
  long unexpected_ = 0;
  long last_index_ = -1;
};

/// The report of the cases folded into `tally`: each claim's verdict (topology_verdict), the
/// counterexample of a disproved claim (its first failing case, shrunk by
/// TopologyConfigurations::shrink: the scene check-claim --topology writes for that
/// configuration), and the first undefined quantity and undecided comparison of each claim
/// (its first such case judged again). `seconds` is left 0.
TopologySweepReport finish_topology_sweep(const TopologyConfigurations& configurations, const TopologySweepTally& tally);

}  // namespace linkproof
