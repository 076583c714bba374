#include "linkproof/report/data_check_report.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "linkproof/core/decimal.h"

namespace linkproof {

namespace {

std::string verdict_of(const SampleCheck& s) {
  if (!s.error.empty()) return "unsolvable";
  return s.agrees() ? "agrees" : "differs";
}

}  // namespace

nlohmann::json to_json(const DataCheck& check) {
  nlohmann::json samples = nlohmann::json::array();
  for (const SampleCheck& s : check.samples) {
    nlohmann::json exact = nlohmann::json::object();
    for (size_t l = 0; l < s.alpha.size(); ++l)
      exact[check.link_names[l]] = {{"omega", format_rational(s.omega[l])}, {"alpha", format_rational(s.alpha[l])},
                                    {"omega_decimal", format_decimal(s.omega[l])},
                                    {"alpha_decimal", format_decimal(s.alpha[l])}};
    nlohmann::json checks = nlohmann::json::array();
    for (const auto& c : s.checks)
      checks.push_back({{"link", c.link}, {"quantity", c.quantity}, {"exact", format_decimal(c.exact)},
                        {"user", c.user_text}, {"difference", c.difference}, {"tolerance", c.tolerance},
                        {"verdict", c.agrees ? "agrees" : "differs"}});
    nlohmann::json j = {{"line", s.line},
                        {"sample", s.label},
                        {"t", s.t},
                        {"input_angle", s.input_angle},
                        {"verdict", verdict_of(s)},
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
          {"tolerance_rule", check.tolerance_rule},
          {"samples", samples},
          {"summary",
           {{"samples", check.samples.size()},
            {"agreeing", check.agreeing},
            {"differing", check.differing},
            {"inconsistent", check.inconsistent},
            {"unsolvable", check.unsolvable}}},
          {"exit_status", exit_status(check)}};
}

void write_text(std::ostream& out, const DataCheck& check) {
  fmt::print(out, "check-data: {} against {}\n", check.data, check.scene);
  fmt::print(out, "{} samples: {} agree, {} differ, {} inconsistent positions, {} unsolvable\n\n", check.samples.size(),
             check.agreeing, check.differing, check.inconsistent, check.unsolvable);
  for (const SampleCheck& s : check.samples) {
    fmt::print(out, "{} (line {}{}): {}{}\n", s.label, s.line, s.input_angle.empty() ? "" : ", input " + s.input_angle,
               verdict_of(s), s.consistent ? "" : " -- INCONSISTENT positions");
    fmt::print(out, "  closure: worst {} off by {:.3g} (tolerance {:.3g})\n", s.closure_worst, s.closure_residual,
               s.closure_tolerance);
    if (!s.error.empty()) fmt::print(out, "  error: {}\n", s.error);
    for (const auto& c : s.checks)
      fmt::print(out, "  {:<6} {:<8} exact {:>30}  user {:>22}  diff {:>10.3e}  tol {:>9.2e}  {}\n", c.quantity, c.link,
                 format_decimal(c.exact), c.user_text, c.difference, c.tolerance, c.agrees ? "agrees" : "DIFFERS");
  }
  fmt::print(out, "\ntolerance: {}\n", check.tolerance_rule);
}

}  // namespace linkproof
