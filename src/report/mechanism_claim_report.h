// Text and JSON of mechanism claims checked on random configurations of a topology
// (proof/mechanism_sampling.h, `linkproof check-claim CLAIMS --topology SCENE`).
//
// JSON: {"mode": "topology", "topology", "seed", "count", "configurations": {"generated",
// "singular_skipped", "solved",
// "degenerate_failures_skipped"}, "rests_on", "claims": [{"id", "source", "statement",
// "expected", "verdict" (holds_on_samples | disproved | undefined), "as_expected", "scope",
// "compared", "undefined_configurations", "undefined": {"quantity", "reason"} | null,
// "counterexample": {"configuration", "shrink_steps", "shrink_tried", "scene_yaml", "check"}
// | null, "seconds"}], "summary": {"claims", "as_expected", "not_as_expected"}, "seconds",
// "exit_status"}. `holds_on_samples` is evidence on the configurations drawn, not a proof: the
// text and `rests_on` say so.
#pragma once

#include <nlohmann/json.hpp>

#include <ostream>

#include "proof/mechanism_sampling.h"
#include "report/claims_status.h"

namespace linkproof {

/// A shrunk counterexample: {"configuration", "shrink_steps", "shrink_tried", "scene_yaml", "check"}.
nlohmann::json to_json(const MechanismCounterexample& c);
/// Its differing values (with decimals) and its scene, indented, for the text reports.
void write_text(std::ostream& out, const MechanismCounterexample& c);

/// "; N inconclusive, the first at LABEL: REASON" when a claim was undecided somewhere, else "".
std::string inconclusive_note(const SampleResult& r);

/// `status`: the program's decisions (report/claims_status.h), one per claim of `run`.
nlohmann::json to_json(const TopologySampleRun& run, const ClaimsStatus& status);

/// The keys of a claim judged on random configurations that `check-claim --topology --count` and
/// `sweep --topology` share (docs/claims.md, docs/sweeps.md), with `scope` as each words it.
nlohmann::json sample_claim_json(const SampleResult& r, bool as_expected, const std::string& scope);
void write_text(std::ostream& out, const TopologySampleRun& run, const ClaimsStatus& status);

}  // namespace linkproof
