#include "report/mechanism_claim_report.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "report/comparison_text.h"
#include "report/json_report.h"
#include "report/number_text.h"

namespace linkproof {

namespace {

using nlohmann::json;

bool sampled_exactly(const TopologySampleRun& run) { return run.options.arithmetic == Arithmetic::Exact; }

std::string rests_on(const TopologySampleRun& run) {
  return fmt::format("{} on random configurations of the topology of {} (seed {}; small-integer "
                     "positions, rational unit axes, rational input rates); holds_on_samples is NOT a proof for "
                     "every configuration",
                     sampled_exactly(run) ? std::string("exact evaluation")
                                   : fmt::format("evaluation in {} with derived error bounds (a failure confirmed "
                                                 "exactly)",
                                                 to_string(run.options.arithmetic)),
                     run.topology, run.options.seed);
}

std::string scope(const SampleResult& r, const TopologySampleRun& run) {
  switch (r.verdict) {
    case TopologyVerdict::HoldsOnSamples:
      return fmt::format("{} on {} random configuration{}{} ({} undefined{}); not a proof",
                         sampled_exactly(run) ? std::string("exactly equal")
                                       : fmt::format("equal within the derived error bound in {}",
                                                     to_string(run.options.arithmetic)),
                         r.compared, r.compared == 1 ? "" : "s",
                         r.compared < run.options.count ? fmt::format(" (fewer than the {} asked: the {} attempts ran out)",
                                                                      run.options.count, run.generated)
                                                        : "",
                         r.undefined, inconclusive_note(r));
    case TopologyVerdict::Disproved:
      return fmt::format("the sides differ on random configuration {} (compared equal on {} before); shrunk in {} "
                         "steps",
                         r.counterexample->configuration, r.compared, r.counterexample->shrink_steps);
    case TopologyVerdict::Inconclusive:
      return fmt::format("no comparison decided on the {} configurations solved{}", run.solved, inconclusive_note(r));
    case TopologyVerdict::Undefined:
      return fmt::format("undefined on every one of the {} configurations solved: {} ({}){}", r.undefined,
                         r.undefined_quantity, r.undefined_reason, inconclusive_note(r));
  }
  return "";
}

}  // namespace

std::string inconclusive_note(const SampleResult& r) {
  if (r.inconclusive == 0) return "";
  return fmt::format("; {} inconclusive, the first at {}: {}", r.inconclusive, r.first_inconclusive->label,
                     reason_text(*r.first_inconclusive));
}

nlohmann::json to_json(const MechanismCounterexample& x) {
  return {{"configuration", x.configuration},
          {"shrink_steps", x.shrink_steps},
          {"shrink_tried", x.shrink_tried},
          {"scene_yaml", x.scene_yaml},
          {"check", to_json(x.outcome)}};
}

void write_text(std::ostream& out, const MechanismCounterexample& x) {
  for (const ComparisonOutcome& c : x.outcome.instances)
    fmt::print(out, "    {}: lhs {}  rhs {}  ({})\n", c.label, c.lhs ? readable_number(*c.lhs) : "undefined",
               c.rhs ? readable_number(*c.rhs) : "undefined", to_string(c.verdict));
  fmt::print(out, "    counterexample scene (check-claim CLAIMS --scene FILE re-fails on it):\n");
  std::string line;
  for (char ch : x.scene_yaml) {
    if (ch != '\n') {
      line += ch;
      continue;
    }
    fmt::print(out, "      {}\n", line);
    line.clear();
  }
  if (!line.empty()) fmt::print(out, "      {}\n", line);
}

nlohmann::json sample_claim_json(const SampleResult& r, bool as_expected, const std::string& scope) {
  return {{"id", r.info.id},
          {"source", r.info.source},
          {"statement", r.info.statement},
          {"expected", std::string(to_string(r.info.expected))},
          {"verdict", to_string(r.verdict)},
          {"as_expected", as_expected},
          {"scope", scope},
          {"compared", r.compared},
          {"undefined_configurations", r.undefined},
          {"inconclusive_configurations", r.inconclusive},
          {"undefined", r.undefined_quantity.empty()
                            ? json(nullptr)
                            : json{{"quantity", r.undefined_quantity}, {"reason", r.undefined_reason}}},
          {"counterexample", r.counterexample ? to_json(*r.counterexample) : json(nullptr)}};
}

nlohmann::json to_json(const TopologySampleRun& run, const ClaimsStatus& status) {
  json claims = json::array();
  int ok = 0;
  for (size_t k = 0; k < run.claims.size(); ++k) {
    const SampleResult& r = run.claims[k];
    ok += status.as_expected[k];
    json c = sample_claim_json(r, status.as_expected[k], scope(r, run));
    c["seconds"] = r.seconds;
    claims.push_back(std::move(c));
  }
  return {{"mode", "topology"},
          {"topology", run.topology},
          {"seed", run.options.seed},
          {"count", run.options.count},
          {"arithmetic", std::string(to_string(run.options.arithmetic))},
          {"configurations", {{"generated", run.generated}, {"singular_skipped", run.singular}, {"solved", run.solved},
                              {"degenerate_failures_skipped", run.degenerate}}},
          {"rests_on", rests_on(run)},
          {"claims", claims},
          {"summary", {{"claims", run.claims.size()}, {"as_expected", ok},
                       {"not_as_expected", static_cast<int>(run.claims.size()) - ok}}},
          {"seconds", run.seconds},
          {"exit_status", status.exit_status}};
}

void write_text(std::ostream& out, const TopologySampleRun& run, const ClaimsStatus& status) {
  int ok = 0;
  for (const bool b : status.as_expected) ok += b;
  fmt::print(out, "{} claim(s) on random configurations of the topology of {}: {} as expected, {} not\n",
             run.claims.size(), run.topology, ok, static_cast<int>(run.claims.size()) - ok);
  fmt::print(out, "configurations: {} drawn, {} skipped (singular velocity system{}), {} solved; seed {}, count {}; "
                  "{}{:.3f} s\n",
             run.generated, run.singular, sampled_exactly(run) ? "" : " or undecided in floating point", run.solved,
             run.options.seed, run.options.count,
             sampled_exactly(run) ? std::string() : fmt::format("arithmetic {}; ", to_string(run.options.arithmetic)),
             run.seconds);
  if (run.degenerate > 0)
    fmt::print(out, "{} failure(s) skipped on degenerate configurations the scene reader refuses\n", run.degenerate);
  fmt::print(out, "rests on: {}\n\n", rests_on(run));
  for (size_t k = 0; k < run.claims.size(); ++k) {
    const SampleResult& r = run.claims[k];
    fmt::print(out, "{:18} {}  (expected {}){}\n", to_string(r.verdict), r.info.id, to_string(r.info.expected),
               status.as_expected[k] ? "" : "  <-- NOT AS EXPECTED");
    fmt::print(out, "    {}\n    {}\n", r.info.statement, scope(r, run));
    if (!r.counterexample) continue;
    write_text(out, *r.counterexample);
  }
}

}  // namespace linkproof
