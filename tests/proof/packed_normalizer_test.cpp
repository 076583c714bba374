// The packed normal form (proof/packed_normalizer.h) is the rational function RationalNormalizer
// computes, with shared divisors taken once, and its polynomial arithmetic is exact; what it
// cannot hold it refuses (the caller then takes GiNaC's route), and it stops at its deadline.
#include <gtest/gtest.h>

#include <chrono>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "proof/packed_normalizer.h"
#include "proof/rational_normal.h"

namespace linkproof::proof_detail {
namespace {

using GiNaC::ex;

std::vector<GiNaC::symbol> packed_symbols(int count) {
  std::vector<GiNaC::symbol> s;
  for (int i = 0; i < count; ++i) s.emplace_back("x" + std::to_string(i));
  return s;
}

bool same_polynomial(const ex& a, const ex& b) { return GiNaC::expand(a - b).is_zero(); }

TEST(PackedPolynomial, ASquareOfASumExpandsAsGiNaCExpandsIt) {
  const std::vector<GiNaC::symbol> x = packed_symbols(3);
  PackedNormalizer n;
  const ex e = GiNaC::pow(x[0] + 2 * x[1] - GiNaC::numeric(3, 7) * x[2] + 5, 4);
  EXPECT_TRUE(same_polynomial(n.to_ex(n.numerator(e)), GiNaC::expand(e)));
  EXPECT_EQ(n.numerator(e).terms(), GiNaC::expand(e).nops());
}

TEST(PackedPolynomial, WideningTheFieldsKeepsTheTermsSortedAndEqual) {
  PackedNormalizer n;
  const std::vector<GiNaC::symbol> x = packed_symbols(4);
  // x0 of degree 1 and x3 of degree 40: adding them repacks x0's field wider.
  const PackedPolynomial a = n.numerator(x[0] * x[1] + x[2] + 1);
  const PackedPolynomial b = n.numerator(GiNaC::pow(x[3], 40) + GiNaC::pow(x[0], 9));
  const PackedPolynomial sum = a + b;
  for (size_t i = 1; i < sum.terms(); ++i) EXPECT_LT(sum.keys()[i - 1], sum.keys()[i]);
  EXPECT_TRUE(same_polynomial(n.to_ex(sum), x[0] * x[1] + x[2] + 1 + GiNaC::pow(x[3], 40) + GiNaC::pow(x[0], 9)));
  EXPECT_TRUE((sum - b) == a);
  EXPECT_TRUE((sum - sum).is_zero());
}

TEST(PackedPolynomial, AProductSplitIntoOutputBucketsEqualsGiNaCsExpansion) {
  // 462 x 463 terms: more partial products than a single hash table takes, so the product is
  // accumulated bucket by bucket (packed_polynomial.cpp); GiNaC expands the power directly.
  const std::vector<GiNaC::symbol> x = packed_symbols(6);
  const ex sum = x[0] + 2 * x[1] - GiNaC::numeric(3, 2) * x[2] + x[3] - 5 * x[4] + x[5];
  PackedNormalizer n;
  const PackedPolynomial sixth = n.numerator(GiNaC::expand(GiNaC::pow(sum, 6)));
  const PackedPolynomial other = n.numerator(GiNaC::expand(GiNaC::pow(sum, 6) + x[0]));
  ASSERT_EQ(sixth.terms() * other.terms(), 462u * 463u);
  const PackedPolynomial product = n.multiply(sixth, other);
  for (size_t i = 1; i < product.terms(); ++i) ASSERT_LT(product.keys()[i - 1], product.keys()[i]);
  const ex expected = GiNaC::expand(GiNaC::pow(sum, 12)) + GiNaC::expand(GiNaC::pow(sum, 6) * x[0]);
  EXPECT_EQ(product.terms(), expected.nops());
  EXPECT_TRUE(same_polynomial(n.to_ex(product), expected));
}

TEST(PackedPolynomial, CoefficientsInAVariableRebuildThePolynomial) {
  PackedNormalizer n;
  const std::vector<GiNaC::symbol> x = packed_symbols(3);
  const ex e = GiNaC::expand(GiNaC::pow(x[0] + x[1] * x[2] - 2, 3) * (x[1] - x[2]));
  const std::vector<PackedPolynomial> c = n.numerator(e).coefficients_in(n.variable(x[1]));
  ASSERT_EQ(c.size(), 5u);  // degree 4 in x1
  ex rebuilt = 0;
  for (size_t k = 0; k < c.size(); ++k) {
    EXPECT_FALSE(n.to_ex(c[k]).has(x[1]));
    rebuilt += n.to_ex(c[k]) * GiNaC::pow(x[1], static_cast<int>(k));
  }
  EXPECT_TRUE(same_polynomial(rebuilt, e));
}

/// A random rational expression DAG: sums, products, quotients and integer powers of the
/// symbols and small rationals, reusing earlier nodes (shared subexpressions, as the proofs' are).
ex random_expression(const std::vector<GiNaC::symbol>& x, std::mt19937& g, int nodes) {
  std::vector<ex> pool;
  for (const GiNaC::symbol& s : x) pool.emplace_back(s);
  pool.emplace_back(GiNaC::numeric(3, 2));
  pool.emplace_back(-2);
  for (int i = 0; i < nodes; ++i) {
    const ex& a = pool[g() % pool.size()];
    const ex& b = pool[g() % pool.size()];
    switch (g() % 5) {
      case 0: pool.push_back(a + b); break;
      case 1: pool.push_back(a - b * GiNaC::numeric(static_cast<int>(g() % 5) + 1, 3)); break;
      case 2: pool.push_back(a * b); break;
      case 3: pool.push_back(b.is_zero() ? a : a / (b + x[g() % x.size()])); break;
      default: pool.push_back(GiNaC::pow(a, static_cast<int>(g() % 3) + 1)); break;
    }
  }
  return pool.back() - pool[pool.size() / 2] * pool[pool.size() - 2];
}

TEST(PackedNormalizer, GivesTheRationalFunctionRationalNormalizerGives) {
  const std::vector<GiNaC::symbol> x = packed_symbols(4);
  const unsigned seed = 20261128;
  std::mt19937 g(seed);
  int compared = 0;
  for (int trial = 0; trial < 120; ++trial) {
    SCOPED_TRACE("seed " + std::to_string(seed) + ", trial " + std::to_string(trial));
    const ex e = random_expression(x, g, 4 + trial % 9);
    RationalNormalizer reference(false);
    PackedNormalizer packed;
    Fraction expected;
    try {
      expected = reference.normal(e);
    } catch (const GiNaC::pole_error&) {
      EXPECT_THROW(packed.normal(e), GiNaC::pole_error);
      continue;
    }
    // num / den = expected.num / expected.den, and the core is zero exactly when e is.
    const ex num = packed.to_ex(packed.numerator(e)), den = packed.to_ex(packed.denominator(e));
    EXPECT_TRUE(same_polynomial(num * expected.den, expected.num * den));
    EXPECT_EQ(packed.core(e).is_zero(), expected.num.is_zero());
    ++compared;
  }
  EXPECT_GT(compared, 100);
}

TEST(PackedNormalizer, TakesADivisorSharedByTwoTermsOnce) {
  const std::vector<GiNaC::symbol> x = packed_symbols(2);
  PackedNormalizer n;
  // 1/(x0 + 1) + x1/((x0 + 1)(x1 + 1)) over (x0 + 1)(x1 + 1), not over (x0 + 1)^2 (x1 + 1).
  const ex e = 1 / (x[0] + 1) + x[1] / ((x[0] + 1) * (x[1] + 1));
  EXPECT_TRUE(same_polynomial(n.to_ex(n.denominator(e)), (x[0] + 1) * (x[1] + 1)));
  EXPECT_TRUE(same_polynomial(n.to_ex(n.numerator(e)), 2 * x[1] + 1));
}

TEST(PackedNormalizer, CancelsAMonomialFactorOfADivisor) {
  const std::vector<GiNaC::symbol> x = packed_symbols(4);
  PackedNormalizer n;
  // (x0 x1 + x0 x2) / (x0 x3 + x0) = (x1 + x2) / (x3 + 1): as a rate over a rate, both with the
  // same delta, lose it.
  const ex e = (x[0] * x[1] + x[0] * x[2]) / (x[0] * x[3] + x[0]);
  EXPECT_TRUE(same_polynomial(n.to_ex(n.numerator(e)), x[1] + x[2]));
  EXPECT_TRUE(same_polynomial(n.to_ex(n.denominator(e)), x[3] + 1));
}

TEST(PackedNormalizer, AnIdentityHasTheZeroNumerator) {
  const std::vector<GiNaC::symbol> x = packed_symbols(3);
  PackedNormalizer n;
  const ex a = x[0] / (x[1] - x[2]), b = x[2] / (x[1] + x[0]);
  // (a + b)^2 - a^2 - 2 a b - b^2 = 0 as a rational function, not as a written expression.
  EXPECT_TRUE(n.numerator(GiNaC::pow(a + b, 2) - GiNaC::pow(a, 2) - 2 * a * b - GiNaC::pow(b, 2)).is_zero());
  EXPECT_FALSE(n.numerator(GiNaC::pow(a + b, 2) - GiNaC::pow(a, 2) - a * b - GiNaC::pow(b, 2)).is_zero());
}

TEST(PackedNormalizer, RefusesWhatItCannotHold) {
  const std::vector<GiNaC::symbol> x = packed_symbols(40);
  PackedNormalizer n;
  EXPECT_THROW(n.normal(GiNaC::abs(x[0]) + x[1]), PackedUnsupported);
  EXPECT_THROW(n.normal(GiNaC::sqrt(GiNaC::ex(2)) * x[1]), PackedUnsupported);
  // 40 variables of degree 100: 280 bits of exponents.
  ex big = 1;
  for (const GiNaC::symbol& s : x) big *= GiNaC::pow(s, 100);
  EXPECT_THROW(n.normal(big + 1), PackedUnsupported);
  // A divisor that is zero only once expanded (GiNaC builds it as written).
  const ex zero = GiNaC::pow(x[0] + 1, 2) - GiNaC::pow(x[0], 2) - 2 * x[0] - 1;
  ASSERT_FALSE(zero.is_zero());
  EXPECT_THROW(n.normal(x[1] / zero), GiNaC::pole_error);
}

TEST(PackedNormalizer, StopsAtItsDeadlineItsTermLimitAndWhatItMayHold) {
  const std::vector<GiNaC::symbol> x = packed_symbols(8);
  ex sum = 0;
  for (const GiNaC::symbol& s : x) sum += s;
  {
    PackedNormalizer n;
    n.set_deadline(std::chrono::steady_clock::now() - std::chrono::seconds(1));
    EXPECT_THROW(n.normal(GiNaC::pow(sum, 12)), NormalizerOutOfTime);
  }
  {
    PackedNormalizer n;
    n.set_limits({1000, 50'000'000});  // (x0 + .. + x7)^12 has 50388 terms
    EXPECT_THROW(n.normal(GiNaC::pow(sum, 12)), NormalizerOutOfTime);
  }
  {
    PackedNormalizer n;
    n.set_limits({10'000'000, 10'000});  // (x0 + .. + x7)^6 times itself: 1716^2 partial products
    const ex sixth = GiNaC::pow(sum, 6);
    EXPECT_NO_THROW(n.normal(sixth));
    try {
      n.normal(sixth * (sixth + 1));
      ADD_FAILURE() << "no limit";
    } catch (const NormalizerOutOfTime& t) {
      EXPECT_NE(t.why.find("partial products"), std::string::npos) << t.why;
    }
  }
  {
    PackedNormalizer n;
    n.set_limits({10'000'000, 50'000'000, 5000});  // the memo holds (x0 + .. + x7)^6 and its parts
    const ex sixth = GiNaC::pow(sum, 6), seventh = sixth * (sum + 1);
    EXPECT_NO_THROW(n.normal(sixth));
    try {
      n.normal(seventh);
      ADD_FAILURE() << "no limit";
    } catch (const NormalizerOutOfTime& t) {
      EXPECT_NE(t.why.find("hold more than"), std::string::npos) << t.why;
    }
  }
}

TEST(PackedNormalizer, ReadsAnInverseSymbolAsOneOverItsPolynomial) {
  const std::vector<GiNaC::symbol> x = packed_symbols(3);
  const GiNaC::symbol delta("delta");
  PackedNormalizer n;
  const ex det = 2 * x[0] * x[1] - x[2];
  n.set_inverses({{delta, det}});
  // a delta^3 + b delta + c with delta = 1/det is (a + b det^2 + c det^3) / det^3.
  const ex a = x[0] + 1, b = x[1] * x[2], c = x[2] - 4;
  const ex e = GiNaC::expand(a * GiNaC::pow(delta, 3) + b * delta + c);
  EXPECT_TRUE(same_polynomial(n.to_ex(n.numerator(e)) * GiNaC::pow(det, 3),
                              (a + b * GiNaC::pow(det, 2) + c * GiNaC::pow(det, 3)) * n.to_ex(n.denominator(e))));
  EXPECT_FALSE(n.to_ex(n.core(e)).has(delta));
  // delta det - 1 = 0: the core is the zero polynomial.
  EXPECT_TRUE(n.core(delta * det - 1).is_zero());
}

TEST(PackedNormalizer, ReducingOnTheCirclesReplacesEvenPowersOfTheSine) {
  const GiNaC::symbol c("c"), s("s"), y("y");
  PackedNormalizer n;
  // s^5 y + s^2 - 1 + c^2 = s (1 - c^2)^2 y + (1 - c^2) - 1 + c^2 = s (1 - c^2)^2 y.
  const PackedPolynomial p = n.numerator(GiNaC::pow(s, 5) * y + GiNaC::pow(s, 2) - 1 + GiNaC::pow(c, 2));
  EXPECT_TRUE(same_polynomial(n.to_ex(reduce_on_circles(p, {{c, s}}, n)), s * GiNaC::pow(1 - c * c, 2) * y));
  EXPECT_TRUE(reduce_on_circles(n.numerator(c * c + s * s - 1), {{c, s}}, n).is_zero());
}

}  // namespace
}  // namespace linkproof::proof_detail
