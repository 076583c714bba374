// The four routes of numerics/routes.h over every arithmetic of the ladder: one typed test per
// arithmetic, the same algorithm for every type.
#include "numerics/routes.h"

#include <gtest/gtest.h>

#include "numerics/error_measure.h"
#include "numerics/ladder.h"
#include "check/random_polygon.h"
#include "support/polygons.h"

namespace linkproof {
namespace {

template <class T>
class RoutesOnLadder : public ::testing::Test {};

using LadderTestTypes =
    ::testing::Types<double, long double, MpFloat<30>, MpFloat<50>, MpFloat<100>, MpFloat<1000>, Rational>;
TYPED_TEST_SUITE(RoutesOnLadder, LadderTestTypes);

/// Within a few hundred ulps of a p-bit arithmetic (these configurations are well conditioned),
/// exactly for exact arithmetic.
template <class T>
void expect_close(const T& computed, const Rational& exact, const char* what) {
  const ErrorMeasure e = measure_error(to_exact(computed), exact, precision_bits<T>());
  if constexpr (ScalarTraits<T>::is_exact) {
    EXPECT_EQ(to_exact(computed), exact) << what;
  } else {
    EXPECT_LT(e.log2_relative_error, -precision_bits<T>() + 10) << what << " in " << arithmetic_name<T>();
  }
}

TYPED_TEST(RoutesOnLadder, EveryRouteGivesTheA8PentagonAnswer) {
  using T = TypeParam;
  const auto ex = test::spec_pentagon();
  const Polygon<T> p = ex.polygon.convert<T>();
  const InputRates<T> in = ex.rates.convert<T>();
  GroundTruthEngine engine;
  for (Route r : kAllRoutes) {
    const RouteValue<T> v = compute_by_route(r, engine, p, in);
    expect_close(v.omega_dot_n1, test::q(3755, 1331), to_string(r).data());
    expect_close(v.omega_dot_n2, test::q(7331, 2662), to_string(r).data());
  }
}

TYPED_TEST(RoutesOnLadder, EveryRouteGivesTheA8HexagonAnswer) {
  using T = TypeParam;
  const auto ex = test::spec_hexagon();
  const Polygon<T> p = ex.polygon.convert<T>();
  const InputRates<T> in = ex.rates.convert<T>();
  GroundTruthEngine engine;
  for (Route r : kAllRoutes) {
    const RouteValue<T> v = compute_by_route(r, engine, p, in);
    expect_close(v.omega_dot_n1, test::q(38322, 6859), to_string(r).data());
    expect_close(v.omega_dot_n2, test::q(46033, 6859), to_string(r).data());
  }
}

TYPED_TEST(RoutesOnLadder, EveryRouteNamesTheDeadCentre) {
  using T = TypeParam;
  // r_{n-2} = (2,-4), r_{n-1} = (-3,6): parallel.
  const Polygon<Rational> dead({{0, 0}, {1, 4}, {5, 5}, {7, 1}, {4, 7}});
  ASSERT_TRUE(cln::zerop(dead.dead_centre_determinant()));
  GroundTruthEngine engine;
  for (Route r : kAllRoutes)
    EXPECT_THROW(compute_by_route(r, engine, dead.convert<T>(), test::spec_pentagon().rates.convert<T>()),
                 UndefinedQuantity)
        << to_string(r);
}

TEST(Routes, AllRoutesAgreeExactlyWithTheClosedFormMotionOnRandomPolygons) {
  GroundTruthEngine engine;
  for (int n : {4, 5, 7, 12}) {
    for (int i = 0; i < 6; ++i) {
      const RandomPolygonCase c = generate_random_polygon(505, n, i);
      SCOPED_TRACE("seed 505, n " + std::to_string(n) + ", index " + std::to_string(i));
      const PolygonMotion<Rational> m = compute_closed_form_motion(c.polygon, c.rates);
      for (Route r : kAllRoutes) {
        RouteValue<Rational> v;
        try {
          v = compute_by_route(r, engine, c.polygon, c.rates);
        } catch (const UndefinedQuantity& u) {
          EXPECT_EQ(r, Route::Construction) << u.what();  // only the construction may break
          continue;
        }
        EXPECT_EQ(v.omega_dot_n1, m.omega_dot[static_cast<size_t>(n - 2)]) << to_string(r);
        EXPECT_EQ(v.omega_dot_n2, m.omega_dot[static_cast<size_t>(n - 3)]) << to_string(r);
      }
    }
  }
}

TEST(Routes, NamesRoundTrip) {
  for (Route r : kAllRoutes) EXPECT_EQ(parse_route(to_string(r)), r);
  EXPECT_FALSE(parse_route("graphic").has_value());
}

TEST(ErrorMeasure, MeasuresErrorsFarBelowDoubleRange) {
  const Rational exact(3);
  const Rational tiny = Rational(1) / cln::expt_pos(cln::cl_I(2), 3000);
  const ErrorMeasure e = measure_error(exact + 3 * tiny, exact, 3392);
  EXPECT_NEAR(e.log2_relative_error, -3000, 1e-9);
  EXPECT_NEAR(e.correct_bits, 3000, 1e-9);
  EXPECT_EQ(format_log2_as_decimal(-3000 * 1.0).substr(0, 3), "8.1");  // 2^-3000 = 8.1e-904
}

TEST(ErrorMeasure, CountsUlpsOfTheComputingArithmetic) {
  const Rational exact(1);
  // One ulp of 1 in double is 2^-52: error_bits = log2(1 + 1) = 1.
  const ErrorMeasure e = measure_error(exact + Rational(1) / cln::expt_pos(cln::cl_I(2), 52), exact, 53);
  EXPECT_NEAR(e.error_bits, 1.0, 1e-12);
  EXPECT_EQ(measure_error(exact, exact, 53).error_bits, 0);
}

}  // namespace
}  // namespace linkproof
