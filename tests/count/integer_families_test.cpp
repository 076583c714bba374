// integer_fixed_side_families: each integer relation is the rational relation of
// relative_rates.h restricted to the free rates, times a nonzero constant of its own (D or D^3),
// with every right-hand side times one common constant (L^2): the scaling under which no rank
// changes (count/integer_families.h). And the ranks `count` takes from them are those of the
// rational relations ranked on the triangle relations, also when the velocities are wrong.
#include "count/integer_families.h"

#include <gtest/gtest.h>

#include <optional>

#include "check/random_polygon.h"
#include "count/counting.h"
#include "support/polygons.h"
#include "support/rational_families.h"

namespace linkproof {
namespace {

/// A rational relation restricted to y_1 .. y_{n-1} (x_ik = y_k - y_i, y_0 = 0).
std::vector<Rational> restricted(const RelativeRates& rates, const RateRelation& r) {
  std::vector<Rational> y(static_cast<size_t>(rates.bodies() - 1), 0);
  for (const auto& [col, a] : r.row) {
    const auto [i, k] = rates.bodies_of(col);
    y[static_cast<size_t>(k - 1)] = y[static_cast<size_t>(k - 1)] + a;
    if (i > 0) y[static_cast<size_t>(i - 1)] = y[static_cast<size_t>(i - 1)] - a;
  }
  return y;
}

/// Checks integer = c * rational (row), integer rhs = c * rhs_scale * rational rhs, for one
/// nonzero c; `rhs_scale` is fixed by the first relation with a nonzero right-hand side.
void expect_scaled(const RelativeRates& rates, const RateRelation& rational, const IntegerRelation& integer,
                   std::optional<Rational>& rhs_scale) {
  const std::vector<Rational> y = restricted(rates, rational);
  ASSERT_EQ(y.size(), integer.row.size());
  std::optional<Rational> c;
  for (size_t k = 0; k < y.size(); ++k)
    if (!cln::zerop(y[k])) {
      c = Rational(integer.row[k]) / y[k];
      break;
    }
  ASSERT_TRUE(c.has_value()) << rational.label << ": a relation with no coefficient";
  ASSERT_FALSE(cln::zerop(*c)) << rational.label;
  for (size_t k = 0; k < y.size(); ++k) EXPECT_EQ(Rational(integer.row[k]), *c * y[k]) << rational.label << ", y_" << k + 1;
  if (cln::zerop(rational.rhs)) {
    EXPECT_TRUE(cln::zerop(integer.rhs)) << rational.label;
    return;
  }
  const Rational scale = Rational(integer.rhs) / (*c * rational.rhs);
  if (!rhs_scale) rhs_scale = scale;
  EXPECT_EQ(scale, *rhs_scale) << rational.label << ": the right-hand sides are not scaled alike";
  EXPECT_GT(scale, 0) << rational.label;
}

std::vector<RandomPolygonCase> polygons_without_dead_centre(std::uint64_t seed) {
  std::vector<RandomPolygonCase> out;
  for (int n = 4; n <= 12; ++n)
    for (int index = 0; index < 6; ++index) {
      RandomPolygonCase c = generate_random_polygon(seed, n, index);
      bool parallel = false;
      for (int j = 1; j <= n; ++j) parallel = parallel || cln::zerop(cross(c.polygon.side(j), c.polygon.side(j % n + 1)));
      if (!parallel) out.push_back(std::move(c));
    }
  return out;
}

TEST(IntegerFamilies, EachRelationIsTheRationalOneTimesANonzeroConstant) {
  const std::uint64_t seed = 3;
  const auto cases = polygons_without_dead_centre(seed);
  ASSERT_GT(cases.size(), 30u);
  for (const RandomPolygonCase& c : cases) {
    SCOPED_TRACE("seed " + std::to_string(seed) + ", n " + std::to_string(c.n) + ", family " + c.family);
    const int n = c.n;
    std::vector<Rational> omega = side_velocities(c.polygon, c.rates);
    omega[1] = omega[1] + Rational(1) / 7;  // any velocities: the scaling holds for all of them
    const IntegerFamilies fam = integer_fixed_side_families(c.polygon, omega);
    ASSERT_EQ(fam.velocity.size(), static_cast<size_t>(2 * n));
    ASSERT_EQ(fam.eq22.size(), static_cast<size_t>(n));
    ASSERT_EQ(fam.companion.size(), static_cast<size_t>(n));
    const RelativeRates rates(n);
    BodyPolygon bp;
    bp.polygon = c.polygon;
    for (int b = 0; b < n; ++b) bp.bodies.push_back(b);
    std::optional<Rational> rhs_scale;
    for (int f = 1; f <= n; ++f) {
      const BodyPolygon q = with_fixed_side(bp, f);
      const auto velocity = velocity_relations(rates, q);
      const auto acceleration = acceleration_relations(rates, q, omega);
      const size_t k = static_cast<size_t>(f - 1);
      expect_scaled(rates, velocity[0], fam.velocity[2 * k], rhs_scale);
      expect_scaled(rates, velocity[1], fam.velocity[2 * k + 1], rhs_scale);
      expect_scaled(rates, acceleration[0], fam.eq22[k], rhs_scale);
      expect_scaled(rates, acceleration[1], fam.companion[k], rhs_scale);
    }
  }
}

TEST(IntegerFamilies, RanksAreThoseOfTheRationalRelationsOnTheTrianglesAlsoWhenInconsistent) {
  const std::uint64_t seed = 9;
  int inconsistent = 0;
  for (const RandomPolygonCase& c : polygons_without_dead_centre(seed)) {
    const int n = c.n;
    std::vector<Rational> omega = side_velocities(c.polygon, c.rates);
    if (n % 2 == 0) omega[2] = omega[2] - Rational(2) / 3;  // wrong velocities: inconsistent accelerations
    SCOPED_TRACE("seed " + std::to_string(seed) + ", n " + std::to_string(n) + ", family " + c.family);
    const auto fams = count_fixed_side_relations(c.polygon, omega);
    const RelativeRates rates(n);
    const test::RationalFamilies ref = test::rational_families(c.polygon, omega);
    const std::vector<const std::vector<RateRelation>*> families{&ref.velocity, &ref.eq22, &ref.acceleration};
    for (size_t k = 0; k < families.size(); ++k) {
      RowEchelon<Rational> e(rates.columns());
      add_and_rank(e, triangle_relations(rates));
      const RankResult all = add_and_rank(e, *families[k]);
      EXPECT_EQ(fams[k].combined.rank, all.rank) << fams[k].name;
      EXPECT_EQ(fams[k].combined.augmented_rank, all.augmented_rank) << fams[k].name;
      inconsistent += !all.consistent();
    }
  }
  EXPECT_GT(inconsistent, 10);  // the wrong velocities were seen
}

TEST(IntegerFamilies, ADeadCentreForSomeFixedSideIsUndefined) {
  // Sides 2 and 3 parallel: the choice of fixed side that makes them sides n-2, n-1 has D = 0.
  const Polygon<Rational> p({{0, 0}, {4, 0}, {4, 2}, {4, 5}, {1, 4}});
  EXPECT_THROW(integer_fixed_side_families(p, {1, 2, 3, 4, 0}), UndefinedQuantity);
}

}  // namespace
}  // namespace linkproof
