// The whole stability study behind `linkproof bench` (docs/conventions.md §A6): error against run time per
// route x arithmetic on random polygons (the Pareto front), error against the parameter of every
// extreme family (numerics/extreme_families.h) with condition estimates, and the cost and escalation
// rate of the adaptive mode (numerics/adaptive.h). The result is data; report/bench_report.h renders
// it as Markdown, JSON and SVG.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <set>
#include <string>
#include <vector>

#include "numerics/extreme_families.h"
#include "numerics/stability.h"

namespace linkproof {

struct BenchOptions {
  std::set<std::string> families;  ///< extreme families to run (names); empty = all
  bool full = false;               ///< full parameter lists, more cases, longer timing
  int random_cases = 3;            ///< random polygons for the error-vs-time table
  int n = 5;                       ///< their number of sides
  double time_budget_seconds = 1e-3;  ///< timing per route x arithmetic x case
  int adaptive_cases = 200;           ///< random polygons for the adaptive-mode statistics
  std::uint64_t seed = 1966;
  /// Called after each unit of work with (done, total): the CLI's progress bar.
  std::function<void(int, int)> progress;
};

/// One row of the error-vs-time table: a route in an arithmetic, over the random cases.
struct ParetoEntry {
  Route route = Route::ClosedForms;
  std::string arithmetic;
  int precision_bits = 0;
  int cases = 0, defined = 0;
  double median_log2_error = 0;  ///< omega-dot_{n-1,n}; -inf if exact
  double max_log2_error = 0;     ///< worst of omega-dot_{n-1,n} and the companion
  double median_error_bits = 0;  ///< log2(1 + ulps) in the arithmetic's own precision
  double median_seconds = 0;     ///< per evaluation of both accelerations
  bool on_front = false;         ///< not dominated in (time, error) by another entry
};

struct FamilyPoint {
  Rational parameter;
  CaseStudy study;
};

struct FamilyCurve {
  const ExtremeFamily* family = nullptr;
  std::vector<FamilyPoint> points;
  /// Per route: where it fails in double and why, e.g. "construction: 30 bits lost at
  /// epsilon = 1e-8; undefined at 0 (Q_1: ...)"; and the route to trust on this family.
  std::vector<std::string> findings;
  std::string trust_route;
};

struct AdaptiveSummary {
  std::string corpus;
  std::string request;      ///< "2^-26 relative" (the default), "2^-40 relative", "correctly rounded"
  std::array<int, 4> by_stage{};  ///< delivered by a priori double, running double, running long double, exact
  int cases = 0;
  std::array<int, 3> by_level{};  ///< delivered by double, long double, exact
  int undefined = 0;
  double mean_double_seconds = 0, mean_adaptive_seconds = 0;
  double fraction_within_2x = 0;  ///< cases with adaptive time <= 2 x plain double time
  double escalation_rate() const { return cases ? 1.0 - static_cast<double>(by_level[0]) / cases : 0.0; }
};

struct BenchResult {
  BenchOptions options;
  std::vector<ParetoEntry> pareto;
  std::vector<FamilyCurve> families;
  std::vector<AdaptiveSummary> adaptive;  ///< random pentagons; the extreme-family corpus
};

/// Runs the study. Unknown family names are an InputError("<api>", "families", ...).
BenchResult run_bench(const BenchOptions& options);

/// The parameter as text: "1e-8", "0", "1000".
std::string format_parameter(const Rational& x);
/// log10 of a positive parameter (for plots); for 0, nullopt-like -inf.
double parameter_log10(const Rational& x);

}  // namespace linkproof
