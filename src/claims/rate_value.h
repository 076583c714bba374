// RateValue<T>: the value of a scalar claim expression while it is evaluated, a polynomial in
// the rates (rate_poly.h) that is usually one term: a constant, a rate, a product of them. One
// term is kept as (coefficient, monomial), without the allocation and sorting of a RatePoly;
// a value becomes a RatePoly only when a sum of two monomials needs one.
//
// Same bytes as RatePoly. Each operation does to the coefficients exactly what the same
// operation on RatePoly does, in the same order (c1 * c2 for a product of terms; c1 + c2 for a
// sum of terms of one monomial; a - b as a + (-b), as RatePoly subtracts), so an evaluation with
// RateValue gives the floating-point results and error bounds of one with RatePoly throughout
// (RateValueOps.* check it on random values).
#pragma once

#include <utility>

#include "claims/rate_poly.h"

namespace linkproof {

template <class T>
class RateValue {
 public:
  RateValue() = default;
  /// c * m (m empty: the constant c).
  static RateValue term(T c, Monomial m = {}) {
    RateValue v;
    v.c_ = std::move(c);
    v.m_ = m;
    return v;
  }
  static RateValue poly(RatePoly<T> p) {
    RateValue v;
    v.is_poly_ = true;
    v.p_ = std::move(p);
    return v;
  }

  bool is_term() const { return !is_poly_; }
  /// A term's coefficient and monomial (is_term()).
  const T& coefficient() const { return c_; }
  const Monomial& monomial() const { return m_; }
  /// A polynomial's terms (!is_term()).
  const RatePoly<T>& polynomial() const { return p_; }

  RatePoly<T> to_poly() && {
    if (is_poly_) return std::move(p_);
    RatePoly<T> q;
    q.add(m_, std::move(c_));
    return q;
  }
  /// total += *this, in place.
  void add_to(RatePoly<T>& total) const {
    if (is_poly_) total += p_;
    else total.add(m_, c_);
  }

  friend RateValue operator+(RateValue a, const RateValue& b) {
    if (!a.is_poly_ && !b.is_poly_ && a.m_ == b.m_) {
      a.c_ = a.c_ + b.c_;
      return a;
    }
    RatePoly<T> s = std::move(a).to_poly();
    b.add_to(s);
    return poly(std::move(s));
  }
  friend RateValue operator-(const RateValue& a) {
    if (!a.is_poly_) return term(-a.c_, a.m_);
    return poly(-a.p_);
  }
  friend RateValue operator-(RateValue a, const RateValue& b) { return std::move(a) + (-b); }
  friend RateValue operator*(const RateValue& a, const RateValue& b) {
    if (!a.is_poly_ && !b.is_poly_) return term(a.c_ * b.c_, Monomial::product(a.m_, b.m_));
    // A constant times a polynomial (a scaled sum, cot_phi * sum_pairs(...)): its terms in order.
    if (!a.is_poly_ && a.m_.empty()) return poly(b.p_.left_scaled(a.c_));
    if (!b.is_poly_ && b.m_.empty()) return poly(a.p_.right_scaled(b.c_));
    return poly(RateValue(a).to_poly() * RateValue(b).to_poly());
  }

 private:
  bool is_poly_ = false;
  Monomial m_;
  T c_;
  RatePoly<T> p_;
};

}  // namespace linkproof
