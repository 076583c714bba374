// The length |u| of a prismatic axis, exactly and as a certified enclosure, for reporting the
// sliding rates along the unit axis u/|u| (docs/mechanisms.md, "Sliders").
//
//   |u|^2 = p/q (reduced)  =>  |u| = sqrt(p q) / q = (s / q) sqrt(m)   with p q = s^2 m,
// where the square factors d^2 of p q with d <= kSquareFactorTrials are taken out and a remaining
// perfect square is taken out whole. m = 1 exactly when |u| is rational; otherwise m may keep a
// square factor of a prime above the trial bound (the form is exact either way, only not
// always the smallest m).
#pragma once

#include <cln/integer.h>

#include "core/scalar.h"
#include "linkproof/core/error.h"
#include "core/tracked.h"
#include "linkproof/core/exact.h"
#include "linkproof/geometry/vec2.h"

namespace linkproof {

/// An exact positive real coefficient * sqrt(radicand), radicand >= 1.
struct SquareRootForm {
  Rational coefficient;
  cln::cl_I radicand = 1;
};

/// sqrt(q) for q > 0 in the form above (LINKPROOF_ASSERT: q > 0).
SquareRootForm construct_square_root(const Rational& q);

/// An enclosure of sqrt(q), q > 0: |sqrt(q) - midpoint| <= half_width, with
/// half_width <= 2^-bits sqrt(q) (from the integer square root floor(sqrt(p q 4^bits))).
struct RationalEnclosure {
  Rational midpoint, half_width;
};
RationalEnclosure enclose_square_root(const Rational& q, int bits);

/// Fractional bits of the enclosure of |u| used in floating arithmetic: beyond the precision of
/// every arithmetic linkproof offers (mp1000 has about 3322 bits).
inline constexpr int kAxisLengthBits = 4096;

/// sqrt(q) in arithmetic T: exact input only (Rational: LINKPROOF_ASSERT that it is rational);
/// Tracked<F>: the enclosure's midpoint rounded to F, its radius the rounding plus the
/// enclosure's half-width, both rounded up.
template <class T>
T square_root_value(const Rational& q) {
  if constexpr (ScalarTraits<T>::is_exact) {
    const SquareRootForm f = construct_square_root(q);
    LINKPROOF_ASSERT(f.radicand == 1, "an exact square root of a rational that is not a square");
    return f.coefficient;
  } else {
    const RationalEnclosure r = enclose_square_root(q, kAxisLengthBits);
    using F = decltype(T{}.v);
    T x = from_rational<T>(r.midpoint);
    x.e = TrackedTraits<F>::add_up(x.e, TrackedTraits<F>::radius_up(r.half_width));
    return x;
  }
}

}  // namespace linkproof
