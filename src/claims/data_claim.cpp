#include "claims/data_claim.h"

#include <memory>

namespace linkproof {

Claim to_claim(const DataClaim& claim) {
  // One shared copy for the seven per-arithmetic functions (a DataClaim holds GiNaC trees and
  // strings; the counterexample search makes a Claim per candidate polygon).
  auto shared = std::make_shared<const DataClaim>(claim);
  return Claim::make(claim.info, [shared](const auto& context) { return evaluate_data_claim(*shared, context); });
}

}  // namespace linkproof
