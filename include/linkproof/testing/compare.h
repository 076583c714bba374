// Comparing a user's angular accelerations with the truth (testing/truth.h): the shared core of
// the GTest matcher AngularAccelerationsMatch (testing/matchers.h) and of the RapidCheck helper
// rc_assert_alpha_matches (testing/oracle.h). No GTest or RapidCheck needed here.
//
// Each link l (the ground too: its alpha is 0) passes when
//   | user_l - alpha_l |  <=  absolute + relative |alpha_l| + double_bounds (bound_l + ulp(alpha_l)/2)
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
#include <vector>

#include "linkproof/testing/truth.h"

namespace linkproof::testing {

struct Tolerance {
  double absolute = 0;
  double relative = 0;
  double double_bounds = 0;
  Tolerance() = default;
  /// A plain number is an absolute tolerance.
  Tolerance(double abs) : absolute(abs) {}  // NOLINT(google-explicit-constructor): reads as a number
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

struct AlphaComparison {
  bool ok = false;
  std::string problem;  ///< e.g. a wrong number of values; empty otherwise
  std::vector<LinkComparison> links;
  /// A table: link, user's alpha, exact alpha (25 digits), difference, tolerance, verdict.
  std::string report() const;
};

AlphaComparison compare_alphas(const MechanismTruth& truth, const std::vector<double>& user, const Tolerance& tolerance);

}  // namespace linkproof::testing
