// Checking a catalogue of claims on one polygon: the library's main entry point.
//
//   GroundTruthEngine engine;
//   PolygonCheck r = check_polygon(engine, dijksman1966::catalogue(), "pentagon", polygon, rates,
//                                  Arithmetic::Exact);
//   r.claims[k].verdict, r.omega[j], ...
//
// Results are values (core/result_number.h: exact rationals, or a float midpoint in its own
// precision with its rigorous radius in the evidence); report/ makes their text.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "linkproof/check/ask.h"
#include "linkproof/claims/claim.h"
#include "linkproof/core/error.h"
#include "linkproof/check/arithmetic.h"
#include "linkproof/check/judge.h"

namespace linkproof {

/// What a check keeps of each comparison. Verdicts never depend on it.
enum class Evidence {
  All,       ///< every comparison with its evidence as text (lhs, rhs, residual, tolerance): reports
  Headline,  ///< each claim's verdict and its headline comparison only; instances and terms stay
             ///< empty (sweeps: the text of the other comparisons is never printed)
};

struct ClaimOutcome {
  ClaimInfo info;
  Verdict verdict = Verdict::Error;
  /// The comparison shown in summaries: the first whose verdict is the claim's verdict.
  ComparisonOutcome headline;
  std::vector<ComparisonOutcome> instances;  ///< empty with Evidence::Headline
  std::vector<ComparisonOutcome> terms;      ///< empty with Evidence::Headline
  std::string error;  ///< set when the evaluation itself threw (verdict Error)

  /// True if this outcome is what the claim is expected to do, or says nothing against it
  /// (undefined/inconclusive; with `strict` these are not as expected for a true claim). An
  /// erratum reading that happens to hold here is not a failure. Error never is as expected.
  bool is_as_expected(bool strict = false) const;
  /// Verdict Undefined, naming the quantity that does not exist and why.
  void mark_undefined(const UndefinedQuantity& u) {
    verdict = Verdict::Undefined;
    headline.verdict = Verdict::Undefined;
    headline.undefined_quantity = u.quantity();
    headline.reason = u.reason();
  }
  /// A true claim that fails: the verifier's "no".
  bool is_unexpected_failure() const { return info.expected == Expectation::Holds && verdict == Verdict::Fails; }
};

struct PolygonCheck {
  std::string scene;
  Arithmetic arithmetic = Arithmetic::Exact;
  int n = 0;
  /// Dead centre (D = 0): the ground truth does not exist; every claim is then undefined.
  bool dead_centre = false;
  std::string dead_centre_reason;
  /// omega_{j,n}, omega-dot_{j,n} for j = 1..n (0-based); nullopt where undefined, or not
  /// asked when `ask` restricts (reports show only the asked rates then).
  std::vector<std::optional<ResultNumber>> omega, omega_dot;
  /// The scene's `ask` (check/ask.h) when it restricts what is computed.
  std::optional<SceneAsk> ask;
  /// What the check computed (claims/polygon_context.h computes each on first use): reports
  /// leave out the sections of what was not needed, and tests see what an ask saves.
  struct Computed {
    bool truth = false, closed_forms = false, construction = false, four_bar_truth = false;
  } computed;
  /// D = r_{n-2} x r_{n-1} in the arithmetic.
  ResultNumber determinant;
  std::vector<ClaimOutcome> claims;
  std::vector<std::string> not_applicable;  ///< ids of claims that do not apply to this n
  /// --strict: undefined or inconclusive on a true claim is not as expected (exit 1).
  bool strict = false;
};

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

/// 0 every claim as expected; 1 a claim not as expected (is_as_expected(check.strict)); 3 a
/// claim's evaluation errored.
int exit_status(const PolygonCheck& check);
/// The CLI's exit code of a list of outcomes: 3 if any verdict is Error, else 1 if one is not as
/// expected (a true claim fails; with `strict` also undefined/inconclusive), else 0. Shared by
/// polygon and mechanism checks.
int exit_status(const std::vector<ClaimOutcome>& outcomes, bool strict = false);

}  // namespace linkproof
