// A slot joint (a pin of one link in a straight slot of another) and the Geneva drive written
// with one (verify/scenes/mechanisms/geneva.yaml), against the closed-form Geneva kinematics
// computed here by hand.
//
// Closed form. Crank (driver) about O2 = (0, 0) with radius a and angle phi from the line of
// centres, wheel about O4 = (c, 0), pin P = a (cos phi, sin phi) = (x, y) in a radial slot. The
// textbook's wheel angle theta (clockwise from the line of centres, seen from O4) satisfies
// tan theta = a sin phi / (c - a cos phi); differentiating with a constant,
//   theta-dot  = omega a (c cos phi - a) / D,            D = a^2 + c^2 - 2 a c cos phi = |P - O4|^2
//   theta-ddot = -omega^2 a c sin phi (c^2 - a^2) / D^2 + omega-dot a (c cos phi - a) / D.
// linkproof's omega is counter-clockwise: omega_wheel = -theta-dot, alpha_wheel = -theta-ddot. With
// a cos phi = x, a sin phi = y, a^2 = x^2 + y^2 everything is rational in x, y, c, omega: the hand
// values are exact for the very rationals the engine runs on, rationalised or not. The pin slides
// outward along the slot at R-dot = d|P - O4|/dt = c y omega / sqrt(D).
#include <cln/real.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

#include "linkproof/core/error.h"
#include "linkproof/io/mechanism_scene.h"
#include "linkproof/mechanism/mechanism_check.h"
#include "mechanism/mechanism_test_support.h"
#include "exit_status.h"
#include "report/claims_status.h"
#include "report/mechanism_report.h"

