#include "report/bench_report.h"

#include <fmt/format.h>

#include <cmath>

#include "linkproof/core/error.h"
#include "report/atomic_file.h"
#include "svg_plot.h"
#include "report/json_report.h"

namespace linkproof {

using nlohmann::json;

namespace {

const double kLog10Of2 = std::log10(2.0);

json finite_or_null(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

std::string error_text(double log2_error) { return format_log2_as_decimal(log2_error); }

std::string time_text(double seconds) {
  if (!(seconds > 0)) return "-";
  if (seconds < 1e-6) return fmt::format("{:.1f} ns", seconds * 1e9);
  if (seconds < 1e-3) return fmt::format("{:.2f} us", seconds * 1e6);
  return fmt::format("{:.2f} ms", seconds * 1e3);
}

const RouteMeasurement* find(const CaseStudy& s, Route r, const std::string& arith) {
  for (const RouteMeasurement& m : s.measurements)
    if (m.route == r && m.arithmetic == arith) return &m;
  return nullptr;
}

const ConditionEstimate* find_condition(const CaseStudy& s, Route r) {
  for (const ConditionEstimate& c : s.conditions)
    if (c.route == r) return &c;
  return nullptr;
}

std::string cell(const RouteMeasurement* m) {
  if (!m) return "-";
  if (!m->defined) return "undefined (" + m->undefined_quantity + ")";
  return error_text(std::max(m->n1.log2_relative_error, m->n2.log2_relative_error));
}

}  // namespace

std::string to_markdown(const BenchResult& r) {
  std::string o = "# linkproof bench: error against run time\n\n";
  o += fmt::format(
      "Random {}-gons (seed {}, {} cases), every route x arithmetic; error against the exact value "
      "(worst of omega-dot_{{n-1,n}} and the companion omega-dot_{{n-2,n}}), time per evaluation of both. "
      "Error bits = log2(1 + ulps) in the arithmetic's own precision. * = on the Pareto front.\n\n",
      r.options.n, r.options.seed, r.options.random_cases);
  o += "| route | arithmetic | bits | defined | median rel. error | worst rel. error | error bits | time/eval | front |\n";
  o += "|---|---|---:|---:|---:|---:|---:|---:|:-:|\n";
  for (const ParetoEntry& e : r.pareto)
    o += fmt::format("| {} | {} | {} | {}/{} | {} | {} | {:.1f} | {} | {} |\n", to_string(e.route), e.arithmetic,
                     e.precision_bits ? std::to_string(e.precision_bits) : "exact", e.defined, e.cases,
                     error_text(e.median_log2_error), error_text(e.max_log2_error), e.median_error_bits,
                     time_text(e.median_seconds), e.on_front ? "*" : "");
  o += "\n# Extreme and stiff families\n\n";
  o += "Relative error in double per route (worst of both accelerations); `cond` is the condition estimate "
       "bound / u of a Tracked<double> evaluation of that route, which bounds the double error.\n";
  for (const FamilyCurve& c : r.families) {
    const ExtremeFamily& f = *c.family;
    o += fmt::format("\n## {}\n\n{}", f.name, f.description);
    if (!f.degenerate_quantity.empty())
      o += fmt::format(". At {} = 0: {} {}.", f.parameter, f.degenerate_quantity,
                       f.singular ? "= 0, the mechanism's singularity" : "undefined (the construction breaks)");
    o += fmt::format("\n\nTrust: **{}**.\n\n", c.trust_route.empty() ? "none" : c.trust_route);
    for (const std::string& s : c.findings) o += "- " + s + "\n";
    o += fmt::format("\n| {} | construction | closed-forms | direct-solve | symbolic-tape | mp30 construction | "
                     "cond (construction) | cond (closed-forms) |\n|---|---|---|---|---|---|---|---|\n",
                     f.parameter);
    for (const FamilyPoint& p : c.points) {
      const auto cond = [&](Route route) -> std::string {
        const ConditionEstimate* e = find_condition(p.study, route);
        if (!e) return "-";
        if (!e->defined) return "undefined";
        return std::isfinite(e->condition) ? fmt::format("{:.2g}", e->condition) : "unbounded";
      };
      o += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} |\n", format_parameter(p.parameter),
                       cell(find(p.study, Route::Construction, "double")), cell(find(p.study, Route::ClosedForms, "double")),
                       cell(find(p.study, Route::DirectSolve, "double")), cell(find(p.study, Route::SymbolicTape, "double")),
                       cell(find(p.study, Route::Construction, "mp30")), cond(Route::Construction),
                       cond(Route::ClosedForms));
    }
  }
  o += "\n# Adaptive mode (certified omega-dot: a priori double -> running double -> running long double -> "
       "exact)\n\n";
  o += "| corpus | request | cases | by a priori double | by running double | by long double | by exact | undefined | "
       "escalation rate | plain double | adaptive | cost ratio | within 2x |\n"
       "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const AdaptiveSummary& a : r.adaptive)
    o += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {:.2f}% | {} | {} | {:.2f} | {:.1f}% |\n", a.corpus,
                     a.request, a.cases, a.by_stage[0], a.by_stage[1], a.by_stage[2], a.by_stage[3], a.undefined,
                     100 * a.escalation_rate(),
                     time_text(a.mean_double_seconds), time_text(a.mean_adaptive_seconds),
                     a.mean_double_seconds > 0 ? a.mean_adaptive_seconds / a.mean_double_seconds : 0.0,
                     100 * a.fraction_within_2x);
  return o;
}

