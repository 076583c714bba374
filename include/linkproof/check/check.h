// The result of checking claims on one polygon (`linkproof check` on a polygon scene): each
// claim's outcome, the rates, the determinant of the velocity system.
//
// Results are values (core/result_number.h: exact rationals, or a float midpoint in its own
// precision with its rigorous radius in the evidence); report/ makes their text.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "linkproof/check/ask.h"
#include "linkproof/claims/claim_info.h"
#include "linkproof/core/error.h"
#include "linkproof/check/arithmetic.h"
#include "linkproof/check/comparison.h"

namespace linkproof {

/// What a check keeps of each comparison. Verdicts never depend on it.
enum class Evidence {
  All,       ///< every comparison with its evidence as text (lhs, rhs, residual, tolerance): reports
  Headline,  ///< each claim's verdict and its headline comparison only; instances and terms stay
             ///< empty
  Examples,  ///< each claim's verdict; the headline only where a sweep keeps it as an example
             ///< (the verdict is unexpected, or disproves an erratum reading): sweeps. A value that
             ///< no comparison's verdict needs is then never computed (an exact claim whose sides
             ///< are the same polynomial holds at any rates: its value at the rates is not made)
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
  /// (undefined or inconclusive). An erratum reading that happens to hold here is not a failure.
  /// Error never is as expected. (The `--strict` policy of the linkproof program, which also
  /// counts an undefined or inconclusive true claim against it, is described in docs/check.md.)
  bool is_as_expected() const;
  /// Verdict Undefined, naming the quantity that does not exist and why.
  void mark_undefined(std::string quantity, std::string reason) {
    verdict = Verdict::Undefined;
    headline.verdict = Verdict::Undefined;
    headline.undefined_quantity = std::move(quantity);
    headline.reason = std::move(reason);
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
};

}  // namespace linkproof
