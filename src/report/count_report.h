// Text and JSON renderings of counting claims (`linkproof count`).
//
// JSON (a contract, see README.md "linkproof count"):
//   {"subject": "...",
//    "claims": [{"id", "verdict": "proved"|"disproved"|"error", "expected", "as_expected",
//                "statement", "expected_value", "observed_value", "reason",
//                "relations"?, "unknowns"?, "rank"?, "augmented_rank"?, "consistent"?,
//                "seconds"?}],          // the last six when the claim is a rank
//    "notes": ["..."],
//    "summary": {"proved": P, "disproved": D, "error": E, "seconds": total},
//    "exit_status": 0|1}
// "rank"/"augmented_rank" are those of the whole system the claim was ranked in (e.g. the
// triangle relations followed by a family); "observed_value" is the rank compared with the
// claim (e.g. taken modulo the triangle relations).
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>

#include "count/count_claim.h"
#include "report/claims_status.h"

namespace linkproof {

nlohmann::json to_json(const CountClaim& c);
/// `status`: the program's decisions (report/claims_status.h): each claim's "as_expected" (with
/// --strict, holds_on_samples is not) and the "exit_status" key.
nlohmann::json to_json(const CountReport& r, const ClaimsStatus& status);

/// A table: verdict, id, expected, observed, relations x unknowns, time; then the notes and
/// the statements of every claim that is not as expected.
void write_text(std::ostream& out, const CountReport& r, const ClaimsStatus& status);

}  // namespace linkproof
