// Stability claims (issue 5, item 6): near a singularity of the construction a floating-point
// claim is `inconclusive`, never a false `fails`, and says how its tolerance was derived and
// what to trust instead.
#include <gtest/gtest.h>

#include "dijksman1966.h"
#include "linkproof/eval/check.h"
#include "linkproof/eval/extreme_families.h"

namespace linkproof {
namespace {

Rational ten_to_minus(int k) {
  Rational p = 1;
  for (int i = 0; i < k; ++i) p = p / 10;
  return p;
}

TEST(JudgeStability, NearAPoleOfTheConstructionTrueClaimsAreInconclusiveNotFailsAndNameWhatToTrust) {
  GroundTruthEngine engine;
  for (const char* family : {"q_infinity", "beta_zero", "p_infinity", "dead_centre"}) {
    for (int k : {8, 12, 14}) {
      SCOPED_TRACE(std::string(family) + " at eps = 1e-" + std::to_string(k));
      const ExtremeCase c = find_extreme_family(family)->make(ten_to_minus(k));
      const PolygonCheck r =
          check_polygon(engine, dijksman1966::catalogue(), family, c.polygon, c.rates, Arithmetic::Double);
      int inconclusive = 0;
      for (const ClaimOutcome& claim : r.claims) {
        if (claim.info.expected == Expectation::Holds) {
          EXPECT_NE(claim.verdict, Verdict::Fails) << claim.info.id;
        }
        for (const auto* list : {&claim.instances, &claim.terms}) {
          for (const ComparisonOutcome& o : *list) {
            if (!o.tolerance.empty()) {
              EXPECT_NE(o.tolerance_derivation.find("condition(lhs)"), std::string::npos);
            }
            if (o.verdict == Verdict::Inconclusive) {
              ++inconclusive;
              EXPECT_NE(o.trust_route.find("exact arithmetic"), std::string::npos) << claim.info.id;
            }
          }
        }
      }
      if (k >= 12) {
        EXPECT_GT(inconclusive, 0);
      }
    }
  }
}

TEST(JudgeStability, WellConditionedDoubleChecksStillHoldWithADerivedTolerance) {
  GroundTruthEngine engine;
  const ExtremeCase c = find_extreme_family("q_infinity")->make(1);
  const PolygonCheck r = check_polygon(engine, dijksman1966::catalogue(), "q1", c.polygon, c.rates, Arithmetic::Double);
  for (const ClaimOutcome& claim : r.claims) {
    if (claim.info.id != "dijksman1966.eq22") continue;
    EXPECT_EQ(claim.verdict, Verdict::Holds);
    EXPECT_FALSE(claim.headline.tolerance_derivation.empty());
    EXPECT_TRUE(claim.headline.trust_route.empty());
  }
}

}  // namespace
}  // namespace linkproof
