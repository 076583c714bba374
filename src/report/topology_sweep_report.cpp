#include "report/topology_sweep_report.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "report/json_report.h"
#include "report/mechanism_claim_report.h"

namespace linkproof {

namespace {

using nlohmann::json;

std::string evaluation(const TopologySweepIdentity& id) {
  return id.arithmetic == Arithmetic::Exact
             ? std::string("exact evaluation")
             : fmt::format("evaluation in {} with derived error bounds (a failure confirmed exactly)",
                           to_string(id.arithmetic));
}

std::string rests_on(const TopologySweepIdentity& id) {
  return fmt::format("{} of every claim on the random configurations 0..{} of the topology of {} (seed {}; "
                     "small-integer positions, rational unit axes, rational input rates; --count is the number of "
                     "configurations drawn); holds_on_samples is NOT a proof for every configuration",
                     evaluation(id), id.count - 1, id.topology, id.seed);
}

std::string scope(const SampleResult& r, const TopologySweepClaim& x, const TopologySampleRun& run,
                  const TopologySweepIdentity& id) {
  switch (r.verdict) {
    case TopologyVerdict::HoldsOnSamples:
      return fmt::format("{} on {} of the {} configurations drawn ({} singular, {} undefined{}); not a proof",
                         id.arithmetic == Arithmetic::Exact
                             ? std::string("exactly equal")
                             : fmt::format("equal within the derived error bound in {}", to_string(id.arithmetic)),
                         r.compared, run.generated, run.singular, r.undefined, inconclusive_note(r));
    case TopologyVerdict::Disproved:
      return fmt::format("the sides differ on {} of the {} configurations drawn, the first being configuration {} "
                         "(compared equal on {}); shrunk in {} steps",
                         x.fails, run.generated, r.counterexample->configuration, r.compared,
                         r.counterexample->shrink_steps);
    case TopologyVerdict::Inconclusive:
      return fmt::format("no comparison decided on the {} configurations solved{}", run.solved, inconclusive_note(r));
    case TopologyVerdict::Undefined:
      return r.undefined == 0 ? fmt::format("nothing compared: none of the {} configurations drawn was solved",
                                            run.generated)
                              : fmt::format("undefined on every one of the {} configurations solved: {} ({}){}",
                                            r.undefined, r.undefined_quantity, r.undefined_reason,
                                            inconclusive_note(r));
  }
  return "";
}

json report_json(const TopologySweepReport& report, const TopologySweepIdentity& id, const Shard& shard,
                 const ClaimsStatus& status) {
  const TopologySampleRun& run = report.run;
  json claims = json::array();
  int ok = 0;
  for (size_t k = 0; k < run.claims.size(); ++k) {
    const SampleResult& r = run.claims[k];
    const TopologySweepClaim& x = report.claims[k];
    ok += status.as_expected[k];
    json c = sample_claim_json(r, status.as_expected[k], scope(r, x, run, id));
    c["failing_configurations"] = x.fails;
    c["first_failing_configuration"] = x.first_failing_case ? json(*x.first_failing_case) : json(nullptr);
    claims.push_back(std::move(c));
  }
  json j = identity_json(id);
  j.update({{"mode", "topology_sweep"},
            {"configurations", {{"generated", run.generated}, {"singular_skipped", run.singular},
                                {"solved", run.solved}, {"degenerate_failures_skipped", run.degenerate}}},
            {"rests_on", rests_on(id)},
            {"claims", claims},
            {"summary", {{"claims", run.claims.size()}, {"as_expected", ok},
                         {"not_as_expected", static_cast<int>(run.claims.size()) - ok}}},
            {"exit_status", status.exit_status}});
  if (!shard.whole()) j["shard"] = fmt::format("{}/{}", shard.k, shard.n);
  return j;
}

}  // namespace

json to_json(const TopologySweepReport& report, const TopologySweepIdentity& id, const Shard& shard,
             const ClaimsStatus& status, double seconds) {
  json j = report_json(report, id, shard, status);
  j["seconds"] = seconds;
  return j;
}

std::string topology_summary_line(const TopologySweepReport& report, const TopologySweepIdentity& id,
                                  const Shard& shard, const ClaimsStatus& status) {
  return json{{"summary", report_json(report, id, shard, status)}}.dump();
}

void write_text(std::ostream& out, const TopologySweepReport& report, const TopologySweepIdentity& id,
                const Shard& shard, const ClaimsStatus& status, double seconds) {
  const TopologySampleRun& run = report.run;
  int ok = 0;
  for (const bool b : status.as_expected) ok += b;
  fmt::print(out, "{} claim(s) on {} random configurations of the topology of {}{}: {} as expected, {} not\n",
             run.claims.size(), id.count, id.topology,
             shard.whole() ? std::string() : fmt::format(" (shard {}/{})", shard.k, shard.n), ok,
             static_cast<int>(run.claims.size()) - ok);
  fmt::print(out, "configurations: {} drawn, {} skipped (singular velocity system{}), {} solved; seed {}; {}; {:.3f} s\n",
             run.generated, run.singular, id.arithmetic == Arithmetic::Exact ? "" : " or undecided in floating point",
             run.solved, id.seed, to_string(id.arithmetic), seconds);
  if (run.degenerate > 0)
    fmt::print(out, "{} failure(s) skipped on degenerate configurations the scene reader refuses\n", run.degenerate);
  fmt::print(out, "rests on: {}\n\n", rests_on(id));
  for (size_t k = 0; k < run.claims.size(); ++k) {
    const SampleResult& r = run.claims[k];
    fmt::print(out, "{:18} {}  (expected {}){}\n", to_string(r.verdict), r.info.id, to_string(r.info.expected),
               status.as_expected[k] ? "" : "  <-- NOT AS EXPECTED");
    fmt::print(out, "    {}\n    {}\n", r.info.statement, scope(r, report.claims[k], run, id));
    if (r.counterexample) write_text(out, *r.counterexample);
  }
}

}  // namespace linkproof
