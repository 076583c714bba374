// One comparison of a claim (a statement, an instance or a coefficient of a term) as a value:
// its verdict, the exact or floating-point values of its two sides and their residual, and for
// floating point the derived tolerance and why a comparison was left undecided. Text for these
// values is made by the report layer; the verdict rules are in docs/verdicts.md.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "linkproof/core/result_number.h"
#include "linkproof/core/verdict.h"

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

}  // namespace linkproof
