// Sliders as textbooks state them (issue 27): a prismatic pair's sliding velocity and
// acceleration along the unit axis u/|u| in length units, positive when the slider moves along
// +u relative to the guide (whatever length u is written with), stated exactly when |u| is
// irrational, enclosed with a bound in floating point; and the Coriolis term 2 omega_guide J v_rel
// of every pair, against hand computations.
#include <cln/integer.h>
#include <cln/real.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "core/scalar.h"
#include "linkproof/io/mechanism_scene.h"
#include "linkproof/mechanism/mechanism_check.h"
#include "mechanism/axis_length.h"
#include "mechanism/mechanism_test_support.h"
#include "support/cli_run.h"

namespace linkproof {
namespace {

// A slider-crank: crank O2 A (A = (3, 4)), rod A B, slider at B = (12, 0) on a frame guide with
// the axis `axis`. By hand: v_A = 2 J (3, 4) = (-8, 6); v_B = v_A + omega_rod J (9, -4)
// = (-8 + 4 omega_rod, 6 + 9 omega_rod).
std::string slider_crank(const std::string& axis) {
  return "name: sc\nmechanism:\n  ground: g\n  joints:\n"
         "    - {name: O2, type: revolute, links: [g, crank], at: [0, 0]}\n"
         "    - {name: A, type: revolute, links: [crank, rod], at: [3, 4]}\n"
         "    - {name: B, type: revolute, links: [rod, slider], at: [12, 0]}\n"
         "    - {name: D, type: prismatic, links: [g, slider], at: [12, 0], axis: " + axis + "}\n"
         "  inputs:\n    - {link: crank, omega: 2, omega_dot: 1}\n";
}

const MechanismCheck::PointMotion& joint_named(const MechanismCheck& c, const std::string& name) {
  for (const auto& p : c.joints)
    if (p.name == name) return p;
  throw std::runtime_error("no joint " + name);
}

Rational exact(const ResultNumber& x) { return std::get<Rational>(x); }

MechanismCheck check_text(const std::string& yaml, Arithmetic a = Arithmetic::Exact) {
  return check_mechanism(parse_mechanism_scene(yaml, "test.yaml"), a);
}

TEST(SlidingRates, AreAlongTheUnitAxisWhateverLengthTheAxisIsWrittenWith) {
  // On the x axis: v_B = (-8 + 4 w, 0) with 6 + 9 w = 0, w = -2/3: v_B = (-32/3, 0).
  for (const char* axis : {"[1, 0]", "[2, 0]", "[1/5, 0]"}) {
    const MechanismCheck c = check_text(slider_crank(axis));
    const auto& d = joint_named(c, "D");
    ASSERT_TRUE(d.sliding.has_value()) << axis;
    EXPECT_EQ(d.sliding->rate_radicand, 1) << axis;
    EXPECT_EQ(exact(d.sliding->v_unit), Rational(-32) / 3) << axis;
    // A frame-fixed guide: the sliding acceleration is the slider point's acceleration along +u.
    EXPECT_EQ(exact(d.sliding->a_unit), exact(d.a[0])) << axis;
    // The old keys stay per unit of the axis as written: sigma-dot = v / |u|.
    EXPECT_EQ(exact(*d.slide) * d.sliding->axis_length, Rational(-32) / 3) << axis;
  }
}

TEST(SlidingRates, PositiveMeansTheSliderMovesAlongPlusAxisRelativeToTheGuide) {
  const MechanismCheck plus = check_text(slider_crank("[1, 0]"));
  const MechanismCheck minus = check_text(slider_crank("[-3, 0]"));
  // The slider moves towards -x (v_B = (-32/3, 0)): negative along +x, positive along -x.
  EXPECT_EQ(exact(joint_named(plus, "D").sliding->v_unit), Rational(-32) / 3);
  EXPECT_EQ(exact(joint_named(minus, "D").sliding->v_unit), Rational(32) / 3);
  EXPECT_EQ(exact(joint_named(minus, "D").sliding->a_unit), -exact(joint_named(plus, "D").sliding->a_unit));
  EXPECT_EQ(joint_named(plus, "D").sliding->guide, "g");
  EXPECT_EQ(joint_named(plus, "D").sliding->slider, "slider");
}

TEST(SlidingRates, AnIrrationalAxisLengthIsStatedExactlyAsARoot) {
  // Guide along (1, 1): -8 + 4 w = 6 + 9 w, w = -14/5, v_B = (-96/5, -96/5); along the unit
  // axis (1, 1)/sqrt(2) that is -96/5 sqrt(2), whether u is written [1, 1] or [2, 2].
  for (const char* axis : {"[1, 1]", "[2, 2]"}) {
    const MechanismCheck c = check_text(slider_crank(axis));
    const auto& s = *joint_named(c, "D").sliding;
    EXPECT_EQ(s.axis_radicand, 2) << axis;
    EXPECT_EQ(s.rate_radicand, 2) << axis;
    EXPECT_EQ(exact(s.v_unit), Rational(-96) / 5) << axis << ": the coefficient of sqrt(2)";
  }
  const MechanismCheck c = check_text(slider_crank("[2, 2]"));
  const auto& s = *joint_named(c, "D").sliding;
  EXPECT_EQ(s.axis_length, 2);  // |(2, 2)| = 2 sqrt(2)
}

TEST(SlidingRates, SquareRootFormIsExact) {
  for (const auto& [q, c, m] : std::vector<std::tuple<Rational, Rational, int>>{
           {Rational(25), 5, 1}, {Rational(2), 1, 2}, {Rational(8), 2, 2}, {Rational(9) / 8, Rational(3) / 4, 2},
           {Rational(4500), 30, 5}, {Rational(1) / 3, Rational(1) / 3, 3}}) {
    const SquareRootForm f = construct_square_root(q);
    EXPECT_EQ(f.coefficient, c) << format_rational(q);
    EXPECT_EQ(f.radicand, m) << format_rational(q);
    EXPECT_EQ(f.coefficient * f.coefficient * f.radicand, q) << format_rational(q);
  }
  // A square of a prime above the trial bound is still found whole: 1009^2 * 3 keeps 3.
  const SquareRootForm big = construct_square_root(Rational(1009 * 1009));
  EXPECT_EQ(big.coefficient, 1009);
  EXPECT_EQ(big.radicand, 1);
}

TEST(SlidingRates, TheEnclosureOfARootHoldsIt) {
  const RationalEnclosure r = enclose_square_root(Rational(2), 200);
  const Rational lo = r.midpoint - r.half_width, hi = r.midpoint + r.half_width;
  EXPECT_TRUE(lo * lo <= 2 && 2 <= hi * hi);
  EXPECT_LE(r.half_width, Rational(1) / cln::expt_pos(cln::cl_I(2), 199));
}

// x = c sqrt(m) in [lo, hi], decided exactly.
bool root_form_within(const Rational& c, const cln::cl_I& m, const Rational& lo, const Rational& hi) {
  const auto at_least = [&](const Rational& r) {  // c sqrt(m) >= r
    if (!cln::minusp(c)) return cln::minusp(r) || c * c * m >= r * r;
    return cln::minusp(r) && c * c * m <= r * r;
  };
  const auto at_most = [&](const Rational& r) {  // c sqrt(m) <= r
    if (cln::minusp(c)) return !cln::minusp(r) || c * c * m >= r * r;
    return !cln::minusp(r) && c * c * m <= r * r;
  };
  return at_least(lo) && at_most(hi);
}


TEST(SlidingRates, FloatingRatesAlongTheUnitAxisEncloseTheExactRoot) {
  const MechanismCheck x = check_text(slider_crank("[1, 1]"));
  const auto& e = *joint_named(x, "D").sliding;
  for (Arithmetic a : {Arithmetic::Double, Arithmetic::LongDouble, Arithmetic::Mp30}) {
    const MechanismCheck f = check_text(slider_crank("[1, 1]"), a);
    const auto& s = *joint_named(f, "D").sliding;
    const std::string where(to_string(a));
    EXPECT_EQ(s.rate_radicand, 1) << where;
    for (const auto& [value, bound, coefficient] :
         {std::tuple{s.v_unit, s.v_unit_bound, exact(e.v_unit)}, std::tuple{s.a_unit, s.a_unit_bound, exact(e.a_unit)}}) {
      ASSERT_TRUE(bound.has_value()) << where;
      const double b = to_double_up(*bound);
      EXPECT_GT(b, 0) << where;
      EXPECT_LE(b, 1e-9 * (1 + std::abs(to_double(value)))) << where;
      const Rational m = testing::exact_value_of_result(value), r = rational_from_double(b);
      EXPECT_TRUE(root_form_within(coefficient, e.rate_radicand, m - r, m + r))
          << where << ": " << format_rational(coefficient) << "*sqrt(2) not within " << b << " of " << to_double(value);
    }
    for (int k = 0; k < 2; ++k) {
      ASSERT_TRUE(s.coriolis_bound[k].has_value()) << where;
      const Rational m = testing::exact_value_of_result(s.coriolis[k]);
      EXPECT_LE(cln::abs(m - exact(e.coriolis[k])), rational_from_double(to_double_up(*s.coriolis_bound[k]))) << where;
    }
  }
}

// The inverted slider-crank (verify/scenes/mechanisms/inverted_slider_crank.yaml) by hand: crank
// O2 A, A = (2, 3), omega_2 = 2; the block at A slides on the rocker O4 A, O4 = (6, 0), unit axis
// e = (-4/5, 3/5). v_A = 2 J (2, 3) = (-6, 4) = omega_4 J (A - O4) + s-dot e = omega_4 (-3, -4)
// + s-dot e. Along e ((-3, -4).e = 0): s-dot = (-6, 4).e = 36/5; along n = (-3, -4)/5:
// 5 omega_4 = (-6, 4).n = 2/5, omega_4 = 2/25. Coriolis 2 omega_4 s-dot J e = (144/125) (-3/5, -4/5)
// = (-432/625, -576/625), magnitude 144/125 = 1.152.
TEST(SlidingCoriolis, InvertedSliderCrankMatchesTheHandComputation) {
  const MechanismScene scene = load_mechanism_scene(testing::mechanism_scene_path("inverted_slider_crank.yaml"));
  const MechanismCheck c = check_mechanism(scene, Arithmetic::Exact);
  const auto& s = *joint_named(c, "S").sliding;
  const Vec2<Rational> e{Rational(-4) / 5, Rational(3) / 5}, A{2, 3}, O4{6, 0};
  const Vec2<Rational> vA = Rational(2) * perp(A), r = A - O4, n{Rational(-3) / 5, Rational(-4) / 5};
  const Rational sdot = dot(vA, e), omega4 = dot(vA, n) / dot(perp(r), n);
  ASSERT_EQ(sdot, Rational(36) / 5);
  ASSERT_EQ(omega4, Rational(2) / 25);
  const Vec2<Rational> coriolis = (2 * omega4 * sdot) * perp(e);
  EXPECT_EQ(exact(s.coriolis[0]), coriolis.x);
  EXPECT_EQ(exact(s.coriolis[1]), coriolis.y);
  EXPECT_EQ(exact(s.coriolis[0]), Rational(-432) / 625);
  EXPECT_EQ(exact(s.coriolis[1]), Rational(-576) / 625);
  EXPECT_EQ(exact(s.v_unit), Rational(36) / 5);
  EXPECT_EQ(s.guide, "rocker");
  EXPECT_EQ(s.slider, "block");
  // Must fail: the term without its factor 2, or with the crank's omega, is not what is reported.
  EXPECT_NE(exact(s.coriolis[0]), (omega4 * sdot * perp(e)).x);
  EXPECT_NE(exact(s.coriolis[0]), (2 * Rational(2) * sdot * perp(e)).x);
}

TEST(SlidingCoriolis, VanishesOnAFrameFixedGuide) {
  const MechanismCheck c = check_text(slider_crank("[1, 0]"));
  const auto& s = *joint_named(c, "D").sliding;
  EXPECT_EQ(exact(s.coriolis[0]), 0);
  EXPECT_EQ(exact(s.coriolis[1]), 0);
}

TEST(SlidingJson, AddsUnitAxisRatesAndCoriolisAndKeepsTheOldKeys) {
  const std::string path = ::testing::TempDir() + "sliding_json_axis2.yaml";
  std::ofstream(path) << slider_crank("[2, 0]");
  const test::CliRun r = test::run_cli({"check", path, "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto d = nlohmann::json::parse(r.out)["joints"]["D"];
  EXPECT_EQ(d["sliding_v"], "-16/3");  // per unit of the axis as written (unchanged)
  EXPECT_EQ(d["sliding_v_unit"], "-32/3");
  EXPECT_EQ(d["axis"], nlohmann::json({"2", "0"}));
  EXPECT_EQ(d["axis_length"], "2");
  EXPECT_EQ(d["guide"], "g");
  EXPECT_EQ(d["slider"], "slider");
  EXPECT_EQ(d["coriolis"], nlohmann::json({"0", "0"}));
  EXPECT_FALSE(d.contains("sliding_v_unit_bound"));

  const test::CliRun inv = test::run_cli({"check", testing::mechanism_scene_path("inverted_slider_crank.yaml"), "--json"});
  ASSERT_EQ(inv.code, 0) << inv.err;
  EXPECT_EQ(nlohmann::json::parse(inv.out)["joints"]["S"]["coriolis"], nlohmann::json({"-432/625", "-576/625"}));

  const std::string diagonal = ::testing::TempDir() + "sliding_json_axis11.yaml";
  std::ofstream(diagonal) << slider_crank("[1, 1]");
  const test::CliRun root = test::run_cli({"check", diagonal, "--json"});
  ASSERT_EQ(root.code, 0) << root.err;
  const auto s = nlohmann::json::parse(root.out)["joints"]["D"];
  EXPECT_EQ(s["axis_length"], "sqrt(2)");
  EXPECT_EQ(s["sliding_v_unit"], "-96/5*sqrt(2)");
  EXPECT_EQ(s["sliding_v"], "-96/5");

  const test::CliRun dbl = test::run_cli({"check", diagonal, "--json", "--arith", "double"});
  ASSERT_EQ(dbl.code, 0) << dbl.err;
  const auto f = nlohmann::json::parse(dbl.out)["joints"]["D"];
  EXPECT_TRUE(f.contains("sliding_v_unit_bound"));
  EXPECT_TRUE(f.contains("sliding_a_unit_bound"));
  EXPECT_TRUE(f.contains("coriolis_bound"));
  EXPECT_NEAR(std::stod(f["sliding_v_unit"].get<std::string>()), -96.0 / 5 * std::sqrt(2.0), 1e-12);
}

TEST(SlidingText, StatesTheConventionAndTheCoriolisTerm) {
  const test::CliRun r = test::run_cli({"check", testing::mechanism_scene_path("inverted_slider_crank.yaml")});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("+ = the slider moves along +u"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("S          guide rocker, slider block, u = (-4/5, 3/5), |u| = 1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("sliding v 36/5 = 7.2"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Coriolis  (-432/625 = -0.6912, -576/625 = -0.9216)"), std::string::npos) << r.out;
  const std::string diagonal = ::testing::TempDir() + "sliding_text_axis11.yaml";
  std::ofstream(diagonal) << slider_crank("[1, 1]");
  const test::CliRun root = test::run_cli({"check", diagonal});
  ASSERT_EQ(root.code, 0) << root.err;
  EXPECT_NE(root.out.find("|u| = sqrt(2)"), std::string::npos) << root.out;
  EXPECT_NE(root.out.find("sliding v -96/5*sqrt(2) ≈ -27.1529004"), std::string::npos) << root.out;
}

}  // namespace
}  // namespace linkproof
