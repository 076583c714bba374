// Mechanism claims evaluated on the seed-001 four-bar, against its published answers
// (verify/scenes/mechanisms/seed001_fourbar.yaml): omega3 = -3/4, alpha3 = 63/160,
// A_P = (-629/16, -341/80), curvature centre of P's path (10923/1222, 17083/1222).
#include "mechanism/mechanism_data_claim.h"

#include <gtest/gtest.h>

#include "linkproof/io/mechanism_scene.h"
#include "support/temp_dir.h"

namespace linkproof {
namespace {

MechanismScene seed001() {
  return load_mechanism_scene(std::string(LINKPROOF_SOURCE_DIR) + "/verify/scenes/mechanisms/seed001_fourbar.yaml");
}

MechanismDataClaim claim(const std::string& lhs, const std::string& rhs, const MechanismScene& scene) {
  MechanismDataClaim c;
  c.info.id = "t";
  c.lhs = MechanismExpression::parse(lhs, ExpressionContext{"t.yaml", "claims[0].lhs", false});
  c.rhs = MechanismExpression::parse(rhs, ExpressionContext{"t.yaml", "claims[0].rhs", false});
  bind_mechanism_claim(c, scene);
  return c;
}

Verdict verdict_of(const std::string& lhs, const std::string& rhs, ClaimOutcome* out = nullptr) {
  const MechanismScene s = seed001();
  const MechanismSolution<Rational> truth = solve_mechanism_exact(s);
  const ClaimOutcome o = run_mechanism_claim(to_mechanism_claim(claim(lhs, rhs, s)), MechanismContext{s, truth});
  if (out) *out = o;
  return o.verdict;
}

TEST(MechanismDataClaim, PublishedValuesOfTheSeed001FourBar) {
  EXPECT_EQ(verdict_of("omega(\"3\")", "-3/4"), Verdict::Holds);
  EXPECT_EQ(verdict_of("omega(\"4\")", "7/20"), Verdict::Holds);
  EXPECT_EQ(verdict_of("alpha(\"3\")", "63/160"), Verdict::Holds);
  EXPECT_EQ(verdict_of("alpha(\"4\", \"3\")", "3109/800 - 63/160"), Verdict::Holds);
  EXPECT_EQ(verdict_of("acc(P, \"3\")", "vec(-629/16, -341/80)"), Verdict::Holds);
  EXPECT_EQ(verdict_of("centre(P, \"3\", \"1\")", "vec(10923/1222, 17083/1222)"), Verdict::Holds);
  EXPECT_EQ(verdict_of("pole(\"2\", \"1\")", "pos(O2)"), Verdict::Holds);
  EXPECT_EQ(verdict_of("pole(\"3\", \"2\")", "pos(A)"), Verdict::Holds);
}

TEST(MechanismDataClaim, AVectorClaimComparesBothComponents) {
  ClaimOutcome o;
  EXPECT_EQ(verdict_of("acc(P, \"3\")", "vec(-629/16, 0)", &o), Verdict::Fails);
  ASSERT_EQ(o.instances.size(), 2u);
  EXPECT_EQ(o.instances[0].label, "x");
  EXPECT_EQ(o.instances[0].verdict, Verdict::Holds);
  EXPECT_EQ(o.instances[1].verdict, Verdict::Fails);
}

TEST(MechanismDataClaim, UndefinedQuantitiesAreNamedNeverAPass) {
  ClaimOutcome o;
  EXPECT_EQ(verdict_of("pole(\"3\", \"3\")", "vec(0, 0)", &o), Verdict::Undefined);
  EXPECT_EQ(o.headline.undefined_quantity, "pole(\"3\", \"3\")");
  EXPECT_EQ(verdict_of("meet(pos(O2), pos(A), pos(O2) + vec(1, 1), pos(A) + vec(1, 1))", "vec(0, 0)", &o),
            Verdict::Undefined);
  EXPECT_NE(o.headline.reason.find("parallel"), std::string::npos);
  EXPECT_EQ(verdict_of("1/omega(\"1\")", "0", &o), Verdict::Undefined);
  EXPECT_EQ(o.headline.undefined_quantity, "omega(\"1\")");
  EXPECT_EQ(verdict_of("centre(O2, \"2\", \"1\")", "vec(0, 0)", &o), Verdict::Undefined);
}

TEST(MechanismDataClaim, CentreAtAConstructedPositionIsTheCentreOfThePointThere) {
  // At a joint's position it is centre(P, L, M); at a constructed point (the pole of 3 and 1
  // built by a meet) the point of 3 there has v = 0: a cusp, undefined, never a pass.
  EXPECT_EQ(verdict_of("centre_at(pos(P), \"3\", \"1\")", "centre(P, \"3\", \"1\")"), Verdict::Holds);
  EXPECT_EQ(verdict_of("centre_at(pos(P) + vec(0, 0), \"3\", \"1\")", "vec(10923/1222, 17083/1222)"), Verdict::Holds);
  EXPECT_EQ(verdict_of("centre_at(pos(B), \"3\", \"1\")", "centre(B, \"3\", \"1\")"), Verdict::Holds);
  EXPECT_EQ(verdict_of("centre_at(pos(B), \"3\", \"1\")", "centre(A, \"3\", \"1\")"), Verdict::Fails);
  ClaimOutcome o;
  EXPECT_EQ(verdict_of("centre_at(meet(pos(O2), pos(A), pos(O4), pos(B)), \"3\", \"1\")", "vec(0, 0)", &o),
            Verdict::Undefined);
  EXPECT_NE(o.headline.reason.find("v = 0"), std::string::npos) << o.headline.reason;
}

MechanismScene slider_scene(const std::string& axis) {
  std::string text = test::slurp(std::string(LINKPROOF_SOURCE_DIR) + "/verify/scenes/mechanisms/seed003_class3.yaml");
  const std::string old_axis = "at: [117.349, -26.785], axis: [1, 0]";
  text.replace(text.find(old_axis), old_axis.size(), "at: [117.349, -26.785], axis: " + axis);
  return parse_mechanism_scene(text, "class3.yaml");
}

Verdict slider_verdict(const MechanismScene& s, const std::string& lhs, const std::string& rhs) {
  const MechanismSolution<Rational> truth = solve_mechanism_exact(s);
  return run_mechanism_claim(to_mechanism_claim(claim(lhs, rhs, s)), MechanismContext{s, truth}).verdict;
}

TEST(MechanismDataClaim, AxisIsTheUnitDirectionOfTheGuideHoweverTheSceneWritesIt) {
  EXPECT_EQ(slider_verdict(slider_scene("[1, 0]"), "axis(D)", "vec(1, 0)"), Verdict::Holds);
  EXPECT_EQ(slider_verdict(slider_scene("[3, 0]"), "axis(D)", "vec(1, 0)"), Verdict::Holds);
  EXPECT_EQ(slider_verdict(slider_scene("[-2, 0]"), "axis(D)", "vec(1, 0)"), Verdict::Fails);
  // The slider's velocity lies along its fixed guide.
  EXPECT_EQ(slider_verdict(slider_scene("[3, 0]"), "cross(vel(C, \"4\"), axis(D))", "0"), Verdict::Holds);
  EXPECT_EQ(slider_verdict(slider_scene("[1, 0]"), "axis(H)", "vec(0, 1)"), Verdict::Holds);
  EXPECT_THROW(claim("axis(A)", "vec(1, 0)", seed001()), InputError);  // a revolute joint
}

TEST(MechanismDataClaim, UnknownNamesAreBadInputAtTheirColumn) {
  const MechanismScene s = seed001();
  try {
    claim("omega(\"3\")", "omega(coupler)", s);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "t.yaml:1:7");
    EXPECT_NE(e.problem().find("unknown link 'coupler'"), std::string::npos) << e.problem();
  }
  EXPECT_THROW(claim("sliding_v(A)", "0", s), InputError);  // a revolute joint
  EXPECT_THROW(claim("vx(pos(Q))", "0", s), InputError);    // no joint or point Q
}

}  // namespace
}  // namespace linkproof
