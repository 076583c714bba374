// The vocabulary of both claim languages: one table of words that drives scanning, checking,
// compiling, evaluating and the listing (`linkproof check-claim --vocabulary`). Documented for
// users in docs/claims.md ("Vocabulary", "Mechanism claims").
//
// The polygon language (a claim about a polygon and its input rates, the 1966 paper). Indices
// follow the paper (docs/conventions.md §A1): inputs j = 1..n-3 (relative to the fixed side n),
// sides and joints k = 1..n, written in [ ]. In an index, `n` is the number of sides and j, l
// are bound by the sums:
//   sum_j(e)         sum over inputs j = 1..n-3
//   sum_pairs(e)     sum over ordered pairs j != l (each unordered pair twice; docs/conventions.md §A3)
//   sum_pairs_lt(e)  sum over j < l only (a tempting misreading: docs/conventions.md §A5.6)
// `for_each: j` in a claim makes j free: the claim is then one statement per input j (eq. 4).
//
// The mechanism language (a claim about a mechanism scene): words whose arguments are names of
// the scene's links, joints and points, written as in the scene: quoted always works
// (`omega("3")`), a bare identifier where the name is one (`omega(coupler)`). A point P is a
// joint or a tracer point of the scene; J = rotation by +90 degrees.
//
// The vector words dot, cross, norm2, perp, vx, vy belong to both languages: one entry each.
//
// Adding a word: one entry in vocabulary.cpp (with a new Evaluation code) and its case in the
// evaluator of each language it belongs to: claims/claim_evaluator.h (polygon),
// mechanism/mechanism_data_claim.cpp (mechanism). tests/claims/vocabulary_test.cpp evaluates
// every word of each language, so an entry without an evaluation fails a test.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace linkproof {

/// The two claim languages.
enum class Language : std::uint8_t { Polygon, Mechanism };

/// The languages a word belongs to.
enum class Languages : std::uint8_t { Polygon, Mechanism, Both };

/// The kind of a value, of an argument of a word, or of a word's result.
enum class ClaimKind : std::uint8_t {
  Number,      ///< a number (a polynomial in the rates, or a rational of a mechanism)
  Vector,      ///< a plane vector
  Link,        ///< mechanism: the name of a link of the scene
  Point,       ///< mechanism: the name of a joint or tracer point of the scene
  Slider,      ///< mechanism: the name of a prismatic joint of the scene
  InputIndex,  ///< polygon: an input index j = 1..n-3, written in [ ]
  SideIndex,   ///< polygon: a side or joint index k = 1..n, written in [ ]
  SumBody,     ///< polygon: a number summed over the inputs the sum binds
  Index,       ///< polygon: the result of n, j, l: an index symbol, only inside [ ]
};

/// What a word reads or computes: the code the evaluators switch on
/// (claims/claim_evaluator.h for the polygon words, mechanism/mechanism_data_claim.cpp for the
/// mechanism words, both for the shared vector words).
enum class Evaluation : std::uint8_t {
  // Polygon: the engine's truth, relative to the fixed side n.
  OmegaOut, OmegaCpl, OmegaDotOut, OmegaDotCpl, SideOmega, SideOmegaDot, JointAcc,
  // Polygon: inputs and the paper's construction for four-bar j.
  InputOmega, InputOmegaDot, IOut, ICpl, CotBeta, CotGamma, Lambda, Mu, Kp, Q, Pp,
  // Polygon: closed forms, four-bar j solved alone, the angle phi.
  IOutClosed, ICplClosed, LambdaClosed, MuClosed,
  FourbarRatioOut, FourbarRatioCpl, FourbarOmegaOut, FourbarOmegaCpl, FourbarOmegaDotOut, FourbarOmegaDotCpl,
  D, CotPhi, Rho, RhoCompanion,
  // Polygon: geometry, sums and index symbols.
  R, K, SumJ, SumPairs, SumPairsLt, IndexN, IndexJ, IndexL,
  // Mechanism.
  Omega, OmegaRelative, Alpha, AlphaRelative,
  Position, Velocity, VelocityRelative, Acceleration, AccelerationRelative,
  Pole, Centre, CentreAt, SlidingV, SlidingA, Axis, Vec, Meet,
  // Both languages.
  Dot, Cross, Norm2, Perp, Vx, Vy,
};

struct Word {
  std::string name;
  Languages languages;
  std::vector<ClaimKind> arguments;  ///< the arity is its size (0: a symbol of the polygon language)
  ClaimKind result;                  ///< Number, Vector, or Index (n, j, l)
  Evaluation evaluation;
  std::string signature;        ///< as documented and listed: "omega[j]", "vel(P, L, M)", "D"
  std::string meaning;          ///< one line, with the paper's notation where there is one

  int arity() const { return static_cast<int>(arguments.size()); }
  bool belongs_to(Language l) const {
    return languages == Languages::Both || (languages == Languages::Polygon) == (l == Language::Polygon);
  }
  /// Polygon: word[k], indexed with [ ] by an input or a side.
  bool is_indexed() const {
    return arguments.size() == 1 && (arguments[0] == ClaimKind::InputIndex || arguments[0] == ClaimKind::SideIndex);
  }
  /// Polygon: sum_j, sum_pairs, sum_pairs_lt.
  bool is_sum() const { return arguments.size() == 1 && arguments[0] == ClaimKind::SumBody; }
};

/// Every word of both languages, in the order of the documentation (the listing of each
/// language is this order, filtered).
const std::vector<Word>& vocabulary();
/// The word of `language` called `name` with `arity` arguments, or nullptr.
const Word* find_word(Language language, const std::string& name, int arity);
/// The word of the polygon language with this evaluation code (the index symbols n, j, l).
const Word& polygon_word(Evaluation evaluation);
/// The signatures of every word of `language` called `name` ("omega(L), omega(L, M)"), or "".
std::string word_signatures(Language language, const std::string& name);
/// The code of a polygon word: its place among the polygon words of vocabulary(). It is part of
/// the GiNaC call that stands for the word (claim_expression.h), hence of the canonical keys that
/// order a claim's terms: it must not change when a mechanism word is added.
int word_code(const Word& w);
/// The polygon word of a code, the inverse of word_code.
const Word& word_of_code(int code);
/// "a number", "a vector", "a link name", ...
std::string describe(ClaimKind kind);

}  // namespace linkproof
