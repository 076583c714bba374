// The body of a sum (sum_j, sum_pairs, sum_pairs_lt) compiled to straight-line code (issue 28),
// once per claim expression: what ClaimEvaluator runs for every j (and l) in place of walking
// the body's tree.
//
// A check at n = 1000 evaluates each pair-sum body half a million times, and most of that went
// to the walk, not to the arithmetic (perf, double n = 100: the node switch, the leaves' lookup,
// building one-term values and their monomials). What the walk decides from the tree alone is
// decided here once: which operations are done on the coefficients, in which order, and where
// a value stays one term (a coefficient times a monomial).
//
// Same bytes. The program does to the coefficients exactly what the evaluator's one-term values
// (claims/rate_value.h) do, in the same order: a product of two terms multiplies their
// coefficients (a * b), a sum of two terms of one monomial adds them (a + b), a negation negates,
// a power starts from 1 and multiplies. A sum of two terms whose monomials differ becomes a
// polynomial that receives the terms in their order, as RatePoly does. Leaves (a quantity at an
// index, a rate, a global number, a vector of the polygon) are evaluated by the evaluator
// itself, one by one in the walk's order, so that their index checks, locality notes, undefined
// quantities and errors come as they did.
//
// A body is compiled only where the tree alone proves each of those decisions: two terms are
// added where their monomials are the same product of rates at the same indices (equal at every
// j and l), and made a polynomial only where they differ in degree or kind (unequal at every j
// and l). Anything else (a division, a nested sum, a side's rate, a joint's acceleration, a
// polynomial-valued quantity, indices that are not affine, a polynomial inside a product) keeps
// the walk: compile_summand() returns nothing. ClaimEvaluator checks both decisions again at
// run time (an InternalError if the monomials disagree), and SummandProgram.* compares the two
// routes bit for bit.
#pragma once

#include <optional>
#include <vector>

#include "claims/claim_program.h"

namespace linkproof {

struct SummandProgram {
  enum class Op : unsigned char {
    Leaf,        ///< the one-term value of leaf `node`, evaluated by the evaluator
    LeafVector,  ///< the vector value of leaf `node`: x in this register, y in the next (a Skip)
    Skip,        ///< the y of the LeafVector before it
    Constant,    ///< the number of node `node` (a Constant or a Scale), a term without rates
    One,         ///< 1, where a power starts
    Add,         ///< registers a + b, two terms of one monomial
    Multiply,    ///< registers a * b
    Negate,      ///< -register a
  };
  struct Instruction {
    Op op = Op::One;
    int a = -1, b = -1;  ///< registers (earlier instructions)
    int node = -1;       ///< Leaf, LeafVector, Constant: the claim program's node
  };

  std::vector<Instruction> code;  ///< register i is the value of instruction i
  /// The registers of the body's value: one for a term; several for a polynomial, in the order
  /// a RatePoly receives its terms (their monomials differ at the first two).
  std::vector<int> terms;
};

/// The program of the body `body` of a sum in p, or nothing where the body must be walked.
std::optional<SummandProgram> compile_summand(const ClaimProgram& p, int body);

}  // namespace linkproof
