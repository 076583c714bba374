// Text and JSON of a sweep of a mechanism topology (proof/topology_sweep.h, `linkproof sweep
// --topology SCENE --claims CLAIMS --count K`), and the summary line of its result file.
//
// JSON: {"mode": "topology_sweep", "topology", "scene_digest", "claims_digest", "seed", "count",
// "arithmetic", "shard" (sharded only), "configurations": {"generated", "singular_skipped",
// "solved", "degenerate_failures_skipped"}, "rests_on", "claims": [{"id", "source", "statement",
// "expected", "verdict" (holds_on_samples | disproved | undefined | inconclusive), "as_expected",
// "scope", "compared", "undefined_configurations", "inconclusive_configurations",
// "failing_configurations", "first_failing_configuration" | null, "undefined": {"quantity",
// "reason"} | null, "counterexample": {"configuration", "shrink_steps", "shrink_tried",
// "scene_yaml", "check"} | null}], "summary": {"claims", "as_expected", "not_as_expected"},
// "seconds", "exit_status"}. `count` is the number of configurations drawn (not, as in
// check-claim --topology --count, the number each claim must be compared on); the text and
// `rests_on` say so, and that holds_on_samples is not a proof.
#pragma once

#include <nlohmann/json.hpp>

#include <ostream>

#include "report/claims_status.h"
#include "report/sweep_lines.h"
#include "report/topology_sweep_lines.h"

namespace linkproof {

/// The report, its sweep and shard, with the program's decisions (one per claim) in `status`.
nlohmann::json to_json(const TopologySweepReport& report, const TopologySweepIdentity& id, const Shard& shard,
                       const ClaimsStatus& status, double seconds);
void write_text(std::ostream& out, const TopologySweepReport& report, const TopologySweepIdentity& id,
                const Shard& shard, const ClaimsStatus& status, double seconds);

/// The summary line of the result file: {"summary": the JSON above without "seconds"}.
std::string topology_summary_line(const TopologySweepReport& report, const TopologySweepIdentity& id,
                                  const Shard& shard, const ClaimsStatus& status);

}  // namespace linkproof
