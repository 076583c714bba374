// Reports of the second-order work (mechanism/curvature_analysis.h): JSON and text.
//
// JSON contract (`linkproof curvature SCENE --json`; the same keys are added to `check --json`
// when the scene asks for this work). Exact values are reduced "p/q" strings; a finite pole or
// centre also has "at_decimal" (its coordinates to 10 significant digits) and a centre
// "radius_decimal", beside the exact ones (report/number_text.h).
//   {"scene": "...",
//    "poles": [{"links": ["0", "1"], "at": ["x", "y"]}                 // every pair of links
//              | {"links": [..], "at_infinity": ["dx", "dy"]}          // omega_i = omega_j
//              | {"links": [..], "undefined": "reason"}],              // no relative motion
//    "curvature_centres": [{"point": "23", "moving": "2", "fixed": "4",
//                           "at": ["x", "y"], "radius": "r" | "sqrt(p/q)", "radius_squared": "p/q",
//                           "velocity": [..], "acceleration": [..],    // of the point in moving/fixed
//                           "pole": [..], "inflection_pole": [..], "pole_normal": [..], "pole_tangent": [..],
//                           "bobillier": {"pairs": "...", "version": "A"|"B", "P": [..], "Q_AB": [..],
//                                         "q_AC_direction": [..], "Q_AC": [..], "gamma": [..]}}
//                          | {..., "at_infinity": [..], "reason": ".."} | {..., "undefined": "reason"}],
//    "reductions": [{"link": "2", "bars": ["1", "3"], "order": 2, "I": ["x", "y"],
//                    "new_far": {"1": [..], "3": [..]}, "poles": {"1": [..], "3": [..]},
//                    "velocities_preserved": true, "accelerations_preserved": true}
//                   | {..., "problem": "why the step could not be done"}],
//    "claims": [...], "not_applicable": [...], "summary": {...}, "exit_status": 0}
// A point that is not finite is written {"at_infinity": [..]} or {"undefined": "quantity: reason"}
// wherever a point [x, y] is expected inside `curvature_centres` and `reductions`.
#pragma once

#include <nlohmann/json.hpp>

#include <ostream>

#include "mechanism/curvature_analysis.h"
#include "report/claims_status.h"

namespace linkproof {

/// The keys "poles", "curvature_centres", "reductions" of `analysis` (added to check --json).
nlohmann::json curvature_json(const CurvatureAnalysis& analysis, const std::vector<std::string>& link_names);

/// `status`: the program's decisions on the claims (report/claims_status.h), printed here.
nlohmann::json to_json(const CurvatureCheck& check, const ClaimsStatus& status);
void write_text(std::ostream& out, const CurvatureCheck& check, const ClaimsStatus& status);
/// The text tables of poles, centres and reductions (shared with `check`).
void write_curvature_text(std::ostream& out, const CurvatureAnalysis& analysis, const std::vector<std::string>& link_names);

}  // namespace linkproof
