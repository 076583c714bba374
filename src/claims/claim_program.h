// A claim expression compiled once (issue 13): the tree ClaimEvaluator walks for every polygon
// and every index j, l of a sum, in place of the GiNaC tree it came from.
//
// Walking GiNaC's tree per polygon and per pair was most of a double check: a type test per
// node (typeid comparisons), a lookup of the canonical form's split, a word lookup per symbol
// and call, and GiNaC substitutions to read every index. All of that depends on the expression
// only, so it is done here once per distinct expression, and what is left at evaluation is
// arithmetic.
//
// The program is independent of the arithmetic, of n and of the polygon: constants stay
// rational, indices are affine forms in n, j, l (or, rarely, a GiNaC expression substituted at
// evaluation). Its nodes are the canonical form's (claim_atoms::canonical_form()), in the same
// order, so an evaluation does the same operations in the same order as evaluating the canonical
// form directly did: the same bytes in floating point.
//
// Whether a value is a number or a vector is decided here, so a claim that adds a number to a
// vector, multiplies two vectors, raises a vector to a power or uses a vector as a number is
// refused when it is compiled (InputError, the messages the evaluator gave), at every n, even one
// at which the offending term is never evaluated (a sum over no inputs).
#pragma once

#include <cln/rational.h>
#include <ginac/ginac.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "claims/vocabulary.h"

namespace linkproof {

struct SummandProgram;

struct ClaimProgram {
  enum class Op {
    Constant,      ///< a rational number
    Scale,         ///< constant * child (the content of a canonical sum or product)
    Sum,           ///< children added left to right (numbers, or vectors componentwise)
    Product,       ///< children multiplied left to right (at most one vector)
    Power,         ///< child^exponent, exponent an integer != 1; negative: 1 / child^|exponent|
    Global,        ///< a global quantity: word
    InputScalar,   ///< word[index], an input quantity
    InputVector,   ///< Kp[j], Q[j], Pp[j]
    SideVector,    ///< r[k], K[k], acc[k]
    SideScalar,    ///< side_omega[k], side_omega_dot[k]
    Function,      ///< a word of vectors, of its children: dot, cross, norm2, perp, vx, vy
    IndexSum,      ///< sum_j, sum_pairs, sum_pairs_lt of child 0
  };

  /// An index expression, read once.
  struct Index {
    bool uses_j = false, uses_l = false;
    bool bare_bound = false;  ///< the index is j or l itself
    bool affine = false;      ///< c0 + cn n + cj j + cl l with integers
    int c0 = 0, cn = 0, cj = 0, cl = 0;
    GiNaC::ex expression;     ///< substituted at evaluation when not affine
    std::string written;      ///< "word[index]" as the claim writes it, for messages
    std::string bound_note;   ///< the locality note of an index using j or l ("" if none)
    /// The index at n, j, l (0: unbound); InputError if it is not an integer there.
    int at(int n, int j, int l) const { return affine ? c0 + cn * n + cj * j + cl * l : substituted(n, j, l); }
    int substituted(int n, int j, int l) const;
  };

  struct Node {
    Op op = Op::Constant;
    bool is_vector = false;
    const Word* word = nullptr;       ///< the word of a Global, indexed, Function or IndexSum node
    Evaluation evaluation{};          ///< word->evaluation, what the evaluator's switch reads
    int index = -1;                   ///< into indexes
    int exponent = 1;                 ///< Power
    bool small_integer = false;       ///< Constant, Scale: the constant is `integer`
    long integer = 0;
    cln::cl_RA rational;              ///< Constant, Scale
    std::vector<int> children;        ///< into nodes, in evaluation order
    /// IndexSum: its body compiled to straight-line code (claims/summand_program.h); null where
    /// the body is walked.
    std::shared_ptr<const SummandProgram> summand;
  };

  std::vector<Node> nodes;
  std::vector<Index> indexes;
  int root = -1;
};

/// The compiled program of e, compiled on first use and kept for the process (not thread-safe:
/// GiNaC is not). Throws InputError("<claim>", "expression", problem) for an expression that is
/// not well formed whatever the polygon.
const ClaimProgram& compiled_claim(const GiNaC::ex& e);

}  // namespace linkproof
