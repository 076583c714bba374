// The comparator: turns the two sides of a comparison into a verdict with its evidence.
//
// Exact arithmetic: the residual lhs - rhs is zero (holds) or not (fails); nothing else.
// Floating point (Tracked<F>, F = double, long double or MpFloat<D>; u = 2^-p of F): each side
// carries a running error bound (core/tracked.h), so
//   tolerance = e_lhs + e_rhs  (+ the rounding of the subtraction itself),
// a bound on |computed residual - exact residual| derived from the evaluation's own condition.
//   |residual| > tolerance                    -> fails (the exact sides cannot be equal)
//   tolerance > sqrt(u) * max(|lhs|, |rhs|)   -> inconclusive (the bound is too wide to confirm
//                                                agreement: half the digits or more are lost)
//   non-finite value or unbounded error        -> inconclusive (for MpFloat, so is a CLN
//                                                underflow/overflow, caught by run_claim)
//   otherwise                                  -> holds
// An undefined side gives `undefined`, naming the quantity.
#pragma once

#include <string>
#include <vector>

#include "linkproof/claims/claim.h"

namespace linkproof {

/// The evidence of one comparison, in the arithmetic's own text format.
struct ComparisonOutcome {
  std::string label;
  Verdict verdict = Verdict::Error;
  std::string lhs, rhs;           ///< empty when undefined
  std::string residual;           ///< lhs - rhs
  std::string tolerance;          ///< floating point only: the derived bound
  double relative_error_bound = 0;  ///< floating point only: tolerance / max(|lhs|, |rhs|)
  /// floating point only: how the tolerance was derived (the two bounds, the conditions of
  /// both sides, u), e.g. "tolerance 3.1e-15 = bound(lhs) 1.2e-15 + bound(rhs) 1.9e-15 + ...".
  std::string tolerance_derivation;
  /// for `inconclusive` in floating point: which side's bound is the wider ("lhs", "rhs",
  /// "both"), the quantity whose bound reached its magnitude (check/inconclusive_cause.h, added
  /// by the claim runner) and what decides instead.
  std::string trust_route;
  std::string inconclusive_side;      ///< "lhs", "rhs" or "both"; empty unless inconclusive in floating point
  std::string inconclusive_quantity;  ///< the quantity of trust_route; empty if none reached its magnitude
  std::string undefined_quantity; ///< for `undefined`: which quantity
  std::string reason;             ///< for `undefined`/`inconclusive`/`error`: why
};

/// The rule by which verdicts are drawn in arithmetic T, for reports.
template <class T>
std::string tolerance_rule();

template <class T>
ComparisonOutcome judge(const Comparison<T>& c);

/// judge(c).verdict, without making any text (for comparisons whose evidence nobody prints).
template <class T>
Verdict judge_verdict(const Comparison<T>& c);

}  // namespace linkproof
