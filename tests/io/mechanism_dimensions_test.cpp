// Mechanism scenes given by dimensions (docs/mechanisms.md, "Mechanisms from dimensions"): each
// placement (`polar`, `dyad`, `slide`, `at: J`), in any order; unplaceable joints and dimension
// sets that do not assemble refused naming the joint and the miss distance; angles and rates
// with pi, deg, rad, rpm; which positions stay exact and which are rationalised, within what.
// Positions that are not rational are compared with an independent route: CLN's own long-float
// cos, sin, sqrt at 150 digits (the reader uses its own series in exact rationals).
#include <gtest/gtest.h>

#include <cln/float.h>
#include <cln/real.h>

#include <algorithm>
#include <string>
#include <vector>

#include "linkproof/core/error.h"
#include "linkproof/io/mechanism_scene.h"
#include "mechanism/mechanism_catalogue.h"

namespace linkproof {
namespace {

const cln::float_format_t kDigits150 = cln::float_format(150);
cln::cl_F lf(const Rational& q) { return cln::cl_float(q, kDigits150); }
cln::cl_F lf(long n) { return cln::cl_float(cln::cl_I(n), kDigits150); }

// The independent route is good to about 1e-145; the reader's bound is what is tested.
bool within(const Rational& used, const cln::cl_F& truth, const Rational& bound) {
  return cln::abs(lf(used) - truth) <= lf(bound) + cln::cl_float(Rational(1) / cln::expt(Rational(10), 140), kDigits150);
}

const std::string kInputs = "  inputs:\n    - {link: \"2\", omega: 2, omega_dot: 5}\n";

// A four-bar O2-A-B-O4 (links 1 ground, 2 crank, 3 coupler, 4 rocker) with each joint's
// placement as given (the text after the links).
std::string fourbar(const std::string& o2, const std::string& a, const std::string& b, const std::string& o4,
                    const std::string& inputs = kInputs) {
  return "name: dims\nmechanism:\n  ground: \"1\"\n  joints:\n"
         "    - {name: O2, type: revolute, links: [\"1\", \"2\"], " + o2 + "}\n"
         "    - {name: A,  type: revolute, links: [\"2\", \"3\"], " + a + "}\n"
         "    - {name: B,  type: revolute, links: [\"3\", \"4\"], " + b + "}\n"
         "    - {name: O4, type: revolute, links: [\"4\", \"1\"], " + o4 + "}\n" + inputs;
}

// A slider-crank: O2 (ground-crank), A (crank-rod), B (rod-slider), D (the slider on the
// ground, prismatic) with their placements.
std::string slider_crank(const std::string& a, const std::string& b, const std::string& d,
                         const std::string& inputs = kInputs) {
  return "name: slider\nmechanism:\n  ground: \"1\"\n  joints:\n"
         "    - {name: O2, type: revolute, links: [\"1\", \"2\"], at: [0, 0]}\n"
         "    - {name: A,  type: revolute, links: [\"2\", \"3\"], " + a + "}\n"
         "    - {name: B,  type: revolute, links: [\"3\", \"4\"], " + b + "}\n"
         "    - {name: D,  type: prismatic, links: [\"1\", \"4\"], " + d + "}\n" + inputs;
}

MechanismScene parse(const std::string& text) { return parse_mechanism_scene(text, "dims.yaml"); }

// "field: problem" of the InputError the scene gives, or "" if none.
std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "dims.yaml");
    return e.field() + ": " + e.problem();
  }
  return "";
}

const LinkageJoint& joint(const MechanismScene& s, const std::string& name) { return s.linkage.joint(*s.linkage.find_joint(name)); }
const GivenValue& given(const MechanismScene& s, const std::string& name) {
  return s.placement.joints[static_cast<size_t>(*s.linkage.find_joint(name))];
}
bool same_point(const Vec2<Rational>& p, const Vec2<Rational>& q) { return p.x == q.x && p.y == q.y; }

