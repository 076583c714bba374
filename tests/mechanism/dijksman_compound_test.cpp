// Dijksman's multi-polygon method (conventions §A7) against the exact engine on random rational
// four-bars, Watt and Stephenson six-bars and Fig. 5-type eight-bars; a slider-crank against a
// hand-derived closed form; a must-fail variant.
#include <gtest/gtest.h>

#include <random>

#include "linkproof/io/mechanism_scene.h"
#include "mechanism/dijksman_compound.h"
#include "mechanism/mechanism_vector_route.h"
#include "mechanism/mechanism_test_support.h"
#include "mechanism/mechanism_catalogue.h"

namespace linkproof {
namespace {

using testing::Topology;

std::vector<Topology> topologies() {
  return {
      {"fourbar", {"0", "1", "2", "3"}, 0, {{0, 1}, {1, 2}, {2, 3}, {3, 0}}, 1},
      {"watt_i", {"g", "AB", "BCD", "DE", "EF", "CFG"}, 0, {{0, 1}, {1, 2}, {2, 5}, {2, 3}, {3, 4}, {4, 5}, {5, 0}}, 1},
      {"stephenson_iii", {"g", "AB", "BCE", "CD", "EF", "FG"}, 0,
       {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {2, 4}, {4, 5}, {5, 0}}, 1},
      {"eightbar_fig5", {"0", "1", "2", "3", "4", "5", "6", "7"}, 0,
       {{0, 1}, {4, 0}, {1, 2}, {1, 5}, {2, 3}, {3, 4}, {6, 3}, {7, 4}, {5, 6}, {5, 7}}, 1},
  };
}

TEST(DijksmanCompound, RandomMechanismsAgreeExactlyWithTheEngine) {
  const unsigned seed = 20261121;
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> coord(-40, 40), den(1, 4), rate(-9, 9);
  for (const Topology& t : topologies()) {
    int checked = 0;
    for (int trial = 0; trial < 40 && checked < 12; ++trial) {
      std::vector<Vec2<Rational>> at;
      for (size_t j = 0; j < t.joints.size(); ++j)
        at.push_back({Rational(coord(rng)) / den(rng), Rational(coord(rng)) / den(rng)});
      const Rational w = Rational(rate(rng)) / den(rng), wd = Rational(rate(rng)) / den(rng);
      const MechanismScene s = testing::make_scene(t, at, w, wd);
      MechanismSolution<Rational> truth;
      DijksmanCompoundSolution<Rational> d;
      try {
        truth = solve_mechanism_exact(s);
        d = solve_dijksman_compound<Rational>(s.linkage, s.inputs[0]);
      } catch (const Error&) {
        continue;  // a singular random configuration (dead centre everywhere, locked): rare, skipped
      }
      for (size_t p = 0; p < d.pairs.size(); ++p) {
        const auto [i, k] = d.pairs[p];
        const auto& m = truth.motion;
        ASSERT_EQ(d.omega_dot[p], m.omega_dot[static_cast<size_t>(i)] - m.omega_dot[static_cast<size_t>(k)])
            << t.name << " seed " << seed << " trial " << trial << " pair " << i << "," << k;
        ASSERT_EQ(d.omega[p], m.omega[static_cast<size_t>(i)] - m.omega[static_cast<size_t>(k)]);
      }
      const int L = s.linkage.link_count();
      EXPECT_EQ(d.acceleration_rank, L * (L - 1) / 2);
      ++checked;
    }
    EXPECT_GE(checked, 10) << t.name << ": too many singular random configurations (seed " << seed << ")";
  }
}

TEST(DijksmanCompound, MixedTermIsNonZeroOnTheEightBarHexagonSoDroppingItWouldFail) {
  // Must-fail: eq. (22) without the mixed term -cot phi S1 - rho S2 disagrees on the eight-bar.
  const MechanismScene s = load_mechanism_scene(testing::mechanism_scene_path("fig5_eightbar.yaml"));
  const auto d = solve_dijksman_compound<Rational>(s.linkage, s.inputs[0]);
  std::string problem;
  const auto polys = dijksman_polygons(s.linkage, problem);
  // The hexagon (n = 6) has 3 inputs, hence a non-zero mixed term somewhere.
  bool nonzero_mixed = false;
  for (const auto& p : polys) {
    if (p.vertices.size() < 6) continue;
    const auto f = compute_closed_forms(Polygon<Rational>(p.vertices));
    const int n = static_cast<int>(p.side_link.size());
    const auto w = [&](int j) {
      const size_t a = static_cast<size_t>(p.side_link[static_cast<size_t>(j - 1)]);
      const size_t b = static_cast<size_t>(p.side_link[static_cast<size_t>(n - 1)]);
      const auto& m = solve_mechanism_exact(s).motion;
      return m.omega[a] - m.omega[b];
    };
    Rational S1 = 0;
    for (int j = 1; j <= n - 3; ++j)
      for (int l = 1; l <= n - 3; ++l)
        if (j != l) S1 += f.i_out[static_cast<size_t>(j - 1)] * f.i_out[static_cast<size_t>(l - 1)] * w(j) * w(l);
    nonzero_mixed = nonzero_mixed || !cln::zerop(S1);
  }
  EXPECT_TRUE(nonzero_mixed);
}

TEST(SliderCrank, MatchesTheHandDerivedClosedForm) {
  // Crank O-A (link 1), rod A-B (link 2), slider B (link 3) on the x axis (guide: frame 0).
  // Rod constraint (x_B - x_A)^2 + y_A^2 = l^2, y_B = 0, differentiated by hand:
  //   xd_B = xd_A - y_A yd_A / (x_B - x_A)
  //   xdd_B = xdd_A - [(xd_B - xd_A)^2 + yd_A^2 + y_A ydd_A] / (x_B - x_A)
  // with xd_A = -w y_A, yd_A = w x_A, xdd_A = -wd y_A - w^2 x_A, ydd_A = wd x_A - w^2 y_A.
  const Vec2<Rational> A{3, 4}, B{11, 0};
  const Rational w = 2, wd = Rational(-1) / 3;
  std::vector<LinkageJoint> joints(4);
  joints[0] = {"O", JointType::Revolute, {0, 1}, {0, 0}, {}};
  joints[1] = {"A", JointType::Revolute, {1, 2}, A, {}};
  joints[2] = {"B", JointType::Revolute, {2, 3}, B, {}};
  joints[3] = {"S", JointType::Prismatic, {0, 3}, B, {2, 0}};  // axis length 2: sigma in units of u
  MechanismScene s;
  s.source = "slider-crank";
  s.linkage = Linkage({"0", "1", "2", "3"}, 0, joints);
  s.inputs = {MechanismInput{MechanismInput::Kind::Link, 1, w, wd}};
  const auto m = solve_mechanism_exact(s);
  const Rational xdA = -w * A.y, ydA = w * A.x, xddA = -wd * A.y - w * w * A.x, yddA = wd * A.x - w * w * A.y;
  const Rational xdB = xdA - A.y * ydA / (B.x - A.x);
  const Rational xddB = xddA - ((xdB - xdA) * (xdB - xdA) + ydA * ydA + A.y * yddA) / (B.x - A.x);
  EXPECT_EQ(m.motion.joint_v[2].x, xdB);
  EXPECT_EQ(m.motion.joint_a[2].x, xddB);
  EXPECT_EQ(m.motion.slide[3] * 2, xdB);  // sigma-dot along u = (2, 0)
  EXPECT_EQ(m.motion.slide_dot[3] * 2, xddB);
  EXPECT_TRUE(cln::zerop(m.motion.joint_a[2].y));
  // Driven by the slider instead, with the sliding rates just found: the same crank rates.
  s.inputs = {MechanismInput{MechanismInput::Kind::Slider, 3, m.motion.slide[3], m.motion.slide_dot[3]}};
  const auto inv = solve_mechanism_exact(s);
  EXPECT_EQ(inv.motion.omega[1], w);
  EXPECT_EQ(inv.motion.omega_dot[1], wd);
}

TEST(SliderCrank, CoriolisTermIsNeededOnAMovingGuide) {
  // Inverted slider-crank: the guide is fixed in the rotating crank (link 1), the slider is
  // pinned to the rod; dropping the Coriolis term changes the answer.
  std::vector<LinkageJoint> joints(4);
  joints[0] = {"O", JointType::Revolute, {0, 1}, {0, 0}, {}};
  joints[1] = {"S", JointType::Prismatic, {1, 3}, {4, 2}, {2, 1}};  // slider 3 on guide in link 1
  joints[2] = {"P", JointType::Revolute, {3, 2}, {4, 2}, {}};
  joints[3] = {"Q", JointType::Revolute, {2, 0}, {7, -3}, {}};
  const Linkage g({"0", "1", "2", "3"}, 0, joints);
  const std::vector<MechanismInput> in{{MechanismInput::Kind::Link, 1, Rational(3), Rational(0)}};
  const auto solve = [&](bool coriolis) {
    return solve_mechanism<Rational>(
        g, in, rigid_body_constraint_matrix<Rational>(g),
        [&](const std::vector<Rational>& qd) { return rigid_body_acceleration_rhs<Rational>(g, qd, coriolis); }, "test");
  };
  const auto with = solve(true), without = solve(false);
  MechanismScene s;
  s.source = "inverted slider-crank";
  s.linkage = g;
  s.inputs = in;
  EXPECT_EQ(with.qddot, solve_mechanism_exact(s).qddot);  // the GiNaC closure carries the term
  EXPECT_NE(with.qddot, without.qddot);
}

}  // namespace
}  // namespace linkproof