json to_json(const BenchResult& r) {
  json j{{"seed", r.options.seed}, {"n", r.options.n}, {"full", r.options.full}};
  j["pareto"] = json::array();
  for (const ParetoEntry& e : r.pareto)
    j["pareto"].push_back({{"route", std::string(to_string(e.route))},
                           {"arithmetic", e.arithmetic},
                           {"precision_bits", e.precision_bits},
                           {"cases", e.cases},
                           {"defined", e.defined},
                           {"median_relative_error", error_text(e.median_log2_error)},
                           {"median_log2_relative_error", finite_or_null(e.median_log2_error)},
                           {"max_log2_relative_error", finite_or_null(e.max_log2_error)},
                           {"median_error_bits", finite_or_null(e.median_error_bits)},
                           {"median_ns_per_eval", finite_or_null(e.median_seconds * 1e9)},
                           {"on_front", e.on_front}});
  j["families"] = json::array();
  for (const FamilyCurve& c : r.families) {
    json points = json::array();
    for (const FamilyPoint& p : c.points) {
      json ms = json::array(), cs = json::array();
      for (const RouteMeasurement& m : p.study.measurements) {
        json mj{{"route", std::string(to_string(m.route))}, {"arithmetic", m.arithmetic}, {"defined", m.defined}};
        if (!m.defined) {
          mj["undefined_quantity"] = m.undefined_quantity;
        } else {
          mj["log2_relative_error"] = finite_or_null(std::max(m.n1.log2_relative_error, m.n2.log2_relative_error));
          mj["correct_bits"] = finite_or_null(std::min(m.n1.correct_bits, m.n2.correct_bits));
          mj["error_bits"] = std::max(m.n1.error_bits, m.n2.error_bits);
        }
        ms.push_back(std::move(mj));
      }
      for (const ConditionEstimate& e : p.study.conditions)
        cs.push_back({{"route", std::string(to_string(e.route))},
                      {"defined", e.defined},
                      {"condition", finite_or_null(e.condition)},
                      {"bound_double", finite_or_null(std::max(e.bound_double_n1, e.bound_double_n2))},
                      {"bound_long_double", finite_or_null(std::max(e.bound_long_double_n1, e.bound_long_double_n2))}});
      points.push_back({{"parameter", format_parameter(p.parameter)},
                        {"truth_defined", p.study.exact_n1.has_value()},
                        {"measurements", std::move(ms)},
                        {"conditions", std::move(cs)}});
    }
    j["families"].push_back({{"name", c.family->name},
                             {"description", c.family->description},
                             {"parameter", c.family->parameter},
                             {"degenerate_quantity", c.family->degenerate_quantity},
                             {"singular", c.family->singular},
                             {"trust_route", c.trust_route},
                             {"findings", c.findings},
                             {"points", std::move(points)}});
  }
  j["adaptive"] = json::array();
  for (const AdaptiveSummary& a : r.adaptive)
    j["adaptive"].push_back(
        {{"corpus", a.corpus},
         {"request", a.request},
         {"cases", a.cases},
         {"by_stage",
          {{"a priori double", a.by_stage[0]},
           {"running double", a.by_stage[1]},
           {"running long double", a.by_stage[2]},
           {"exact", a.by_stage[3]}}},
         {"by_level", {{"double", a.by_level[0]}, {"long double", a.by_level[1]}, {"exact", a.by_level[2]}}},
         {"undefined", a.undefined},
         {"escalation_rate", a.escalation_rate()},
         {"mean_double_ns", a.mean_double_seconds * 1e9},
         {"mean_adaptive_ns", a.mean_adaptive_seconds * 1e9},
         {"cost_ratio", a.mean_double_seconds > 0 ? a.mean_adaptive_seconds / a.mean_double_seconds : 0.0},
         {"fraction_within_2x", a.fraction_within_2x}});
  return j;
}

