// The counting claims of Dijksman (1966) sec. 3 (conventions §A7, §A5.5) as the catalogue states them.
#include "exit_status.h"
#include "dijksman1966_counting.h"

#include <gtest/gtest.h>

namespace linkproof {
namespace {

// The triangle rank and the balance have constant coefficients: an exact rank is a proof for
// that n. The rank-2 families depend on the geometry: computed on sample polygons, they are
// holds_on_samples (issue 11, finding 7: one random polygon was called a proof).
TEST(Dijksman1966Counting, TriangleRanksAreProvedAndGeometricRanksHoldOnSamples) {
  for (int n = 3; n <= 60; ++n) {
    const auto claims = dijksman1966::count_claims_for_n(n, 1);
    ASSERT_EQ(claims.size(), 5u);
    for (size_t k = 0; k < claims.size(); ++k) {
      const auto& c = claims[k];
      EXPECT_EQ(c.verdict, k < 2 ? CountVerdict::Proved : CountVerdict::HoldsOnSamples) << c.id << ": " << c.reason;
      EXPECT_TRUE(c.as_expected()) << c.id;
      EXPECT_EQ(cli::is_as_expected(c, /*strict=*/true), k < 2) << c.id;
      if (k >= 2) {
        EXPECT_EQ(c.samples, 2) << c.id;
      }
    }
  }
}

TEST(Dijksman1966Counting, CountingPolygonsAvoidTheDeadCentreForEveryFixedSide) {
  for (int n = 3; n <= 30; ++n) {
    const auto p = dijksman1966::counting_polygon(n, 5);
    for (int j = 1; j <= n; ++j) EXPECT_FALSE(cln::zerop(cross(p.polygon.side(j), p.polygon.side(j % n + 1)))) << p.origin;
  }
}

TEST(Dijksman1966Counting, EightBarClaimsHoldAndThePrintedCountIsDisproved) {
  std::vector<std::string> notes;
  const auto loops = parse_polygon_list(dijksman1966::kFig5Polygons, "test", "loops");
  const auto claims = dijksman1966::eightbar_claims(dijksman1966::fig5_eightbar(), loops, notes);
  bool printed_seen = false;
  for (const auto& c : claims) {
    EXPECT_TRUE(c.as_expected()) << c.id << ": " << c.reason;
    if (c.id == "dijksman1966.sec3.count.printed") {
      printed_seen = true;
      EXPECT_EQ(c.verdict, CountVerdict::Disproved);
      EXPECT_EQ(c.expected_value, "7");
      EXPECT_EQ(c.observed_value, "6");
    }
    if (c.id == "dijksman1966.fig5.with_polygons") {
      EXPECT_EQ(c.observed_value, "28");
    }
  }
  EXPECT_TRUE(printed_seen);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("A5.5"), std::string::npos);
  EXPECT_NE(notes[0].find("28 - 22 = 6"), std::string::npos);
}

TEST(Dijksman1966Counting, TwoLoopsAreReportedAsNotEnough) {
  std::vector<std::string> notes;
  const auto loops = parse_polygon_list("1-2-3-4-0,1-5-7-4-0", "test", "loops");
  const auto claims = dijksman1966::eightbar_claims(dijksman1966::fig5_eightbar(), loops, notes);
  int not_as_expected = 0;
  for (const auto& c : claims) not_as_expected += c.as_expected() ? 0 : 1;
  EXPECT_GT(not_as_expected, 0);
}

// One loop three times does not determine the velocities: the value claims and the sec. 3
// count computed nothing, so they are errors, not disproved, and no rank is printed as -1.
TEST(Dijksman1966Counting, LoopsThatDoNotDetermineTheVelocitiesGiveErrorsNotDisproofs) {
  std::vector<std::string> notes;
  const auto loops = parse_polygon_list("1-2-3-4-0,1-2-3-4-0,1-2-3-4-0", "test", "loops");
  const auto claims = dijksman1966::eightbar_claims(dijksman1966::fig5_eightbar(), loops, notes);
  int errors = 0;
  for (const auto& c : claims) {
    EXPECT_EQ(c.reason.find("-1"), std::string::npos) << c.id << ": " << c.reason;
    EXPECT_EQ(c.observed_value.find("undetermined"), std::string::npos) << c.id;
    if (c.id == "dijksman1966.fig5.omega" || c.id == "dijksman1966.fig5.omega_dot_4_0" ||
        c.id == "dijksman1966.fig5.omega_dot_1_2" || c.id == "dijksman1966.sec3.count") {
      EXPECT_EQ(c.verdict, CountVerdict::Error) << c.id << ": " << c.reason;
      ++errors;
    }
  }
  EXPECT_EQ(errors, 4);
}

}  // namespace
}  // namespace linkproof
