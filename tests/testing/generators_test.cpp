// linkproof::testing generators: every case is exact and well posed, its double truth bounds the
// exact one, biased cases are where they claim to be, and shrinking reaches the simplest mechanism.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <functional>
#include <sstream>

#include "geometry/construction.h"
#include "linkproof/testing/generators.h"
#include "linkproof/core/exact.h"
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

/// |exact - value| <= bound, decided in rationals; an infinite bound (every digit lost) holds
/// vacuously and is reported to RapidCheck's coverage table.
void expect_double_bounds_exact(const MechanismTruth& t) {
  const auto holds = [](const BoundedDouble& d, const Rational& exact) {
    RC_ASSERT(std::isfinite(d.value));
    if (!std::isfinite(d.bound)) {
      RC_CLASSIFY(true, "a double bound is infinite");
      return;
    }
    RC_ASSERT(cln::abs(rational_from_double(d.value) - exact) <= rational_from_double(d.bound));
  };
  for (const LinkTruth& l : t.links) {
    holds(l.alpha_double, l.alpha);
    holds(l.omega_double, l.omega);
  }
}

// ---- reading a biased case back: the label names the loop, j and the exponent ----

/// The bias exponent k of "...-1e-<k>" (-1 if none).
int exponent_of(const std::string& family) {
  const auto p = family.rfind("-1e-");
  return p == std::string::npos ? -1 : std::stoi(family.substr(p + 4));
}

/// j of "-j<j>-" (0 if none).
int j_of(const std::string& family) {
  const auto p = family.find("-j");
  return p == std::string::npos ? 0 : family[p + 2] - '0';
}

/// The joints K_1..K_n of the loop the label names ("loop-C.D.E.F-"); four-bars' near-toggle
/// label predates the loop name: their loop is O2, A, B, O4.
std::vector<Point> loop_of(const MechanismCase& c) {
  std::string names = "O2.A.B.O4";
  if (const auto p = c.family.find("loop-"); p != std::string::npos)
    names = c.family.substr(p + 5, c.family.find("-1e-", p) - p - 5);
  std::vector<Point> k;
  std::stringstream ss(names);
  for (std::string name; std::getline(ss, name, '.');) {
    const auto j = c.scene.linkage.find_joint(name);
    EXPECT_TRUE(j.has_value()) << name << " in " << c.family;
    if (j) k.push_back(c.scene.linkage.joint(*j).at);
  }
  return k;
}

Rational pow10(int k) { return cln::expt(Rational(10), k); }

/// sin^2 of the angle between a and b, exactly.
Rational sine2(const Point& a, const Point& b) { return cross(a, b) * cross(a, b) / (norm2(a) * norm2(b)); }

/// The largest |coordinate| of the case's joints (at least 1): the size against which 10^-k is read.
Rational scale_of(const MechanismCase& c) {
  Rational s = 1;
  for (const auto& j : c.scene.linkage.joints()) s = cln::max(s, cln::max(cln::abs(j.at.x), cln::abs(j.at.y)));
  return s;
}

/// True if moving joint `joint` by +-delta along x or along y changes the sign of the velocity
/// determinant: a configuration where the input cannot drive lies within delta of the case.
bool singular_within(const MechanismCase& c, const std::string& joint, const Rational& delta) {
  const Linkage& g = c.scene.linkage;
  const auto j = g.find_joint(joint);
  if (!j) return false;
  for (const Point& e : {Point{1, 0}, Point{0, 1}}) {
    std::array<Rational, 2> d;
    for (int s = 0; s < 2; ++s) {
      std::vector<LinkageJoint> joints = g.joints();
      joints[static_cast<size_t>(*j)].at = g.joint(*j).at + (s == 0 ? -delta : delta) * e;
      MechanismScene moved = c.scene;
      moved.linkage = Linkage(g.link_names(), g.ground(), std::move(joints));
      d[static_cast<size_t>(s)] = compute_velocity_determinant(moved);
    }
    if (cln::minusp(d[0] * d[1])) return true;
  }
  return false;
}

