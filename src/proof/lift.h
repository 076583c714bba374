// The lift lemma of a proof for every n, checked by the program for one claim.
//
// Lemma (what a proof for every n needs): at every n of the claim's range, the coefficient of a
// monomial in the input rates (omega-dot_j, omega_j^2, omega_j omega_l, or the rate-free part)
// in each side of the claim is one function F(r_j[, r_l], r_{n-2}, r_{n-1}, K_n) of the sides
// that monomial names and of the last two sides and the ground joint, the same function at
// every n. Then the per-n proof at n = 5, where r_1, r_2, r_3, r_4, K_5 are independent generic
// vectors, shows F = 0 for every n.
//
// What is checked, and how:
//   1. uniformity in n (syntactic, ClaimEvaluator::locality_violations): the claim's indices are
//      j, l, n, n-1, n-2; joints and accelerations are not indexed by j; every term of a sum
//      carries rates of the sum's indices; degree <= 2 in the rates. The evaluator then
//      computes each coefficient by the same operations at every n;
//   2. what the evaluation actually reads (semantic): at an n where other sides exist (n >= 6),
//      every coefficient of both sides, as built from the claim's reading of the construction
//      and the engine's truth, is tested for the symbols of every other side: a coefficient
//      that does not contain them depends on none of them; one that does is differentiated by
//      each and the derivative zero-tested (GiNaC normal()). A reading that moves r_j's start
//      to K_j (which depends on every side after j) is found here, not from the index syntax.
#pragma once

#include <string>
#include <vector>

#include "check/check_polygon.h"
#include "claims/data_claim.h"

namespace linkproof {

struct LiftCheck {
  int n = 0;                              ///< where the semantic check ran
  int coefficients = 0;                   ///< coefficients tested
  std::vector<std::string> violations;    ///< empty iff the lemma holds for this claim
  double seconds = 0;
};

/// Checks both parts of the lemma at n sides (n >= 6; n in the claim's range).
LiftCheck check_lift_lemma(GroundTruthEngine& engine, const DataClaim& claim, int n);

}  // namespace linkproof
