// A claim about a mechanism given as data (a claim file read for a mechanism scene,
// io/claim_file.h): its ClaimInfo and its two sides in the mechanism vocabulary
// (claims/vocabulary.h). Both sides have the same kind: a number claim compares one
// value, a vector claim both components. Evaluated on a solved mechanism by
// mechanism/mechanism_data_claim.h.
#pragma once

#include <string>

#include "claims/mechanism_expression.h"
#include "linkproof/claims/claim_info.h"

namespace linkproof {

struct MechanismDataClaim {
  ClaimInfo info;
  MechanismExpression lhs, rhs;
  std::string field;  ///< "claims[3]" in its file, for messages
};

}  // namespace linkproof