const Rational kBound60 = Rational(1) / cln::expt(Rational(10), 58);  // 60 digits below a scale of 11..120

// --- polar

TEST(MechanismDimensions, PolarPlacesAtTheLengthAndAbsoluteAngle) {
  // A at distance 5 from O2, at 30 degrees: (5 cos 30deg, 5/2); sin 30deg = 1/2 is rational,
  // cos 30deg = sqrt(3)/2 is not.
  const MechanismScene s = parse(fourbar("at: [0, 0]", "polar: {from: O2, length: 5, angle: 30deg}",
                                         "dyad: {from: [A, 9], to: [O4, 10], side: left}", "at: [11, 0]"));
  const LinkageJoint& a = joint(s, "A");
  const GivenValue& g = given(s, "A");
  EXPECT_EQ(g.given_by, "polar");
  EXPECT_FALSE(g.exact);
  EXPECT_TRUE(cln::plusp(g.bound));
  EXPECT_LE(g.bound, kBound60);
  EXPECT_EQ(a.at.y, Rational(5) / 2);  // the rational coordinate is kept exactly
  EXPECT_TRUE(within(a.at.x, lf(5) * cln::sqrt(lf(3)) / 2, g.bound));
  // B is placed from A's enclosure: also rationalised, and 9 from A, 10 from O4 within the bounds.
  EXPECT_FALSE(given(s, "B").exact);
}

TEST(MechanismDimensions, PolarAtRightAnglesWithRationalLengthStaysExact) {
  for (const std::string angle : {"0deg", "0", "90deg", "pi/2", "180deg", "-270deg", "2*pi", "1/2*pi rad"}) {
    SCOPED_TRACE(angle);
    const MechanismScene s = parse(fourbar("at: [0, 0]", "polar: {from: O2, length: 4, angle: \"" + angle + "\"}",
                                           "at: [7, 6]", "at: [11, 0]"));
    EXPECT_TRUE(given(s, "A").exact);
    EXPECT_EQ(given(s, "A").bound, 0);
    const Vec2<Rational> a = joint(s, "A").at;
    EXPECT_TRUE(same_point(a, {4, 0}) || same_point(a, {0, 4}) || same_point(a, {-4, 0}))
        << format_rational(a.x) << ", " << format_rational(a.y);
  }
}

TEST(MechanismDimensions, PolarAtOneRadianMatchesAnIndependentCosAndSin) {
  const MechanismScene s = parse(fourbar("at: [0, 0]", "polar: {from: O2, length: 5, angle: 1rad}",
                                         "at: [7, 6]", "at: [11, 0]"));
  const GivenValue& g = given(s, "A");
  ASSERT_FALSE(g.exact);
  EXPECT_TRUE(within(joint(s, "A").at.x, lf(5) * cln::cos(lf(1)), g.bound));
  EXPECT_TRUE(within(joint(s, "A").at.y, lf(5) * cln::sin(lf(1)), g.bound));
}

TEST(MechanismDimensions, AnglesInDegreesRadiansAndPiGiveTheSamePosition) {
  const auto a_at = [](const std::string& angle) {
    return joint(parse(fourbar("at: [0, 0]", "polar: {from: O2, length: 5, angle: \"" + angle + "\"}", "at: [7, 6]",
                               "at: [11, 0]")),
                 "A")
        .at;
  };
  const Vec2<Rational> ref = a_at("30deg");
  for (const std::string same : {"pi/6", "1/6*pi", "pi*30/180", "-330deg", "390deg", "pi / 6 rad", "0.5*pi/3"})
    EXPECT_TRUE(same_point(a_at(same), ref)) << same;
  // Plain radians: the rational 0.5235987755982988730771 is not pi/6, but within 1e-22 of it.
  const Vec2<Rational> plain = a_at("0.5235987755982988730771");
  EXPECT_LT(cln::abs(plain.x - ref.x), Rational(1) / cln::expt(Rational(10), 21));
  EXPECT_FALSE(same_point(plain, ref));
}

