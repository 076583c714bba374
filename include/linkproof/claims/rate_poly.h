// RatePoly<T>: a polynomial in the input rates omega_j and omega-dot_j (j = 1..n-3) with
// coefficients in T. Every claim side is evaluated to one, so that the comparison of two sides
// is made both as a whole (at the given rates) and term by term (per monomial): a wrong
// coefficient of omega_1 omega_2 is named, not just a wrong total (SPEC A4, last item).
//
// Division is allowed only by a rate-free polynomial: the paper's formulas are polynomial in
// the rates, and a claim that is not is reported as such.
#pragma once

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "linkproof/core/error.h"
#include "linkproof/core/scalar.h"

namespace linkproof {

/// A rate variable: omega_j (kind Omega) or omega-dot_j (kind OmegaDot), j >= 1.
struct RateVariable {
  enum Kind { Omega = 0, OmegaDot = 1 };
  int index;
  Kind kind;
  int id() const { return 2 * index + kind; }
  static RateVariable from_id(int id) { return {id / 2, static_cast<Kind>(id % 2)}; }
};

/// A monomial: the sorted ids of its variables, with repetition ([] is the constant 1).
using Monomial = std::vector<int>;

/// "1", "omega[1]^2", "omega[1]*omega_dot[2]": the labels of term-by-term comparisons.
std::string monomial_label(const Monomial& m);
/// The input indices a monomial involves (sorted, unique).
std::vector<int> monomial_indices(const Monomial& m);

template <class T>
class RatePoly {
 public:
  RatePoly() = default;
  /// The constant c.
  explicit RatePoly(T c) { terms_.emplace(Monomial{}, std::move(c)); }
  static RatePoly variable(RateVariable v) {
    RatePoly p;
    p.terms_.emplace(Monomial{v.id()}, from_int<T>(1));
    return p;
  }

  const std::map<Monomial, T>& terms() const { return terms_; }
  bool is_constant() const { return terms_.empty() || (terms_.size() == 1 && terms_.begin()->first.empty()); }
  /// The rate-free part.
  T constant() const {
    auto it = terms_.find(Monomial{});
    return it == terms_.end() ? from_int<T>(0) : it->second;
  }
  /// The coefficient of m (0 if absent).
  T coefficient(const Monomial& m) const {
    auto it = terms_.find(m);
    return it == terms_.end() ? from_int<T>(0) : it->second;
  }
  int degree() const {
    int d = 0;
    for (const auto& [m, c] : terms_) d = std::max(d, static_cast<int>(m.size()));
    return d;
  }

  /// The value at the given rates (omega[j-1], omega_dot[j-1]).
  T evaluate(const std::vector<T>& omega, const std::vector<T>& omega_dot) const {
    T sum = from_int<T>(0);
    for (const auto& [m, c] : terms_) {
      T t = c;
      for (int id : m) {
        const RateVariable v = RateVariable::from_id(id);
        const auto k = static_cast<size_t>(v.index - 1);
        t = t * (v.kind == RateVariable::Omega ? omega.at(k) : omega_dot.at(k));
      }
      sum = sum + t;
    }
    return sum;
  }

  /// In place: O(terms of b), whatever the size of *this (a sum accumulated term by term with
  /// `total = total + t` would copy the total every time).
  RatePoly& operator+=(const RatePoly& b) {
    for (const auto& [m, c] : b.terms_) add(m, c);
    return *this;
  }
  RatePoly& operator-=(const RatePoly& b) {
    for (const auto& [m, c] : b.terms_) add(m, -c);
    return *this;
  }
  friend RatePoly operator+(RatePoly a, const RatePoly& b) { return std::move(a += b); }
  friend RatePoly operator-(RatePoly a, const RatePoly& b) { return std::move(a -= b); }
  friend RatePoly operator-(const RatePoly& a) { return RatePoly() - a; }
  friend RatePoly operator*(const RatePoly& a, const RatePoly& b) {
    RatePoly p;
    for (const auto& [ma, ca] : a.terms_)
      for (const auto& [mb, cb] : b.terms_) {
        Monomial m = ma;
        m.insert(m.end(), mb.begin(), mb.end());
        std::sort(m.begin(), m.end());
        p.add(m, ca * cb);
      }
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
    for (auto& [m, c] : a.terms_) c = c / d;
    return a;
  }

 private:
  void add(const Monomial& m, const T& c) {
    auto [it, fresh] = terms_.emplace(m, c);
    if (!fresh) it->second = it->second + c;
  }
  // Exact zero coefficients are kept: whether a coefficient vanishes is for the judge to say
  // (in floating point "zero" is a verdict, not a representation decision).
  std::map<Monomial, T> terms_;
};

}  // namespace linkproof
