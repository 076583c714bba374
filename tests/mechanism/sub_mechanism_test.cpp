// The part of a mechanism an ask needs (mechanism/sub_mechanism.h): every link of every bundled
// mechanism, asked alone, moves in its sub-mechanism exactly as in the whole; groups nothing
// asked hangs on are left out; and check_mechanism with an ask lists only what it asks.
#include <gtest/gtest.h>

#include <filesystem>

#include "linkproof/io/mechanism_scene.h"
#include "report/comparison_text.h"
#include "mechanism/mechanism_catalogue.h"
#include "mechanism/sub_mechanism.h"
#include "mechanism_test_support.h"

namespace linkproof {
namespace {

using testing::mechanism_scene_path;

std::vector<std::string> bundled_scenes() {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(mechanism_scene_path("")))
    if (e.path().extension() == ".yaml") out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

TEST(SubMechanism, EveryLinkAskedAloneMovesAsInTheWholeMechanism) {
  int scenes = 0, smaller = 0;
  for (const std::string& path : bundled_scenes()) {
    const MechanismScene s = load_mechanism_scene(path);
    if (!inputs_fix_motion(s.linkage, s.inputs)) continue;
    ++scenes;
    const MechanismSolution<Rational> whole = solve_mechanism_exact(s);
    for (int l = 0; l < s.linkage.link_count(); ++l) {
      const SubMechanism sub = determined_sub_mechanism(s, {l});
      SCOPED_TRACE(path + " link " + s.linkage.link_name(l));
      ASSERT_TRUE(inputs_fix_motion(sub.scene.linkage, sub.scene.inputs));
      const MechanismSolution<Rational> part = solve_mechanism_exact(sub.scene);
      const auto at = static_cast<size_t>(std::find(sub.kept_links.begin(), sub.kept_links.end(), l) - sub.kept_links.begin());
      ASSERT_LT(at, sub.kept_links.size());
      EXPECT_EQ(part.motion.omega[at], whole.motion.omega[static_cast<size_t>(l)]);
      EXPECT_EQ(part.motion.omega_dot[at], whole.motion.omega_dot[static_cast<size_t>(l)]);
      // Every kept joint too.
      for (size_t j = 0; j < sub.kept_joints.size(); ++j) {
        EXPECT_EQ(part.motion.joint_a[j].x, whole.motion.joint_a[static_cast<size_t>(sub.kept_joints[j])].x);
        EXPECT_EQ(part.motion.joint_a[j].y, whole.motion.joint_a[static_cast<size_t>(sub.kept_joints[j])].y);
      }
      smaller += sub.kept_links.size() < static_cast<size_t>(s.linkage.link_count());
    }
  }
  EXPECT_GE(scenes, 10);
  EXPECT_GT(smaller, 0);
}

TEST(SubMechanism, TheStephensonSixBarsFourBarIsAskedWithoutTheDyadOnIt) {
  const MechanismScene s = load_mechanism_scene(mechanism_scene_path("pmks_stephenson_iii_example_2_1.yaml"));
  const SubMechanism sub = determined_sub_mechanism(s, {*s.linkage.find_link("CD")});
  EXPECT_EQ(sub.scene.linkage.link_names(), (std::vector<std::string>{"ground", "AB", "BCE", "CD"}));
  EXPECT_EQ(sub.scene.linkage.loops().size(), 1u);
  // FG hangs on BCE through the dyad EF-FG: asking for it keeps everything.
  EXPECT_EQ(determined_sub_mechanism(s, {*s.linkage.find_link("FG")}).kept_links.size(), 6u);
}

TEST(SubMechanism, TheFig5EightBarIsOneGroupAndKeepsEveryLink) {
  const MechanismScene s = load_mechanism_scene(mechanism_scene_path("fig5_eightbar.yaml"));
  EXPECT_EQ(determined_sub_mechanism(s, {*s.linkage.find_link("2")}).kept_links.size(), 8u);
}

TEST(AskedMechanismCheck, ListsOnlyTheAskedLinkAndRunsOnlyTheAskedClaims) {
  MechanismScene s = load_mechanism_scene(mechanism_scene_path("pmks_stephenson_iii_example_2_1.yaml"));
  const MechanismCheck whole = check_mechanism(s, {}, Arithmetic::Exact);
  s.ask = SceneAsk{};
  s.ask->links = {AskedName{"CD", "ask[0].links[0]"}};
  s.ask->claims = std::vector<AskedName>{AskedName{"routes_agree", "ask[1].claims[0]"}};
  const MechanismCheck c = check_mechanism(s, {}, Arithmetic::Exact);
  ASSERT_EQ(c.link_names, std::vector<std::string>{"CD"});
  const auto k = static_cast<size_t>(std::find(whole.link_names.begin(), whole.link_names.end(), "CD") - whole.link_names.begin());
  EXPECT_EQ(c.omega[0], whole.omega[k]);
  EXPECT_EQ(c.omega_dot[0], whole.omega_dot[k]);
  ASSERT_EQ(c.claims.size(), 1u);
  EXPECT_EQ(c.claims[0].info.id, "mechanism.routes_agree");
  EXPECT_EQ(c.claims[0].verdict, Verdict::Holds);
  EXPECT_TRUE(c.relative.empty());
  EXPECT_TRUE(c.joints.empty());
  // An asked claim is about the whole mechanism: it is evaluated on all six links.
  EXPECT_EQ(c.computed_links.size(), 6u);
  EXPECT_EQ(c.all_links, 6);
  EXPECT_EQ(c.all_loops, 2);
  EXPECT_EQ(c.loops, 2);
  // Without claims, only the sub-mechanism that determines CD is solved.
  s.ask->claims = std::vector<AskedName>{};
  const MechanismCheck rates_only = check_mechanism(s, {}, Arithmetic::Exact);
  EXPECT_EQ(rates_only.computed_links.size(), 4u);
  EXPECT_EQ(rates_only.loops, 1);
  EXPECT_EQ(rates_only.omega_dot[0], whole.omega_dot[k]);

  s.ask->claims = std::vector<AskedName>{AskedName{"no_such_claim", "ask[1].claims[0]"}};
  EXPECT_THROW(check_mechanism(s, {}, Arithmetic::Exact), InputError);
}

// A claim asked beside one link is evaluated on the whole mechanism: for every bundled scene
// and every link whose sub-mechanism is smaller than the whole, every claim asked with that link
// has the whole check's verdict and headline (compound.rank once compared the ranks of a
// four-bar cut out of a six-bar: "rank 1 vs 1: holds").
TEST(AskedMechanismCheck, AClaimAskedBesideOneLinkHasTheWholeMechanismsVerdict) {
  int compared = 0;
  for (const std::string& path : bundled_scenes()) {
    MechanismScene s = load_mechanism_scene(path);
    if (!inputs_fix_motion(s.linkage, s.inputs)) continue;
    s.ask.reset();
    const MechanismCheck whole = check_mechanism(s, {}, Arithmetic::Exact);
    for (int l = 0; l < s.linkage.link_count(); ++l) {
      if (determined_sub_mechanism(s, {l}).kept_links.size() == static_cast<size_t>(s.linkage.link_count())) continue;
      for (const ClaimOutcome& expected : whole.claims) {
        SCOPED_TRACE(path + " link " + s.linkage.link_name(l) + " claim " + expected.info.id);
        MechanismScene asked = s;
        asked.ask = SceneAsk{};
        asked.ask->links = {AskedName{s.linkage.link_name(l), "ask[0].links[0]"}};
        asked.ask->claims = std::vector<AskedName>{AskedName{expected.info.id, "ask[1].claims[0]"}};
        const MechanismCheck c = check_mechanism(asked, {}, Arithmetic::Exact);
        ASSERT_EQ(c.claims.size(), 1u);
        EXPECT_EQ(c.claims[0].verdict, expected.verdict);
        EXPECT_EQ(lhs_text(c.claims[0].headline), lhs_text(expected.headline));
        EXPECT_EQ(rhs_text(c.claims[0].headline), rhs_text(expected.headline));
        ++compared;
      }
      break;  // one smaller sub-mechanism per scene is enough
    }
  }
  EXPECT_GT(compared, 0);
}

TEST(AskedMechanismCheck, AnAskedJointIsListedWithItsWholeMechanismMotion) {
  MechanismScene s = load_mechanism_scene(mechanism_scene_path("pmks_stephenson_iii_example_2_1.yaml"));
  const MechanismCheck whole = check_mechanism(s, {}, Arithmetic::Exact);
  s.ask = SceneAsk{};
  s.ask->points = {AskedName{"C", "ask[0].points[0]"}};
  const MechanismCheck c = check_mechanism(s, {}, Arithmetic::Exact);
  ASSERT_EQ(c.joints.size(), 1u);
  const auto same = std::find_if(whole.joints.begin(), whole.joints.end(), [](const auto& p) { return p.name == "C"; });
  EXPECT_EQ(c.joints[0].a[0], same->a[0]);
  EXPECT_EQ(c.joints[0].v[1], same->v[1]);
  EXPECT_TRUE(c.claims.empty());
  EXPECT_TRUE(c.link_names.empty());
}

TEST(AskedMechanismCheck, TheReaderNamesAnUnknownLinkOrPoint) {
  const std::string base = "name: m\nmechanism:\n  ground: \"0\"\n  joints:\n"
                           "    - {name: A, type: revolute, links: [\"0\", \"1\"], at: [0, 0]}\n"
                           "    - {name: B, type: revolute, links: [\"1\", \"2\"], at: [1, 2]}\n"
                           "    - {name: C, type: revolute, links: [\"2\", \"3\"], at: [4, 3]}\n"
                           "    - {name: D, type: revolute, links: [\"3\", \"0\"], at: [5, 0]}\n"
                           "  inputs:\n    - {link: \"1\", omega: 1, omega_dot: 0}\n";
  EXPECT_NO_THROW(parse_mechanism_scene(base + "ask: [omega_dot(3), points: [C]]\n", "m.yaml"));
  try {
    parse_mechanism_scene(base + "ask: [omega_dot(9)]\n", "m.yaml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("ask[0]"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("no link `9`"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse_mechanism_scene(base + "ask: [points: [Z]]\n", "m.yaml"), InputError);
  EXPECT_THROW(parse_mechanism_scene(base + "ask: [links: [\"1\", \"1\"]]\n", "m.yaml"), InputError);
}

}  // namespace
}  // namespace linkproof