// --- dyad

TEST(MechanismDimensions, DyadPlacesLeftOrRightOfTheDirectedLine) {
  // The seed-001 four-bar: B = (11, 10) is 10 from A = (3, 4) and 10 from O4 = (11, 0), on the
  // left of A -> O4; the right one is its mirror image in the line A O4, also rational.
  const MechanismScene left = parse(fourbar("at: [0, 0]", "at: [3, 4]", "dyad: {from: [A, 10], to: [O4, 10], side: left}",
                                            "at: [11, 0]"));
  EXPECT_TRUE(given(left, "B").exact);
  EXPECT_TRUE(same_point(joint(left, "B").at, {11, 10}));
  const MechanismScene right = parse(fourbar("at: [0, 0]", "at: [3, 4]",
                                             "dyad: {from: [A, 10], to: [O4, 10], side: right}", "at: [11, 0]"));
  const Vec2<Rational> b = joint(right, "B").at;
  EXPECT_TRUE(given(right, "B").exact);
  EXPECT_EQ(norm2(b - Vec2<Rational>{3, 4}), 100);
  EXPECT_EQ(norm2(b - Vec2<Rational>{11, 0}), 100);
  EXPECT_TRUE(cln::minusp(cross(Vec2<Rational>{8, -4}, b - Vec2<Rational>{3, 4})));  // right of A -> O4
  // Swapping from and to swaps the sides.
  const MechanismScene swapped = parse(fourbar("at: [0, 0]", "at: [3, 4]",
                                               "dyad: {from: [O4, 10], to: [A, 10], side: right}", "at: [11, 0]"));
  EXPECT_TRUE(same_point(joint(swapped, "B").at, {11, 10}));
}

TEST(MechanismDimensions, DyadWithIrrationalIntersectionIsRationalisedWithinItsBound) {
  // Circles of radius 8 about A = (3, 4) and 9 about O4 = (11, 0): the intersection on the left,
  // computed independently by the law of cosines.
  const MechanismScene s = parse(fourbar("at: [0, 0]", "at: [3, 4]", "dyad: {from: [A, 8], to: [O4, 9], side: left}",
                                         "at: [11, 0]"));
  const GivenValue& g = given(s, "B");
  ASSERT_FALSE(g.exact);
  EXPECT_LE(g.bound, kBound60);
  const cln::cl_F dx = lf(8), dy = lf(-4), d = cln::sqrt(dx * dx + dy * dy);
  const cln::cl_F cos_beta = (lf(64) + d * d - lf(81)) / (lf(16) * d);
  const cln::cl_F beta = cln::atan(cos_beta, cln::sqrt(lf(1) - cos_beta * cos_beta));
  const cln::cl_F direction = cln::atan(dx, dy) + beta;  // turned counter-clockwise: the left
  EXPECT_TRUE(within(joint(s, "B").at.x, lf(3) + lf(8) * cln::cos(direction), g.bound));
  EXPECT_TRUE(within(joint(s, "B").at.y, lf(4) + lf(8) * cln::sin(direction), g.bound));
}

