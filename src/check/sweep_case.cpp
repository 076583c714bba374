#include "check/sweep_case.h"
#include "check/check_polygon.h"

#include <fmt/format.h>

namespace linkproof {

long SweepPlan::size() const { return static_cast<long>(o_.n_max - o_.n_min + 1) * per_n(); }

std::pair<int, int> SweepPlan::at(long k) const {
  LINKPROOF_ASSERT(k >= 0 && k < size(), "case number out of range");
  const int n = o_.n_min + static_cast<int>(k / per_n());
  const int index = o_.only_index ? *o_.only_index : static_cast<int>(k % per_n());
  return {n, index};
}

long SweepPlan::case_of(int n, int index) const {
  return static_cast<long>(n - o_.n_min) * per_n() + (o_.only_index ? 0 : index);
}

const SweepExample* SweepCase::example_for(const std::string& claim_id) const {
  for (const auto& e : examples)
    if (e.claim_id == claim_id) return &e;
  return nullptr;
}

SweepCase run_sweep_case(GroundTruthEngine& engine, const std::vector<Claim>& catalogue, const SweepOptions& o,
                         long k) {
  const auto [n, index] = SweepPlan(o).at(k);
  SweepCase c;
  c.k = k;
  c.polygon = generate_random_polygon(o.seed, n, index);
  const PolygonCheck check = check_polygon(engine, catalogue, fmt::format("random-n{}-i{}", n, index),
                                           c.polygon.polygon, c.polygon.rates, o.arithmetic, Evidence::Examples);
  c.not_applicable = check.not_applicable;
  for (const ClaimOutcome& outcome : check.claims) {
    c.verdicts[outcome.info.id] = outcome.verdict;
    if (is_unexpected(outcome.info.expected, outcome.verdict) || is_disproof(outcome.info.expected, outcome.verdict))
      c.examples.push_back({outcome.info.id, outcome.verdict, c.polygon, outcome.headline,
                            is_unexpected(outcome.info.expected, outcome.verdict) ? outcome.error : ""});
  }
  return c;
}

}  // namespace linkproof
