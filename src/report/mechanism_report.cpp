#include "report/mechanism_report.h"

#include <cln/integer.h>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <fmt/ostream.h>

#include <algorithm>

#include "mechanism/axis_length.h"
#include "report/comparison_text.h"
#include "report/dimensioned_bound_report.h"
#include "report/json_report.h"
#include "report/number_text.h"
#include "report/slot_rows.h"

namespace linkproof {

using nlohmann::json;

namespace {

// c * sqrt(m) as text: "p/q" when m is 1, "sqrt(m)" or "p/q*sqrt(m)" otherwise (exact).
std::string square_root_text(const Rational& c, const cln::cl_I& m) {
  if (m == 1) return format_rational(c);
  const std::string root = "sqrt(" + format_rational(Rational(m)) + ")";
  if (c == 1) return root;
  if (c == -1) return "-" + root;
  return format_rational(c) + "*" + root;
}

// A rate along the unit axis: the number itself, or its exact form with the root.
std::string unit_rate_text(const ResultNumber& x, const cln::cl_I& radicand) {
  if (radicand == 1 || !is_exact(x)) return number_text(x);
  return square_root_text(std::get<Rational>(x), radicand);
}

// The keys a prismatic joint adds (additive: sliding_v, sliding_a keep their meaning, per unit
// of the axis as written).
void add_sliding_json(json& j, const MechanismCheck::Sliding& s) {
  j["guide"] = s.guide, j["slider"] = s.slider;
  j["axis"] = {format_rational(s.axis.x), format_rational(s.axis.y)};
  j["axis_length"] = square_root_text(s.axis_length, s.axis_radicand);
  j["sliding_v_unit"] = unit_rate_text(s.v_unit, s.rate_radicand);
  j["sliding_a_unit"] = unit_rate_text(s.a_unit, s.rate_radicand);
  j["coriolis"] = {number_text(s.coriolis[0]), number_text(s.coriolis[1])};
  if (s.v_unit_bound && s.a_unit_bound)
    j["sliding_v_unit_bound"] = radius_text(*s.v_unit_bound), j["sliding_a_unit_bound"] = radius_text(*s.a_unit_bound);
  if (s.coriolis_bound[0] && s.coriolis_bound[1])
    j["coriolis_bound"] = {radius_text(*s.coriolis_bound[0]), radius_text(*s.coriolis_bound[1])};
}

json point_json(const MechanismCheck::PointMotion& p) {
  json j{{"v", {number_text(p.v[0]), number_text(p.v[1])}}, {"a", {number_text(p.a[0]), number_text(p.a[1])}}};
  if (is_exact(p.v[0]) && is_exact(p.v[1])) j["v_decimal"] = {decimal_text(p.v[0]), decimal_text(p.v[1])};
  if (is_exact(p.a[0]) && is_exact(p.a[1])) j["a_decimal"] = {decimal_text(p.a[0]), decimal_text(p.a[1])};
  if (p.slide) j["sliding_v"] = number_text(*p.slide), j["sliding_a"] = number_text(*p.slide_dot);
  // Floating arithmetic: the bound of each value (both components are bounded or neither).
  if (p.v_bound[0] && p.v_bound[1] && p.a_bound[0] && p.a_bound[1]) {
    j["v_bound"] = {radius_text(*p.v_bound[0]), radius_text(*p.v_bound[1])};
    j["a_bound"] = {radius_text(*p.a_bound[0]), radius_text(*p.a_bound[1])};
  }
  if (p.slide_bound && p.slide_dot_bound)
    j["sliding_v_bound"] = radius_text(*p.slide_bound), j["sliding_a_bound"] = radius_text(*p.slide_dot_bound);
  if (p.sliding) add_sliding_json(j, *p.sliding);
  return j;
}

// {"omega": .., "omega_dot": ..}, with their bounds in a floating arithmetic.
json rates_json(const ResultNumber& omega, const ResultNumber& omega_dot, const std::optional<ResultRadius>& omega_bound,
                const std::optional<ResultRadius>& omega_dot_bound) {
  json j{{"omega", number_text(omega)}, {"omega_dot", number_text(omega_dot)}};
  if (is_exact(omega)) j["omega_decimal"] = decimal_text(omega);
  if (is_exact(omega_dot)) j["omega_dot_decimal"] = decimal_text(omega_dot);
  if (omega_bound && omega_dot_bound)
    j["omega_bound"] = radius_text(*omega_bound), j["omega_dot_bound"] = radius_text(*omega_dot_bound);
  return j;
}

// A value as text, followed by its bound when it has one: "-0.75000000000000011 +- 2.22e-16"; an
// exact value with its decimal beside it: "-3/4 = -0.75" (report/number_text.h).
std::string bounded_text(const ResultNumber& x, const std::optional<ResultRadius>& bound, int digits) {
  return bound ? number_text(x) + " +- " + radius_short_text(*bound) : readable_number(x, digits);
}

// c * sqrt(m) for a person: "3/2*sqrt(5) ≈ 3.354101966" (the decimal to `digits` significant
// digits, trailing zeros dropped, from c times a rational within 2^-(4 digits + 64) relative of
// sqrt(m)); a form longer than kLongFraction characters by its decimal and size; a rational
// (m = 1) as readable_number shows it.
std::string root_readable(const Rational& c, const cln::cl_I& m, int digits) {
  if (m == 1 || cln::zerop(c)) return readable_number(ResultNumber(c), digits);
  std::string decimal = format_decimal(c * enclose_square_root(Rational(m), 4 * digits + 64).midpoint, digits);
  const size_t e = decimal.find('e');
  std::string mantissa = decimal.substr(0, e), exponent = e == std::string::npos ? "" : decimal.substr(e);
  if (mantissa.find('.') != std::string::npos) {
    while (mantissa.back() == '0') mantissa.pop_back();
    if (mantissa.back() == '.') mantissa.pop_back();
  }
  decimal = mantissa + exponent;
  const std::string exact = square_root_text(c, m);
  if (exact.size() <= kLongFraction) return exact + " ≈ " + decimal;
  size_t figures = 0;
  for (const char ch : exact) figures += ch >= '0' && ch <= '9';
  return fmt::format("≈ {} (exact: p/q*sqrt(m) of {} digits, see --json)", decimal, figures);
}

// A given number (an axis coordinate, |u|) as written, or by its decimal when it is long.
std::string coordinate_text(const Rational& x, int digits) {
  const std::string exact = format_rational(x);
  return exact.size() <= kLongFraction ? exact : readable_number(ResultNumber(x), digits);
}

// A rate along the unit axis for a person: exact (a rational, or a multiple of a root), or
// "0.3 +- 1.1e-16" in a floating arithmetic.
std::string unit_rate_readable(const ResultNumber& x, const cln::cl_I& radicand, const std::optional<ResultRadius>& bound,
                               int digits) {
  if (radicand == 1 || !is_exact(x)) return bounded_text(x, bound, digits);
  return root_readable(std::get<Rational>(x), radicand, digits);
}

// The prismatic pairs as textbooks state them: the sliding rates along the unit axis, with the
// sign convention, and the Coriolis term of each.
void write_sliding_section(std::ostream& out, const MechanismCheck& c, int digits) {
  const bool any = std::any_of(c.joints.begin(), c.joints.end(), [](const auto& p) { return p.sliding.has_value(); });
  if (!any) return;
  fmt::print(out, "\nprismatic pairs: the slider relative to its guide along the unit axis u/|u| (u as written, fixed in "
                  "the guide; + = the slider moves along +u), in length/time and length/time^2; Coriolis 2 omega_guide x "
                  "v_rel = 2 omega_guide J v_rel\n");
  for (const auto& p : c.joints) {
    if (!p.sliding) continue;
    const MechanismCheck::Sliding& s = *p.sliding;
    const std::string length = s.axis_radicand == 1 ? coordinate_text(s.axis_length, digits)
                                                     : root_readable(s.axis_length, s.axis_radicand, digits);
    // A slot: the pin's link slides in the slotted link (its block is not shown).
    const MechanismCheck::Slot* slot = slot_of_joint(c, p.name);
    fmt::print(out, "{:<10} {}, u = ({}, {}), |u| {}{}\n", p.name,
               slot ? slot_description(*slot) : fmt::format("guide {}, slider {}", s.guide, s.slider),
               coordinate_text(s.axis.x, digits), coordinate_text(s.axis.y, digits),
               length.rfind("≈", 0) == 0 ? "" : "= ", length);
    fmt::print(out, "{:<10} sliding v {}\n", "", unit_rate_readable(s.v_unit, s.rate_radicand, s.v_unit_bound, digits));
    fmt::print(out, "{:<10} sliding a {}\n", "", unit_rate_readable(s.a_unit, s.rate_radicand, s.a_unit_bound, digits));
    fmt::print(out, "{:<10} Coriolis  ({}, {})\n", "", bounded_text(s.coriolis[0], s.coriolis_bound[0], digits),
               bounded_text(s.coriolis[1], s.coriolis_bound[1], digits));
  }
}

}  // namespace

json claims_summary_json(const std::vector<ClaimOutcome>& claims, const ClaimsStatus& status) {
  LINKPROOF_ASSERT(status.as_expected.size() == claims.size(), "one status per claim");
  json summary{{"holds", 0}, {"fails", 0}, {"undefined", 0}, {"inconclusive", 0}, {"error", 0},
               {"unexpected_failures", 0}};
  if (status.strict) summary["not_as_expected"] = 0, summary["strict"] = true;
  for (size_t k = 0; k < claims.size(); ++k) {
    const ClaimOutcome& cl = claims[k];
    const std::string v(to_string(cl.verdict));
    summary[v] = summary[v].get<int>() + 1;
    if (cl.is_unexpected_failure()) summary["unexpected_failures"] = summary["unexpected_failures"].get<int>() + 1;
    if (status.strict && !status.as_expected[k])
      summary["not_as_expected"] = summary["not_as_expected"].get<int>() + 1;
  }
  return summary;
}

void write_claim_table(std::ostream& out, const std::vector<ClaimOutcome>& claims, const ClaimsStatus& status) {
  LINKPROOF_ASSERT(status.as_expected.size() == claims.size(), "one status per claim");
  bool any_long = false;
  fmt::print(out, "\n{:<48} {:<13} {:<9} {}\n", "claim", "verdict", "expected", "evidence");
  for (size_t k = 0; k < claims.size(); ++k) {
    const ClaimOutcome& cl = claims[k];
    std::string evidence = cl.error;
    if (evidence.empty()) {
      const auto& h = cl.headline;
      evidence = h.verdict == Verdict::Undefined ? "undefined: " + h.undefined_quantity
                                                 : fmt::format("{}: {} vs {}", h.label, lhs_text(h, NumberStyle::Compact),
                                                               rhs_text(h, NumberStyle::Compact));
      any_long = any_long || (h.lhs && is_long_fraction(*h.lhs)) || (h.rhs && is_long_fraction(*h.rhs));
    }
    if (status.strict && !status.as_expected[k]) evidence += "  <-- NOT AS EXPECTED (strict)";
    fmt::print(out, "{:<48} {:<13} {:<9} {}\n", cl.info.id, to_string(cl.verdict), to_string(cl.info.expected),
               evidence);
  }
  if (any_long) fmt::print(out, "{}\n", long_fraction_note());
}

void write_claim_section(std::ostream& out, const std::vector<ClaimOutcome>& claims,
                         const std::vector<std::string>& not_applicable, const ClaimsStatus& status) {
  write_claim_table(out, claims, status);
  if (!not_applicable.empty()) {
    fmt::print(out, "\nnot applicable:");
    for (const auto& id : not_applicable) fmt::print(out, " {}", id);
    fmt::print(out, "\n");
  }
  fmt::print(out, "\nexit status {}{}\n", status.exit_status,
             status.strict ? " (strict: undefined or inconclusive on a true claim counts)" : "");
}

json to_json(const MechanismCheck& c, const ClaimsStatus& status) {
  json links = json::object(), relative = json::object(), joints = json::object(), points = json::object(),
       tables = json::object(), claims = json::array();
  for (size_t l = 0; l < c.link_names.size(); ++l)
    links[c.link_names[l]] = rates_json(c.omega[l], c.omega_dot[l], c.omega_bound[l], c.omega_dot_bound[l]);
  for (const auto& r : c.relative)
    relative[r.i + "," + r.k] = rates_json(r.omega, r.omega_dot, r.omega_bound, r.omega_dot_bound);
  for (const auto& p : c.joints) joints[p.name] = point_json(p);
  for (const auto& p : c.points) points[p.name] = point_json(p);
  for (const auto& t : c.tables) {
    json rows = json::object();
    for (const auto& [k, v] : t.rows) rows[k] = v;
    tables[t.title] = rows;
  }
  for (const auto& cl : c.claims) claims.push_back(to_json(cl));
  const json summary = claims_summary_json(c.claims, status);
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
          {"exit_status", status.exit_status}};
  if (c.dimensioned) j["dimensioned_bound"] = dimensioned_bound_json(*c.dimensioned);
  if (!c.slots.empty()) {  // added; "links" and "joints" keep the block and the pin (existing keys)
    json slots = json::object();
    for (const auto& s : c.slots)
      slots[s.joint] = {{"slotted", s.slotted}, {"pin_link", s.pin_link}, {"block", s.block}, {"pin", s.pin}};
    j["slots"] = slots;
  }
  if (c.ask) {
    j["ask"] = c.ask->describe();
    j["computed"] = {{"links", c.computed_links}, {"of_links", c.all_links}, {"of_loops", c.all_loops}};
  }
  return j;
}