TEST(MechanismDimensions, DyadThatMissesIsRefusedWithTheMissDistance) {
  // |A O4| = 10: radii 4 + 5 fall short by 1; radii 30 and 5 nest, short by 15.
  const std::string apart = error_of(fourbar("at: [0, 0]", "at: [3, 4]", "dyad: {from: [A, 4], to: [O4, 5], side: left}",
                                             "at: [11, -2]"));
  EXPECT_NE(apart.find("mechanism.joints[2].dyad: joint `B` cannot be placed"), std::string::npos) << apart;
  EXPECT_NE(apart.find("the dyad misses by 1"), std::string::npos) << apart;
  const std::string nested = error_of(fourbar("at: [0, 0]", "at: [3, 4]", "dyad: {from: [A, 30], to: [O4, 5], side: left}",
                                              "at: [11, -2]"));
  EXPECT_NE(nested.find("one lies inside the other"), std::string::npos) << nested;
  EXPECT_NE(nested.find("the dyad misses by 15"), std::string::npos) << nested;
  // An irrational miss is given to 6 digits: |A O4| = sqrt(80) = 8.94427..., radii 3 + 4.
  const std::string irrational = error_of(fourbar("at: [0, 0]", "at: [3, 4]",
                                                  "dyad: {from: [A, 3], to: [O4, 4], side: left}", "at: [11, 0]"));
  EXPECT_NE(irrational.find("misses by 1.94427"), std::string::npos) << irrational;
  const std::string concentric = error_of(fourbar("at: [0, 0]", "at: [3, 4]",
                                                  "dyad: {from: [A, 3], to: [A, 4], side: left}", "at: [11, 0]"));
  EXPECT_NE(concentric.find("concentric"), std::string::npos) << concentric;
}

TEST(MechanismDimensions, ATangentDyadIsExactWhenRationalAndUndecidableWhenNot) {
  // Rational data, circles touching: the one point where they meet, exactly (a dead centre).
  const MechanismScene touching = parse(fourbar("at: [0, 0]", "at: [3, 4]", "dyad: {from: [A, 4], to: [O4, 6], side: left}",
                                                "at: [11, -2]"));
  EXPECT_TRUE(given(touching, "B").exact);
  EXPECT_TRUE(same_point(joint(touching, "B").at, {Rational(3) + Rational(16) / 5, Rational(4) - Rational(12) / 5}));
  // The same touch with O4 placed at 30deg from A: |A O4| = 4 + 6 exactly, but A and O4 are
  // enclosures; no precision decides the sign of the discriminant, 0: refused, not guessed.
  const std::string e = error_of(fourbar("at: [0, 0]", "at: [3, 4]", "dyad: {from: [A, 4], to: [O4, 6], side: left}",
                                         "polar: {from: A, length: 10, angle: 30deg}"));
  EXPECT_NE(e.find("mechanism.joints[2].dyad: joint `B`: cannot decide whether the circles about `A` and `O4` meet"),
            std::string::npos)
      << e;
}

// --- slide and at: J

TEST(MechanismDimensions, SlidePicksTheIntersectionAheadOrBehind) {
  // The circle of radius 5 about A = (3, 4) meets the x-axis at x = 0 and x = 6.
  const auto b_of = [](const std::string& pick) {
    return joint(parse(slider_crank("at: [3, 4]", "slide: {line: [O2, 0deg], from: [A, 5], pick: " + pick + "}",
                                    "at: B, axis: [1, 0]")),
                 "B");
  };
  EXPECT_TRUE(same_point(b_of("ahead").at, {6, 0}));
  EXPECT_TRUE(same_point(b_of("behind").at, {0, 0}));
  // Along 180deg "ahead" is toward -x.
  const MechanismScene back = parse(slider_crank("at: [3, 4]", "slide: {line: [O2, 180deg], from: [A, 5], pick: ahead}",
                                                 "at: B, axis: [1, 0]"));
  EXPECT_TRUE(same_point(joint(back, "B").at, {0, 0}));
}

