// The vocabulary of claim expressions: the names a claim file may use, what each means, and how
// it is indexed. Documented for users in README.md ("Claim files"); `linkproof check-claim
// --vocabulary` prints this table.
//
// Indices follow the paper (docs/conventions.md §A1): inputs j = 1..n-3 (relative to the fixed side n), sides
// and joints k = 1..n. In an index, `n` is the number of sides and j, l are bound by the sums:
//   sum_j(e)         sum over inputs j = 1..n-3
//   sum_pairs(e)     sum over ordered pairs j != l (each unordered pair twice; docs/conventions.md §A3)
//   sum_pairs_lt(e)  sum over j < l only (a tempting misreading: docs/conventions.md §A5.6)
// `for_each: j` in a claim makes j free: the claim is then one statement per input j (eq. 4).
#pragma once

#include <string>
#include <vector>

namespace linkproof {

enum class WordKind {
  GlobalScalar,   ///< a number of the configuration: omega_dot_out, cot_phi, D, ...
  InputScalar,    ///< indexed by an input j: i_out[j], lambda[j], omega[j], ...
  SideVector,     ///< indexed by a side or joint k = 1..n: r[k], K[k], acc[k]
  InputVector,    ///< indexed by an input j: Kp[j], Q[j], Pp[j]
  SideScalar,     ///< indexed by a side k: side_omega[k], side_omega_dot[k]
  VectorFunction, ///< dot(a,b), cross(a,b), norm2(a), perp(a), vx(a), vy(a)
  Sum,            ///< sum_j, sum_pairs, sum_pairs_lt
  Index,          ///< n, j, l: only inside an index
};

struct Word {
  std::string name;
  WordKind kind;
  int arity;            ///< number of arguments (0 for symbols)
  std::string meaning;  ///< one line, with the paper's notation and docs/conventions.md section
};

/// Every word, in the order of the documentation.
const std::vector<Word>& vocabulary();
/// The word called `name` with `arity` arguments, or nullptr.
const Word* find_word(const std::string& name, int arity);
/// Index of a word in vocabulary().
int word_code(const Word& w);

}  // namespace linkproof
