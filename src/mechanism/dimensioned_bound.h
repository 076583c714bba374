// How far the results of a rationalised scene may be from the results at its dimensioned values
// (docs/mechanisms.md, "Rationalised, and said so"; MechanismCheck::dimensioned).
//
// A scene placed from dimensions runs on rationals x near the dimensioned values x* (positions,
// axis directions, input rates; io/joint_placement.h): |x_i - x*_i| <= b_i per coordinate,
// certified. The velocity and acceleration systems
//   A(p) q-dot = (input rates),   A(p) q-ddot = h(p, u, q-dot) + (input accelerations)
// and every derived quantity (point velocities and accelerations, sliding rates, Coriolis terms)
// are functions of the positions p, the axes u and the input rates only (mechanism_solve.h,
// mechanism_vector_route.h): nothing else of the dimensioned configuration enters. So the rigid-
// body route is solved once more in midpoint-radius arithmetic (Tracked<MpFloat<100>>,
// core/tracked.h), every rationalised value starting with its bound b_i as radius (exact values:
// radius 0). Each operation's rule holds for any operands within their radii, so each result's
// enclosure [m - e, m + e] contains that result for every point of the box x +- b: for the
// rationals x (the exact results reported) and for the dimensioned values x* alike. Their
// distance is therefore at most the width 2e, which is the bound reported.
//
// The solve's pivots must be bounded away from zero on the whole box: a division by an enclosure
// that reaches 0 (a configuration within the bounds of a dead centre, where the system is
// singular) gives an unbounded radius, reported as "not bounded" with the quantity, never as a
// small bound. Rows the solve finds dependent are dropped: the dimensioned mechanism moves with the
// given input rates (that is what its results mean), so its motion satisfies every row and is the
// unique solution of the rows kept, whose pivots are certified non-zero on the box.
#pragma once

#include <utility>
#include <vector>

#include "linkproof/mechanism/mechanism_check.h"
#include "linkproof/mechanism/mechanism_scene.h"

namespace linkproof {

/// Decimal digits of the bounding solve: 40 beyond the rationalisation (10^-60 of the scale), so
/// its own rounding is negligible beside the starting radii.
inline constexpr int kDimensionedBoundDigits = 100;

/// The starting radii: per joint (each coordinate of its position), per joint (each coordinate of
/// a prismatic axis as written; revolute entries 0), per input (rate, rate-dot).
struct StartingRadii {
  std::vector<Rational> position, axis;
  std::vector<std::pair<Rational, Rational>> input;
};

/// From the scene's placement, by name: a rationalised joint its bound; an axis given as an angle
/// its bound; an axis `{from: J}` of joint P (u = P - J) the sum of P's and J's bounds; a
/// rationalised rate its bound; everything else 0.
StartingRadii construct_starting_radii(const MechanismScene& s);

/// The bound of every result (DimensionedBound), from the solve described above with `radii`.
/// Throws nothing for a solve that fails within the box: the bound is then "not bounded" with
/// the reason.
DimensionedBound compute_dimensioned_bound(const MechanismScene& s, const StartingRadii& radii);

}  // namespace linkproof