TEST(MechanismDimensions, SlideOnAnInclinedLineMatchesAnIndependentRoute) {
  // The line through O2 at 45deg, 13 from A = (3, 4): t = b + sqrt(b^2 - |A|^2 + 169), b = 7/sqrt(2).
  const MechanismScene s = parse(slider_crank("at: [3, 4]", "slide: {line: [O2, 45deg], from: [A, 13], pick: ahead}",
                                              "at: B, axis: 45deg"));
  const GivenValue& g = given(s, "B");
  ASSERT_FALSE(g.exact);
  const cln::cl_F b = lf(7) / cln::sqrt(lf(2)), t = b + cln::sqrt(b * b - lf(25) + lf(169));
  EXPECT_TRUE(within(joint(s, "B").at.x, t / cln::sqrt(lf(2)), g.bound));
  EXPECT_TRUE(within(joint(s, "B").at.y, t / cln::sqrt(lf(2)), g.bound));
  // D is at B (the same rational point), its axis an exactly unit rational vector near 45deg.
  EXPECT_TRUE(same_point(joint(s, "D").at, joint(s, "B").at));
  EXPECT_EQ(given(s, "D").given_by, "at joint");
  const Vec2<Rational> u = joint(s, "D").axis;
  EXPECT_EQ(norm2(u), 1);
  ASSERT_EQ(s.placement.axes.size(), 1u);
  EXPECT_FALSE(s.placement.axes[0].exact);
  EXPECT_TRUE(within(u.x, cln::sqrt(lf(2)) / 2, s.placement.axes[0].bound));
  EXPECT_TRUE(within(u.y, cln::sqrt(lf(2)) / 2, s.placement.axes[0].bound));
}

TEST(MechanismDimensions, SlideThatMissesIsRefusedWithTheMissDistance) {
  // A = (3, 4) is 4 from the x-axis: a rod of 3 misses it by 1.
  const std::string e = error_of(slider_crank("at: [3, 4]", "slide: {line: [O2, 0deg], from: [A, 3], pick: ahead}",
                                              "at: B, axis: [1, 0]"));
  EXPECT_NE(e.find("mechanism.joints[2].slide: joint `B` cannot be placed"), std::string::npos) << e;
  EXPECT_NE(e.find("passes 4 from `A`"), std::string::npos) << e;
  EXPECT_NE(e.find("misses the circle by 1"), std::string::npos) << e;
}

// --- order, references, cycles

TEST(MechanismDimensions, JointsMayBeListedInAnyOrder) {
  const std::vector<std::string> lines = {
      "    - {name: B,  type: revolute, links: [\"3\", \"4\"], dyad: {from: [A, 120], to: [O4, 80], side: left}}\n",
      "    - {name: A,  type: revolute, links: [\"2\", \"3\"], polar: {from: O2, length: 40, angle: 30deg}}\n",
      "    - {name: O2, type: revolute, links: [\"1\", \"2\"], at: [0, 0]}\n",
      "    - {name: O4, type: revolute, links: [\"4\", \"1\"], at: [100, 0]}\n",
      "    - {name: C,  type: revolute, links: [\"3\", \"5\"], at: B}\n"};
  const std::string tail = "    - {name: E,  type: revolute, links: [\"5\", \"1\"], at: [200, 0]}\n" + kInputs;
  std::vector<int> order = {0, 1, 2, 3, 4};
  std::optional<Vec2<Rational>> b, c;
  int permutations = 0;
  do {
    std::string text = "name: order\nmechanism:\n  ground: \"1\"\n  joints:\n";
    for (int k : order) text += lines[static_cast<size_t>(k)];
    const MechanismScene s = parse(text + tail);
    if (!b) b = joint(s, "B").at, c = joint(s, "C").at;
    EXPECT_TRUE(same_point(joint(s, "B").at, *b));
    EXPECT_TRUE(same_point(joint(s, "C").at, *c));
    ++permutations;
  } while (std::next_permutation(order.begin(), order.end()));
  EXPECT_EQ(permutations, 120);
  EXPECT_TRUE(same_point(*b, *c));
}

