#include "core/a_priori_bound.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "core/scalar.h"

namespace linkproof {
namespace {

using S = ShadowedFloat<double>;

/// The bound of x^ against the exact rational value of the same program.
void expect_bound_holds(const S& x, long depth, const Rational& exact) {
  const double bound = a_priori_error_bound(x, depth);
  ASSERT_TRUE(std::isfinite(bound));
  EXPECT_LE(cln::abs(exact_value_of(x.v) - exact), exact_value_of(bound))
      << "value " << x.v << " shadow " << x.m << " depth " << depth;
}

TEST(APrioriBound, DepthFollowsTheOperationTree) {
  const OperationDepth in{0};
  EXPECT_EQ((in * in + in).k, 2);           // a product (1) then a sum
  EXPECT_EQ(((in * in) * (in * in)).k, 3);  // depths of factors add, plus one
  EXPECT_EQ(((in + in) - in).k, 2);         // sums take the maximum, plus one
  EXPECT_EQ((-(in * in)).k, 1);             // negation is exact
}

TEST(APrioriBound, CoversCatastrophicCancellation) {
  // (1 + 2^-30)^2 - 1 - 2^-29 = 2^-60, computed in double with one rounding of the square.
  const S one = S::exact(1), x = S::exact(1 + 0x1p-30), t = S::exact(0x1p-29);
  const S r = x * x - one - t;
  expect_bound_holds(r, 3, Rational(1) / cln::expt_pos(cln::cl_I(2), 60));
}

TEST(APrioriBound, CoversUnderflowOfAProduct) {
  // 2^-600 * 2^-600 underflows to 0 in double; the exact value is 2^-1200.
  const S a = S::exact(0x1p-600);
  const S r = a * a;
  EXPECT_EQ(r.v, 0.0);
  expect_bound_holds(r, 1, Rational(1) / cln::expt_pos(cln::cl_I(2), 1200));
}

TEST(APrioriBound, IsInfiniteWhenTheShadowOverflows) {
  const S big = S::exact(1e300);
  EXPECT_TRUE(std::isinf(a_priori_error_bound(big * big, 1)));
}

/// Random straight-line program: a dot product of length 3 squared minus a product, on random
/// doubles of random scale; depth and exact value computed alongside.
RC_GTEST_PROP(APrioriBound, BoundsTheErrorOfRandomProgramsAgainstExactArithmetic, ()) {
  std::array<double, 7> v{};
  for (double& x : v) {
    const int mantissa = *rc::gen::inRange(-(1 << 20), 1 << 20);
    const int exponent = *rc::gen::inRange(-60, 60);
    x = std::ldexp(static_cast<double>(mantissa), exponent);
  }
  const auto program = [&]<class T>(auto make) {
    const T d = make(v[0]) * make(v[1]) + make(v[2]) * make(v[3]) - make(v[4]) * make(v[5]);
    return d * d - make(v[6]) * d;
  };
  const S x = program.template operator()<S>([](double a) { return S::exact(a); });
  const OperationDepth k = program.template operator()<OperationDepth>([](double) { return OperationDepth{0}; });
  const Rational exact = program.template operator()<Rational>([](double a) { return exact_value_of(a); });
  const double bound = a_priori_error_bound(x, k.k);
  RC_ASSERT(std::isfinite(bound));
  RC_ASSERT(cln::abs(exact_value_of(x.v) - exact) <= exact_value_of(bound));
}

}  // namespace
}  // namespace linkproof
