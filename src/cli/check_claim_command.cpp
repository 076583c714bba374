// linkproof check-claim FILE.yaml [--n A..B] [--count N] [--seed S] [--scene SCENE [--arith A]] [--json]
// linkproof check-claim FILE.yaml --scene MECHANISM_SCENE [--json]
// linkproof check-claim FILE.yaml --topology MECHANISM_SCENE [--count K [--arith A]] [--seed S] [--proof-seconds S] [--json]
// linkproof check-claim --vocabulary
//
// Mechanism claims (docs/claims.md, "Mechanism claims"): with a mechanism scene, FILE is read in
// the mechanism vocabulary; --scene judges every claim on the scene's exact solution, --topology
// proves it over every configuration of the scene's topology (proof/mechanism_proof.h), or with
// --count K judges it on K random configurations, exactly or in --arith A with derived error
// bounds (holds_on_samples, not a proof, or disproved with a shrunk exact counterexample scene).
//
// A user's claims: proved for every n (symbolic, with the exceptional set), proved for the
// given n, holding on every random exact instance (no proof found), or failing with an exact
// counterexample shrunk to small integer coordinates and rates, and the terms that differ.
#include <fmt/format.h>
#include <fmt/ostream.h>

#include "cli.h"
#include "command.h"
#include "io/claim_file.h"
#include "linkproof/io/mechanism_scene.h"
#include "mechanism/mechanism_data_claim.h"
#include "proof/mechanism_sampling.h"
#include "report/mechanism_claim_report.h"
#include "report/mechanism_report.h"
#include "claims/vocabulary.h"
#include "check/random_polygon.h"
#include "linkproof/io/scene.h"
#include "report/json_report.h"
#include "report/prove_report.h"
#include "report/scene_placement_report.h"
#include "report/text_report.h"
#include "check/check_polygon.h"

