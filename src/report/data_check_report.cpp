#include "report/data_check_report.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "linkproof/core/exact.h"

namespace linkproof {

namespace {

/// The verdict rule of check-data (numerics/data_check.h), stated in every report.
const char* const kTolerancePolicy =
    "tolerance = radius of the Tracked<double> solve started from the data's digit uncertainties (positions and "
    "input rates) + the uncertainty of the user's digits; differs iff |user - exact| > tolerance; inconclusive "
    "if the tolerance is not finite or not smaller than |exact|; agrees otherwise (decided exactly); digits: half a "
    "unit of the last digit, one ulp for 16+ significant digits (a printed double), integers and fractions exact; "
    "the scene's coordinates are exact (one ulp for a 16+ digit decimal)";

// The JSON contract's spellings (docs/testing.md).
const char* to_word(SampleVerdict v) {
  switch (v) {
    case SampleVerdict::Agrees: return "agrees";
    case SampleVerdict::Differs: return "differs";
    case SampleVerdict::Inconclusive: return "inconclusive";
    case SampleVerdict::NothingCompared: return "nothing compared";
    case SampleVerdict::Unsolvable: return "unsolvable";
  }
  return "";
}

const char* to_word(RateOutcome o) {
  switch (o) {
    case RateOutcome::Agrees: return "agrees";
    case RateOutcome::Differs: return "differs";
    case RateOutcome::Inconclusive: return "inconclusive";
  }
  return "";
}

/// The CSV column's prefix: omega, alpha, v, a.
const char* to_word(RecordedQuantity q) {
  switch (q) {
    case RecordedQuantity::Omega: return "omega";
    case RecordedQuantity::Alpha: return "alpha";
    case RecordedQuantity::SlideVelocity: return "v";
    case RecordedQuantity::SlideAcceleration: return "a";
  }
  return "";
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c);
  return s;
}

}  // namespace

nlohmann::json to_json(const DataCheck& check, int exit_status) {
  nlohmann::json samples = nlohmann::json::array();
  for (const SampleCheck& s : check.samples) {
    nlohmann::json exact = nlohmann::json::object();
    for (size_t l = 0; l < s.alpha.size(); ++l)
      exact[check.link_names[l]] = {{"omega", format_rational(s.omega[l])}, {"alpha", format_rational(s.alpha[l])},
                                    {"omega_decimal", format_decimal(s.omega[l])},
                                    {"alpha_decimal", format_decimal(s.alpha[l])}};
    nlohmann::json checks = nlohmann::json::array();
    for (const auto& c : s.checks)
      checks.push_back({{c.is_slide() ? "joint" : "link", c.name},
                        {"quantity", to_word(c.quantity)},
                        {"exact", format_decimal(c.exact)},
                        {"exact_rational", format_rational(c.exact)},
                        {"user", c.user_text},
                        {"difference", c.difference},
                        {"tolerance", c.tolerance},
                        {"outcome", to_word(c.outcome)},
                        {"agrees", c.agrees()},
                        {"verdict", to_word(c.outcome)}});
    nlohmann::json j = {{"line", s.line},
                        {"sample", s.label},
                        {"t", s.t},
                        {"input_angle", s.input_angle},
                        {"verdict", to_word(s.verdict())},
                        {"consistent", s.consistent},
                        {"closure", {{"residual", s.closure_residual}, {"tolerance", s.closure_tolerance}, {"worst", s.closure_worst}}},
                        {"exact", exact},
                        {"checks", checks}};
    if (!s.error.empty()) j["error"] = s.error;
    samples.push_back(std::move(j));
  }
  return {{"scene", check.scene},
          {"data", check.data},
          {"links", check.link_names},
          {"tolerance_rule", kTolerancePolicy},
          {"samples", samples},
          {"summary",
           {{"samples", check.samples.size()},
            {"agreeing", check.agreeing},
            {"differing", check.differing},
            {"inconclusive", check.inconclusive},
            {"nothing_compared", check.nothing_compared},
            {"inconsistent", check.inconsistent},
            {"unsolvable", check.unsolvable},
            {"values_compared", check.compared}}},
          {"exit_status", exit_status}};
}

void write_text(std::ostream& out, const DataCheck& check) {
  fmt::print(out, "check-data: {} against {}\n", check.data, check.scene);
  fmt::print(out, "{} samples: {} agree, {} differ, {} inconclusive, {} nothing compared, {} inconsistent positions, {} "
                  "unsolvable ({} values compared)\n",
             check.samples.size(), check.agreeing, check.differing, check.inconclusive, check.nothing_compared,
             check.inconsistent, check.unsolvable, check.compared);
  if (check.compared == 0) fmt::print(out, "nothing compared in the whole file: not a pass\n");
  fmt::print(out, "\n");
  for (const SampleCheck& s : check.samples) {
    fmt::print(out, "{} (line {}{}): {}{}\n", s.label, s.line, s.input_angle.empty() ? "" : ", input " + s.input_angle,
               to_word(s.verdict()), s.consistent ? "" : " -- INCONSISTENT positions");
    fmt::print(out, "  closure: worst {} off by {:.3g} (tolerance {:.3g})\n", s.closure_worst, s.closure_residual,
               s.closure_tolerance);
    if (!s.error.empty()) fmt::print(out, "  error: {}\n", s.error);
    for (const auto& c : s.checks)
      fmt::print(out, "  {:<6} {:<8} exact {:>30}  user {:>22}  diff {:>10.3e}  tol {:>9.2e}  {}\n", to_word(c.quantity),
                 c.name, format_decimal(c.exact), c.user_text, c.difference, c.tolerance,
                 c.outcome == RateOutcome::Agrees ? std::string("agrees") : upper(to_word(c.outcome)));
  }
  fmt::print(out, "\ntolerance: {}\n", kTolerancePolicy);
}

}  // namespace linkproof
