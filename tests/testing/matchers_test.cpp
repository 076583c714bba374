// linkproof::testing matchers and oracle: they accept values found without linkproof (the
// textbook answer of docs/conventions.md §B, the textbook four-bar closed form), reject a planted error with
// the exact value and the scene in the message, and the printed scene reads back.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <stdexcept>
#include <type_traits>

#include "linkproof/io/mechanism_scene.h"
#include "linkproof/testing.h"

namespace linkproof::testing {
namespace {

Point int_point(long x, long y) { return {Rational(x), Rational(y)}; }

MechanismCase seed001_fourbar() {
  // conventions §B: O2 (0,0), A (3,4), B (11,10), O4 (11,0), omega2 = 2, alpha2 = 5.
  return make_fourbar(int_point(0, 0), int_point(3, 4), int_point(11, 10), int_point(11, 0), 2, 5);
}

// The textbook answer of docs/conventions.md §B (verify/scenes/mechanisms/seed001_fourbar.yaml), written
// here, not computed by linkproof: links ground, crank, coupler, rocker.
const Rational kSeed001Omega3 = Rational(-3) / 4, kSeed001Omega4 = Rational(7) / 20;
const Rational kSeed001Alpha3 = Rational(63) / 160, kSeed001Alpha4 = Rational(3109) / 800;
// The same alphas as decimal literals: 63/160 = 0.39375 and 3109/800 = 3.88625 exactly, so each
// literal is the double nearest the exact answer (and not equal to it: neither is a dyadic).
const std::vector<double> kSeed001AlphaDoubles = {0.0, 5.0, 0.39375, 3.88625};

TEST(TestingMatchers, AngularAccelerationsMatchAcceptsTheTextbookAnswerOfConventionsB) {
  const MechanismCase c = seed001_fourbar();
  const MechanismTruth t = compute_truth(c.scene);
  ASSERT_EQ(t.links.size(), 4u);
  EXPECT_EQ(t.links[2].omega, kSeed001Omega3);
  EXPECT_EQ(t.links[3].omega, kSeed001Omega4);
  EXPECT_EQ(t.links[2].alpha, kSeed001Alpha3);
  EXPECT_EQ(t.links[3].alpha, kSeed001Alpha4);
  EXPECT_THAT(kSeed001AlphaDoubles, AngularAccelerationsMatch(t, Tolerance::double_bound(1)));
  // The comparison is exact: 63/160 is not a double, so its nearest double misses a zero tolerance.
  EXPECT_THAT(kSeed001AlphaDoubles, ::testing::Not(AngularAccelerationsMatch(t, Tolerance{})));
}

// The omegas of §B as decimal literals: -3/4 and 7/20 = 0.35 (0.35 is not a dyadic: its literal
// is the nearest double, not the exact value).
const std::vector<double> kSeed001OmegaDoubles = {0.0, 2.0, -0.75, 0.35};

TEST(TestingMatchers, AngularVelocitiesMatchAcceptsTheTextbookOmegasAndRejectsAPerturbedOne) {
  const MechanismTruth t = compute_truth(seed001_fourbar().scene);
  EXPECT_THAT(kSeed001OmegaDoubles, AngularVelocitiesMatch(t, Tolerance::double_bound(1)));
  EXPECT_THAT(t.omega_doubles(), ::testing::ElementsAreArray(kSeed001OmegaDoubles));
  std::vector<double> wrong = kSeed001OmegaDoubles;
  wrong[2] = -0.75 * (1 + 1e-12);
  const auto m = ::testing::Matcher<const std::vector<double>&>(AngularVelocitiesMatch(t, Tolerance::double_bound(4)));
  ::testing::StringMatchResultListener listener;
  EXPECT_FALSE(m.MatchAndExplain(wrong, &listener));
  EXPECT_THAT(listener.str(), ::testing::HasSubstr("exact omega"));
  EXPECT_THAT(listener.str(), ::testing::HasSubstr("WRONG"));
  // omega and alpha are different rates: the alphas are not the omegas.
  EXPECT_THAT(kSeed001AlphaDoubles, ::testing::Not(AngularVelocitiesMatch(t, Tolerance::double_bound(4))));
  EXPECT_EQ(t.link_index("coupler"), 2u);
  EXPECT_THROW(t.link_index("no such link"), std::out_of_range);
}

TEST(TestingMatchers, ToleranceIsNeverABareNumber) {
  static_assert(!std::is_convertible_v<double, Tolerance>);
  const Tolerance a = Tolerance::absolute_to(1e-3);
  EXPECT_EQ(a.absolute, 1e-3);
  EXPECT_EQ(a.relative, 0);
  EXPECT_EQ(a.double_bounds, 0);
  const MechanismTruth t = compute_truth(seed001_fourbar().scene);
  std::vector<double> off = kSeed001AlphaDoubles;
  off[2] += 5e-4;
  EXPECT_THAT(off, AngularAccelerationsMatch(t, Tolerance::absolute_to(1e-3)));
  EXPECT_THAT(off, ::testing::Not(AngularAccelerationsMatch(t, Tolerance::absolute_to(1e-4))));
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
  PolygonCase p{"polygon/scattered/n=5", Polygon<Rational>({int_point(0, 0), int_point(1, 4), int_point(5, 5), int_point(7, 1), int_point(3, -2)}),
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

TEST(TestingMatchers, CheckClaimGivesATypedVerdictAndTheResidualAsExactAndDouble) {
  const PolygonCase p{"polygon/scattered/n=5", Polygon<Rational>({int_point(0, 0), int_point(1, 4), int_point(5, 5), int_point(7, 1), int_point(3, -2)}),
                      {{2, -1}, {1, 3}}};
  const ClaimResult holds = check_claim("dijksman1966.eq22", p);
  EXPECT_TRUE(holds.found);
  EXPECT_EQ(holds.verdict, Verdict::Holds);
  ASSERT_TRUE(holds.residual_exact.has_value());
  EXPECT_EQ(*holds.residual_exact, 0);
  EXPECT_EQ(holds.residual, 0.0);
  const ClaimResult erratum = check_claim("dijksman1966.eq22.unsigned_phi", p);
  EXPECT_EQ(erratum.verdict, Verdict::Fails);
  ASSERT_TRUE(erratum.residual_exact.has_value() && erratum.residual.has_value());
  EXPECT_NE(*erratum.residual_exact, 0);
  EXPECT_EQ(*erratum.residual, nearest_double(*erratum.residual_exact));
  const ClaimResult unknown = check_claim("dijksman1966.no_such_eq", p);
  EXPECT_FALSE(unknown.found);
  EXPECT_EQ(unknown.verdict, Verdict::Error);
  EXPECT_FALSE(unknown.residual.has_value());
  EXPECT_THAT(unknown.detail, ::testing::HasSubstr("dijksman1966.eq22"));  // the known ids
}

RC_GTEST_PROP(TestingMatchers, Eq22HoldsOnEveryGeneratedPolygonWhereItsConstructionExists, ()) {
  PolygonOptions o;
  o.n_max = 6;
  const PolygonCase c = *gen_polygon(o);
  classify_case(c);
  const ClaimResult r = check_claim("dijksman1966.eq22", c);
  // Undefined where the construction is (Q_j or P'_j at infinity, conventions §A6); never fails.
  RC_CLASSIFY(!r.holds, "construction undefined");
  RC_ASSERT(r.holds || r.verdict == Verdict::Undefined);
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

/// An independent four-bar alpha, written from the textbook and not from linkproof: the
/// loop-closure solution of the four-bar (Norton, Design of Machinery, eqs. 6.18 and 7.12) in
/// double. The loop is a e^{i th2} + b e^{i th3} - c e^{i th4} - d e^{i th1} = 0 with a = |O2A|
/// (crank), b = |AB| (coupler), c = |O4B| (rocker); differentiating once with th1 fixed gives
///   omega3 = a omega2 sin(th4 - th2) / (b sin(th3 - th4)),
///   omega4 = a omega2 sin(th2 - th3) / (c sin(th4 - th3)),
/// and twice, the real and imaginary parts give the 2x2 system solved by Cramer's rule:
///   alpha3 = (C D - A F) / (A E - B D),  alpha4 = (C E - B F) / (A E - B D),
///   A = c sin th4, B = b sin th3, D = c cos th4, E = b cos th3,
///   C = a alpha2 sin th2 + a omega2^2 cos th2 + b omega3^2 cos th3 - c omega4^2 cos th4,
///   F = a alpha2 cos th2 - a omega2^2 sin th2 - b omega3^2 sin th3 + c omega4^2 sin th4.
/// The angles are absolute (from the joints), so the ground need not lie along x. One alpha per
/// link in the linkage's link order; the ground's is 0.
std::vector<double> closed_form_fourbar_alpha(const Linkage& m, const std::vector<MechanismInput>& in) {
  const auto o2 = joint_xy(m, "O2"), a_ = joint_xy(m, "A"), b_ = joint_xy(m, "B"), o4 = joint_xy(m, "O4");
  const double a = std::hypot(a_[0] - o2[0], a_[1] - o2[1]);
  const double b = std::hypot(b_[0] - a_[0], b_[1] - a_[1]);
  const double c = std::hypot(b_[0] - o4[0], b_[1] - o4[1]);
  const double th2 = std::atan2(a_[1] - o2[1], a_[0] - o2[0]);
  const double th3 = std::atan2(b_[1] - a_[1], b_[0] - a_[0]);
  const double th4 = std::atan2(b_[1] - o4[1], b_[0] - o4[0]);
  const double w2 = nearest_double(in.at(0).rate), al2 = nearest_double(in.at(0).rate_dot);
  const double w3 = a * w2 * std::sin(th4 - th2) / (b * std::sin(th3 - th4));
  const double w4 = a * w2 * std::sin(th2 - th3) / (c * std::sin(th4 - th3));
  const double A = c * std::sin(th4), B = b * std::sin(th3), D = c * std::cos(th4), E = b * std::cos(th3);
  const double C = a * al2 * std::sin(th2) + a * w2 * w2 * std::cos(th2) + b * w3 * w3 * std::cos(th3) -
                   c * w4 * w4 * std::cos(th4);
  const double F = a * al2 * std::cos(th2) - a * w2 * w2 * std::sin(th2) - b * w3 * w3 * std::sin(th3) +
                   c * w4 * w4 * std::sin(th4);
  std::vector<double> alpha(static_cast<size_t>(m.link_count()), 0.0);
  const auto at = [&](const char* link) -> double& { return alpha.at(static_cast<size_t>(*m.find_link(link))); };
  at("crank") = al2;
  at("coupler") = (C * D - A * F) / (A * E - B * D);
  at("rocker") = (C * E - B * F) / (A * E - B * D);
  return alpha;
}

// The independent formula itself, against the textbook answer (no linkproof truth involved).
TEST(TestingOracle, ClosedFormFourBarGivesTheTextbookAnswerOfConventionsB) {
  const MechanismCase c = seed001_fourbar();
  const std::vector<double> alpha = closed_form_fourbar_alpha(c.scene.linkage, c.scene.inputs);
  ASSERT_EQ(alpha.size(), kSeed001AlphaDoubles.size());
  for (size_t l = 0; l < alpha.size(); ++l) EXPECT_NEAR(alpha[l], kSeed001AlphaDoubles[l], 1e-12) << l;
}

// The oracle passes an independent, correct four-bar: its truth agrees with the textbook closed
// form on every generated four-bar (any Grashof class). The closed form rounds on its own route
// (atan2, sin, cos: sin(pi) is 1.2e-16, not 0, where an exact alpha is 0), so the tolerance
// adds 1e-9 absolute and relative to linkproof's double bound: far below any wrong term (the
// generated coordinates and rates are small integers and fractions), far above the rounding.
RC_GTEST_PROP(TestingOracle, PassesTheTextbookClosedFormFourBarAlpha, ()) {
  Tolerance t = Tolerance::double_bound(4);
  t.absolute = 1e-9;
  t.relative = 1e-9;
  rc_assert_alpha_matches(*gen_fourbar(), closed_form_fourbar_alpha, t);
}

}  // namespace
}  // namespace linkproof::testing
