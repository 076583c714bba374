// Why a floating-point comparison was inconclusive: which quantity's error bound reached its
// magnitude, so that the trust route (report/comparison_text.h) names it instead of blaming the construction every time.
//
// A comparison is inconclusive when a side's bound is unbounded (a divisor's bound reached its
// magnitude) or too wide (check/judge.h). The judge names the side (the one whose bound is the
// wider relative to its magnitude). This file names the quantity: the context records what the
// claim read while it was evaluated (PolygonContext::reads, claims/polygon_context.h: the claims
// of a check share one context, and a quantity another claim computed is not this claim's
// cause), and the quantities read are searched in dependency order:
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

/// Searches what one claim read (`reads`, recorded by the context while the claim was evaluated
/// on it: see the file comment). T is one of the Tracked arithmetics of ClaimScalarTypes.
template <class T>
InconclusiveCause find_inconclusive_cause(const PolygonContext<T>& context, const typename PolygonContext<T>::Reads& reads);

}  // namespace linkproof
