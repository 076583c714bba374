#include "report/prove_report.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "report/comparison_text.h"
#include "report/json_report.h"

namespace linkproof {

nlohmann::json to_json(const Counterexample& c) {
  nlohmann::json joints = nlohmann::json::array();
  for (int k = 1; k <= c.polygon.n(); ++k)
    joints.push_back({format_rational(c.polygon.joint(k).x), format_rational(c.polygon.joint(k).y)});
  nlohmann::json w = nlohmann::json::array(), wd = nlohmann::json::array();
  for (const auto& q : c.rates.omega) w.push_back(format_rational(q));
  for (const auto& q : c.rates.omega_dot) wd.push_back(format_rational(q));
  nlohmann::json differing = nlohmann::json::array();
  for (const auto* group : {&c.outcome.instances, &c.outcome.terms})
    for (const auto& t : *group)
      if (t.verdict == Verdict::Fails) differing.push_back(to_json(t));
  return {{"n", c.polygon.n()},        {"joints", joints},
          {"omega", w},                {"omega_dot", wd},
          {"differing", differing},    {"scene_yaml", c.scene_yaml},
          {"candidates_tried", c.candidates_tried}, {"shrink_steps", c.shrink_steps},
          {"seconds", c.seconds}};
}

nlohmann::json to_json(const ProofResult& r, bool as_expected) {
  nlohmann::json j = {{"id", r.id},
                      {"expected", r.expected == Expectation::Holds ? "holds" : "fails"},
                      {"verdict", to_string(r.verdict)},
                      {"as_expected", as_expected},
                      {"scope", r.scope},
                      {"seconds", r.seconds}};
  nlohmann::json except = nlohmann::json::array();
  for (const auto& e : r.except) except.push_back({{"polynomial", e.polynomial}, {"meaning", e.meaning}});
  j["except"] = except;
  j["argument"] = r.argument;
  j["not_local"] = r.not_local;
  j["proved_n"] = r.proved_n;
  nlohmann::json per_n = nlohmann::json::array();
  for (const auto& p : r.per_n)
    per_n.push_back({{"n", p.n}, {"proved", p.proved}, {"monomials", p.monomials}, {"tree_size", p.tree_size},
                     {"dag_size", p.dag_size}, {"seconds", p.seconds}, {"first_nonzero", p.first_nonzero}});
  j["per_n"] = per_n;
  if (r.counterexample) j["counterexample"] = to_json(*r.counterexample);
  if (r.samples) {
    j["samples"] = r.samples;
    j["samples_compared"] = r.samples_compared;
    j["samples_undefined"] = r.samples_undefined;
  }
  if (!r.error.empty()) j["error"] = r.error;
  return j;
}

nlohmann::json to_json(const std::vector<ProofResult>& results, const ClaimsStatus& status) {
  LINKPROOF_ASSERT(status.as_expected.size() == results.size(), "one status per claim");
  nlohmann::json claims = nlohmann::json::array();
  nlohmann::json verdicts = nlohmann::json::object();
  int as_expected = 0;
  double seconds = 0;
  for (size_t k = 0; k < results.size(); ++k) {
    const ProofResult& r = results[k];
    claims.push_back(to_json(r, static_cast<bool>(status.as_expected[k])));
    as_expected += status.as_expected[k];
    seconds += r.seconds;
    verdicts[to_string(r.verdict)] = verdicts.value(to_string(r.verdict), 0) + 1;
  }
  return {{"claims", claims},
          {"coordinates", kProofCoordinates},
          {"summary",
           {{"claims", results.size()},
            {"as_expected", as_expected},
            {"not_as_expected", static_cast<int>(results.size()) - as_expected},
            {"verdicts", verdicts},
            {"strict", status.strict},
            {"seconds", seconds}}},
          {"exit_status", status.exit_status}};
}

void write_text(std::ostream& out, const std::vector<ProofResult>& results, const ClaimsStatus& status) {
  LINKPROOF_ASSERT(status.as_expected.size() == results.size(), "one status per claim");
  fmt::print(out, "coordinates: {}\n\n", kProofCoordinates);
  for (size_t k = 0; k < results.size(); ++k) {
    const ProofResult& r = results[k];
    fmt::print(out, "{}  [{}]  {}{}  ({:.3f} s){}\n", r.id, r.expected == Expectation::Holds ? "holds" : "fails",
               to_string(r.verdict), r.scope.empty() ? "" : " for " + r.scope, r.seconds,
               status.as_expected[k] ? "" : "  <-- NOT AS EXPECTED");
    if (!r.error.empty()) fmt::print(out, "  error: {}\n", r.error);
    for (const auto& a : r.argument) fmt::print(out, "  {}\n", a);
    if (!r.not_local.empty()) {
      fmt::print(out, "  no proof for every n, because:\n");
      for (const auto& v : r.not_local) fmt::print(out, "    - {}\n", v);
    }
    if (!r.except.empty()) {
      fmt::print(out, "  holds generically, except where (a denominator vanishes):\n");
      for (const auto& e : r.except) fmt::print(out, "    - {} = 0: {}\n", e.polynomial, e.meaning);
    }
    for (const auto& p : r.per_n)
      fmt::print(out, "  n = {:3}: {:12} {:5} coefficients, tree {:8}, dag {:7}, {:.3f} s{}\n", p.n,
                 p.proved ? "proved" : "NOT zero", p.monomials, p.tree_size, p.dag_size, p.seconds,
                 p.first_nonzero.empty() ? "" : "  (first nonzero: " + p.first_nonzero + ")");
    if (r.counterexample) {
      const Counterexample& c = *r.counterexample;
      fmt::print(out, "  counterexample (exact, shrunk in {} steps, {} configurations, {:.3f} s):\n", c.shrink_steps,
                 c.candidates_tried, c.seconds);
      std::string text = c.scene_yaml;
      for (size_t p = 0; (p = text.find('\n', p)) != std::string::npos && p + 1 < text.size(); p += 5) text.replace(p, 1, "\n    ");
      fmt::print(out, "    {}\n", text);
      for (const auto* group : {&c.outcome.instances, &c.outcome.terms})
        for (const auto& t : *group)
          if (t.verdict == Verdict::Fails)
            fmt::print(out, "    differs: {}: lhs {} vs rhs {} (residual {})\n", t.label, lhs_text(t), rhs_text(t),
                       residual_text(t));
    }
    out << "\n";
  }
  int ok = 0;
  for (const bool as_expected : status.as_expected) ok += as_expected;
  fmt::print(out, "summary: {}/{} claims as expected{}\n", ok, results.size(),
             status.strict ? " (strict: only proofs for the whole range count)" : "");
}

void report_proofs(std::ostream& out, const std::vector<ProofResult>& results, bool as_json, const ClaimsStatus& status) {
  if (as_json)
    out << json_text(to_json(results, status)) << "\n";
  else
    write_text(out, results, status);
}

}  // namespace linkproof
