// RatePoly<T>: a polynomial in the input rates omega_j and omega-dot_j (j = 1..n-3) with
// coefficients in T. Every claim side is evaluated to one, so that the comparison of two sides
// is made both as a whole (at the given rates) and term by term (per monomial): a wrong
// coefficient of omega_1 omega_2 is named, not just a wrong total (docs/conventions.md §A4, last item).
//
// Division is allowed only by a rate-free polynomial: the paper's formulas are polynomial in
// the rates, and a claim that is not is reported as such.
//
// Representation (issue 13): a monomial is a fixed-size key (no allocation) and a polynomial a
// flat vector of (monomial, coefficient) terms, appended to and sorted only when read. The
// result is the one a map from monomial to coefficient gives, bit for bit: terms come out in
// the monomials' order, and the coefficients of one monomial are added in the order they
// arrived ((c1 + c2) + c3), which floating-point results depend on.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <compare>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "linkproof/core/error.h"
#include "core/exact_sum.h"
#include "core/scalar.h"
#include "core/stable_radix_sort.h"

namespace linkproof {

/// A rate variable: omega_j (kind Omega) or omega-dot_j (kind OmegaDot), j >= 1.
struct RateVariable {
  enum Kind { Omega = 0, OmegaDot = 1 };
  int index;
  Kind kind;
  int id() const { return 2 * index + kind; }
  static RateVariable from_id(int id) { return {id / 2, static_cast<Kind>(id % 2)}; }
};

/// A monomial: the sorted ids of its variables, with repetition (empty: the constant 1), at
/// most kMaxDegree of them. Ordered lexicographically by its ids, a prefix first.
class Monomial {
 public:
  static constexpr int kMaxDegree = 8;
  static constexpr int kMaxId = 0xfffe;

  Monomial() = default;
  /// The product of the given variables (any order).
  Monomial(std::initializer_list<int> ids) {
    check_degree(static_cast<int>(ids.size()));
    std::array<int, kMaxDegree> sorted{};
    // check_degree threw above kMaxDegree; the min says so to the compiler (-Warray-bounds).
    const size_t k = std::min(ids.size(), sorted.size());
    std::copy(ids.begin(), ids.begin() + k, sorted.begin());
    std::sort(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(k));
    for (size_t i = 0; i < k; ++i) set(static_cast<int>(i), sorted[i]);
  }

  /// The number of variables (the degree).
  int size() const {
    if (words_[0] == 0) return 0;
    if (words_[1] == 0) return 4 - std::countr_zero(words_[0]) / 16;
    return 8 - std::countr_zero(words_[1]) / 16;
  }
  bool empty() const { return words_[0] == 0; }
  /// The i-th id in ascending order, 0 <= i < size().
  int operator[](int i) const { return static_cast<int>((words_[i / 4] >> shift(i)) & 0xffff) - 1; }

  /// a * b; a term of degree above kMaxDegree is refused (a claim's input error).
  static Monomial product(const Monomial& a, const Monomial& b) {
    if (b.words_[0] == 0) return a;
    if (a.words_[0] == 0) return b;
    const int na = a.size(), nb = b.size();
    // Degree <= 4 (a claim's terms are of degree 2): every slot in word 0, merged as stored
    // values (id + 1, already checked when a and b were made). A summand program forms one
    // product per instruction per j and l: the general merge below was 6 % of a double check.
    if (na + nb <= 4) return product_in_word0(a.words_[0], na, b.words_[0], nb);
    check_degree(na + nb);
    Monomial m;
    int i = 0, k = 0, out = 0;
    while (i < na || k < nb) {
      if (k == nb || (i < na && a[i] <= b[k])) m.set(out++, a[i++]);
      else m.set(out++, b[k++]);
    }
    return m;
  }

  // Slot i holds id + 1 in 16 bits, slot 0 in the highest bits of the first word and unused
  // slots 0, so that comparing the words compares the ids lexicographically.
  // Written out: the defaulted operators compare the std::array through a memcmp call (~5 %
  // of a double check).
  friend std::strong_ordering operator<=>(const Monomial& a, const Monomial& b) {
    if (a.words_[0] != b.words_[0]) return a.words_[0] <=> b.words_[0];
    return a.words_[1] <=> b.words_[1];
  }
  friend bool operator==(const Monomial& a, const Monomial& b) {
    return a.words_[0] == b.words_[0] && a.words_[1] == b.words_[1];
  }
  /// The two words, whose integer order (word 0 first) is the monomials' order: a radix key.
  const std::array<std::uint64_t, 2>& key() const { return words_; }

