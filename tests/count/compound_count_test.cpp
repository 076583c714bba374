// The eight-bar of Fig. 5 (conventions §A7, §A8): ranks 21 -> 22 -> 28, exact omega and omega-dot, and
// the same answers from other loops and other fixed sides (an independent route).
#include "count/compound_count.h"

#include <gtest/gtest.h>

#include "dijksman1966_counting.h"
#include "linkproof/core/error.h"
#include "support/polygons.h"

namespace linkproof {
namespace {

using dijksman1966::fig5_eightbar;
using dijksman1966::kFig5Polygons;

using test::q;

CompoundCount count_fig5(const std::string& loops) {
  return count_compound(fig5_eightbar(), parse_polygon_list(loops, "test", "loops"));
}

TEST(CompoundCount, EightBarRanksAre21Then22Then28) {
  const CompoundCount c = count_fig5(kFig5Polygons);
  EXPECT_EQ(c.unknowns, 28);
  EXPECT_EQ(c.triangles.relations, 56);
  EXPECT_EQ(c.triangles.rank, 21);
  EXPECT_EQ(c.with_input.rank, 22);
  ASSERT_TRUE(c.with_polygons.has_value());
  EXPECT_EQ(c.with_polygons->relations, 56 + 1 + 6);
  EXPECT_EQ(c.with_polygons->rank, 28);
  EXPECT_TRUE(c.with_polygons->consistent());
  EXPECT_EQ(c.velocity.rank, 28);
  EXPECT_TRUE(c.velocity.consistent());
}

TEST(CompoundCount, EightBarSolutionIsTheConventionsA8Answer) {
  const CompoundCount c = count_fig5(kFig5Polygons);
  const std::vector<Rational> omega = {0, 1, q(-7, 317), q(60, 317), q(159, 317), q(-20, 317), q(-279, 317), q(22, 317)};
  for (size_t l = 0; l < omega.size(); ++l) {
    ASSERT_TRUE(c.omega[l].has_value()) << "link " << l;
    EXPECT_EQ(*c.omega[l], omega[l]) << "link " << l;
  }
  EXPECT_EQ(*c.relative_omega_dot(4, 0), q(171151479, 318550130));
  EXPECT_EQ(*c.relative_omega_dot(1, 2), q(8471254, 159275065));
  EXPECT_EQ(*c.relative_omega_dot(1, 0), q(1, 2));
}

TEST(CompoundCount, OtherLoopsAndOtherFixedSidesGiveTheSameAccelerations) {
  // Each loop rotated so another link is side n, and a different third loop (2-3-6-5-1 is the
  // paper's third loop reversed and rotated; 0-1-5-6-3-4 is a hexagon of the same mechanism).
  const CompoundCount ref = count_fig5(kFig5Polygons);
  for (const char* loops : {"2-3-4-0-1,5-7-4-0-1,6-3-2-1-5", "0-4-3-2-1,1-5-7-4-0,2-3-6-5-1",
                            "1-2-3-4-0,1-5-7-4-0,0-1-5-6-3-4"}) {
    SCOPED_TRACE(loops);
    const CompoundCount c = count_fig5(loops);
    ASSERT_TRUE(c.with_polygons.has_value());
    EXPECT_EQ(c.with_polygons->rank, 28);
    EXPECT_TRUE(c.with_polygons->consistent());
    for (int l = 0; l < 8; ++l) {
      ASSERT_TRUE(c.omega_dot[static_cast<size_t>(l)].has_value());
      EXPECT_EQ(*c.omega_dot[static_cast<size_t>(l)], *ref.omega_dot[static_cast<size_t>(l)]) << "link " << l;
    }
  }
}

// Must fail: two pentagons leave the velocities undetermined, so the count stops short.
TEST(CompoundCount, TwoLoopsDoNotDetermineTheMechanism) {
  const CompoundCount c = count_fig5("1-2-3-4-0,1-5-7-4-0");
  EXPECT_EQ(c.velocity.rank, 26);
  EXPECT_FALSE(c.with_polygons.has_value());
  EXPECT_FALSE(c.omega[6].has_value());
}

// Must fail: a wrong input omega-dot changes the solution, so the known answer is not reproduced.
TEST(CompoundCount, AWrongInputGivesAnotherOmegaDot) {
  CompoundMechanism m = fig5_eightbar();
  m.input_omega_dot = 1;
  const CompoundCount c = count_compound(m, parse_polygon_list(kFig5Polygons, "test", "loops"));
  ASSERT_TRUE(c.relative_omega_dot(4, 0).has_value());
  EXPECT_NE(*c.relative_omega_dot(4, 0), q(171151479, 318550130));
}

TEST(CompoundCount, PolygonListsAreParsedOrRejectedByName) {
  const auto loops = parse_polygon_list("1-2-3-4-0,1-5-7-4-0", "src", "field");
  EXPECT_EQ(loops, (std::vector<std::vector<int>>{{1, 2, 3, 4, 0}, {1, 5, 7, 4, 0}}));
  for (const char* bad : {"", "1-2", "1-2-x", "1-2-3,", "1--2-3", "1-2-1", "1-2-3 "}) {
    try {
      parse_polygon_list(bad, "src", "field");
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), "field");
    }
  }
}

TEST(CompoundCount, ALoopThroughUnjoinedLinksIsBadInput) {
  EXPECT_THROW(count_fig5("1-2-7-4-0"), InputError);  // links 2 and 7 share no joint
  EXPECT_THROW(count_fig5("1-2-3-9"), InputError);    // no link 9
}

}  // namespace
}  // namespace linkproof
