// Euler-Savary and Bobillier on a mechanism with a slider (issue 27): Bobillier takes a prismatic
// pair's pole at infinity and a straight path's centre at infinity as pairs (docs/mechanisms.md,
// "Bobillier with sliders") and gives the analytic centre; where a claim has no value the
// undefined reason says which quantity and why (a relative translation has its pole at infinity).
#include <gtest/gtest.h>

#include <string>

#include "linkproof/io/mechanism_scene.h"
#include "mechanism/curvature_analysis.h"
#include "mechanism/mechanism_catalogue.h"

namespace linkproof {
namespace {

// The inverted slider-crank of verify/scenes/mechanisms/inverted_slider_crank.yaml with a tracer
// point Q on the block and curvature requests: the block's only revolute joint is A, its other
// pair the prismatic S on the rocker.
const char* kInvertedSliderCrank =
    "name: isc-curvature\nmechanism:\n  ground: frame\n  links: [frame, crank, block, rocker]\n  joints:\n"
    "    - {name: O2, type: revolute,  links: [frame, crank],  at: [0, 0]}\n"
    "    - {name: A,  type: revolute,  links: [crank, block],  at: [2, 3]}\n"
    "    - {name: S,  type: prismatic, links: [rocker, block], at: [2, 3], axis: [-4/5, 3/5]}\n"
    "    - {name: O4, type: revolute,  links: [rocker, frame], at: [6, 0]}\n"
    "  inputs:\n    - {link: crank, omega: 2, omega_dot: 1}\n"
    "  points: [{name: Q, link: block, at: [3, 5]}]\n"
    "curvature:\n"
    "  - {point: Q, moving: block, fixed: frame}\n"
    "  - {point: A, moving: block, fixed: rocker}\n";

const ClaimOutcome& claim(const CurvatureCheck& c, const std::string& id) {
  for (const auto& o : c.claims)
    if (o.info.id == id) return o;
  throw std::runtime_error("no claim " + id);
}

// The first undefined comparison of a claim.
const ComparisonOutcome& first_undefined(const ClaimOutcome& o) {
  for (const auto* list : {&o.instances, &o.terms})
    for (const auto& x : *list)
      if (x.verdict == Verdict::Undefined) return x;
  throw std::runtime_error("no undefined comparison in " + o.info.id);
}

// The comparison of a claim whose label starts with `prefix`.
const ComparisonOutcome& instance(const ClaimOutcome& o, const std::string& prefix) {
  for (const auto* list : {&o.instances, &o.terms})
    for (const auto& x : *list)
      if (x.label.rfind(prefix, 0) == 0) return x;
  throw std::runtime_error("no comparison " + prefix + " in " + o.info.id);
}

// Q on the block in block/frame: the pairs are A (centre O2, through the crank) and the prismatic
// S, whose pole block/rocker is the point at infinity along n = J u, with its centre on the
// rocker's return circle: the rocker turns about O4, so beta = O4. Bobillier's gamma is the
// analytic centre; the mirrored step (c) is not.
TEST(CurvatureOnSliders, BobillierWithThePrismaticPoleAtInfinityGivesTheAnalyticCentre) {
  const CurvatureCheck c = check_curvature(parse_mechanism_scene(kInvertedSliderCrank, "isc.yaml"), {});
  const ComparisonOutcome& q = instance(claim(c, "curvature.bobillier"), "Q in block/frame");
  EXPECT_EQ(q.verdict, Verdict::Holds) << q.label << ": " << q.reason;
  const ComparisonOutcome& m = instance(claim(c, "curvature.bobillier.mirrored_step_c"), "Q in block/frame");
  EXPECT_EQ(m.verdict, Verdict::Fails) << m.label;
}

// A in block/rocker: the relative motion is the translation along S itself; Bobillier has no
// second pair (S joins the two links of the motion) and says so.
TEST(CurvatureOnSliders, BobillierAcrossTheSlideItselfIsUndefinedNamingTheTranslation) {
  const CurvatureCheck c = check_curvature(parse_mechanism_scene(kInvertedSliderCrank, "isc.yaml"), {});
  const ClaimOutcome& b = claim(c, "curvature.bobillier");
  ASSERT_EQ(b.verdict, Verdict::Undefined);
  const ComparisonOutcome& u = first_undefined(b);
  EXPECT_NE(u.undefined_quantity.find("Bobillier's gamma of A in block/rocker"), std::string::npos) << u.undefined_quantity;
  EXPECT_NE(u.reason.find("prismatic joint S (links rocker and block: its links are the two of the motion: a relative "
                          "translation)"),
            std::string::npos)
      << u.reason;
  EXPECT_NE(u.reason.find("joint A (it is the requested point)"), std::string::npos) << u.reason;
}

// An offset slider-crank with a tracer C on the rod, C in rod/frame: the pairs are A (centre O2)
// and the slider's pin B, whose path is the straight guide: its centre is at infinity along the
// normal. (In-line with |O2 B| = 2 x_A the collineation axis is perpendicular to PB and the
// mirrored step (c) coincides: not a test of it.)
TEST(CurvatureOnSliders, BobillierWithACentreAtInfinityGivesTheAnalyticCentre) {
  const char* scene =
      "name: slider-crank-curvature\nmechanism:\n  ground: frame\n  links: [frame, crank, rod, slider]\n  joints:\n"
      "    - {name: O2, type: revolute,  links: [frame, crank], at: [0, 0]}\n"
      "    - {name: A,  type: revolute,  links: [crank, rod],   at: [3, 4]}\n"
      "    - {name: B,  type: revolute,  links: [rod, slider],  at: [15, -1]}\n"
      "    - {name: D,  type: prismatic, links: [frame, slider], at: [15, -1], axis: [1, 0]}\n"
      "  inputs:\n    - {link: crank, omega: 2, omega_dot: 1}\n"
      "  points: [{name: C, link: rod, at: [8, 2]}]\n"
      "curvature:\n  - {point: C, moving: rod, fixed: frame}\n";
  const CurvatureCheck c = check_curvature(parse_mechanism_scene(scene, "sc.yaml"), {});
  EXPECT_EQ(claim(c, "curvature.bobillier").verdict, Verdict::Holds);
  EXPECT_EQ(claim(c, "curvature.bobillier.mirrored_step_c").verdict, Verdict::Fails);
}

// The Geneva drive at a Pythagorean crank angle (every position exact) with a tracer Q on the
// crank, Q in crank/wheel: the pin P.pin runs along the slot, a straight path in the wheel (its
// centre at infinity), and O2 gives the other pair.
TEST(CurvatureOnSliders, BobillierOnTheGenevaSlotGivesTheAnalyticCentre) {
  const char* scene =
      "name: geneva-curvature\nmechanism:\n  ground: frame\n  links: [frame, crank, wheel]\n  joints:\n"
      "    - {name: O2, type: revolute, links: [frame, crank], at: [0, 0]}\n"
      "    - {name: O4, type: revolute, links: [wheel, frame], at: [100, 0]}\n"
      "    - {name: P,  type: slot,     links: [wheel, crank], at: [40, 30], axis: {from: O4}}\n"
      "  inputs:\n    - {link: crank, omega: 2, omega_dot: 1}\n"
      "  points: [{name: Q, link: crank, at: [20, 40]}]\n"
      "curvature:\n  - {point: Q, moving: crank, fixed: wheel}\n";
  const CurvatureCheck c = check_curvature(parse_mechanism_scene(scene, "geneva.yaml"), {});
  const ClaimOutcome& b = claim(c, "curvature.bobillier");
  EXPECT_EQ(b.verdict, Verdict::Holds) << (b.instances.empty() ? "" : b.instances[0].reason);
  EXPECT_EQ(claim(c, "curvature.bobillier.mirrored_step_c").verdict, Verdict::Fails);
}

TEST(CurvatureOnSliders, EulerSavaryAcrossAPrismaticPairNamesThePoleAtInfinity) {
  const CurvatureCheck c = check_curvature(parse_mechanism_scene(kInvertedSliderCrank, "isc.yaml"), {});
  const ClaimOutcome& rays = claim(c, "curvature.euler_savary.rays");
  // block/frame has a finite pole: its rays hold; block/rocker is a translation across S.
  ASSERT_EQ(rays.verdict, Verdict::Undefined);
  const ComparisonOutcome& u = first_undefined(rays);
  EXPECT_EQ(u.undefined_quantity, "P_block/rocker");
  EXPECT_NE(u.reason.find("the pole of block/rocker is at infinity in the direction"), std::string::npos) << u.reason;
  EXPECT_NE(u.reason.find("(the prismatic joint S between them)"), std::string::npos) << u.reason;
  for (const auto& x : rays.instances) {
    if (x.label.rfind("block/frame", 0) == 0) {
      EXPECT_EQ(x.verdict, Verdict::Holds) << x.label;
    }
  }
  EXPECT_EQ(claim(c, "curvature.euler_savary.bar_lines").verdict, Verdict::Holds);
  EXPECT_EQ(claim(c, "curvature.aronhold_kennedy").verdict, Verdict::Holds);
}

}  // namespace
}  // namespace linkproof
