// balanced_sum (core/exact_sum.h) adds exact numbers in a balanced tree: the value must be the
// sequential sum's, for every length (odd widths carry their last term up a level), in CLN's
// rationals and in InlineRational; and an exact rate polynomial's value, which uses it, must be
// the sum of its terms' values.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <random>
#include <vector>

#include "claims/rate_poly.h"
#include "core/exact_sum.h"
#include "core/inline_rational.h"

namespace linkproof {
namespace {

constexpr std::uint64_t kBalancedSumSeed = 20261128;

// A rational with its own denominator (up to ~40 bits), so that partial sums grow.
Rational draw_with_own_denominator(std::mt19937_64& g) {
  const auto num = static_cast<long>(g() % 2000001) - 1000000;
  const auto den = static_cast<long>(g() % (1L << 40)) + 1;
  return Rational(num) / Rational(den);
}

TEST(BalancedSum, GivesTheSequentialSumForEveryLengthInBothExactTypes) {
  std::printf("BalancedSum seed %llu\n", static_cast<unsigned long long>(kBalancedSumSeed));
  std::mt19937_64 g(kBalancedSumSeed);
  for (int length = 0; length <= 70; ++length) {
    std::vector<Rational> q;
    std::vector<InlineRational> w;
    Rational sequential = 0;
    for (int k = 0; k < length; ++k) {
      q.push_back(draw_with_own_denominator(g));
      w.emplace_back(q.back());
      sequential = sequential + q.back();
    }
    EXPECT_EQ(balanced_sum(q), sequential) << "length " << length;
    EXPECT_EQ(balanced_sum(w).to_rational(), sequential) << "length " << length;
  }
}

// RatePoly::evaluate reuses one buffer for every group's sum: the in-place sum must give the
// same value and leave the vector's storage to the next group (cleared and filled again).
TEST(BalancedSum, InPlaceSumsOfOneReusedBufferGiveTheSequentialSums) {
  std::mt19937_64 g(kBalancedSumSeed + 2);
  std::vector<InlineRational> buffer;
  buffer.reserve(70);
  const InlineRational* storage = buffer.data();
  for (int length = 0; length <= 70; ++length) {
    buffer.clear();
    Rational sequential = 0;
    for (int k = 0; k < length; ++k) {
      buffer.emplace_back(draw_with_own_denominator(g));
      sequential = sequential + buffer.back().to_rational();
    }
    EXPECT_EQ(balanced_sum(buffer).to_rational(), sequential) << "length " << length;
    EXPECT_EQ(buffer.data(), storage) << "length " << length << ": the buffer was given away";
  }
}

TEST(BalancedSum, ExactRatePolynomialValueIsTheSumOfItsTermsAtTheRates) {
  std::mt19937_64 g(kBalancedSumSeed + 1);
  constexpr int kInputs = 40;
  std::vector<InlineRational> omega, omega_dot;
  std::vector<Rational> omega_q, omega_dot_q;
  for (int j = 0; j < kInputs; ++j) {
    omega_q.push_back(draw_with_own_denominator(g));
    omega_dot_q.push_back(draw_with_own_denominator(g));
    omega.emplace_back(omega_q.back());
    omega_dot.emplace_back(omega_dot_q.back());
  }
  const auto w = [](int j) { return RateVariable{j, RateVariable::Omega}.id(); };
  const auto wd = [](int j) { return RateVariable{j, RateVariable::OmegaDot}.id(); };
  // Every pair, every square and every omega-dot, in the monomials' order, plus a constant:
  // 861 terms, each rate with its own denominator.
  RatePoly<InlineRational> p;
  Rational expected = 0;
  const Rational c0 = draw_with_own_denominator(g);
  p.add(Monomial{}, InlineRational(c0));
  expected = expected + c0;
  for (int j = 1; j <= kInputs; ++j) {
    for (int l = j; l <= kInputs; ++l) {
      const Rational c = draw_with_own_denominator(g);
      p.add(Monomial{w(j), w(l)}, InlineRational(c));
      expected = expected + c * omega_q[j - 1] * omega_q[l - 1];
    }
    const Rational c = draw_with_own_denominator(g);
    p.add(Monomial{wd(j)}, InlineRational(c));
    expected = expected + c * omega_dot_q[j - 1];
  }
  ASSERT_EQ(p.terms().size(), 1u + kInputs * (kInputs + 1) / 2 + kInputs);
  EXPECT_EQ(p.evaluate(omega, omega_dot).to_rational(), expected);
}

}  // namespace
}  // namespace linkproof
