// The worked example of docs/testing.md: a kinematics library's own tests, with linkproof as the
// oracle. MyFourBar.PlantedBugIsCaught is EXPECTED TO FAIL (scripts/test_consumer.sh checks that
// it fails, that the scene it prints is small, and that `linkproof check` reads it).
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <linkproof/testing.h>

#include "my_fourbar.h"

namespace lt = linkproof::testing;

// The library's correct alpha agrees with the exact truth on every Grashof class.
RC_GTEST_PROP(MyFourBar, AlphaMatchesLinkproof, ()) {
  lt::rc_assert_alpha_matches(*lt::gen_fourbar(), my_fourbar_alpha);
}

// The angular velocities too.
RC_GTEST_PROP(MyFourBar, OmegaMatchesLinkproof, ()) {
  lt::rc_assert_omega_matches(*lt::gen_fourbar(), my_fourbar_omega);
}

// ... also with extreme link ratios (1e+-8). (Near the toggle, Bias::NearDeadCentre, a plain
// double loop solution loses more than a small multiple of linkproof's own bound: see
// docs/testing.md; such a property needs a tolerance chosen for it.)
RC_GTEST_PROP(MyFourBar, AlphaMatchesLinkproofAtExtremeRatios, ()) {
  lt::rc_assert_alpha_matches(*lt::gen_fourbar(std::nullopt, lt::Bias::ExtremeRatio), my_fourbar_alpha,
                              lt::Tolerance::double_bound(4));
}

// The planted bug (the coupler's centripetal term dropped): linkproof catches it and RapidCheck
// shrinks it to a small four-bar, printed as a scene.
RC_GTEST_PROP(MyFourBar, PlantedBugIsCaught, ()) {
  lt::rc_assert_alpha_matches(*lt::gen_fourbar(), buggy_fourbar_alpha);
}

// The GTest matchers on a fixed case: the four-bar of conventions §B, and Dijksman's eq. (22).
TEST(MyFourBar, ConventionsBFourBarMatchesTheExactTruth) {
  const lt::MechanismCase c = lt::make_fourbar({0, 0}, {3, 4}, {11, 10}, {11, 0}, 2, 5);
  const lt::MechanismTruth truth = lt::compute_truth(c.scene);
  EXPECT_THAT(my_fourbar_alpha(c.scene.linkage, c.scene.inputs),
              lt::AngularAccelerationsMatch(truth, lt::Tolerance::double_bound(4)));
  EXPECT_THAT(buggy_fourbar_alpha(c.scene.linkage, c.scene.inputs),
              ::testing::Not(lt::AngularAccelerationsMatch(truth, lt::Tolerance::double_bound(4))));
}

RC_GTEST_PROP(MyFourBar, GeneratedPentagonsSatisfyEq22, ()) {
  lt::PolygonOptions o;
  o.n_min = o.n_max = 5;
  const lt::PolygonCase p = *lt::gen_polygon(o);
  lt::classify_case(p);
  const lt::ClaimResult r = lt::check_claim("dijksman1966.eq22", p);
  RC_ASSERT(r.holds || r.verdict == linkproof::Verdict::Undefined);  // undefined: Q_j or P'_j at infinity (conventions §A6)
}

TEST(MyFourBar, ClaimHoldsOnTheA8Pentagon) {
  const lt::PolygonCase p{"polygon/spec-a8", linkproof::Polygon<linkproof::Rational>({{0, 0}, {1, 4}, {5, 5}, {7, 1}, {3, -2}}),
                          {{2, -1}, {1, 3}}};
  EXPECT_THAT(p, lt::ClaimHolds("dijksman1966.eq22"));
  EXPECT_THAT(p, ::testing::Not(lt::ClaimHolds("dijksman1966.eq22.unsigned_phi")));
}
