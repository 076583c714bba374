// Joint-joining of Dijksman (1984): first order keeps velocities, second order also
// accelerations (conventions §D), on random rational eight-bars.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "mechanism/curvature_analysis.h"
#include "mechanism/curvature_support.h"

namespace linkproof {
namespace {

using PP = PlanePoint<Rational>;

// The reductions of a random eight-bar asked for by `requests`; discards singular draws.
CurvatureAnalysis reduce_random_eightbar(const std::vector<JointJoiningRequest>& requests) {
  MechanismScene s = random_scene(testing::eightbar_topology());
  s.joint_joining = requests;
  const MechanismSolution<Rational> truth = testing::solve_or_discard(s);
  CurvatureAnalysis a = analyse_curvature(s, truth);
  for (const auto& r : a.reductions) RC_PRE(r.solved);
  return a;
}

RC_GTEST_PROP(JointJoining, SecondOrderPreservesVelocitiesAndAccelerations, ()) {
  const auto a = reduce_random_eightbar({{2, {1, 3}, 2}, {6, {5, 7}, 2}});
  for (const auto& r : a.reductions) {
    RC_ASSERT(r.velocities_preserved);
    RC_ASSERT(r.accelerations_preserved);
    for (int b = 0; b < 2; ++b) {  // the relocated far joint is the centre of I
      RC_ASSERT(r.step.centre_of_I[b].is_finite());
      RC_ASSERT(r.step.new_far[b].at.x == r.step.centre_of_I[b].at.x);
      RC_ASSERT(r.step.new_far[b].at.y == r.step.centre_of_I[b].at.y);
    }
  }
}

RC_GTEST_PROP(JointJoining, FirstOrderPreservesVelocitiesButNotAccelerations, ()) {
  const auto a = reduce_random_eightbar({{2, {1, 3}, 1}});
  const auto& r = a.reductions[0];
  RC_ASSERT(r.velocities_preserved);
  // Accelerations agree only if the far joints already were the centres of I (never generic).
  for (int b = 0; b < 2; ++b) RC_PRE(r.step.centre_of_I[b].is_finite());
  RC_PRE(!(r.step.centre_of_I[0].at.x == r.step.new_far[0].at.x && r.step.centre_of_I[0].at.y == r.step.new_far[0].at.y));
  RC_ASSERT(!r.accelerations_preserved);
}

TEST(JointJoining, RelocationFormulaMovesTheFarJointAlongTheBarLine) {
  // Pole at the origin, bar from N = (2, 0) to F = (6, 0), new near joint K = (3, 0):
  // 1/F' = 1/6 + 1/3 - 1/2 = 0 -> at infinity; K = (4, 0): 1/F' = 1/6 + 1/4 - 1/2 = -1/12.
  const Vec2<Rational> P{0, 0}, N{2, 0}, F{6, 0};
  EXPECT_EQ(relocate_far_joint(P, N, F, Vec2<Rational>{3, 0}, "F'").kind, PP::Kind::AtInfinity);
  const PP f = relocate_far_joint(P, N, F, Vec2<Rational>{4, 0}, "F'");
  ASSERT_TRUE(f.is_finite());
  EXPECT_EQ(f.at.x, Rational(-12));
  EXPECT_EQ(f.at.y, Rational(0));
  EXPECT_EQ(relocate_far_joint(P, P, F, Vec2<Rational>{4, 0}, "F'").kind, PP::Kind::Undefined);
}

}  // namespace
}  // namespace linkproof
