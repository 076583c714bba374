#include "linkproof/testing/compare.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <limits>

#include "linkproof/core/exact.h"
#include "core/scalar.h"

namespace linkproof::testing {

std::string Tolerance::describe() const {
  std::vector<std::string> parts;
  if (absolute > 0) parts.push_back(fmt::format("{:.3g}", absolute));
  if (relative > 0) parts.push_back(fmt::format("{:.3g} |exact|", relative));
  if (double_bounds > 0) parts.push_back(fmt::format("{:g} x (linkproof's double bound + ulp/2)", double_bounds));
  if (parts.empty()) return "0 (exact equality)";
  return fmt::format("{}", fmt::join(parts, " + "));
}

std::string_view to_string(Rate r) { return r == Rate::Omega ? "omega" : "alpha"; }

RateComparison compare_rates(const MechanismTruth& truth, Rate rate, const std::vector<double>& user,
                             const Tolerance& t) {
  RateComparison out;
  out.rate = rate;
  if (user.size() != truth.links.size()) {
    out.problem = fmt::format("expected {} angular {} (one per link, in the scene's link order, the ground "
                              "included), got {}", truth.links.size(),
                              rate == Rate::Omega ? "velocities" : "accelerations", user.size());
    return out;
  }
  out.ok = true;
  for (size_t l = 0; l < user.size(); ++l) {
    const LinkTruth& lt = truth.links[l];
    LinkComparison c;
    c.link = lt.link;
    c.user = user[l];
    const bool omega = rate == Rate::Omega;
    c.exact = omega ? lt.omega : lt.alpha;
    c.linkproof_double = omega ? lt.omega_double : lt.alpha_double;
    const double nearest = ScalarTraits<double>::from_rational(c.exact);
    const double half_ulp = std::abs(std::nextafter(nearest, std::numeric_limits<double>::infinity()) - nearest) / 2;
    c.tolerance = t.absolute + t.relative * std::abs(nearest);
    // Where linkproof's own double solve bounds nothing (a near-singular case), the double
    // criterion judges nothing either: only the plain tolerances apply.
    if (t.double_bounds > 0 && std::isfinite(c.linkproof_double.bound))
      c.tolerance += t.double_bounds * (c.linkproof_double.bound + half_ulp);
    if (!std::isfinite(c.user)) {
      c.difference = c.user;
      c.ok = false;
    } else {
      const Rational diff = rational_from_double(c.user) - c.exact;
      c.difference = ScalarTraits<double>::from_rational(diff);
      c.ok = cln::abs(diff) <= rational_from_double(c.tolerance);
    }
    out.ok = out.ok && c.ok;
    out.links.push_back(std::move(c));
  }
  return out;
}

std::string RateComparison::report() const {
  if (!problem.empty()) return problem + "\n";
  std::string s = fmt::format("{:<10} {:>24} {:>28} {:>11} {:>10} {:>10}  {}\n", "link", fmt::format("user {}", to_string(rate)),
                              fmt::format("exact {} (25 digits)", to_string(rate)), "difference", "tolerance", "lp bound",
                              "verdict");
  for (const auto& c : links)
    s += fmt::format("{:<10} {:>24.17g} {:>28} {:>11.3e} {:>10.3e} {:>10.3e}  {}\n", c.link, c.user,
                     format_decimal(c.exact), c.difference, c.tolerance, c.linkproof_double.bound,
                     c.ok ? "ok" : "WRONG");
  return s;
}

}  // namespace linkproof::testing
