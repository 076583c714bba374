// RateValue (claims/rate_value.h) keeps one-term values without a RatePoly; every operation must
// still give what the same operation on RatePoly gives, bit for bit, values and error bounds.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "claims/rate_poly.h"
#include "claims/rate_value.h"
#include "core/tracked.h"

namespace linkproof {
namespace {

using D = Tracked<double>;

/// A value and the RatePoly the old evaluator would have held for it.
struct Pair {
  RateValue<D> value;
  RatePoly<D> poly;
};

void expect_same(RateValue<D> v, const RatePoly<D>& want, const std::string& what) {
  const RatePoly<D> got = std::move(v).to_poly();
  ASSERT_EQ(got.terms().size(), want.terms().size()) << what;
  for (size_t i = 0; i < got.terms().size(); ++i) {
    const auto &[gm, gc] = got.terms()[i];
    const auto &[wm, wc] = want.terms()[i];
    EXPECT_EQ(monomial_label(gm), monomial_label(wm)) << what;
    EXPECT_EQ(gc.v, wc.v) << what << " " << monomial_label(gm);  // bit for bit
    EXPECT_EQ(gc.e, wc.e) << what << " " << monomial_label(gm);
  }
}

TEST(RateValueOps, RandomSumsDifferencesProductsAndNegationsGiveRatePolysBytes) {
  const unsigned seed = 20261124;
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> id(2, 7), pick(0, 99), degree(0, 2);
  std::uniform_real_distribution<double> coef(-3, 3);
  // A leaf: a constant or a rate times a constant (a term), or, sometimes, a sum of two terms
  // (a polynomial), made as the evaluator makes them.
  const auto leaf = [&]() {
    Monomial m;
    RatePoly<D> p(D(coef(rng), 0.0));
    for (int d = degree(rng); d > 0; --d) {
      const int i = id(rng);
      m = Monomial::product(m, Monomial{i});
      p = p * RatePoly<D>::variable(RateVariable::from_id(i));
    }
    const D c = p.terms().front().second;
    Pair x{RateValue<D>::term(c, m), p};
    if (pick(rng) < 20) {
      RatePoly<D> q = p + RatePoly<D>(D(coef(rng), 1e-17));
      x = {RateValue<D>::poly(q), q};
    }
    return x;
  };
  int polys = 0, terms = 0;
  for (int round = 0; round < 300; ++round) {
    Pair acc = leaf();
    for (int step = 0; step < 6; ++step) {
      const Pair b = leaf();
      const int op = pick(rng) % 4;
      if (op == 0) acc = {acc.value + b.value, acc.poly + b.poly};
      else if (op == 1) acc = {acc.value - b.value, acc.poly - b.poly};
      else if (op == 2 && acc.poly.degree() + b.poly.degree() <= Monomial::kMaxDegree)
        acc = {acc.value * b.value, acc.poly * b.poly};
      else acc = {-acc.value, -acc.poly};
      expect_same(acc.value, acc.poly, "round " + std::to_string(round) + " step " + std::to_string(step));
      (acc.value.is_term() ? terms : polys)++;
    }
  }
  // Both representations were exercised.
  EXPECT_GT(terms, 100);
  EXPECT_GT(polys, 100);
}

TEST(RateValueOps, TermsOfOneMonomialStayOneTermAndOthersBecomeAPolynomial) {
  const Monomial w1{RateVariable{1, RateVariable::Omega}.id()}, w2{RateVariable{2, RateVariable::Omega}.id()};
  const auto t = [](double c, Monomial m) { return RateValue<double>::term(c, m); };
  const RateValue<double> same = t(2, w1) + t(3, w1);
  ASSERT_TRUE(same.is_term());
  EXPECT_EQ(same.coefficient(), 5);
  EXPECT_TRUE((t(2, w1) * t(3, w2)).is_term());
  const RateValue<double> two = t(2, w1) - t(3, w2);
  ASSERT_FALSE(two.is_term());
  EXPECT_EQ(two.polynomial().coefficient(w2), -3);
}

}  // namespace
}  // namespace linkproof
