// Worked examples given by dimensions (lengths, angles, rpm), checked against closed forms
// computed here by a separate route: each mechanism's loop written as complex numbers and
// solved by hand (law of cosines for the position, 2x2 Cramer for the rates), evaluated with
// CLN's long floats at 150 digits. The engine solves the GiNaC loop closure exactly on the
// rationalised positions (docs/mechanisms.md, "Mechanisms from dimensions").
//
// Tolerance (kAgreement): the rationalised positions and rates are within 1e-58 of the
// dimensioned ones (asserted below from the scene's own bounds). omega and alpha are smooth
// functions of them; here their partial derivatives are below 1e8 per unit (omega2^2 < 5e4,
// lengths >= 40, transmission sines >= 1/2), so the engine's exact values move by less than
// 1e-49. 1e-40 relative leaves nine digits of room and still checks 40 digits; the closed forms
// themselves are good to about 1e-145.
#include <gtest/gtest.h>

#include <cln/float.h>
#include <cln/real.h>

#include "linkproof/io/mechanism_scene.h"
#include "mechanism/dimensioned_closed_forms.h"
#include "mechanism/mechanism_catalogue.h"

namespace linkproof {
namespace {

using testing::lf;
const cln::float_format_t kDigits150 = testing::kClosedFormDigits;
const Rational kAgreement = Rational(1) / cln::expt(Rational(10), 40);
const Rational kRationalised = Rational(1) / cln::expt(Rational(10), 58);

void expect_agrees(const Rational& engine, const cln::cl_F& closed_form, const std::string& what) {
  const cln::cl_F scale = cln::max(lf(1), cln::abs(closed_form));
  EXPECT_TRUE(cln::abs(lf(engine) - closed_form) <= lf(kAgreement) * scale)
      << what << ": engine " << cln::double_approx(engine) << ", closed form " << cln::double_approx(closed_form);
}

struct Solved {
  MechanismScene scene;
  MechanismSolution<Rational> truth;
  int link(const std::string& name) const { return *scene.linkage.find_link(name); }
  int joint(const std::string& name) const { return *scene.linkage.find_joint(name); }
  const Rational& omega(const std::string& l) const { return truth.motion.omega[static_cast<size_t>(link(l))]; }
  const Rational& alpha(const std::string& l) const { return truth.motion.omega_dot[static_cast<size_t>(link(l))]; }
};

Solved solve(const std::string& text) {
  MechanismScene s = parse_mechanism_scene(text, "worked.yaml");
  MechanismSolution<Rational> m = solve_mechanism_exact(s);
  return {std::move(s), std::move(m)};
}

void expect_rationalised_within(const MechanismScene& s, const Rational& bound) {
  for (const auto* list : {&s.placement.joints, &s.placement.axes, &s.placement.rates})
    for (const GivenValue& v : *list) EXPECT_LE(v.bound, bound) << v.subject;
}

// Crank-rocker four-bar: ground O2 O4 = 100 mm, crank 40, coupler 120, rocker 80; crank at 30
// degrees turning at 1500 rpm (counter-clockwise), alpha2 = 0; the open assembly (B left of A -> O4).
TEST(DimensionedWorkedExamples, FourBarAt30DegreesAnd1500RpmAgreesWithTheClosedForm) {
  const Solved r = solve(R"(name: fourbar-1500rpm
mechanism:
  ground: frame
  joints:
    - {name: O2, type: revolute, links: [frame, crank], at: [0, 0]}
    - {name: A,  type: revolute, links: [crank, coupler], polar: {from: O2, length: 40, angle: 30deg}}
    - {name: B,  type: revolute, links: [coupler, rocker], dyad: {from: [A, 120], to: [O4, 80], side: left}}
    - {name: O4, type: revolute, links: [rocker, frame], at: [100, 0]}
  inputs:
    - {link: crank, omega: 1500rpm, omega_dot: 0}
)");
  expect_rationalised_within(r.scene, kRationalised);
  EXPECT_TRUE(r.scene.placement.is_rationalised());
  // Closed form (mechanism/dimensioned_closed_forms.h).
  const cln::cl_F pi = cln::pi(kDigits150);
  const testing::FourBarClosedForm cf = testing::fourbar_closed_form(lf(40), lf(120), lf(80), lf(100), pi / 6,
                                                                     lf(1500) * lf(2) * pi / lf(60));
  const cln::cl_F &bx = cf.bx, &by = cf.by, &w3 = cf.w3, &w4 = cf.w4, &al3 = cf.al3, &al4 = cf.al4;
  const cln::cl_F w2 = lf(1500) * lf(2) * pi / lf(60);

  const Vec2<Rational>& B = r.scene.linkage.joint(r.joint("B")).at;
  const Rational bound = r.scene.placement.joints[static_cast<size_t>(r.joint("B"))].bound;
  EXPECT_LE(cln::abs(lf(B.x) - bx), lf(bound)) << "B.x";
  EXPECT_LE(cln::abs(lf(B.y) - by), lf(bound)) << "B.y";
  expect_agrees(r.omega("crank"), w2, "omega2 = 50 pi");
  expect_agrees(r.omega("coupler"), w3, "omega3");
  expect_agrees(r.omega("rocker"), w4, "omega4");
  expect_agrees(r.alpha("coupler"), al3, "alpha3");
  expect_agrees(r.alpha("rocker"), al4, "alpha4");
  // The values to 10 digits, for the reader of docs/mechanisms.md.
  EXPECT_NEAR(cln::double_approx(r.omega("coupler")), -41.19243417, 1e-8);
  EXPECT_NEAR(cln::double_approx(r.omega("rocker")), 19.12222162, 1e-8);
  EXPECT_NEAR(cln::double_approx(r.alpha("coupler")), 15886.11117, 1e-5);
  EXPECT_NEAR(cln::double_approx(r.alpha("rocker")), 26663.75776, 1e-5);
}

// Slider-crank: crank 50 mm at 60 degrees turning clockwise at 2000 rpm, connecting rod 200 mm,
// the slider on the line through O2 along +x (an in-line slider-crank).
TEST(DimensionedWorkedExamples, SliderCrankAt60DegreesAndMinus2000RpmAgreesWithTheClosedForm) {
  const Solved r = solve(R"(name: slider-crank
mechanism:
  ground: frame
  joints:
    - {name: O2, type: revolute, links: [frame, crank], at: [0, 0]}
    - {name: A,  type: revolute, links: [crank, rod], polar: {from: O2, length: 50, angle: 60deg}}
    - {name: B,  type: revolute, links: [rod, slider], slide: {line: [O2, 0deg], from: [A, 200], pick: ahead}}
    - {name: D,  type: prismatic, links: [frame, slider], at: B, axis: 0deg}
  inputs:
    - {link: crank, omega: -2000rpm, omega_dot: 0}
)");
  expect_rationalised_within(r.scene, kRationalised);
  // Closed form (mechanism/dimensioned_closed_forms.h).
  const cln::cl_F pi = cln::pi(kDigits150), w = lf(-2000) * lf(2) * pi / lf(60);
  const testing::SliderCrankClosedForm cf = testing::slider_crank_closed_form(lf(50), lf(200), pi / 3, w);
  const cln::cl_F &x = cf.x, &w3 = cf.w3, &al3 = cf.al3;

  const int B = r.joint("B"), D = r.joint("D");
  EXPECT_LE(cln::abs(lf(r.scene.linkage.joint(B).at.x) - x), lf(r.scene.placement.joints[static_cast<size_t>(B)].bound));
  EXPECT_EQ(r.scene.linkage.joint(B).at.y, 0);  // on the line: the y of the slide is exact
  const auto& m = r.truth.motion;
  expect_agrees(m.joint_v[static_cast<size_t>(B)].x, cf.v, "v_B");
  expect_agrees(m.slide[static_cast<size_t>(D)], cf.v, "sliding velocity of D");
  EXPECT_EQ(m.joint_v[static_cast<size_t>(B)].y, 0);
  expect_agrees(m.joint_a[static_cast<size_t>(B)].x, cf.a, "a_B");
  expect_agrees(m.slide_dot[static_cast<size_t>(D)], cf.a, "sliding acceleration of D");
  expect_agrees(r.omega("rod"), w3, "omega3");
  expect_agrees(r.alpha("rod"), al3, "alpha3");
  EXPECT_NEAR(cln::double_approx(m.joint_v[static_cast<size_t>(B)].x), 10230.16288, 1e-5);
  EXPECT_NEAR(cln::double_approx(m.joint_a[static_cast<size_t>(B)].x), -822711.7293, 1e-4);
}

// The course notes' four-bar (docs/conventions.md §B; verify/scenes/mechanisms/seed001_fourbar.yaml)
// given by its lengths: |O2 O4| = 11 along 0deg, |A B| = |B O4| = 10. Every position is rational,
// so nothing is rationalised and the printed answers come out exactly.
TEST(DimensionedWorkedExamples, CourseNotesFourBarByLengthsReproducesThePrintedValuesExactly) {
  const Solved r = solve(R"(name: seed001-by-lengths
mechanism:
  ground: "1"
  joints:
    - {name: B,  type: revolute, links: ["3", "4"], dyad: {from: [A, 10], to: [O4, 10], side: left}}
    - {name: O4, type: revolute, links: ["4", "1"], polar: {from: O2, length: 11, angle: 0deg}}
    - {name: O2, type: revolute, links: ["1", "2"], at: [0, 0]}
    - {name: A,  type: revolute, links: ["2", "3"], at: [3, 4]}
  inputs:
    - {link: "2", omega: 2, omega_dot: 5}
)");
  EXPECT_FALSE(r.scene.placement.is_rationalised());
  EXPECT_TRUE(r.scene.placement.is_dimensioned());
  EXPECT_EQ(r.omega("3"), Rational(-3) / 4);
  EXPECT_EQ(r.omega("4"), Rational(7) / 20);
  EXPECT_EQ(r.alpha("3"), Rational(63) / 160);
  EXPECT_EQ(r.alpha("4"), Rational(3109) / 800);
}

}  // namespace
}  // namespace linkproof
