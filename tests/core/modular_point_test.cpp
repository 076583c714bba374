// ModularPoint: a one-sided zero test. It may say "non-zero" only for expressions that are not
// identically zero; identically zero ones (however they are built) must never be rejected.
#include "core/modular_point.h"

#include <gtest/gtest.h>

#include "core/symbolic_scalar.h"

namespace linkproof {
namespace {

using GiNaC::ex;

TEST(ModularPoint, ShowsAGenericPolynomialNonZero) {
  const GiNaC::symbol x("x"), y("y");
  ModularPoint p;
  EXPECT_TRUE(p.shows_nonzero(x * y - 1));
  EXPECT_TRUE(p.shows_nonzero(GiNaC::pow(x + y, -2)));
}

TEST(ModularPoint, NeverRejectsAnIdenticallyZeroRationalFunction) {
  const GiNaC::symbol x("x"), y("y"), z("z");
  const ex s = x + 2 * y - z / 3;
  // Unexpanded against expanded, with a shared subexpression and a fraction.
  const ex zero1 = GiNaC::pow(s, 3) - GiNaC::expand(GiNaC::pow(s, 3));
  const ex zero2 = (x * x - y * y) / (x - y) - x - y;
  const ex zero3 = s / (s + 1) + 1 / (s + 1) - 1;
  ModularPoint p;
  for (const ex& e : {zero1, zero2, zero3}) {
    EXPECT_FALSE(p.shows_nonzero(e)) << e;
    const auto v = p.value(e);
    if (v) {
      EXPECT_EQ(*v, 0u) << e;
    }
  }
}

// Regression: the terms of a sum are rebuilt by op() on every call, so a memo keyed by the
// address of a temporary term returned stale values (a true identity of the eq22 proof at
// n = 4 was rejected). Many sums of products, each identically zero, in one evaluator.
TEST(ModularPoint, ReusedAddressesOfRebuiltTermsDoNotLeakValues) {
  std::vector<GiNaC::symbol> v;
  for (int k = 0; k < 8; ++k) v.emplace_back("v" + std::to_string(k));
  ModularPoint p;
  for (int a = 0; a < 8; ++a)
    for (int b = 0; b < 8; ++b) {
      const ex u = 3 * v[static_cast<size_t>(a)] - 5 * v[static_cast<size_t>(b)] + 7;
      const ex w = 2 * v[static_cast<size_t>((a + b) % 8)] + v[static_cast<size_t>(a)] * v[static_cast<size_t>(b)];
      const ex zero = u * w - GiNaC::expand(u * w);
      EXPECT_FALSE(p.shows_nonzero(zero)) << zero;
    }
}

TEST(ModularPoint, SaysNothingWhereADenominatorVanishesOrAFunctionAppears) {
  const GiNaC::symbol x("x");
  ModularPoint p;
  const GiNaC::symbol y("y");
  const ex d = GiNaC::pow(x + y, 2) - GiNaC::expand(GiNaC::pow(x + y, 2));  // 0, not folded
  EXPECT_FALSE(p.value(GiNaC::pow(d, -1)).has_value());
  EXPECT_FALSE(p.value(GiNaC::sin(x)).has_value());
  EXPECT_FALSE(p.value(GiNaC::sqrt(x)).has_value());
}

TEST(ModularPoint, SymbolicZeroTestStillSaysZeroForIdentities) {
  const GiNaC::symbol x("x"), y("y");
  EXPECT_TRUE(ScalarTraits<ex>::is_zero((x * x - y * y) / (x + y) - (x - y)));
  EXPECT_FALSE(ScalarTraits<ex>::is_zero((x * x - y * y) / (x + y) - (x + y)));
}

}  // namespace
}  // namespace linkproof
