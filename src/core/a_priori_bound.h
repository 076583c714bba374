// A priori forward error bounds for division-free programs: the cheap first stage of a
// floating-point filter (Shewchuk's "static/semi-static filters", CGAL's filtered kernels).
//
// A program of +, -, * evaluated in an IEEE type F with unit roundoff u, on inputs that are
// exact in F, satisfies for every computed value x^ (Higham, "Accuracy and Stability of
// Numerical Algorithms", 2nd ed., sec. 3.1 and Lemma 3.1)
//
//     |x^ - x| <= gamma_k * m,      gamma_k = k u / (1 - k u),
//
// where x is the exact value of the same program, m the exact value of its "magnitude shadow"
// (the program run on |inputs| with every - replaced by +), and k the program's depth:
//     depth(input) = 0,  depth(a +- b) = max(depth a, depth b) + 1,  depth(a b) = depth a + depth b + 1.
// Underflow: a product may lose up to eta = 2^-1075 absolutely (sums are exact when subnormal).
// The shadow of a product adds c = 2^-1000 (so gamma_1 c >= eta covers it), which also keeps the
// shadow itself normal. The shadow computed in F, m^, satisfies m^ >= (1 - u)^(2k) m (each
// operation of the shadow rounds at most twice per level of depth, and only downwards by u), so
//
//     |x^ - x| <= gamma_k (1 - u)^(-2k) m^  <=  1.001 k u m^      whenever k u <= 2^-20.
//
// Two scalar types evaluate one generic program to obtain these: ShadowedFloat<F> carries the
// value and its shadow; OperationDepth carries the depth k (data-independent, so computed once
// per program shape). Overflow shows as a non-finite value or shadow; the caller rejects it.
// Neither type has ScalarTraits: generic programs run on them take their zero as T{}, since a
// constant rounded at run time would cost more than the program.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace linkproof {

/// A value computed in F together with its magnitude shadow (see the file comment).
template <class F>
struct ShadowedFloat {
  F v{};  ///< the value, computed in F
  F m{};  ///< the magnitude shadow, computed in F (>= 0)

  /// The added shadow of every product, covering its underflow (2^-1000).
  static constexpr F underflow_cover() { return F(0x1p-1000); }

  ShadowedFloat() = default;
  /// An input that is exact in F (depth 0): its shadow is |x|.
  static ShadowedFloat exact(F x) { return {x, std::abs(x)}; }
  /// The correctly rounded result of one operation on exact inputs, e.g. a difference of two
  /// exact coordinates: |x - exact| <= u |exact|, so it enters at depth 1 with shadow |x| (the
  /// shadow's (1 - u) shortfall is inside the (1 - u)^(2k) of the file comment). Far tighter
  /// than the shadow |p| + |q| of p - q when p and q are large and close.
  static ShadowedFloat rounded_once(F x) { return {x, std::abs(x)}; }

  friend ShadowedFloat operator+(const ShadowedFloat& a, const ShadowedFloat& b) { return {a.v + b.v, a.m + b.m}; }
  friend ShadowedFloat operator-(const ShadowedFloat& a, const ShadowedFloat& b) { return {a.v - b.v, a.m + b.m}; }
  friend ShadowedFloat operator-(const ShadowedFloat& a) { return {-a.v, a.m}; }
  friend ShadowedFloat operator*(const ShadowedFloat& a, const ShadowedFloat& b) {
    return {a.v * b.v, a.m * b.m + underflow_cover()};
  }
  ShadowedFloat& operator+=(const ShadowedFloat& b) { return *this = *this + b; }
  ShadowedFloat& operator-=(const ShadowedFloat& b) { return *this = *this - b; }
  ShadowedFloat& operator*=(const ShadowedFloat& b) { return *this = *this * b; }

 private:
  ShadowedFloat(F value, F shadow) : v(value), m(shadow) {}
};

/// The depth k of a value in a program of +, -, * (see the file comment); inputs have depth 0.
struct OperationDepth {
  long k = 0;

  friend OperationDepth operator+(OperationDepth a, OperationDepth b) { return {std::max(a.k, b.k) + 1}; }
  friend OperationDepth operator-(OperationDepth a, OperationDepth b) { return {std::max(a.k, b.k) + 1}; }
  friend OperationDepth operator-(OperationDepth a) { return a; }
  friend OperationDepth operator*(OperationDepth a, OperationDepth b) { return {a.k + b.k + 1}; }
  OperationDepth& operator+=(OperationDepth b) { return *this = *this + b; }
  OperationDepth& operator-=(OperationDepth b) { return *this = *this - b; }
  OperationDepth& operator*=(OperationDepth b) { return *this = *this * b; }
};

/// Upper bound of |x^ - x| for a value of depth k with computed shadow m (see the file comment);
/// infinite if k u > 2^-20 or m is not finite. The bound's own rounding is inside the 1.001.
template <class F>
F a_priori_error_bound(const ShadowedFloat<F>& x, long depth) {
  const F u = std::numeric_limits<F>::epsilon() / 2;
  const F ku = static_cast<F>(depth) * u;
  if (!(ku <= F(0x1p-20)) || !std::isfinite(x.m)) return std::numeric_limits<F>::infinity();
  return F(1.001) * ku * x.m;
}

}  // namespace linkproof
