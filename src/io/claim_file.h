// Claim files: claims as reviewable data (YAML). Schema:
//
//   paper: "Dijksman (1966), J. Mechanisms 1:73-81"   # optional: prefixed to every source
//   id_prefix: dijksman1966.                           # optional: prefixed to every id
//   claims:
//     - id: eq22                                       # unique; letters, digits, . _ -
//       source: "sec. 2.2.1, eq. (22)"                 # where in the paper
//       statement: "omega-dot_{n-1,n} = ..."           # in words and symbols
//       expected: holds                                # holds (default) | fails (an erratum reading)
//       note: "..."                                    # optional: what is misread and why it fails
//       n: "4.."                                       # optional: N, "A..B" or "A.." (default "4..")
//       for_each: j                                    # optional: one statement per input j
//       reading: [unsigned_phi]                        # optional: misreadings of the paper (below)
//       lhs: omega_dot_out                             # expressions, vocabulary.h
//       rhs: sum_j(lambda[j]*omega[j]^2 + i_out[j]*omega_dot[j]) - ...
//
// Readings (docs/conventions.md §A5): undisplaced_start (K_j for K'_j), beta_towards_p (P_j for P'_j in
// beta_j), reversed_beta (beta_j > 0 iff clockwise), unsigned_ratios (lengths, not directed
// segments), unsigned_phi (the drawn angle |phi|).
//
// Errors: InputError(source, field, problem); field is "claims[3].rhs" and so on; an error
// inside an expression has source "FILE:LINE:COLUMN" at the offending character.
#pragma once

#include <string>
#include <vector>

#include "claims/data_claim.h"
#include "claims/mechanism_claim.h"

namespace linkproof {

struct ClaimFile {
  std::string source;
  std::vector<DataClaim> claims;
};

/// Parses claim-file text; `source` names it in errors.
ClaimFile parse_claim_file(const std::string& yaml_text, const std::string& source);
/// A user's claim file (its text already read from `path`): parsed, each claim's info.file set,
/// so that a claim that is not well formed is refused as bad input naming the file.
ClaimFile parse_user_claim_file(const std::string& yaml_text, const std::string& path);
/// Reads (with the input size cap) and parses a user's claim file.
ClaimFile load_claim_file(const std::string& path);

/// A claim file about a mechanism (docs/claims.md, "Mechanism claims"): the same schema with the
/// fields id, source, statement, expected, note, lhs and rhs (no n, for_each or reading), the
/// sides in the mechanism vocabulary (claims/vocabulary.h), both of one kind (two
/// numbers or two vectors). Errors name the file, the claim and, inside an expression, its
/// line and column. Names are bound to a scene later (mechanism/mechanism_data_claim.h).
struct MechanismClaimFile {
  std::string source;
  std::vector<MechanismDataClaim> claims;
};

MechanismClaimFile parse_mechanism_claim_file(const std::string& yaml_text, const std::string& source);
/// Reads (with the input size cap) and parses a user's mechanism claim file (info.file set).
MechanismClaimFile load_mechanism_claim_file(const std::string& path);

/// Upper bound on the number of sides a claim may ask for ("4..60"): proofs and sweeps are
/// polynomial in n but not cheap.
constexpr int kMaxClaimSides = 200;

}  // namespace linkproof
