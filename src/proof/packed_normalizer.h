// The normal form of RationalNormalizer(cancel = false) (rational_normal.h), computed in packed
// polynomials (packed_polynomial.h): the same numerator and denominator, term for term, at the
// cost of hash-table arithmetic instead of GiNaC's expansion. Private to src/proof.
//
// It walks the expression DAG once per distinct node (memoised by structural equality) and
// combines the children's fractions by the same rules, without gcds:
//   a/b + c/d = (a d + c b) / (b d), or (a + c) / b when b = d;  (a/b)(c/d) = (a c) / (b d);
//   integer powers; a rational number p/q is itself over 1.
// Every step is an identity of rational functions, so the numerator is the zero polynomial iff
// the expression is identically zero. What it cannot represent (a function such as abs, a
// non-rational number, more than 64 symbols, exponents past 128 bits) throws PackedUnsupported:
// the caller takes GiNaC's route instead. Past the deadline, or about to pass a product's limits
// (its terms, its partial products), it throws NormalizerOutOfTime as RationalNormalizer does.
#pragma once

#include <ginac/ginac.h>

#include <chrono>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "proof/packed_polynomial.h"
#include "proof/rational_normal.h"

namespace linkproof::proof_detail {

/// An expression the packed normal form cannot hold: `why` names the part.
struct PackedUnsupported {
  std::string why;
};

class PackedNormalizer {
 public:
  struct Fraction {
    PackedPolynomial num, den;
  };
  void set_deadline(std::chrono::steady_clock::time_point deadline) { deadline_ = deadline; }
  /// What one product may cost before NormalizerOutOfTime (packed_polynomial.h).
  void set_limits(const PackedLimits& limits) { limits_ = limits; }

  /// The normal form of e (GiNaC::pole_error if a denominator is identically 0).
  const Fraction& normal(const GiNaC::ex& e);
  const PackedPolynomial& numerator(const GiNaC::ex& e) { return normal(e).num; }
  /// The index of symbol s in this normalizer's polynomials (assigned on first use).
  int variable(const GiNaC::ex& s);
  /// a b under this normalizer's deadline and term limit.
  PackedPolynomial multiply(const PackedPolynomial& a, const PackedPolynomial& b);
  /// p as a GiNaC polynomial in the symbols this normalizer has indexed (for tests and reports).
  GiNaC::ex to_ex(const PackedPolynomial& p) const;

 private:
  Fraction compute(const GiNaC::ex& e);
  Fraction sum(const Fraction& a, const Fraction& b);
  Fraction product(const Fraction& a, const Fraction& b);
  void check_deadline() const;
  NormalizerOutOfTime out_of_limits(const PackedTooLarge& t) const;
  std::unordered_map<GiNaC::ex, Fraction, std::hash<GiNaC::ex>, GiNaC::ex_is_equal> memo_;
  std::unordered_map<GiNaC::ex, int, std::hash<GiNaC::ex>, GiNaC::ex_is_equal> index_;
  std::vector<GiNaC::ex> symbols_;
  std::optional<std::chrono::steady_clock::time_point> deadline_;
  PackedLimits limits_;
};

/// det_b^k p for each (delta_b, det_b) in turn, k = p's degree in delta_b: p with every
/// delta_b = 1/det_b cleared, as clear_delta does it in GiNaC (Horner's rule from the lowest
/// power of delta_b present).
PackedPolynomial clear_inverses(PackedPolynomial p, const std::vector<std::pair<GiNaC::ex, GiNaC::ex>>& inverses,
                                PackedNormalizer& n);

/// p reduced by s^2 = 1 - c^2 for every unit axis (c, s): zero iff p vanishes on the circles.
PackedPolynomial reduce_on_circles(PackedPolynomial p, const std::vector<std::pair<GiNaC::ex, GiNaC::ex>>& axes,
                                   PackedNormalizer& n);

}  // namespace linkproof::proof_detail
