// The vocabulary of mechanism claims (docs/claims.md, "Mechanism claims"): the words a claim
// about a mechanism scene may use, one table that drives parsing (arity, the kind of every
// argument), kind checking (a number or a vector) and evaluation (the `quantity` each word
// reads, mechanism/mechanism_claim_value.h). `linkproof check-claim --vocabulary` prints it.
//
// Names of links, joints and points are written as in the scene: quoted always works
// (`omega("3")`), a bare identifier where the name is one (`omega(coupler)`).
//
// Meanings (a point P is a joint or a tracer point of the scene; J = rotation by +90 degrees):
//   omega(L), alpha(L)          angular velocity / acceleration of link L relative to the ground
//   omega(L, M), alpha(L, M)    of L relative to M: omega(L) - omega(M), alpha(L) - alpha(M)
//   pos(P)                      the position of P (a vector)
//   vel(P, L), acc(P, L)        velocity / acceleration of the point of link L now at P
//   vel(P, L, M), acc(P, L, M)  the same seen from link M: v_L - v_M and
//                               a_L - a_M - 2 omega(M) J (v_L - v_M)  (with the Coriolis term)
//   pole(L, M)                  the instant centre of L and M (undefined at infinity or where
//                               L and M have no relative motion)
//   centre(P, L, M)             the centre of curvature of the path of the point of L at P
//                               seen from M: P + |v|^2/(v x a) J v (undefined where v = 0 or
//                               v x a = 0)
//   centre_at(X, L, M)          the same for the point of L at a constructed position X (a
//                               vector: a meet, a pole), e.g. Dijksman's double joints I13
//   sliding_v(J), sliding_a(J)  the rates of prismatic joint J along its unit axis (slider
//                               relative to guide): sigma-dot |u|, sigma-ddot |u|
//   axis(J)                     the unit axis u of prismatic joint J (its guide's direction)
//   dot, cross, perp, norm2, vx, vy, vec(x, y), meet(A, B, C, D) (lines AB and CD)
#pragma once

#include <string>
#include <vector>

namespace linkproof {

/// The kind of a value or of an argument of a word.
enum class MechanismKind {
  Number,  ///< a rational number
  Vector,  ///< a plane vector (two rationals)
  Link,    ///< the name of a link of the scene
  Point,   ///< the name of a joint or tracer point of the scene
  Slider,  ///< the name of a prismatic joint of the scene
};

/// What a word reads or computes: the evaluator's switch (mechanism/mechanism_claim_value.cpp).
enum class MechanismQuantity {
  Omega, OmegaRelative, Alpha, AlphaRelative,
  Position, Velocity, VelocityRelative, Acceleration, AccelerationRelative,
  Pole, Centre, CentreAt, SlidingV, SlidingA, Axis,
  Dot, Cross, Perp, Norm2, Vx, Vy, Vec, Meet,
};

struct MechanismWord {
  std::string name;
  std::vector<MechanismKind> arguments;  ///< the arity is its size
  MechanismKind result;                  ///< Number or Vector
  MechanismQuantity quantity;
  std::string signature;                 ///< as documented, e.g. "vel(P, L, M)"
  std::string meaning;                   ///< one line
};

/// Every word, in the order of the documentation.
const std::vector<MechanismWord>& mechanism_vocabulary();
/// The word called `name` with `arity` arguments, or nullptr.
const MechanismWord* find_mechanism_word(const std::string& name, int arity);
/// The signatures of every word called `name` ("omega(L), omega(L, M)"), or "" if none.
std::string mechanism_word_signatures(const std::string& name);
/// "a number", "a vector", "a link name", ...
std::string describe(MechanismKind kind);

}  // namespace linkproof
