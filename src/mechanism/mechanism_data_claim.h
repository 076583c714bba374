// Mechanism claims given as data, evaluated exactly on a solved mechanism (docs/claims.md,
// "Mechanism claims").
//
// bind_mechanism_claim resolves the names a claim writes (links, joints, tracer points,
// prismatic joints) against a scene, once: an unknown name, or a revolute joint where a
// prismatic one is due, is an InputError at the name's file:line:column. A scene with the same
// link, joint and point names in the same order (a random configuration of its topology,
// proof/mechanism_sampling.h) uses the same binding.
//
// Evaluation (MechanismFrame): every value is an exact rational or a pair of them, from the
// link fields of mechanism/poles.h (v_L(X) = v0_L + omega_L J X, a_L(X) = a0_L + alpha_L J X -
// omega_L^2 X); a quantity that does not exist (a division by 0, a pole at infinity, parallel
// lines in meet, the curvature centre of a point at the pole) throws UndefinedQuantity naming it
// as written, which the claim's run turns into the verdict `undefined`.
#pragma once

#include <vector>

#include "claims/mechanism_claim.h"
#include "mechanism/mechanism_catalogue.h"
#include "mechanism/poles.h"

namespace linkproof {

/// A value of a mechanism claim expression: a number (x) or a vector (x, y).
struct MechanismValue {
  bool is_vector = false;
  Rational x, y;
};

/// What an evaluation reads: the scene and its solved motion.
struct MechanismFrame {
  MechanismFrame(const MechanismScene& scene, const MechanismMotion<Rational>& motion);
  const MechanismScene& scene;
  const MechanismMotion<Rational>& motion;
  std::vector<LinkField<Rational>> fields;  ///< per link (mechanism/poles.h)
};

/// Resolves every name of both sides against `scene` (see the header comment); throws
/// InputError naming the claim, the field and the name's file:line:column.
void bind_mechanism_claim(MechanismDataClaim& claim, const MechanismScene& scene);

/// The value of a bound expression; throws UndefinedQuantity where a quantity does not exist.
MechanismValue evaluate_mechanism_expression(const MechanismNode& node, const MechanismFrame& frame);

/// The comparisons of a bound claim: "total" for a number claim, "x" and "y" for a vector claim.
ClaimSides<Rational> evaluate_mechanism_claim(const MechanismDataClaim& claim, const MechanismFrame& frame);

/// The claim as a MechanismClaim (run by run_mechanism_claim; the claim must be bound to a scene
/// with the names of the one it is run on).
MechanismClaim to_mechanism_claim(const MechanismDataClaim& claim);

}  // namespace linkproof
