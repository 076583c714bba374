// Extreme and stiff families of configurations (docs/conventions.md §A6), each a continuous one-parameter
// family of exact polygons, for the stability study (`linkproof bench`).
//
// Degeneracy families: a pentagon (the pentagon of docs/conventions.md §A8, sides r_1..r_4, inputs omega = (2, -1),
// omega-dot = (1, 3)) in which one side is moved so that at epsilon = 0 the named degeneracy
// holds exactly and at epsilon != 0 it does not (a = r_{n-2} = r_3, b = r_{n-1} = r_4, J turns
// by +90 degrees):
//   dead_centre   b = -3/2 a + eps J a         D = r_{n-2} x r_{n-1} = 20 eps: the only true
//                                              singularity (omega ~ 1/D, omega-dot ~ 1/D^3)
//   q_infinity    r_1 = -b + a/2 + eps J a     r_{n-2} x (r_1 + r_{n-1}) = 0: Q_1 at infinity
//   beta_zero     r_1 = a/2 + eps J a          r_1 || r_{n-2}: beta_1 undefined (Q_1 = K'_1)
//   p_infinity    r_1 = b/2 + eps J b          r_1 || r_{n-1}: P'_1 at infinity
//   q_at_k        r_1 = -a + b/2 + eps J b     Q_1 = K_{n-1}: the ray Q_1K_{n-1} is null
//   kprime_at_kn  r_1 = -(a + b) + eps (1, 1)  K'_1 = K_n: the ground line is undefined
// Everywhere but the dead centre the mechanism is regular: the truth and the closed forms are
// continuous through epsilon = 0 and only the construction breaks (docs/conventions.md §A6).
//
// Stiff families (scale, not degeneracy):
//   length_ratio  r_{n-2} scaled by s, s = 1e-8 .. 1e8 (a very short or very long coupler)
//   omega_scale   omega_1 = 2 s, omega_2 = -1, s = 1e-6 .. 1e6 (velocity ratios over 12 decades)
//   large_n       the first scattered random polygon (seed 1966) with n sides, n = 5 .. 1000
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "linkproof/geometry/polygon.h"

namespace linkproof {

struct ExtremeCase {
  Polygon<Rational> polygon;
  InputRates<Rational> rates;
};

struct ExtremeFamily {
  std::string name;         ///< "dead_centre", "q_infinity", ...
  std::string description;  ///< what the parameter does
  std::string parameter;    ///< "epsilon", "s" or "n"
  /// Degeneracy families: the quantity that is undefined at epsilon = 0 (as the construction
  /// names it, e.g. "Q_1", "beta_1", "P'_1"; the dead centre names D). Empty for stiff families.
  std::string degenerate_quantity;
  /// True only for the dead centre: the mechanism itself is singular at the limit.
  bool singular = false;
  /// The configuration at a parameter value (epsilon or s: any rational; n: an integer >= 4).
  std::function<ExtremeCase(const Rational&)> make;
  /// Parameter values of the quick and of the full study (ordered towards the extreme).
  std::vector<Rational> quick_values, full_values;
};

/// All families, degeneracy families first.
const std::vector<ExtremeFamily>& extreme_families();
/// The family of that name, or nullptr.
const ExtremeFamily* find_extreme_family(const std::string& name);

}  // namespace linkproof
