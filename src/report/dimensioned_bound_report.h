// Reports of the bound on how far a rationalised scene's results may be from those at its
// dimensioned values (MechanismCheck::dimensioned, mechanism/dimensioned_bound.h).
//
// JSON (`check --json`, key "dimensioned_bound", present only for a rationalised scene; every
// other key is unchanged):
//   "dimensioned_bound": {"bounded": true, "reason": null, "digits": 100,
//     "summary": {"omega": "3.1e-55", "omega_dot": "...", "v": "...", "a": "...",
//                 "sliding_v": "...", "sliding_a": "..."},
//     "links":  {"coupler": {"omega": "...", "omega_dot": "..."}, ...},          // moving links
//     "joints": {"B": {"v": "...", "a": "..."},                                  // per coordinate
//                "D": {"v": .., "a": .., "sliding_v": .., "sliding_a": ..,         // prismatic:
//                      "sliding_v_unit": .., "sliding_a_unit": .., "coriolis": ..}},  as its keys
//     "points": {"P": {"v": "...", "a": "..."}}}
// Each bound is a decimal that reads back to a double >= the bound (as the "_bound" keys of
// report/mechanism_report.h), "inf" where not bounded; "reason" says why then.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

#include "linkproof/mechanism/mechanism_check.h"

namespace linkproof {

nlohmann::json dimensioned_bound_json(const DimensionedBound& b);

/// One line: "distance to the dimensioned values: omega <= 3.1e-55, alpha <= ..., point v <= ...,
/// a <= ... (...)", or "distance to the dimensioned values: not bounded (reason)".
std::string dimensioned_bound_summary(const DimensionedBound& b);

/// b rounded up to two significant digits, "3.1e-55"; "unbounded" for +inf.
std::string bound_short_text(double b);

}  // namespace linkproof
