// Known answers of conventions §A8: every intermediate quantity of the construction.
#include <gtest/gtest.h>

#include <cstdio>

#include "check/random_polygon.h"
#include "geometry/closed_forms.h"
#include "geometry/construction.h"
#include "support/polygons.h"

namespace linkproof {
namespace {

using test::q;

void expect_point(const Vec2<Rational>& p, const Rational& x, const Rational& y) {
  EXPECT_EQ(p.x, x) << format_rational(p.x);
  EXPECT_EQ(p.y, y) << format_rational(p.y);
}

TEST(Construction, PentagonReproducesConventionsA8Quantities) {
  const auto ex = test::spec_pentagon();
  const auto c1 = construct_four_bar(ex.polygon, 1);
  expect_point(c1.k_prime, 4, 1);
  expect_point(c1.q.get(), q(26, 5), q(23, 5));
  expect_point(c1.p_prime.get(), q(43, 13), q(-23, 13));
  EXPECT_EQ(c1.i_out.get(), q(6, 11));
  EXPECT_EQ(c1.i_cpl.get(), q(13, 22));
  EXPECT_EQ(c1.cot_beta.get(), q(-47, 44));
  EXPECT_EQ(c1.lambda.get(), q(-705, 2662));

  const auto c2 = construct_four_bar(ex.polygon, 2);
  expect_point(c2.k_prime, ex.polygon.joint(2).x, ex.polygon.joint(2).y);  // K'_{n-3} = K_{n-3}
  expect_point(c2.q.get(), -8, 31);
  expect_point(c2.p_prime.get(), 16, q(31, 4));
  EXPECT_EQ(c2.i_out.get(), q(9, 11));
  EXPECT_EQ(c2.i_cpl.get(), q(-4, 11));
  EXPECT_EQ(c2.cot_beta.get(), q(94, 33));
  EXPECT_EQ(c2.lambda.get(), q(564, 1331));

  const auto cf = compute_closed_forms(ex.polygon);
  EXPECT_EQ(cf.D, -22);
  EXPECT_EQ(cf.cot_phi, q(-2, 11));
  EXPECT_EQ(cf.rho, q(-10, 11));
}

TEST(Construction, HexagonReproducesConventionsA8Ratios) {
  const auto ex = test::spec_hexagon();
  const Rational i_out[] = {q(4, 19), q(14, 19), q(15, 19)};
  const Rational i_cpl[] = {q(16, 19), q(-1, 19), q(-16, 19)};
  const Rational cot_beta[] = {q(-108, 95), q(-22, 133), q(452, 57)};
  const Rational lambda[] = {q(-1296, 6859), q(-220, 6859), q(9040, 6859)};
  for (int j = 1; j <= 3; ++j) {
    const auto c = construct_four_bar(ex.polygon, j);
    EXPECT_EQ(c.i_out.get(), i_out[j - 1]) << "j=" << j;
    EXPECT_EQ(c.i_cpl.get(), i_cpl[j - 1]) << "j=" << j;
    EXPECT_EQ(c.cot_beta.get(), cot_beta[j - 1]) << "j=" << j;
    EXPECT_EQ(c.lambda.get(), lambda[j - 1]) << "j=" << j;
  }
}

TEST(Construction, ClosedFormsEqualConstructionOnWorkedExamples) {
  for (const auto& ex : {test::spec_pentagon(), test::spec_hexagon()}) {
    const auto cf = compute_closed_forms(ex.polygon);
    for (int j = 1; j <= ex.polygon.n() - 3; ++j) {
      const auto c = construct_four_bar(ex.polygon, j);
      EXPECT_EQ(c.i_out.get(), cf.i_out[j - 1]);
      EXPECT_EQ(c.i_cpl.get(), cf.i_cpl[j - 1]);
      EXPECT_EQ(c.lambda.get(), cf.lambda[j - 1]);
      EXPECT_EQ(c.mu.get(), cf.mu[j - 1]);  // gamma's sign rule (conventions §A4 companion)
    }
  }
}

TEST(Construction, ParallelLinesReportQAtInfinityByName) {
  // r_{n-2} x (r_j + r_{n-1}) = 0 for j = 1: line K_nK'_1 is parallel to K_{n-2}K_{n-1}.
  // r_1 = (1,2), r_3 = (2,0), r_4 = (-2,-2): r_1 + r_4 = (-1,0) is parallel to r_3; D = -4.
  const Polygon<Rational> p({{0, 0}, {1, 2}, {3, 3}, {5, 3}, {3, 1}});
  const Vec2<Rational> r3 = p.side(3), s = p.side(1) + p.side(4);
  ASSERT_TRUE(cln::zerop(cross(r3, s)));
  const auto c = construct_four_bar(p, 1);
  EXPECT_FALSE(c.q.has_value());
  EXPECT_EQ(c.q.quantity(), "Q_1");
  EXPECT_FALSE(c.i_out.has_value());
  EXPECT_EQ(compute_closed_forms(p).i_out[0], 1);  // the continuous extension (conventions §A6)
}

bool same_value(const Rational& a, const Rational& b) { return a == b; }
bool same_value(const Vec2<Rational>& a, const Vec2<Rational>& b) { return a.x == b.x && a.y == b.y; }

template <class V>
void expect_same_defined(const Defined<V>& a, const Defined<V>& b, const std::string& what) {
  ASSERT_EQ(a.has_value(), b.has_value()) << what;
  if (a.has_value()) {
    EXPECT_TRUE(same_value(a.get(), b.get())) << what;
  } else {
    EXPECT_EQ(a.quantity(), b.quantity()) << what;
    EXPECT_EQ(a.reason(), b.reason()) << what;
  }
}

void expect_same_construction(const FourBarConstruction<Rational>& a, const FourBarConstruction<Rational>& b,
                              const std::string& what) {
  EXPECT_EQ(a.j, b.j) << what;
  EXPECT_TRUE(same_value(a.k_prime, b.k_prime)) << what;
  expect_same_defined(a.q, b.q, what + " Q");
  expect_same_defined(a.p_prime, b.p_prime, what + " P'");
  expect_same_defined(a.i_out, b.i_out, what + " i_out");
  expect_same_defined(a.i_cpl, b.i_cpl, what + " i_cpl");
  expect_same_defined(a.cot_beta, b.cot_beta, what + " cot beta");
  expect_same_defined(a.cot_gamma, b.cot_gamma, what + " cot gamma");
  expect_same_defined(a.lambda, b.lambda, what + " lambda");
  expect_same_defined(a.mu, b.mu, what + " mu");
}

ConstructionReading reading_of_bits(int bits) {
  return {(bits & 1) != 0, (bits & 2) != 0, (bits & 4) != 0, (bits & 8) != 0};
}

// PolygonContext::construction_for computes the steps once per construction_steps_key and
// reads them under each reading: steps made under any reading of the key must give every
// reading of it the construction construct_four_bar makes, defined or named.
TEST(Construction, ReadingsOfOneStepsKeyGiveTheirConstructionsFromSharedSteps) {
  constexpr std::uint64_t kSeed = 2812;
  std::printf("construction steps seed %llu (generate_random_polygon(seed, n, index))\n",
              static_cast<unsigned long long>(kSeed));
  std::vector<Polygon<Rational>> polygons = {test::spec_pentagon().polygon, test::spec_hexagon().polygon,
                                             Polygon<Rational>({{0, 0}, {1, 2}, {3, 3}, {5, 3}, {3, 1}})};
  for (int n = 5; n <= 8; ++n)
    for (int index = 0; index < 3; ++index) polygons.push_back(generate_random_polygon(kSeed, n, index).polygon);
  int shared = 0;
  for (const Polygon<Rational>& p : polygons) {
    const FourBarFrame<Rational> frame = make_four_bar_frame(p);
    for (int j = 1; j <= p.n() - 3; ++j)
      for (int read = 0; read < 16; ++read)
        for (int made = 0; made < 16; ++made) {
          const ConstructionReading r = reading_of_bits(read), m = reading_of_bits(made);
          if (construction_steps_key(r) != construction_steps_key(m)) continue;
          const FourBarSteps<Rational> steps = construct_four_bar_steps(frame, p.joint(j), p.side(j), m);
          expect_same_construction(construction_from_steps(steps, j, r), construct_four_bar(p, j, r),
                                   "n=" + std::to_string(p.n()) + " j=" + std::to_string(j) + " read " +
                                       std::to_string(read) + " made " + std::to_string(made));
          ++shared;
        }
  }
  EXPECT_GT(shared, 1000);
}

TEST(Construction, DirectedRatioIsNegativeWhenPointsStraddleTheOrigin) {
  const Vec2<Rational> x{0, 0}, a{-1, -2}, b{2, 4};
  EXPECT_EQ(compute_directed_ratio(x, a, b, "r"), q(-1, 2));
}

}  // namespace
}  // namespace linkproof
