// Mechanism claims on random exact configurations of a scene's topology (`linkproof check-claim
// CLAIMS --topology SCENE --count K`): evidence, not a proof.
//
// A configuration of the topology keeps the scene's links, joints (names, types, the links they
// join, guide and slider), inputs (which link or joint drives), tracer points (name and link) and
// which joints and points coincide; it draws every position afresh as a small integer point
// (|x|, |y| <= 10), every prismatic axis as a random rational unit direction ((1, 0), (3/5, 4/5),
// (5/13, 12/13), (8/17, 15/17), turned by a multiple of 90 degrees or reflected), and every input
// rate as a rational p/q (|p| <= 9, 1 <= q <= 4; omega != 0). Configuration i of seed S is the
// same on every platform (splitmix64). A configuration whose velocity system is singular (a dead
// centre, a change point, inputs that do not fix the motion) is skipped and counted; so is a
// failure on a configuration the scene reader refuses (a driven link whose joints coincide).
//
// Each configuration is solved by the rigid-body vector route (mechanism/mechanism_vector_route.h),
// exactly or in the floating arithmetic asked for (with derived error bounds), and every claim is
// evaluated on it:
//   holds_on_samples   both sides exactly equal (floating point: equal within the derived bound)
//                      on K configurations on which the claim is defined and the comparison
//                      decided (fewer if the attempts, 20 K + 100, ran out: the scope says so).
//                      NOT a proof: a claim true on these configurations may fail on others.
//   disproved          the sides differ exactly on some configuration: a counterexample, shrunk
//                      one value at a time toward small integers (positions toward 0, rates toward
//                      1 or 0, axes toward (1, 0) or (0, 1)) while it still fails, written as a
//                      scene that `check-claim CLAIMS --scene` re-fails.
//   undefined          the claim was undefined on every non-singular configuration (named).
//   inconclusive       floating point: no comparison was decided by the error bounds.
// Only holds_on_samples is as expected for a true claim, only disproved for a false one.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "claims/mechanism_claim.h"
#include "linkproof/check/arithmetic.h"
#include "linkproof/check/check.h"
#include "linkproof/mechanism/mechanism_scene.h"

namespace linkproof {

struct TopologySampling {
  int count = 20;            ///< K: configurations on which each claim must be compared
  /// The arithmetic each configuration is solved and judged in (`--arith`). Floating point
  /// (Tracked<F>, core/tracked.h) judges with derived error bounds: `holds` where the sides agree
  /// within them, `fails` only where they cannot be equal, else inconclusive (not counted); a
  /// failure is confirmed in exact arithmetic before it is a counterexample, and shrunk exactly.
  Arithmetic arithmetic = Arithmetic::Exact;
  std::uint64_t seed = 1;
  int coordinate_range = 10; ///< positions are integers in [-range, range]
  int shrink_budget = 4000;  ///< configurations evaluated while shrinking, at most
};

/// Inconclusive: floating point only, no comparison on any configuration was decided by the
/// error bounds (and none was undefined).
enum class TopologyVerdict { HoldsOnSamples, Disproved, Undefined, Inconclusive };
std::string to_string(TopologyVerdict v);

struct MechanismCounterexample {
  int configuration = 0;   ///< index of the failing random configuration (replays with the seed)
  int shrink_steps = 0;    ///< accepted shrinking steps
  int shrink_tried = 0;    ///< configurations evaluated while shrinking
  MechanismScene scene;    ///< the shrunk configuration
  std::string scene_yaml;  ///< ... as a mechanism scene file
  ClaimOutcome outcome;    ///< the failing check on it (exact), lhs and rhs per component
};

struct SampleResult {
  ClaimInfo info;
  TopologyVerdict verdict = TopologyVerdict::Undefined;
  int compared = 0;   ///< configurations on which both sides were defined and compared
  int undefined = 0;  ///< configurations on which the claim was undefined
  /// Floating point: configurations on which the error bounds could not decide (not counted as
  /// compared), and the first undecided comparison (its evidence says why).
  int inconclusive = 0;
  std::optional<ComparisonOutcome> first_inconclusive;
  std::string undefined_quantity, undefined_reason;  ///< the first undefined quantity met
  std::optional<MechanismCounterexample> counterexample;
  double seconds = 0;
  /// As expected: a true claim holds on the samples (undefined or undecided on every one of them
  /// is not a pass), a claim expected to fail is disproved. (The program's --strict policy,
  /// under which samples never suffice for a true claim, is decided in cli/.)
  bool is_as_expected() const;
};

struct TopologySampleRun {
  std::string topology;         ///< the scene's name
  TopologySampling options;
  int generated = 0;            ///< configurations drawn
  /// ... skipped: singular velocity system (in floating point: the rounded solve found another
  /// rank or mobility, or its arithmetic failed)
  int singular = 0;
  /// Failures skipped because the scene reader refuses their configuration (e.g. a driven link
  /// whose joints coincide): a counterexample must replay with `check-claim --scene`.
  int degenerate = 0;
  int solved = 0;               ///< ... solved and evaluated
  double seconds = 0;
  std::vector<SampleResult> claims;
};

/// Configuration `index` of the topology of `scene` (see the header comment); its name is
/// "<scene name>-sample-<index>".
MechanismScene random_topology_configuration(const MechanismScene& scene, std::uint64_t seed, int index,
                                             int coordinate_range = 10);

/// The verdict of a claim from its counts: disproved if it `failed` on a replayable
/// configuration, else holds_on_samples if it was compared on at least one, else inconclusive if
/// it was never undefined but undecided somewhere, else undefined.
TopologyVerdict topology_verdict(const SampleResult& counts, bool failed);

/// Samples the topology of `scene` and judges every claim (bound to `scene`'s names).
TopologySampleRun sample_topology(const MechanismScene& scene, const std::vector<MechanismDataClaim>& claims,
                                  const TopologySampling& options);

}  // namespace linkproof
