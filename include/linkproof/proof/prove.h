// Proofs of claims in symbolic coordinates, and disproofs by counterexample.
//
// Per-n proof: the polygon's joints are symbols X_k, Y_k, the rates stay symbolic (the claim's
// sides are rate polynomials, claim_evaluator.h); the coefficient of every monomial of
// lhs - rhs is a rational function of the coordinates, and the claim is proved for that n iff
// every one is identically zero (GiNaC normal(): numerator and denominator cancelled).
//
// Proof for every n (SPEC A4, last item): the per-n proof at n = 5, where r_1, r_2, r_3, r_4
// and K_5 are independent generic vectors, plus the lifting argument printed in
// ProofResult::argument: the exact omega-dot of sides n-1, n-2 comes from the differentiated
// closure sum_k (omega-dot_k J r_k - omega_k^2 r_k) = 0 solved by Cramer's rule, a sum of
// terms each involving one side, so the coefficient of a monomial in the input rates is one
// function of the sides it names and r_{n-2}, r_{n-1}, the same for every n. The claim's sides
// must be local in the same sense (ClaimEvaluator::locality_violations empty) and of degree
// <= 2 in the rates; otherwise only per-n proofs are given.
//
// Generic vs everywhere: normal() cancels factors that may vanish. The denominators of both
// sides are factored and each factor named where it matches a degeneracy of SPEC A6 (dead
// centre, Q_j or P'_j at infinity, beta_j undefined, ...): the verdict is then "holds
// generically, except where" those factors vanish.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "linkproof/proof/counterexample.h"

namespace linkproof {

enum class ProofVerdict { Proved, ProvedGenerically, Disproved, HoldsOnSamples, Error };
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
  std::string scope;                       ///< "every n >= 4", "n = 5", "n = 4..9", ...
  std::vector<ExceptionalSet> except;      ///< where the proof divides by something that may vanish
  std::vector<std::string> argument;       ///< the steps of the proof, for the report
  std::vector<std::string> not_local;      ///< why no proof for every n, if none
  std::vector<PerNProof> per_n;            ///< per-n proofs made
  std::optional<Counterexample> counterexample;
  int samples = 0;                         ///< exact random instances checked (holds_on_samples)
  double seconds = 0;
  std::string error;
  /// proved / proved_generically for a true claim, disproved for an erratum.
  bool is_as_expected() const;
};

struct ProveOptions {
  std::optional<int> only_n;           ///< prove for this n only (no proof for every n)
  int n_max = 0;                       ///< per-n ladder: up to this n (0: until the budget ends)
  double ladder_seconds = 1.0;         ///< time budget of the per-n ladder, per claim
  CounterexampleSearch search;         ///< for disproofs
  int samples_per_n = 20;              ///< random exact instances when no proof is found
};

/// Proves or disproves one claim. Never throws for a well-formed claim: problems become Error.
ProofResult prove_claim(GroundTruthEngine& engine, const DataClaim& claim, const ProveOptions& options);

/// The per-n proof alone (n sides, symbolic coordinates and rates).
PerNProof prove_for_n(GroundTruthEngine& engine, const DataClaim& claim, int n,
                      std::vector<std::string>* not_local = nullptr, std::vector<ExceptionalSet>* except = nullptr);

}  // namespace linkproof
