// A canonical structure of rational expressions that does not depend on the run: what the Tape
// compiles (tape.h), so that floating-point results are the same bytes in every run, process and
// symbol-creation order.
//
// Why the operand order (canonical_order.h) is not enough. GiNaC moves numeric content between
// a sum and the product or power it stands in, choosing by its own operand order, which follows
// hash values seeded with addresses (ASLR) and symbol serials (creation order):
//
//   (b - a) * c   is stored as  (b - a)*c  in one run and  -(a - b)*c  in another;
//   (4b - 2a)^-1  as            1/2*(2b - a)^-1            or  -1/2*(a - 2b)^-1.
//
// The trees are equal as functions but not as trees, and a floating-point evaluation of each
// rounds differently. Here every expression is split as
//
//   e = content(e) * primitive(e),     content a rational number,
//
// with the primitive part canonical (a function of the mathematical structure only):
//   * a number is its own content, primitive 1;
//   * a symbol has content 1;
//   * a product (or integer power) multiplies the contents of its factors; its primitive part is
//     the product of the factors' primitive parts, equal bases merged (exponents added);
//   * a sum of terms t_i = c_i p_i (terms with equal p_i merged, zero terms dropped) has content
//     s*g, g = gcd(numerators of c_i) / lcm(denominators of c_i), s the sign of the coefficient of
//     the first term in the canonical order below, and primitive part sum (c_i / (s g)) p_i:
//     integer coefficients without a common factor, the first one positive.
// Whichever way GiNaC distributed signs and factors, the primitive parts are the same nodes and
// the contents the same numbers.
//
// Primitive parts are interned as nodes (One, Symbol, Sum, Product), equal structures get one id,
// and every node carries a 64-bit key of its structure (symbols by input index and name, numbers
// by value). compare() is a total order: by key, then (on a key collision) by structure; the
// children of every node are stored in that order, which is the order the Tape evaluates them in.
//
// Supported: rational numbers, the given input symbols, sums, products, integer powers; anything
// else is an InternalError, unless the form was made with_atoms(): then every other symbol,
// function call, irrational number or non-integer power is an opaque Atom node (keyed by name
// and the canonical keys of its arguments), for evaluators that give atoms a value themselves
// (the claim evaluator). Not thread-safe (GiNaC is not).
#pragma once

#include <ginac/ginac.h>

#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace linkproof {

class CanonicalForm {
 public:
  using Id = std::uint32_t;
  enum class Kind : std::uint8_t { One, Symbol, Sum, Product, Atom };

  /// A primitive part. Children are in canonical order (compare()).
  struct Node {
    Kind kind = Kind::One;
    std::uint32_t input = 0;                               ///< Symbol: index among the inputs
    std::vector<std::pair<Id, GiNaC::numeric>> terms;      ///< Sum (>= 2 terms): (primitive, nonzero integer coefficient)
    std::vector<std::pair<Id, int>> factors;               ///< Product: (Symbol, Sum or Atom, nonzero exponent), not a lone x^1
    GiNaC::ex atom;                                        ///< Atom: the opaque subexpression
    std::uint64_t key = 0;
  };

  /// e = content * node(primitive).
  struct Split {
    GiNaC::numeric content;
    Id primitive;
  };

  /// The primitive part 1 (the node of every number).
  static constexpr Id one = 0;

  /// `inputs` are the symbols an expression may contain; a symbol is identified by its
  /// position here (and named in keys by its name).
  explicit CanonicalForm(const std::vector<GiNaC::ex>& inputs);
  /// A form whose inputs are known by name only: its expressions are built with the builders
  /// below (motion_tape.h), not split from GiNaC trees.
  explicit CanonicalForm(std::vector<std::string> input_names);
  /// A form without inputs in which whatever is not a rational function is an Atom.
  static CanonicalForm with_atoms();

  /// The split of e; memoised per distinct subexpression. Throws InternalError for what is not
  /// a rational function of the inputs with rational coefficients.
  Split split(const GiNaC::ex& e);

  /// Builders: the split of a number, of input `index`, and of the sum, product or integer
  /// power of split operands, each what split() gives for the GiNaC tree of that shape (split()
  /// is made of them). A sum does not merge an operand that is itself a sum into its terms
  /// (GiNaC's add does, before split() sees it): a builder passes those terms one by one.
  Split number(const GiNaC::numeric& value) const;
  Split input(std::uint32_t index);
  Split sum(const std::vector<Split>& terms);
  Split product(const std::vector<Split>& factors);
  Split power(const Split& base, int exponent);

  size_t input_count() const { return input_names_.size(); }
  const Node& node(Id id) const { return nodes_[id]; }

  /// A total order of primitive parts that is the same in every run: <0, 0, >0.
  int compare(Id a, Id b) const;

 private:
  Id intern(Node n);
  Id sum_of(std::vector<std::pair<Id, GiNaC::numeric>> terms, GiNaC::numeric& content);
  Id product_of(std::vector<std::pair<Id, int>> factors);
  Split split_uncached(const GiNaC::ex& e);
  Split atom(const GiNaC::ex& e);

  bool atoms_ = false;
  std::vector<Node> nodes_;
  std::vector<std::string> input_names_;
  std::unordered_map<GiNaC::ex, std::uint32_t, std::hash<GiNaC::ex>, GiNaC::ex_is_equal> input_index_;
  std::unordered_map<std::string, Id> interned_;
  std::unordered_map<GiNaC::ex, Split, std::hash<GiNaC::ex>, GiNaC::ex_is_equal> memo_;
  std::unordered_map<GiNaC::ex, Id, std::hash<GiNaC::ex>, GiNaC::ex_is_equal> atom_ids_;
};

}  // namespace linkproof
