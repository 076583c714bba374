// Route 2 to a mechanism's kinematics: the rigid-body vector formulas, written directly, over any
// scalar type T. Independent of the symbolic route (mechanism/mechanism_closure.h), which
// differentiates the closure with GiNaC; the two must give the same A and h exactly.
//
// Loop closure on joint position vectors: a loop (mechanism/linkage.h) runs through links
// l_0..l_{k-1}; inside l_i it goes from joint c_i to joint c_{i+1}, the vector r_i, fixed in l_i;
// through a prismatic joint it adds +-sigma u (u fixed in the guide, sigma = 0 now). Hence
//   sum_i r_i + sum_prismatic (+-) sigma u = 0,
//   d/dt:     sum_i omega_{l_i} J r_i + sum (+-) sigma-dot u = 0
//   d2/dt2:   sum_i (omega-dot_{l_i} J r_i - omega_{l_i}^2 r_i)
//             + sum (+-) (sigma-ddot u + 2 omega_guide sigma-dot J u) = 0   (Coriolis, docs/conventions.md §C)
// and per prismatic pair omega_slider - omega_guide = 0 (and its derivative).
// No angles appear: with rational joints and rates every entry is rational.
// Both builders read positions and axes through a JointGeometry (mechanism/joint_geometry.h):
// the linkage's exact values converted to T, or values already in T (Tracked data, symbols).
#pragma once

#include <span>
#include <vector>

#include "core/scalar.h"
#include "linkproof/mechanism/linkage.h"
#include "mechanism/joint_geometry.h"
#include "mechanism/linear_system.h"

namespace linkproof {

/// The loop vector from joint `from` to joint `to` (exact differences when the geometry is the
/// linkage's own).
template <class T>
Vec2<T> joint_difference(const Linkage& g, int from, int to, const JointGeometry<T>& geo) {
  if (geo.at) return geo.position(g, to) - geo.position(g, from);
  return vec_from_rational<T>(g.joint(to).at - g.joint(from).at);
}

/// The constraint matrix A (Linkage::constraint_count() x unknown_count()).
template <class T>
DenseMatrix<T> rigid_body_constraint_matrix(const Linkage& g, const JointGeometry<T>& geo = {}) {
  const size_t N = static_cast<size_t>(g.unknown_count());
  DenseMatrix<T> A = DenseMatrix<T>::with_columns(N);
  A.reserve(static_cast<size_t>(g.constraint_count()));
  const T zero = from_int<T>(0);
  for (const LinkageLoop& loop : g.loops()) {
    A.add_row(zero), A.add_row(zero);
    const std::span<T> rx = A[A.size() - 2], ry = A[A.size() - 1];
    const size_t k = loop.crossings.size();
    for (size_t i = 0; i < k; ++i) {
      const JointCrossing& c = loop.crossings[i];
      const JointCrossing& next = loop.crossings[(i + 1) % k];
      const Vec2<T> r = joint_difference<T>(g, c.joint, next.joint, geo);
      if (const int col = g.unknown_of_link(c.to); col >= 0) {
        rx[static_cast<size_t>(col)] = rx[static_cast<size_t>(col)] - r.y;  // J r = (-r_y, r_x)
        ry[static_cast<size_t>(col)] = ry[static_cast<size_t>(col)] + r.x;
      }
      if (const int s = g.sliding_sign(c); s != 0) {
        const Vec2<T> u = geo.direction(g, c.joint);
        const size_t col = static_cast<size_t>(g.unknown_of_joint(c.joint));
        rx[col] = rx[col] + from_int<T>(s) * u.x;
        ry[col] = ry[col] + from_int<T>(s) * u.y;
      }
    }
  }
  for (const LinkageJoint& j : g.joints()) {
    if (j.type != JointType::Prismatic) continue;
    const std::span<T> row = A.add_row(zero);
    if (const int c = g.unknown_of_link(j.links[1]); c >= 0) row[static_cast<size_t>(c)] = from_int<T>(1);
    if (const int c = g.unknown_of_link(j.links[0]); c >= 0) row[static_cast<size_t>(c)] = from_int<T>(-1);
  }
  return A;
}

/// h(q-dot): the acceleration system's right-hand side (everything without omega-dot or
/// sigma-ddot, moved to the right). `coriolis = false` drops the Coriolis terms: a deliberately
/// wrong variant, for the claim that they are needed (docs/conventions.md §C).
template <class T>
std::vector<T> rigid_body_acceleration_rhs(const Linkage& g, const std::vector<T>& qdot, bool coriolis = true,
                                          const JointGeometry<T>& geo = {}) {
  const auto omega = [&](int link) {
    const int c = g.unknown_of_link(link);
    return c < 0 ? from_int<T>(0) : qdot[static_cast<size_t>(c)];
  };
  std::vector<T> h;
  h.reserve(static_cast<size_t>(g.constraint_count()));
  for (const LinkageLoop& loop : g.loops()) {
    Vec2<T> acc{from_int<T>(0), from_int<T>(0)};
    const size_t k = loop.crossings.size();
    for (size_t i = 0; i < k; ++i) {
      const JointCrossing& c = loop.crossings[i];
      const JointCrossing& next = loop.crossings[(i + 1) % k];
      const Vec2<T> r = joint_difference<T>(g, c.joint, next.joint, geo);
      const T w = omega(c.to);
      acc = acc + (w * w) * r;
      if (const int s = g.sliding_sign(c); s != 0 && coriolis) {
        const LinkageJoint& j = g.joint(c.joint);
        const T sd = qdot[static_cast<size_t>(g.unknown_of_joint(c.joint))];
        acc = acc - (from_int<T>(2 * s) * omega(j.links[0]) * sd) * perp(geo.direction(g, c.joint));
      }
    }
    h.push_back(acc.x);
    h.push_back(acc.y);
  }
  for (const LinkageJoint& j : g.joints())
    if (j.type == JointType::Prismatic) h.push_back(from_int<T>(0));
  return h;
}

}  // namespace linkproof
