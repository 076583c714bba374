#include "report/dimensioned_bound_report.h"

#include <fmt/format.h>

#include <cmath>
#include <vector>

#include "report/number_text.h"

namespace linkproof {

namespace {

using nlohmann::json;

json bound_json(double b) { return radius_text(ResultRadius(b)); }

}  // namespace

std::string bound_short_text(double b) {
  if (std::isinf(b) || std::isnan(b)) return "unbounded";
  if (b <= 0) return "0";
  // Two significant digits rounded up: m.d x 10^e >= b (the division's own rounding is covered
  // by moving the quotient up a little before the ceiling).
  int e = static_cast<int>(std::floor(std::log10(b)));
  double m = std::ceil(b / std::pow(10.0, e - 1) * (1 + 1e-12));
  if (m >= 100) m = std::ceil(m / 10), ++e;
  if (m < 10) m *= 10, --e;
  return fmt::format("{:.1f}e{}", m / 10, e);
}

json dimensioned_bound_json(const DimensionedBound& b) {
  json links = json::object(), joints = json::object(), points = json::object();
  for (const auto& l : b.links) links[l.name] = {{"omega", bound_json(l.omega)}, {"omega_dot", bound_json(l.omega_dot)}};
  const auto point = [](const DimensionedBound::Point& p) {
    json j = {{"v", bound_json(p.v)}, {"a", bound_json(p.a)}};
    if (p.slide) j["sliding_v"] = bound_json(*p.slide);
    if (p.slide_dot) j["sliding_a"] = bound_json(*p.slide_dot);
    if (p.v_unit) j["sliding_v_unit"] = bound_json(*p.v_unit);
    if (p.a_unit) j["sliding_a_unit"] = bound_json(*p.a_unit);
    if (p.coriolis) j["coriolis"] = bound_json(*p.coriolis);
    return j;
  };
  for (const auto& p : b.joints) joints[p.name] = point(p);
  for (const auto& p : b.points) points[p.name] = point(p);
  return {{"bounded", b.bounded},
          {"reason", b.reason.empty() ? json(nullptr) : json(b.reason)},
          {"digits", b.digits},
          {"summary",
           {{"omega", bound_json(b.omega)},
            {"omega_dot", bound_json(b.omega_dot)},
            {"v", bound_json(b.v)},
            {"a", bound_json(b.a)},
            {"sliding_v", bound_json(b.sliding_v)},
            {"sliding_a", bound_json(b.sliding_a)}}},
          {"links", links},
          {"joints", joints},
          {"points", points}};
}

std::string dimensioned_bound_summary(const DimensionedBound& b) {
  if (!b.bounded) return "distance to the dimensioned values: not bounded (" + b.reason + ")";
  std::string s = fmt::format("distance to the dimensioned values: omega <= {}, alpha <= {}, point v <= {}, a <= {}",
                              bound_short_text(b.omega), bound_short_text(b.omega_dot), bound_short_text(b.v),
                              bound_short_text(b.a));
  bool sliders = false;
  for (const auto& p : b.joints) sliders = sliders || p.v_unit.has_value();
  if (sliders)
    s += fmt::format(", sliding v <= {}, a <= {}", bound_short_text(b.sliding_v), bound_short_text(b.sliding_a));
  return s + fmt::format(" (each |result for these rationals - result at the dimensioned values|, per coordinate; "
                         "derived by solving again in {}-digit midpoint-radius arithmetic over every value within the "
                         "bounds above)",
                         b.digits);
}

}  // namespace linkproof
