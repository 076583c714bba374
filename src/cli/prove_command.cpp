// linkproof prove [--claim ID] [--n N] [--file CLAIMS.yaml] [--ladder-seconds S] [--json] [--strict]
#include <optional>

#include "command.h"
#include "dijksman1966.h"
#include "report/prove_report.h"

namespace linkproof::cli {

namespace {

struct ProveArgs {
  std::vector<std::string> claims;
  std::optional<int> n;
  std::string file;
  double ladder_seconds = 1.0;
  int n_max = 0;
  bool json = false;
  bool strict = false;
};

int run_prove(const ProveArgs& a, std::ostream& out, std::ostream&) {
  const ClaimFile file = a.file.empty() ? dijksman1966::claim_file() : load_claim_file(a.file);
  check_prove_limits(a.n, a.ladder_seconds);
  const std::vector<const DataClaim*> chosen = choose_claims(file, a.claims);
  ProveOptions o;
  o.only_n = a.n;
  o.ladder_seconds = a.ladder_seconds;
  o.n_max = a.n_max;
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
  p->add_option("--ladder-seconds", a.ladder_seconds, "time for per-n proofs n = 4, 5, ... per claim (default 1)")
      ->check(seconds_validator());
  p->add_option("--n-max", a.n_max, "stop the per-n ladder at this n")
      ->check(int_range_validator(4, kMaxClaimSides));
  p->add_flag("--json", a.json, "print JSON (the contract in docs/claims.md)");
  p->add_flag("--strict", a.strict,
              "only a proof for the claim's whole range is as expected for a true claim (proved_for and "
              "holds_on_samples then exit 1): for CI");
}

}  // namespace linkproof::cli
