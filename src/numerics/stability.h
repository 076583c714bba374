// The stability study of one configuration: every route (numerics/routes.h) in every arithmetic of
// the ladder (numerics/ladder.h), its error against the exact value in relative error, correct
// bits and ulps (numerics/error_measure.h), its run time per evaluation, and a condition estimate
// per route that predicts (and in double bounds) the error.
//
// Condition estimate: the route is evaluated once more in Tracked<double> and in
// Tracked<long double> (core/tracked.h), whose radius bounds |computed - exact| rigorously for
// the same operations in plain double / long double (the midpoints are those operations, bit
// for bit), inputs rounded from the exact configuration included. condition = bound / (u |v|)
// is the route's amplification of rounding errors; for a p-bit arithmetic the predicted
// relative error is condition * 2^-p (an estimate, first order).
#pragma once

#include <optional>
#include <set>
#include <string>
#include <vector>

#include "numerics/error_measure.h"
#include "numerics/routes.h"

namespace linkproof {

struct RouteMeasurement {
  Route route = Route::ClosedForms;
  std::string arithmetic;  ///< ladder name: "double", ..., "mp1000", "exact"
  int precision_bits = 0;  ///< 0 for exact
  /// False where the route does not exist in this arithmetic on this configuration (the
  /// construction at a pole at infinity; every route at the dead centre).
  bool defined = true;
  std::string undefined_quantity, reason;
  ErrorMeasure n1;  ///< error of omega-dot_{n-1,n}
  ErrorMeasure n2;  ///< error of omega-dot_{n-2,n} (companion)
  double seconds_per_eval = 0;  ///< 0 when not timed
};

struct ConditionEstimate {
  Route route = Route::ClosedForms;
  bool defined = true;
  std::string undefined_quantity;
  /// Rigorous bounds on the relative error of the plain double / long double result of this
  /// route (infinite if a divisor is not distinguishable from zero), omega-dot_{n-1,n}, n-2.
  double bound_double_n1 = 0, bound_double_n2 = 0;
  double bound_long_double_n1 = 0, bound_long_double_n2 = 0;
  /// bound_double / u_double: the route's condition on this configuration (max of both sides);
  /// a p-bit evaluation's relative error is predicted as condition * 2^-p.
  double condition = 0;
};

struct StudyOptions {
  /// Arithmetics to run (ladder names); empty = all.
  std::set<std::string> arithmetics;
  /// Routes to run; empty = all.
  std::set<Route> routes;
  /// Wall time spent timing each route x arithmetic; 0 = do not time (one evaluation).
  double time_budget_seconds = 0;
};

struct CaseStudy {
  int n = 0;
  /// The exact omega-dot_{n-1,n}, omega-dot_{n-2,n}; absent at the dead centre.
  std::optional<Rational> exact_n1, exact_n2;
  std::string truth_undefined_reason;
  std::vector<RouteMeasurement> measurements;
  std::vector<ConditionEstimate> conditions;
};

/// Studies one exact configuration. Never throws for a valid polygon.
CaseStudy study_case(GroundTruthEngine& engine, const Polygon<Rational>& polygon, const InputRates<Rational>& rates,
                     const StudyOptions& options);

/// Seconds per call of f(), timed in batches until `budget` seconds are spent (at least one
/// call). Used by the study and the adaptive-mode statistics.
template <class F>
double seconds_per_call(F&& f, double budget);

}  // namespace linkproof

#include <chrono>

namespace linkproof {

namespace stability_detail {
/// Keeps the compiler from discarding a computed value (as Google Benchmark's DoNotOptimize).
template <class T>
inline void keep(const T& value) {
  asm volatile("" : : "r"(&value) : "memory");
}
}  // namespace stability_detail

template <class F>
double seconds_per_call(F&& f, double budget) {
  using Clock = std::chrono::steady_clock;
  long batch = 1;
  for (;;) {
    const auto start = Clock::now();
    for (long k = 0; k < batch; ++k) {
      auto r = f();
      stability_detail::keep(r);
    }
    const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    if (elapsed >= budget / 4 || batch >= (1L << 30)) return elapsed / static_cast<double>(batch);
    batch *= elapsed > 0 ? std::max(2L, std::min(64L, static_cast<long>(budget / 4 / elapsed) + 1)) : 64;
  }
}

}  // namespace linkproof
