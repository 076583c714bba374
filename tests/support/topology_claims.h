// Helpers of the topology-proof tests: paths in the source tree, a claim file's claims bound to a
// mechanism scene, and whether a proof names a dead centre among its exceptions.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include "io/claim_file.h"
#include "mechanism/mechanism_data_claim.h"
#include "proof/mechanism_proof.h"

namespace linkproof::test {

/// A path inside the source tree.
inline std::string source_path(const std::string& rel) { return std::string(LINKPROOF_SOURCE_DIR) + "/" + rel; }

/// Every claim of `f`, bound to `s`.
inline std::vector<MechanismDataClaim> bind_all(MechanismClaimFile f, const MechanismScene& s) {
  for (MechanismDataClaim& c : f.claims) bind_mechanism_claim(c, s);
  return f.claims;
}

/// The claims of `claims_file` whose id is in `ids`, in the file's order, bound to `scene`.
inline std::vector<MechanismDataClaim> bound_claims(const MechanismScene& scene, const std::string& claims_file,
                                                    const std::vector<std::string>& ids) {
  MechanismClaimFile file = load_mechanism_claim_file(claims_file);
  std::vector<MechanismDataClaim> claims;
  for (MechanismDataClaim& c : file.claims)
    if (std::find(ids.begin(), ids.end(), c.info.id) != ids.end()) {
      bind_mechanism_claim(c, scene);
      claims.push_back(c);
    }
  return claims;
}

/// det A = 0 (a dead centre or change point) is among the proof's exceptions.
inline bool names_dead_centre(const TopologyProof& p) {
  return std::any_of(p.except.begin(), p.except.end(),
                     [](const auto& e) { return e.meaning.find("dead centre") != std::string::npos; });
}

}  // namespace linkproof::test
