// Tracked<F>: the radius bounds the true error, checked against exact rationals, for every F
// (IEEE double and long double, CLN long floats at 128 and 3392 bits) through one template.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cln/integer.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <random>

#include "claims/polygon_context.h"
#include "core/multiprecision.h"
#include "core/scalar.h"
#include "check/arithmetic_types.h"
#include "check/random_polygon.h"
#include "geometry/closed_forms.h"
#include "linkproof/io/scene.h"

namespace linkproof {
namespace {

template <class F>
Rational radius_value(const double& e) { return exact_value_of(e); }
template <class F>
Rational radius_value(const long double& e) { return exact_value_of(e); }
template <class F>
Rational radius_value(const WideBound& e) { return e.to_rational(); }

/// |exact - v| <= e, decided exactly (an unbounded radius encloses everything).
template <class F>
bool encloses(const Tracked<F>& t, const Rational& exact) {
  if (TrackedTraits<F>::is_unbounded(t.e)) return true;
  return cln::abs(exact - ScalarTraits<F>::to_rational(t.v)) <= radius_value<F>(t.e);
}

/// e <= 2^(slack - p) |exact|: the bound is tight, not merely true.
template <class F>
bool is_tight(const Tracked<F>& t, const Rational& exact, int slack_bits) {
  if (TrackedTraits<F>::is_unbounded(t.e)) return false;
  const int p = TrackedTraits<F>::precision_bits();
  return radius_value<F>(t.e) <= cln::abs(exact) / cln::ash(cln::cl_I(1), p - slack_bits);
}

TEST(Tracked, ConversionRadiusIsTheExactRoundingError) {
  const auto t = ScalarTraits<Tracked<double>>::from_rational(Rational(1) / 10);
  EXPECT_EQ(t.v, 0.1);
  EXPECT_GT(t.e, 0.0);
  EXPECT_LT(t.e, 1e-17);
  const auto exact = ScalarTraits<Tracked<double>>::from_rational(Rational(3) / 4);
  EXPECT_EQ(exact.e, 0.0);
}

TEST(Tracked, DivisionByAnIntervalContainingZeroIsUnbounded) {
  const Tracked<double> a{1.0, 0.0}, b{1e-20, 1e-19};
  EXPECT_FALSE(std::isfinite((a / b).e));
}

RC_GTEST_PROP(Tracked, BoundEnclosesTheExactClosedFormMotion, ()) {
  const int n = *rc::gen::inRange(4, 10);
  const int index = *rc::gen::inRange(0, 1000);
  const auto rc_case = generate_random_polygon(7, n, index);
  const auto exact = compute_closed_form_motion(rc_case.polygon, rc_case.rates);
  const auto tracked = compute_closed_form_motion(rc_case.polygon.convert<Tracked<double>>(),
                                                  rc_case.rates.convert<Tracked<double>>());
  for (int j = 0; j < n; ++j) {
    RC_ASSERT(encloses(tracked.omega[j], exact.omega[j]));
    RC_ASSERT(encloses(tracked.omega_dot[j], exact.omega_dot[j]));
  }
}

// --- One typed test per arithmetic ------------------------------------------------------------

template <class F>
class TrackedTyped : public ::testing::Test {};
using TrackedFloats = ::testing::Types<double, long double, MpFloat<30>, MpFloat<1000>>;
TYPED_TEST_SUITE(TrackedTyped, TrackedFloats);

TYPED_TEST(TrackedTyped, UnitRoundoffIsTwoToMinusPrecision) {
  using TT = TrackedTraits<TypeParam>;
  EXPECT_EQ(radius_value<TypeParam>(TT::unit_roundoff()), 1 / Rational(cln::ash(cln::cl_I(1), TT::precision_bits())));
  if constexpr (!std::is_floating_point_v<TypeParam>) {
    EXPECT_EQ(TT::precision_bits(), TypeParam::precision_bits());
  }
}

TYPED_TEST(TrackedTyped, ExactInputsHaveZeroRadiusAndRoundedOnesTheirRoundingError) {
  using T = Tracked<TypeParam>;
  const T exact = ScalarTraits<T>::from_rational(Rational(-3) / 4);
  EXPECT_TRUE(exact.e == typename T::Radius{});
  EXPECT_TRUE(is_zero(ScalarTraits<T>::from_rational(0)));
  const Rational third = Rational(1) / 3;
  const T t = ScalarTraits<T>::from_rational(third);
  EXPECT_TRUE(encloses(t, third));
  EXPECT_TRUE(is_tight(t, third, 2));
  EXPECT_FALSE(is_zero(t));
}

TYPED_TEST(TrackedTyped, DivisionByAnIntervalContainingZeroIsUnboundedNeverAnException) {
  using T = Tracked<TypeParam>;
  using TT = TrackedTraits<TypeParam>;
  const T one = ScalarTraits<T>::from_rational(1);
  const T tiny = ScalarTraits<T>::from_rational(Rational(1) / 3 / cln::ash(cln::cl_I(1), 200));
  // tiny - tiny: midpoint exactly 0 with a positive radius. CLN would throw on x / 0.
  const T zero_ish = tiny - tiny;
  EXPECT_TRUE(TT::is_unbounded((one / zero_ish).e));
  EXPECT_FALSE(TT::is_unbounded((one / tiny).e));
  // Unbounded stays unbounded through further operations.
  const T q = one / zero_ish;
  EXPECT_TRUE(TT::is_unbounded((q * ScalarTraits<T>::from_rational(0)).e));
  EXPECT_TRUE(TT::is_unbounded((q + one).e));
}

/// A random straight-line program of + - * / over random rationals, evaluated exactly and in
/// Tracked<F>: every intermediate is enclosed. Operands span 2^-60..2^60, cancellations and
/// divisions by small differences occur; the seed is in the failure message.
template <class F>
void check_random_program(std::uint64_t seed) {
  using T = Tracked<F>;
  std::mt19937_64 g(seed);
  const auto rnd = [&](long lo, long hi) { return std::uniform_int_distribution<long>(lo, hi)(g); };
  std::vector<Rational> exact;
  std::vector<T> tracked;
  for (int i = 0; i < 5; ++i) {
    const long k = rnd(-60, 60);
    const Rational scale = k >= 0 ? Rational(cln::ash(cln::cl_I(1), k)) : 1 / Rational(cln::ash(cln::cl_I(1), -k));
    const Rational q = Rational(rnd(-1000000, 1000000)) / Rational(rnd(1, 1000000)) * scale;
    exact.push_back(q);
    tracked.push_back(ScalarTraits<T>::from_rational(q));
  }
  for (int step = 0; step < 14; ++step) {
    const size_t a = static_cast<size_t>(rnd(0, static_cast<long>(exact.size()) - 1));
    size_t b = static_cast<size_t>(rnd(0, static_cast<long>(exact.size()) - 1));
    switch (rnd(0, 4)) {
      case 0: exact.push_back(exact[a] + exact[b]), tracked.push_back(tracked[a] + tracked[b]); break;
      case 1: exact.push_back(exact[a] - exact[b]), tracked.push_back(tracked[a] - tracked[b]); break;
      case 2: exact.push_back(exact[a] * exact[b]), tracked.push_back(tracked[a] * tracked[b]); break;
      case 3:
        if (cln::zerop(exact[b])) continue;
        exact.push_back(exact[a] / exact[b]), tracked.push_back(tracked[a] / tracked[b]);
        break;
      default: {  // a - (a + small): cancellation, then divide by it
        const Rational d = exact[a] - (exact[a] + exact[b] / 1000000);
        if (cln::zerop(d)) continue;
        const T td = tracked[a] - (tracked[a] + tracked[b] / ScalarTraits<T>::from_rational(1000000));
        exact.push_back(exact[a] / d), tracked.push_back(tracked[a] / td);
      }
    }
  }
  for (size_t i = 0; i < exact.size(); ++i)
    ASSERT_TRUE(encloses(tracked[i], exact[i])) << "seed " << seed << ", value " << i << ": exact " << format_rational(exact[i])
                                                << ", midpoint " << to_text(tracked[i]);
}

TYPED_TEST(TrackedTyped, RadiusEnclosesTheExactValueOfRandomPrograms) {
  for (std::uint64_t seed = 1; seed <= 150; ++seed) check_random_program<TypeParam>(seed);
}

// The pentagon of conventions §A8, read from the bundled scene: truth, closed forms and construction in
// Tracked<F> enclose the exact values printed in conventions §A8, with a tight radius.
TYPED_TEST(TrackedTyped, PentagonValuesOfConventionsA8AreEnclosedTightly) {
  using T = Tracked<TypeParam>;
  const PolygonScene s = load_polygon_scene(std::string(LINKPROOF_SOURCE_DIR) + "/verify/scenes/pentagon.yaml");
  GroundTruthEngine engine;
  const PolygonContext<T> c = build_polygon_context<T>(engine, s.polygon, s.rates);
  const auto q = [](long p, long d) { return Rational(p) / d; };
  const auto check = [](const T& t, const Rational& exact, const char* what) {
    EXPECT_TRUE(encloses(t, exact)) << what << ": " << to_text(t) << " vs " << format_rational(exact);
    EXPECT_TRUE(is_tight(t, exact, 16)) << what;
  };
  const auto& m = c.truth().get();
  check(m.omega[2], q(17, 11), "omega_3");
  check(m.omega[3], q(3, 11), "omega_4");
  check(m.omega_dot[2], q(7331, 2662), "omega_dot_3");
  check(m.omega_dot[3], q(3755, 1331), "omega_dot_4");
  const auto& cf = c.closed().get();
  check(cf.D, -22, "D");
  check(cf.cot_phi, q(-2, 11), "cot phi");
  check(cf.rho, q(-10, 11), "|r_3|^2/D");
  check(cf.i_out[0], q(6, 11), "i_41");
  check(cf.i_cpl[0], q(13, 22), "i_31");
  check(cf.lambda[0], q(-705, 2662), "lambda_1");
  check(cf.i_out[1], q(9, 11), "i_42");
  check(cf.i_cpl[1], q(-4, 11), "i_32");
  check(cf.lambda[1], q(564, 1331), "lambda_2");
  check(c.construction_for()[0].cot_beta.get(), q(-47, 44), "cot beta_1 (construction)");
  check(c.construction_for()[1].cot_beta.get(), q(94, 33), "cot beta_2 (construction)");
  check(c.construction_for()[0].lambda.get(), q(-705, 2662), "lambda_1 (construction)");
}

// A divisor's margin |v| - e must never be overestimated (the quotient's radius divides by
// it): both the fast path (e <= |v|/1024, no CLN operation) and the exact one in F.
RC_GTEST_PROP(TrackedMp, MarginIsALowerBoundOfTheDistanceFromZero, ()) {
  using F = MpFloat<30>;
  const long k = *rc::gen::inRange<long>(-3000, 3000);
  const Rational scale = k >= 0 ? Rational(cln::ash(cln::cl_I(1), k)) : 1 / Rational(cln::ash(cln::cl_I(1), -k));
  const Rational q = Rational(*rc::gen::inRange<long>(-(1L << 50), 1L << 50)) / 3 * scale;
  const F v(q);
  const Rational abs_v = cln::abs(ScalarTraits<F>::to_rational(v));
  // e = |v| times a random fraction in [2^-70, 1.5]
  const Rational fraction = Rational(*rc::gen::inRange<long>(1, 3L << 40)) / Rational(cln::ash(cln::cl_I(1), *rc::gen::inRange(41, 111)));
  const WideBound e = WideBound::from_rational_up(abs_v * fraction);
  const WideBound m = TrackedTraits<F>::margin(v, e);
  const Rational exact = abs_v - e.to_rational();
  if (exact <= 0) {
    RC_ASSERT(m.is_zero());
  } else {
    RC_ASSERT(m.to_rational() <= exact);
    if (e.to_rational() <= abs_v / 2) RC_ASSERT(m.to_rational() >= exact * 255 / 256);
  }
}

// CLN long floats have a 64-bit exponent: values far below double's range keep a tight
// radius (the WideBound radius never underflows), and nothing is flushed to zero.
TEST(TrackedMp, TinyAndHugeMagnitudesKeepTightBounds) {
  using T = Tracked<MpFloat<30>>;
  const Rational tiny = Rational(1) / 7 / cln::ash(cln::cl_I(1), 5000);
  const Rational huge = Rational(5) / 3 * cln::ash(cln::cl_I(1), 5000);
  const T a = ScalarTraits<T>::from_rational(tiny), b = ScalarTraits<T>::from_rational(huge);
  const T c = (a * a) / (b + a) - a;
  const Rational exact = (tiny * tiny) / (huge + tiny) - tiny;
  EXPECT_TRUE(encloses(c, exact));
  EXPECT_TRUE(is_tight(c, exact, 8));
  EXPECT_FALSE(cln::cl_inhibit_floating_point_underflow);  // the radius relies on CLN throwing
}

}  // namespace
}  // namespace linkproof

