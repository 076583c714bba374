// Evidence::Headline draws the same verdicts and the same headline as Evidence::All (what
// `check` prints), in exact and double arithmetic: only the text of the other comparisons is left
// unmade. Evidence::Examples (what sweeps use) draws the same verdicts, and the same headline
// where a sweep keeps one; an exact total whose sides are one polynomial is made only on demand,
// and judged with its text it is what the eager route makes.
#include <gtest/gtest.h>

#include "dijksman1966.h"
#include "check/check_polygon.h"
#include "report/comparison_text.h"
#include "check/random_polygon.h"
#include "core/inline_rational.h"

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

/// Checks random polygons (n = 4..8, four each, from `seed`) in exact and double arithmetic with
/// full evidence and with `evidence`, and calls `compare(full, other, where)` for every claim.
template <class Compare>
void for_each_claim_both_ways(std::uint64_t seed, Evidence evidence, Compare compare) {
  GroundTruthEngine engine;
  for (Arithmetic a : {Arithmetic::Exact, Arithmetic::Double}) {
    for (int n = 4; n <= 8; ++n) {
      for (int i = 0; i < 4; ++i) {
        const auto rc = generate_random_polygon(seed, n, i);
        const PolygonCheck all = check_polygon(engine, dijksman1966::catalogue(), "t", rc.polygon, rc.rates, a);
        const PolygonCheck other =
            check_polygon(engine, dijksman1966::catalogue(), "t", rc.polygon, rc.rates, a, evidence);
        ASSERT_EQ(all.claims.size(), other.claims.size());
        for (size_t k = 0; k < all.claims.size(); ++k) {
          const std::string where = std::string(to_string(a)) + " seed " + std::to_string(seed) + " n " +
                                    std::to_string(n) + " index " + std::to_string(i) + " " + all.claims[k].info.id;
          EXPECT_EQ(all.claims[k].verdict, other.claims[k].verdict) << where;
          EXPECT_TRUE(other.claims[k].terms.empty() && other.claims[k].instances.empty()) << where;
          compare(all.claims[k], other.claims[k], where);
        }
      }
    }
  }
}

TEST(CheckEvidence, HeadlineEvidenceGivesTheVerdictsAndHeadlinesOfFullEvidence) {
  for_each_claim_both_ways(13, Evidence::Headline,
                           [](const ClaimOutcome& all, const ClaimOutcome& head, const std::string& where) {
                             expect_same_headline(all.headline, head.headline, where);
                           });
}

TEST(CheckEvidence, ExamplesEvidenceGivesTheVerdictsAndTheHeadlinesASweepKeeps) {
  int kept = 0, left = 0;
  const auto compare = [&](const ClaimOutcome& o, const ClaimOutcome& ex, const std::string& where) {
    if (is_unexpected(o.info.expected, o.verdict) || is_disproof(o.info.expected, o.verdict)) {
      expect_same_headline(o.headline, ex.headline, where);
      ++kept;
    } else {
      EXPECT_TRUE(ex.headline.label.empty()) << where;
      ++left;
    }
  };
  for_each_claim_both_ways(17, Evidence::Examples, compare);
  std::printf("seed 17: %d headlines kept (unexpected verdicts or disproofs), %d left unmade\n", kept, left);
  EXPECT_GT(kept, 100);
  EXPECT_GT(left, 100);
}

TEST(CheckEvidence, AnExactTotalMadeOnDemandIsJudgedAsTheEagerOne) {
  const std::uint64_t seed = 19;
  GroundTruthEngine engine;
  int on_demand = 0, eager = 0;
  for (int n = 4; n <= 9; ++n) {
    for (int i = 0; i < 3; ++i) {
      const auto rc = generate_random_polygon(seed, n, i);
      auto now = build_polygon_context<InlineRational>(engine, rc.polygon, rc.rates);
      auto later = build_polygon_context<InlineRational>(engine, rc.polygon, rc.rates);
      later.values_on_demand = true;
      for (const Claim& claim : dijksman1966::catalogue()) {
        if (!claim.info.applies_to(n)) continue;
        const std::string where =
            "seed 19 n " + std::to_string(n) + " index " + std::to_string(i) + " " + claim.info.id;
        ClaimSides<InlineRational> a, b;
        try {
          a = claim.function<InlineRational>()(now);
          b = claim.function<InlineRational>()(later);
        } catch (const UndefinedQuantity&) {
          continue;  // the claim is undefined here in both routes (its run_claim says so)
        }
        ASSERT_EQ(a.instances.size(), b.instances.size()) << where;
        for (size_t k = 0; k < a.instances.size(); ++k) {
          EXPECT_FALSE(a.instances[k].same_value) << where;
          if (b.instances[k].same_value) {
            ++on_demand;
            // A verdict alone makes no value: the sides are one polynomial.
            EXPECT_EQ(judge_verdict(b.instances[k]), Verdict::Holds) << where;
          } else {
            ++eager;
          }
          expect_same_headline(judge(a.instances[k]), judge(b.instances[k]), where);
        }
      }
    }
  }
  std::printf("seed 19: %d totals made on demand, %d eagerly\n", on_demand, eager);
  EXPECT_GT(on_demand, 100);
  EXPECT_GT(eager, 10);
}

TEST(CheckEvidence, AVerdictAloneReadsNoValueMadeOnDemand) {
  int made = 0;
  Comparison<InlineRational> c{"total", Defined<InlineRational>::pending(), Defined<InlineRational>::pending()};
  c.same_value = [&made] {
    ++made;
    return InlineRational(Rational(7) / 3);
  };
  EXPECT_EQ(judge_verdict(c), Verdict::Holds);
  EXPECT_EQ(made, 0);
  const ComparisonOutcome o = judge(c);
  EXPECT_EQ(made, 1);
  EXPECT_EQ(o.verdict, Verdict::Holds);
  EXPECT_EQ(lhs_text(o), "7/3");
  EXPECT_EQ(rhs_text(o), "7/3");
  EXPECT_EQ(residual_text(o), "0");
}

}  // namespace
}  // namespace linkproof