 private:
  static int shift(int i) { return 48 - 16 * (i % 4); }
  void set(int i, int id) {
    if (id < 0 || id > kMaxId) throw InternalError("rate variable id " + std::to_string(id) + " out of range");
    words_[static_cast<size_t>(i / 4)] |= static_cast<std::uint64_t>(id + 1) << shift(i);
  }
  /// The product of na slots of word a and nb of word b (na, nb >= 1, na + nb <= 4).
  static Monomial product_in_word0(std::uint64_t a, int na, std::uint64_t b, int nb) {
    Monomial m;
    if (na == 1 && nb == 1) {  // the common case: omega_j * omega_l
      const std::uint64_t x = a >> 48, y = b >> 48;
      m.words_[0] = std::min(x, y) << 48 | std::max(x, y) << 32;
      return m;
    }
    std::array<std::uint64_t, 4> slots{};
    int k = 0;
    for (int i = 0; i < na; ++i) slots[static_cast<size_t>(k++)] = a >> shift(i) & 0xffff;
    for (int i = 0; i < nb; ++i) slots[static_cast<size_t>(k++)] = b >> shift(i) & 0xffff;
    for (int i = 1; i < k; ++i)
      for (int j = i; j > 0 && slots[static_cast<size_t>(j)] < slots[static_cast<size_t>(j - 1)]; --j)
        std::swap(slots[static_cast<size_t>(j)], slots[static_cast<size_t>(j - 1)]);
    for (int i = 0; i < k; ++i) m.words_[0] |= slots[static_cast<size_t>(i)] << shift(i);
    return m;
  }
  static void check_degree(int degree) {
    if (degree > kMaxDegree)
      throw InputError("<claim>", "expression",
                       "a term of degree " + std::to_string(degree) + " in the rates; at most " +
                           std::to_string(kMaxDegree) + " is supported (the paper's formulas are of degree 2)");
  }
  std::array<std::uint64_t, 2> words_{};
};

/// "1", "omega[1]^2", "omega[1]*omega_dot[2]": the labels of term-by-term comparisons.
std::string monomial_label(const Monomial& m);
/// The input indices a monomial involves (sorted, unique).
std::vector<int> monomial_indices(const Monomial& m);
/// Whether m has a rate (omega or omega-dot) of input j; without allocating, for inner loops.
inline bool involves_input(const Monomial& m, int j) {
  for (int i = 0; i < m.size(); ++i)
    if (RateVariable::from_id(m[i]).index == j) return true;
  return false;
}

template <class T>
class RatePoly {
 public:
  using Term = std::pair<Monomial, T>;

  RatePoly() = default;
  /// The constant c.
  explicit RatePoly(T c) { terms_.emplace_back(Monomial{}, std::move(c)); }
  static RatePoly variable(RateVariable v) {
    RatePoly p;
    p.terms_.emplace_back(Monomial{v.id()}, from_int<T>(1));
    return p;
  }

  /// The terms in ascending order of their monomials, one per monomial.
  const std::vector<Term>& terms() const {
    normalize();
    return terms_;
  }
  bool is_constant() const {
    const auto& t = terms();
    return t.empty() || (t.size() == 1 && t.front().first.empty());
  }
  /// The rate-free part.
  T constant() const { return coefficient(Monomial{}); }
  /// The coefficient of m (0 if absent).
  T coefficient(const Monomial& m) const {
    const auto& t = terms();
    auto it = std::lower_bound(t.begin(), t.end(), m, [](const Term& a, const Monomial& b) { return a.first < b; });
    return it == t.end() || !(it->first == m) ? from_int<T>(0) : it->second;
  }
  int degree() const {
    int d = 0;
    for (const auto& [m, c] : terms()) d = std::max(d, m.size());
    return d;
  }

