#include "numerics/stability.h"

#include <gtest/gtest.h>

#include <cmath>

#include "numerics/extreme_families.h"
#include "check/random_polygon.h"

namespace linkproof {
namespace {

/// The condition estimate's double bound must cover the observed double error, route by route.
/// Returns how many (route, arithmetic) errors it compared. Where the exact value exists (not
/// the dead centre) at least one must have been compared: a study that measured no double or
/// long double route, or whose condition estimates match none, would otherwise pass unseen.
int expect_bound_covers_double_error(const CaseStudy& s, const std::string& where) {
  int compared = 0;
  for (const RouteMeasurement& m : s.measurements) {
    if (m.arithmetic != "double" && m.arithmetic != "long double") continue;
    if (!m.defined) continue;
    for (const ConditionEstimate& c : s.conditions) {
      if (c.route != m.route || !c.defined) continue;
      ++compared;
      const bool dbl = m.arithmetic == "double";
      const double b1 = dbl ? c.bound_double_n1 : c.bound_long_double_n1;
      const double b2 = dbl ? c.bound_double_n2 : c.bound_long_double_n2;
      // Relative errors compare in log2 (bounds may be 0 when the result is exact).
      EXPECT_TRUE(m.n1.log2_relative_error <= std::log2(b1) + 1e-9)
          << where << " " << to_string(m.route) << " " << m.arithmetic << ": error 2^" << m.n1.log2_relative_error
          << " > bound " << b1;
      EXPECT_TRUE(m.n2.log2_relative_error <= std::log2(b2) + 1e-9)
          << where << " " << to_string(m.route) << " " << m.arithmetic << " (companion)";
    }
  }
  if (s.exact_n1.has_value()) {
    EXPECT_GT(compared, 0) << where << ": no double or long double error was compared with its bound";
  }
  return compared;
}

TEST(Stability, ConditionEstimateBoundsTheDoubleErrorOnRandomPolygons) {
  GroundTruthEngine engine;
  StudyOptions o;
  o.arithmetics = {"double", "long double"};
  int compared = 0;
  for (int n : {4, 5, 8}) {
    for (int i = 0; i < 12; ++i) {
      const RandomPolygonCase c = generate_random_polygon(77, n, i);
      compared += expect_bound_covers_double_error(study_case(engine, c.polygon, c.rates, o),
                                                   "seed 77 n " + std::to_string(n) + " index " + std::to_string(i));
    }
  }
  EXPECT_GE(compared, 36);  // at least one per case (asserted case by case above)
}

TEST(Stability, ConditionEstimateBoundsTheDoubleErrorOnExtremeFamilies) {
  GroundTruthEngine engine;
  StudyOptions o;
  o.arithmetics = {"double", "long double"};
  int compared = 0, families = 0;
  for (const ExtremeFamily& f : extreme_families()) {
    int in_family = 0;
    for (const Rational& x : f.quick_values) {
      if (f.name == "large_n" && x > 20) continue;
      const ExtremeCase c = f.make(x);
      in_family += expect_bound_covers_double_error(study_case(engine, c.polygon, c.rates, o),
                                                    f.name + " at " + format_rational(x));
    }
    EXPECT_GT(in_family, 0) << f.name << ": no value of the family compared an error with its bound";
    compared += in_family;
    ++families;
  }
  EXPECT_GT(families, 0);
  EXPECT_GT(compared, 0);
}

TEST(Stability, MultiprecisionConvergesToTheExactValueAsDigitsGrow) {
  GroundTruthEngine engine;
  const ExtremeFamily& f = *find_extreme_family("dead_centre");
  const ExtremeCase c = f.make(Rational(1) / 1000000);  // ill-conditioned: omega-dot ~ 1/D^3
  const CaseStudy s = study_case(engine, c.polygon, c.rates, {});
  for (Route r : kAllRoutes) {
    double previous = 0;
    for (const RouteMeasurement& m : s.measurements) {
      if (m.route != r || m.arithmetic == "exact") continue;
      ASSERT_TRUE(m.defined) << to_string(r) << " " << m.arithmetic;
      EXPECT_LT(m.n1.log2_relative_error, previous) << to_string(r) << " " << m.arithmetic;
      EXPECT_LT(m.n1.log2_relative_error, -m.precision_bits + 60.0) << to_string(r) << " " << m.arithmetic;
      previous = m.n1.log2_relative_error;
    }
    for (const RouteMeasurement& m : s.measurements) {
      if (m.route == r && m.arithmetic == "exact") {
        EXPECT_TRUE(std::isinf(m.n1.log2_relative_error));
      }
    }
  }
}

TEST(Stability, DeadCentreMakesEveryMeasurementUndefined) {
  GroundTruthEngine engine;
  const ExtremeCase c = find_extreme_family("dead_centre")->make(0);
  const CaseStudy s = study_case(engine, c.polygon, c.rates, {});
  EXPECT_FALSE(s.exact_n1.has_value());
  for (const RouteMeasurement& m : s.measurements) EXPECT_FALSE(m.defined);
}

TEST(Stability, TimingGivesAPositiveTimePerEvaluation) {
  GroundTruthEngine engine;
  StudyOptions o;
  o.arithmetics = {"double", "exact"};
  o.routes = {Route::ClosedForms};
  o.time_budget_seconds = 1e-4;
  const auto c = generate_random_polygon(3, 6, 0);
  for (const RouteMeasurement& m : study_case(engine, c.polygon, c.rates, o).measurements)
    EXPECT_GT(m.seconds_per_eval, 0) << m.arithmetic;
}

}  // namespace
}  // namespace linkproof
