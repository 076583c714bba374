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
  if (relative > 0) parts.push_back(fmt::format("{:.3g} |alpha|", relative));
  if (double_bounds > 0) parts.push_back(fmt::format("{:g} x (linkproof's double bound + ulp/2)", double_bounds));
  if (parts.empty()) return "0 (exact equality)";
  return fmt::format("{}", fmt::join(parts, " + "));
}

AlphaComparison compare_alphas(const MechanismTruth& truth, const std::vector<double>& user, const Tolerance& t) {
  AlphaComparison out;
  if (user.size() != truth.links.size()) {
    out.problem = fmt::format("expected {} angular accelerations (one per link, in the scene's link order, the ground "
                              "included), got {}", truth.links.size(), user.size());
    return out;
  }
  out.ok = true;
  for (size_t l = 0; l < user.size(); ++l) {
    const LinkTruth& lt = truth.links[l];
    LinkComparison c;
    c.link = lt.link;
    c.user = user[l];
    c.exact = lt.alpha;
    c.linkproof_double = lt.alpha_double;
    const double nearest = ScalarTraits<double>::from_rational(lt.alpha);
    const double half_ulp = std::abs(std::nextafter(nearest, std::numeric_limits<double>::infinity()) - nearest) / 2;
    c.tolerance = t.absolute + t.relative * std::abs(nearest);
    // Where linkproof's own double solve bounds nothing (a near-singular case), the double
    // criterion judges nothing either: only the plain tolerances apply.
    if (t.double_bounds > 0 && std::isfinite(lt.alpha_double.bound))
      c.tolerance += t.double_bounds * (lt.alpha_double.bound + half_ulp);
    if (!std::isfinite(c.user)) {
      c.difference = c.user;
      c.ok = false;
    } else {
      const Rational diff = rational_from_double(c.user) - lt.alpha;
      c.difference = ScalarTraits<double>::from_rational(diff);
      c.ok = cln::abs(diff) <= rational_from_double(c.tolerance);
    }
    out.ok = out.ok && c.ok;
    out.links.push_back(std::move(c));
  }
  return out;
}

std::string AlphaComparison::report() const {
  if (!problem.empty()) return problem + "\n";
  std::string s = fmt::format("{:<10} {:>24} {:>28} {:>11} {:>10} {:>10}  {}\n", "link", "user alpha",
                              "exact alpha (25 digits)", "difference", "tolerance", "lp bound", "verdict");
  for (const auto& c : links)
    s += fmt::format("{:<10} {:>24.17g} {:>28} {:>11.3e} {:>10.3e} {:>10.3e}  {}\n", c.link, c.user,
                     format_decimal(c.exact), c.difference, c.tolerance, c.linkproof_double.bound,
                     c.ok ? "ok" : "WRONG");
  return s;
}

}  // namespace linkproof::testing
