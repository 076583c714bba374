#include "linkproof/testing/claim_result.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "dijksman1966.h"
#include "check/check_polygon.h"
#include "linkproof/core/verdict.h"
#include "report/comparison_text.h"
#include "mechanism_catalogues.h"

namespace linkproof::testing {

namespace {

ClaimResult from_outcome(const ClaimOutcome& o) {
  ClaimResult r;
  r.found = true;
  r.holds = o.verdict == Verdict::Holds;
  r.verdict = o.verdict;
  const ComparisonOutcome& h = o.headline;
  if (o.error.empty() && h.residual && is_exact(*h.residual)) {
    r.residual_exact = std::get<Rational>(*h.residual);
    r.residual = nearest_double(*r.residual_exact);
  }
  if (!o.error.empty())
    r.detail = o.error;
  else if (!h.undefined_quantity.empty())
    r.detail = fmt::format("{} is undefined: {}", h.undefined_quantity, h.reason);
  else
    r.detail = fmt::format("{}lhs {} rhs {} residual {}", h.label.empty() ? "" : h.label + ": ", lhs_text(h), rhs_text(h),
                           residual_text(h));
  return r;
}

ClaimResult unknown(const std::string& id, const std::vector<std::string>& known) {
  ClaimResult r;
  r.verdict = Verdict::Error;
  r.detail = fmt::format("unknown claim: no claim `{}` applies to this case; known here: {}", id, fmt::join(known, ", "));
  return r;
}

}  // namespace

ClaimResult check_claim(const std::string& id, const PolygonCase& c) {
  std::vector<std::string> known;
  for (const Claim& claim : dijksman1966::catalogue()) {
    if (!claim.info.applies_to(c.polygon.n())) continue;
    if (claim.info.id != id) {
      known.push_back(claim.info.id);
      continue;
    }
    thread_local GroundTruthEngine engine;  // GiNaC: one engine per thread
    const PolygonCheck check = check_polygon(engine, {claim}, c.family, c.polygon, c.rates, Arithmetic::Exact);
    if (check.claims.empty()) return unknown(id, known);
    return from_outcome(check.claims.front());
  }
  return unknown(id, known);
}

ClaimResult check_claim(const std::string& id, const MechanismCase& c) {
  const MechanismCheck check = check_mechanism(c.scene, catalogues::mechanism_catalogues(c.scene), Arithmetic::Exact);
  std::vector<std::string> known;
  for (const ClaimOutcome& o : check.claims) {
    if (o.info.id == id) return from_outcome(o);
    known.push_back(o.info.id);
  }
  return unknown(id, known);
}

}  // namespace linkproof::testing
