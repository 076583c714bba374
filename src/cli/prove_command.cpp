// linkproof prove [--claim ID] [--n N] [--file CLAIMS.yaml] [--ladder-seconds S] [--json] [--strict]
// linkproof prove --file CLAIMS.yaml --topology MECHANISM_SCENE [--claim ID] [--proof-seconds S]
//                 [--count K] [--seed S] [--json] [--strict]
//   mechanism claims over every configuration of the scene's topology (proof/mechanism_proof.h)
#include <optional>

#include "command.h"
#include "dijksman1966.h"
#include "linkproof/io/mechanism_scene.h"
#include "report/prove_report.h"

namespace linkproof::cli {

namespace {

struct ProveArgs {
  std::vector<std::string> claims;
  std::optional<int> n;
  std::string file;
  std::optional<double> ladder_seconds;  // given: per-n proofs also re-check claims proved for every n
  int n_max = 0;
  bool json = false;
  bool strict = false;
  std::string topology;
  double proof_seconds = 60;
  int count = 20;
  std::uint64_t seed = 1;
};

int run_topology(const ProveArgs& a, std::ostream& out) {
  if (a.file.empty()) throw InputError("<command line>", "--topology", "needs --file CLAIMS: the mechanism claims to prove");
  if (a.n) throw InputError("<command line>", "--n", "applies to polygon claims, not to a mechanism topology");
  if (a.count < 1 || a.count > 100000) throw InputError("<command line>", "--count", "must be between 1 and 100000");
  const MechanismScene scene = load_mechanism_scene(a.topology);
  std::vector<MechanismDataClaim> claims = mechanism_claims_for(a.file, scene, a.topology);
  if (!a.claims.empty()) {
    std::vector<MechanismDataClaim> chosen;
    for (const std::string& id : a.claims) {
      const auto it = std::find_if(claims.begin(), claims.end(), [&](const MechanismDataClaim& c) {
        return c.info.id == id || (c.info.id.size() > id.size() && c.info.id.ends_with("." + id));
      });
      if (it == claims.end()) throw InputError("<command line>", "--claim", "no claim '" + id + "' in " + a.file);
      chosen.push_back(*it);
    }
    claims = std::move(chosen);
  }
  TopologyProofOptions o;
  o.seconds = a.proof_seconds;
  o.sampling.count = a.count;
  o.sampling.seed = a.seed;
  return run_topology_proof(scene, claims, o, a.json, a.strict, out);
}

int run_prove(const ProveArgs& a, std::ostream& out, std::ostream&) {
  if (!a.topology.empty()) return run_topology(a, out);
  const ClaimFile file = a.file.empty() ? dijksman1966::claim_file() : load_claim_file(a.file);
  ProveOptions o;
  check_prove_limits(a.n, a.ladder_seconds.value_or(o.ladder_seconds));
  const std::vector<const DataClaim*> chosen = choose_claims(file, a.claims);
  o.only_n = a.n;
  o.n_max = a.n_max;
  set_ladder(o, a.ladder_seconds, a.n_max > 0);
  GroundTruthEngine engine;
  std::vector<ProofResult> results;
  for (const DataClaim* c : chosen) {
    if (a.n && !c->info.applies_to(*a.n)) continue;
    results.push_back(prove_claim(engine, *c, o));
  }
  if (results.empty()) throw InputError("<command line>", "--n", "no chosen claim applies to n = " + std::to_string(*a.n));
  const ClaimsStatus status = proofs_status(results, a.strict);
  report_proofs(out, results, a.json, status);
  return status.exit_status;
}

}  // namespace

void add_prove_command(CLI::App& app, Action& action) {
  auto* p = app.add_subcommand("prove", "prove claims in symbolic coordinates (for every n, or for one n); disprove errata with exact counterexamples");
  auto& a = bind_action<ProveArgs>(p, action, run_prove);
  p->add_option("--claim", a.claims, "claim id (repeatable; default: every claim), e.g. dijksman1966.eq22 or eq22");
  p->add_option("--n", a.n, "prove for this number of sides only");
  p->add_option("--file", a.file, "claim file (default: the bundled verify/claims/dijksman1966.yaml)");
  p->add_option("--ladder-seconds", a.ladder_seconds,
                "time for per-n proofs n = 4, 5, ... per claim (default 1: where a proof leaves part of the range "
                "uncovered; given, or with --n-max, they also re-check claims proved for every n)")
      ->check(seconds_validator());
  p->add_option("--n-max", a.n_max, "stop the per-n ladder at this n")
      ->check(int_range_validator(4, kMaxClaimSides));
  p->add_option("--topology", a.topology,
                "prove the mechanism claims of --file over every configuration of this mechanism scene's topology");
  p->add_option("--proof-seconds", a.proof_seconds,
                "with --topology: time for the symbolic proof per claim (default 60); past it the claim is judged on "
                "--count random exact configurations (holds_on_samples)")
      ->check(seconds_validator(kMaxClaimLadderSeconds));
  p->add_option("--count", a.count, "with --topology: random exact configurations when no proof is made (default 20)");
  p->add_option("--seed", a.seed, "with --topology: seed of the counterexample search and the samples (default 1)")
      ->check(seed_validator());
  p->add_flag("--json", a.json, "print JSON (the contract in docs/claims.md)");
  p->add_flag("--strict", a.strict,
              "only a proof for the claim's whole range is as expected for a true claim (proved_for and "
              "holds_on_samples then exit 1): for CI");
}

}  // namespace linkproof::cli
