// Reports of a mechanism check (mechanism/mechanism_check.h): JSON and text.
//
// JSON contract (`linkproof check --json` on a mechanism scene):
//   {"scene": "...", "arithmetic": "exact", "mobility": 1,
//    "grubler_mobility": 1, "rank": 7, "loops": 3, "unknowns": 7,
//    "condition": 41.3,                        // 2-norm condition of the velocity system (double)
//    "closure_residual": "0", "dimension_residual": 0,
//    "links":  {"1": {"omega": "1", "omega_dot": "1/2"}, ...},      // relative to the ground
//    "relative": {"1,2": {"omega": "...", "omega_dot": "..."}, ...}, // omega_ik = omega_i - omega_k
//    "joints": {"12": {"v": ["..", ".."], "a": ["..", ".."]},         // prismatic: the slider's
//               "D": {"v": [..], "a": [..], "sliding_v": "..", "sliding_a": ".."}},  point
//    "points": {"P": {"v": [..], "a": [..]}},
//    "tables": {"fourbar_polygon": {"A_A^n": "(x, y)", ...}},
//    "claims": [{"id": "...", "verdict": "holds", "expected": "holds", "as_expected": true, ...}],
//    "not_applicable": [...], "summary": {...}, "exit_status": 0}
// Numbers are exact reduced "p/q" in exact mode, shortest round-trip decimals otherwise (every
// digit for mp30...). In a floating arithmetic each number has its rigorous bound beside it
// (MechanismCheck, "_bound" members): "omega_bound", "omega_dot_bound" in links and relative;
// "v_bound", "a_bound" ([x, y]) and "sliding_v_bound", "sliding_a_bound" in joints and points,
// each a decimal that reads back to a bound ("inf" when unbounded); absent when exact.
// Claim entries are those of the polygon check (report/json_report.h).
#pragma once

#include <nlohmann/json.hpp>

#include <ostream>

#include "mechanism/mechanism_catalogue.h"
#include "report/claims_status.h"
#include "report/number_text.h"

namespace linkproof {

/// `status` (every function below): the program's decisions on the claims
/// (report/claims_status.h), printed, never made here: the exit status, and with --strict the
/// marks of claims not as expected under that policy.
nlohmann::json to_json(const MechanismCheck& check, const ClaimsStatus& status);
/// {"holds": n, "fails": n, "undefined": n, "inconclusive": n, "error": n, "unexpected_failures": n};
/// with --strict (status.strict) also "not_as_expected": n and "strict": true.
nlohmann::json claims_summary_json(const std::vector<ClaimOutcome>& claims, const ClaimsStatus& status);
/// The text table of claims: id, verdict, expected, headline evidence; with --strict a claim not
/// as expected under it is marked "<-- NOT AS EXPECTED (strict)".
void write_claim_table(std::ostream& out, const std::vector<ClaimOutcome>& claims, const ClaimsStatus& status);
/// The claim table, the ids not applicable and the exit status (the end of a text report).
void write_claim_section(std::ostream& out, const std::vector<ClaimOutcome>& claims,
                         const std::vector<std::string>& not_applicable, const ClaimsStatus& status);
/// In a floating arithmetic every value is followed by its bound ("value +- bound").
/// Exact values are shown with their decimal to `digits` significant digits beside them.
void write_text(std::ostream& out, const MechanismCheck& check, const ClaimsStatus& status, int digits = kReadableDigits);

}  // namespace linkproof
