// Adaptive precision: omega-dot_{n-1,n} and omega-dot_{n-2,n} with a certified error bound, or
// correctly rounded to double, paying for exact arithmetic only where double cannot decide
// (the filtered-predicate idea of Shewchuk's robust predicates and of CGAL's filtered kernels).
//
// The inputs are doubles, taken as exact numbers (every double is a dyadic rational). Stages,
// each accepted if its bound is finite and meets the request, else the next one runs:
//   1. A priori double: omega-dot = P / D^3 by the division-free fraction (numerics/omega_dot_fraction.h).
//      Its O(n) sums run in ShadowedFloat<double>, bounded by gamma_k times the magnitude shadow
//      (core/a_priori_bound.h); the O(1) combination runs in Tracked<double>. About two double
//      evaluations: the filter that makes the common case cheap (Shewchuk's semi-static filter).
//   2. Running double: the direct solve of the differentiated loop closure (numerics/routes.h,
//      Route::DirectSolve) in Tracked<double>, a rigorous running error bound (core/tracked.h),
//      tighter than the a priori one where sums cancel or n is large.
//   3. Running long double: the same with 11 more bits.
//   4. Exact rationals: the exact value, rounded to nearest double; its bound is the exact
//      rounding error. Undefined only at the exact dead centre D = 0 (the only singularity).
// Requests: a relative bound |value - exact| <= tolerance |value| (default 2^-26, i.e. at least
// 26 certified bits), or correct rounding (tolerance = 0): the value is the double nearest to
// the exact result, certified when every real in [v - e, v + e] rounds to the same double.
#pragma once

#include <array>
#include <string>

#include "linkproof/geometry/polygon.h"

namespace linkproof {

/// The arithmetic that delivered a result.
enum class AdaptiveLevel { Double = 0, LongDouble = 1, Exact = 2 };
std::string_view to_string(AdaptiveLevel l);
/// The stage that delivered a result (see the file comment); stages 1 and 2 are level Double.
enum class AdaptiveStage { APrioriDouble, RunningDouble, RunningLongDouble, Exact };
std::string_view to_string(AdaptiveStage s);

struct AdaptiveOptions {
  /// Requested relative bound; 0 requests correct rounding in double. The default is 2^-26
  /// (about sqrt(u) of double): the threshold below which linkproof's floating-point verdicts
  /// trust a figure (check/judge.h), so that a value adaptive mode returns by default is one a
  /// verdict would accept. Ask for more (e.g. 2^-40) or for correct rounding when needed.
  double relative_tolerance = 0x1p-26;
};

struct AdaptiveResult {
  /// False only at the exact dead centre (the truth does not exist).
  bool defined = true;
  std::string undefined_quantity;
  /// omega-dot_{n-1,n} and omega-dot_{n-2,n}, and certified bounds |value - exact| <= bound.
  double omega_dot_n1 = 0, omega_dot_n2 = 0;
  double bound_n1 = 0, bound_n2 = 0;
  /// True if both values are certified to be the nearest doubles to the exact results.
  bool correctly_rounded = false;
  /// The arithmetic and the stage that delivered the result.
  AdaptiveLevel level = AdaptiveLevel::Double;
  AdaptiveStage stage = AdaptiveStage::APrioriDouble;
};

/// See the file comment. Never throws for a valid polygon (n >= 4, no zero sides).
AdaptiveResult compute_omega_dot_adaptive(const Polygon<double>& polygon, const InputRates<double>& rates,
                                          const AdaptiveOptions& options = {});

/// The double nearest to q (ties to even), decided exactly.
double round_to_nearest_double(const Rational& q);

}  // namespace linkproof
