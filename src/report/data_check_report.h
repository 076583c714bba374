// Reports of `linkproof check-data` (numerics/data_check.h): JSON and text.
//
// JSON contract (`linkproof check-data SCENE DATA.csv --json`):
//   {"scene": "...", "data": "...", "links": ["ground", "AB", ...], "tolerance_rule": "...",
//    "samples": [
//      {"line": 7, "sample": "matlab_0016", "t": "", "input_angle": "-5",
//       "verdict": "agrees" | "differs" | "unsolvable",
//       "consistent": true,                          // positions close the loops within tolerance
//       "closure": {"residual": 1.5e-15, "tolerance": 2.1e-14, "worst": "|BD| of link BCD"},
//       "exact": {"BCD": {"omega": "p/q", "alpha": "p/q", "omega_decimal": "...", "alpha_decimal": "..."}, ...},
//       "checks": [{"link": "EF", "quantity": "alpha", "exact": "-413.33509186405891303824710",  // 25 digits
//                   "user": "-212.328906", "difference": 201.0, "tolerance": 5e-7,
//                   "verdict": "agrees" | "differs"}, ...],
//       "error": "..."}                              // only when the sample cannot be solved
//    ],
//    "summary": {"samples": 8, "agreeing": 5, "differing": 3, "inconsistent": 0, "unsolvable": 0},
//    "exit_status": 1}
// Exact values are reduced "p/q" (and 25-digit decimals); differences and tolerances are doubles.
#pragma once

#include <nlohmann/json.hpp>

#include <ostream>

#include "numerics/data_check.h"

namespace linkproof {

/// `exit_status`: the program's (cli/exit_status.h), printed as the "exit_status" key.
nlohmann::json to_json(const DataCheck& check, int exit_status);
void write_text(std::ostream& out, const DataCheck& check);

}  // namespace linkproof
