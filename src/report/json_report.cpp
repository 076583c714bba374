#include "report/json_report.h"

#include <fmt/format.h>

#include "report/comparison_text.h"
#include "report/number_text.h"

namespace linkproof {

using nlohmann::json;

json to_json(const ComparisonOutcome& c) {
  json j{{"label", c.label}, {"verdict", std::string(to_string(c.verdict))}};
  if (c.verdict == Verdict::Undefined) {
    j["undefined_quantity"] = c.undefined_quantity;
    j["reason"] = c.reason;
    return j;
  }
  if (c.verdict == Verdict::Error) {
    j["reason"] = c.reason;
    return j;
  }
  // A comparison that could not be evaluated (an arithmetic's exponent range exceeded) keeps
  // the keys, empty, as the contract has always had them.
  for (const auto& [key, x] : {std::pair{"lhs", &c.lhs}, {"rhs", &c.rhs}, {"residual", &c.residual}})
    j[key] = *x ? number_text(**x) : std::string();
  if (c.floating) {
    j["tolerance"] = radius_text(c.floating->tolerance);
    j["relative_error_bound"] = c.floating->relative_error_bound;
    j["tolerance_derivation"] = tolerance_derivation_text(c);
  }
  if (const std::string t = trust_route_text(c); !t.empty()) j["trust_route"] = t;
  if (c.floating && c.floating->wider_side != Side::None)
    j["inconclusive_side"] = std::string(to_string(c.floating->wider_side));
  if (const std::string q = inconclusive_quantity(c); !q.empty()) j["inconclusive_quantity"] = q;
  if (const std::string r = reason_text(c); !r.empty()) j["reason"] = r;
  return j;
}

json evidence_json(const SweepExample& e) {
  return e.recorded_evidence.empty() ? to_json(e.headline) : json::parse(e.recorded_evidence);
}

namespace {

json rates_object(const std::vector<std::optional<ResultNumber>>& v, bool decimal = false) {
  json o = json::object();
  for (size_t j = 0; j < v.size(); ++j)
    o[std::to_string(j + 1)] = v[j] ? json(decimal ? decimal_text(*v[j]) : number_text(*v[j])) : json(nullptr);
  return o;
}

// A comparison's exact values get their decimals beside them: "lhs_decimal" beside "lhs", ...
// (report/number_text.h decimal_text; additive: the exact strings stay as they were).
void add_decimals(json& j, const ComparisonOutcome& c) {
  for (const auto& [key, x] : {std::pair{"lhs", &c.lhs}, {"rhs", &c.rhs}, {"residual", &c.residual}})
    if (*x && is_exact(**x) && j.contains(key)) j[std::string(key) + "_decimal"] = decimal_text(**x);
}

// With an `ask`, only the asked sides (null where undefined).
json asked_rates_object(const std::vector<std::optional<ResultNumber>>& v, const SceneAsk& ask, bool dot,
                        bool decimal = false) {
  json o = json::object();
  for (const AskedRate& r : ask.rates) {
    if (r.dot != dot) continue;
    const auto& x = v[static_cast<size_t>(std::stoi(r.subject.name) - 1)];
    o[r.subject.name] = x ? json(decimal ? decimal_text(*x) : number_text(*x)) : json(nullptr);
  }
  return o;
}

json claim_json(const ClaimOutcome& c) {
  json j{{"id", c.info.id},
         {"verdict", std::string(to_string(c.verdict))},
         {"expected", std::string(to_string(c.info.expected))},
         {"as_expected", c.is_as_expected()},
         {"source", c.info.source},
         {"statement", c.info.statement}};
  if (!c.info.note.empty()) j["note"] = c.info.note;
  // The headline comparison's evidence at the top level (the contract's lhs/rhs/residual).
  json headline = to_json(c.headline);  // named: items() must not outlive its json
  add_decimals(headline, c.headline);
  for (const auto& [k, v] : headline.items())
    if (k != "label" && k != "verdict") j[k] = v;
  if (!c.headline.label.empty()) j["headline"] = c.headline.label;
  if (!c.error.empty()) j["error"] = c.error;
  j["instances"] = json::array();
  for (const auto& i : c.instances) {
    json ij = to_json(i);
    add_decimals(ij, i);
    j["instances"].push_back(std::move(ij));
  }
  j["terms"] = json::array();
  for (const auto& t : c.terms) {
    json tj = to_json(t);
    add_decimals(tj, t);
    tj["monomial"] = t.label;  // lhs: the engine's exact coefficient; rhs: the formula's
    j["terms"].push_back(std::move(tj));
  }
  return j;
}

json case_json(const RandomPolygonCase& rc) {
  json joints = json::array();
  for (const auto& k : rc.polygon.joints()) joints.push_back({format_rational(k.x), format_rational(k.y)});
  json w = json::array(), wd = json::array();
  for (const auto& x : rc.rates.omega) w.push_back(format_rational(x));
  for (const auto& x : rc.rates.omega_dot) wd.push_back(format_rational(x));
  return {{"seed", rc.seed}, {"n", rc.n}, {"index", rc.index}, {"family", rc.family},
          {"clockwise_numbering", rc.clockwise_numbering},
          {"polygon", {{"joints", joints}, {"omega", w}, {"omega_dot", wd}}}};
}

json example_json(const SweepExample& e) {
  json j = case_json(e.polygon);
  j["claim"] = e.claim_id;
  j["verdict"] = std::string(to_string(e.verdict));
  j["evidence"] = evidence_json(e);
  if (!e.error.empty()) j["error"] = e.error;
  return j;
}

}  // namespace

json to_json(const ClaimOutcome& c) { return claim_json(c); }

json to_json(const PolygonCheck& check, const ClaimsStatus& status) {
  LINKPROOF_ASSERT(status.as_expected.size() == check.claims.size(), "one status per claim");
  json claims = json::array();
  json summary{{"holds", 0}, {"fails", 0}, {"undefined", 0}, {"inconclusive", 0}, {"error", 0},
               {"unexpected_failures", 0}, {"not_as_expected", 0}};
  for (size_t k = 0; k < check.claims.size(); ++k) {
    const ClaimOutcome& c = check.claims[k];
    claims.push_back(claim_json(c));
    if (status.strict) claims.back()["as_expected"] = static_cast<bool>(status.as_expected[k]);
    summary[std::string(to_string(c.verdict))] = summary[std::string(to_string(c.verdict))].get<int>() + 1;
    if (c.is_unexpected_failure()) summary["unexpected_failures"] = summary["unexpected_failures"].get<int>() + 1;
    if (!status.as_expected[k]) summary["not_as_expected"] = summary["not_as_expected"].get<int>() + 1;
  }
  if (status.strict) summary["strict"] = true;
  json j = {{"scene", check.scene},
          {"arithmetic", std::string(to_string(check.arithmetic))},
          {"polygon",
           {{"n", check.n},
            {"omega", rates_object(check.omega)},
            {"omega_dot", rates_object(check.omega_dot)},
            {"omega_decimal", rates_object(check.omega, true)},
            {"omega_dot_decimal", rates_object(check.omega_dot, true)},
            {"D", number_text(check.determinant)},
            {"D_decimal", decimal_text(check.determinant)},
            {"dead_centre", check.dead_centre}}},
          {"tolerance_rule", tolerance_rule(check.arithmetic)},
          {"claims", claims},
          {"not_applicable", check.not_applicable},
          {"summary", summary},
          {"exit_status", status.exit_status}};
  if (check.ask) {
    j["ask"] = check.ask->describe();
    j["polygon"]["omega"] = asked_rates_object(check.omega, *check.ask, false);
    j["polygon"]["omega_dot"] = asked_rates_object(check.omega_dot, *check.ask, true);
    j["polygon"]["omega_decimal"] = asked_rates_object(check.omega, *check.ask, false, true);
    j["polygon"]["omega_dot_decimal"] = asked_rates_object(check.omega_dot, *check.ask, true, true);
  }
  return j;
}

json to_json(const SweepReport& s, int exit_status) {
  json claims = json::array();
  for (const auto& t : s.tallies)
    claims.push_back({{"id", t.id},
                      {"expected", std::string(to_string(t.expected))},
                      {"holds", t.holds},
                      {"fails", t.fails},
                      {"undefined", t.undefined},
                      {"inconclusive", t.inconclusive},
                      {"error", t.error},
                      {"not_applicable", t.not_applicable}});
  json unexpected = json::array(), disproofs = json::array();
  for (const auto& e : s.unexpected) unexpected.push_back(example_json(e));
  for (const auto& e : s.erratum_counterexamples) disproofs.push_back(example_json(e));
  const auto& o = s.options;
  return {{"seed", o.seed},
          {"n", fmt::format("{}..{}", o.n_min, o.n_max)},
          {"count_per_n", o.count},
          {"arithmetic", std::string(to_string(o.arithmetic))},
          {"cases", s.cases},
          {"seconds", s.seconds},
          {"tolerance_rule", tolerance_rule(o.arithmetic)},
          {"claims", claims},
          {"unexpected", unexpected},
          {"erratum_counterexamples", disproofs},
          {"exit_status", exit_status}};
}

std::string json_text(const nlohmann::json& j) {
  return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace linkproof