TEST(MechanismDimensions, AJointThatCannotBePlacedIsRefusedNamingIt) {
  // A cycle: A is placed from B, B from A.
  const std::string cycle = error_of(fourbar("at: [0, 0]", "polar: {from: B, length: 5, angle: 0}",
                                             "dyad: {from: [A, 10], to: [O4, 10], side: left}", "at: [11, 0]"));
  EXPECT_NE(cycle.find("cannot be placed from placed joints"), std::string::npos) << cycle;
  EXPECT_NE(cycle.find("A -> B -> A"), std::string::npos) << cycle;
  // A joint at itself.
  const std::string self = error_of(fourbar("at: [0, 0]", "at: A", "at: [11, 10]", "at: [11, 0]"));
  EXPECT_NE(self.find("mechanism.joints[1].at: joint `A` cannot be placed"), std::string::npos) << self;
  // An unknown reference names the field of the reference and the joint.
  const std::string unknown = error_of(fourbar("at: [0, 0]", "at: [3, 4]",
                                               "dyad: {from: [A, 10], to: [Q4, 10], side: left}", "at: [11, 0]"));
  EXPECT_NE(unknown.find("mechanism.joints[2].dyad.to[0]: unknown joint `Q4`: joint `B` is placed from it"),
            std::string::npos)
      << unknown;
}

// --- parsing: placements, angles, rates

TEST(MechanismDimensions, MalformedPlacementsAreRefusedNamingTheField) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {fourbar("at: [0, 0]", "at: [3, 4], polar: {from: O2, length: 5, angle: 0}", "at: [11, 10]", "at: [11, 0]"),
       "mechanism.joints[1].polar: the joint position is given twice, by `at` and by `polar`"},
      {fourbar("at: [0, 0]", "links: [\"2\", \"3\"]", "at: [11, 10]", "at: [11, 0]"), ""},  // duplicate key: YAML error
      {fourbar("at: [0, 0]", "polar: {from: O2, length: -5, angle: 0}", "at: [11, 10]", "at: [11, 0]"),
       "mechanism.joints[1].polar.length: expected a length > 0"},
      {fourbar("at: [0, 0]", "polar: {from: O2, length: 5}", "at: [11, 10]", "at: [11, 0]"),
       "mechanism.joints[1].polar.angle: missing required field"},
      {fourbar("at: [0, 0]", "polar: {from: O2, length: 5, angle: 0, side: left}", "at: [11, 10]", "at: [11, 0]"),
       "mechanism.joints[1].polar.side: unknown field"},
      {fourbar("at: [0, 0]", "polar: [O2, 5, 0]", "at: [11, 10]", "at: [11, 0]"),
       "mechanism.joints[1].polar: expected a map for `polar`"},
      {fourbar("at: [0, 0]", "at: [3, 4]", "dyad: {from: [A, 10], to: [O4, 10], side: up}", "at: [11, 0]"),
       "mechanism.joints[2].dyad.side: expected `left` or `right`"},
      {fourbar("at: [0, 0]", "at: [3, 4]", "dyad: {from: [A], to: [O4, 10], side: left}", "at: [11, 0]"),
       "mechanism.joints[2].dyad.from: expected [joint, length]"},
      {fourbar("at: [0, 0]", "at: [3, 4]", "dyad: {from: [A, 10], side: left}", "at: [11, 0]"),
       "mechanism.joints[2].dyad.to: expected [joint, length]"},
      {slider_crank("at: [3, 4]", "slide: {line: [O2, 0], from: [A, 5], pick: first}", "at: B, axis: [1, 0]"),
       "mechanism.joints[2].slide.pick: expected `ahead` or `behind`"},
      {slider_crank("at: [3, 4]", "slide: {line: O2, from: [A, 5], pick: ahead}", "at: B, axis: [1, 0]"),
       "mechanism.joints[2].slide.line: expected [joint, angle]"},
      {fourbar("at: [0, 0]", "name: X", "at: [11, 10]", "at: [11, 0]"), ""},  // duplicate key
      {"name: m\nmechanism:\n  ground: \"1\"\n  joints:\n    - {name: O2, type: revolute, links: [\"1\", \"2\"]}\n" + kInputs,
       "mechanism.joints[0].at: missing required field: the joint position [x, y]"},
  };
  for (const auto& [text, expected] : cases) {
    const std::string e = error_of(text);
    EXPECT_FALSE(e.empty()) << text;
    if (!expected.empty()) {
      EXPECT_NE(e.find(expected), std::string::npos) << "expected `" << expected << "` in `" << e << "`";
    }
  }
}

