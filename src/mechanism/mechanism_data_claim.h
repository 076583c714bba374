// Mechanism claims given as data, evaluated exactly on a solved mechanism (docs/claims.md,
// "Mechanism claims").
//
// bind_mechanism_claim resolves the names a claim writes (links, joints, tracer points,
// prismatic joints) against a scene, once: an unknown name, or a revolute joint where a
// prismatic one is due, is an InputError at the name's file:line:column. A scene with the same
// link, joint and point names in the same order (a random configuration of its topology,
// proof/mechanism_sampling.h) uses the same binding.
//
// Evaluation (MechanismFrameOf<T>): every value is a number or a pair of them in T (exact
// rationals; a floating arithmetic with error bounds; GiNaC expressions of a topology's symbols
// for proof/mechanism_proof.h), from the link fields of mechanism/poles.h (v_L(X) = v0_L +
// omega_L J X, a_L(X) = a0_L + alpha_L J X - omega_L^2 X); a quantity that does not exist (a division by 0, a pole at infinity, parallel
// lines in meet, the curvature centre of a point at the pole) throws UndefinedQuantity naming it
// as written, which the claim's run turns into the verdict `undefined`.
#pragma once

#include <vector>

#include "claims/mechanism_claim.h"
#include "mechanism/mechanism_catalogue.h"
#include "mechanism/poles.h"

namespace linkproof {

/// A value of a mechanism claim expression: a number (x) or a vector (x, y), in T.
template <class T>
struct MechanismValueOf {
  bool is_vector = false;
  T x, y;
};
using MechanismValue = MechanismValueOf<Rational>;

/// What an evaluation reads: the scene, its solved motion, and where its joints, tracer points
/// and axes are in T (by default the scene's exact values; symbols for a proof over a topology).
template <class T>
struct MechanismFrameOf {
  MechanismFrameOf(const MechanismScene& scene, const MechanismMotion<T>& motion);
  /// Positions and axes given in T: those the motion was solved at. `unit_axes`: every axis has
  /// length 1 by construction (the symbolic axes (c, s) of a proof, read on c^2 + s^2 = 1), so
  /// sliding rates need no |u|.
  MechanismFrameOf(const MechanismScene& scene, const MechanismMotion<T>& motion, std::vector<Vec2<T>> joint_at,
                   std::vector<Vec2<T>> point_at, std::vector<Vec2<T>> axis, bool unit_axes);
  const MechanismScene& scene;
  const MechanismMotion<T>& motion;
  std::vector<Vec2<T>> joint_at, point_at, axis;  ///< per joint, per tracer point, per joint
  bool unit_axes = false;
  /// Per link: the motion's (mechanism/linkage_motion.h), made with the positions it was solved
  /// at, which are the frame's.
  const std::vector<LinkField<T>>& fields;
};
using MechanismFrame = MechanismFrameOf<Rational>;

/// Resolves every name of both sides against `scene` (see the header comment); throws
/// InputError naming the claim, the field and the name's file:line:column.
void bind_mechanism_claim(MechanismDataClaim& claim, const MechanismScene& scene);

/// The value of a bound expression; throws UndefinedQuantity where a quantity does not exist.
/// Instantiated for every arithmetic (check/arithmetic_types.h; in a floating one "does not
/// exist" means "is certainly 0": a divisor whose enclosure merely contains 0 gives an unbounded
/// error bound, which the judge calls inconclusive) and for GiNaC::ex (where it means "for every
/// configuration": a divisor that is identically 0).
template <class T>
MechanismValueOf<T> evaluate_mechanism_expression(const MechanismNode& node, const MechanismFrameOf<T>& frame);

/// The comparisons of a bound claim: "total" for a number claim, "x" and "y" for a vector claim.
/// Instantiated for every arithmetic.
template <class T>
ClaimSides<T> evaluate_mechanism_claim(const MechanismDataClaim& claim, const MechanismFrameOf<T>& frame);

/// The claim as a MechanismClaim (run by run_mechanism_claim; the claim must be bound to a scene
/// with the names of the one it is run on).
MechanismClaim to_mechanism_claim(const MechanismDataClaim& claim);

}  // namespace linkproof
