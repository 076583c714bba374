#include "report/topology_proof_report.h"

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <fmt/ranges.h>

#include "report/json_report.h"
#include "report/mechanism_claim_report.h"
#include "report/number_text.h"

namespace linkproof {

namespace {

using nlohmann::json;

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

}  // namespace

nlohmann::json to_json(const TopologyProofRun& run, const ClaimsStatus& status) {
  json claims = json::array();
  int ok = 0;
  for (size_t k = 0; k < run.claims.size(); ++k) {
    const TopologyProof& r = run.claims[k];
    ok += status.as_expected[k];
    json except = json::array();
    for (const ExceptionalSet& e : r.except) except.push_back({{"polynomial", e.polynomial}, {"meaning", e.meaning}});
    claims.push_back({{"id", r.info.id},
                      {"source", r.info.source},
                      {"statement", r.info.statement},
                      {"expected", std::string(to_string(r.info.expected))},
                      {"verdict", to_string(r.verdict)},
                      {"as_expected", static_cast<bool>(status.as_expected[k])},
                      {"except", except},
                      {"argument", r.argument},
                      {"samples_compared", r.samples_compared},
                      {"identity_test", r.verdict == ProofVerdict::HoldsWithProbability
                                            ? json{{"trials", r.trials}, {"degree_bound", r.degree_bound},
                                                   {"failure_bound", r.failure_bound}}
                                            : json(nullptr)},
                      {"numerator_terms", r.numerator_terms},
                      {"counterexample", r.counterexample ? to_json(*r.counterexample) : json(nullptr)},
                      {"error", r.error},
                      {"seconds", r.seconds}});
  }
  return {{"mode", "topology_proof"},
          {"topology", run.topology},
          {"coordinates", run.symbols},
          {"relations", run.relations},
          {"velocity_system", {{"unknowns", run.unknowns}, {"det_terms", run.det_terms}, {"note", run.system_note},
                               {"groups", run.groups},
                               {"proof_driver", run.proof_driver.empty() ? json(nullptr)
                                                                         : json{{"link", run.proof_driver},
                                                                                {"groups", run.proof_driver_groups}}}}},
          {"claims", claims},
          {"summary", {{"claims", run.claims.size()}, {"as_expected", ok},
                       {"not_as_expected", static_cast<int>(run.claims.size()) - ok}}},
          {"seconds", run.seconds},
          {"exit_status", status.exit_status}};
}

void write_text(std::ostream& out, const TopologyProofRun& run, const ClaimsStatus& status) {
  int ok = 0;
  for (const bool b : status.as_expected) ok += b;
  fmt::print(out, "{} claim(s) over every configuration of the topology of {}: {} as expected, {} not ({:.3f} s)\n",
             run.claims.size(), run.topology, ok, static_cast<int>(run.claims.size()) - ok, run.seconds);
  fmt::print(out, "coordinates (every value is a configuration): {}\n", joined(run.symbols));
  if (!run.relations.empty()) fmt::print(out, "relations: {}\n", joined(run.relations));
  if (run.det_terms > 0)
    fmt::print(out, "velocity system: {} unknowns in groups of {} (in the order solved, Cramer's rule in each); det A has {} "
               "terms\n", run.unknowns, fmt::join(run.groups, ", "), run.det_terms);
  if (!run.proof_driver.empty())
    fmt::print(out, "proofs with link {} as the driver: groups of {}\n", run.proof_driver, fmt::join(run.proof_driver_groups, ", "));
  if (!run.system_note.empty()) fmt::print(out, "velocity system: {}\n", run.system_note);
  fmt::print(out, "\n");
  for (size_t k = 0; k < run.claims.size(); ++k) {
    const TopologyProof& r = run.claims[k];
    fmt::print(out, "{:18} {}  (expected {}, {:.3f} s){}\n", to_string(r.verdict), r.info.id, to_string(r.info.expected),
               r.seconds, status.as_expected[k] ? "" : "  <-- NOT AS EXPECTED");
    fmt::print(out, "    {}\n", r.info.statement);
    for (const std::string& step : r.argument) fmt::print(out, "    {}\n", step);
    if (!r.error.empty()) fmt::print(out, "    error: {}\n", r.error);
    if (!r.except.empty()) {
      fmt::print(out, "    except where:\n");
      for (const ExceptionalSet& e : r.except) fmt::print(out, "      {} = 0   ({})\n", e.polynomial, e.meaning);
    }
    if (r.counterexample) write_text(out, *r.counterexample);
  }
}

}  // namespace linkproof