void write_text(std::ostream& out, const MechanismCheck& c, const ClaimsStatus& status, int digits) {
  fmt::print(out, "scene {} ({} arithmetic)\n", c.scene, to_string(c.arithmetic));
  fmt::print(out, "mobility {} (Gruebler {}), {} loops, {} unknowns, rank {}, condition {:.3g}, closure residual {}\n\n",
             c.mobility, c.grubler, c.loops, c.unknowns, c.rank, c.condition, format_rational(c.closure_residual));
  if (!c.arithmetic_note.empty()) fmt::print(out, "note: {}\n\n", c.arithmetic_note);
  if (c.ask)
    fmt::print(out, "asked (the scene's `ask`): {}\ncomputed on the sub-mechanism of links {} ({} of {} links, {} of {} "
               "loops): nothing else is needed for what is asked\n\n",
               fmt::join(c.ask->describe(), "; "), fmt::join(c.computed_links, ", "), c.computed_links.size(),
               c.all_links, c.loops, c.all_loops);
  // Exact: the columns of old; with bounds ("value +- bound") they are wider.
  const bool bounded = std::any_of(c.omega_bound.begin(), c.omega_bound.end(), [](const auto& b) { return b.has_value(); });
  const int rate_width = bounded ? 40 : 28, point_width = bounded ? 64 : 40;
  // Exact cells show a long fraction by its decimal and a mark, with one note under the table.
  CompactCells cells{digits};
  const auto cell = [&](const ResultNumber& x, const std::optional<ResultRadius>& bound) {
    return bound ? bounded_text(x, bound, digits) : cells.text(x);
  };
  const auto note = [&] {
    if (cells.any_long) fmt::print(out, "{}\n", long_fraction_note(digits));
    cells.any_long = false;
  };
  if (!c.ask || !c.link_names.empty()) {
    fmt::print(out, "{:<10} {:>{}} {:>{}}\n", "link", "omega", rate_width, "omega_dot", rate_width);
    for (size_t l = 0; l < c.link_names.size(); ++l) {
      if (is_hidden_slot_part(c, c.link_names[l])) continue;  // a slot's block turns with the slotted link
      fmt::print(out, "{:<10} {:>{}} {:>{}}\n", c.link_names[l], cell(c.omega[l], c.omega_bound[l]), rate_width,
                 cell(c.omega_dot[l], c.omega_dot_bound[l]), rate_width);
    }
    note();
  }
  if (!c.ask || !c.joints.empty() || !c.points.empty())
    fmt::print(out, "\n{:<10} {:>{}} {:>{}}\n", "joint", "v", point_width, "a", point_width);
  for (const auto* list : {&c.joints, &c.points})
    for (const auto& p : *list) {
      if (list == &c.joints && is_hidden_slot_part(c, p.name)) continue;  // a slot's pin: the slot's point
      const MechanismCheck::Slot* slot = list == &c.joints ? slot_of_joint(c, p.name) : nullptr;
      fmt::print(out, "{:<10} {:>{}} {:>{}}{}\n", p.name,
                 fmt::format("({}, {})", cell(p.v[0], p.v_bound[0]), cell(p.v[1], p.v_bound[1])), point_width,
                 fmt::format("({}, {})", cell(p.a[0], p.a_bound[0]), cell(p.a[1], p.a_bound[1])), point_width,
                 slot ? "   (" + slot_description(*slot) + "; its sliding rates below)"
                      : p.sliding ? "   (slider's point; its sliding rates below)" : "");
    }
  note();
  write_sliding_section(out, c, digits);
  for (const auto& t : c.tables) {
    fmt::print(out, "\n{}\n", t.title);
    for (const auto& [k, v] : t.rows) fmt::print(out, "  {:<28} {}\n", k, v);
  }
  write_claim_section(out, c.claims, c.not_applicable, status);
}

}  // namespace linkproof
