// RatePoly: the flat representation (a fixed-size monomial key, terms sorted when read) must give
// what a map from monomial to coefficient gives: the terms in the monomials' lexicographic order,
// one per monomial, the coefficients of one monomial added in the order they arrived.
#include <gtest/gtest.h>

#include <cln/rational.h>
#include <cln/rational_io.h>

#include <algorithm>
#include <map>
#include <random>
#include <vector>

#include "claims/rate_poly.h"
#include "linkproof/core/error.h"

namespace linkproof {
namespace {

std::vector<int> ids_of(const Monomial& m) {
  std::vector<int> v;
  for (int i = 0; i < m.size(); ++i) v.push_back(m[i]);
  return v;
}

TEST(RatePolyMonomial, IdsAreSortedWithRepetitionAndTheDegreeCounted) {
  const Monomial m{7, 2, 7, 3};
  EXPECT_EQ(ids_of(m), (std::vector<int>{2, 3, 7, 7}));
  EXPECT_EQ(m.size(), 4);
  EXPECT_EQ(Monomial{}.size(), 0);
  EXPECT_TRUE(Monomial{}.empty());
  const Monomial eight{9, 1, 8, 2, 7, 3, 6, 4};
  EXPECT_EQ(eight.size(), 8);
  EXPECT_EQ(ids_of(eight), (std::vector<int>{1, 2, 3, 4, 6, 7, 8, 9}));
  EXPECT_EQ(ids_of(Monomial{Monomial::kMaxId}), (std::vector<int>{Monomial::kMaxId}));
}

TEST(RatePolyMonomial, OrderIsTheLexicographicOrderOfTheIdsWithAPrefixFirst) {
  // Every monomial of degree <= 3 in ids 0..3 (and some of degree 5..8), compared as the
  // sorted id vectors the old representation used.
  std::vector<std::vector<int>> all{{}};
  for (int a = 0; a < 4; ++a) {
    all.push_back({a});
    for (int b = a; b < 4; ++b) {
      all.push_back({a, b});
      for (int c = b; c < 4; ++c) all.push_back({a, b, c});
    }
  }
  all.push_back({0, 0, 1, 1, 2});
  all.push_back({0, 0, 1, 1, 2, 3, 3, 3});
  all.push_back({0, 0, 1, 1, 2, 3, 3});
  const auto make = [](const std::vector<int>& v) {
    Monomial m;
    for (int id : v) m = Monomial::product(m, Monomial{id});
    return m;
  };
  for (const auto& a : all)
    for (const auto& b : all) {
      EXPECT_EQ(make(a) < make(b), a < b) << ::testing::PrintToString(a) << " vs " << ::testing::PrintToString(b);
      EXPECT_EQ(make(a) == make(b), a == b);
    }
}

TEST(RatePolyMonomial, ProductMergesTheIdsAndRefusesADegreeAboveTheLimit) {
  EXPECT_EQ(ids_of(Monomial::product(Monomial{1, 4}, Monomial{2, 4, 5})), (std::vector<int>{1, 2, 4, 4, 5}));
  EXPECT_EQ(ids_of(Monomial::product(Monomial{}, Monomial{3})), (std::vector<int>{3}));
  const Monomial four{1, 1, 1, 1}, five{2, 2, 2, 2, 2};
  EXPECT_EQ(Monomial::product(four, Monomial{1, 1, 1, 1}).size(), 8);
  try {
    (void)Monomial::product(four, five);
    FAIL() << "a term of degree 9 was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("degree 9 in the rates"), std::string::npos) << e.what();
  }
  EXPECT_THROW((Monomial{1, 1, 1, 1, 1, 1, 1, 1, 1}), InputError);
}

// Products of degree <= 4 are merged in one word (product_in_word0), the rest by the general
// merge: both must give the monomial of the sorted ids, for every split of the degree between
// the factors, with repeated ids and the extreme ids.
TEST(RatePolyMonomial, ProductIsTheMonomialOfTheSortedIdsAtEveryDegreeSplit) {
  std::mt19937_64 g(2813);
  const int extremes[] = {0, 1, Monomial::kMaxId - 1, Monomial::kMaxId};
  std::uniform_int_distribution<int> small_id(0, 5), any_id(0, Monomial::kMaxId);
  int checked = 0;
  for (int na = 1; na <= 7; ++na)
    for (int nb = 1; na + nb <= 8; ++nb)
      for (int trial = 0; trial < 200; ++trial) {
        std::vector<int> a, b;
        for (int i = 0; i < na; ++i) a.push_back(trial % 3 == 0 ? small_id(g) : trial % 3 == 1 ? any_id(g) : extremes[g() % 4]);
        for (int i = 0; i < nb; ++i) b.push_back(trial % 3 == 0 ? small_id(g) : trial % 3 == 1 ? any_id(g) : extremes[g() % 4]);
        Monomial ma, mb;
        for (int id : a) ma = Monomial::product(ma, Monomial{id});
        for (int id : b) mb = Monomial::product(mb, Monomial{id});
        std::vector<int> all = a;
        all.insert(all.end(), b.begin(), b.end());
        std::sort(all.begin(), all.end());
        const Monomial p = Monomial::product(ma, mb);
        ASSERT_EQ(ids_of(p), all) << "na " << na << " nb " << nb << " trial " << trial;
        ASSERT_TRUE(p == Monomial::product(mb, ma));
        ++checked;
      }
  EXPECT_EQ(checked, 28 * 200);
}

TEST(RatePolyMonomial, LabelsAndIndicesReadTheIds) {
  const int w1 = RateVariable{1, RateVariable::Omega}.id(), wd2 = RateVariable{2, RateVariable::OmegaDot}.id();
  EXPECT_EQ(monomial_label(Monomial{}), "1");
  EXPECT_EQ(monomial_label(Monomial{w1, w1}), "omega[1]^2");
  EXPECT_EQ(monomial_label(Monomial{wd2, w1}), "omega[1]*omega_dot[2]");
  EXPECT_EQ(monomial_indices(Monomial{wd2, w1, w1}), (std::vector<int>{1, 2}));
  EXPECT_TRUE(involves_input(Monomial{wd2, w1}, 2));
  EXPECT_TRUE(involves_input(Monomial{wd2, w1}, 1));
  EXPECT_FALSE(involves_input(Monomial{wd2, w1}, 3));
  EXPECT_FALSE(involves_input(Monomial{}, 1));
}

/// The reference: the map the representation replaced, fed the same additions in the same order.
using Reference = std::map<std::vector<int>, double>;

/// c times the rate variables `ids`, made as the claims make it: a product of variables.
RatePoly<double> term_of(const std::vector<int>& ids, double c) {
  RatePoly<double> term(c);
  for (int i : ids) term = term * RatePoly<double>::variable(RateVariable::from_id(i));
  return term;
}
/// ref[ids] += c: one monomial's coefficients added in the order they arrive.
void accumulate(Reference& ref, const std::vector<int>& ids, double c) {
  auto [it, fresh] = ref.emplace(ids, c);
  if (!fresh) it->second = it->second + c;
}
/// p's terms are the map's: its monomials in order, each coefficient bit for bit.
void expect_map_terms(const RatePoly<double>& p, const Reference& ref) {
  ASSERT_EQ(p.terms().size(), ref.size());
  auto it = ref.begin();
  for (const auto& [m, c] : p.terms()) {
    ASSERT_EQ(ids_of(m), it->first);
    ASSERT_EQ(c, it->second) << "coefficient of " << monomial_label(m);
    ++it;
  }
}

TEST(RatePolyTerms, RandomSumsAndProductsGiveTheMapsTermsBitForBit) {
  const unsigned seed = 20261124;
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> id(2, 9), count(0, 6);
  std::uniform_real_distribution<double> coef(-1, 1);
  for (int round = 0; round < 200; ++round) {
    // Two random polynomials, built term by term in an unsorted order with repeated monomials.
    RatePoly<double> p[2];
    Reference ref[2];
    for (int s = 0; s < 2; ++s)
      for (int t = count(rng); t > 0; --t) {
        std::vector<int> ids;
        for (int d = count(rng) % 3; d > 0; --d) ids.push_back(id(rng));
        std::sort(ids.begin(), ids.end());
        const double c = coef(rng);
        p[s] += term_of(ids, c);
        accumulate(ref[s], ids, c);
      }
    // The product, term by term as the map did it.
    Reference prod;
    for (const auto& [ma, ca] : ref[0])
      for (const auto& [mb, cb] : ref[1]) {
        std::vector<int> m = ma;
        m.insert(m.end(), mb.begin(), mb.end());
        std::sort(m.begin(), m.end());
        accumulate(prod, m, ca * cb);
      }
    Reference sum = ref[0];
    for (const auto& [m, c] : ref[1]) accumulate(sum, m, c);
    const auto expect_same = [&](const RatePoly<double>& got, const Reference& want, const char* what) {
      ASSERT_EQ(got.terms().size(), want.size()) << what << " round " << round;
      auto it = want.begin();
      for (const auto& [m, c] : got.terms()) {
        EXPECT_EQ(ids_of(m), it->first) << what << " round " << round;
        EXPECT_EQ(c, it->second) << what << " round " << round;  // bit for bit
        EXPECT_EQ(got.coefficient(m), it->second);
        ++it;
      }
    };
    expect_same(p[0], ref[0], "p");
    expect_same(p[0] * p[1], prod, "product");
    expect_same(p[0] + p[1], sum, "sum");
  }
}

// A sum over pairs at large n: thousands of terms arriving out of order, many monomials more
// than once (sorted by radix, core/stable_radix_sort.h, above 256 terms). The terms must be the
// map's, each coefficient summed in the order its terms arrived, bit for bit.
TEST(RatePolyTerms, LargeUnsortedSumsGiveTheMapsTermsBitForBit) {
  const unsigned seed = 20261127;
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937 rng(seed);
  // Ids of one byte (up to 3 varying bytes: the packed radix path) or two (up to 6: the full one).
  for (const int ids : {40, 2000}) {
    std::uniform_int_distribution<int> id(2, ids), degree(0, 3);
    std::uniform_real_distribution<double> coef(-1, 1);
    RatePoly<double> p;
    Reference ref;
    for (int t = 0; t < 20000; ++t) {
      std::vector<int> m;
      for (int d = degree(rng); d > 0; --d) m.push_back(id(rng));
      std::sort(m.begin(), m.end());
      const double c = coef(rng);
      p += term_of(m, c);
      accumulate(ref, m, c);
    }
    expect_map_terms(p, ref);
  }
}

// A side is usually a few sorted sums added one after another: its ascending runs are merged
// (up to 8 of them) in place of the radix sort. From 1 to 10 runs, with monomials repeated within
// and across runs, the terms are the map's, bit for bit.
TEST(RatePolyTerms, SumsOfAFewSortedRunsGiveTheMapsTermsBitForBit) {
  const unsigned seed = 20261128;
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> id(2, 60), degree(0, 2);
  std::uniform_real_distribution<double> coef(-1, 1);
  for (int runs = 1; runs <= 10; ++runs) {
    SCOPED_TRACE(std::to_string(runs) + " runs");
    RatePoly<double> p;
    Reference ref;
    for (int r = 0; r < runs; ++r) {
      // One run: 40 ascending monomials, some of them twice in a row.
      std::vector<std::vector<int>> ms;
      for (int t = 0; t < 40; ++t) {
        std::vector<int> m;
        for (int d = degree(rng); d > 0; --d) m.push_back(id(rng));
        std::sort(m.begin(), m.end());
        ms.push_back(m);
        if (t % 7 == 0) ms.push_back(m);
      }
      std::sort(ms.begin(), ms.end());  // the ids' lexicographic order, a prefix first: the monomials' order
      RatePoly<double> run;
      Reference run_ref;  // a run arrives in p as its terms, each monomial's added up already
      for (const auto& m : ms) {
        const double c = coef(rng);
        run += term_of(m, c);
        accumulate(run_ref, m, c);
      }
      p += run;
      for (const auto& [m, c] : run_ref) accumulate(ref, m, c);
    }
    expect_map_terms(p, ref);
  }
}

TEST(RatePolyTerms, ZeroCoefficientsAreKeptAndAbsentOnesReadAsZero) {
  const auto w = RatePoly<double>::variable({1, RateVariable::Omega});
  const RatePoly<double> p = w - w;
  ASSERT_EQ(p.terms().size(), 1u);  // "zero" is for the judge to say, not the representation
  EXPECT_EQ(p.terms().front().second, 0.0);
  EXPECT_FALSE(p.is_constant());
  EXPECT_EQ(p.coefficient(Monomial{RateVariable{2, RateVariable::Omega}.id()}), 0.0);
  EXPECT_EQ(p.degree(), 1);
}

TEST(RatePolyTerms, ConstantDivisionAndEvaluationInExactArithmetic) {
  using Q = cln::cl_RA;
  const auto w1 = RatePoly<Q>::variable({1, RateVariable::Omega});
  const auto wd2 = RatePoly<Q>::variable({2, RateVariable::OmegaDot});
  const RatePoly<Q> p = (RatePoly<Q>(Q(3)) * wd2 + w1 * w1 + RatePoly<Q>(Q(5))) / RatePoly<Q>(Q(2));
  EXPECT_TRUE(RatePoly<Q>(Q(7)).is_constant());
  EXPECT_FALSE(p.is_constant());
  EXPECT_EQ(p.constant(), Q(5) / 2);
  EXPECT_EQ(p.degree(), 2);
  // At omega = (2, 0), omega-dot = (0, 4): (3*4 + 4 + 5) / 2.
  EXPECT_EQ(p.evaluate({Q(2), Q(0)}, {Q(0), Q(4)}), Q(21) / 2);
  EXPECT_THROW((void)(p / w1), InputError);
  EXPECT_THROW((void)(p / RatePoly<Q>(Q(0))), UndefinedQuantity);
}

TEST(RatePolyDiffering, DifferingTermsIgnoreZeroTermsAndKeepEachSidesCoefficient) {
  using R = Rational;
  const Monomial w1{RateVariable{1, RateVariable::Omega}.id()};
  const Monomial w1w2{RateVariable{1, RateVariable::Omega}.id(), RateVariable{2, RateVariable::Omega}.id()};
  const Monomial wd2{RateVariable{2, RateVariable::OmegaDot}.id()};
  const auto same = [](const RatePoly<R>& x, const RatePoly<R>& y) {
    const auto d = differing_terms(x, y);
    return d.first.terms().empty() && d.second.terms().empty();
  };
  RatePoly<R> a, b;
  a.add(w1, R(3));
  a.add(w1w2, R(0));  // cancelled on one side only
  a.add(wd2, R(1) / 7);
  b.add(wd2, R(2) / 14);
  b.add(w1, R(3));
  EXPECT_TRUE(same(a, b));
  EXPECT_TRUE(same(b, a));
  RatePoly<R> c = b;
  c.add(w1w2, R(1) / 1000000);  // one more nonzero term: in c's part only
  auto ac = differing_terms(a, c);
  EXPECT_TRUE(ac.first.terms().empty());
  ASSERT_EQ(ac.second.terms().size(), 1u);
  EXPECT_TRUE(ac.second.terms()[0].first == w1w2);
  EXPECT_FALSE(same(c, a));
  RatePoly<R> d;
  d.add(w1, R(3));
  d.add(wd2, R(1) / 8);  // one coefficient differs: in both parts, each with its own
  const auto ad = differing_terms(a, d);
  ASSERT_EQ(ad.first.terms().size(), 1u);
  ASSERT_EQ(ad.second.terms().size(), 1u);
  EXPECT_EQ(ad.first.terms()[0].second, R(1) / 7);
  EXPECT_EQ(ad.second.terms()[0].second, R(1) / 8);
  // a - d = a' - d' at any rates.
  const std::vector<R> w{R(2), R(-3)}, wd{R(5), R(1) / 3};
  EXPECT_EQ(a.evaluate(w, wd) - d.evaluate(w, wd), ad.first.evaluate(w, wd) - ad.second.evaluate(w, wd));
  RatePoly<R> zero, zeros;
  zeros.add(w1, R(0));
  zeros.add(Monomial{}, R(0));
  EXPECT_TRUE(same(zero, zeros));
  EXPECT_FALSE(same(zero, a));
}

}  // namespace
}  // namespace linkproof
