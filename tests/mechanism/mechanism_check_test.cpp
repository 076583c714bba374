// A mechanism checked in floating point (`check --arith double`, mp30, ...): every value comes
// with a rigorous bound derived by running error analysis of the floating solve (Tracked<F>,
// core/tracked.h), never measured against the answer. The test measures: the exact solve (an
// independent route, CLN rationals) must lie within every bound, on every bundled kind of
// mechanism (four-bar, eight-bar, class-3, slider-crank with a prismatic joint).
#include <cln/real.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

#include "core/scalar.h"
#include "linkproof/io/mechanism_scene.h"
#include "linkproof/mechanism/mechanism_check.h"
#include "mechanism/mechanism_test_support.h"
#include "support/cli_run.h"

namespace linkproof {
namespace {


struct Enclosure {
  int values = 0, positive_bounds = 0;

  // |exact - midpoint| <= bound, compared as exact rationals (the bound rounded up to a double).
  void expect(const ResultNumber& exact, const ResultNumber& midpoint, const std::optional<ResultRadius>& bound,
              const std::string& what) {
    ++values;
    ASSERT_FALSE(is_exact(midpoint)) << what;
    ASSERT_TRUE(bound.has_value()) << what << ": no bound";
    const double b = to_double_up(*bound);
    ASSERT_TRUE(std::isfinite(b)) << what;
    positive_bounds += b > 0;
    const Rational error = cln::abs(std::get<Rational>(exact) - testing::exact_value_of_result(midpoint));
    EXPECT_LE(error, rational_from_double(b)) << what << ": exact " << format_rational(std::get<Rational>(exact))
                                              << ", bound " << b;
    // A bound that means something: a few hundred units of roundoff of the value's size.
    EXPECT_LE(b, 1e-9 * (1 + std::abs(to_double(exact)))) << what;
  }
};

void expect_bounds_enclose_exact(const std::string& scene_name, Arithmetic a) {
  const MechanismScene s = load_mechanism_scene(testing::mechanism_scene_path(scene_name));
  const MechanismCheck exact = check_mechanism(s, Arithmetic::Exact);
  const MechanismCheck floating = check_mechanism(s, a);
  const std::string where = scene_name + " " + std::string(to_string(a));
  ASSERT_TRUE(floating.arithmetic_note.empty()) << where << ": " << floating.arithmetic_note;
  // Exact values carry no bound.
  for (const auto& b : exact.omega_bound) EXPECT_FALSE(b.has_value()) << where;
  Enclosure e;
  ASSERT_EQ(floating.omega.size(), exact.omega.size());
  ASSERT_EQ(floating.omega_bound.size(), exact.omega.size());
  ASSERT_EQ(floating.omega_dot_bound.size(), exact.omega.size());
  for (size_t l = 0; l < exact.omega.size(); ++l) {
    e.expect(exact.omega[l], floating.omega[l], floating.omega_bound[l], where + " omega " + exact.link_names[l]);
    e.expect(exact.omega_dot[l], floating.omega_dot[l], floating.omega_dot_bound[l], where + " omega_dot " + exact.link_names[l]);
  }
  ASSERT_EQ(floating.relative.size(), exact.relative.size());
  for (size_t k = 0; k < exact.relative.size(); ++k) {
    const auto &x = exact.relative[k], &f = floating.relative[k];
    e.expect(x.omega, f.omega, f.omega_bound, where + " omega_" + x.i + x.k);
    e.expect(x.omega_dot, f.omega_dot, f.omega_dot_bound, where + " omega_dot_" + x.i + x.k);
  }
  for (auto lists : {&MechanismCheck::joints, &MechanismCheck::points}) {
    const auto &xs = exact.*lists, &fs = floating.*lists;
    ASSERT_EQ(xs.size(), fs.size());
    for (size_t j = 0; j < xs.size(); ++j)
      for (int c = 0; c < 2; ++c) {
        e.expect(xs[j].v[c], fs[j].v[c], fs[j].v_bound[c], where + " v of " + xs[j].name);
        e.expect(xs[j].a[c], fs[j].a[c], fs[j].a_bound[c], where + " a of " + xs[j].name);
      }
    for (size_t j = 0; j < xs.size(); ++j) {
      ASSERT_EQ(xs[j].slide.has_value(), fs[j].slide.has_value());
      if (!xs[j].slide) continue;
      e.expect(*xs[j].slide, *fs[j].slide, fs[j].slide_bound, where + " sliding v of " + xs[j].name);
      e.expect(*xs[j].slide_dot, *fs[j].slide_dot, fs[j].slide_dot_bound, where + " sliding a of " + xs[j].name);
      // Along the unit axis and the Coriolis term (issue 27): bounded too.
      ASSERT_TRUE(xs[j].sliding && fs[j].sliding) << where;
      const auto &xu = *xs[j].sliding, &fu = *fs[j].sliding;
      for (int c = 0; c < 2; ++c)
        e.expect(xu.coriolis[c], fu.coriolis[c], fu.coriolis_bound[c], where + " Coriolis of " + xs[j].name);
      if (xu.rate_radicand != 1) continue;  // an irrational |u|: sliding_rates_test.cpp
      e.expect(xu.v_unit, fu.v_unit, fu.v_unit_bound, where + " sliding v along the unit axis of " + xs[j].name);
      e.expect(xu.a_unit, fu.a_unit, fu.a_unit_bound, where + " sliding a along the unit axis of " + xs[j].name);
    }
  }
  EXPECT_GT(e.values, 10) << where;
  // Not vacuous: rounding happened somewhere, and its bound says so.
  EXPECT_GT(e.positive_bounds, 0) << where;
}

TEST(MechanismFloatingBounds, EveryValueOfTheFloatingSolveIsBoundedAndTheBoundContainsTheExactValue) {
  for (const char* scene : {"seed001_fourbar.yaml", "fig5_eightbar.yaml", "seed003_class3.yaml",
                            "dimensions_slider_crank.yaml", "inverted_slider_crank.yaml"})
    for (Arithmetic a : {Arithmetic::Double, Arithmetic::LongDouble, Arithmetic::Mp30})
      expect_bounds_enclose_exact(scene, a);
}

TEST(MechanismFloatingBounds, CheckPrintsTheBoundOfEveryFloatingValueInJsonAndText) {
  const std::string scene = testing::mechanism_scene_path("seed001_fourbar.yaml");
  const test::CliRun json = test::run_cli({"check", scene, "--arith", "double", "--json"});
  ASSERT_EQ(json.code, 0) << json.err;
  const auto j = nlohmann::json::parse(json.out);
  const auto& link = j["links"]["3"];
  ASSERT_TRUE(link.contains("omega_bound")) << link.dump();
  ASSERT_TRUE(link.contains("omega_dot_bound")) << link.dump();
  const double omega = std::stod(link["omega"].get<std::string>());
  const double bound = std::stod(link["omega_bound"].get<std::string>());
  EXPECT_GT(bound, 0);
  EXPECT_LE(std::abs(omega - -0.75), bound);
  ASSERT_TRUE(j["joints"]["B"].contains("v_bound")) << j["joints"]["B"].dump();
  EXPECT_EQ(j["joints"]["B"]["v_bound"].size(), 2u);

  const test::CliRun text = test::run_cli({"check", scene, "--arith", "double"});
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_NE(text.out.find("-0.75000000000000011 +- "), std::string::npos) << text.out;
  // Exact arithmetic: no bounds anywhere.
  const test::CliRun exact = test::run_cli({"check", scene, "--json"});
  ASSERT_EQ(exact.code, 0) << exact.err;
  EXPECT_FALSE(nlohmann::json::parse(exact.out)["links"]["3"].contains("omega_bound"));
}

}  // namespace
}  // namespace linkproof
