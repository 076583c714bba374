// Exact ranks of the rate relations (conventions §A7): triangle relations for n = 3..60, the rank-2
// families over all choices of the fixed side, and must-fail cases.
#include "count/counting.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "count/count_claim.h"
#include "check/random_polygon.h"
#include "support/polygons.h"

namespace linkproof {
namespace {

TEST(Counting, TriangleRelationsHaveRankTForEveryNFrom3To60) {
  for (int n = 3; n <= 60; ++n) {
    const RankResult r = count_triangle_relations(n);
    EXPECT_EQ(r.relations, static_cast<long>(n) * (n - 1) * (n - 2) / 6) << "n = " << n;
    EXPECT_EQ(r.unknowns, n * (n - 1) / 2) << "n = " << n;
    EXPECT_EQ(r.rank, (n - 1) * (n - 2) / 2) << "n = " << n;
    EXPECT_TRUE(r.consistent()) << "n = " << n;
    // Dijksman's balance with the computed rank.
    EXPECT_EQ(n * (n - 1) / 2 - (n - 3), 2 + r.rank) << "n = " << n;
  }
}

TEST(Counting, TriangleRankDoesNotDependOnTheOrderOfTheRelations) {
  const int n = 14;
  const RelativeRates rates(n);
  std::vector<RateRelation> rel = triangle_relations(rates);
  std::mt19937 gen(7);  // fixed seed
  std::shuffle(rel.begin(), rel.end(), gen);
  RowEchelon<Rational> e(rates.columns());
  add_and_rank(e, rel);
  EXPECT_EQ(e.rank(), (n - 1) * (n - 2) / 2);
}

TEST(Counting, RelativeRateColumnsAreALexicographicBijection) {
  const RelativeRates rates(9);
  int expected = 0;
  for (int i = 0; i < 9; ++i)
    for (int k = i + 1; k < 9; ++k) {
      EXPECT_EQ(rates.column(i, k), expected);
      EXPECT_EQ(rates.bodies_of(expected), std::make_pair(i, k));
      ++expected;
    }
  EXPECT_EQ(expected, rates.columns());
  EXPECT_EQ(rates.term(5, 2, 3).first, rates.column(2, 5));
  EXPECT_EQ(rates.term(5, 2, 3).second, -3);
}

void expect_rank_two_families(const Polygon<Rational>& p, const std::vector<Rational>& omega) {
  const auto fams = count_fixed_side_relations(p, omega);
  ASSERT_EQ(fams.size(), 3u);
  const int n = p.n();
  EXPECT_EQ(fams[0].relations, 2 * n);
  EXPECT_EQ(fams[1].relations, n);
  EXPECT_EQ(fams[2].relations, 2 * n);
  for (const auto& f : fams) {
    EXPECT_EQ(f.triangles.rank, (n - 1) * (n - 2) / 2) << f.name;
    EXPECT_EQ(f.rank_over_triangles(), 2) << f.name << ", n = " << n;
    EXPECT_EQ(f.augmented_rank_over_triangles(), 2) << f.name << ", n = " << n;
  }
}

TEST(Counting, FixedSideFamiliesHaveRankTwoOnTheA8PentagonAndHexagon) {
  for (const auto& ex : {test::spec_pentagon(), test::spec_hexagon()})
    expect_rank_two_families(ex.polygon, side_velocities(ex.polygon, ex.rates));
}

TEST(Counting, FixedSideFamiliesHaveRankTwoOnRandomPolygons) {
  const std::uint64_t seed = 11;
  for (int n = 4; n <= 16; ++n)
    for (int index = 0; index < 3; ++index) {
      const RandomPolygonCase c = generate_random_polygon(seed, n, index);
      bool dead = false;
      for (int j = 1; j <= n; ++j) dead = dead || cln::zerop(cross(c.polygon.side(j), c.polygon.side(j % n + 1)));
      if (dead) continue;  // some fixed side would be a dead centre
      SCOPED_TRACE("seed 11, n " + std::to_string(n) + ", index " + std::to_string(index));
      expect_rank_two_families(c.polygon, side_velocities(c.polygon, c.rates));
    }
}

TEST(Counting, SideVelocitiesAreTheA8PentagonAnswers) {
  const auto ex = test::spec_pentagon();
  const auto w = side_velocities(ex.polygon, ex.rates);
  EXPECT_EQ(w, (std::vector<Rational>{2, -1, test::q(17, 11), test::q(3, 11), 0}));
}

// Must fail: velocities that violate (5)/(6) make the constants of (22) contradict each other
// across the choices of the fixed side: the acceleration families become inconsistent.
TEST(Counting, WrongVelocitiesMakeTheAccelerationFamiliesInconsistent) {
  const auto ex = test::spec_hexagon();
  std::vector<Rational> w = side_velocities(ex.polygon, ex.rates);
  w[3] = w[3] + 1;  // omega_{4,6} off by one
  const auto fams = count_fixed_side_relations(ex.polygon, w);
  EXPECT_EQ(fams[0].rank_over_triangles(), 2);  // the velocity relations do not see omega
  for (size_t k = 1; k < 3; ++k) {
    EXPECT_EQ(fams[k].rank_over_triangles(), 2) << fams[k].name;
    EXPECT_GT(fams[k].augmented_rank_over_triangles(), 2) << fams[k].name;
    const CountClaim c = judge_rank("must_fail", "", 2, fams[k].rank_over_triangles(),
                                    fams[k].augmented_rank_over_triangles(), fams[k].combined);
    EXPECT_EQ(c.verdict, CountVerdict::Disproved);
  }
}

// Must fail: one velocity relation with a wrong coefficient is a third independent constraint.
TEST(Counting, AWrongVelocityRelationRaisesTheRankToThree) {
  const auto ex = test::spec_pentagon();
  const int n = ex.polygon.n();
  const RelativeRates rates(n);
  BodyPolygon bp{{0, 1, 2, 3, 4}, ex.polygon};
  RowEchelon<Rational> e(rates.columns());
  add_and_rank(e, triangle_relations(rates));
  const int t = e.rank();
  for (int f = 1; f <= n; ++f) add_and_rank(e, velocity_relations(rates, with_fixed_side(bp, f)));
  EXPECT_EQ(e.rank() - t, 2);
  std::vector<RateRelation> wrong = velocity_relations(rates, bp);
  wrong[0].row.front().second = wrong[0].row.front().second * 2;  // a coefficient doubled
  add_and_rank(e, wrong);
  EXPECT_EQ(e.rank() - t, 3);
}

TEST(Counting, AWrongClaimedRankIsDisprovedWithTheObservedRank) {
  const RankResult r = count_triangle_relations(10);
  const CountClaim wrong = judge_rank("must_fail", "", 37, r.rank, r.augmented_rank, r);
  EXPECT_EQ(wrong.verdict, CountVerdict::Disproved);
  EXPECT_EQ(wrong.observed_value, "36");
  const CountClaim right = judge_rank("ok", "", 36, r.rank, r.augmented_rank, r);
  EXPECT_EQ(right.verdict, CountVerdict::Proved);
}

TEST(Counting, FixedSideOfARotatedPolygonIsTheRequestedSide) {
  const auto ex = test::spec_pentagon();
  const BodyPolygon bp{{10, 11, 12, 13, 14}, ex.polygon};
  const BodyPolygon q = with_fixed_side(bp, 2);
  EXPECT_EQ(q.bodies, (std::vector<int>{12, 13, 14, 10, 11}));
  for (int t = 1; t <= 5; ++t) {
    const int s = (2 + t - 1) % 5 + 1;
    EXPECT_EQ(q.polygon.side(t).x, ex.polygon.side(s).x);
    EXPECT_EQ(q.polygon.side(t).y, ex.polygon.side(s).y);
  }
}

}  // namespace
}  // namespace linkproof