namespace linkproof::cli {

namespace {

struct CheckClaimArgs {
  std::string file;
  std::string n_range;
  int count = 20;
  std::uint64_t seed = 1;
  std::string scene;
  std::string topology;
  bool count_given = false;
  double proof_seconds = 60;
  std::string arith = "exact";
  std::optional<double> ladder_seconds;  // given: per-n proofs also re-check claims proved for every n
  bool json = false;
  bool vocabulary = false;
  bool strict = false;
};

// The one vocabulary table, the words of each language in turn.
void print_vocabulary(std::ostream& out) {
  const auto print = [&out](Language language) {
    for (const Word& w : vocabulary())
      if (w.belongs_to(language)) fmt::print(out, "{:24} {}\n", w.signature, w.meaning);
  };
  print(Language::Polygon);
  fmt::print(out, "\nmechanism claims (with --scene or --topology MECHANISM_SCENE; L, M links, P a joint or point, J a "
                  "prismatic joint; names bare or quoted):\n");
  print(Language::Mechanism);
}

int run_mechanism_claims(const CheckClaimArgs& a, const std::string& scene_path, bool topology, std::ostream& out) {
  // A proof and a scene's check are exact; random configurations may be judged in any
  // arithmetic (floating point with derived error bounds).
  if (a.arith != "exact" && !(topology && a.count_given))
    throw InputError("<command line>", "--arith",
                     "mechanism claims are evaluated exactly, except on random configurations of a topology "
                     "(--topology SCENE --count K --arith A)");
  if (!a.n_range.empty()) throw InputError("<command line>", "--n", "applies to polygon claims, not to a mechanism scene");
  const MechanismScene scene = load_mechanism_scene(scene_path);
  const std::vector<MechanismDataClaim> claims = mechanism_claims_for(a.file, scene, scene_path);
  if (!topology) {
    if (a.count_given) throw InputError("<command line>", "--count", "applies to --topology, not to --scene");
    std::vector<MechanismClaim> run;
    for (const MechanismDataClaim& c : claims) run.push_back(to_mechanism_claim(c));
    const MechanismCheck check = check_mechanism_claims(scene, run);
    const ClaimsStatus status = claims_status(check.claims, a.strict);
    // Positions placed from dimensions are said, as `check` says them: the claims are judged
    // exactly at the rationalised positions, so a claim about the dimensions themselves may fail
    // there by less than the rationalisation.
    if (a.json) {
      nlohmann::json j = to_json(check, status);
      j.update(scene_placement_json(scene));
      out << json_text(j) << "\n";
    } else {
      write_scene_placement_text(out, scene);
      write_text(out, check, status);
    }
    return status.exit_status;
  }
  if (a.count < 1 || a.count > 100000) throw InputError("<command line>", "--count", "must be between 1 and 100000");
  if (!a.count_given) {  // a proof for every configuration; the samples only where none is made
    TopologyProofOptions o;
    o.seconds = a.proof_seconds;
    o.sampling.count = a.count;
    o.sampling.seed = a.seed;
    return run_topology_proof(scene, claims, o, a.json, a.strict, out);
  }
  TopologySampling o;
  o.count = a.count;
  o.seed = a.seed;
  o.arithmetic = arithmetic_or_throw(a.arith);
  const TopologySampleRun run = sample_topology(scene, claims, o);
  const ClaimsStatus status = sampling_status(run, a.strict);
  if (a.json)
    out << json_text(to_json(run, status)) << "\n";
  else
    write_text(out, run, status);
  return status.exit_status;
}

/// No symbolic form: the claim on `count` random exact polygons per n, judged in `arith`. Only
/// evaluations that produced a comparison count towards holds_on_samples; undefined and
/// inconclusive ones are counted apart, an evaluation error makes the result an error, and a
/// failure is a counterexample (in floating point too: `fails` means the exact sides differ).
void sample(GroundTruthEngine& engine, const DataClaim& c, int lo, int hi, const CheckClaimArgs& a, Arithmetic arith,
            ProofResult& r) {
  const std::vector<Claim> claim{to_claim(c)};
  int inconclusive = 0;
  for (int n = std::max(lo, c.info.min_n); n <= hi && (c.info.max_n == 0 || n <= c.info.max_n); ++n)
    for (int i = 0; i < a.count; ++i) {
      const auto rc = generate_random_polygon(a.seed, n, i);
      const PolygonCheck check = check_polygon(engine, claim, "sample", rc.polygon, rc.rates, arith);
      const ClaimOutcome& o = check.claims.front();
      ++r.samples;
      switch (o.verdict) {
        case Verdict::Holds: ++r.samples_compared; break;
        case Verdict::Undefined: ++r.samples_undefined; break;
        case Verdict::Inconclusive: ++inconclusive; break;
        case Verdict::Error:
          r.verdict = ProofVerdict::Error;
          r.error = fmt::format("sample {} at n = {} (seed {}): the evaluation failed: {}", i, n, a.seed, o.error);
          return;
        case Verdict::Fails: {
          CounterexampleSearch s;
          s.n_min = std::max(lo, c.info.min_n);
          s.n_max = n;
          s.seed = a.seed;
          r.counterexample = find_counterexample(engine, c, s);
          if (!r.counterexample) {  // the random polygon itself, unshrunk
            Counterexample cx{rc.polygon, rc.rates, o, r.samples, 0, 0, ""};
            cx.scene_yaml = polygon_scene_to_yaml(PolygonScene{"counterexample-" + c.info.id, "", rc.polygon, rc.rates});
            r.counterexample = cx;
          }
          r.verdict = ProofVerdict::Disproved;
          return;
        }
      }
    }
  // K = the comparisons that really ran; fewer than --count of them supports no verdict.
  if (r.samples_compared < a.count) {
    r.verdict = ProofVerdict::Error;
    r.error = fmt::format("only {} of {} samples produced a comparison ({} undefined, {} inconclusive): too few to "
                          "say the claim holds",
                          r.samples_compared, r.samples, r.samples_undefined, inconclusive);
    return;
  }
  r.verdict = ProofVerdict::HoldsOnSamples;
  r.scope = fmt::format("{} exact random polygons compared, n = {}..{} ({} undefined, {} inconclusive)",
                        r.samples_compared, std::max(lo, c.info.min_n),
                        c.info.max_n ? std::min(hi, c.info.max_n) : hi, r.samples_undefined, inconclusive);
}

int run_check_claim(const CheckClaimArgs& a, std::ostream& out, std::ostream&) {
  if (a.vocabulary) {
    print_vocabulary(out);
    return kAsExpected;
  }
  if (a.file.empty()) throw InputError("<command line>", "FILE", "a claim file is required (or --vocabulary)");
  if (!a.topology.empty()) {
    if (!a.scene.empty()) throw InputError("<command line>", "--topology", "give --scene or --topology, not both");
    return run_mechanism_claims(a, a.topology, true, out);
  }
  if (!a.scene.empty() && is_mechanism_scene_text(read_scene_text(a.scene))) return run_mechanism_claims(a, a.scene, false, out);
  // Proofs, the counterexample search and its shrinking are exact whatever --arith says; it sets
  // the arithmetic of the --scene check and of the random instances judged when no proof exists.
  const Arithmetic arith = arithmetic_or_throw(a.arith);
  const ClaimFile file = load_claim_file(a.file);
  GroundTruthEngine engine;
  if (!a.scene.empty()) {  // every claim on one configuration, as `check` does
    const PolygonScene scene = load_polygon_scene(a.scene);
    std::vector<Claim> claims;
    for (const auto& c : file.claims) claims.push_back(to_claim(c));
    const PolygonCheck check = check_polygon(engine, claims, scene.name, scene.polygon, scene.rates, arith);
    const ClaimsStatus status = claims_status(check.claims, a.strict);
    if (a.json)
      out << json_text(to_json(check, status)) << "\n";
    else
      write_text(out, check, status, true);
    return status.exit_status;
  }
  if (a.count < 1 || a.count > 100000) throw InputError("<command line>", "--count", "must be between 1 and 100000");
  int lo = 4, hi = 12;
  if (!a.n_range.empty()) std::tie(lo, hi) = parse_n_range(a.n_range, "--n", 4, kMaxClaimSides);
  std::vector<ProofResult> results;
  for (const DataClaim& c : file.claims) {
    ProveOptions o;
    set_ladder(o, a.ladder_seconds, !a.n_range.empty() && lo != hi);
    o.search.seed = a.seed;
    o.search.n_min = lo;
    o.search.n_max = std::max(lo, std::min(hi, 8));
    if (!a.n_range.empty() && lo == hi) o.only_n = lo;
    check_prove_limits(o.only_n, o.ladder_seconds);
    if (!a.n_range.empty() && lo != hi) o.n_max = hi;
    ProofResult r = prove_claim(engine, c, o);
    // Only a claim with no symbolic form is sampled; any other error stays an error.
    if (r.verdict == ProofVerdict::Error && !r.symbolic) {
      const std::string why = r.error;
      r.error.clear();
      sample(engine, c, lo, hi, a, arith, r);
      if (r.verdict == ProofVerdict::HoldsOnSamples) r.argument.push_back("no proof: " + why);
    }
    results.push_back(std::move(r));
  }
  const ClaimsStatus status = proofs_status(results, a.strict);
  report_proofs(out, results, a.json, status);
  return status.exit_status;
}

}  // namespace

void add_check_claim_command(CLI::App& app, Action& action) {
  auto* c = app.add_subcommand("check-claim", "prove or disprove your own claims (a claim file, see docs/claims.md)");
  auto& a = bind_action<CheckClaimArgs>(c, action, run_check_claim);
  c->add_option("file", a.file, "claim file (YAML)");
  c->add_option("--n", a.n_range, "sides: N (prove for this n) or A..B (default: every n, searching 4..8)");
  c->add_option("--count", a.count,
                "random exact instances per n when no proof is found; with --topology, configurations per claim "
                "(default 20)")
      ->each([&a](const std::string&) { a.count_given = true; });
  c->add_option("--seed", a.seed, "seed of the counterexample search and the samples (default 1)")
      ->check(seed_validator());
  c->add_option("--scene", a.scene,
                "check the claims on this scene only (in the arithmetic of --arith); a mechanism scene takes mechanism "
                "claims (exact)");
  c->add_option("--topology", a.topology,
                "mechanism claims over every configuration of this mechanism scene's topology: proved, "
                "proved_generically (with the exceptional set) or disproved with a shrunk counterexample scene; with "
                "--count K only K random exact configurations (holds_on_samples, not a proof)");
  c->add_option("--proof-seconds", a.proof_seconds,
                "with --topology: time for the symbolic proof per claim (default 60); past it the claim is judged "
                "on --count random configurations")
      ->check(seconds_validator(kMaxClaimLadderSeconds));
  c->add_option("--arith", a.arith,
                "arithmetic of the --scene check and of the random instances judged when no proof is found: "
                "exact (default), double, long-double, mp30, mp50, mp100, mp1000 (see check --help); proofs and "
                "counterexample shrinking are exact");
  c->add_option("--ladder-seconds", a.ladder_seconds,
                "time for per-n proofs per claim (default 1, where a proof leaves part of the range uncovered; "
                "given, or with --n LO..HI, they also re-check claims proved for every n)")
      ->check(seconds_validator());
  c->add_flag("--vocabulary", a.vocabulary, "print the names a claim may use");
  c->add_flag("--json", a.json, "print JSON");
  c->add_flag("--strict", a.strict,
              "only a proof for the claim's whole range is as expected for a true claim (proved_for and "
              "holds_on_samples then exit 1; with --scene: undefined or inconclusive on a true claim fails)");
}

}  // namespace linkproof::cli
