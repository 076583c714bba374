// First-order plane geometry of a linkage at one instant: the velocity and acceleration field of
// every link, the motion of a point of one link relative to another, and the poles (instant
// centres) P_ij of every pair of links (docs/conventions.md §D), over any scalar type T.
//
// Field of link l (rates omega_l, omega-dot_l relative to the ground): with v0_l, a0_l the
// velocity and acceleration of the point of l now at the world origin,
//   v_l(X) = v0_l + omega_l J X,      a_l(X) = a0_l + omega-dot_l J X - omega_l^2 X.
// Point X fixed in link m, seen from link f (the frame f may move):
//   v = v_m(X) - v_f(X),
//   a = a_m(X) - a_f(X) - 2 omega_f J v        (Coriolis term: zero when f is the ground).
// Pole P_mf: the point with v_m(P) = v_f(P). With w = omega_m - omega_f, d = v0_m - v0_f:
//   w != 0:          P = J d / w                        (a finite point)
//   w = 0, d != 0:   at infinity in the direction J d   (a relative translation)
//   w = 0, d = 0:    undefined (the two links do not move relative to each other)
// Aronhold-Kennedy: P_ij, P_jk, P_ik are collinear (finite or not; checked with homogeneous
// coordinates, see homogeneous()).
#pragma once

#include <string>
#include <vector>

#include "core/scalar.h"
#include "mechanism/linkage_motion.h"
#include "geometry/zero_vector.h"

namespace linkproof {

/// A point that may lie at infinity or not exist: the value every construction here returns.
/// Finite: `at` is the point. AtInfinity: `at` is its direction. Undefined: `quantity` and
/// `reason` say what does not exist and why.
template <class T>
struct PlanePoint {
  enum class Kind { Finite, AtInfinity, Undefined } kind = Kind::Undefined;
  Vec2<T> at;
  std::string quantity, reason;

  bool is_finite() const { return kind == Kind::Finite; }
  static PlanePoint finite(Vec2<T> p) { return {Kind::Finite, p, {}, {}}; }
  static PlanePoint infinite(Vec2<T> d) { return {Kind::AtInfinity, d, {}, {}}; }
  static PlanePoint undefined(std::string q, std::string r) { return {Kind::Undefined, {}, std::move(q), std::move(r)}; }
};

/// Homogeneous coordinates (x, y, 1) of a finite point, (dx, dy, 0) of a point at infinity.
template <class T>
struct Homogeneous {
  T x, y, w;
};

template <class T>
Homogeneous<T> homogeneous(const PlanePoint<T>& p) {
  return {p.at.x, p.at.y, from_int<T>(p.is_finite() ? 1 : 0)};
}

/// det[p; q; r]: zero iff the three (finite or infinite) points are collinear.
template <class T>
T collinearity(const Homogeneous<T>& p, const Homogeneous<T>& q, const Homogeneous<T>& r) {
  return p.x * (q.y * r.w - q.w * r.y) - p.y * (q.x * r.w - q.w * r.x) + p.w * (q.x * r.y - q.y * r.x);
}

/// line(p1, p2) x line(p3, p4): finite, at infinity (parallel lines: direction of p1p2) or
/// undefined (a line through two equal points, or the same line twice).
template <class T>
PlanePoint<T> intersect_lines(const Vec2<T>& p1, const Vec2<T>& p2, const Vec2<T>& p3, const Vec2<T>& p4,
                              const std::string& quantity) {
  const Vec2<T> d1 = p2 - p1, d2 = p4 - p3;
  if (is_zero_vector(d1) || is_zero_vector(d2))
    return PlanePoint<T>::undefined(quantity, "a line through two coincident points");
  const T den = cross(d1, d2);
  if (is_zero(den)) {
    if (is_zero(cross(p3 - p1, d1))) return PlanePoint<T>::undefined(quantity, "the two lines coincide");
    return PlanePoint<T>::infinite(d1);
  }
  return PlanePoint<T>::finite(p1 + (cross(p3 - p1, d2) / den) * d1);
}

/// The field of every link read at the first joint it has (in the joints' order), from the
/// joints' motion (joint_v / joint_a filled). The same fields as the motion's own
/// (complete_joint_motion, read along the spanning tree) for numbers; for the symbolic proof
/// (proof/mechanism_proof.cpp) the form matters: two links that meet at a joint are then read at
/// it, so their relative motion there cancels term by term (vel(S, block, guide) is
/// sliding_v(S) u without the loop closure) and the proof needs no exceptional set for it.
template <class T>
std::vector<LinkField<T>> link_fields_from_joints(const Linkage& g, const MechanismMotion<T>& m,
                                                  const JointGeometry<T>& geo = {}) {
  std::vector<LinkField<T>> out(static_cast<size_t>(g.link_count()));
  std::vector<bool> done(out.size(), false);
  const Vec2<T> zero{from_int<T>(0), from_int<T>(0)};
  for (size_t l = 0; l < out.size(); ++l) out[l] = {m.omega[l], m.omega_dot[l], zero, zero};
  for (int jn = 0; jn < g.joint_count(); ++jn) {
    const LinkageJoint& j = g.joint(jn);
    const Vec2<T> X = geo.position(g, jn);
    for (int s = 0; s < 2; ++s) {
      const size_t l = static_cast<size_t>(j.links[s]);
      if (done[l]) continue;
      Vec2<T> v = m.joint_v[static_cast<size_t>(jn)], a = m.joint_a[static_cast<size_t>(jn)];
      if (j.type == JointType::Prismatic && s == 0) {  // joint_v/a are the slider's point
        const Vec2<T> u = geo.direction(g, jn);
        const T sd = m.slide[static_cast<size_t>(jn)];
        v = v - sd * u;
        a = a - (m.slide_dot[static_cast<size_t>(jn)] * u + (from_int<T>(2) * m.omega[l] * sd) * perp(u));
      }
      LinkField<T>& f = out[l];
      f.v0 = v - f.omega * perp(X);
      f.a0 = a - f.omega_dot * perp(X) + (f.omega * f.omega) * X;
      done[l] = true;
    }
  }
  return out;
}

/// Velocity and acceleration of the point X fixed in `moving`, seen from `fixed` (Coriolis
/// included).
template <class T>
struct RelativePointMotion {
  Vec2<T> v, a;
};

template <class T>
RelativePointMotion<T> relative_point_motion(const LinkField<T>& moving, const LinkField<T>& fixed, const Vec2<T>& X) {
  const Vec2<T> v = moving.velocity(X) - fixed.velocity(X);
  const Vec2<T> a = moving.acceleration(X) - fixed.acceleration(X) - (from_int<T>(2) * fixed.omega) * perp(v);
  return {v, a};
}

/// The pole P_mf (see the header comment); `quantity` names it in an undefined result.
template <class T>
PlanePoint<T> construct_pole(const LinkField<T>& m, const LinkField<T>& f, const std::string& quantity) {
  const T w = m.omega - f.omega;
  const Vec2<T> d = m.v0 - f.v0;
  if (!is_zero(w)) return PlanePoint<T>::finite((from_int<T>(1) / w) * perp(d));
  if (!is_zero_vector(d)) return PlanePoint<T>::infinite(perp(d));
  return PlanePoint<T>::undefined(quantity, "the two links have no relative motion (equal omega and velocity)");
}

}  // namespace linkproof
