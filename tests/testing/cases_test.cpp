// linkproof::testing case builders: exact Grashof classes, polygons as closed chains, the named
// families assemble and solve exactly (conventions §A8 known answers).
#include <gtest/gtest.h>

#include "symbolic/ground_truth.h"
#include "linkproof/testing/cases.h"
#include "linkproof/testing/truth.h"

namespace linkproof::testing {
namespace {

Rational q(long p, long d = 1) { return Rational(p) / Rational(d); }
Point pt(long x, long y) { return {Rational(x), Rational(y)}; }

TEST(TestingCases, RootSumSignIsExactIncludingEquality) {
  EXPECT_EQ(sign_of_root_sum_difference(2, 8, 18, 0), 0);   // sqrt2 + 2 sqrt2 = 3 sqrt2
  EXPECT_EQ(sign_of_root_sum_difference(1, 16, 4, 9), 0);   // 1 + 4 = 2 + 3
  EXPECT_EQ(sign_of_root_sum_difference(1, 17, 4, 9), 1);
  EXPECT_EQ(sign_of_root_sum_difference(1, 15, 4, 9), -1);
  // sqrt(2) + sqrt(3) = 3.1462... vs sqrt(1) + sqrt(5) = 3.2360...: opposite signs of u and t.
  EXPECT_EQ(sign_of_root_sum_difference(2, 3, 1, 5), -1);
  EXPECT_EQ(sign_of_root_sum_difference(1, 5, 2, 3), 1);
}

TEST(TestingCases, GrashofClassFollowsTheShortestLink) {
  // ground 10, crank 2 (A = (0,2)), coupler and rocker long: 2 + l < p + q.
  EXPECT_EQ(classify_grashof(pt(0, 0), pt(0, 2), pt(6, 8), pt(10, 0)), GrashofClass::CrankRocker);
  // ground shortest: O4 = (1, 0).
  EXPECT_EQ(classify_grashof(pt(0, 0), pt(0, 6), pt(5, 8), pt(1, 0)), GrashofClass::DoubleCrank);
  // parallelogram: s + l = p + q exactly.
  EXPECT_EQ(classify_grashof(pt(0, 0), pt(1, 3), pt(8, 3), pt(7, 0)), GrashofClass::ChangePoint);
  // lengths ground 10, crank 8, coupler 1, rocker ~8.06: coupler shortest, Grashof.
  EXPECT_EQ(classify_grashof(pt(0, 0), pt(0, 8), pt(1, 8), pt(10, 0)), GrashofClass::DoubleRocker);
  // lengths 10, 5, 5, 7.07: s + l = 15 > p + q = 12.07, non-Grashof.
  EXPECT_EQ(classify_grashof(pt(0, 0), pt(0, 5), pt(5, 5), pt(10, 0)), GrashofClass::TripleRocker);
}

TEST(TestingCases, PolygonAsClosedChainHasThePolygonsGroundTruth) {
  PolygonCase p{"polygon/scattered/n=5", Polygon<Rational>({pt(0, 0), pt(1, 4), pt(5, 5), pt(7, 1), pt(3, -2)}),
                {{2, -1}, {1, 3}}};
  const MechanismTruth t = compute_truth(polygon_mechanism(p).scene);
  ASSERT_EQ(t.links.size(), 5u);
  EXPECT_EQ(t.links[3].alpha, q(3755, 1331));  // omega-dot_{4,5} of conventions §A8
  EXPECT_EQ(t.links[2].alpha, q(7331, 2662));
  EXPECT_EQ(t.links[2].omega, q(17, 11));
  GroundTruthEngine engine;
  const auto m = engine.motion(p.polygon, p.rates);
  for (size_t j = 0; j < 5; ++j) EXPECT_EQ(t.links[j].alpha, m.omega_dot[j]) << j;
}

TEST(TestingCases, Fig5EightBarBuilderReproducesConventionsA8) {
  const MechanismCase c = make_fig5_eightbar({pt(0, 4), pt(6, 9), pt(12, 7), pt(10, 0), pt(0, 0), pt(1, 2), pt(10, 3),
                                              pt(11, 4), pt(5, 4), pt(6, 3)},
                                             1, q(1, 2));
  ASSERT_TRUE(is_well_posed(c.scene));
  const MechanismTruth t = compute_truth(c.scene);
  EXPECT_EQ(t.links[4].omega, q(159, 317));
  EXPECT_EQ(t.links[4].alpha, q(171151479, 318550130));
}

TEST(TestingCases, SliderFamiliesAreWellPosedAndLockedOnesAreNot) {
  EXPECT_TRUE(is_well_posed(make_slider_crank(pt(0, 0), pt(1, 2), pt(6, 0), pt(1, 0), 2, 1).scene));
  EXPECT_TRUE(is_well_posed(make_inverted_slider_crank(pt(0, 0), pt(1, 2), pt(5, 0), 2, 1).scene));
  // Rod perpendicular to the guide: the crank cannot drive the slider (toggle).
  EXPECT_FALSE(is_well_posed(make_slider_crank(pt(0, 0), pt(1, 2), pt(1, 0), pt(1, 0), 2, 1).scene));
  // Two joints of one link at one point.
  EXPECT_FALSE(is_well_posed(make_fourbar(pt(0, 0), pt(0, 0), pt(3, 4), pt(5, 0), 1, 0).scene));
}

}  // namespace
}  // namespace linkproof::testing
