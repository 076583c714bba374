// Checking a catalogue of claims on one polygon: the library's entry point behind `linkproof check`.
//
//   GroundTruthEngine engine;
//   PolygonCheck r = check_polygon(engine, dijksman1966::catalogue(), "pentagon", polygon, rates,
//                                  Arithmetic::Exact);
//   r.claims[k].verdict, r.omega[j], ...
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "check/judge.h"
#include "claims/claim.h"
#include "linkproof/check/check.h"
#include "symbolic/ground_truth.h"

namespace linkproof {

/// Evaluates every applicable claim of `catalogue` on the polygon in arithmetic `a`.
/// Never throws for a valid polygon (see polygon_input_problem): a claim whose evaluation
/// throws gets the verdict Error with the message. Cost O(n^2) operations in the arithmetic
/// (the Theta(n^2) pair terms), plus the text of the evidence kept.
/// With an `ask` that restricts (check/ask.h), only the asked rates are computed: an input
/// side's or the fixed side's rate costs nothing, a solved side's (n-2, n-1) the engine's
/// motion; the claims evaluated are `catalogue` as given (asked_claims chooses them).
PolygonCheck check_polygon(GroundTruthEngine& engine, const std::vector<Claim>& catalogue, const std::string& scene,
                           const Polygon<Rational>& polygon, const InputRates<Rational>& rates, Arithmetic a,
                           Evidence evidence = Evidence::All, const std::optional<SceneAsk>& ask = std::nullopt);

/// Runs one claim in scalar type T on a prepared context.
template <class T>
ClaimOutcome run_claim(const Claim& claim, const PolygonContext<T>& context, Evidence evidence = Evidence::All);

/// True if this outcome makes a sweep's case an example of "unexpected" (a true claim fails, or
/// any evaluation errors).
bool is_unexpected(Expectation expected, Verdict v);
/// True if this outcome disproves an erratum reading (expected to fail, and fails).
bool is_disproof(Expectation expected, Verdict v);

}  // namespace linkproof