MechanismCase draw(const rc::Gen<MechanismCase>& g, int seed) {
  return g(rc::Random(static_cast<uint64_t>(seed)), rc::kNominalSize).value();
}

struct BiasedFamily {
  std::string name;
  std::function<rc::Gen<MechanismCase>(Bias)> gen;
  std::string toggle_joint;  ///< the joint NearDeadCentre moves ("" : named in the label)
};

std::vector<BiasedFamily> loop_families() {
  return {{"fourbar/", [](Bias b) { return gen_fourbar(std::nullopt, b); }, "B"},
          {"sixbar/watt-i/", [](Bias b) { return gen_watt_sixbar(b); }, "E"},
          {"sixbar/stephenson-iii/", [](Bias b) { return gen_stephenson_sixbar(b); }, "F"},
          {"eightbar/fig5/", [](Bias b) { return gen_fig5_eightbar(b); }, ""}};
}

constexpr int kSeeds = 12;

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

TEST(TestingGenerators, NearToggleCasesAreWithin10ToTheMinusKOfADeadPoint) {
  // Loop families: the named loop's D = r_{n-2} x r_{n-1} is ~10^-k of |r_{n-2}||r_{n-1}| (the
  // sine of the angle between them lies in [10^-k/8, 8 10^-k]), and, independently, the velocity
  // determinant of the whole mechanism changes sign when the moved joint moves by 10 10^-k (times
  // the mechanism's size) along x or y: the case is that near a configuration the input cannot drive.
  for (const BiasedFamily& f : loop_families()) {
    for (int seed = 1; seed <= kSeeds; ++seed) {
      const MechanismCase c = draw(f.gen(Bias::NearDeadCentre), seed);
      SCOPED_TRACE(c.family + " seed " + std::to_string(seed));
      ASSERT_EQ(c.family.rfind(f.name, 0), 0u);
      ASSERT_NE(c.family.find("/near-toggle-"), std::string::npos);
      ASSERT_TRUE(is_well_posed(c.scene));
      const int k = exponent_of(c.family);
      ASSERT_GE(k, 2);
      ASSERT_LE(k, 12);
      const Rational eps = Rational(1) / pow10(k);
      std::string joint = f.toggle_joint;
      if (joint.empty()) {  // eight-bar: "/near-toggle-J57-1e-6"
        const auto p = c.family.find("/near-toggle-") + 13;
        joint = c.family.substr(p, c.family.find("-1e-") - p);
      } else {
        const std::vector<Point> k_ = loop_of(c);
        const size_t n = k_.size();
        const Rational s2 = sine2(k_[n - 2] - k_[n - 3], k_[n - 1] - k_[n - 2]);
        EXPECT_LE(s2, Rational(64) * eps * eps);
        EXPECT_GE(s2, eps * eps / Rational(64));
      }
      EXPECT_TRUE(singular_within(c, joint, Rational(10) * eps * scale_of(c))) << c;
    }
  }
}

TEST(TestingGenerators, NearToggleSlidersAreWithin10ToTheMinusKOfADeadPoint) {
  // Slider-crank: the rod within ~10^-k of perpendicular to the guide (cos^2 <= 16 10^-2k).
  // Inverted slider-crank: the block A within ~10^-k of the slot's pivot O4, relative to O2 O4.
  int crank = 0, inverted = 0;
  for (int seed = 1; seed <= 3 * kSeeds; ++seed) {
    const MechanismCase c = draw(gen_slider_mechanism(Bias::NearDeadCentre), seed);
    SCOPED_TRACE(c.family + " seed " + std::to_string(seed));
    ASSERT_NE(c.family.find("/near-toggle-"), std::string::npos);
    ASSERT_TRUE(is_well_posed(c.scene));
    const Rational eps = Rational(1) / pow10(exponent_of(c.family));
    const Linkage& g = c.scene.linkage;
    const auto at = [&](const char* name) { return g.joint(*g.find_joint(name)).at; };
    if (c.family.rfind("slider/crank/", 0) == 0) {
      ++crank;
      const Point rod = at("B") - at("A"), axis = g.joint(*g.find_joint("P")).axis;
      EXPECT_LE(dot(rod, axis) * dot(rod, axis) / (norm2(rod) * norm2(axis)), Rational(16) * eps * eps);
    } else {
      ++inverted;
      EXPECT_LE(norm2(at("A") - at("O4")), Rational(16) * eps * eps * norm2(at("O2") - at("O4"))) << c;
    }
  }
  EXPECT_GT(crank, 0);
  EXPECT_GT(inverted, 0);
}

