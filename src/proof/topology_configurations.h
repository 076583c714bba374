// One random configuration of a mechanism scene's topology, judged claim by claim: what
// `check-claim CLAIMS --topology SCENE --count K` (proof/mechanism_sampling.h, adaptive: a claim
// stops once decided) and `sweep --topology SCENE` (proof/topology_sweep.h, every claim on
// configurations 0..K-1) both do for each configuration, and the shrinking of a failing one.
//
//   const TopologyConfigurations configurations(scene, claims, options);
//   std::vector<SampleResult> notes(claims.size());  std::vector<double> seconds(claims.size());
//   const auto verdicts = configurations.judge(7, std::vector<bool>(claims.size()), notes, seconds);
//   if (verdicts && (*verdicts)[0] == Verdict::Fails && configurations.is_replayable(7))
//     MechanismCounterexample cx = configurations.shrink(0, 7);
//
// Configuration i of seed S is the same on every platform (splitmix64), and so is everything
// computed from it: the verdicts, the notes and the shrunk counterexample depend on (scene,
// claims, options, i) only, never on which process computed them or in what order.
#pragma once

#include <optional>
#include <vector>

#include "proof/mechanism_sampling.h"
#include "proof/topology_layout.h"

namespace linkproof {

class TopologyConfigurations {
 public:
  /// `scene` and `claims` (bound to the scene's names) must outlive this object.
  TopologyConfigurations(const MechanismScene& scene, const std::vector<MechanismDataClaim>& claims,
                         const TopologySampling& options);

  /// The values of configuration `index` (positions, axes, input rates).
  TopologyValues values(int index) const;

  /// Configuration `index` solved in the options' arithmetic and every claim not `skip`ped judged
  /// on it: Holds, Fails (in floating point confirmed exactly: the sides differ exactly),
  /// Undefined or Inconclusive (floating point only); a skipped claim's entry is Holds and means
  /// nothing. nullopt where the velocity system is singular (in floating point also: the rounded
  /// solve decides another rank, or its arithmetic fails). `notes[k]` receives the first
  /// undefined quantity and the first inconclusive comparison met (kept if already set);
  /// `seconds[k]` the time spent on claim k.
  std::optional<std::vector<Verdict>> judge(int index, const std::vector<bool>& skip, std::vector<SampleResult>& notes,
                                            std::vector<double>& seconds) const;

  /// True if the scene reader accepts configuration `index` as written: a failure on it replays
  /// with `check-claim CLAIMS --scene`. (The reader refuses some configurations the solver
  /// accepts, e.g. a driven link whose joints coincide.)
  bool is_replayable(int index) const;

  /// Claim `claim` failing on configuration `index` (a replayable one), shrunk one value at a
  /// time while it still fails and still solves (mechanism_sampling.h), as a scene.
  MechanismCounterexample shrink(size_t claim, int index) const;

  /// The name of configuration `index`: "<scene name>-sample-<index>".
  std::string name(int index) const;

  const MechanismScene& scene() const { return scene_; }
  const std::vector<MechanismDataClaim>& claims() const { return claims_; }
  const TopologySampling& options() const { return options_; }

 private:
  const MechanismScene& scene_;
  const std::vector<MechanismDataClaim>& claims_;
  TopologySampling options_;
  TopologyLayout layout_;
};

}  // namespace linkproof
