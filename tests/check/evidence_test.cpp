// Evidence::Headline (what sweeps use) draws the same verdicts and the same headline as
// Evidence::All (what `check` prints), in exact and double arithmetic: only the text of the
// other comparisons is left unmade.
#include <gtest/gtest.h>

#include "dijksman1966.h"
#include "check/check_polygon.h"
#include "report/comparison_text.h"
#include "check/random_polygon.h"

namespace linkproof {
namespace {

void expect_same_headline(const ComparisonOutcome& a, const ComparisonOutcome& b, const std::string& where) {
  EXPECT_EQ(a.label, b.label) << where;
  EXPECT_EQ(a.verdict, b.verdict) << where;
  EXPECT_EQ(lhs_text(a), lhs_text(b)) << where;
  EXPECT_EQ(rhs_text(a), rhs_text(b)) << where;
  EXPECT_EQ(residual_text(a), residual_text(b)) << where;
  EXPECT_EQ(tolerance_text(a), tolerance_text(b)) << where;
  EXPECT_EQ(trust_route_text(a), trust_route_text(b)) << where;
  EXPECT_EQ(a.undefined_quantity, b.undefined_quantity) << where;
  EXPECT_EQ(reason_text(a), reason_text(b)) << where;
}

TEST(CheckEvidence, HeadlineEvidenceGivesTheVerdictsAndHeadlinesOfFullEvidence) {
  const std::uint64_t seed = 13;
  GroundTruthEngine engine;
  for (Arithmetic a : {Arithmetic::Exact, Arithmetic::Double}) {
    for (int n = 4; n <= 8; ++n) {
      for (int i = 0; i < 4; ++i) {
        const auto rc = generate_random_polygon(seed, n, i);
        const PolygonCheck all = check_polygon(engine, dijksman1966::catalogue(), "t", rc.polygon, rc.rates, a);
        const PolygonCheck head =
            check_polygon(engine, dijksman1966::catalogue(), "t", rc.polygon, rc.rates, a, Evidence::Headline);
        ASSERT_EQ(all.claims.size(), head.claims.size());
        for (size_t k = 0; k < all.claims.size(); ++k) {
          const std::string where = std::string(to_string(a)) + " seed 13 n " + std::to_string(n) + " index " +
                                    std::to_string(i) + " " + all.claims[k].info.id;
          EXPECT_EQ(all.claims[k].verdict, head.claims[k].verdict) << where;
          expect_same_headline(all.claims[k].headline, head.claims[k].headline, where);
          EXPECT_TRUE(head.claims[k].terms.empty() && head.claims[k].instances.empty()) << where;
        }
      }
    }
  }
}

}  // namespace
}  // namespace linkproof
