// Certified enclosures of real numbers (ball arithmetic over exact rationals), for placing the
// joints of a mechanism scene from its dimensions (joint_placement.h). Private to src/io.
//
// An Enclosure is a rational midpoint m and a rational radius r >= 0 and stands for one real x
// with |x - m| <= r. Every operation computes its result's midpoint exactly in rationals and a
// radius that covers every real the operands may stand for; then, unless the result is exact
// (r = 0), the midpoint is rounded to `bits` significant bits and the rounding is added to the
// radius (so midpoints stay short). Exact operands give exact results, never rounded.
//
// The transcendental values come from series summed in fixed point (integers scaled by 2^F)
// with every truncation counted:
//   pi       Machin: pi = 16 atan(1/5) - 4 atan(1/239), atan(1/m) = sum (-1)^n / ((2n+1) m^(2n+1));
//   cos, sin argument reduced by the nearest multiple q of pi/2 (y = x - q pi/2, |y| < 1), then
//            the Taylor series of cos y and sin y.
// Each fixed-point step is a floor division (error < 1 unit of 2^-F) and the series alternate
// with decreasing terms (|y| < 1; 1/m^2 < 1), so the error of the computed sum is at most the
// count given in enclosure.cpp; the argument's own radius is added once more (|cos' |, |sin' | <= 1).
// sqrt takes rigorous lower and upper bounds from integer square roots. Nothing here trusts a
// floating-point library.
#pragma once

#include <optional>

#include "linkproof/core/exact.h"

namespace linkproof::placement {

struct Enclosure {
  Rational mid = 0;  ///< the midpoint m
  Rational rad = 0;  ///< the radius r >= 0; 0: m is the value exactly
  int bits = 0;      ///< working precision of a non-exact value (significant bits of m)

  bool is_exact() const;
  static Enclosure exact(const Rational& q) { return {q, 0, 0}; }
};

Enclosure operator+(const Enclosure& a, const Enclosure& b);
Enclosure operator-(const Enclosure& a, const Enclosure& b);
Enclosure operator-(const Enclosure& a);
Enclosure operator*(const Enclosure& a, const Enclosure& b);

/// a / b. Precondition: 0 is not in b (|b.mid| > b.rad; LINKPROOF_ASSERT).
Enclosure divide(const Enclosure& a, const Enclosure& b);

/// sqrt(a), exact when a is the exact square of a rational. Precondition: a.mid - a.rad >= 0.
/// A non-exact result carries max(bits, a.bits) bits.
Enclosure sqrt_of(const Enclosure& a, int bits);

/// +1 or -1 when every value of the enclosure has that sign, 0 for an exact zero, nullopt when
/// the enclosure contains 0 but is not exactly 0 (undecided at this precision).
std::optional<int> decided_sign(const Enclosure& a);

/// pi to `bits` significant bits (a radius of a few units of 2^-bits).
Enclosure pi_enclosure(int bits);

struct CosSin {
  Enclosure cos, sin;
};
/// cos x and sin x; exact (1, 0) for an exact 0. Precondition: |x| <= 2^30 (the caller limits
/// angles far below that).
CosSin cos_sin_of(const Enclosure& x, int bits);

/// The rational nearest m on the grid `grid` (a multiple of it), for writing an enclosure as a
/// rational: |result - x| <= |result - m| + r for every x the enclosure stands for.
Rational nearest_on_grid(const Rational& m, const Rational& grid);

/// e with 2^(e-1) <= |q| < 2^(e+1) roughly: integer_length(|p|) - integer_length(q) of q = p/q'.
/// For choosing precisions and grids, never for bounds. 0 for q = 0.
long binary_exponent(const Rational& q);

}  // namespace linkproof::placement
