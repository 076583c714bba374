// Proofs of claims in symbolic coordinates, and disproofs by counterexample.
//
// Per-n proof: the polygon's joints are symbols X_k, Y_k, the rates stay symbolic (the claim's
// sides are rate polynomials, claim_evaluator.h); the coefficient of every monomial of
// lhs - rhs is a rational function of the coordinates, and the claim is proved for that n iff
// every one is identically zero (GiNaC normal(): numerator and denominator cancelled).
//
// Proof for every n (docs/conventions.md §A4, last item): the lift lemma, checked by the program for the claim
// at hand (lift.h): every coefficient of lhs and of the truth reads only the sides of its
// monomial and r_{n-2}, r_{n-1}, K_n, at an n where other sides exist; then the per-n proof at
// the base n = max(min_n, 5), where those sides are independent generic vectors, covers every
// n >= 5 of the range, and n = 4 (if in the range) gets its own per-n proof. A claim that is not
// local (or of degree > 2 in the rates) gets per-n proofs only: `proved`/`proved_generically`
// if they cover its whole (finite) range, `proved_for` with the exact list of n otherwise.
//
// Generic vs everywhere: normal() cancels factors that may vanish. Every divisor the compared
// expressions contain (the construction's, the engine's, and the claim expression's own) is
// factored and each factor named where it matches a degeneracy of docs/conventions.md §A6 (dead centre, Q_j or
// P'_j at infinity, beta_j undefined, ...): the verdict is then "holds generically, except
// where" those factors vanish. A polynomial identity has no exceptions.
//
// Verdicts (docs/verdicts.md): proved, proved_generically (every n of the range covered),
// proved_for (the n listed only), disproved (an exact counterexample), holds_on_samples
// (check-claim only: comparisons that really ran, counted), error (anything else, with why).
// A positive verdict is issued only after the counterexample search over n = 4..8 found none.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "proof/counterexample.h"

namespace linkproof {

/// HoldsWithProbability: a randomized identity test (mechanism claims over a topology,
/// proof/mechanism_proof.h) with a stated bound on the chance that a false claim passes it.
enum class ProofVerdict { Proved, ProvedGenerically, ProvedFor, Disproved, HoldsOnSamples, HoldsWithProbability, Error };
std::string to_string(ProofVerdict v);

struct ExceptionalSet {
  std::string polynomial;  ///< a factor of a denominator, in the proof's coordinates
  std::string meaning;     ///< the degeneracy it describes, or "unnamed"
};

struct PerNProof {
  int n = 0;
  bool proved = false;        ///< every coefficient of lhs - rhs is identically 0
  int monomials = 0;          ///< coefficients compared
  size_t tree_size = 0;       ///< nodes of the compared expressions as trees
  size_t dag_size = 0;        ///< nodes with shared subexpressions counted once
  double seconds = 0;
  std::string first_nonzero;  ///< label of a coefficient that is not zero, if any
};

struct ProofResult {
  std::string id;
  Expectation expected = Expectation::Holds;
  ProofVerdict verdict = ProofVerdict::Error;
  std::string scope;                       ///< what was covered, computed after all work: "every n >= 4", "n = 5, 6, 7"
  std::vector<ExceptionalSet> except;      ///< where the proof divides by something that may vanish
  std::vector<std::string> argument;       ///< the steps of the proof, for the report
  std::vector<std::string> not_local;      ///< why no proof for every n, if none
  std::vector<int> proved_n;               ///< the n covered by a per-n proof (proved_for lists them)
  std::vector<PerNProof> per_n;            ///< per-n proofs made
  std::optional<Counterexample> counterexample;
  int samples = 0;                         ///< instances evaluated (holds_on_samples)
  int samples_compared = 0;                ///< ... of which produced a comparison (the K of holds_on_samples)
  int samples_undefined = 0;               ///< ... of which were undefined (a degenerate configuration)
  double seconds = 0;
  std::string error;
  /// False when the claim has no symbolic form (e.g. |x| of an expression): no proof could be
  /// attempted, and only exact instances can decide (check-claim samples them).
  bool symbolic = true;
  /// A true claim: proved or proved_generically, and also proved_for or holds_on_samples
  /// (positive verdicts that say what they rest on). An erratum: disproved. Error is never as
  /// expected. (The program's --strict, under which only proofs for the whole range count, is
  /// the command line's policy.)
  bool is_as_expected() const;
};

/// The largest n of a proof at one n (`only_n`). Its cost grows about as n^3: eq. (22) takes
/// about 5 s at n = 10, 20 s at n = 20 and 70 s at n = 28 on one busy core, so n = 200 would take
/// hours. Larger n are covered by the proof for every n (the lift lemma, lift.h).
constexpr int kMaxPerNProofSides = 20;

struct ProveOptions {
  std::optional<int> only_n;           ///< prove for this n only (no proof for every n)
  int n_max = 0;                       ///< per-n ladder: up to this n (0: until the budget ends)
  double ladder_seconds = 1.0;         ///< time budget of the per-n ladder, per claim
  /// The ladder's job. Where the proofs so far leave part of a claim's range uncovered (the lift
  /// lemma does not apply), it adds per-n proofs n = 4, 5, ... while the budget lasts: coverage.
  /// Where they cover the whole range, more per-n proofs only re-check it, so they run only when
  /// this is set (the command line sets it when --ladder-seconds or --n-max is given): by
  /// default such a claim's result does not depend on how fast the machine is.
  bool recheck_proved = false;
  CounterexampleSearch search;         ///< for disproofs, and before every positive verdict
};

/// Proves or disproves one claim. Never throws for a well-formed claim: problems become Error.
ProofResult prove_claim(GroundTruthEngine& engine, const DataClaim& claim, const ProveOptions& options);

/// The per-n proof alone (n sides, symbolic coordinates and rates).
PerNProof prove_for_n(GroundTruthEngine& engine, const DataClaim& claim, int n,
                      std::vector<std::string>* not_local = nullptr, std::vector<ExceptionalSet>* except = nullptr);

}  // namespace linkproof
