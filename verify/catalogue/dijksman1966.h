// The claims of Dijksman (1966), "Graphic method to determine the angular acceleration of links
// of compound mechanisms", J. Mechanisms 1, 73-81 (1966), with the conventions and errata
// of docs/conventions.md part A. They live as data in verify/claims/dijksman1966.yaml (one entry per
// equation; the erratum readings of conventions §A5 beside the correct ones with `expected: fails`),
// embedded into this library at build time.
//
// Claim ids: dijksman1966.eqN (eq4 ... eq22, eq9a, eq6.sum), dijksman1966.sec3,
// dijksman1966.companion, and <id>.<reading> for erratum readings (printed, unsigned_phi,
// j_lt_l, reversed_beta, unsigned_ratio).
#pragma once

#include <vector>

#include "claims/claim.h"
#include "io/claim_file.h"

namespace linkproof::dijksman1966 {

/// The claim file as data (parsed once).
const ClaimFile& claim_file();

/// Every claim of the paper and every erratum reading, in equation order, ready to check.
const std::vector<Claim>& catalogue();

}  // namespace linkproof::dijksman1966
