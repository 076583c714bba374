// Poles, path curvature centres, Euler-Savary and the inflection circle (conventions §D).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "mechanism/curvature_analysis.h"
#include "linkproof/io/mechanism_scene.h"
#include "mechanism/curvature_support.h"
#include "mechanism/mechanism_catalogue.h"

namespace linkproof {
namespace {

using testing::mechanism_scene_path;
using PP = PlanePoint<Rational>;

Rational q(long p, long d = 1) { return Rational(p) / Rational(d); }

TEST(Curvature, CouplerPointCentreOfSeed001IsTheKnownAnswer) {
  const MechanismScene s = load_mechanism_scene(mechanism_scene_path("seed001_fourbar_curvature.yaml"));
  const CurvatureAnalysis a = analyse_curvature(s, solve_mechanism_exact(s));
  ASSERT_TRUE(a.centres[0].centre.is_finite());
  EXPECT_EQ(a.centres[0].centre.at.x, q(10923, 1222));
  EXPECT_EQ(a.centres[0].centre.at.y, q(17083, 1222));
}

TEST(Curvature, PointAtThePoleIsACuspWithUndefinedCentre) {
  const LinkField<Rational> m{q(2), q(1), {q(0), q(0)}, {q(1), q(3)}}, f{q(0), q(0), {q(0), q(0)}, {q(0), q(0)}};
  const PP pole = construct_pole(m, f, "P");
  ASSERT_TRUE(pole.is_finite());
  const PP c = construct_curvature_centre(pole.at, relative_point_motion(m, f, pole.at), "centre");
  EXPECT_EQ(c.kind, PP::Kind::Undefined);
  EXPECT_NE(c.reason.find("cusp"), std::string::npos);
}

TEST(Curvature, PointOnTheInflectionCircleHasItsCentreAtInfinity) {
  // Rotation about the origin with a_P = (4, 0), omega = 2: inflection pole W = (1, 0).
  const LinkField<Rational> m{q(2), q(0), {q(0), q(0)}, {q(4), q(0)}}, f{q(0), q(0), {q(0), q(0)}, {q(0), q(0)}};
  const auto circle = construct_inflection_circle(m, f, "P");
  ASSERT_TRUE(inflection_pole(circle).is_finite());
  EXPECT_EQ(circle.inflection.x, q(1));
  const Vec2<Rational> W = circle.inflection;
  EXPECT_EQ(construct_curvature_centre(W, relative_point_motion(m, f, W), "c").kind, PP::Kind::AtInfinity);
  const Vec2<Rational> on_circle{q(1, 2), q(1, 2)};  // on the circle with diameter PW
  EXPECT_EQ(construct_curvature_centre(on_circle, relative_point_motion(m, f, on_circle), "c").kind, PP::Kind::AtInfinity);
}

TEST(Curvature, EqualOmegaPutsThePoleAtInfinityPerpendicularToTheRelativeVelocity) {
  const LinkField<Rational> m{q(1), q(0), {q(3), q(0)}, {q(0), q(0)}}, f{q(1), q(0), {q(0), q(0)}, {q(0), q(0)}};
  const PP p = construct_pole(m, f, "P");
  ASSERT_EQ(p.kind, PP::Kind::AtInfinity);
  EXPECT_EQ(dot(p.at, Vec2<Rational>{q(3), q(0)}), q(0));
  EXPECT_EQ(construct_pole(f, f, "P").kind, PP::Kind::Undefined);
}

TEST(Curvature, CoriolisTermIsNeededWhenTheReferenceLinkMoves) {
  // A point fixed in the ground seen from a link rotating about the origin at omega = 1: it
  // circles the origin, so its centre is the origin; without the Coriolis term it would not be.
  const LinkField<Rational> ground{q(0), q(0), {q(0), q(0)}, {q(0), q(0)}}, spin{q(1), q(0), {q(0), q(0)}, {q(0), q(0)}};
  const Vec2<Rational> X{q(2), q(0)};
  const auto rel = relative_point_motion(ground, spin, X);
  const PP c = construct_curvature_centre(X, rel, "c");
  ASSERT_TRUE(c.is_finite());
  EXPECT_EQ(c.at.x, q(0));
  EXPECT_EQ(c.at.y, q(0));
  RelativePointMotion<Rational> no_coriolis{rel.v, ground.acceleration(X) - spin.acceleration(X)};
  const PP wrong = construct_curvature_centre(X, no_coriolis, "c");
  EXPECT_FALSE(wrong.is_finite() && cln::zerop(wrong.at.x) && cln::zerop(wrong.at.y));
}

// Random four-bars and eight-bars: every claim of the analysis has its expected verdict.
void expect_claims_as_expected(const MechanismScene& s) {
  const MechanismSolution<Rational> truth = testing::solve_or_discard(s);
  for (const LinkageJoint& j : s.linkage.joints())  // printed on failure: the configuration, exact
    RC_LOG() << j.name << " (" << format_rational(j.at.x) << ", " << format_rational(j.at.y) << ")\n";
  RC_LOG() << "input " << format_rational(s.inputs[0].rate) << ", " << format_rational(s.inputs[0].rate_dot) << "\n";
  const auto a = std::make_shared<const CurvatureAnalysis>(analyse_curvature(s, truth));
  // Two links without relative motion (a degenerate draw) leave a pole undefined.
  for (const PoleEntry& p : a->poles) RC_PRE(p.pole.kind != PP::Kind::Undefined);
  const MechanismContext ctx{s, truth};
  for (const MechanismClaim& c : curvature_claims(a)) {
    if (c.applies && !c.applies(ctx)) continue;
    const ClaimOutcome o = run_mechanism_claim(c, ctx);
    RC_LOG() << c.info.id << ": " << to_string(o.verdict) << " " << o.headline.label << " " << o.headline.undefined_quantity
             << " " << o.headline.reason << "\n";
    if (c.info.id == "curvature.aronhold_kennedy" || c.info.id == "curvature.joint_poles") {
      RC_ASSERT(o.verdict == Verdict::Holds);
    }
    RC_ASSERT(o.verdict != Verdict::Error);
    if (o.verdict == Verdict::Fails) RC_ASSERT(c.info.expected == Expectation::Fails);
  }
}

RC_GTEST_PROP(Curvature, AronholdKennedyAndEulerSavaryHoldOnRandomFourBars, ()) {
  MechanismScene s = random_scene(testing::fourbar_topology());
  s.curvature.push_back({"X", *testing::small_point(10), 2, 0});
  expect_claims_as_expected(s);
}

RC_GTEST_PROP(Curvature, AronholdKennedyHoldsForEveryTripleOfRandomEightBars, ()) {
  MechanismScene s = random_scene(testing::eightbar_topology());
  s.curvature.push_back({"X", *testing::small_point(10), 2, 4});
  expect_claims_as_expected(s);
}

}  // namespace
}  // namespace linkproof
