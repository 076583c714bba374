#include "report/count_report.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

namespace linkproof {

nlohmann::json to_json(const CountClaim& c) {
  nlohmann::json j{{"id", c.id},
                   {"verdict", to_string(c.verdict)},
                   {"expected", to_string(c.expected)},
                   {"as_expected", c.as_expected()},
                   {"statement", c.statement},
                   {"expected_value", c.expected_value},
                   {"observed_value", c.observed_value},
                   {"reason", c.reason}};
  if (c.rank) {
    j["relations"] = c.rank->relations;
    j["unknowns"] = c.rank->unknowns;
    j["rank"] = c.rank->rank;
    j["augmented_rank"] = c.rank->augmented_rank;
    j["consistent"] = c.rank->consistent();
    j["seconds"] = c.rank->seconds;
  }
  return j;
}

nlohmann::json to_json(const CountReport& r, const ClaimsStatus& status) {
  LINKPROOF_ASSERT(status.as_expected.size() == r.claims.size(), "one status per claim");
  nlohmann::json claims = nlohmann::json::array();
  int proved = 0, on_samples = 0, disproved = 0, error = 0;
  double seconds = 0;
  for (size_t k = 0; k < r.claims.size(); ++k) {
    const CountClaim& c = r.claims[k];
    claims.push_back(to_json(c));
    claims.back()["as_expected"] = static_cast<bool>(status.as_expected[k]);
    if (c.samples) claims.back()["samples"] = c.samples;
    (c.verdict == CountVerdict::Proved            ? proved
     : c.verdict == CountVerdict::HoldsOnSamples ? on_samples
     : c.verdict == CountVerdict::Disproved      ? disproved
                                                 : error) += 1;
    if (c.rank) seconds += c.rank->seconds;
  }
  return {{"subject", r.subject},
          {"claims", claims},
          {"notes", r.notes},
          {"summary",
           {{"proved", proved}, {"holds_on_samples", on_samples}, {"disproved", disproved}, {"error", error},
            {"seconds", seconds}}},
          {"exit_status", status.exit_status}};
}

void write_text(std::ostream& out, const CountReport& r, const ClaimsStatus& status) {
  LINKPROOF_ASSERT(status.as_expected.size() == r.claims.size(), "one status per claim");
  fmt::print(out, "linkproof count: {}\n\n", r.subject);
  fmt::print(out, "{:<16} {:<42} {:>24} {:>24} {:>16} {:>9}\n", "verdict", "claim", "stated", "computed",
             "relations x unk", "ms");
  for (size_t k = 0; k < r.claims.size(); ++k) {
    const CountClaim& c = r.claims[k];
    const std::string size = c.rank ? fmt::format("{} x {}", c.rank->relations, c.rank->unknowns) : "";
    const std::string ms = c.rank ? fmt::format("{:.1f}", 1000 * c.rank->seconds) : "";
    std::string verdict(to_string(c.verdict));
    if (!status.as_expected[k]) verdict += "!";
    fmt::print(out, "{:<16} {:<42} {:>24} {:>24} {:>16} {:>9}\n", verdict, c.id, c.expected_value,
               c.observed_value, size, ms);
  }
  int bad = 0;
  for (size_t k = 0; k < r.claims.size(); ++k)
    if (const CountClaim& c = r.claims[k]; !status.as_expected[k] || c.verdict == CountVerdict::Error) {
      if (bad++ == 0) fmt::print(out, "\n");
      fmt::print(out, "{} {} (expected {}): {}\n  {}\n", c.id, to_string(c.verdict), to_string(c.expected),
                 c.reason, c.statement);
    }
  for (const auto& n : r.notes) fmt::print(out, "\n{}\n", n);
  fmt::print(out, "\n{} claims, {} not as expected ('!' marks them; an erratum reading is expected to be "
                  "disproved; holds_on_samples: a rank that depends on the geometry, computed exactly on that many "
                  "polygons, not proved for every configuration)\n",
             r.claims.size(), bad);
}

}  // namespace linkproof
