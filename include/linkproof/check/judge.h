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

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "linkproof/claims/claim.h"
#include "linkproof/core/result_number.h"

namespace linkproof {

/// A side of a comparison (None: not applicable).
enum class Side { None, Lhs, Rhs, Both };
/// "lhs", "rhs", "both"; "" for None (the JSON values of `inconclusive_side`).
std::string_view to_string(Side s);

/// Why a floating-point comparison was not decided (None: it was).
enum class Undecided {
  None,
  NonFinite,  ///< a side overflowed or is not a number in this precision
  Unbounded,  ///< the error bound is unbounded (a divisor not distinguishable from zero)
  TooWide,    ///< agreement within the bound, but the bound exceeds sqrt(u) of the magnitude
};

/// The quantity whose error bound reached its magnitude, found by re-evaluating an inconclusive
/// claim (check/inconclusive_cause.h).
struct InconclusiveCause {
  enum class Kind { DeadCentre, Construction, OwnArithmetic };
  Kind kind = Kind::OwnArithmetic;
  /// The quantity whose bound is beyond sqrt(u) of its magnitude ("D = r_{n-2} x r_{n-1}",
  /// "cot beta_2 of four-bar 2 (construction)"); for OwnArithmetic, the widest one read, or empty.
  std::string quantity;
  double relative_bound = 0;  ///< bound / |value| of that quantity (display; +inf if unbounded)
};

/// The evidence a floating-point comparison has beyond its values: how the tolerance was derived.
struct FloatEvidence {
  ResultRadius tolerance;           ///< bound on |computed residual - exact residual|
  ResultRadius bound_lhs, bound_rhs;  ///< each side's running error bound
  double relative_error_bound = 0;  ///< tolerance / max(|lhs|, |rhs|), rounded upward
  double condition_lhs = 0, condition_rhs = 0;  ///< bound / (u |value|) of each side
  int precision_bits = 0;           ///< p of u = 2^-p
  Undecided undecided = Undecided::None;
  /// When undecided: the side whose bound is the wider relative to its own magnitude, and the
  /// two relative bounds (the wider first).
  Side wider_side = Side::None;
  double relative_wide = 0, relative_narrow = 0;
};

/// The evidence of one comparison.
struct ComparisonOutcome {
  std::string label;
  Verdict verdict = Verdict::Error;
  std::optional<ResultNumber> lhs, rhs;  ///< nullopt when undefined or not evaluated
  std::optional<ResultNumber> residual;  ///< lhs - rhs
  std::optional<FloatEvidence> floating;  ///< floating point only
  /// For an undecided floating-point comparison: the quantity that made it so, when the claim
  /// runner looked (polygon claims).
  std::optional<InconclusiveCause> cause;
  std::string undefined_quantity;  ///< for `undefined`: which quantity
  /// Why, when the comparison could not be made: an undefined quantity's reason, an error's
  /// message, an exception of the arithmetic (e.g. a CLN exponent overflow).
  std::string reason;
};

template <class T>
ComparisonOutcome judge(const Comparison<T>& c);

/// judge(c).verdict, without keeping any evidence (for comparisons nobody prints).
template <class T>
Verdict judge_verdict(const Comparison<T>& c);

}  // namespace linkproof
