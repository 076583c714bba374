// Human-readable renderings of check and sweep results: a summary first, then one row per
// claim, then the term-by-term tables and the reasons for every undefined or failing claim.
#pragma once

#include <ostream>

#include "check/check_polygon.h"
#include "check/sweep.h"

namespace linkproof {

void write_text(std::ostream& out, const PolygonCheck& check, bool show_terms = true);
void write_text(std::ostream& out, const SweepReport& sweep);

}  // namespace linkproof
