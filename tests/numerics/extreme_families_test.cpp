#include "numerics/extreme_families.h"

#include <gtest/gtest.h>

#include "numerics/routes.h"
#include "numerics/stability.h"

namespace linkproof {
namespace {

TEST(ExtremeFamilies, EachDegeneracyFamilyReachesItsDegeneracyExactlyAtEpsilonZero) {
  int degeneracy_families = 0;
  for (const ExtremeFamily& f : extreme_families()) {
    if (f.degenerate_quantity.empty()) continue;
    ++degeneracy_families;
    SCOPED_TRACE(f.name);
    const ExtremeCase at_zero = f.make(0);
    EXPECT_EQ(polygon_input_problem(at_zero.polygon), "");
    const bool dead = cln::zerop(at_zero.polygon.dead_centre_determinant());
    EXPECT_EQ(dead, f.singular);
    try {
      (void)compute_by_construction(at_zero.polygon, at_zero.rates);
      ADD_FAILURE() << "the construction exists at epsilon = 0";
    } catch (const UndefinedQuantity& u) {
      EXPECT_EQ(u.quantity(), f.degenerate_quantity) << u.what();
    }
    if (!f.singular) {
      // Regular mechanism: the closed forms and the direct solve still give the truth.
      const PolygonMotion<Rational> m = compute_closed_form_motion(at_zero.polygon, at_zero.rates);
      EXPECT_EQ(compute_by_direct_solve(at_zero.polygon, at_zero.rates).omega_dot_n1, m.omega_dot[3]);
    }
  }
  EXPECT_EQ(degeneracy_families, 6);
}

TEST(ExtremeFamilies, AwayFromTheLimitEveryRouteExistsAndAgreesExactly) {
  GroundTruthEngine engine;
  for (const ExtremeFamily& f : extreme_families()) {
    SCOPED_TRACE(f.name);
    for (const Rational& x : f.quick_values) {
      if (cln::zerop(x) || (f.name == "large_n" && x > 20)) continue;
      const ExtremeCase c = f.make(x);
      ASSERT_EQ(polygon_input_problem(c.polygon), "");
      const PolygonMotion<Rational> m = compute_closed_form_motion(c.polygon, c.rates);
      const size_t n1 = static_cast<size_t>(c.polygon.n() - 2);
      for (Route r : kAllRoutes) {
        if (r == Route::Construction && f.name == "large_n") continue;  // random: may hit a pole
        EXPECT_EQ(compute_by_route(r, engine, c.polygon, c.rates).omega_dot_n1, m.omega_dot[n1]) << to_string(r);
      }
    }
  }
}

TEST(ExtremeFamilies, ConstructionLosesDigitsTowardsTheLimitWhileTheClosedFormsDoNot) {
  // conventions §A6: near Q_j -> infinity the construction loses accuracy like 1e-16 / eps in double.
  GroundTruthEngine engine;
  const ExtremeFamily& f = *find_extreme_family("q_infinity");
  StudyOptions o;
  o.arithmetics = {"double"};
  o.routes = {Route::Construction, Route::ClosedForms};
  const CaseStudy near = study_case(engine, f.make(Rational(1) / 100000000000LL).polygon, f.make(Rational(1) / 100000000000LL).rates, o);
  ASSERT_EQ(near.measurements.size(), 2u);
  EXPECT_GT(near.measurements[0].n1.log2_relative_error, -40);  // construction: <= 40 bits right
  EXPECT_LT(near.measurements[1].n1.log2_relative_error, -45);  // closed forms: near full precision
}

}  // namespace
}  // namespace linkproof
