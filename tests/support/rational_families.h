// Test support: the fixed-side families of `count` built from the rational relations of
// mechanism/relative_rates.h (the reference the integer families and their ranks are checked
// against), over all n choices of the fixed side.
#pragma once

#include <vector>

#include "count/counting.h"

namespace linkproof::test {

struct RationalFamilies {
  std::vector<RateRelation> velocity;      ///< (5), (6) of each fixed side
  std::vector<RateRelation> eq22;          ///< (22) of each fixed side
  std::vector<RateRelation> acceleration;  ///< (22) then companion of each fixed side
};

/// Side j of `p` is body j - 1; `omega` one velocity per side.
inline RationalFamilies rational_families(const Polygon<Rational>& p, const std::vector<Rational>& omega) {
  const int n = p.n();
  const RelativeRates rates(n);
  BodyPolygon bp;
  bp.polygon = p;
  for (int b = 0; b < n; ++b) bp.bodies.push_back(b);
  RationalFamilies out;
  for (int f = 1; f <= n; ++f) {
    const BodyPolygon q = with_fixed_side(bp, f);
    for (auto& r : velocity_relations(rates, q)) out.velocity.push_back(r);
    const auto acc = acceleration_relations(rates, q, omega);
    out.eq22.push_back(acc[0]);
    out.acceleration.insert(out.acceleration.end(), acc.begin(), acc.end());
  }
  return out;
}

}  // namespace linkproof::test
