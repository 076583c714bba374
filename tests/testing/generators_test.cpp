// linkproof::testing generators: every case is exact and well posed, its double truth bounds the
// exact one, biased cases are where they claim to be, and shrinking reaches the simplest mechanism.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <functional>

#include "linkproof/testing/generators.h"
#include "linkproof/testing/truth.h"

namespace linkproof::testing {
namespace {

/// Greedy shrinking as RapidCheck does it: from the generated value, keep taking the first
/// shrink that still satisfies `fails` until none does. Returns the final value.
template <class T>
T shrink_greedily(const rc::Gen<T>& gen, int seed, const std::function<bool(const T&)>& fails) {
  rc::Shrinkable<T> s = gen(rc::Random(static_cast<uint64_t>(seed)), rc::kNominalSize);
  for (int guard = 0; guard < 100000; ++guard) {
    bool moved = false;
    auto shrinks = s.shrinks();
    while (auto next = shrinks.next()) {
      if (fails(next->value())) {
        s = *next;
        moved = true;
        break;
      }
    }
    if (!moved) break;
  }
  return s.value();
}

void expect_double_bounds_exact(const MechanismTruth& t) {
  for (const LinkTruth& l : t.links) {
    const Rational err = cln::abs(rational_from_double(l.alpha_double.value) - l.alpha);
    RC_ASSERT(err <= rational_from_double(l.alpha_double.bound));
    const Rational werr = cln::abs(rational_from_double(l.omega_double.value) - l.omega);
    RC_ASSERT(werr <= rational_from_double(l.omega_double.bound));
  }
}

RC_GTEST_PROP(TestingGenerators, EveryMechanismIsWellPosedAndItsDoubleTruthBoundsTheExact, ()) {
  MechanismOptions o;
  o.bias = Bias::Any;
  const MechanismCase c = *gen_mechanism(o);
  classify_case(c);
  RC_ASSERT(is_well_posed(c.scene));
  expect_double_bounds_exact(compute_truth(c.scene));
}

RC_GTEST_PROP(TestingGenerators, PolygonsHaveNoDeadCentreAndTheirShapeHolds, ()) {
  PolygonOptions o;
  o.bias = Bias::Any;
  const PolygonCase c = *gen_polygon(o);
  classify_case(c);
  RC_ASSERT(c.polygon.n() >= o.n_min && c.polygon.n() <= o.n_max);
  RC_ASSERT(!cln::zerop(c.polygon.dead_centre_determinant()));
  RC_ASSERT(c.rates.omega.size() == static_cast<size_t>(c.polygon.n() - 3));
  if (c.family.find("/convex/") != std::string::npos && c.family.find("/n=") != std::string::npos &&
      c.family.find("-1e") == std::string::npos && c.family.find("ratio") == std::string::npos) {
    // Unbiased convex polygons turn the same way at every joint.
    const int n = c.polygon.n();
    int sign = 0;
    for (int j = 1; j <= n; ++j) {
      const Rational t = cross(c.polygon.side(j), c.polygon.side(j % n + 1));
      const int s = cln::minusp(t) ? -1 : 1;
      RC_ASSERT(!cln::zerop(t));
      if (sign == 0) sign = s;
      RC_ASSERT(s == sign);
    }
  }
}

RC_GTEST_PROP(TestingGenerators, FourBarsHaveTheRequestedGrashofClass, ()) {
  const auto cls = *rc::gen::element(GrashofClass::CrankRocker, GrashofClass::DoubleCrank, GrashofClass::DoubleRocker,
                                     GrashofClass::ChangePoint, GrashofClass::TripleRocker);
  const MechanismCase c = *gen_fourbar(cls);
  classify_case(c);
  const auto& g = c.scene.linkage;
  RC_ASSERT(classify_grashof(g.joint(0).at, g.joint(1).at, g.joint(2).at, g.joint(3).at) == cls);
}

TEST(TestingGenerators, NearDeadCentreBiasMakesTheDeterminantSmall) {
  PolygonOptions o;
  o.bias = Bias::NearDeadCentre;
  o.shape = PolygonShape::Scattered;
  for (int seed = 1; seed <= 20; ++seed) {
    const PolygonCase c = gen_polygon(o)(rc::Random(static_cast<uint64_t>(seed)), rc::kNominalSize).value();
    const int n = c.polygon.n();
    // |D| / (|r_{n-2}| |r_{n-1}|) is the sine of the angle at K_{n-1}: far below an ordinary one.
    const double d = cln::double_approx(c.polygon.dead_centre_determinant());
    const double a = std::sqrt(cln::double_approx(norm2(c.polygon.side(n - 2))));
    const double b = std::sqrt(cln::double_approx(norm2(c.polygon.side(n - 1))));
    EXPECT_LT(std::abs(d) / (a * b), 1e-1) << c.family << " seed " << seed;
    EXPECT_NE(c.family.find("near-dead-centre"), std::string::npos) << c.family;
  }
}

TEST(TestingGenerators, ShrinkingReachesAFourBarWithSmallCoordinates) {
  // A property that fails on every mechanism shrinks to the simplest one: a four-bar (the first
  // family), coordinates of magnitude <= 2 and rates 0 or small.
  for (int seed = 1; seed <= 5; ++seed) {
    const MechanismCase c = shrink_greedily<MechanismCase>(gen_mechanism(), seed, [](const MechanismCase&) { return true; });
    EXPECT_EQ(c.scene.linkage.link_count(), 4) << "seed " << seed << ": " << c.family;
    EXPECT_EQ(c.family.rfind("fourbar/", 0), 0u) << c.family;
    for (const auto& j : c.scene.linkage.joints()) {
      EXPECT_LE(cln::abs(j.at.x), 2) << c.family;
      EXPECT_LE(cln::abs(j.at.y), 2) << c.family;
    }
    EXPECT_TRUE(cln::zerop(c.scene.inputs[0].rate_dot)) << c.family;
  }
}

TEST(TestingGenerators, ShrinkingKeepsOnlyWhatTheFailureNeeds) {
  // Failing only on six-bars or larger: the shrunk case is a six-bar (the first family with 6 links).
  const auto big = [](const MechanismCase& c) { return c.scene.linkage.link_count() >= 6; };
  for (int seed = 1; seed <= 40; ++seed) {
    const rc::Gen<MechanismCase> g = gen_mechanism();
    if (!big(g(rc::Random(static_cast<uint64_t>(seed)), rc::kNominalSize).value())) continue;
    const MechanismCase c = shrink_greedily<MechanismCase>(g, seed, big);
    EXPECT_EQ(c.scene.linkage.link_count(), 6) << c.family;
    EXPECT_EQ(c.family, "sixbar/watt-i") << "the first six-bar family";
    return;
  }
  FAIL() << "no seed in 1..40 drew a mechanism with 6 or more links";
}

}  // namespace
}  // namespace linkproof::testing
