#include "report/polygon_document.h"

#include <fmt/format.h>
#include <ginac/ginac.h>

#include <algorithm>
#include <chrono>
#include <sstream>

#include "geometry/construction.h"
#include "report/number_rich.h"
#include "report/number_text.h"
#include "canonical_latex.h"
#include "svg_plot.h"
#include "check/check_polygon.h"

namespace linkproof::report {

namespace {

using GiNaC::ex;

// The same text in every run (GiNaC's own printer follows an order that ASLR moves).
std::string latex_of(const ex& e) { return canonical_latex(e); }


Point2 polygon_point(const Vec2<Rational>& p) { return {cln::double_approx(p.x), cln::double_approx(p.y)}; }

Rich defined_rich(const Defined<Vec2<Rational>>& d) {
  if (d.has_value()) return point_rich(d.get());
  return plain("undefined: " + d.quantity());
}

Rich defined_rich(const Defined<Rational>& d) {
  if (d.has_value()) return number_rich(d.get());
  return plain("undefined: " + d.quantity());
}

// A rate of the ground truth as the report shows it, or why it has none.
Rich rate_rich(const std::optional<ResultNumber>& v, const char* missing) {
  return v ? number_rich(*v) : plain(missing);
}

// ---------------------------------------------------------------- summary
std::string construction_caption(int n) {
  return "The polygon to scale (side " + std::to_string(n) +
         " fixed, grey); per input side j in its colour: r_j moved to end in K_{n-2} (arrow from K'_j), the lines "
         "K_nK'_j and K_{n-2}K_{n-1} (dashed) meeting in Q_j, the lines K_{n-1}K_n and K'_jK_{n-2} (thin) "
         "meeting in P'_j, and the angle beta_j at Q_j.";
}

Rich construction_rich_caption(int n) {
  return {text("The polygon to scale (side " + std::to_string(n) + " fixed, grey); per input side "), math("j"),
          text(" in its colour: "), math("r_j"), text(" moved to end in "), math("K_{n-2}"), text(" (arrow from "),
          math("K'_j"), text("), the lines "), math("K_nK'_j"), text(" and "), math("K_{n-2}K_{n-1}"),
          text(" (dashed) meeting in "), math("Q_j"), text(", the lines "), math("K_{n-1}K_n"), text(" and "),
          math("K'_jK_{n-2}"), text(" (thin) meeting in "), math("P'_j"), text(", and the angle "), math("\\beta_j"),
          text(" at "), math("Q_j"), text(".")};
}

// The summary opens with what a reader came for: the polygon drawn large (with its construction
// when that was computed), beside the headline results (the asked values, the claims at a glance).
Section summary_section(const PolygonScene& scene, const PolygonCheck& check) {
  Section s{"summary", "Summary", {}, {}};
  const bool construction = !check.ask || check.computed.construction;
  s.blocks.push_back(figure_block(
      {scene.name + "-construction",
       construction ? construction_caption(check.n)
                    : "The polygon to scale (side " + std::to_string(check.n) + " fixed, grey).",
       construction ? polygon_construction_drawing(scene.polygon)
                    : polygon_construction_drawing(scene.polygon, /*with_construction=*/false),
       construction ? construction_rich_caption(check.n) : Rich{}}));
  std::vector<Rich> headline;
  if (check.ask)
    for (const AskedRate& r : check.ask->rates) {
      // The side as a number (the reader checked it is one): no text of the scene goes into math.
      const int side = std::stoi(r.subject.name);
      const auto& v = (r.dot ? check.omega_dot : check.omega)[static_cast<size_t>(side - 1)];
      Rich item = tex(std::string(r.dot ? "\\dot\\omega_{" : "\\omega_{") + std::to_string(side) + "," +
                      std::to_string(check.n) + "} =");
      item.push_back(text(" "));
      for (const Span& x : rate_rich(v, "undefined")) item.push_back(x);
      headline.push_back(std::move(item));
    }
  if (check.dead_centre) headline.push_back(plain("dead centre: every claim is undefined"));
  for (Rich& r : claims_at_a_glance(check.claims)) headline.push_back(std::move(r));
  if (!headline.empty()) s.blocks.push_back(headline_block(std::move(headline)));
  int as_expected = 0;
  for (const auto& c : check.claims) as_expected += c.is_as_expected() ? 1 : 0;
  s.blocks.push_back(paragraph(
      {text(fmt::format("Scene {} ({}): an n-side polygon with ", scene.name, scene.source)),
       math(fmt::format("n = {}", check.n)), text(", side "), math(fmt::format("{}", check.n)),
       text(" fixed; the claims of Dijksman (1966) checked in " + std::string(to_string(check.arithmetic)) +
            " arithmetic: "),
       text(fmt::format("{} of {} as expected. ", as_expected, check.claims.size())),
       text("Each verdict rests on this one instance; a proof for every n is made by "),
       text("`linkproof report` on the claim file (prove).")}));
  if (check.ask) {
    std::string asked;
    for (const auto& item : check.ask->describe()) asked += (asked.empty() ? "" : "; ") + item;
    s.blocks.push_back(paragraph(plain("The scene asks for " + asked +
                                       "; nothing else was computed, and the sections of what was not needed are left out.")));
  }
  if (check.dead_centre)
    s.blocks.push_back(paragraph(plain("Dead centre: " + check.dead_centre_reason +
                                       ". The ground truth does not exist here; every claim is undefined.")));
  if (!check.claims.empty()) s.blocks.push_back(table_block(claim_summary_table(check.claims, check.arithmetic)));
  if (!check.not_applicable.empty()) {
    std::string na;
    for (const auto& id : check.not_applicable) na += (na.empty() ? "" : ", ") + id;
    s.blocks.push_back(paragraph(plain(fmt::format("Not applicable at n = {}: {}.", check.n, na))));
  }
  return s;
}

// ---------------------------------------------------------------- derivation
Section derivation_section(GroundTruthEngine& engine, const PolygonScene& scene, const PolygonCheck& check) {
  const int n = check.n, m = n - 3;
  Section s{"derivation", "Derivation", {}, {}};
  Table values{{plain("side j"), tex("\\omega_{j," + std::to_string(n) + "}"),
                tex("\\dot\\omega_{j," + std::to_string(n) + "}")},
               {}};
  for (int j = 1; j <= n; ++j) {
    const auto& w = check.omega[static_cast<size_t>(j - 1)];
    const auto& wd = check.omega_dot[static_cast<size_t>(j - 1)];
    const auto asked = [&](bool dot) {
      return std::any_of(check.ask->rates.begin(), check.ask->rates.end(),
                         [&](const AskedRate& r) { return r.dot == dot && r.subject.name == std::to_string(j); });
    };
    if (check.ask && !asked(false) && !asked(true)) continue;  // only the asked rates
    values.rows.push_back({plain(std::to_string(j) + (j <= m ? " (input)" : j == n ? " (fixed)" : " (solved)")),
                           rate_rich(w, check.ask && !asked(false) ? "not asked" : "undefined"),
                           rate_rich(wd, check.ask && !asked(true) ? "not asked" : "undefined")});
  }
  if (n > kSymbolicReportMaxN) {
    s.blocks.push_back(paragraph(
        {text(fmt::format("At n = {} the derived expressions have O(n) terms; they are not printed (printed for n ≤ {}). "
                          "The engine's result agrees with docs/conventions.md §A2: ",
                          n, kSymbolicReportMaxN))}));
    s.blocks.push_back(display_math("\\omega_{n-1} D = \\sum_j \\omega_j (r_j \\times r_{n-2}),\\qquad "
                                    "\\omega_{n-2} D = \\sum_j \\omega_j (r_{n-1} \\times r_j)"));
    s.blocks.push_back(paragraph(plain("Exact values on this scene:")));
    s.blocks.push_back(table_block(std::move(values)));
    return s;
  }
  const auto& d = engine.symbolic_derivation(n);
  const LoopSolution& sol = d.solution;
  const PolygonSymbols& sym = d.symbols;
  const std::string N = std::to_string(n), n1 = std::to_string(n - 1), n2 = std::to_string(n - 2);
  s.blocks.push_back(paragraph({text("Loop closure (eq. 1), side "), math(N), text(" fixed ("),
                                math("\\theta_{" + N + "}"), text(" constant):")}));
  s.blocks.push_back(display_folded(latex_of(sol.closure[0]) + " = 0", "the loop closure, x component"));
  s.blocks.push_back(display_folded(latex_of(sol.closure[1]) + " = 0", "the loop closure, y component"));
  s.blocks.push_back(paragraph({text("First time derivative, with "), math("L_j\\cos\\theta_j = x_j"), text(", "),
                                math("L_j\\sin\\theta_j = y_j"), text(" (the side components of "),
                                math("r_j"), text("):")}));
  s.blocks.push_back(display_folded(latex_of(sol.velocity[0]) + " = 0", "the first time derivative, x component"));
  s.blocks.push_back(display_folded(latex_of(sol.velocity[1]) + " = 0", "the first time derivative, y component"));
  s.blocks.push_back(paragraph(plain("Second time derivative:")));
  s.blocks.push_back(display_folded(latex_of(sol.acceleration[0]) + " = 0", "the second time derivative, x component"));
  s.blocks.push_back(display_folded(latex_of(sol.acceleration[1]) + " = 0", "the second time derivative, y component"));
  s.blocks.push_back(paragraph({text("Solved by Cramer's rule with "), math("D = r_{" + n2 + "}\\times r_{" + n1 + "}"),
                                text(" = "), math(latex_of(sol.determinant)), text(":")}));
  s.blocks.push_back(display_equation("\\omega_{" + n1 + "," + N + "}", latex_of(sol.omega_n1.normal())));
  s.blocks.push_back(display_equation("\\omega_{" + n2 + "," + N + "}", latex_of(sol.omega_n2.normal())));
  // omega-dot in the structural form the engine solves (omega of the solved sides as symbols).
  const ex wd1 = sol.omega_dot_n1, wd2 = sol.omega_dot_n2;
  s.blocks.push_back(display_equation("\\dot\\omega_{" + n1 + "," + N + "}", latex_of(wd1)));
  s.blocks.push_back(display_equation("\\dot\\omega_{" + n2 + "," + N + "}", latex_of(wd2)));

  // Coefficients of omega-dot_{n-1,n} in the input rates (ground_truth.h: by differentiation):
  // with an ask, only when an asked claim compares them term by term.
  const bool terms_asked = std::any_of(check.claims.begin(), check.claims.end(), [](const auto& c) { return !c.terms.empty(); });
  if (check.ask && !terms_asked) {
    if (!values.rows.empty()) {
      s.blocks.push_back(paragraph(plain("Exact values on this scene:")));
      s.blocks.push_back(table_block(std::move(values)));
    }
    return s;
  }
  s.blocks.push_back(paragraph({text("Coefficients of "), math("\\dot\\omega_{" + n1 + "," + N + "}"),
                                text(" in the input rates (by differentiation; normalised), and their values here:")}));
  const TermCoefficients<Rational> values_here = engine.coefficients(scene.polygon).first;
  std::vector<Rational> flat = values_here.omega_dot;
  flat.insert(flat.end(), values_here.omega_sq.begin(), values_here.omega_sq.end());
  flat.insert(flat.end(), values_here.omega_pair.begin(), values_here.omega_pair.end());
  Table t{{plain("monomial"), plain("coefficient"), plain("value")}, {}};
  std::vector<std::pair<std::string, ex>> rows;
  for (int j = 1; j <= m; ++j)
    rows.emplace_back("\\dot\\omega_{" + std::to_string(j) + "}", wd1.diff(sym.omega_dot(j)));
  for (int j = 1; j <= m; ++j)
    rows.emplace_back("\\omega_{" + std::to_string(j) + "}^2", wd1.diff(sym.omega(j), 2) / 2);
  for (int j = 1; j <= m; ++j)
    for (int l = j + 1; l <= m; ++l)
      rows.emplace_back("\\omega_{" + std::to_string(j) + "}\\omega_{" + std::to_string(l) + "}",
                        wd1.diff(sym.omega(j)).diff(sym.omega(l)));
  for (size_t k = 0; k < rows.size(); ++k) {
    const std::string coefficient = latex_of(rows[k].second.normal());
    Rich cell = tex(coefficient);
    if (coefficient.size() > kFoldTexChars)
      cell = {folded(math(coefficient), fmt::format("a rational function, {} characters of TeX: open to show it",
                                                    coefficient.size()))};
    t.rows.push_back({tex(rows[k].first), std::move(cell), k < flat.size() ? number_rich(flat[k]) : plain("")});
  }
  s.blocks.push_back(table_block(std::move(t)));
  s.blocks.push_back(paragraph(plain("Exact values on this scene:")));
  s.blocks.push_back(table_block(std::move(values)));
  return s;
}

// ---------------------------------------------------------------- construction
Drawing construction_drawing(const Polygon<Rational>& p, const std::vector<FourBarConstruction<Rational>>& cs) {
  const int n = p.n();
  Drawing d;
  for (int j = 1; j <= n; ++j) {
    Segment side{polygon_point(p.joint(j)), polygon_point(p.joint(j + 1))};
    if (j == n) side.color = "#888888", side.label = "fixed";
    d.segments.push_back(side);
  }
  const Point2 kn2 = polygon_point(p.joint(n - 2)), kn1 = polygon_point(p.joint(n - 1)), kn = polygon_point(p.joint(n));
  for (const auto& c : cs) {
    const std::string col = palette_color(static_cast<size_t>(c.j));
    const std::string J = std::to_string(c.j);
    const Point2 kp = polygon_point(c.k_prime);
    d.segments.push_back({kp, kn2, col, Stroke::Solid, true, ""});  // r_j moved to end in K_{n-2}
    d.markers.push_back({kp, "K'_" + J, col, false, false});
    if (c.q.has_value()) {
      const Point2 q = polygon_point(c.q.get());
      d.segments.push_back({kn, q, col, Stroke::Dashed, false, ""});   // line K_n K'_j
      d.segments.push_back({kn1, q, col, Stroke::Dashed, false, ""});  // line K_{n-2} K_{n-1}
      d.markers.push_back({q, "Q_" + J, col, false, true});
      if (c.p_prime.has_value()) {
        const Point2 pp = polygon_point(c.p_prime.get());
        d.angles.push_back({q, {kn1.x - q.x, kn1.y - q.y}, {pp.x - q.x, pp.y - q.y}, "beta_" + J, col});
      }
    }
    if (c.p_prime.has_value()) {
      const Point2 pp = polygon_point(c.p_prime.get());
      d.segments.push_back({kn, pp, col, Stroke::Thin, false, ""});  // line K_{n-1} K_n
      d.segments.push_back({kp, pp, col, Stroke::Thin, false, ""});  // line K'_j K_{n-2}
      d.markers.push_back({pp, "P'_" + J, col, false, true});
    }
  }
  for (int j = 1; j <= n; ++j) d.markers.push_back({polygon_point(p.joint(j)), "K_" + std::to_string(j), "#222222", true, false});
  return d;
}

Section construction_section(const PolygonScene& scene) {
  const Polygon<Rational>& p = scene.polygon;
  const int n = p.n();
  Section s{"construction", "Construction", {}, {}};
  std::vector<FourBarConstruction<Rational>> cs;
  for (int j = 1; j <= n - 3; ++j) cs.push_back(construct_four_bar(p, j));
  s.blocks.push_back(paragraph(
      {text("Four-bar j is "), math("K'_j K_{n-2} K_{n-1} K_n"), text(" with "), math("K'_j = K_{n-2} - r_j"),
       text("; "), math("Q_j = K_{n-2}K_{n-1} \\cap K_nK'_j"), text(", "), math("P'_j = K_{n-1}K_n \\cap K'_jK_{n-2}"),
       text("; the ratios are directed segments and "), math("\\beta_j > 0"),
       text(" iff "), math("P'_j \\to Q_j \\to K_{n-1}"),
       text(" is counter-clockwise (docs/conventions.md §A3). Exact values, each with its decimal:")}));
  Table t{{plain("j"), tex("K'_j"), tex("Q_j"), tex("P'_j"), tex("i_{n-1,j}"), tex("i_{n-2,j}"), tex("\\cot\\beta_j"),
           tex("\\lambda_j")},
          {}};
  for (const auto& c : cs)
    t.rows.push_back({plain(std::to_string(c.j)), point_rich(c.k_prime), defined_rich(c.q), defined_rich(c.p_prime),
                      defined_rich(c.i_out), defined_rich(c.i_cpl), defined_rich(c.cot_beta), defined_rich(c.lambda)});
  s.blocks.push_back(table_block(std::move(t)));
  const Rational D = p.dead_centre_determinant();
  if (!cln::zerop(D)) {
    const Vec2<Rational> a = p.side(n - 2), b = p.side(n - 1);
    s.blocks.push_back(paragraph({text("The signed angle "), math("\\varphi = (r_{n-2}, r_{n-1})"), text(": "),
                                  math("D = " + number_tex(D)), text(", "),
                                  math("\\cot\\varphi = " + number_tex(dot(a, b) / D)), text(", "),
                                  math("|r_{n-2}|^2/D = " + number_tex(norm2(a) / D)), text(".")}));
  }
  s.blocks.push_back(paragraph(plain("The construction is drawn at the top of the report (Summary).")));
  return s;
}

// ---------------------------------------------------------------- numerics
Section numerics_section(GroundTruthEngine& engine, const std::vector<Claim>& catalogue, const PolygonScene& scene) {
  Section s{"numerics", "Numerics", {}, {}};
  s.blocks.push_back(paragraph(plain(
      "Every claim re-checked in each floating-point arithmetic with running error bounds: the largest derived "
      "relative error bound over the claims that hold, the verdicts that differ from the exact ones, and the run time "
      "of the whole check (wall clock, one run).")));
  const PolygonCheck exact = check_polygon(engine, catalogue, scene.name, scene.polygon, scene.rates, Arithmetic::Exact);
  Table t{{plain("arithmetic"), plain("largest relative bound"), plain("verdicts differing from exact"),
           plain("time (ms)")},
          {}};
  for (Arithmetic a : {Arithmetic::Double, Arithmetic::LongDouble, Arithmetic::Mp30, Arithmetic::Mp100}) {
    const auto t0 = std::chrono::steady_clock::now();
    const PolygonCheck c = check_polygon(engine, catalogue, scene.name, scene.polygon, scene.rates, a);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    double worst = 0;
    int differing = 0;
    for (size_t k = 0; k < c.claims.size(); ++k) {
      if (c.claims[k].verdict == Verdict::Holds) worst = std::max(worst, c.claims[k].headline.floating ? c.claims[k].headline.floating->relative_error_bound : 0.0);
      if (k < exact.claims.size() && c.claims[k].verdict != exact.claims[k].verdict) ++differing;
    }
    t.rows.push_back({plain(std::string(to_string(a))), plain(fmt::format("{:.3g}", worst)),
                      plain(std::to_string(differing)), plain(fmt::format("{:.1f}", ms))});
  }
  s.blocks.push_back(table_block(std::move(t)));
  return s;
}

}  // namespace

Drawing polygon_construction_drawing(const Polygon<Rational>& polygon, bool with_construction) {
  std::vector<FourBarConstruction<Rational>> cs;
  for (int j = 1; with_construction && j <= polygon.n() - 3; ++j) cs.push_back(construct_four_bar(polygon, j));
  return construction_drawing(polygon, cs);
}

Document build_polygon_document(GroundTruthEngine& engine, const std::vector<Claim>& catalogue,
                                const PolygonScene& scene, const PolygonCheck& check,
                                const PolygonReportOptions& options) {
  Document d;
  d.title = "Derivation report: " + scene.name;
  d.subtitle = fmt::format("Dijksman (1966), the n-side polygon (n = {}); linkproof", check.n);
  d.sections.push_back(summary_section(scene, check));
  // With an ask, a section is left out when the asked items did not need what it shows.
  if (!check.dead_centre && (!check.ask || check.computed.truth))
    d.sections.push_back(derivation_section(engine, scene, check));
  if (!check.ask || check.computed.construction) d.sections.push_back(construction_section(scene));
  Section terms = terms_section(check.claims);
  if (!terms.subsections.empty()) d.sections.push_back(std::move(terms));
  Section errata = errata_section(check.claims, options.scene_text);
  if (!errata.subsections.empty()) d.sections.push_back(std::move(errata));
  if (options.numerics) d.sections.push_back(numerics_section(engine, catalogue, scene));
  return d;
}

}  // namespace linkproof::report
