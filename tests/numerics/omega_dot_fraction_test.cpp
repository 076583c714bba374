#include "numerics/omega_dot_fraction.h"

#include <gtest/gtest.h>

#include "check/random_polygon.h"
#include "numerics/routes.h"

namespace linkproof {
namespace {

OmegaDotFraction<Rational> fraction_of(const RandomPolygonCase& c) {
  return compute_omega_dot_fraction<Rational>(
      c.polygon.n(), [&](int j) { return c.polygon.side(j); },
      [&](int k, Rational& w, Rational& wd) {
        w = c.rates.omega[static_cast<size_t>(k)];
        wd = c.rates.omega_dot[static_cast<size_t>(k)];
      });
}

TEST(OmegaDotFraction, EqualsTheDirectSolveExactlyOnRandomPolygons) {
  constexpr std::uint64_t kSeed = 515;
  for (int n = 4; n <= 9; ++n) {
    for (int i = 0; i < 20; ++i) {
      SCOPED_TRACE("seed " + std::to_string(kSeed) + " n " + std::to_string(n) + " index " + std::to_string(i));
      const RandomPolygonCase c = generate_random_polygon(kSeed, n, i);
      if (cln::zerop(c.polygon.dead_centre_determinant())) continue;
      const OmegaDotFraction<Rational> f = fraction_of(c);
      const RouteValue<Rational> truth = compute_by_direct_solve(c.polygon, c.rates);
      EXPECT_EQ(f.numerator_n1 / f.denominator, truth.omega_dot_n1);
      EXPECT_EQ(f.numerator_n2 / f.denominator, truth.omega_dot_n2);
    }
  }
}

TEST(OmegaDotFraction, DenominatorIsTheCubeOfTheDeadCentreDeterminant) {
  const RandomPolygonCase c = generate_random_polygon(516, 6, 0);
  const OmegaDotFraction<Rational> f = fraction_of(c);
  const Rational d = c.polygon.dead_centre_determinant();
  EXPECT_EQ(f.denominator, d * d * d);
}

}  // namespace
}  // namespace linkproof
