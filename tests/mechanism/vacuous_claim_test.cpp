// A mechanism claim that compares nothing is no pass: driver_inversion where no moving link but
// the input turns, and any claim whose evaluation gives no comparison.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "linkproof/io/mechanism_scene.h"
#include "mechanism/mechanism_catalogue.h"

namespace linkproof {
namespace {

// An in-line slider-crank; `crank_top` the crank pin A. At A = (0, 3) the crank is perpendicular
// to the guide: the rod translates (omega 0) and the slider never turns.
MechanismScene slider_crank_with_crank_pin_at(const std::string& crank_pin) {
  const std::string text =
      "name: slider-crank\n"
      "mechanism:\n"
      "  ground: frame\n"
      "  links: [frame, crank, rod, slider]\n"
      "  joints:\n"
      "    - {name: O2, type: revolute,  links: [frame, crank], at: [0, 0]}\n"
      "    - {name: A,  type: revolute,  links: [crank, rod],   at: " + crank_pin + "}\n"
      "    - {name: B,  type: revolute,  links: [rod, slider],  at: [4, 0]}\n"
      "    - {name: D,  type: prismatic, links: [frame, slider], at: B, axis: [1, 0]}\n"
      "  inputs:\n"
      "    - {link: crank, omega: 2, omega_dot: 1}\n";
  return parse_mechanism_scene(text, "slider_crank.yaml");
}

const ClaimOutcome* find_claim(const MechanismCheck& c, const std::string& id) {
  const auto it = std::find_if(c.claims.begin(), c.claims.end(), [&](const ClaimOutcome& o) { return o.info.id == id; });
  return it == c.claims.end() ? nullptr : &*it;
}

TEST(DriverInversion, IsNotApplicableWhereNoMovingLinkButTheInputTurns) {
  const MechanismCheck at_rest = check_mechanism(slider_crank_with_crank_pin_at("[0, 3]"), Arithmetic::Exact);
  ASSERT_EQ(at_rest.omega.size(), 4u);
  EXPECT_EQ(find_claim(at_rest, "mechanism.driver_inversion"), nullptr) << "it held with nothing compared";
  EXPECT_NE(std::find(at_rest.not_applicable.begin(), at_rest.not_applicable.end(), "mechanism.driver_inversion"),
            at_rest.not_applicable.end());
  // Where the rod turns, the rod drives and every link is compared.
  const MechanismCheck turning = check_mechanism(slider_crank_with_crank_pin_at("[1, 3]"), Arithmetic::Exact);
  const ClaimOutcome* inversion = find_claim(turning, "mechanism.driver_inversion");
  ASSERT_NE(inversion, nullptr);
  EXPECT_EQ(inversion->verdict, Verdict::Holds);
  EXPECT_EQ(inversion->instances.size(), 8u);  // omega and omega-dot of 4 links, the rod driving
}

TEST(MechanismClaimRunner, AClaimThatComparesNothingIsAnErrorNotAPass) {
  const MechanismScene s = slider_crank_with_crank_pin_at("[1, 3]");
  const MechanismSolution<Rational> truth = solve_mechanism_exact(s);
  const MechanismClaim empty{ClaimInfo{"empty", "test", "compares nothing", Expectation::Holds, "", 4, 0},
                             [](const MechanismContext&) { return ClaimSides<Rational>{}; },
                             {}};
  const ClaimOutcome o = run_mechanism_claim(empty, MechanismContext{s, truth});
  EXPECT_EQ(o.verdict, Verdict::Error);
  EXPECT_EQ(o.error, "the claim produced no comparison");
}

}  // namespace
}  // namespace linkproof
