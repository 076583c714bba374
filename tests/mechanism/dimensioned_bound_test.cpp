// The bound on the distance between a rationalised scene's exact results and the results at its
// dimensioned values (mechanism/dimensioned_bound.h, MechanismCheck::dimensioned), against the
// independent closed forms of the two bundled dimension scenes at 150 digits
// (mechanism/dimensioned_closed_forms.h): the bound must contain the true distance, which is not
// zero (the rationals are not the dimensioned values), and must be lost without the starting
// radii.
#include <gtest/gtest.h>

#include <cln/float.h>
#include <cln/real.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "linkproof/io/mechanism_scene.h"
#include "linkproof/mechanism/mechanism_check.h"
#include "mechanism/dimensioned_bound.h"
#include "mechanism/dimensioned_closed_forms.h"
#include "mechanism/mechanism_test_support.h"
#include "exit_status.h"
#include "report/claims_status.h"
#include "report/mechanism_report.h"

namespace linkproof {
namespace {

using testing::lf;

constexpr double kSmall = 1e-50;  // the rationalisation is 1e-58 of the scale; sensitivities < 1e8

const DimensionedBound::Link& link_bound(const DimensionedBound& b, const std::string& name) {
  for (const auto& l : b.links)
    if (l.name == name) return l;
  throw std::runtime_error("no link bound " + name);
}
const DimensionedBound::Point& joint_bound(const DimensionedBound& b, const std::string& name) {
  for (const auto& p : b.joints)
    if (p.name == name) return p;
  throw std::runtime_error("no joint bound " + name);
}

Rational exact_of(const ResultNumber& x) { return testing::exact_value_of_result(x); }

/// |exact - closed form| (the distance to the dimensioned value, to 1e-145).
cln::cl_F distance(const Rational& exact, const cln::cl_F& closed_form) { return cln::abs(lf(exact) - closed_form); }

/// The bound holds the distance, which is not 0: a bound that only covered rounding would not.
void expect_contains(double bound, const Rational& exact, const cln::cl_F& closed_form, const std::string& what) {
  ASSERT_TRUE(std::isfinite(bound)) << what;
  const cln::cl_F d = distance(exact, closed_form);
  EXPECT_GT(d, lf(Rational(1) / cln::expt(Rational(10), 100))) << what << ": the rationals are the dimensioned values?";
  EXPECT_LE(d, lf(ScalarTraits<double>::to_rational(bound)))
      << what << ": distance " << cln::double_approx(d) << " > bound " << bound;
  EXPECT_LE(bound, kSmall) << what;
}

struct FourBar {
  MechanismScene scene = load_mechanism_scene(testing::mechanism_scene_path("dimensions_fourbar.yaml"));
  MechanismCheck check = check_mechanism(scene, Arithmetic::Exact);
  testing::FourBarClosedForm cf;
  FourBar() {
    const cln::cl_F pi = cln::pi(testing::kClosedFormDigits);
    cf = testing::fourbar_closed_form(lf(40), lf(120), lf(80), lf(100), pi / 6, lf(1500) * lf(2) * pi / lf(60));
  }
  Rational omega(const std::string& l) const { return exact_of(check.omega[*scene.linkage.find_link(l)]); }
  Rational alpha(const std::string& l) const { return exact_of(check.omega_dot[*scene.linkage.find_link(l)]); }
};

TEST(DimensionedBound, FourBarBoundIsSmallAndContainsTheClosedFormAtTheDimensionedValues) {
  const FourBar f;
  ASSERT_TRUE(f.check.dimensioned.has_value());
  const DimensionedBound& b = *f.check.dimensioned;
  ASSERT_TRUE(b.bounded) << b.reason;
  expect_contains(link_bound(b, "coupler").omega, f.omega("coupler"), f.cf.w3, "omega3");
  expect_contains(link_bound(b, "rocker").omega, f.omega("rocker"), f.cf.w4, "omega4");
  expect_contains(link_bound(b, "coupler").omega_dot, f.alpha("coupler"), f.cf.al3, "alpha3");
  expect_contains(link_bound(b, "rocker").omega_dot, f.alpha("rocker"), f.cf.al4, "alpha4");
  EXPECT_LE(b.omega, kSmall);
  EXPECT_LE(b.omega_dot, kSmall);
  EXPECT_LE(b.v, kSmall);
  EXPECT_LE(b.a, kSmall);
}

TEST(DimensionedBound, SliderCrankBoundIsSmallAndContainsTheClosedFormAtTheDimensionedValues) {
  const MechanismScene scene = load_mechanism_scene(testing::mechanism_scene_path("dimensions_slider_crank.yaml"));
  const MechanismCheck check = check_mechanism(scene, Arithmetic::Exact);
  const cln::cl_F pi = cln::pi(testing::kClosedFormDigits);
  const testing::SliderCrankClosedForm cf =
      testing::slider_crank_closed_form(lf(50), lf(200), pi / 3, lf(-2000) * lf(2) * pi / lf(60));
  ASSERT_TRUE(check.dimensioned.has_value());
  const DimensionedBound& b = *check.dimensioned;
  ASSERT_TRUE(b.bounded) << b.reason;
  const int rod = *scene.linkage.find_link("rod"), B = *scene.linkage.find_joint("B"), D = *scene.linkage.find_joint("D");
  expect_contains(link_bound(b, "rod").omega, exact_of(check.omega[static_cast<size_t>(rod)]), cf.w3, "omega3");
  expect_contains(link_bound(b, "rod").omega_dot, exact_of(check.omega_dot[static_cast<size_t>(rod)]), cf.al3, "alpha3");
  const auto& jb = check.joints[static_cast<size_t>(B)];
  expect_contains(joint_bound(b, "B").v, exact_of(jb.v[0]), cf.v, "v_B");
  expect_contains(joint_bound(b, "B").a, exact_of(jb.a[0]), cf.a, "a_B");
  // The slider D: sliding rates along the unit axis (the axis 0deg is exactly (1, 0)).
  const auto& jd = check.joints[static_cast<size_t>(D)];
  ASSERT_TRUE(jd.sliding.has_value());
  const DimensionedBound::Point& db = joint_bound(b, "D");
  ASSERT_TRUE(db.v_unit && db.a_unit && db.coriolis);
  expect_contains(*db.v_unit, exact_of(jd.sliding->v_unit), cf.v, "sliding v of D");
  expect_contains(*db.a_unit, exact_of(jd.sliding->a_unit), cf.a, "sliding a of D");
  EXPECT_LE(b.sliding_v, kSmall);
}

// Without the starting radii the same solve bounds only its own rounding (about 1e-98): it no
// longer holds the results at the dimensioned values. This is what the radii are for.
TEST(DimensionedBound, WithoutStartingRadiiTheBoundMissesTheDimensionedValues) {
  const FourBar f;
  StartingRadii zero = construct_starting_radii(f.scene);
  for (auto& r : zero.position) r = 0;
  for (auto& r : zero.axis) r = 0;
  for (auto& r : zero.input) r = {0, 0};
  const DimensionedBound b = compute_dimensioned_bound(f.scene, zero);
  ASSERT_TRUE(b.bounded);
  const double w3 = link_bound(b, "coupler").omega;
  EXPECT_GT(distance(f.omega("coupler"), f.cf.w3), lf(ScalarTraits<double>::to_rational(w3)))
      << "bound without radii " << w3 << " still contains the dimensioned omega3";
  // And with them (the scene's own) it does: the radii, not the precision, make the bound.
  const DimensionedBound with = compute_dimensioned_bound(f.scene, construct_starting_radii(f.scene));
  EXPECT_LE(distance(f.omega("coupler"), f.cf.w3), lf(ScalarTraits<double>::to_rational(link_bound(with, "coupler").omega)));
}

// The rationalised positions and the rate get radii; exact ones 0 (by name, per coordinate).
TEST(DimensionedBound, StartingRadiiAreTheRationalisationBounds) {
  const FourBar f;
  const StartingRadii r = construct_starting_radii(f.scene);
  const Linkage& g = f.scene.linkage;
  EXPECT_EQ(r.position[static_cast<size_t>(*g.find_joint("O2"))], 0);
  EXPECT_EQ(r.position[static_cast<size_t>(*g.find_joint("O4"))], 0);
  for (const GivenValue& v : f.scene.placement.joints)
    EXPECT_EQ(r.position[static_cast<size_t>(*g.find_joint(v.subject))], v.exact ? Rational(0) : v.bound) << v.subject;
  ASSERT_EQ(r.input.size(), 1u);
  EXPECT_GT(r.input[0].first, 0);   // 1500rpm = 50 pi rad/s
  EXPECT_EQ(r.input[0].second, 0);  // omega_dot: 0
}

// The Geneva pin's slot axis is {from: O4}: it moves with the rationalised pin, so it gets the
// pin's radius too.
TEST(DimensionedBound, SlotAxisFromAJointTakesTheRadiiOfBothJoints) {
  const MechanismScene s = load_mechanism_scene(testing::mechanism_scene_path("geneva.yaml"));
  const StartingRadii r = construct_starting_radii(s);
  const size_t P = static_cast<size_t>(*s.linkage.find_joint("P"));
  EXPECT_GT(r.position[P], 0);
  EXPECT_EQ(r.axis[P], r.position[P]);  // O4 is exact
  const MechanismCheck c = check_mechanism(s, Arithmetic::Exact);
  ASSERT_TRUE(c.dimensioned && c.dimensioned->bounded) << (c.dimensioned ? c.dimensioned->reason : "none");
  EXPECT_LE(c.dimensioned->omega, kSmall);
  EXPECT_LE(c.dimensioned->sliding_v, kSmall);
}

// A four-bar whose dimensions put coupler and rocker within 1e-64 of collinear (the circles of
// the dyad meet 1e-130 past tangency): every configuration within the rationalisation bounds of
// 1e-58 is not away from the toggle, so nothing is bounded, and the check says so.
TEST(DimensionedBound, NearADeadCentreTheBoundIsNotBoundedWithTheReason) {
  // L1 = |A O4| - 30 + 1e-130, truncated to 135 decimals (|A O4|^2 = 11600 - 4000 sqrt 3).
  const MechanismScene s = parse_mechanism_scene(R"(name: fourbar-near-toggle
mechanism:
  ground: frame
  joints:
    - {name: O2, type: revolute, links: [frame, crank], at: [0, 0]}
    - {name: A,  type: revolute, links: [crank, coupler], polar: {from: O2, length: 40, angle: 30deg}}
    - {name: B,  type: revolute, links: [coupler, rocker], dyad: {from: [A, 38.350543302335869771241147884104034325079625095374112908839554571949900212377391437468924635614249234163913701280134998322886886444341563], to: [O4, 30], side: left}}
    - {name: O4, type: revolute, links: [rocker, frame], at: [100, 0]}
  inputs:
    - {link: crank, omega: 1500rpm, omega_dot: 0}
)", "near_toggle.yaml");
  ASSERT_TRUE(s.placement.is_rationalised());
  const MechanismCheck c = check_mechanism(s, Arithmetic::Exact);
  ASSERT_TRUE(c.dimensioned.has_value());
  EXPECT_FALSE(c.dimensioned->bounded);
  EXPECT_FALSE(c.dimensioned->reason.empty());
  EXPECT_TRUE(std::isinf(c.dimensioned->omega)) << c.dimensioned->omega;
  const nlohmann::json j = to_json(c, cli::claims_status(c.claims));
  EXPECT_EQ(j["dimensioned_bound"]["bounded"], false);
  EXPECT_TRUE(j["dimensioned_bound"]["reason"].is_string());
}

// JSON: the key "dimensioned_bound" is added for a rationalised scene, every other key and value
// unchanged; an exact scene has no such key.
TEST(DimensionedBound, JsonAddsOneKeyAndChangesNoOther) {
  const FourBar f;
  const nlohmann::json with = to_json(f.check, cli::claims_status(f.check.claims));
  MechanismCheck plain = f.check;
  plain.dimensioned.reset();
  nlohmann::json without = to_json(plain, cli::claims_status(plain.claims));
  ASSERT_TRUE(with.contains("dimensioned_bound"));
  EXPECT_FALSE(without.contains("dimensioned_bound"));
  nlohmann::json stripped = with;
  stripped.erase("dimensioned_bound");
  EXPECT_EQ(stripped, without);
  const nlohmann::json& d = with["dimensioned_bound"];
  EXPECT_EQ(d["bounded"], true);
  EXPECT_TRUE(d["reason"].is_null());
  for (const char* k : {"omega", "omega_dot", "v", "a", "sliding_v", "sliding_a"}) EXPECT_TRUE(d["summary"].contains(k)) << k;
  EXPECT_TRUE(d["links"]["coupler"].contains("omega"));
  EXPECT_TRUE(d["joints"]["B"].contains("v"));
  // Each bound reads back to at least the bound.
  EXPECT_GE(std::stod(d["links"]["coupler"]["omega"].get<std::string>()), link_bound(*f.check.dimensioned, "coupler").omega);

  const MechanismScene exact = load_mechanism_scene(testing::mechanism_scene_path("seed001_fourbar.yaml"));
  const MechanismCheck e = check_mechanism(exact, Arithmetic::Exact);
  EXPECT_FALSE(e.dimensioned.has_value());
  EXPECT_FALSE(to_json(e, cli::claims_status(e.claims)).contains("dimensioned_bound"));
}

}  // namespace
}  // namespace linkproof
