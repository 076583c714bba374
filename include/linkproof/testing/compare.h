// Comparing a user's angular velocities or accelerations with the truth (testing/truth.h): the
// shared core of the GTest matchers AngularVelocitiesMatch / AngularAccelerationsMatch
// (testing/matchers.h) and of the RapidCheck helpers rc_assert_omega_matches /
// rc_assert_alpha_matches (testing/oracle.h). No GTest or RapidCheck needed here.
//
// Each link l (the ground too: its omega and alpha are 0) passes when, with x_l the exact omega_l
// or alpha_l,
//   | user_l - x_l |  <=  absolute + relative |x_l| + double_bounds (bound_l + ulp(x_l)/2)
// decided exactly (the user's double is converted to its exact rational value; the right-hand
// side is computed in double from the user's tolerance, which is the user's choice of number):
//   absolute, relative   plain tolerances;
//   double_bounds        a multiple of what double arithmetic can be held to on this mechanism:
//                        bound_l is the rigorous error bound of linkproof's own Tracked<double>
//                        solve (a condition estimate times the unit roundoff), ulp/2 the rounding
//                        of the exact value to a double. double_bounds = 1 asks for exactly the
//                        accuracy linkproof's double route reaches; a stable library should meet
//                        a small multiple of it.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "linkproof/testing/truth.h"

namespace linkproof::testing {

struct Tolerance {
  double absolute = 0;
  double relative = 0;
  double double_bounds = 0;
  /// Exact equality (every term 0). Say which tolerance you mean with the factories below: a
  /// bare number does not convert (is 1e-9 absolute, relative, or a multiple of a bound?).
  Tolerance() = default;
  static Tolerance absolute_to(double a) { Tolerance t; t.absolute = a; return t; }
  static Tolerance relative_to(double r) { Tolerance t; t.relative = r; return t; }
  static Tolerance double_bound(double k) { Tolerance t; t.double_bounds = k; return t; }
  std::string describe() const;
};

struct LinkComparison {
  std::string link;
  double user = 0;
  Rational exact;
  BoundedDouble linkproof_double;  ///< the truth's double and its bound
  double difference = 0;           ///< user - exact, rounded
  double tolerance = 0;
  bool ok = false;
};

/// Which rate of every link is compared.
enum class Rate { Omega, Alpha };
/// "omega" or "alpha".
std::string_view to_string(Rate r);

struct RateComparison {
  Rate rate = Rate::Alpha;
  bool ok = false;
  std::string problem;  ///< e.g. a wrong number of values; empty otherwise
  std::vector<LinkComparison> links;
  /// A table: link, user's value, exact value (25 digits), difference, tolerance, verdict.
  std::string report() const;
};
using AlphaComparison = RateComparison;

/// The user's values of `rate` (one per link, in the scene's link order, the ground included)
/// against the truth.
RateComparison compare_rates(const MechanismTruth& truth, Rate rate, const std::vector<double>& user,
                             const Tolerance& tolerance);
inline RateComparison compare_alphas(const MechanismTruth& truth, const std::vector<double>& user,
                                     const Tolerance& tolerance) {
  return compare_rates(truth, Rate::Alpha, user, tolerance);
}
inline RateComparison compare_omegas(const MechanismTruth& truth, const std::vector<double>& user,
                                     const Tolerance& tolerance) {
  return compare_rates(truth, Rate::Omega, user, tolerance);
}

}  // namespace linkproof::testing
