// Human-readable renderings of check and sweep results: a summary first, then one row per
// claim, then the term-by-term tables and the reasons for every undefined or failing claim.
#pragma once

#include <ostream>

#include "check/check_polygon.h"
#include "check/sweep.h"
#include "report/claims_status.h"
#include "report/number_text.h"

namespace linkproof {

/// `status`: the program's decisions (report/claims_status.h): each claim's "<-- UNEXPECTED"
/// mark and the summary's count of claims not as expected follow its policy. Exact rates and D are
/// shown with their decimal to `digits` significant digits beside them (report/number_text.h).
void write_text(std::ostream& out, const PolygonCheck& check, const ClaimsStatus& status, bool show_terms = true,
                int digits = kReadableDigits);
void write_text(std::ostream& out, const SweepReport& sweep);

}  // namespace linkproof
