// The comparator: turns the two sides of a comparison into a verdict with its evidence, as
// values (no text: report/comparison_text.h makes the sentences).
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

#include "claims/claim.h"
#include "linkproof/check/comparison.h"

namespace linkproof {

template <class T>
ComparisonOutcome judge(const Comparison<T>& c);

/// judge(c).verdict, without keeping any evidence (for comparisons nobody prints).
template <class T>
Verdict judge_verdict(const Comparison<T>& c);

}  // namespace linkproof
