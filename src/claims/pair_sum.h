// PairSum<T>: the total of a sum over ordered pairs (sum_pairs), accumulated without sorting.
//
// The terms omega_a omega_b (a < b) of such a sum arrive from the pair (a, b) and again, later,
// from (b, a): out of the monomials' order, so a RatePoly collecting them sorted all m^2 of them
// when read (a stable sort, ~6 % of a double check at n = 40, more at n = 1000). Here each such
// term is added at once into a table indexed by the pair; every other term goes to a RatePoly.
// A monomial's parts are added in the order they arrived, as RatePoly's stable sort adds them,
// and the table and the rest are merged in the monomials' order: the same terms, bit for bit
// (PairSumTerms.* compares it with a RatePoly).
#pragma once

#include <vector>

#include "claims/rate_poly.h"
#include "symbolic/ground_truth.h"

namespace linkproof {

template <class T>
class PairSum {
 public:
  /// For the rates of inputs 1..m.
  explicit PairSum(int m) : m_(m), coefficient_(m > 1 ? pair_index(m - 1, m, m) + 1 : 0), present_(coefficient_.size()) {}

  void add(const Monomial& mono, const T& c) {
    if (mono.size() == 2) {
      const RateVariable a = RateVariable::from_id(mono[0]), b = RateVariable::from_id(mono[1]);
      if (a.kind == RateVariable::Omega && b.kind == RateVariable::Omega && a.index < b.index && b.index <= m_) {
        const size_t k = pair_index(a.index, b.index, m_);
        if (present_[k]) {
          coefficient_[k] = coefficient_[k] + c;
        } else {
          coefficient_[k] = c;
          present_[k] = 1;
        }
        return;
      }
    }
    rest_.add(mono, c);
  }
  void add(const RatePoly<T>& p) {
    for (const auto& [mono, c] : p.terms()) add(mono, c);
  }

  /// The total, its terms in the monomials' order.
  RatePoly<T> total() const {
    RatePoly<T> out;
    const auto& rest = rest_.terms();
    size_t i = 0;
    for (int a = 1; a <= m_; ++a)
      for (int b = a + 1; b <= m_; ++b) {
        const size_t k = pair_index(a, b, m_);
        if (!present_[k]) continue;
        const Monomial mono{RateVariable{a, RateVariable::Omega}.id(), RateVariable{b, RateVariable::Omega}.id()};
        for (; i < rest.size() && rest[i].first < mono; ++i) out.add(rest[i].first, rest[i].second);
        out.add(mono, coefficient_[k]);
      }
    for (; i < rest.size(); ++i) out.add(rest[i].first, rest[i].second);
    return out;
  }

 private:
  int m_;
  std::vector<T> coefficient_;
  std::vector<char> present_;
  RatePoly<T> rest_;
};

}  // namespace linkproof
