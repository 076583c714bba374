// JSON renderings of check and sweep results (the CLI's --json). The field names are a
// contract relied on by outside checks: see README.md, "JSON contract".
#pragma once

#include <nlohmann/json.hpp>

#include "check/check_polygon.h"
#include "check/sweep.h"
#include "report/claims_status.h"

namespace linkproof {

/// {"scene", "arithmetic", "polygon": {"n", "omega": {"1": ..}, "omega_dot": {..}, "D",
///  "dead_centre"}, "tolerance_rule", "claims": [{"id", "verdict", "expected", "as_expected",
///  "residual", "lhs", "rhs", "tolerance"?, "undefined_quantity"?, "reason"?, "source",
///  "statement", "note"?, "instances": [..], "terms": [..]}], "not_applicable", "summary"}
/// `status`: the program's decisions (report/claims_status.h): the "exit_status" key, and with
/// --strict each claim's "as_expected" and the summary's "not_as_expected" under that policy.
nlohmann::json to_json(const PolygonCheck& check, const ClaimsStatus& status);
nlohmann::json to_json(const ComparisonOutcome& c);
/// One claim's outcome as in the `claims` list of the check JSON (shared by polygon and mechanism checks).
nlohmann::json to_json(const ClaimOutcome& c);
/// `exit_status`: the program's (cli/exit_status.h), printed as the "exit_status" key.
nlohmann::json to_json(const SweepReport& sweep, int exit_status);
/// An example's evidence: its headline comparison, or the evidence its result file recorded.
nlohmann::json evidence_json(const SweepExample& e);

/// `j` printed with an indent of 2, bytes that are not valid UTF-8 replaced by U+FFFD: the
/// readers already escape such bytes in names and statements (io), this is the last guard so that
/// printing JSON never throws.
std::string json_text(const nlohmann::json& j);

}  // namespace linkproof
