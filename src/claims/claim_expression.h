// A claim expression: text in the polygon language of vocabulary.h, checked and parsed into a GiNaC
// expression (GiNaC's own parser does the parsing; `i_out[j]` is read as the function call
// i_out(j)).
//
// Before GiNaC sees the text, a scanner checks it with positions, because GiNaC's parser
// reports neither line nor column reliably: unknown names, a wrong number of arguments, an
// index outside [ ], j or l where no sum binds them, unbalanced brackets, a missing operand,
// decimal numbers (GiNaC reads 0.5 as a float; claims are exact: write 1/2). Every error is an
// InputError whose source is "FILE:LINE:COLUMN" of the offending character.
#pragma once

#include <ginac/ginac.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "claims/vocabulary.h"
#include "symbolic/canonical_form.h"

namespace linkproof {

/// Where a character of an expression is in its file: (line, column), both 1-based.
using PositionMap = std::function<std::pair<int, int>(size_t offset)>;

/// A position map for text that stands alone: line 1 + newlines, column from the line start.
PositionMap standalone_positions(const std::string& text);

struct ExpressionContext {
  std::string file = "<expression>";  ///< for error messages
  std::string field = "expression";   ///< e.g. "claims[3].rhs"
  bool j_is_free = false;             ///< `for_each: j`: j may be used outside sums
};

/// Which sum binds the index symbols at a place in an expression (the scanner knows it).
enum class IndexBinding { None, ForEachJ, SumJ, SumPairs, SumPairsLt };

/// One indexed word in an expression, as written: `omega[j]`, `r[n-1]`, `K[2]`.
struct IndexUse {
  std::string word;          ///< the vocabulary word, e.g. "omega"
  bool input_index = false;  ///< 1..n-3 (an input j) rather than 1..n (a side or joint)
  GiNaC::ex index;           ///< the index expression, in the symbols n, j, l
  std::string index_text;    ///< as written
  IndexBinding binding = IndexBinding::None;
  std::string where;         ///< "FILE:LINE:COLUMN" of the word
};

/// One divisor of an expression as written: the operand after a '/', or the base of a negative
/// power. GiNaC simplifies an expression as it builds it (Z*X/Z = X, 0/Z = 0, (1/Z)^0 = 1), so a
/// divisor can be gone from expression() although the claim as written is undefined where it
/// vanishes; the evaluator tests each of these separately (claim_evaluator.h). Numbers are left
/// out (GiNaC refuses a division by the number 0 when it parses).
struct WrittenDivisor {
  std::string text;     ///< as written, e.g. "dot(r[j], perp(r[j]))"
  GiNaC::ex expression;  ///< its own parse (its inner divisors are entries of their own)
  IndexBinding binding = IndexBinding::None;  ///< which sum binds its j, l
  std::string where;    ///< "FILE:LINE:COLUMN" of its first character
};

/// One quantity word of an expression as written (`omega_out`, `cot_beta[j]`, `Q[j+1]`, not a
/// function such as dot or a sum). GiNaC simplifies as it builds (0*X = 0, X - X = 0, X^0 = 1,
/// D*N/D = N), and the canonical form may cancel more, so a word can be gone from what is
/// evaluated although the claim as written is undefined where the word is (a dead centre, Q at
/// infinity). The evaluator evaluates each word that is gone (claim_evaluator.h), and in a proof
/// every word, whose divisors belong to the exceptional set.
struct WrittenWord {
  std::string text;     ///< as written, e.g. "cot_beta[j]"
  GiNaC::ex expression;  ///< its own parse
  IndexBinding binding = IndexBinding::None;  ///< which sum binds its j, l
  std::string where;    ///< "FILE:LINE:COLUMN" of its first character
  /// True if the compiled expression (claim_program.h) has no leaf of this word with this index
  /// under this binding: evaluating the expression never reads it.
  bool cancelled = false;
};

class ClaimExpression {
 public:
  /// Checks and parses `text`; throws InputError naming file:line:column, the field and the problem.
  static ClaimExpression parse(const std::string& text, const ExpressionContext& context,
                               const PositionMap& positions);
  static ClaimExpression parse(const std::string& text, const ExpressionContext& context = {}) {
    return parse(text, context, standalone_positions(text));
  }

  const std::string& text() const { return text_; }
  const GiNaC::ex& expression() const { return expression_; }
  /// Every indexed word, for the range checks of claim_indices.h.
  const std::vector<IndexUse>& index_uses() const { return index_uses_; }
  /// Every divisor as written, in the order of the text.
  const std::vector<WrittenDivisor>& divisors() const { return divisors_; }
  /// Every quantity word as written, in the order of the text.
  const std::vector<WrittenWord>& words() const { return words_; }
  const std::string& field() const { return field_; }

 private:
  std::string text_;
  GiNaC::ex expression_;
  std::vector<IndexUse> index_uses_;
  std::vector<WrittenDivisor> divisors_;
  std::vector<WrittenWord> words_;
  std::string field_;
};

/// The GiNaC atoms of the vocabulary (one table, so that symbols keep their identity).
namespace claim_atoms {
/// The symbol of a 0-arity word (global quantity or index symbol n, j, l).
const GiNaC::symbol& symbol_of(int word_code);
/// The symbol of an index word: n, j or l (Evaluation::IndexN, IndexJ, IndexL).
const GiNaC::symbol& index_symbol(Evaluation index);
/// The word code of a symbol of the table, or -1.
int code_of_symbol(const GiNaC::ex& e);
/// If e is a call of a vocabulary word: its code and arguments; else code -1.
int code_of_call(const GiNaC::ex& e);
/// The canonical form (symbolic/canonical_form.h, with atoms: vocabulary symbols and calls) in
/// which claim expressions are evaluated. GiNaC orders the operands of sums and products, and
/// places signs and numeric factors between them, by hash values that depend on addresses (ASLR)
/// and symbol serials, so evaluating its trees as stored gave other floating-point results and
/// bounds in other runs. One per process, on the thread that uses GiNaC.
CanonicalForm& canonical_form();
}  // namespace claim_atoms

}  // namespace linkproof
