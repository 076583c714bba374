#include "report/mechanism_report.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <fmt/ostream.h>

#include "report/comparison_text.h"
#include "report/json_report.h"
#include "report/number_text.h"

namespace linkproof {

using nlohmann::json;

namespace {

json point_json(const MechanismCheck::PointMotion& p) {
  json j{{"v", {number_text(p.v[0]), number_text(p.v[1])}}, {"a", {number_text(p.a[0]), number_text(p.a[1])}}};
  if (p.slide) j["sliding_v"] = number_text(*p.slide), j["sliding_a"] = number_text(*p.slide_dot);
  return j;
}

}  // namespace

json claims_summary_json(const std::vector<ClaimOutcome>& claims, bool strict) {
  json summary{{"holds", 0}, {"fails", 0}, {"undefined", 0}, {"inconclusive", 0}, {"error", 0},
               {"unexpected_failures", 0}};
  if (strict) summary["not_as_expected"] = 0, summary["strict"] = true;
  for (const auto& cl : claims) {
    const std::string v(to_string(cl.verdict));
    summary[v] = summary[v].get<int>() + 1;
    if (cl.is_unexpected_failure()) summary["unexpected_failures"] = summary["unexpected_failures"].get<int>() + 1;
    if (strict && !cl.is_as_expected(true)) summary["not_as_expected"] = summary["not_as_expected"].get<int>() + 1;
  }
  return summary;
}

void write_claim_table(std::ostream& out, const std::vector<ClaimOutcome>& claims, bool strict) {
  fmt::print(out, "\n{:<48} {:<13} {:<9} {}\n", "claim", "verdict", "expected", "evidence");
  for (const auto& cl : claims) {
    std::string evidence = cl.error;
    if (evidence.empty()) {
      const auto& h = cl.headline;
      evidence = h.verdict == Verdict::Undefined ? "undefined: " + h.undefined_quantity
                                                 : fmt::format("{}: {} vs {}", h.label, lhs_text(h), rhs_text(h));
    }
    if (strict && !cl.is_as_expected(true)) evidence += "  <-- NOT AS EXPECTED (strict)";
    fmt::print(out, "{:<48} {:<13} {:<9} {}\n", cl.info.id, to_string(cl.verdict), to_string(cl.info.expected),
               evidence);
  }
}

void write_claim_section(std::ostream& out, const std::vector<ClaimOutcome>& claims,
                         const std::vector<std::string>& not_applicable, bool strict) {
  write_claim_table(out, claims, strict);
  if (!not_applicable.empty()) {
    fmt::print(out, "\nnot applicable:");
    for (const auto& id : not_applicable) fmt::print(out, " {}", id);
    fmt::print(out, "\n");
  }
  fmt::print(out, "\nexit status {}{}\n", exit_status(claims, strict),
             strict ? " (strict: undefined or inconclusive on a true claim counts)" : "");
}

json to_json(const MechanismCheck& c) {
  json links = json::object(), relative = json::object(), joints = json::object(), points = json::object(),
       tables = json::object(), claims = json::array();
  for (size_t l = 0; l < c.link_names.size(); ++l)
    links[c.link_names[l]] = {{"omega", number_text(c.omega[l])}, {"omega_dot", number_text(c.omega_dot[l])}};
  for (const auto& r : c.relative) relative[r.i + "," + r.k] = {{"omega", number_text(r.omega)}, {"omega_dot", number_text(r.omega_dot)}};
  for (const auto& p : c.joints) joints[p.name] = point_json(p);
  for (const auto& p : c.points) points[p.name] = point_json(p);
  for (const auto& t : c.tables) {
    json rows = json::object();
    for (const auto& [k, v] : t.rows) rows[k] = v;
    tables[t.title] = rows;
  }
  for (const auto& cl : c.claims) claims.push_back(to_json(cl));
  const json summary = claims_summary_json(c.claims, c.strict);
  json j = {{"scene", c.scene},
          {"arithmetic", std::string(to_string(c.arithmetic))},
          {"arithmetic_note", c.arithmetic_note.empty() ? nlohmann::json(nullptr) : nlohmann::json(c.arithmetic_note)},
          {"mobility", c.mobility},
          {"grubler_mobility", c.grubler},
          {"rank", c.rank},
          {"loops", c.loops},
          {"unknowns", c.unknowns},
          {"condition", c.condition},
          {"closure_residual", format_rational(c.closure_residual)},
          {"dimension_residual", c.dimension_residual},
          {"links", links},
          {"relative", relative},
          {"joints", joints},
          {"points", points},
          {"tables", tables},
          {"claims", claims},
          {"not_applicable", c.not_applicable},
          {"summary", summary},
          {"exit_status", exit_status(c)}};
  if (c.ask) {
    j["ask"] = c.ask->describe();
    j["computed"] = {{"links", c.computed_links}, {"of_links", c.all_links}, {"of_loops", c.all_loops}};
  }
  return j;
}

void write_text(std::ostream& out, const MechanismCheck& c) {
  fmt::print(out, "scene {} ({} arithmetic)\n", c.scene, to_string(c.arithmetic));
  fmt::print(out, "mobility {} (Gruebler {}), {} loops, {} unknowns, rank {}, condition {:.3g}, closure residual {}\n\n",
             c.mobility, c.grubler, c.loops, c.unknowns, c.rank, c.condition, format_rational(c.closure_residual));
  if (!c.arithmetic_note.empty()) fmt::print(out, "note: {}\n\n", c.arithmetic_note);
  if (c.ask)
    fmt::print(out, "asked (the scene's `ask`): {}\ncomputed on the sub-mechanism of links {} ({} of {} links, {} of {} "
               "loops): nothing else is needed for what is asked\n\n",
               fmt::join(c.ask->describe(), "; "), fmt::join(c.computed_links, ", "), c.computed_links.size(),
               c.all_links, c.loops, c.all_loops);
  if (!c.ask || !c.link_names.empty()) {
    fmt::print(out, "{:<10} {:>28} {:>28}\n", "link", "omega", "omega_dot");
    for (size_t l = 0; l < c.link_names.size(); ++l)
      fmt::print(out, "{:<10} {:>28} {:>28}\n", c.link_names[l], number_text(c.omega[l]), number_text(c.omega_dot[l]));
  }
  if (!c.ask || !c.joints.empty() || !c.points.empty()) fmt::print(out, "\n{:<10} {:>40} {:>40}\n", "joint", "v", "a");
  for (const auto* list : {&c.joints, &c.points})
    for (const auto& p : *list)
      fmt::print(out, "{:<10} {:>40} {:>40}{}\n", p.name, fmt::format("({}, {})", number_text(p.v[0]), number_text(p.v[1])),
                 fmt::format("({}, {})", number_text(p.a[0]), number_text(p.a[1])),
                 p.slide ? fmt::format("   sliding v {}, a {}", number_text(*p.slide), number_text(*p.slide_dot)) : "");
  for (const auto& t : c.tables) {
    fmt::print(out, "\n{}\n", t.title);
    for (const auto& [k, v] : t.rows) fmt::print(out, "  {:<28} {}\n", k, v);
  }
  write_claim_section(out, c.claims, c.not_applicable, c.strict);
}

}  // namespace linkproof