namespace linkproof {
namespace {

struct GenevaHand {
  Rational omega_wheel, alpha_wheel, sigma_dot;  ///< sigma-dot: per unit of u = P - O4
};

GenevaHand geneva_by_hand(const Vec2<Rational>& pin, const Rational& c, const Rational& omega, const Rational& omega_dot) {
  const Rational x = pin.x, y = pin.y, a2 = x * x + y * y;
  const Rational D = a2 + c * c - 2 * c * x;
  const Rational theta_dot = omega * (c * x - a2) / D;
  const Rational theta_ddot = -omega * omega * c * y * (c * c - a2) / (D * D) + omega_dot * (c * x - a2) / D;
  // R-dot / |u| with |u| = sqrt(D): c y omega / D.
  return {-theta_dot, -theta_ddot, c * y * omega / D};
}

size_t link_index(const MechanismCheck& c, const std::string& name) {
  for (size_t k = 0; k < c.link_names.size(); ++k)
    if (c.link_names[k] == name) return k;
  throw std::runtime_error("no link " + name);
}

const MechanismCheck::PointMotion& joint_named(const MechanismCheck& c, const std::string& name) {
  for (const auto& p : c.joints)
    if (p.name == name) return p;
  throw std::runtime_error("no joint " + name);
}

Rational exact(const ResultNumber& x) { return std::get<Rational>(x); }

// The six-slot Geneva at a Pythagorean crank angle (cos phi = 4/5): every position exact.
const char* kExactGeneva =
    "name: geneva-exact\nmechanism:\n  ground: frame\n  links: [frame, crank, wheel]\n  joints:\n"
    "    - {name: O2, type: revolute, links: [frame, crank], at: [0, 0]}\n"
    "    - {name: O4, type: revolute, links: [wheel, frame], at: [100, 0]}\n"
    "    - {name: P, type: slot, links: [wheel, crank], at: [40, 30], axis: {from: O4}}\n"
    "  inputs:\n    - {link: crank, omega: 2, omega_dot: 0}\n";

TEST(SlotJoint, IsAPrismaticPairWithAHiddenBlockAndAPin) {
  const MechanismScene s = parse_mechanism_scene(kExactGeneva, "geneva.yaml");
  const Linkage& g = s.linkage;
  ASSERT_TRUE(g.find_link("P.block").has_value());
  const LinkageJoint& slot = g.joint(*g.find_joint("P"));
  EXPECT_EQ(slot.type, JointType::Prismatic);
  EXPECT_EQ(g.link_name(slot.links[0]), "wheel");  // the slotted link is the guide
  EXPECT_EQ(g.link_name(slot.links[1]), "P.block");
  EXPECT_EQ(slot.axis.x, -60);  // from O4 to the pin
  EXPECT_EQ(slot.axis.y, 30);
  const LinkageJoint& pin = g.joint(*g.find_joint("P.pin"));
  EXPECT_EQ(pin.type, JointType::Revolute);
  EXPECT_EQ(g.link_name(pin.links[0]), "P.block");
  EXPECT_EQ(g.link_name(pin.links[1]), "crank");
  EXPECT_EQ(pin.at.x, 40);
  EXPECT_EQ(pin.at.y, 30);
  const MechanismCheck c = check_mechanism(s, Arithmetic::Exact);
  EXPECT_EQ(c.mobility, 1);
  EXPECT_EQ(c.grubler, 1);
  // The block turns with the slotted wheel.
  EXPECT_EQ(exact(c.omega[link_index(c, "P.block")]), exact(c.omega[link_index(c, "wheel")]));
}

TEST(GenevaDrive, ExactWheelRatesMatchTheClosedForm) {
  const MechanismCheck c = check_mechanism(parse_mechanism_scene(kExactGeneva, "geneva.yaml"), Arithmetic::Exact);
  const GenevaHand h = geneva_by_hand({40, 30}, 100, 2, 0);
  const size_t wheel = link_index(c, "wheel");
  EXPECT_EQ(exact(c.omega[wheel]), h.omega_wheel);
  EXPECT_EQ(exact(c.omega_dot[wheel]), h.alpha_wheel);
  // By hand with numbers: D = 2500 + 10000 - 8000 = 4500; omega 2 (2500 - 4000) / 4500 = -2/3;
  // alpha = 4 * 100 * 30 * 7500 / 4500^2 = 40/9.
  EXPECT_EQ(h.omega_wheel, Rational(-2) / 3);
  EXPECT_EQ(h.alpha_wheel, Rational(40) / 9);
  // The pin slides outward at R-dot = c y omega / sqrt(D) = 6000 / (30 sqrt(5)) = 40 sqrt(5):
  // along u = (-60, 30), |u| = 30 sqrt(5), sigma-dot = 4/3, and along the unit axis 40 * sqrt(5).
  const auto& p = joint_named(c, "P");
  EXPECT_EQ(exact(*p.slide), h.sigma_dot);
  EXPECT_EQ(h.sigma_dot, Rational(4) / 3);
  ASSERT_TRUE(p.sliding.has_value());
  EXPECT_EQ(p.sliding->axis_length, 30);
  EXPECT_EQ(p.sliding->axis_radicand, 5);
  EXPECT_EQ(exact(p.sliding->v_unit), 40);
  EXPECT_EQ(p.sliding->rate_radicand, 5);
  // Coriolis 2 omega_wheel sigma-dot J u = 2 (-2/3)(4/3) (-30, -60) = (160/3, 320/3).
  EXPECT_EQ(exact(p.sliding->coriolis[0]), Rational(160) / 3);
  EXPECT_EQ(exact(p.sliding->coriolis[1]), Rational(320) / 3);
}

TEST(GenevaDrive, TextbookSceneMatchesTheClosedFormOnItsRationalsAndInDecimals) {
  const MechanismScene s = load_mechanism_scene(testing::mechanism_scene_path("geneva.yaml"));
  const Linkage& g = s.linkage;
  const Vec2<Rational> pin = g.joint(*g.find_joint("P")).at, O2 = g.joint(*g.find_joint("O2")).at,
                       O4 = g.joint(*g.find_joint("O4")).at;
  ASSERT_EQ(O2.x, 0);
  ASSERT_EQ(O2.y, 0);
  ASSERT_EQ(O4.y, 0);
  EXPECT_TRUE(s.placement.is_rationalised());  // 30deg and 100rpm are not rational
  const MechanismCheck c = check_mechanism(s, Arithmetic::Exact);
  const GenevaHand h = geneva_by_hand(pin, O4.x, s.inputs[0].rate, s.inputs[0].rate_dot);
  const size_t wheel = link_index(c, "wheel");
  // Exact for the rationals the engine ran on.
  EXPECT_EQ(exact(c.omega[wheel]), h.omega_wheel);
  EXPECT_EQ(exact(c.omega_dot[wheel]), h.alpha_wheel);
  // And the textbook's numbers: a = 50, c = 100, phi = 30deg, 100 rpm, from the closed form in
  // long double (the rationalisation is within 1e-58; long double carries about 19 digits).
  const long double a = 50, cc = 100, phi = std::numbers::pi_v<long double> / 6,
                    w = 100 * 2 * std::numbers::pi_v<long double> / 60;
  const long double D = a * a + cc * cc - 2 * a * cc * std::cos(phi);
  const long double omega_wheel = w * a * (a - cc * std::cos(phi)) / D;
  const long double alpha_wheel = w * w * a * cc * std::sin(phi) * (cc * cc - a * a) / (D * D);
  EXPECT_NEAR(cln::double_approx(exact(c.omega[wheel])), static_cast<double>(omega_wheel), 1e-12);
  EXPECT_NEAR(cln::double_approx(exact(c.omega_dot[wheel])), static_cast<double>(alpha_wheel), 1e-10);
  EXPECT_NEAR(static_cast<double>(omega_wheel), -4.991227418384041, 1e-12);
  EXPECT_NEAR(static_cast<double>(alpha_wheel), 139.46124029707093, 1e-10);
}

TEST(GenevaDrive, MustFailAWrongClosedFormIsNotTheEngineValue) {
  // The closed form with the sign of its omega-dot-free term flipped (theta-ddot for alpha,
  // the textbook's clockwise angle taken as counter-clockwise) is not what the engine reports.
  const MechanismCheck c = check_mechanism(parse_mechanism_scene(kExactGeneva, "geneva.yaml"), Arithmetic::Exact);
  const GenevaHand h = geneva_by_hand({40, 30}, 100, 2, 0);
  EXPECT_NE(exact(c.omega_dot[link_index(c, "wheel")]), -h.alpha_wheel);
  EXPECT_NE(exact(c.omega[link_index(c, "wheel")]), -h.omega_wheel);
}

TEST(SlotJoint, ASlotOverAnExistingBlockNameIsRefused) {
  std::string text = kExactGeneva;
  text.replace(text.find("links: [frame, crank, wheel]"), 28, "links: [frame, crank, wheel, P.block]");
  try {
    parse_mechanism_scene(text, "geneva.yaml");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "mechanism.joints[2].name");
    EXPECT_NE(e.problem().find("needs the link name `P.block`"), std::string::npos) << e.problem();
  }
}

TEST(SlotJoint, SceneWriterRoundTripsTheDesugaredSlot) {
  const MechanismScene s = parse_mechanism_scene(kExactGeneva, "geneva.yaml");
  const MechanismScene back = parse_mechanism_scene(mechanism_scene_to_yaml(s), "geneva.yaml");
  const MechanismCheck a = check_mechanism(s, Arithmetic::Exact), b = check_mechanism(back, Arithmetic::Exact);
  EXPECT_EQ(exact(a.omega[link_index(a, "wheel")]), exact(b.omega[link_index(b, "wheel")]));
  EXPECT_EQ(exact(a.omega_dot[link_index(a, "wheel")]), exact(b.omega_dot[link_index(b, "wheel")]));
}

// The lines of `text` that start with `prefix`.
std::vector<std::string> lines_starting(const std::string& text, const std::string& prefix) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(prefix, 0) == 0) out.push_back(line);
  return out;
}

