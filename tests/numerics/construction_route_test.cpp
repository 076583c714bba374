// The construction route (numerics/routes.h, compute_by_construction) runs the paper's construction
// for each four-bar j through construct_four_bar_steps with plain values, and builds the named
// construct_four_bar only where a step is undefined. These tests pin down that this fast path
// computes what reading i_{n-1,j}, i_{n-2,j}, lambda_j, mu_j off construct_four_bar(p, j) for each
// j computes (bit for bit in floating point, exactly in Rational), and that where the
// construction breaks (conventions §A6) it names the same quantity for the same reason.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>

#include "core/multiprecision.h"
#include "numerics/extreme_families.h"
#include "numerics/ladder.h"
#include "check/random_polygon.h"
#include "numerics/routes.h"
#include "linkproof/io/scene.h"

namespace linkproof {
namespace {

/// Seed of the random polygons (replay: generate_random_polygon(kConstructionRouteSeed, n, index)).
constexpr std::uint64_t kConstructionRouteSeed = 19660315;

/// The construction route as it was before the fast path: construct_four_bar for each j, its
/// Defined values read in the order i_{n-1,j}, i_{n-2,j}, lambda_j, mu_j (the first undefined one
/// is thrown), then eq. (22) and the companion. The reference the fast path must reproduce.
template <class T>
RouteValue<T> route_by_construct_four_bar(const Polygon<T>& p, const InputRates<T>& in) {
  const int n = p.n();
  const Vec2<T> a = p.side(n - 2), b = p.side(n - 1);
  const T D = cross(a, b);
  if (linkproof::is_zero(D)) throw dead_centre_error();
  DijksmanAccumulator<T> acc;
  for (int j = 1; j <= n - 3; ++j) {
    const FourBarConstruction<T> c = construct_four_bar(p, j);
    const auto k = static_cast<size_t>(j - 1);
    const T& i_out = c.i_out.get();
    const T& i_cpl = c.i_cpl.get();
    const T& lambda = c.lambda.get();
    const T& mu = c.mu.get();
    acc.add(in.omega[k], in.omega_dot[k], i_out, i_cpl, lambda, mu);
  }
  return acc.finish(dot(a, b) / D, norm2(a) / D, norm2(b) / D);
}

/// The same number, bit for bit for IEEE types (sign of zero included), exactly otherwise.
template <class T>
bool identical(const T& a, const T& b) {
  if constexpr (std::is_floating_point_v<T>)
    return (a == b && std::signbit(a) == std::signbit(b)) || (std::isnan(a) && std::isnan(b));
  else if constexpr (requires { a.v, a.e; })
    return identical(a.v, b.v) && identical(a.e, b.e);
  else if constexpr (requires { a.value(); })
    return a.value() == b.value();  // MpFloat: the CLN floats, compared exactly
  else
    return a == b;
}

/// What a route gives: the two values, or the undefined quantity and its reason.
template <class T>
struct Outcome {
  std::optional<RouteValue<T>> value;
  std::string quantity, reason;
};

template <class T, class F>
Outcome<T> outcome_of(const F& route) {
  Outcome<T> o;
  try {
    o.value = route();
  } catch (const UndefinedQuantity& u) {
    o.quantity = u.quantity();
    o.reason = u.reason();
  }
  return o;
}

/// The configuration as exact rationals, for failure messages.
std::string describe(const Polygon<Rational>& p, const InputRates<Rational>& in) {
  std::string s = "K =";
  for (const auto& k : p.joints()) s += " (" + format_rational(k.x) + ", " + format_rational(k.y) + ")";
  s += "; omega =";
  for (const auto& w : in.omega) s += " " + format_rational(w);
  s += "; omega_dot =";
  for (const auto& w : in.omega_dot) s += " " + format_rational(w);
  return s;
}

/// The fast route and the reference on one exact configuration converted to T: both undefined
/// with the same name and reason, or both defined with identical values. Returns whether the
/// construction was undefined.
template <class T>
bool expect_route_matches_reference(const Polygon<Rational>& exact_p, const InputRates<Rational>& exact_in) {
  SCOPED_TRACE(std::string(arithmetic_name<T>()) + ": " + describe(exact_p, exact_in));
  const Polygon<T> p = exact_p.convert<T>();
  const InputRates<T> in = exact_in.convert<T>();
  const Outcome<T> fast = outcome_of<T>([&] { return compute_by_construction(p, in); });
  const Outcome<T> ref = outcome_of<T>([&] { return route_by_construct_four_bar(p, in); });
  EXPECT_EQ(fast.value.has_value(), ref.value.has_value());
  EXPECT_EQ(fast.quantity, ref.quantity);
  EXPECT_EQ(fast.reason, ref.reason);
  if (fast.value && ref.value) {
    EXPECT_TRUE(identical(fast.value->omega_dot_n1, ref.value->omega_dot_n1))
        << to_text(fast.value->omega_dot_n1) << " vs " << to_text(ref.value->omega_dot_n1);
    EXPECT_TRUE(identical(fast.value->omega_dot_n2, ref.value->omega_dot_n2))
        << to_text(fast.value->omega_dot_n2) << " vs " << to_text(ref.value->omega_dot_n2);
  }
  return !ref.value.has_value();
}

template <class T>
class ConstructionRoute : public ::testing::Test {};

using RouteTypes = ::testing::Types<double, long double, Tracked<double>, MpFloat<30>, Rational>;
TYPED_TEST_SUITE(ConstructionRoute, RouteTypes);

TYPED_TEST(ConstructionRoute, StepsGiveConstructFourBarsValuesForEveryJOnRandomPolygons) {
  using T = TypeParam;
  SCOPED_TRACE("seed " + std::to_string(kConstructionRouteSeed));
  for (int n : {4, 5, 7, 12}) {
    for (int i = 0; i < 12; ++i) {
      const RandomPolygonCase rc = generate_random_polygon(kConstructionRouteSeed, n, i);
      SCOPED_TRACE("n " + std::to_string(n) + ", index " + std::to_string(i) + ": " + describe(rc.polygon, rc.rates));
      const Polygon<T> p = rc.polygon.convert<T>();
      const FourBarFrame<T> frame = make_four_bar_frame(p);
      for (int j = 1; j <= n - 3; ++j) {
        SCOPED_TRACE("j " + std::to_string(j));
        const FourBarSteps<T> s = construct_four_bar_steps(frame, p.joint(j), p.side(j));
        const FourBarConstruction<T> c = construct_four_bar(p, j);
        const auto same = [](const Defined<T>& d, StepStatus st, const T& v) {
          return d.has_value() == (st == StepStatus::defined) && (!d.has_value() || identical(d.get(), v));
        };
        EXPECT_TRUE(same(c.i_out, s.i_out_status, s.i_out));
        EXPECT_TRUE(same(c.i_cpl, s.i_cpl_status, s.i_cpl));
        EXPECT_TRUE(same(c.cot_beta, s.beta_status, s.cot_beta));
        EXPECT_TRUE(same(c.cot_gamma, s.gamma_status, s.cot_gamma));
        EXPECT_EQ(c.lambda.has_value() && c.mu.has_value(), s.coefficients_defined);
        if (c.lambda.has_value()) {
          EXPECT_TRUE(identical(c.lambda.get(), s.lambda));
        }
        if (c.mu.has_value()) {
          EXPECT_TRUE(identical(c.mu.get(), s.mu));
        }
      }
    }
  }
}

TYPED_TEST(ConstructionRoute, FastRouteEqualsConstructFourBarRouteOnRandomPolygons) {
  SCOPED_TRACE("seed " + std::to_string(kConstructionRouteSeed));
  int undefined = 0;
  for (int n : {4, 5, 6, 7, 12, 40}) {
    for (int i = 0; i < 24; ++i) {
      const RandomPolygonCase rc = generate_random_polygon(kConstructionRouteSeed, n, i);
      SCOPED_TRACE("n " + std::to_string(n) + ", index " + std::to_string(i));
      undefined += expect_route_matches_reference<TypeParam>(rc.polygon, rc.rates);
    }
  }
  this->RecordProperty("undefined_cases", undefined);
}

/// Every degeneracy family of conventions §A6 (numerics/extreme_families.h) at epsilon = 0, where the
/// construction breaks, and next to it.
TYPED_TEST(ConstructionRoute, FastRouteEqualsConstructFourBarRouteOnEveryDegeneracyFamily) {
  for (const ExtremeFamily& f : extreme_families()) {
    if (f.degenerate_quantity.empty()) continue;
    SCOPED_TRACE(f.name);
    for (const Rational& eps : {Rational(0), Rational(1) / 1000000, Rational(1) / 100000000000LL}) {
      const ExtremeCase c = f.make(eps);
      expect_route_matches_reference<TypeParam>(c.polygon, c.rates);
    }
  }
}

// Exactly at each degeneracy (Rational), the quantity and the reason the construction route
// names, as it named them before the fast path: the bundled scenes of verify/scenes/degenerate
// and the families of numerics/extreme_families.h at epsilon = 0.
struct ExpectedUndefined {
  const char* source;  ///< scene file or family name
  const char* quantity;
  const char* reason;
};

constexpr ExpectedUndefined kScenes[] = {
    {"beta_undefined.yaml", "beta_1", "rays Q_1K_{n-1} and Q_1P'_1 are collinear: the angle is 0 or pi, its cotangent infinite"},
    {"dead_centre.yaml", "D = r_{n-2} x r_{n-1}", "dead centre: sides n-2 and n-1 are parallel, omega ~ 1/D, omega-dot ~ 1/D^3"},
    {"k_prime_at_ground.yaml", "Q_1", "K'_1 coincides with K_n: the ground line K_nK'_1 is undefined"},
    {"p_prime_at_infinity.yaml", "P'_2", "lines K_{n-1}K_n and K'_2K_{n-2} are parallel: the point is at infinity"},
    {"q_at_infinity.yaml", "Q_1", "lines K_{n-2}K_{n-1} and K_nK'_1 are parallel: the point is at infinity"},
    {"q_at_joint.yaml", "beta_1", "a ray of rays Q_1K_{n-1} and Q_1P'_1 is null (its end coincides with the vertex)"},
};

constexpr ExpectedUndefined kFamilies[] = {
    {"dead_centre", "D = r_{n-2} x r_{n-1}", "dead centre: sides n-2 and n-1 are parallel, omega ~ 1/D, omega-dot ~ 1/D^3"},
    {"q_infinity", "Q_1", "lines K_{n-2}K_{n-1} and K_nK'_1 are parallel: the point is at infinity"},
    {"beta_zero", "beta_1", "rays Q_1K_{n-1} and Q_1P'_1 are collinear: the angle is 0 or pi, its cotangent infinite"},
    {"p_infinity", "P'_1", "lines K_{n-1}K_n and K'_1K_{n-2} are parallel: the point is at infinity"},
    {"q_at_k", "beta_1", "a ray of rays Q_1K_{n-1} and Q_1P'_1 is null (its end coincides with the vertex)"},
    {"kprime_at_kn", "Q_1", "K'_1 coincides with K_n: the ground line K_nK'_1 is undefined"},
};

void expect_names(const ExpectedUndefined& e, const Polygon<Rational>& p, const InputRates<Rational>& in) {
  SCOPED_TRACE(std::string(e.source) + ": " + describe(p, in));
  EXPECT_TRUE(expect_route_matches_reference<Rational>(p, in));
  try {
    (void)compute_by_construction(p, in);
    ADD_FAILURE() << "the construction route exists";
  } catch (const UndefinedQuantity& u) {
    EXPECT_EQ(u.quantity(), e.quantity);
    EXPECT_EQ(u.reason(), e.reason);
  }
}

TEST(ConstructionRoute, NamesTheUndefinedQuantityOfEveryDegenerateScene) {
  const std::string dir = std::string(LINKPROOF_SOURCE_DIR) + "/verify/scenes/degenerate/";
  for (const ExpectedUndefined& e : kScenes) {
    const PolygonScene s = load_polygon_scene(dir + e.source);
    expect_names(e, s.polygon, s.rates);
  }
}

TEST(ConstructionRoute, NamesTheUndefinedQuantityOfEveryDegeneracyFamilyAtEpsilonZero) {
  int checked = 0;
  for (const ExpectedUndefined& e : kFamilies) {
    const ExtremeFamily* f = find_extreme_family(e.source);
    ASSERT_NE(f, nullptr) << e.source;
    EXPECT_EQ(f->degenerate_quantity, e.quantity);
    const ExtremeCase c = f->make(0);
    expect_names(e, c.polygon, c.rates);
    ++checked;
  }
  EXPECT_EQ(checked, 6);
}

}  // namespace
}  // namespace linkproof
