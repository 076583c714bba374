#include "report/scene_placement_report.h"

#include <cln/integer.h>
#include <cln/rational.h>
#include <fmt/format.h>
#include <fmt/ostream.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <iterator>
#include <map>
#include <vector>

#include "report/dimensioned_bound_report.h"
#include "report/slot_rows.h"

namespace linkproof {

namespace {

using nlohmann::json;

constexpr std::size_t kMaxNamed = 12;  // names per bound in the one-line statement

json value_json(const GivenValue& v, const char* how_key) {
  return {{how_key, v.given_by}, {"exact", v.exact}, {"bound", format_bound(v.bound)}};
}

// "A, B within 1e-60, C within 1e-45": the rationalised subjects grouped by their bound's text.
std::string grouped(const std::vector<GivenValue>& values) {
  std::vector<std::pair<std::string, std::vector<std::string>>> groups;
  for (const GivenValue& v : values) {
    if (v.exact) continue;
    const std::string b = format_bound(v.bound);
    auto it = std::find_if(groups.begin(), groups.end(), [&](const auto& g) { return g.first == b; });
    if (it == groups.end()) it = groups.insert(groups.end(), {b, {}});
    it->second.push_back(v.subject);
  }
  std::vector<std::string> parts;
  for (auto& [bound, subjects] : groups) {
    // A long list is cut (the table and the JSON name every one).
    if (subjects.size() > kMaxNamed) {
      const std::size_t more = subjects.size() - kMaxNamed;
      subjects.resize(kMaxNamed);
      subjects.push_back(fmt::format("and {} more", more));
    }
    parts.push_back(fmt::format("{} within {}", fmt::join(subjects, ", "), bound));
  }
  return fmt::format("{}", fmt::join(parts, ", "));
}

}  // namespace

std::string format_bound(const Rational& b) {
  if (cln::zerop(b)) return "0";
  // 10^(k-1) < b <= 10^k, from an estimate through the lengths of numerator and denominator.
  const long bits = static_cast<long>(cln::integer_length(cln::numerator(b))) -
                    static_cast<long>(cln::integer_length(cln::denominator(b)));
  long k = static_cast<long>(static_cast<double>(bits) * 0.30102999566398120);
  while (cln::expt(Rational(10), k) < b) ++k;
  while (cln::expt(Rational(10), k - 1) >= b) --k;
  return fmt::format("1e{}", k);
}

std::string rationalised_statement(const MechanismScene& scene) {
  const ScenePlacement& p = scene.placement;
  if (!p.is_rationalised()) return "";
  std::vector<std::string> parts;
  // A slot is one joint to its reader: its pin joint P.pin is at P and placed with it.
  std::vector<GivenValue> joints;
  std::copy_if(p.joints.begin(), p.joints.end(), std::back_inserter(joints),
               [&](const GivenValue& v) { return !is_slot_pin_joint(scene.linkage, v.subject); });
  if (const std::string j = grouped(joints); !j.empty()) parts.push_back("joints " + j);
  std::vector<GivenValue> axes = p.axes;
  for (GivenValue& a : axes) a.subject = "of " + a.subject;
  if (const std::string a = grouped(axes); !a.empty()) parts.push_back("prismatic axes " + a);
  if (const std::string r = grouped(p.rates); !r.empty()) parts.push_back("input rates " + r);
  return fmt::format("runs on rationalised positions: {}", fmt::join(parts, "; "));
}

json scene_placement_json(const MechanismScene& scene) {
  const ScenePlacement& p = scene.placement;
  json positions = json::object(), rates = json::object();
  for (const GivenValue& v : p.joints) positions[v.subject] = value_json(v, "given_by");
  for (const GivenValue& a : p.axes)
    if (positions.contains(a.subject)) positions[a.subject]["axis"] = value_json(a, "given_by");
  for (const GivenValue& r : p.rates) rates[r.subject] = value_json(r, "given");
  const std::string statement = rationalised_statement(scene);
  return {{"positions", positions},
          {"input_rates", rates},
          {"rationalised", statement.empty() ? json(nullptr) : json(statement)}};
}

void write_scene_placement_text(std::ostream& out, const MechanismScene& scene, const DimensionedBound* bound) {
  const ScenePlacement& p = scene.placement;
  if (!p.is_dimensioned()) return;
  if (p.is_rationalised()) {
    fmt::print(out,
               "{}\n  (each coordinate of a position or direction, each rate: |rational - dimensioned value| <= the "
               "bound, certified by enclosures in ball arithmetic over exact rationals)\n  The results below are "
               "exact for these rationals.\n",
               rationalised_statement(scene));
    if (bound) fmt::print(out, "  {}\n", dimensioned_bound_summary(*bound));
  } else
    fmt::print(out, "positions from dimensions: every position and rate is exact (rational)\n");
  fmt::print(out, "{:<16} {:<20} {}\n", "joint", "given by", "position used");
  for (const GivenValue& v : p.joints) {
    if (is_slot_pin_joint(scene.linkage, v.subject)) continue;  // at its slot's point, placed with it
    fmt::print(out, "{:<16} {:<20} {}\n", v.subject, v.given_by,
               v.exact ? "exact" : "rationalised, within " + format_bound(v.bound));
  }
  for (const GivenValue& a : p.axes)
    fmt::print(out, "{:<16} {:<20} {}\n", a.subject, a.given_by,
               a.exact ? "exact unit direction" : "rationalised unit direction, within " + format_bound(a.bound));
  for (const GivenValue& r : p.rates)
    fmt::print(out, "{:<16} {:<20} {}\n", r.subject, r.given_by,
               r.exact ? "exact" : "rationalised, within " + format_bound(r.bound));
  fmt::print(out, "\n");
}

}  // namespace linkproof
