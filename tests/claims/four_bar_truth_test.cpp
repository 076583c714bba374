// PolygonContext::four_bar in exact arithmetic: the four-bar's motion read off one
// differentiation of its solution must be what evaluating the motion gives.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "check/random_polygon.h"
#include "claims/polygon_context.h"
#include "core/inline_rational.h"
#include "support/polygons.h"

namespace linkproof {
namespace {

template <class T>
void expect_same_defined_value(const Defined<T>& got, const Defined<T>& want, const std::string& what) {
  ASSERT_EQ(got.has_value(), want.has_value()) << what;
  if (want.has_value()) {
    EXPECT_EQ(ScalarTraits<T>::to_rational(got.get()), ScalarTraits<T>::to_rational(want.get())) << what;
  } else {
    EXPECT_EQ(got.quantity(), want.quantity()) << what;
    EXPECT_EQ(got.reason(), want.reason()) << what;
  }
}

template <class T>
void expect_same_terms(const TermCoefficients<T>& got, const TermCoefficients<T>& want, const std::string& what) {
  ASSERT_EQ(got.omega_dot.size(), 1u) << what;
  ASSERT_EQ(got.omega_sq.size(), 1u) << what;
  EXPECT_EQ(ScalarTraits<T>::to_rational(got.omega_dot[0]), ScalarTraits<T>::to_rational(want.omega_dot[0])) << what;
  EXPECT_EQ(ScalarTraits<T>::to_rational(got.omega_sq[0]), ScalarTraits<T>::to_rational(want.omega_sq[0])) << what;
  EXPECT_TRUE(got.omega_pair.empty()) << what;
}

// Four-bar j against its motion evaluated as the context evaluates it in floating point: at unit
// input rates (the ratios), at the polygon's rates, and the term coefficients. Returns how many
// four-bars were defined.
template <class T>
int expect_four_bar_is_its_evaluated_motion(GroundTruthEngine& engine, const Polygon<Rational>& exact,
                                            const InputRates<Rational>& rates, const std::string& name) {
  const PolygonContext<T> c = build_polygon_context<T>(engine, exact, rates);
  const bool dead_centre = cln::zerop(exact.dead_centre_determinant());
  int defined = 0;
  for (int j = 1; j <= c.inputs(); ++j) {
    const std::string what = name + " j=" + std::to_string(j);
    const Polygon<T> fb = make_four_bar_polygon(c.polygon, j);
    const FourBarTruth<T>& t = c.four_bar(j);
    if (dead_centre) {
      // Every quantity is undefined, named as the rest of the context names the dead centre.
      for (const Defined<T>* d : {&t.ratio_out, &t.ratio_cpl, &t.omega_out, &t.omega_cpl, &t.omega_dot_out, &t.omega_dot_cpl}) {
        EXPECT_FALSE(d->has_value()) << what;
        EXPECT_EQ(d->quantity(), c.truth().quantity()) << what;
        EXPECT_EQ(d->reason(), c.truth().reason()) << what;
      }
      EXPECT_FALSE(t.coefficients.has_value()) << what;
      EXPECT_EQ(t.coefficients.quantity(), c.truth().quantity()) << what;
      continue;
    }
    const PolygonMotion<T> unit = engine.motion(fb, InputRates<T>{{from_int<T>(1)}, {from_int<T>(0)}});
    const PolygonMotion<T> real = engine.motion(fb, InputRates<T>{{c.omega_in(j)}, {c.omega_dot_in(j)}});
    expect_same_defined_value(t.ratio_out, Defined<T>(unit.omega[2]), what + " ratio_out");
    expect_same_defined_value(t.ratio_cpl, Defined<T>(unit.omega[1]), what + " ratio_cpl");
    expect_same_defined_value(t.omega_out, Defined<T>(real.omega[2]), what + " omega_out");
    expect_same_defined_value(t.omega_cpl, Defined<T>(real.omega[1]), what + " omega_cpl");
    expect_same_defined_value(t.omega_dot_out, Defined<T>(real.omega_dot[2]), what + " omega_dot_out");
    expect_same_defined_value(t.omega_dot_cpl, Defined<T>(real.omega_dot[1]), what + " omega_dot_cpl");
    const auto want = engine.coefficients(fb);
    expect_same_terms(t.coefficients.get().first, want.first, what + " out coefficients");
    expect_same_terms(t.coefficients.get().second, want.second, what + " cpl coefficients");
    ++defined;
  }
  return defined;
}

TEST(FourBarTruth, ExactFourBarsFromOneDifferentiationAreTheirEvaluatedMotion) {
  constexpr std::uint64_t kSeed = 2814;
  std::printf("four-bar truth seed %llu (generate_random_polygon(seed, n, index))\n",
              static_cast<unsigned long long>(kSeed));
  std::vector<std::pair<std::string, RandomPolygonCase>> cases;
  for (int n = 4; n <= 9; ++n)
    for (int index = 0; index < 6; ++index)
      cases.emplace_back("n=" + std::to_string(n) + " index " + std::to_string(index), generate_random_polygon(kSeed, n, index));
  RandomPolygonCase pentagon;
  pentagon.polygon = test::spec_pentagon().polygon;
  pentagon.rates = test::spec_pentagon().rates;
  cases.emplace_back("the bundled pentagon", pentagon);
  // Sides r_3 and r_4 parallel: D = 0, the dead centre, where every four-bar is undefined too.
  RandomPolygonCase dead = pentagon;
  dead.polygon = Polygon<Rational>({{0, 0}, {1, 2}, {3, 3}, {4, 3}, {6, 3}});
  ASSERT_TRUE(cln::zerop(dead.polygon.dead_centre_determinant()));
  cases.emplace_back("a dead centre", dead);
  GroundTruthEngine engine;
  int defined = 0;
  for (const auto& [name, k] : cases) {
    defined += expect_four_bar_is_its_evaluated_motion<InlineRational>(engine, k.polygon, k.rates, name + " (words)");
    defined += expect_four_bar_is_its_evaluated_motion<Rational>(engine, k.polygon, k.rates, name + " (CLN)");
  }
  EXPECT_GT(defined, 200);
}

}  // namespace
}  // namespace linkproof