  /// The value at the given rates (omega[j-1], omega_dot[j-1]).
  /// Exact types add the terms in a balanced tree (core/exact_sum.h) and multiply the terms
  /// that share their first rate variable by it once; others add each term's product in order.
  T evaluate(const std::vector<T>& omega, const std::vector<T>& omega_dot) const {
    const auto rate = [&](int id) -> const T& {
      const RateVariable v = RateVariable::from_id(id);
      const auto k = static_cast<size_t>(v.index - 1);
      return v.kind == RateVariable::Omega ? omega.at(k) : omega_dot.at(k);
    };
    // The coefficient times the monomial's rate variables from the `from`-th on.
    const auto value = [&](const Term& term, int from) {
      T t = term.second;
      for (int i = from; i < term.first.size(); ++i) t = t * rate(term.first[i]);
      return t;
    };
    const std::vector<Term>& t = terms();
    if constexpr (GrowingExactNumber<T>) {
      // The terms with the same first variable are consecutive (the monomials' lexicographic
      // order): omega_j (c_jj omega_j + c_j,j+1 omega_{j+1} + ...), one product by omega_j.
      // One buffer for every group's terms (reused) and one for the groups.
      std::vector<T> groups, inner;
      groups.reserve(t.size());
      inner.reserve(t.size());
      for (size_t i = 0; i < t.size();) {
        if (t[i].first.empty()) {
          groups.push_back(t[i++].second);
          continue;
        }
        const int first = t[i].first[0];
        inner.clear();
        for (; i < t.size() && !t[i].first.empty() && t[i].first[0] == first; ++i) inner.push_back(value(t[i], 1));
        groups.push_back(balanced_sum(inner) * rate(first));
      }
      return balanced_sum(groups);
    } else {
      T sum = from_int<T>(0);
      for (const Term& term : t) sum = sum + value(term, 0);
      return sum;
    }
  }

  /// The terms in which a and b differ, each with its own side's coefficient: a' and b' with
  /// a - b = a' - b'. A monomial whose coefficients differ is in each side's part where its
  /// coefficient there is not zero; a term with a zero coefficient counts as absent (a side may
  /// keep the terms that cancelled).
  /// Both are empty exactly when a and b are the same polynomial. Exact types only: for a
  /// floating-point T, equal midpoints are no statement about values.
  friend std::pair<RatePoly, RatePoly> differing_terms(const RatePoly& a, const RatePoly& b)
    requires ScalarTraits<T>::is_exact
  {
    const auto &at = a.terms(), &bt = b.terms();
    std::pair<RatePoly, RatePoly> d;  // appended in ascending order: sorted
    for (size_t i = 0, k = 0; i < at.size() || k < bt.size();) {
      if (k == bt.size() || (i < at.size() && at[i].first < bt[k].first)) {
        if (!linkproof::is_zero(at[i].second)) d.first.terms_.push_back(at[i]);
        ++i;
      } else if (i == at.size() || bt[k].first < at[i].first) {
        if (!linkproof::is_zero(bt[k].second)) d.second.terms_.push_back(bt[k]);
        ++k;
      } else {
        if (!(at[i].second == bt[k].second)) {
          if (!linkproof::is_zero(at[i].second)) d.first.terms_.push_back(at[i]);
          if (!linkproof::is_zero(bt[k].second)) d.second.terms_.push_back(bt[k]);
        }
        ++i, ++k;
      }
    }
    return d;
  }

  /// In place: O(terms of b), whatever the size of *this (the terms are sorted once, when read).
  RatePoly& operator+=(const RatePoly& b) {
    for (const auto& [m, c] : b.terms()) add(m, c);
    return *this;
  }
  RatePoly& operator-=(const RatePoly& b) {
    for (const auto& [m, c] : b.terms()) add(m, -c);
    return *this;
  }
  friend RatePoly operator+(RatePoly a, const RatePoly& b) { return std::move(a += b); }
  friend RatePoly operator-(RatePoly a, const RatePoly& b) { return std::move(a -= b); }
  friend RatePoly operator-(const RatePoly& a) { return RatePoly() - a; }
  friend RatePoly operator*(const RatePoly& a, const RatePoly& b) {
    RatePoly p;
    const auto &ta = a.terms(), &tb = b.terms();
    p.terms_.reserve(ta.size() * tb.size());
    for (const auto& [ma, ca] : ta)
      for (const auto& [mb, cb] : tb) p.add(Monomial::product(ma, mb), ca * cb);
    return p;
  }
  /// c * b and b * c for a constant c: the product with the constant polynomial c, term by term
  /// in the same order (c * coefficient, or coefficient * c), without merging.
  RatePoly left_scaled(const T& c) const {
    RatePoly p = *this;
    p.normalize();
    for (auto& [m, k] : p.terms_) k = c * k;
    return p;
  }
  RatePoly right_scaled(const T& c) const {
    RatePoly p = *this;
    p.normalize();
    for (auto& [m, k] : p.terms_) k = k * c;
    return p;
  }
  /// Division by a rate-free polynomial; anything else is an InputError of the claim.
  friend RatePoly operator/(RatePoly a, const RatePoly& b) {
    if (!b.is_constant())
      throw InputError("<claim>", "expression", "division by an expression that contains rates: not a polynomial in the rates");
    const T d = b.constant();
    // Tested like every divisor of the construction: exactly (a symbolic proof records it in
    // its exceptional set; an exact check reports the claim undefined where it vanishes).
    if (linkproof::is_zero(d))
      throw UndefinedQuantity("a divisor in the claim's expression", "it is zero at this configuration");
    a.normalize();
    for (auto& [m, c] : a.terms_) c = c / d;
    return a;
  }

