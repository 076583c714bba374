#include "dijksman1966.h"

namespace linkproof::embedded {
extern const char* const k_dijksman1966_claims;
}

namespace linkproof::dijksman1966 {

const ClaimFile& claim_file() {
  static const ClaimFile file = parse_claim_file(embedded::k_dijksman1966_claims, "verify/claims/dijksman1966.yaml");
  return file;
}

const std::vector<Claim>& catalogue() {
  static const std::vector<Claim> claims = [] {
    std::vector<Claim> v;
    for (const DataClaim& c : claim_file().claims) v.push_back(to_claim(c));
    return v;
  }();
  return claims;
}

}  // namespace linkproof::dijksman1966
