// Random polygons: deterministic in (seed, n, index), valid, and available up to the sweep's n.
#include <gtest/gtest.h>

#include "check/random_polygon.h"

namespace linkproof {
namespace {

TEST(RandomPolygon, SameSeedNAndIndexGiveTheSameCase) {
  const auto a = generate_random_polygon(5, 7, 3), b = generate_random_polygon(5, 7, 3);
  ASSERT_EQ(a.polygon.n(), b.polygon.n());
  for (int j = 1; j <= 7; ++j) {
    EXPECT_EQ(a.polygon.joint(j).x, b.polygon.joint(j).x);
    EXPECT_EQ(a.polygon.joint(j).y, b.polygon.joint(j).y);
  }
  EXPECT_EQ(a.rates.omega, b.rates.omega);
}

TEST(RandomPolygon, EveryFamilyDrawsValidPolygonsUpToTheSweepLimit) {
  for (int n : {4, 12, 60, 200}) {
    for (int index = 0; index < 3; ++index) {
      const auto c = generate_random_polygon(1, n, index);
      EXPECT_EQ(c.polygon.n(), n);
      EXPECT_TRUE(polygon_input_problem(c.polygon).empty()) << c.family << " n " << n;
      EXPECT_FALSE(cln::zerop(c.polygon.dead_centre_determinant()));
      EXPECT_EQ(static_cast<int>(c.rates.omega.size()), n - 3);
    }
  }
}

}  // namespace
}  // namespace linkproof
