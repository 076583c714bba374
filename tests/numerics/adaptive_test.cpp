#include "numerics/adaptive.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cln/integer.h>

#include <array>
#include <cmath>
#include <cstdio>

#include "numerics/extreme_families.h"
#include "check/random_polygon.h"
#include "geometry/closed_forms.h"

namespace linkproof {
namespace {

struct DoubleCase {
  std::string label;
  Polygon<double> polygon;
  InputRates<double> rates;
};

/// Random polygons and every extreme family at every parameter of the full study (exactly
/// singular and nearly singular ones among them), rounded to double: the doubles are the input.
std::vector<DoubleCase> corpus() {
  std::vector<DoubleCase> out;
  for (int n : {4, 5, 6, 9}) {
    for (int i = 0; i < 30; ++i) {
      const RandomPolygonCase c = generate_random_polygon(4242, n, i);
      out.push_back({"seed 4242 n " + std::to_string(n) + " index " + std::to_string(i), c.polygon.convert<double>(),
                     c.rates.convert<double>()});
    }
  }
  for (const ExtremeFamily& f : extreme_families()) {
    for (const Rational& x : f.full_values) {
      if (f.name == "large_n" && x > 50) continue;
      const ExtremeCase c = f.make(x);
      out.push_back({f.name + " at " + format_rational(x), c.polygon.convert<double>(), c.rates.convert<double>()});
    }
  }
  return out;
}

/// The exact truth for the double inputs, by another route (closed forms, Cramer's rule).
std::optional<std::pair<Rational, Rational>> exact_truth(const DoubleCase& c) {
  std::vector<Vec2<Rational>> joints;
  for (const auto& k : c.polygon.joints()) joints.push_back({exact_value_of(k.x), exact_value_of(k.y)});
  InputRates<Rational> in;
  for (double w : c.rates.omega) in.omega.push_back(exact_value_of(w));
  for (double w : c.rates.omega_dot) in.omega_dot.push_back(exact_value_of(w));
  const Polygon<Rational> p(std::move(joints));
  if (cln::zerop(p.dead_centre_determinant())) return std::nullopt;
  const PolygonMotion<Rational> m = compute_closed_form_motion(p, in);
  const auto n = static_cast<size_t>(p.n());
  return std::make_pair(m.omega_dot[n - 2], m.omega_dot[n - 3]);
}

void check_corpus(const AdaptiveOptions& o) {
  int escalated = 0, singular = 0;
  std::array<int, 4> by_stage{};
  for (const DoubleCase& c : corpus()) {
    SCOPED_TRACE(c.label);
    const AdaptiveResult r = compute_omega_dot_adaptive(c.polygon, c.rates, o);
    const auto truth = exact_truth(c);
    if (!truth) {
      ++singular;
      EXPECT_FALSE(r.defined);
      continue;
    }
    ASSERT_TRUE(r.defined);
    if (r.level != AdaptiveLevel::Double) ++escalated;
    ++by_stage[static_cast<size_t>(r.stage)];
    for (auto [value, bound, exact] : {std::tuple{r.omega_dot_n1, r.bound_n1, truth->first},
                                       std::tuple{r.omega_dot_n2, r.bound_n2, truth->second}}) {
      ASSERT_TRUE(std::isfinite(value) && std::isfinite(bound));
      EXPECT_LE(cln::abs(exact - exact_value_of(value)), exact_value_of(bound)) << "value " << value;
      if (o.relative_tolerance == 0)
        EXPECT_EQ(value, round_to_nearest_double(exact)) << "not correctly rounded";
      else
        EXPECT_LE(bound, o.relative_tolerance * std::abs(value));
    }
  }
  for (size_t i = 0; i < by_stage.size(); ++i)
    std::printf("%s: %d\n", std::string(to_string(static_cast<AdaptiveStage>(i))).c_str(), by_stage[i]);
  EXPECT_GE(singular, 1);   // the exact dead centre is in the corpus
  EXPECT_GE(escalated, 1);  // and cases double cannot certify
}

TEST(Adaptive, CertifiedBoundIsNeverWrongOnACorpusWithSingularAndNearlySingularCases) {
  check_corpus(AdaptiveOptions{});
}

TEST(Adaptive, CorrectlyRoundedModeIsNeverWrongOnTheSameCorpus) {
  AdaptiveOptions o;
  o.relative_tolerance = 0;
  check_corpus(o);
}

/// How many of kCases random pentagons the first (a priori double) stage certifies.
int certified_by_first_stage(const AdaptiveOptions& o, std::uint64_t seed, int cases) {
  int a_priori = 0;
  for (int i = 0; i < cases; ++i) {
    const RandomPolygonCase c = generate_random_polygon(seed, 5, i);
    const AdaptiveResult r = compute_omega_dot_adaptive(c.polygon.convert<double>(), c.rates.convert<double>(), o);
    if (r.stage == AdaptiveStage::APrioriDouble) ++a_priori;
  }
  std::printf("seed %llu, tolerance %g: %d of %d random pentagons certified by the a priori double stage\n",
              static_cast<unsigned long long>(seed), o.relative_tolerance, a_priori, cases);
  return a_priori;
}

TEST(Adaptive, TheAPrioriDoubleStageCertifiesAtLeast99PercentOfRandomPentagonsAtTheDefaultRequest) {
  EXPECT_GE(certified_by_first_stage(AdaptiveOptions{}, 20261121, 2000), 2000 * 99 / 100);
}

TEST(Adaptive, TheAPrioriDoubleStageCertifiesAtLeast98PercentOfRandomPentagonsAt40Bits) {
  EXPECT_GE(certified_by_first_stage(AdaptiveOptions{0x1p-40}, 20261121, 2000), 2000 * 98 / 100);
}

/// Random polygons scaled by 2^s (lengths) and rates by 2^t, s and t far beyond the bench
/// families: products underflow or overflow in double, so the filter stages must refuse rather
/// than certify a wrong value; omega-dot scales by 2^(2t) only, which the exact truth checks.
RC_GTEST_PROP(Adaptive, NeverWrongOnRandomPolygonsAtExtremeScales, ()) {
  const int n = *rc::gen::inRange(4, 8);
  const int index = *rc::gen::inRange(0, 1000);
  const int s = *rc::gen::inRange(-1000, 1000);
  const int t = *rc::gen::inRange(-500, 500);
  const bool correctly_rounded = *rc::gen::arbitrary<bool>();
  const RandomPolygonCase c = generate_random_polygon(77, n, index);
  std::vector<Vec2<double>> joints;
  for (const auto& k : c.polygon.joints())
    joints.push_back({std::ldexp(cln::double_approx(k.x), s), std::ldexp(cln::double_approx(k.y), s)});
  InputRates<double> in;
  for (const Rational& w : c.rates.omega) in.omega.push_back(std::ldexp(cln::double_approx(w), t));
  for (const Rational& w : c.rates.omega_dot) in.omega_dot.push_back(std::ldexp(cln::double_approx(w), 2 * t));
  const DoubleCase d{"", Polygon<double>(joints), in};
  AdaptiveOptions o;
  if (correctly_rounded) o.relative_tolerance = 0;
  const AdaptiveResult r = compute_omega_dot_adaptive(d.polygon, d.rates, o);
  const auto truth = exact_truth(d);  // joints that collapsed to equal doubles give D = 0
  RC_ASSERT(r.defined == truth.has_value());
  if (!truth) return;
  RC_TAG(std::string(to_string(r.stage)));
  for (auto [value, bound, exact] : {std::tuple{r.omega_dot_n1, r.bound_n1, truth->first},
                                     std::tuple{r.omega_dot_n2, r.bound_n2, truth->second}}) {
    if (!std::isfinite(value)) {
      // Only the exact stage returns a non-finite value: the exact result is beyond double's range.
      RC_ASSERT(r.stage == AdaptiveStage::Exact);
      continue;
    }
    RC_ASSERT(cln::abs(exact - exact_value_of(value)) <= exact_value_of(bound));
    if (correctly_rounded) RC_ASSERT(value == round_to_nearest_double(exact));
  }
}

TEST(Adaptive, RoundToNearestDoubleDecidesExactly) {
  const Rational third = Rational(1) / 3;
  EXPECT_EQ(round_to_nearest_double(third), 1.0 / 3.0);
  // 1 + 2^-53 is a tie between 1 and 1 + 2^-52: ties to even gives 1.
  EXPECT_EQ(round_to_nearest_double(1 + Rational(1) / cln::ash(cln::cl_I(1), 53)), 1.0);
  EXPECT_EQ(round_to_nearest_double(1 + 3 * (Rational(1) / cln::ash(cln::cl_I(1), 54))), 1.0 + 0x1p-52);
  // Below 2^-1022 (where CLN's double_approx gives 0): 3 * 2^-1075 ties between 2^-1074 and
  // 2^-1073; even gives 2^-1073. A third of 2^-1060 is 2^14/3 steps of 2^-1074: rounds to 5461.
  const Rational step = Rational(1) / cln::ash(cln::cl_I(1), 1074);
  EXPECT_EQ(round_to_nearest_double(3 * step / 2), 0x1p-1073);
  EXPECT_EQ(round_to_nearest_double(-step * 16384 / 3), -5461 * 0x1p-1074);
}

}  // namespace
}  // namespace linkproof