TEST(MechanismDimensions, BadAnglesAreRefusedNamingFieldAndProblem) {
  const auto angle_error = [](const std::string& angle) {
    return error_of(fourbar("at: [0, 0]", "polar: {from: O2, length: 5, angle: \"" + angle + "\"}", "at: [11, 10]",
                            "at: [11, 0]"));
  };
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"30 degrees", "unknown name `degrees` at character 4"},
      {"30grad", "unknown name `g` at character 3"},
      {"30rpm", "the unit `rpm` is for an angular velocity; an angle takes `deg`, `rad` or no unit"},
      {"pi/0", "division by zero at character 4"},
      {"2pi", "a missing `*` before `pi` at character 2"},
      {"pi*", "expected a number or `pi` at character 4, got the end"},
      {"deg", "a unit `deg` without a number"},
      {"1e5000deg", "exponent"},
      {"2e6", "beyond 1000000 rad"},
      {"1e7*pi", "beyond 1000000 rad"},
      {"3 + pi", "`+` at character 3: an angle or a rate is a product"},
      {"pi/6)", "expected `*`, `/` or the end at character 5, got `)`"},
      {"---------pi", "more than 8 signs in a row"},
  };
  for (const auto& [angle, expected] : cases) {
    const std::string e = angle_error(angle);
    EXPECT_NE(e.find("mechanism.joints[1].polar.angle: "), std::string::npos) << e;
    EXPECT_NE(e.find(expected), std::string::npos) << "angle `" << angle << "`: expected `" << expected << "` in `" << e << "`";
  }
  // Words that are not numbers keep the exact-number reader's messages.
  EXPECT_NE(angle_error(".nan").find("not finite"), std::string::npos);
}

TEST(MechanismDimensions, RatesInRpmAreRationalisedAndStated) {
  const std::string inputs = "  inputs:\n    - {link: \"2\", omega: -2000rpm, omega_dot: 100rpm/s}\n";
  const MechanismScene s = parse(fourbar("at: [0, 0]", "at: [3, 4]", "at: [11, 10]", "at: [11, 0]", inputs));
  ASSERT_EQ(s.placement.rates.size(), 2u);
  const GivenValue& w = s.placement.rates[0];
  EXPECT_EQ(w.subject, "inputs[0].omega");
  EXPECT_EQ(w.given_by, "-2000rpm");
  EXPECT_FALSE(w.exact);
  // -2000 rpm = -2000 * 2 pi / 60 rad/s = -200 pi / 3 (clockwise), 60 digits: within 1e-57.
  EXPECT_TRUE(within(s.inputs[0].rate, -lf(200) * cln::pi(kDigits150) / 3, w.bound));
  EXPECT_LE(w.bound, Rational(1) / cln::expt(Rational(10), 57));
  EXPECT_TRUE(within(s.inputs[0].rate_dot, lf(10) * cln::pi(kDigits150) / 3, s.placement.rates[1].bound));
  EXPECT_TRUE(s.placement.is_rationalised());
}

TEST(MechanismDimensions, RatesThatAreRationalStayExact) {
  // 60/pi rpm is exactly 2 rad/s; 0rpm is 0; a plain number is not an expression.
  const std::string inputs = "  inputs:\n    - {link: \"2\", omega: 60/pi rpm, omega_dot: 0rpm/s}\n";
  const MechanismScene s = parse(fourbar("at: [0, 0]", "at: [3, 4]", "at: [11, 10]", "at: [11, 0]", inputs));
  EXPECT_EQ(s.inputs[0].rate, 2);
  EXPECT_EQ(s.inputs[0].rate_dot, 0);
  ASSERT_EQ(s.placement.rates.size(), 2u);
  EXPECT_TRUE(s.placement.rates[0].exact);
  EXPECT_FALSE(s.placement.is_rationalised());
  const MechanismScene plain = parse(fourbar("at: [0, 0]", "at: [3, 4]", "at: [11, 10]", "at: [11, 0]"));
  EXPECT_TRUE(plain.placement.rates.empty());
  EXPECT_FALSE(plain.placement.is_dimensioned());
}

