// Tracked<F>: the radius bounds the true error, checked against exact rationals.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "linkproof/core/scalar.h"
#include "linkproof/geometry/closed_forms.h"
#include "linkproof/eval/random_polygon.h"

namespace linkproof {
namespace {

/// |exact - v| <= e, decided exactly.
template <class F>
bool encloses(const Tracked<F>& t, const Rational& exact) {
  if (!std::isfinite(t.e)) return true;
  return cln::abs(exact - exact_value_of(t.v)) <= exact_value_of(t.e);
}

TEST(Tracked, ConversionRadiusIsTheExactRoundingError) {
  const auto t = ScalarTraits<Tracked<double>>::from_rational(Rational(1) / 10);
  EXPECT_EQ(t.v, 0.1);
  EXPECT_GT(t.e, 0.0);
  EXPECT_LT(t.e, 1e-17);
  const auto exact = ScalarTraits<Tracked<double>>::from_rational(Rational(3) / 4);
  EXPECT_EQ(exact.e, 0.0);
}

TEST(Tracked, DivisionByAnIntervalContainingZeroIsUnbounded) {
  const Tracked<double> a{1.0, 0.0}, b{1e-20, 1e-19};
  EXPECT_FALSE(std::isfinite((a / b).e));
}

RC_GTEST_PROP(Tracked, BoundEnclosesTheExactClosedFormMotion, ()) {
  const int n = *rc::gen::inRange(4, 10);
  const int index = *rc::gen::inRange(0, 1000);
  const auto rc_case = generate_random_polygon(7, n, index);
  const auto exact = compute_closed_form_motion(rc_case.polygon, rc_case.rates);
  const auto tracked = compute_closed_form_motion(rc_case.polygon.convert<Tracked<double>>(),
                                                  rc_case.rates.convert<Tracked<double>>());
  for (int j = 0; j < n; ++j) {
    RC_ASSERT(encloses(tracked.omega[j], exact.omega[j]));
    RC_ASSERT(encloses(tracked.omega_dot[j], exact.omega_dot[j]));
  }
}

}  // namespace
}  // namespace linkproof
