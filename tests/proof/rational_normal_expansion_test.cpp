// The expansions of the symbolic normal form (proof/rational_normal.h): a product of two long
// sums is expanded one partial product at a time and combined once. GiNaC's own expand adds each
// partial product to the running result (a cost quadratic in the sums' lengths), in one call no
// deadline could stop: a six-bar acceleration claim ran 463 s on a 60 s budget that way.
#include <gtest/gtest.h>

#include <chrono>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "proof/rational_normal.h"

namespace linkproof::proof_detail {
namespace {

using Clock = std::chrono::steady_clock;
using GiNaC::ex;

std::vector<GiNaC::symbol> symbols(int count) {
  std::vector<GiNaC::symbol> s;
  for (int i = 0; i < count; ++i) s.emplace_back("x" + std::to_string(i));
  return s;
}

/// A sum of `terms` random monomials of degree `degree` with coefficients in -9..9, and `constant`.
ex random_sum(const std::vector<GiNaC::symbol>& s, int terms, int degree, int constant, std::mt19937& g) {
  ex sum = constant;
  for (int t = 0; t < terms; ++t) {
    ex m = static_cast<int>(g() % 19) - 9;
    for (int d = 0; d < degree; ++d) m *= s[g() % s.size()];
    sum += m;
  }
  return GiNaC::expand(sum);
}

TEST(RationalNormalExpansion, ASumOfProductsEqualsGiNaCsExpansion) {
  const std::vector<GiNaC::symbol> s = symbols(5);
  const unsigned seed = 20261127;
  std::mt19937 g(seed);
  for (int trial = 0; trial < 40; ++trial) {
    SCOPED_TRACE("seed " + std::to_string(seed) + ", trial " + std::to_string(trial));
    // Sums with and without a constant term, single monomials, numbers and zero.
    const auto operand = [&](int k) -> ex {
      switch (k % 5) {
        case 0: return random_sum(s, 1 + static_cast<int>(g() % 12), 3, 0, g);
        case 1: return random_sum(s, 1 + static_cast<int>(g() % 12), 2, 7, g);
        case 2: return random_sum(s, 1, 3, 0, g);
        case 3: return static_cast<int>(g() % 5) - 2;
        default: return random_sum(s, 3, 1, -1, g);
      }
    };
    std::vector<std::pair<ex, ex>> products;
    ex expected = 0;
    for (int p = 0; p < 1 + trial % 3; ++p) {
      products.emplace_back(operand(static_cast<int>(g())), operand(static_cast<int>(g())));
      expected += products.back().first * products.back().second;
    }
    RationalNormalizer n(false);
    const ex got = n.expanded_sum(products);
    EXPECT_TRUE(GiNaC::expand(got - GiNaC::expand(expected)).is_zero()) << got << "\nexpected " << GiNaC::expand(expected);
  }
}

TEST(RationalNormalExpansion, AProductOfTwoLongSumsStopsAtTheDeadline) {
  // Two 500-term sums in 12 symbols: GiNaC's expand of their product takes about a minute here
  // and cannot be interrupted.
  const std::vector<GiNaC::symbol> s = symbols(12);
  std::mt19937 g(7);
  const ex a = random_sum(s, 560, 6, 0, g), b = random_sum(s, 560, 6, 0, g);
  RationalNormalizer n(false);
  n.normal(a);
  n.normal(b);
  const auto start = Clock::now();
  n.set_deadline(start + std::chrono::milliseconds(20));
  EXPECT_THROW(n.normal(a * b), NormalizerOutOfTime);
  EXPECT_LT(std::chrono::duration<double>(Clock::now() - start).count(), 2.0);
}

}  // namespace
}  // namespace linkproof::proof_detail