std::string pareto_svg(const BenchResult& r) {
  SvgPlot plot;
  plot.title = fmt::format("omega-dot: worst relative error vs time per evaluation (random {}-gons)", r.options.n);
  plot.x_label = "time per evaluation [s]";
  plot.y_label = "worst relative error (exact results at the bottom)";
  double floor = 0;
  for (const ParetoEntry& e : r.pareto)
    if (e.defined && std::isfinite(e.max_log2_error)) floor = std::min(floor, e.max_log2_error * kLog10Of2);
  floor -= 20;  // exact results (error 0) are drawn below every finite error
  std::vector<std::pair<double, double>> front;
  for (Route route : kAllRoutes) {
    SvgSeries s;
    s.name = std::string(to_string(route));
    s.color = palette_color(static_cast<size_t>(route));
    s.line = false;
    for (const ParetoEntry& e : r.pareto) {
      if (e.route != route || e.defined == 0 || !(e.median_seconds > 0)) continue;
      const double x = std::log10(e.median_seconds);
      const double y = std::isfinite(e.max_log2_error) ? e.max_log2_error * kLog10Of2 : floor;
      s.points.emplace_back(x, y);
      plot.labels.push_back({x, y, e.arithmetic});
      if (e.on_front) front.emplace_back(x, y);
    }
    plot.series.push_back(std::move(s));
  }
  std::sort(front.begin(), front.end());
  plot.series.push_back({"Pareto front", "#000000", true, true, false, front});
  return plot.render();
}

std::string family_svg(const FamilyCurve& c) {
  const ExtremeFamily& f = *c.family;
  SvgPlot plot;
  plot.title = fmt::format("{}: relative error vs {}", f.name, f.parameter);
  if (!f.degenerate_quantity.empty()) plot.title += fmt::format(" ({} at {} = 0)", f.degenerate_quantity, f.parameter);
  plot.x_label = f.parameter;
  plot.y_label = "relative error of omega-dot (worst of both sides)";
  for (Route route : kAllRoutes) {
    for (const char* arith : {"double", "mp30"}) {
      SvgSeries s;
      s.name = std::string(to_string(route)) + " " + arith;
      s.color = palette_color(static_cast<size_t>(route));
      s.dashed = std::string(arith) != "double";
      for (const FamilyPoint& p : c.points) {
        const RouteMeasurement* m = find(p.study, route, arith);
        if (!m || !m->defined) continue;
        s.points.emplace_back(parameter_log10(p.parameter),
                              std::max(m->n1.log2_relative_error, m->n2.log2_relative_error) * kLog10Of2);
      }
      plot.series.push_back(std::move(s));
    }
    SvgSeries bound;
    bound.name = std::string(to_string(route)) + " double bound";
    bound.color = palette_color(static_cast<size_t>(route));
    bound.line = false;
    for (const FamilyPoint& p : c.points) {
      const ConditionEstimate* e = find_condition(p.study, route);
      if (!e || !e->defined) continue;
      bound.points.emplace_back(parameter_log10(p.parameter),
                                std::log10(std::max(e->bound_double_n1, e->bound_double_n2)));
    }
    plot.series.push_back(std::move(bound));
  }
  return plot.render();
}

std::vector<std::filesystem::path> write_bench_files(const BenchResult& r, const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError("<api>", "output directory", "cannot create directory '" + dir.string() + "': " + ec.message());
  std::vector<std::filesystem::path> written;
  const auto write = [&](const std::string& name, const std::string& text) {
    const std::filesystem::path p = dir / name;
    write_file_atomically(p, text, "output directory");
    written.push_back(p);
  };
  write("bench.md", to_markdown(r));
  write("bench.json", json_text(to_json(r)) + "\n");
  write("pareto.svg", pareto_svg(r));
  for (const FamilyCurve& c : r.families) write("family_" + c.family->name + ".svg", family_svg(c));
  return written;
}

}  // namespace linkproof
