// Bobillier's construction (a)-(e) against the analytic curvature centre (conventions §D).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <random>

#include "mechanism/curvature_analysis.h"
#include "mechanism/curvature_support.h"

namespace linkproof {
namespace {

using PP = PlanePoint<Rational>;

struct FourBarCase {
  MechanismScene scene;
  std::vector<LinkField<Rational>> fields;
  Vec2<Rational> O2, A, B, O4;
};

FourBarCase random_fourbar() {
  FourBarCase c{random_scene(testing::fourbar_topology()), {}, {}, {}, {}, {}};
  const MechanismSolution<Rational> truth = testing::solve_or_discard(c.scene);
  c.fields = truth.motion.fields;
  c.O2 = c.scene.linkage.joint(0).at, c.A = c.scene.linkage.joint(1).at;
  c.B = c.scene.linkage.joint(2).at, c.O4 = c.scene.linkage.joint(3).at;
  return c;
}

RC_GTEST_PROP(Bobillier, GivesTheAnalyticCentreOfARandomCouplerPoint, ()) {
  const FourBarCase c = random_fourbar();
  const Vec2<Rational> C = *testing::small_point(10);
  const PP analytic = construct_curvature_centre(C, relative_point_motion(c.fields[2], c.fields[0], C), "centre");
  const auto b = construct_bobillier(c.A, c.O2, c.B, c.O4, C);
  RC_PRE(analytic.is_finite() && b.gamma.is_finite());
  RC_ASSERT(b.gamma.at.x == analytic.at.x);
  RC_ASSERT(b.gamma.at.y == analytic.at.y);
}

// The mirrored reading of step (c) is wrong generically, not everywhere: it coincides with the
// centre on special positions (found by RapidCheck, e.g. O2 (-6,-6), A (-7,-4), B (-6,-4),
// O4 (-2,-8), C (-10,-10); not characterised). So this counts, over a fixed printed seed, how
// often it misses: in all but a small fraction of random four-bars.
TEST(Bobillier, MirroredStepCMissesTheCentreInAlmostEveryRandomFourBar) {
  const unsigned seed = 20261124;
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> coord(-40, 40);
  const auto point = [&] { return Vec2<Rational>{Rational(coord(rng)) / 4, Rational(coord(rng)) / 4}; };
  int compared = 0, missed = 0;
  while (compared < 200) {
    MechanismScene s = testing::make_scene(testing::fourbar_topology(), {point(), point(), point(), point()}, 2, 1);
    MechanismSolution<Rational> truth;
    try {
      truth = solve_rigid_body(s.linkage, s.inputs, s.source);
    } catch (const InputError&) {
      continue;
    }
    const auto& fields = truth.motion.fields;
    const auto& g = s.linkage;
    const Vec2<Rational> C = point();
    const PP analytic = construct_curvature_centre(C, relative_point_motion(fields[2], fields[0], C), "centre");
    const auto mirrored = construct_bobillier(g.joint(1).at, g.joint(0).at, g.joint(2).at, g.joint(3).at, C, true);
    if (!analytic.is_finite() || !mirrored.gamma.is_finite()) continue;
    ++compared;
    if (!(mirrored.gamma.at.x == analytic.at.x && mirrored.gamma.at.y == analytic.at.y)) ++missed;
  }
  EXPECT_GE(missed, 190) << "seed " << seed << ": the mirrored reading hit the centre in " << compared - missed
                         << " of " << compared << " random four-bars";
}

TEST(Bobillier, PointOnThePoleRayPAUsesTheBVersion) {
  // The four-bar of the course notes (conventions §B): C = A lies on the ray PA; the B/beta
  // version gives A's centre O2.
  const Vec2<Rational> O2{0, 0}, A{3, 4}, B{11, 10}, O4{11, 0};
  const auto b = construct_bobillier(A, O2, B, O4, A);
  EXPECT_EQ(b.version, 'B');
  ASSERT_TRUE(b.gamma.is_finite());
  EXPECT_EQ(b.gamma.at.x, Rational(0));
  EXPECT_EQ(b.gamma.at.y, Rational(0));
}

TEST(Bobillier, ParallelCranksPutThePoleAtInfinityAndReportIt) {
  const Vec2<Rational> O2{0, 0}, A{0, 4}, B{6, 5}, O4{6, 0};
  const auto b = construct_bobillier(A, O2, B, O4, Vec2<Rational>{3, 7});
  EXPECT_EQ(b.P.kind, PP::Kind::AtInfinity);
  EXPECT_EQ(b.gamma.kind, PP::Kind::Undefined);
  EXPECT_NE(b.gamma.reason.find("pole P"), std::string::npos);
}

}  // namespace
}  // namespace linkproof
