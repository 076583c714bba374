// The result file of a sweep of a mechanism topology (`sweep --topology SCENE --claims CLAIMS
// --out FILE`; proof/topology_sweep.h): JSON Lines, one case per line in case order, then one
// summary line, as for polygon sweeps (report/sweep_lines.h). Field names are a contract
// (docs/sweeps.md, "Sweeps of a mechanism topology"):
//
//   {"arithmetic":"exact","case":7,"claims_digest":"...","count":200,"degenerate":false,
//    "digest":"...","scene_digest":"...","seed":3,"singular":false,"topology":"fourbar-seed001",
//    "verdicts":{"fourbar.coupler_velocity":"holds",...}}
//   {"summary":{ ...the `sweep --topology --json` object without "seconds"..., "shard":"2/4"}}
//
// Every case line names its sweep (the scene's name, the digests of the scene file and of the
// claim file, seed, count, arithmetic), so that a line of another sweep is refused where it is
// read back (--resume, merge). `singular`: the configuration's velocity system is singular (no
// verdicts); `degenerate`: a claim fails on it and the scene reader refuses the configuration
// (its failures are skipped). `digest` is the content hash of report/sweep_lines.h
// (sweep_line_digest), and a line read back must match it and be in canonical form.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "linkproof/check/arithmetic.h"
#include "proof/topology_sweep.h"

namespace linkproof {

/// What names a sweep of a topology: every case line carries it.
struct TopologySweepIdentity {
  std::string topology;       ///< the scene's name
  std::string scene_digest;   ///< sweep_line_digest (FNV-1a, 64 bits) of the scene file's bytes
  std::string claims_digest;  ///< ... of the claim file's bytes
  std::uint64_t seed = 1;
  long count = 0;             ///< K: the configurations drawn
  Arithmetic arithmetic = Arithmetic::Exact;
  bool operator==(const TopologySweepIdentity&) const = default;
};

/// "fourbar-seed001 (scene 1a2b..., claims 3c4d..., seed 3, count 200, exact)", for messages.
std::string describe(const TopologySweepIdentity& id);
/// The identity's keys, as a case line and the --json report write them: topology, scene_digest,
/// claims_digest, seed, count, arithmetic.
nlohmann::json identity_json(const TopologySweepIdentity& id);

/// One case as a result-file line (no trailing newline); `claim_ids` in the claims' order.
std::string topology_case_line(const TopologySweepCase& c, const TopologySweepIdentity& id,
                               const std::vector<std::string>& claim_ids);

/// What one line of a topology result file holds.
struct TopologySweepLine {
  std::optional<TopologySweepCase> sweep_case;  ///< a case line
  TopologySweepIdentity identity;               ///< of a case line
  std::optional<nlohmann::json> summary;        ///< the summary line's object
};

/// Parses one line; InputError naming `file`, "line L" and the field. A case line must carry its
/// digest, match it, be in canonical form, hold every field with its type and no other, and a
/// verdict (holds, fails, undefined, inconclusive) of each of `claim_ids` and of no other claim
/// (none if singular; degenerate only with a failure).
TopologySweepLine parse_topology_line(const std::string& line, const std::string& file, long line_number,
                                      const std::vector<std::string>& claim_ids);

/// Checks that `line` (a case line) is case `expected` of sweep `id`; InputError naming `file`,
/// `where`, both sweeps and the first field that differs: the file belongs to another sweep or
/// shard.
void check_topology_case_identity(const TopologySweepLine& line, long expected, const TopologySweepIdentity& id,
                                  const std::string& file, const std::string& where);

}  // namespace linkproof
