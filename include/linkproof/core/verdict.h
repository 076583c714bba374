// The closed set of verification outcomes, with the evidence that produced them.
#pragma once

#include <string>
#include <string_view>

namespace linkproof {

/// Outcome of comparing two sides of a claim.
///  Holds        the sides agree: exactly (exact arithmetic) or within a derived error bound.
///  Fails        the sides differ: exactly, or by more than the derived bound.
///  Undefined    a quantity needed by the claim does not exist here (named in the evidence).
///  Inconclusive floating point cannot decide: the error bound is too wide to confirm.
///  Error        the evaluation itself failed (a bug or resource problem; message attached).
enum class Verdict { Holds, Fails, Undefined, Inconclusive, Error };

/// "holds", "fails", "undefined", "inconclusive", "error" (the JSON contract's spelling).
std::string_view to_string(Verdict v);

/// Combines the verdicts of the parts of one claim: a definite Fails dominates, then Error,
/// Undefined, Inconclusive; Holds only if every part holds.
Verdict combine(Verdict a, Verdict b);

/// What a claim is expected to do: a true statement holds; an erratum reading (the paper's
/// printed or a tempting wrong reading) is expected to fail on generic configurations.
enum class Expectation { Holds, Fails };
std::string_view to_string(Expectation e);

}  // namespace linkproof
