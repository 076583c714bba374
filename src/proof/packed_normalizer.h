// A normal form of rational expressions in packed polynomials (packed_polynomial.h), for the
// mechanism proofs' zero tests. Private to src/proof.
//
// Every value is kept as core x prod_k atom_k^e_k: `core` a polynomial, the exponents non-zero
// integers (negative: a denominator), each atom a polynomial stored once, monic (its leading
// coefficient moved into the core): a polynomial met as a divisor, or a single symbol (the
// core's monomial content: a symbol is the atom x^1 over the core 1). It walks the expression
// DAG once per distinct node (memoised by structural equality) and combines the children
// without gcds:
//   products add exponents (an atom divided by itself cancels: no polynomial is multiplied);
//   a sum takes out the atoms' common power, min(e_k, f_k) per atom, multiplies each core by
//   the atom powers the other has more of, and moves the new core's monomial content into the
//   symbols' atoms: the sum of fractions over their least common denominator as a product of
//   atoms, and of their common factors;
//   a quotient makes the divisor's core an atom (a constant core is a number);
//   a symbol registered by set_inverses (a motion's delta_b) is its polynomial's inverse.
// RationalNormalizer(false) (rational_normal.h) multiplies whole denominators instead, so a
// nested construction whose parts share divisors (a point built from points built on the same
// lines) squares them at every level; here they are taken once, and a rate over a rate with
// the same delta_b loses it.
//
// Every step is an identity of rational functions and every atom is a non-zero polynomial, so
// the expression is identically zero iff its core is the zero polynomial. What it cannot
// represent (a function such as abs, a non-rational number, more than 64 symbols, exponents past
// 127 bits) throws PackedUnsupported: the caller takes GiNaC's route instead. Past the deadline,
// about to pass a product's limits (its terms, its partial products), or holding more terms in
// all than its limit allows (memory), it throws NormalizerOutOfTime as RationalNormalizer does.
#pragma once

#include <ginac/ginac.h>

#include <chrono>
#include <map>
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
  /// core x prod atom^exponent; zero: a zero core and no powers.
  struct Factored {
    PackedPolynomial core;
    std::vector<std::pair<int, int>> powers;  ///< (atom, exponent != 0), by atom
  };
  void set_deadline(std::chrono::steady_clock::time_point deadline) { deadline_ = deadline; }
  /// What one product, and the normal form in all, may cost before NormalizerOutOfTime
  /// (packed_polynomial.h).
  void set_limits(const PackedLimits& limits) { limits_ = limits; }
  /// Symbols that stand for 1 / polynomial (a motion's delta_b = 1 / det_b): each is read as
  /// its polynomial's inverse, so no core holds them. Before the first normal().
  void set_inverses(const std::vector<std::pair<GiNaC::ex, GiNaC::ex>>& inverses) {
    for (const auto& [symbol, polynomial] : inverses) inverses_.emplace(symbol, polynomial);
  }

  /// The normal form of e (GiNaC::pole_error if a divisor is identically 0).
  const Factored& normal(const GiNaC::ex& e);
  /// e's core: the zero polynomial iff e is identically zero.
  const PackedPolynomial& core(const GiNaC::ex& e) { return normal(e).core; }
  /// e as a fraction: the core times the atoms of positive exponent, over the others.
  PackedPolynomial numerator(const GiNaC::ex& e);
  PackedPolynomial denominator(const GiNaC::ex& e);
  /// The index of symbol s in this normalizer's polynomials (assigned on first use).
  int variable(const GiNaC::ex& s);
  /// a b under this normalizer's deadline and term limit.
  PackedPolynomial multiply(const PackedPolynomial& a, const PackedPolynomial& b);
  /// p as a GiNaC polynomial in the symbols this normalizer has indexed (for tests and reports).
  GiNaC::ex to_ex(const PackedPolynomial& p) const;

 private:
  Factored compute(const GiNaC::ex& e);
  Factored sum(const Factored& a, const Factored& b);
  Factored product(const Factored& a, const Factored& b);
  Factored inverse(const Factored& a);
  Factored power(const Factored& a, int k);
  /// The atom of polynomial p (registered if new) and the constant c with p = c atom.
  std::pair<int, cln::cl_RA> atom_of(const PackedPolynomial& p);
  /// The atom of the polynomial x_v.
  int variable_atom(int v);
  /// f with its core's monomial content moved into its variables' atoms.
  Factored without_content(Factored f);
  /// atom^k (k > 0), cached.
  const PackedPolynomial& atom_power(int atom, int k);
  /// The product of the atom powers with exponents of sign `sign` (+1 or -1), as a polynomial.
  PackedPolynomial atom_product(const std::vector<std::pair<int, int>>& powers, int sign);
  void check_deadline() const;
  /// Counts p's terms as held (memo, caches); past limits_.held, NormalizerOutOfTime.
  void hold(const PackedPolynomial& p);
  NormalizerOutOfTime out_of_limits(const PackedTooLarge& t) const;
  std::unordered_map<GiNaC::ex, Factored, std::hash<GiNaC::ex>, GiNaC::ex_is_equal> memo_;
  std::vector<PackedPolynomial> atoms_;
  std::unordered_multimap<size_t, int> atom_index_;  // hash of an atom's terms -> atom
  std::vector<int> variable_atoms_;  // per variable: its atom, or -1
  std::map<std::pair<int, int>, PackedPolynomial> atom_powers_;  // (atom, k >= 2) -> atom^k
  std::unordered_map<GiNaC::ex, int, std::hash<GiNaC::ex>, GiNaC::ex_is_equal> index_;
  std::vector<GiNaC::ex> symbols_;
  std::optional<std::chrono::steady_clock::time_point> deadline_;
  PackedLimits limits_;
  size_t held_ = 0;
  std::unordered_map<GiNaC::ex, GiNaC::ex, std::hash<GiNaC::ex>, GiNaC::ex_is_equal> inverses_;
};

/// p reduced by s^2 = 1 - c^2 for every unit axis (c, s): zero iff p vanishes on the circles.
PackedPolynomial reduce_on_circles(PackedPolynomial p, const std::vector<std::pair<GiNaC::ex, GiNaC::ex>>& axes,
                                   PackedNormalizer& n);

}  // namespace linkproof::proof_detail
