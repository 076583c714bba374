// Renderers of the stability study (numerics/bench_study.h), written by `linkproof bench`:
//   bench.md            error-vs-time table (route x arithmetic), one section per extreme family
//                       (error of each route in double vs the parameter, condition estimates,
//                       where each route fails and why, the route to trust), adaptive mode;
//   bench.json          the same data for machines (keys below);
//   pareto.svg          worst relative error against time per evaluation, per route and
//                       arithmetic, with the Pareto front;
//   family_<name>.svg   relative error against the family parameter, per route, in double
//                       (solid) and mp30 (dashed), with the double error bound of the condition
//                       estimate (markers).
// JSON keys: "seed", "n", "full", "pareto" [{"route", "arithmetic", "precision_bits", "cases",
// "defined", "median_relative_error", "median_log2_relative_error", "max_log2_relative_error",
// "median_error_bits", "median_ns_per_eval", "on_front"}], "families" [{"name", "description",
// "parameter", "degenerate_quantity", "singular", "trust_route", "findings", "points"
// [{"parameter", "truth_defined", "measurements" [{"route", "arithmetic", "defined",
// "undefined_quantity", "log2_relative_error", "correct_bits", "error_bits"}], "conditions"
// [{"route", "defined", "condition", "bound_double", "bound_long_double"}]}]}], "adaptive"
// [{"corpus", "cases", "by_level" {"double", "long double", "exact"}, "undefined",
// "escalation_rate", "mean_double_ns", "mean_adaptive_ns", "cost_ratio", "fraction_within_2x"}].
// A log2 error of -infinity (an exact result) is written as null.
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "numerics/bench_study.h"

namespace linkproof {

std::string to_markdown(const BenchResult& r);
nlohmann::json to_json(const BenchResult& r);
std::string pareto_svg(const BenchResult& r);
std::string family_svg(const FamilyCurve& c);

/// Writes bench.md, bench.json, pareto.svg and family_<name>.svg into `dir` (created if
/// missing); returns the paths written. Throws InputError(.., "output directory", ..) if it
/// cannot write.
std::vector<std::filesystem::path> write_bench_files(const BenchResult& r, const std::filesystem::path& dir);

}  // namespace linkproof
