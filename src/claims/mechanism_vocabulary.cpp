#include "claims/mechanism_vocabulary.h"

namespace linkproof {

const std::vector<MechanismWord>& mechanism_vocabulary() {
  using K = MechanismKind;
  using Q = MechanismQuantity;
  static const std::vector<MechanismWord> words = {
      {"omega", {K::Link}, K::Number, Q::Omega, "omega(L)", "angular velocity of link L relative to the ground (ground: 0)"},
      {"omega", {K::Link, K::Link}, K::Number, Q::OmegaRelative, "omega(L, M)", "omega(L) - omega(M): L relative to M"},
      {"alpha", {K::Link}, K::Number, Q::Alpha, "alpha(L)", "angular acceleration of link L relative to the ground (ground: 0)"},
      {"alpha", {K::Link, K::Link}, K::Number, Q::AlphaRelative, "alpha(L, M)", "alpha(L) - alpha(M): L relative to M"},
      {"pos", {K::Point}, K::Vector, Q::Position, "pos(P)", "position of joint or tracer point P (a vector)"},
      {"vel", {K::Point, K::Link}, K::Vector, Q::Velocity, "vel(P, L)", "velocity of the point of link L now at P"},
      {"vel", {K::Point, K::Link, K::Link}, K::Vector, Q::VelocityRelative, "vel(P, L, M)",
       "the same seen from link M: vel(P, L) - vel(P, M)"},
      {"acc", {K::Point, K::Link}, K::Vector, Q::Acceleration, "acc(P, L)", "acceleration of the point of link L now at P"},
      {"acc", {K::Point, K::Link, K::Link}, K::Vector, Q::AccelerationRelative, "acc(P, L, M)",
       "the same seen from link M: acc(P, L) - acc(P, M) - 2 omega(M) perp(vel(P, L, M)) (Coriolis)"},
      {"pole", {K::Link, K::Link}, K::Vector, Q::Pole, "pole(L, M)",
       "instant centre of L and M (undefined at infinity, omega(L) = omega(M), or with no relative motion)"},
      {"centre", {K::Point, K::Link, K::Link}, K::Vector, Q::Centre, "centre(P, L, M)",
       "centre of curvature of the path of the point of L at P seen from M (undefined where v = 0 or v x a = 0)"},
      {"centre_at", {K::Vector, K::Link, K::Link}, K::Vector, Q::CentreAt, "centre_at(X, L, M)",
       "the same for the point of L at the position X (a vector, e.g. a meet): centre(P, L, M) with X for pos(P)"},
      {"sliding_v", {K::Slider}, K::Number, Q::SlidingV, "sliding_v(J)",
       "sliding velocity of prismatic joint J along its unit axis (slider relative to guide)"},
      {"sliding_a", {K::Slider}, K::Number, Q::SlidingA, "sliding_a(J)",
       "sliding acceleration of prismatic joint J along its unit axis (slider relative to guide)"},
      {"axis", {K::Slider}, K::Vector, Q::Axis, "axis(J)",
       "the unit axis u of prismatic joint J, the direction of its guide (undefined if |u| is irrational)"},
      {"dot", {K::Vector, K::Vector}, K::Number, Q::Dot, "dot(a, b)", "a . b"},
      {"cross", {K::Vector, K::Vector}, K::Number, Q::Cross, "cross(a, b)", "a x b = ax by - ay bx"},
      {"perp", {K::Vector}, K::Vector, Q::Perp, "perp(a)", "a turned by +90 degrees: (-ay, ax)"},
      {"norm2", {K::Vector}, K::Number, Q::Norm2, "norm2(a)", "a . a"},
      {"vx", {K::Vector}, K::Number, Q::Vx, "vx(a)", "x component of a"},
      {"vy", {K::Vector}, K::Number, Q::Vy, "vy(a)", "y component of a"},
      {"vec", {K::Number, K::Number}, K::Vector, Q::Vec, "vec(x, y)", "the vector (x, y)"},
      {"meet", {K::Vector, K::Vector, K::Vector, K::Vector}, K::Vector, Q::Meet, "meet(A, B, C, D)",
       "intersection of lines AB and CD (undefined for parallel lines or A = B, C = D)"},
  };
  return words;
}

const MechanismWord* find_mechanism_word(const std::string& name, int arity) {
  for (const MechanismWord& w : mechanism_vocabulary())
    if (w.name == name && static_cast<int>(w.arguments.size()) == arity) return &w;
  return nullptr;
}

std::string mechanism_word_signatures(const std::string& name) {
  std::string out;
  for (const MechanismWord& w : mechanism_vocabulary())
    if (w.name == name) out += (out.empty() ? "" : ", ") + w.signature;
  return out;
}

std::string describe(MechanismKind kind) {
  switch (kind) {
    case MechanismKind::Number: return "a number";
    case MechanismKind::Vector: return "a vector";
    case MechanismKind::Link: return "a link name";
    case MechanismKind::Point: return "a joint or point name";
    case MechanismKind::Slider: return "a prismatic joint name";
  }
  return "?";
}

}  // namespace linkproof