namespace linkproof {
namespace {

// from_int takes a short cut for tracked IEEE types (the claim evaluator makes a 1 per rate
// variable); it must give exactly what the conversion through a Rational gives, radius included,
// on both sides of 2^53 (past it the short cut does not apply and the radius is the rounding).
template <class F>
void expect_from_int_is_from_rational() {
  const long big = 1L << 53;
  for (long k : {0L, 1L, -1L, 7L, -12345L, big - 1, big, -big, big + 1, -(big + 1), big * 4 + 3}) {
    const Tracked<F> fast = from_int<Tracked<F>>(k);
    const Tracked<F> slow = ScalarTraits<Tracked<F>>::from_rational(Rational(k));
    EXPECT_EQ(fast.v, slow.v) << "k = " << k;
    EXPECT_TRUE(fast.e == slow.e) << "k = " << k;
  }
}

// A zero operand makes a result exact (x * 0, 0 / x, x - x of exact x, x + 0), and its radius
// stays 0: it was the least subnormal (one upward step from 0), and every later product with a
// subnormal radius took a microcode assist of about 70 ns on x86 (half the time of a double
// four-bar sample). An exact 0 is also what makes a relative rate of a link with itself, or an
// exact zero pivot, decidable in floating point.
TYPED_TEST(TrackedTyped, AZeroOperandKeepsTheRadiusAnExactZero) {
  using T = Tracked<TypeParam>;
  using Radius = typename T::Radius;
  const T zero(0), three(3), x = ScalarTraits<T>::from_rational(Rational(1) / 3);
  ASSERT_NE(x.e, Radius{});
  for (const T& r : {zero * x, x * zero, zero * three, zero / x, three - three, zero + zero, zero - zero})
    EXPECT_TRUE(r.e == Radius{});
  EXPECT_TRUE(ScalarTraits<T>::is_zero(zero * x));
  EXPECT_FALSE(ScalarTraits<T>::is_zero(x - x)) << "x has a radius: x - x is 0 within it, not known to be 0";
}

// A quotient of exact operands spreads no input error: its radius is its own rounding error
// (the shortcut that skips the second division). A NaN radius is not "no error" and stays NaN.
TEST(TrackedDivision, ExactOperandsGiveTheRoundingErrorAloneAndANaNRadiusIsKept) {
  const Tracked<double> one(1), three(3);
  const Tracked<double> q = one / three;
  EXPECT_EQ(q.v, 1.0 / 3.0);
  EXPECT_EQ(q.e, TrackedTraits<double>::rounding_error(q.v));
  const Tracked<double> unknown(1.0, std::numeric_limits<double>::quiet_NaN());
  EXPECT_FALSE(std::isfinite((unknown / three).e));
  EXPECT_EQ((Tracked<double>(6) / three).e, TrackedTraits<double>::rounding_error(2.0)) << "6 / 3 = 2 in double";
}

TEST(TrackedFromInt, SmallIntegersAreExactWithZeroRadiusAsThroughARational) {
  expect_from_int_is_from_rational<double>();
  expect_from_int_is_from_rational<long double>();
}

// The fast path of Tracked<double>::from_rational for p/q with |p|, q < 2^53 (IEEE division and an
// exact fma remainder, no CLN arithmetic) against the exact rounding error: the same midpoint as
// round_rational, a radius that is >= |q - v|, 0 exactly when v = q, and at most one step above
// the exact error rounded to nearest.
TEST(TrackedFromRational, SmallFractionsGetTheCorrectlyRoundedMidpointAndTheExactErrorRoundedUp) {
  const unsigned seed = 20261127;
  std::mt19937_64 g(seed);
  const std::int64_t top = std::int64_t{1} << 53;
  for (int i = 0; i < 20000; ++i) {
    // Small and large numerators and denominators, powers of two among them.
    const int pb = 1 + static_cast<int>(g() % 53), qb = 1 + static_cast<int>(g() % 53);
    std::int64_t p = static_cast<std::int64_t>(g() % static_cast<std::uint64_t>(std::int64_t{1} << pb));
    std::int64_t d = 1 + static_cast<std::int64_t>(g() % static_cast<std::uint64_t>((std::int64_t{1} << qb) - 1));
    if (i % 7 == 0) d = std::int64_t{1} << (g() % 53);
    if (g() % 2) p = -p;
    ASSERT_LT(std::abs(p), top);
    ASSERT_LT(d, top);
    const Rational q = Rational(cln::cl_I(static_cast<long>(p))) / cln::cl_I(static_cast<long>(d));
    const Tracked<double> t = from_rational<Tracked<double>>(q);
    const double v = round_rational<double>(q);
    const Rational err = cln::abs(q - exact_value_of(t.v));
    ASSERT_EQ(t.v, v) << "seed " << seed << ", " << p << "/" << d;
    ASSERT_GE(exact_value_of(t.e), err) << "seed " << seed << ", " << p << "/" << d;
    ASSERT_EQ(t.e == 0, cln::zerop(err)) << "seed " << seed << ", " << p << "/" << d;
    if (!cln::zerop(err)) {
      ASSERT_LE(t.e, next_up(next_up(round_rational<double>(err)))) << p << "/" << d;
    }
  }
}


// from_fraction(p, d) is the value from_rational(p/d) gives, radius included, in every
// arithmetic: for fractions not in lowest terms, integers, and numerators beyond 2^53 (where
// Tracked<double> leaves its fast path).
TEST(FromFraction, GivesWhatFromRationalGivesInEveryArithmetic) {
  const unsigned seed = 71;
  std::mt19937_64 g(seed);
  std::vector<std::pair<long, long>> cases{{0, 1}, {0, 7}, {6, 4}, {-2, 6}, {1, 3}, {9, 1}, {-9, 4}, {(1L << 53) + 1, 3},
                                           {-(1L << 60), 7}, {5, 1L << 54}};
  for (int i = 0; i < 2000; ++i) {
    const long p = static_cast<long>(g() % 2000001) - 1000000, d = 1 + static_cast<long>(g() % 1000);
    cases.emplace_back(p, i % 5 == 0 ? 1 : d);
  }
  const auto same = []<class T>(const T& a, const T& b) {
    if constexpr (requires { a.e; }) return to_exact(a) == to_exact(b) && a.e == b.e;
    else return to_exact(a) == to_exact(b);
  };
  std::apply([&]<class... T>(T...) {
    (
        [&] {
          for (const auto& [p, d] : cases)
            ASSERT_TRUE(same(from_fraction<T>(p, d), from_rational<T>(Rational(p) / Rational(d))))
                << ScalarTraits<T>::name << " " << p << "/" << d << ", seed " << seed;
        }(),
        ...);
  }, ArithmeticScalarTypes{});
}

}  // namespace
}  // namespace linkproof
