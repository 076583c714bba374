// The symbolic ground truth against the closed forms of conventions §A2: exactly on random polygons,
// and as a rational-function identity in generic symbols.
#include <gtest/gtest.h>

#include "check/random_polygon.h"
#include "geometry/closed_forms.h"
#include "symbolic/ground_truth.h"
#include "support/polygons.h"

namespace linkproof {
namespace {

using test::q;

TEST(GroundTruth, PentagonMatchesConventionsA8) {
  GroundTruthEngine engine;
  const auto ex = test::spec_pentagon();
  const auto m = engine.motion(ex.polygon, ex.rates);
  EXPECT_EQ(m.omega[2], q(17, 11));
  EXPECT_EQ(m.omega[3], q(3, 11));
  EXPECT_EQ(m.omega_dot[2], q(7331, 2662));
  EXPECT_EQ(m.omega_dot[3], q(3755, 1331));
  EXPECT_EQ(m.omega[4], 0);
}

TEST(GroundTruth, HexagonMatchesConventionsA8) {
  GroundTruthEngine engine;
  const auto ex = test::spec_hexagon();
  const auto m = engine.motion(ex.polygon, ex.rates);
  EXPECT_EQ(m.omega[3], q(-30, 19));
  EXPECT_EQ(m.omega[4], q(21, 19));
  EXPECT_EQ(m.omega_dot[3], q(46033, 6859));
  EXPECT_EQ(m.omega_dot[4], q(38322, 6859));
}

TEST(GroundTruth, EqualsClosedFormsOnRandomPolygonsN4To12) {
  const std::uint64_t seed = 20261121;
  GroundTruthEngine engine;
  for (int n = 4; n <= 12; ++n) {
    for (int i = 0; i < 30; ++i) {
      const auto rc = generate_random_polygon(seed, n, i);
      const auto m = engine.motion(rc.polygon, rc.rates);
      const auto c = compute_closed_form_motion(rc.polygon, rc.rates);
      for (int j = 0; j < n; ++j) {
        ASSERT_EQ(m.omega[j], c.omega[j]) << "seed " << seed << " n " << n << " index " << i << " side " << j + 1;
        ASSERT_EQ(m.omega_dot[j], c.omega_dot[j]) << "seed " << seed << " n " << n << " index " << i;
      }
    }
  }
}

TEST(GroundTruth, TermCoefficientsMatchConventionsA4Structure) {
  // Coefficient of omega-dot_j is i_{n-1,j}; of omega_j^2 is lambda_j; of omega_j omega_l is
  // -2[cot phi i_{n-1,j} i_{n-1,l} + (|r_{n-2}|^2/D) i_{n-2,j} i_{n-2,l}] (closed forms).
  GroundTruthEngine engine;
  for (int i = 0; i < 10; ++i) {
    const auto rc = generate_random_polygon(99, 7, i);
    const auto [c1, c2] = engine.coefficients(rc.polygon);
    const auto cf = compute_closed_forms(rc.polygon);
    const int m = 4;
    for (int j = 1; j <= m; ++j) {
      EXPECT_EQ(c1.omega_dot[j - 1], cf.i_out[j - 1]);
      EXPECT_EQ(c1.omega_sq[j - 1], cf.lambda[j - 1]);
      EXPECT_EQ(c2.omega_dot[j - 1], cf.i_cpl[j - 1]);
      EXPECT_EQ(c2.omega_sq[j - 1], cf.mu[j - 1]);
      for (int l = j + 1; l <= m; ++l)
        EXPECT_EQ(c1.omega_pair[pair_index(j, l, m)],
                  -2 * (cf.cot_phi * cf.i_out[j - 1] * cf.i_out[l - 1] + cf.rho * cf.i_cpl[j - 1] * cf.i_cpl[l - 1]));
    }
  }
}

TEST(GroundTruth, ForwardModeTermsEqualTheSymbolicDerivativesOnRandomPolygons) {
  // Two routes to the same coefficients: the motion tape evaluated over rate jets (what checks
  // use) and the solution differentiated symbolically in GiNaC and compiled (coefficient_tape).
  const std::uint64_t seed = 20261124;
  GroundTruthEngine engine;
  for (int n = 4; n <= 9; ++n) {
    for (int i = 0; i < 6; ++i) {
      const auto rc = generate_random_polygon(seed, n, i);
      const auto jets = engine.terms(rc.polygon);
      const auto [out, cpl] = engine.coefficients_by_symbolic_derivatives(rc.polygon);
      const std::string where = "seed " + std::to_string(seed) + " n " + std::to_string(n) + " index " + std::to_string(i);
      for (const auto& [a, b] : {std::pair(&jets.out, &out), std::pair(&jets.cpl, &cpl)}) {
        EXPECT_EQ(a->omega_dot, b->omega_dot) << where;
        EXPECT_EQ(a->omega_sq, b->omega_sq) << where;
        EXPECT_EQ(a->omega_pair, b->omega_pair) << where;
      }
      // Velocity: the motion for a unit input j.
      for (int j = 1; j <= n - 3; ++j) {
        InputRates<Rational> unit{std::vector<Rational>(static_cast<size_t>(n - 3), 0),
                                  std::vector<Rational>(static_cast<size_t>(n - 3), 0)};
        unit.omega[static_cast<size_t>(j - 1)] = 1;
        const auto m = engine.motion(rc.polygon, unit);
        EXPECT_EQ(jets.velocity_out[static_cast<size_t>(j - 1)], m.omega[static_cast<size_t>(n - 2)]) << where;
        EXPECT_EQ(jets.velocity_cpl[static_cast<size_t>(j - 1)], m.omega[static_cast<size_t>(n - 3)]) << where;
      }
    }
  }
}

// The jet evaluator frees each register after its last read (rate_jet.h); reused, it remakes
// them: every output of a reused evaluator is that of a fresh one, on one polygon after another.
TEST(GroundTruth, AReusedJetEvaluatorGivesWhatAFreshOneGives) {
  const std::uint64_t seed = 20261128;
  GroundTruthEngine engine;
  for (int n : {4, 7, 12}) {
    const Tape& tape = engine.derivation(n).motion;
    const size_t numbers = 2 * static_cast<size_t>(n - 1);
    TapeJetEvaluator<Rational> reused(tape, numbers);
    for (int i = 0; i < 3; ++i) {
      const auto rc = generate_random_polygon(seed, n, i);
      std::vector<Rational> in;
      for (int j = 1; j <= n - 1; ++j) in.push_back(rc.polygon.side(j).x);
      for (int j = 1; j <= n - 1; ++j) in.push_back(rc.polygon.side(j).y);
      const auto a = reused(in);
      const auto b = TapeJetEvaluator<Rational>(tape, numbers)(in);
      ASSERT_EQ(a.size(), b.size());
      for (size_t k = 0; k < a.size(); ++k) {
        const std::string where = "seed 20261128 n " + std::to_string(n) + " index " + std::to_string(i);
        EXPECT_EQ(a[k].constant, b[k].constant) << where;
        EXPECT_EQ(a[k].linear, b[k].linear) << where;
        EXPECT_EQ(a[k].quadratic, b[k].quadratic) << where;
        EXPECT_FALSE(a[k].quadratic.empty() && a[k].linear.empty()) << where;
      }
    }
  }
}

TEST(GroundTruth, ForwardModeTermsAreUndefinedAtTheDeadCentre) {
  // r_{n-2} parallel to r_{n-1}: D = 0.
  const Polygon<Rational> p({{0, 0}, {0, 3}, {1, 5}, {2, 4}, {4, 4}, {6, 4}});
  ASSERT_TRUE(cln::zerop(p.dead_centre_determinant()));
  GroundTruthEngine engine;
  EXPECT_THROW(engine.terms(p), UndefinedQuantity);
}

TEST(GroundTruth, SymbolicSolutionEqualsClosedFormIdenticallyForN4To6) {
  // Zero test of (engine - closed form) as a rational function in generic x_j, y_j, omega_j,
  // omega_dot_j: numerator of the normal form is 0.
  using namespace GiNaC;
  for (int n = 4; n <= 6; ++n) {
    GroundTruthEngine engine;
    const auto& d = engine.symbolic_derivation(n);
    const auto& s = d.symbols;
    const ex ax = s.x(n - 2), ay = s.y(n - 2), bx = s.x(n - 1), by = s.y(n - 1);
    const ex D = ax * by - ay * bx;
    ex w1 = 0, w2 = 0, acc1 = 0;
    for (int j = 1; j <= n - 3; ++j) {
      w1 += s.omega(j) * (s.x(j) * ay - s.y(j) * ax);
      w2 += s.omega(j) * (bx * s.y(j) - by * s.x(j));
    }
    w1 /= D;
    w2 /= D;
    for (int j = 1; j <= n - 3; ++j)
      acc1 += s.omega_dot(j) * (s.x(j) * ay - s.y(j) * ax) - pow(s.omega(j), 2) * (ax * s.x(j) + ay * s.y(j));
    acc1 = (acc1 - pow(w2, 2) * (ax * ax + ay * ay) - pow(w1, 2) * (ax * bx + ay * by)) / D;
    EXPECT_TRUE((d.solution.omega_n1 - w1).normal().is_zero()) << "n=" << n;
    EXPECT_TRUE((d.solution.omega_n2 - w2).normal().is_zero()) << "n=" << n;
    EXPECT_TRUE((d.solution.omega_dot_n1 - acc1).normal().is_zero()) << "n=" << n;
    EXPECT_TRUE((d.solution.determinant - D).expand().is_zero()) << "n=" << n;
  }
}

TEST(GroundTruth, DeadCentreIsReportedAsUndefinedDeterminant) {
  GroundTruthEngine engine;
  const Polygon<Rational> p({{0, 0}, {1, 4}, {5, 5}, {7, 3}, {9, 1}});
  ASSERT_TRUE(cln::zerop(p.dead_centre_determinant()));
  try {
    engine.motion(p, InputRates<Rational>{{1, 1}, {0, 0}});
    FAIL() << "expected UndefinedQuantity";
  } catch (const UndefinedQuantity& u) {
    EXPECT_NE(u.quantity().find("D"), std::string::npos);
  }
}

TEST(GroundTruth, DerivationSizeGrowsLinearlyInN) {
  GroundTruthEngine engine;
  const size_t s24 = engine.derivation(24).motion.size();
  const size_t s48 = engine.derivation(48).motion.size();
  EXPECT_LT(s48, 2 * s24 + 64) << "tape sizes " << s24 << " and " << s48;
}

}  // namespace
}  // namespace linkproof