TEST(TestingGenerators, QFarAndBetaSmallBendTheLoopAndTheJTheLabelNames) {
  // QFar: r_{n-2} nearly parallel to r_j + r_{n-1} (sine in [10^-k/8, 8 10^-k]), so Q_j
  // (geometry/construction.h, on the polygon of the named loop) is far from K_n.
  // BetaSmall: r_j nearly parallel to r_{n-2}, so |tan beta_j| <= 2 10^-k.
  int q_cases = 0, q_near = 0;
  for (const BiasedFamily& f : loop_families()) {
    for (const Bias bias : {Bias::QFar, Bias::BetaSmall}) {
      for (int seed = 1; seed <= kSeeds; ++seed) {
        const MechanismCase c = draw(f.gen(bias), seed);
        SCOPED_TRACE(c.family + " seed " + std::to_string(seed));
        ASSERT_EQ(c.family.rfind(f.name, 0), 0u);
        ASSERT_NE(c.family.find(bias == Bias::QFar ? "/q-far-j" : "/beta-small-j"), std::string::npos);
        ASSERT_TRUE(is_well_posed(c.scene));
        const Rational eps = Rational(1) / pow10(exponent_of(c.family));
        const std::vector<Point> k_ = loop_of(c);
        const Polygon<Rational> poly(k_);
        const int n = poly.n(), j = j_of(c.family);
        ASSERT_GE(j, 1);
        ASSERT_LE(j, n - 3);
        const Point toward = bias == Bias::QFar ? poly.side(j) + poly.side(n - 1) : poly.side(j);
        const Rational s2 = sine2(poly.side(n - 2), toward);
        EXPECT_LE(s2, Rational(64) * eps * eps);
        EXPECT_GE(s2, eps * eps / Rational(64));
        const FourBarConstruction<Rational> fb = construct_four_bar(poly, j);
        if (bias == Bias::QFar) {
          // Q_j is ~10^k times the mechanism's size away unless the two lines that meet there
          // are also nearly one line (D small too): allowed in at most one case in ten.
          ++q_cases;
          const Rational far = pow10(exponent_of(c.family) - 2) * scale_of(c);
          if (norm2(fb.q.get() - poly.joint(n)) < far * far) ++q_near;
        } else {
          EXPECT_GE(cln::abs(fb.cot_beta.get()), Rational(1) / (Rational(2) * eps)) << "tan beta_j <= 2 10^-k";
        }
      }
    }
  }
  EXPECT_LE(10 * q_near, q_cases) << q_near << " of " << q_cases << " QFar cases have |Q_j - K_n| < 10^(k-2) size";
}

TEST(TestingGenerators, BiasesThatAFamilyCannotHaveSaySoInTheLabel) {
  // Sliders have no Dijksman polygon (a prismatic pair); a change-point four-bar's s + l = p + q
  // does not survive moving a joint. The case is ordinary and the label says which bias was refused.
  for (int seed = 1; seed <= kSeeds; ++seed) {
    for (const Bias bias : {Bias::QFar, Bias::BetaSmall}) {
      const MechanismCase c = draw(gen_slider_mechanism(bias), seed);
      EXPECT_TRUE(is_well_posed(c.scene));
      EXPECT_NE(c.family.find(bias == Bias::QFar ? "/q-far-does-not-apply" : "/beta-small-does-not-apply"),
                std::string::npos)
          << c.family;
      EXPECT_EQ(coverage_label(c.family), c.family) << "no exponent to strip";
    }
    const MechanismCase cp = draw(gen_fourbar(GrashofClass::ChangePoint, Bias::NearDeadCentre), seed);
    EXPECT_EQ(cp.family, "fourbar/change-point/near-toggle-does-not-apply");
  }
}

