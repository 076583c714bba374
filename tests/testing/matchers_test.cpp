// linkproof::testing matchers and oracle: they accept the truth, reject a planted error with the
// exact value and the scene in the message, and the printed scene reads back.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "linkproof/io/mechanism_scene.h"
#include "linkproof/testing.h"

namespace linkproof::testing {
namespace {

Point pt(long x, long y) { return {Rational(x), Rational(y)}; }

MechanismCase seed001_fourbar() {
  // conventions §B: O2 (0,0), A (3,4), B (11,10), O4 (11,0), omega2 = 2, alpha2 = 5.
  return make_fourbar(pt(0, 0), pt(3, 4), pt(11, 10), pt(11, 0), 2, 5);
}

TEST(TestingMatchers, AngularAccelerationsMatchAcceptsTheTruthOfConventionsB) {
  const MechanismCase c = seed001_fourbar();
  const MechanismTruth t = compute_truth(c.scene);
  EXPECT_EQ(t.links[2].alpha, Rational(63) / 160);   // alpha3
  EXPECT_EQ(t.links[3].alpha, Rational(3109) / 800);  // alpha4
  EXPECT_THAT(t.alpha_doubles(), AngularAccelerationsMatch(t, Tolerance::double_bound(1)));
  // The comparison is exact: 63/160 is not a double, so its nearest double misses a zero tolerance.
  EXPECT_THAT(t.alpha_doubles(), ::testing::Not(AngularAccelerationsMatch(t, 0.0)));
}

TEST(TestingMatchers, AngularAccelerationsMatchRejectsAWrongLinkAndShowsTheExactValue) {
  const MechanismCase c = seed001_fourbar();
  const MechanismTruth t = compute_truth(c.scene);
  std::vector<double> wrong = t.alpha_doubles();
  wrong[3] += 1e-9;
  const auto m = ::testing::Matcher<const std::vector<double>&>(AngularAccelerationsMatch(t, Tolerance::double_bound(4)));
  ::testing::StringMatchResultListener listener;
  EXPECT_FALSE(m.MatchAndExplain(wrong, &listener));
  EXPECT_THAT(listener.str(), ::testing::HasSubstr("3.88625"));  // 3109/800 = 3.88625 exactly
  EXPECT_THAT(listener.str(), ::testing::HasSubstr("WRONG"));
  EXPECT_TRUE(m.Matches(t.alpha_doubles()));
  EXPECT_FALSE(m.Matches({0.0, 1.0}));  // wrong count
}

TEST(TestingMatchers, ClaimHoldsOnTheA8PentagonAndExplainsAnErratum) {
  PolygonCase p{"polygon/scattered/n=5", Polygon<Rational>({pt(0, 0), pt(1, 4), pt(5, 5), pt(7, 1), pt(3, -2)}),
                {{2, -1}, {1, 3}}};
  EXPECT_THAT(p, ClaimHolds("dijksman1966.eq22"));
  EXPECT_THAT(p, ClaimHolds("dijksman1966.sec3"));
  const auto printed = ::testing::Matcher<const PolygonCase&>(ClaimHolds("dijksman1966.eq22.unsigned_phi"));
  ::testing::StringMatchResultListener listener;
  EXPECT_FALSE(printed.MatchAndExplain(p, &listener));
  EXPECT_THAT(listener.str(), ::testing::HasSubstr("fails"));
  EXPECT_FALSE(::testing::Matcher<const PolygonCase&>(ClaimHolds("dijksman1966.no_such_eq")).Matches(p));
  EXPECT_THAT(polygon_mechanism(p), ClaimHolds("mechanism.routes_agree"));
}

RC_GTEST_PROP(TestingMatchers, Eq22HoldsOnEveryGeneratedPolygonWhereItsConstructionExists, ()) {
  PolygonOptions o;
  o.n_max = 6;
  const PolygonCase c = *gen_polygon(o);
  classify_case(c);
  const ClaimResult r = check_claim("dijksman1966.eq22", c);
  // Undefined where the construction is (Q_j or P'_j at infinity, conventions §A6); never fails.
  RC_CLASSIFY(!r.holds, "construction undefined");
  RC_ASSERT(r.holds || r.verdict == "undefined");
}

/// A planted bug: the truth, but the rocker's (last link's) alpha with the wrong sign; wrong
/// whenever that alpha is not 0.
std::vector<double> buggy_fourbar_alpha(const Linkage& m, const std::vector<MechanismInput>& in) {
  MechanismScene s;
  s.linkage = m;
  s.inputs = in;
  std::vector<double> a = compute_truth(s).alpha_doubles();
  a.back() = -a.back();
  return a;
}

TEST(TestingOracle, CatchesAPlantedBugAndPrintsAShrunkSceneThatReadsBack) {
  const auto result = rc::detail::checkTestable([] {
    rc_assert_alpha_matches(*gen_fourbar(), buggy_fourbar_alpha);
  });
  rc::detail::FailureResult failure;
  ASSERT_TRUE(result.match(failure)) << "the planted bug was not caught";
  const std::string& text = failure.description;
  const auto begin = text.find("--- scene ---\n"), end = text.find("--- end scene ---");
  ASSERT_NE(begin, std::string::npos) << text;
  ASSERT_NE(end, std::string::npos) << text;
  const MechanismScene s = parse_mechanism_scene(text.substr(begin + 14, end - begin - 14), "shrunk");
  EXPECT_EQ(s.linkage.link_count(), 4);
  // Shrunk: the bug needs a turning coupler, but no more than small coordinates.
  for (const auto& j : s.linkage.joints()) {
    EXPECT_LE(cln::abs(j.at.x), 3) << text;
    EXPECT_LE(cln::abs(j.at.y), 3) << text;
  }
  EXPECT_THAT(text, ::testing::HasSubstr("WRONG"));
}

TEST(TestingOracle, PassesACorrectFourBarAlpha) {
  const auto correct = [](const Linkage& m, const std::vector<MechanismInput>& in) {
    MechanismScene s;
    s.linkage = m;
    s.inputs = in;
    return compute_truth(s).alpha_doubles();
  };
  const auto result = rc::detail::checkTestable([&] { rc_assert_alpha_matches(*gen_mechanism(), correct); });
  rc::detail::SuccessResult success;
  EXPECT_TRUE(result.match(success));
}

}  // namespace
}  // namespace linkproof::testing
