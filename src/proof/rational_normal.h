// Zero tests of rational functions built as expression DAGs, for the per-n proofs and the lift
// check. Private to src/proof.
//
// GiNaC's normal() decides "identically zero as a rational function", but it walks the
// expression as a tree: a subexpression shared by many nodes (the construction's points, the
// truth's solved rates: the trees of a proof are 15-30 times their DAGs) is normalised again at
// every use. RationalNormalizer computes the same normal form, numerator / denominator as
// expanded polynomials, once per distinct node (memoised by structural equality), combining the
// children's fractions as normal() does:
//   a/b + c/d = (a d' + c b') / (g b' d')   with g = gcd(b, d), b = g b', d = g d',
//   (a/b)(c/d), powers with integer exponents, then the gcd of numerator and denominator
//   cancelled. A node that is not a rational operation (a function such as abs, a non-integer
//   power) is normalised by normal() itself and kept as an opaque numerator / denominator.
// Soundness does not rest on the gcds (they only keep the polynomials small): every step is an
// identity of rational functions, so the numerator is the zero polynomial iff the expression is
// identically zero wherever it is defined. As with normal(), cancelled factors may vanish: the
// exceptional sets are read off the unsimplified expressions (exceptional_set.h), not from here.
#pragma once

#include <ginac/ginac.h>

#include <chrono>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "core/modular_point.h"

namespace linkproof::proof_detail {

/// A rational function as numerator / denominator, both expanded; the denominator is never 0.
struct Fraction {
  GiNaC::ex num, den;
  bool polynomial = true;  ///< false if num or den holds an opaque part (no gcd is taken then)
};

/// Thrown by a RationalNormalizer past its deadline, or about to expand a product of more terms
/// than its limit (one such expansion could outlast any deadline): `why` says which.
struct NormalizerOutOfTime {
  std::string why;
  bool deadline = false;  ///< the time budget ran out (else a size limit was reached)
};

class RationalNormalizer {
 public:
  /// `cancel`: take gcds to keep fractions reduced (the default). Without, sums and products
  /// only multiply out (a/b + c/d = (ad + cb)/(bd) unless b = d): the numerator is still zero
  /// exactly when the expression is, and no multivariate gcd is ever computed (for expressions
  /// whose denominators are few and known, e.g. the mechanism proofs', gcds cost the most).
  explicit RationalNormalizer(bool cancel = true) : cancel_(cancel) {}
  /// From now on, normalising a node not seen before after `deadline` throws NormalizerOutOfTime.
  void set_deadline(std::chrono::steady_clock::time_point deadline) { deadline_ = deadline; }
  /// From now on, a product whose expansion may have more than `terms` terms throws
  /// NormalizerOutOfTime instead of being expanded.
  void set_term_limit(double terms) { term_limit_ = terms; }

  /// The normal form of e (throws GiNaC::pole_error if a denominator is identically 0).
  const Fraction& normal(const GiNaC::ex& e);
  /// The numerator of e's normal form (expanded; GiNaC's normal() where e is not a rational
  /// operation throughout, so that it is reduced against the denominator).
  GiNaC::ex numerator(const GiNaC::ex& e);
  /// e is identically zero as a rational function of its symbols.
  bool is_zero(const GiNaC::ex& e);
  /// d e / d s is identically zero (from the normal form N/D: N' D - N D' = 0).
  bool is_constant_in(const GiNaC::ex& e, const GiNaC::symbol& s);
  /// The expanded sum of the products a_i b_i of `products`, under this normalizer's deadline
  /// (checked between partial products; the term limit is not applied: such an expansion can be
  /// stopped at the deadline).
  GiNaC::ex expanded_sum(const std::vector<std::pair<GiNaC::ex, GiNaC::ex>>& products);

 private:
  Fraction compute(const GiNaC::ex& e);
  std::unordered_map<GiNaC::ex, Fraction, std::hash<GiNaC::ex>, GiNaC::ex_is_equal> memo_;
  ModularPoint point_;  // a quick rejection before the symbolic normal form
  std::optional<std::chrono::steady_clock::time_point> deadline_;
  bool cancel_ = true;
  double term_limit_ = 0;  // 0: none
  void check_product_size(const GiNaC::ex& a, const GiNaC::ex& b, int power = 1) const;
  /// Throws NormalizerOutOfTime past the deadline: before every combination of normalized parts,
  /// which is where the time goes when the parts themselves are memoized.
  void check_deadline() const;
};

}  // namespace linkproof::proof_detail