  /// Adds c * m in place. While the terms are sorted, the last is the only one of its monomial
  /// and a term of that monomial is added to it at once; once they are not, adding must wait for
  /// normalize(), which keeps the order of arrival.
  void add(const Monomial& m, T c) {
    if (sorted_ && !terms_.empty()) {
      Term& last = terms_.back();
      if (last.first == m) {
        last.second = last.second + c;
        return;
      }
      if (m < last.first) sorted_ = false;
    }
    // Most polynomials of a claim have a few terms: one allocation for up to 8, not four.
    if (terms_.capacity() == 0) terms_.reserve(8);
    terms_.emplace_back(m, std::move(c));
  }

 private:
  /// Sorts the terms by monomial (stably: the order of arrival is kept within a monomial) and
  /// adds those of one monomial from left to right.
  void normalize() const {
    if (sorted_) return;
    const auto by_monomial = [](const Term& a, const Term& b) { return a.first < b.first; };
    if (terms_.size() <= 16) {
      for (size_t i = 1; i < terms_.size(); ++i)  // insertion sort: no buffer for small polynomials
        for (size_t k = i; k > 0 && by_monomial(terms_[k], terms_[k - 1]); --k) std::swap(terms_[k], terms_[k - 1]);
    } else if (!merge_sorted_runs(by_monomial)) {
      stable_sort_by_key<2>(terms_, [](const Term& t) { return t.first.key(); });
    }
    size_t out = 0;
    for (size_t i = 1; i < terms_.size(); ++i) {
      if (terms_[i].first == terms_[out].first) terms_[out].second = terms_[out].second + terms_[i].second;
      else if (++out != i) terms_[out] = std::move(terms_[i]);
    }
    terms_.resize(terms_.empty() ? 0 : out + 1);
    sorted_ = true;
  }
  /// Sorts the terms stably by merging their ascending runs, where there are few of them (a
  /// side is usually a few sorted sums added one after another: 11 % of a double check at
  /// n = 1000 went to radix-sorting such sides, perf). A stable sort has one result, so this is
  /// the radix sort's order. False, doing nothing, where there are more than kMaxRuns runs.
  template <class Less>
  bool merge_sorted_runs(Less less) const {
    constexpr size_t kMaxRuns = 8;
    std::array<size_t, kMaxRuns + 1> starts{};
    size_t runs = 1;
    for (size_t i = 1; i < terms_.size(); ++i)
      if (less(terms_[i], terms_[i - 1])) {
        if (runs == kMaxRuns) return false;
        starts[runs++] = i;
      }
    starts[runs] = terms_.size();
    // Each run merged into the sorted prefix before it: equal monomials keep the prefix's first.
    for (size_t r = 1; r < runs; ++r)
      std::inplace_merge(terms_.begin(), terms_.begin() + static_cast<std::ptrdiff_t>(starts[r]),
                         terms_.begin() + static_cast<std::ptrdiff_t>(starts[r + 1]), less);
    return true;
  }

  // Exact zero coefficients are kept: whether a coefficient vanishes is for the judge to say
  // (in floating point "zero" is a verdict, not a representation decision). Sorted and merged
  // lazily (normalize()), hence mutable; a RatePoly is never shared between threads.
  mutable std::vector<Term> terms_;
  mutable bool sorted_ = true;
};

}  // namespace linkproof
