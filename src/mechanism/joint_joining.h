// Joint-joining (linkage reduction; Dijksman 1984, sections 2-4; docs/conventions.md §D).
//
// A ternary link t carries two bars b1, b2 (binary links with two revolute joints): bar b has its
// near joint N_b on t and its far joint F_b on another link x_b. The bar lines meet at
//   I = line(N_1, F_1) x line(N_2, F_2).
// First order:  both near joints move to I, the far joints stay. Velocities of every other link
//               are preserved (I has no velocity relative to t), accelerations in general not.
// Second order: both near joints move to I and each far joint is relocated along its bar line so
//               that it is the curvature centre of I in the motion t/x_b. By Euler-Savary on the
//               bar line (pole P = P_{t x_b}, which lies on it), signed distances along the line:
//                 1/(P F') = 1/(P F) + 1/(P I) - 1/(P N)          (paper eqs. (1'), (3'), ...)
//               Velocities and accelerations of every other link are preserved exactly.
// Any point K of the bar line may replace I as the new near joint of one bar (with F' from the
// same formula, K in place of I): the second-order equivalence does not depend on the choice.
// The reduced linkage keeps every link and joint name (the bars become b', with moved joints)
// and is solved again by the same engine (the rigid-body route, exact).
#pragma once

#include <string>

#include "core/scalar.h"
#include "linkproof/mechanism/mechanism_scene.h"
#include "mechanism/mechanism_solve.h"
#include "mechanism/poles.h"

namespace linkproof {

/// The joints of bar `bar` seen from link `t`: near on t, far on the other link.
struct BarEnds {
  int near_joint = -1, far_joint = -1, far_link = -1;
};

/// Empty if `bar` is a bar (two revolute joints, no other) with exactly one joint on `t`;
/// otherwise what is wrong, naming the links.
std::string bar_problem(const Linkage& g, int t, int bar);
/// Precondition: bar_problem(g, t, bar) is empty.
BarEnds bar_ends(const Linkage& g, int t, int bar);

/// Second-order relocation of the far joint F of a bar from near joint N to new near joint K,
/// with the pole P of (t, x) on the bar line: the formula of the header comment, or Undefined
/// (P coincides with N, F or K; the new far joint at infinity).
template <class T>
PlanePoint<T> relocate_far_joint(const Vec2<T>& P, const Vec2<T>& N, const Vec2<T>& F, const Vec2<T>& K,
                                 const std::string& quantity) {
  const Vec2<T> u = F - N;
  const T sN = dot(N - P, u), sF = dot(F - P, u), sK = dot(K - P, u);
  if (is_zero(sN) || is_zero(sF) || is_zero(sK))
    return PlanePoint<T>::undefined(quantity, "the pole coincides with a joint of the bar line");
  const T inv = from_int<T>(1) / sF + from_int<T>(1) / sK - from_int<T>(1) / sN;
  if (is_zero(inv)) return PlanePoint<T>::infinite(u);
  return PlanePoint<T>::finite(P + (from_int<T>(1) / (inv * norm2(u))) * u);
}

/// One joining step applied to `g` (whose exact motion is `motion`).
struct JointJoiningStep {
  PlanePoint<Rational> I;
  BarEnds ends[2];
  PlanePoint<Rational> pole[2];      ///< P_{t, x_b}
  PlanePoint<Rational> new_far[2];   ///< F_b (order 1) or F'_b (order 2)
  /// Order 2: the curvature centre of I (fixed in t) in the motion t/x_b, by the analytic route.
  PlanePoint<Rational> centre_of_I[2];
  std::string problem;               ///< non-empty: the step could not be done (why)
  Linkage reduced;                   ///< valid when problem is empty
};

JointJoiningStep join_joints(const Linkage& g, const MechanismMotion<Rational>& motion, const JointJoiningRequest& r);

/// The linkage with one bar's near joint moved to K and its far joint to F (a rebuilt Linkage).
Linkage move_bar(const Linkage& g, const BarEnds& ends, const Vec2<Rational>& K, const Vec2<Rational>& F);

/// The exact motion of `g` driven by `inputs` (rigid-body route); throws InputError.
MechanismSolution<Rational> solve_rigid_body(const Linkage& g, const std::vector<MechanismInput>& inputs,
                                             const std::string& source);

}  // namespace linkproof
