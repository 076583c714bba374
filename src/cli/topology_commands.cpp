// What check-claim and prove share for mechanism claims: the claim file read for a mechanism
// scene, and the proof over every configuration of its topology (`prove --file CLAIMS
// --topology SCENE`, `check-claim CLAIMS --topology SCENE`).
#include <ostream>

#include "command.h"
#include "exit_status.h"
#include "io/claim_file.h"
#include "mechanism/mechanism_data_claim.h"
#include "report/json_report.h"
#include "report/topology_proof_report.h"

namespace linkproof::cli {

// The claim file read for a mechanism scene and bound to its names. A polygon claim file is
// named as such (the scene is the other half of the mismatch).
std::vector<MechanismDataClaim> mechanism_claims_for(const std::string& file, const MechanismScene& scene,
                                                     const std::string& scene_path) {
  MechanismClaimFile claims;
  try {
    claims = load_mechanism_claim_file(file);
  } catch (const InputError& e) {
    bool polygon_file = false;
    try {
      load_claim_file(file);
      polygon_file = true;
    } catch (const InputError&) {
    }
    if (!polygon_file) throw;
    throw InputError(scene_path, "mechanism",
                     "this is a mechanism scene (top-level `mechanism`), and " + file +
                         " is a claim file about polygons (" + e.source() + ": " + e.problem() +
                         "); mechanism claims use omega(L), pos(P), vel(P, L), ... (check-claim --vocabulary)");
  }
  for (MechanismDataClaim& c : claims.claims) bind_mechanism_claim(c, scene);
  return std::move(claims.claims);
}

int run_topology_proof(const MechanismScene& scene, const std::vector<MechanismDataClaim>& claims,
                       const TopologyProofOptions& options, bool json, bool strict, std::ostream& out) {
  const TopologyProofRun run = prove_topology(scene, claims, options);
  const ClaimsStatus status = topology_proof_status(run, strict);
  if (json)
    out << json_text(to_json(run, status)) << "\n";
  else
    write_text(out, run, status);
  return status.exit_status;
}

}  // namespace linkproof::cli
