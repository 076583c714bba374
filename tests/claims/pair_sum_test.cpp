// PairSum (claims/pair_sum.h) adds the terms of a sum over ordered pairs without sorting them;
// its total must be the RatePoly that collecting the same terms in the same order gives, bit for
// bit, error bounds included.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "claims/pair_sum.h"
#include "core/tracked.h"

namespace linkproof {
namespace {

using D = Tracked<double>;

TEST(PairSumTerms, OrderedPairsAndOtherTermsGiveTheRatePolysTermsBitForBit) {
  const unsigned seed = 20261124;
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> coef(-2, 2), radius(0, 1e-15);
  std::uniform_int_distribution<int> pick(0, 9);
  const auto omega = [](int j) { return RateVariable{j, RateVariable::Omega}.id(); };
  const auto omega_dot = [](int j) { return RateVariable{j, RateVariable::OmegaDot}.id(); };
  for (int m : {1, 2, 3, 7, 12}) {
    PairSum<D> pairs(m);
    RatePoly<D> want;
    // As sum_pairs arrives: j = 1..m, l = 1..m, l != j; each summand one term omega_j omega_l,
    // sometimes a few more (a non-local claim: omega_1^2, omega_j omega-dot_l, a constant) or
    // none (a term left out).
    for (int j = 1; j <= m; ++j)
      for (int l = 1; l <= m; ++l) {
        if (l == j || pick(rng) == 0) continue;
        RatePoly<D> t;
        t.add(Monomial{omega(j), omega(l)}, D(coef(rng), radius(rng)));
        if (pick(rng) < 3) t.add(Monomial{omega(1), omega(1)}, D(coef(rng), radius(rng)));
        if (pick(rng) < 3) t.add(Monomial{omega(j), omega_dot(l)}, D(coef(rng), radius(rng)));
        if (pick(rng) < 2) t.add(Monomial{}, D(coef(rng), radius(rng)));
        if (pick(rng) < 2) t.add(Monomial{omega(j), omega(l), omega(l)}, D(coef(rng), 0.0));
        pairs.add(t);
        want += t;
      }
    const RatePoly<D> got = pairs.total();
    ASSERT_EQ(got.terms().size(), want.terms().size()) << "m = " << m;
    for (size_t i = 0; i < got.terms().size(); ++i) {
      const auto &[gm, gc] = got.terms()[i];
      const auto &[wm, wc] = want.terms()[i];
      EXPECT_EQ(monomial_label(gm), monomial_label(wm)) << "m = " << m;
      EXPECT_EQ(gc.v, wc.v) << "m = " << m << " " << monomial_label(gm);
      EXPECT_EQ(gc.e, wc.e) << "m = " << m << " " << monomial_label(gm);
    }
  }
}

TEST(PairSumTerms, AZeroCoefficientIsKeptAndAnAbsentPairIsNotATerm) {
  PairSum<double> pairs(3);
  const Monomial w12{RateVariable{1, RateVariable::Omega}.id(), RateVariable{2, RateVariable::Omega}.id()};
  pairs.add(w12, 1.5);
  pairs.add(w12, -1.5);
  const RatePoly<double> t = pairs.total();
  ASSERT_EQ(t.terms().size(), 1u);  // omega_1 omega_2 with 0; omega_1 omega_3, omega_2 omega_3 absent
  EXPECT_EQ(t.terms().front().second, 0.0);
}

}  // namespace
}  // namespace linkproof