TEST(TestingGenerators, CoverageLabelsNameFamilyBiasLoopAndJWithoutTheExponent) {
  EXPECT_EQ(coverage_label("sixbar/stephenson-iii/q-far-j2-loop-A.B.E.F.G-1e-6"),
            "sixbar/stephenson-iii/q-far-j2-loop-A.B.E.F.G");
  EXPECT_EQ(coverage_label("eightbar/fig5/near-toggle-J57-1e-11"), "eightbar/fig5/near-toggle-J57");
  for (const BiasedFamily& f : loop_families())
    for (const Bias bias : {Bias::NearDeadCentre, Bias::QFar, Bias::BetaSmall}) {
      const std::string label = coverage_label(draw(f.gen(bias), 3).family);
      EXPECT_EQ(label.rfind(f.name, 0), 0u) << label;
      EXPECT_EQ(label.find("1e"), std::string::npos) << label;
    }
}

TEST(TestingGenerators, APlantedFailureOnABiasedFamilyShrinksToExponent2AndSmallCoordinates) {
  // A property that fails on every case of a biased family shrinks (greedily, as RapidCheck
  // does) to the mildest bias, j = 1, zero rates and coordinates of magnitude <= 2 except for the
  // joint the bias places (which stays within a few units).
  struct Run {
    std::string name;
    rc::Gen<MechanismCase> gen;
  };
  std::vector<Run> runs;
  for (const BiasedFamily& f : loop_families())
    for (const Bias bias : {Bias::NearDeadCentre, Bias::QFar, Bias::BetaSmall}) runs.push_back({f.name, f.gen(bias)});
  runs.push_back({"slider/", gen_slider_mechanism(Bias::NearDeadCentre)});
  for (const Run& r : runs) {
    for (int seed = 1; seed <= 3; ++seed) {
      const MechanismCase c = shrink_greedily<MechanismCase>(r.gen, seed, [](const MechanismCase&) { return true; });
      SCOPED_TRACE(c.family + " seed " + std::to_string(seed));
      EXPECT_EQ(c.family.rfind(r.name, 0), 0u);
      EXPECT_EQ(exponent_of(c.family), 2);
      if (c.family.find("-j") != std::string::npos) {
        EXPECT_EQ(j_of(c.family), 1);
      }
      EXPECT_TRUE(cln::zerop(c.scene.inputs[0].rate)) << c;
      EXPECT_TRUE(cln::zerop(c.scene.inputs[0].rate_dot)) << c;
      int large = 0;
      for (const auto& j : c.scene.linkage.joints()) {
        if (cln::abs(j.at.x) > 2 || cln::abs(j.at.y) > 2) ++large;
        EXPECT_LE(cln::abs(j.at.x), 8) << c;
        EXPECT_LE(cln::abs(j.at.y), 8) << c;
      }
      EXPECT_LE(large, 1) << c;
    }
  }
}

RC_GTEST_PROP(TestingGenerators, DoubleTruthBoundsTheExactOnBiasedMultiLoopAndSliderCases, ()) {
  // compute_truth on the biased cases: every link's omega and alpha exact, and the double value's
  // rigorous bound contains the exact value (decided in rationals).
  const Bias bias = *rc::gen::element(Bias::NearDeadCentre, Bias::QFar, Bias::BetaSmall, Bias::ExtremeRatio);
  for (const auto& gen : {gen_watt_sixbar(bias), gen_stephenson_sixbar(bias), gen_fig5_eightbar(bias),
                          gen_slider_mechanism(bias)}) {
    const MechanismCase c = *gen;
    classify_case(c);
    const MechanismTruth t = compute_truth(c.scene);
    RC_ASSERT(t.links.size() == static_cast<size_t>(c.scene.linkage.link_count()));
    expect_double_bounds_exact(t);
  }
}

}  // namespace
}  // namespace linkproof::testing
