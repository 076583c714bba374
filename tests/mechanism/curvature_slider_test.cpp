// Euler-Savary and Bobillier on a mechanism with a slider (issue 27): where a claim has no value
// the undefined reason says which quantity and which pair (a prismatic pair is a pole at
// infinity); where it has one (Euler-Savary with a finite pole) it holds.
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

TEST(CurvatureOnSliders, BobillierUndefinedReasonNamesThePrismaticPairAndThePairsFound) {
  const CurvatureCheck c = check_curvature(parse_mechanism_scene(kInvertedSliderCrank, "isc.yaml"), {});
  const ClaimOutcome& b = claim(c, "curvature.bobillier");
  ASSERT_EQ(b.verdict, Verdict::Undefined);
  const ComparisonOutcome& u = first_undefined(b);
  EXPECT_NE(u.undefined_quantity.find("Bobillier's gamma of Q in block/frame"), std::string::npos) << u.undefined_quantity;
  EXPECT_NE(u.reason.find("bars joining block and frame: crank"), std::string::npos) << u.reason;
  EXPECT_NE(u.reason.find("prismatic joint S (links rocker and block turn together"), std::string::npos) << u.reason;
  EXPECT_NE(u.reason.find("joints of block with a finite centre: A"), std::string::npos) << u.reason;
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
