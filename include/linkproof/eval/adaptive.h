// Adaptive precision: omega-dot_{n-1,n} and omega-dot_{n-2,n} with a certified error bound, or
// correctly rounded to double, paying for exact arithmetic only where double cannot decide
// (the filtered-predicate idea of Shewchuk's robust predicates and of CGAL's filtered kernels).
//
// The inputs are doubles, taken as exact numbers (every double is a dyadic rational). Route:
// the direct solve of the differentiated loop closure (eval/routes.h, Route::DirectSolve),
// allocation-free and backward-stable away from the dead centre. Stages:
//   1. Tracked<double>: the double result with a rigorous running error bound (core/tracked.h).
//      Accepted if the bound is finite and meets the request.
//   2. Tracked<long double>: the same with 11 more bits; accepted on the same test.
//   3. Exact rationals: the exact value, rounded to nearest double; its bound is the exact
//      rounding error. Undefined only at the exact dead centre D = 0 (the only singularity).
// Requests: a relative bound |value - exact| <= tolerance |value| (default 2^-40, i.e. at least
// 40 certified bits), or correct rounding (tolerance = 0): the value is the double nearest to
// the exact result, certified when every real in [v - e, v + e] rounds to the same double.
#pragma once

#include <array>
#include <string>

#include "linkproof/geometry/polygon.h"

namespace linkproof {

enum class AdaptiveLevel { Double = 0, LongDouble = 1, Exact = 2 };
std::string_view to_string(AdaptiveLevel l);

struct AdaptiveOptions {
  /// Requested relative bound; 0 requests correct rounding in double.
  double relative_tolerance = 0x1p-40;
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
  /// The stage that delivered the result.
  AdaptiveLevel level = AdaptiveLevel::Double;
};

/// See the file comment. Never throws for a valid polygon (n >= 4, no zero sides).
AdaptiveResult compute_omega_dot_adaptive(const Polygon<double>& polygon, const InputRates<double>& rates,
                                          const AdaptiveOptions& options = {});

/// The double nearest to q (ties to even), decided exactly.
double round_to_nearest_double(const Rational& q);

}  // namespace linkproof