TEST(MechanismDimensions, BadRatesAreRefusedNamingFieldAndProblem) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"{link: \"2\", omega: 1500rpm/s, omega_dot: 0}", "mechanism.inputs[0].omega: expected an angular velocity"},
      {"{link: \"2\", omega: 1500rpm/s, omega_dot: 0}", "the unit `rpm/s` is for an angular acceleration"},
      {"{link: \"2\", omega: 2, omega_dot: 100rpm}", "mechanism.inputs[0].omega_dot: expected an angular acceleration"},
      {"{link: \"2\", omega: 1500 rev/min, omega_dot: 0}", "unknown name `rev`"},
      {"{link: \"2\", omega: 1500rmp, omega_dot: 0}", "unknown name `rmp`"},
  };
  for (const auto& [input, expected] : cases) {
    const std::string e = error_of(fourbar("at: [0, 0]", "at: [3, 4]", "at: [11, 10]", "at: [11, 0]",
                                           "  inputs:\n    - " + input + "\n"));
    EXPECT_NE(e.find(expected), std::string::npos) << "expected `" << expected << "` in `" << e << "`";
  }
  const std::string slider = error_of(slider_crank("at: [3, 4]", "at: [6, 0]", "at: B, axis: [1, 0]",
                                                   "  inputs:\n    - {joint: D, v: 1500rpm, a: 0}\n"));
  EXPECT_NE(slider.find("mechanism.inputs[0].v: expected a sliding rate"), std::string::npos) << slider;
  EXPECT_NE(slider.find("the unit `rpm` is for an angular velocity"), std::string::npos) << slider;
}

// --- declared dimensions, the writer

TEST(MechanismDimensions, DeclaredDimensionsOfRationalisedJointsHoldWithinTheBounds) {
  const std::string placed = fourbar("at: [0, 0]", "polar: {from: O2, length: 5, angle: 30deg}",
                                     "dyad: {from: [A, 9], to: [O4, 10], side: left}", "at: [11, 0]");
  const std::string declared = "  dimensions:\n    - {joints: [O2, A], length: 5}\n    - {joints: [A, B], length: 9}\n";
  EXPECT_EQ(error_of(placed + declared), "");
  const std::string wrong = error_of(placed + "  dimensions:\n    - {joints: [A, B], length: 9.000001}\n");
  EXPECT_NE(wrong.find("does not close at the given positions"), std::string::npos) << wrong;
  EXPECT_NE(wrong.find("plus the rationalisation of the positions"), std::string::npos) << wrong;
}

TEST(MechanismDimensions, TheWriterWritesTheRationalisedPositionsExactly) {
  const MechanismScene s = parse(slider_crank("polar: {from: O2, length: 50, angle: 60deg}",
                                              "slide: {line: [O2, 0deg], from: [A, 200], pick: ahead}",
                                              "at: B, axis: 0deg", "  inputs:\n    - {link: \"2\", omega: 1500rpm, omega_dot: 0}\n"));
  const MechanismScene back = parse_mechanism_scene(mechanism_scene_to_yaml(s), "back.yaml");
  for (int j = 0; j < s.linkage.joint_count(); ++j)
    EXPECT_TRUE(same_point(s.linkage.joint(j).at, back.linkage.joint(j).at)) << s.linkage.joint(j).name;
  EXPECT_EQ(s.inputs[0].rate, back.inputs[0].rate);
  EXPECT_FALSE(back.placement.is_dimensioned());  // what is written is the rationals, given exactly
}

}  // namespace
}  // namespace linkproof