// The slot is one joint in `check`'s text: no row for the block link P.block or the pin joint
// P.pin, P's row and its sliding section say what it is, with the sliding rates and the Coriolis
// term; the JSON keeps its existing keys and adds `slots`.
TEST(SlotJoint, CheckTextShowsTheSlotAsOneJointWithoutItsBlockRow) {
  const MechanismScene s = load_mechanism_scene(testing::mechanism_scene_path("geneva.yaml"));
  const MechanismCheck c = check_mechanism(s, Arithmetic::Exact);
  ASSERT_EQ(c.slots.size(), 1u);
  EXPECT_EQ(c.slots[0].block, "P.block");
  EXPECT_EQ(c.slots[0].pin_link, "crank");
  std::ostringstream out;
  write_text(out, c, cli::claims_status(c.claims));
  const std::string text = out.str();
  EXPECT_TRUE(lines_starting(text, "P.block ").empty()) << text;
  EXPECT_TRUE(lines_starting(text, "P.pin ").empty()) << text;
  const std::vector<std::string> p = lines_starting(text, "P ");
  ASSERT_EQ(p.size(), 2u) << text;  // the joint row and the sliding section's first line
  EXPECT_NE(p[0].find("(pin of crank in a slot of wheel; its sliding rates below)"), std::string::npos) << p[0];
  EXPECT_NE(p[1].find("pin of crank in a slot of wheel, u = "), std::string::npos) << p[1];
  EXPECT_NE(text.find("sliding v "), std::string::npos);
  EXPECT_NE(text.find("sliding a "), std::string::npos);
  EXPECT_NE(text.find("Coriolis  ("), std::string::npos);
  EXPECT_FALSE(lines_starting(text, "wheel ").empty());
  const nlohmann::json j = to_json(c, cli::claims_status(c.claims));
  EXPECT_TRUE(j["links"].contains("P.block"));  // existing keys stay
  EXPECT_TRUE(j["joints"].contains("P.pin"));
  EXPECT_EQ(j["slots"]["P"]["slotted"], "wheel");
  EXPECT_EQ(j["slots"]["P"]["pin_link"], "crank");
}

}  // namespace
}  // namespace linkproof
