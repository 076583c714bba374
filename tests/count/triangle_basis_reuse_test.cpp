// The triangle basis of `count` is grown one body at a time and kept between calls, and the
// (22)+companion family continues from the (22) one: the ranks must be those of ranking every
// relation afresh, whatever order the n come in.
#include <gtest/gtest.h>

#include "check/random_polygon.h"
#include "count/counting.h"
#include "support/rational_families.h"

namespace linkproof {
namespace {

RankResult fresh_triangle_rank(int n) {
  const RelativeRates rates(n);
  RowEchelon<Rational> e(rates.columns());
  return add_and_rank(e, triangle_relations(rates));
}

TEST(TriangleBasisReuse, RanksAreThoseOfAFreshRankingWhenNGoesUpDownAndRepeats) {
  for (int n : {5, 9, 9, 4, 12, 3, 7, 20, 6}) {
    const RankResult cached = count_triangle_relations(n), fresh = fresh_triangle_rank(n);
    EXPECT_EQ(cached.relations, fresh.relations) << "n = " << n;
    EXPECT_EQ(cached.unknowns, fresh.unknowns) << "n = " << n;
    EXPECT_EQ(cached.rank, fresh.rank) << "n = " << n;
    EXPECT_EQ(cached.augmented_rank, fresh.augmented_rank) << "n = " << n;
  }
}

TEST(TriangleBasisReuse, FamilyRanksAreThoseOfRankingEachFamilyFromTheTriangles) {
  const std::uint64_t seed = 5;
  for (int n : {5, 8, 6, 4, 11}) {
    // A polygon without two consecutive parallel sides: no choice of the fixed side is a dead centre.
    RandomPolygonCase c;
    for (int index = 0;; index += 3) {
      c = generate_random_polygon(seed, n, index);
      bool parallel = false;
      for (int j = 1; j <= n; ++j) parallel = parallel || cln::zerop(cross(c.polygon.side(j), c.polygon.side(j % n + 1)));
      if (!parallel) break;
    }
    const std::vector<Rational> omega = side_velocities(c.polygon, c.rates);
    const auto fams = count_fixed_side_relations(c.polygon, omega);
    // Reference: every family ranked on a fresh triangle basis, rows in the original order.
    const RelativeRates rates(n);
    const test::RationalFamilies ref = test::rational_families(c.polygon, omega);
    const std::vector<const std::vector<RateRelation>*> families{&ref.velocity, &ref.eq22, &ref.acceleration};
    ASSERT_EQ(fams.size(), families.size());
    for (size_t k = 0; k < families.size(); ++k) {
      RowEchelon<Rational> e(rates.columns());
      const RankResult tri = add_and_rank(e, triangle_relations(rates));
      const RankResult all = add_and_rank(e, *families[k]);
      SCOPED_TRACE("seed " + std::to_string(seed) + ", n " + std::to_string(n) + ", " + fams[k].name);
      EXPECT_EQ(fams[k].relations, static_cast<long>(families[k]->size()));
      EXPECT_EQ(fams[k].triangles.rank, tri.rank);
      EXPECT_EQ(fams[k].combined.relations, all.relations);
      EXPECT_EQ(fams[k].combined.rank, all.rank);
      EXPECT_EQ(fams[k].combined.augmented_rank, all.augmented_rank);
    }
  }
}

}  // namespace
}  // namespace linkproof
