// Text and JSON of mechanism claims proved over every configuration of a topology
// (proof/mechanism_proof.h: `linkproof prove --file CLAIMS --topology SCENE`, and
// `linkproof check-claim CLAIMS --topology SCENE` without --count).
//
// JSON: {"mode": "topology_proof", "topology", "coordinates": [symbol, ...], "relations":
// ["c_D^2 + s_D^2 = 1", ...], "velocity_system": {"unknowns", "det_terms", "note", "groups": [size,
// ...], "proof_driver": {"link", "groups"} | null}, "claims":
// [{"id", "source", "statement", "expected", "verdict" (proved | proved_generically | disproved |
// holds_with_probability | holds_on_samples | error), "as_expected", "except": [{"polynomial",
// "meaning"}], "argument": [step, ...], "samples_compared", "identity_test": {"trials",
// "degree_bound", "failure_bound"} | null, "numerator_terms", "counterexample": {"configuration",
// "shrink_steps", "shrink_tried", "scene_yaml", "check"} | null, "error", "seconds"}], "summary":
// {"claims", "as_expected", "not_as_expected"}, "seconds", "exit_status"}.
#pragma once

#include <nlohmann/json.hpp>

#include <ostream>

#include "proof/mechanism_proof.h"
#include "report/claims_status.h"

namespace linkproof {

nlohmann::json to_json(const TopologyProofRun& run, const ClaimsStatus& status);
void write_text(std::ostream& out, const TopologyProofRun& run, const ClaimsStatus& status);

}  // namespace linkproof
