// Why a floating-point comparison was inconclusive: which quantity's error bound reached its
// magnitude, so that the trust route (report/comparison_text.h) names it instead of blaming the construction every time.
//
// A comparison is inconclusive when a side's bound is unbounded (a divisor's bound reached its
// magnitude) or too wide (check/judge.h). The judge names the side (the one whose bound is the
// wider relative to its magnitude). This file names the quantity: the claim is evaluated again
// on a fresh context (claims/polygon_context.h), so that what is computed afterwards is exactly
// what this claim reads, and the quantities read are searched in dependency order:
//   1. D = r_{n-2} x r_{n-1}, which the engine, the closed forms, the four-bar truths and the
//      construction all divide by (near the dead centre every route loses, docs/conventions.md §A6);
//   2. the construction of each four-bar j it reads: Q_j, P'_j, i_{n-1,j}, i_{n-2,j},
//      cot beta_j, cot gamma_j, lambda_j, mu_j (near a pole of the construction only the
//      construction loses: the closed forms and the engine keep full accuracy).
// The first whose bound is beyond sqrt(u) of its magnitude (the judge's limit), or reached it
// (unbounded), is the cause: everything computed from it inherits at least that loss. If none
// is, the digits were lost in the claim's own arithmetic (cancellation between its terms), and
// the widest quantity read is reported for information.
#pragma once

#include <string>

#include "check/judge.h"
#include "claims/claim.h"

namespace linkproof {

/// Evaluates `claim` again on context.fresh() and searches what it read (see the file comment).
/// T is one of the Tracked arithmetics of ClaimScalarTypes.
template <class T>
InconclusiveCause find_inconclusive_cause(const Claim& claim, const PolygonContext<T>& context);

}  // namespace linkproof
