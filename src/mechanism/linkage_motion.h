// The motion of a linkage at one instant, over any scalar type T (core/scalar.h), and the
// rigid-body formulas that give every joint's velocity and acceleration from the link rates.
//
// Rigid body (link l with rates omega_l, omega-dot_l, a point P and a reference point O of l):
//   v_P = v_O + omega_l J (P - O)
//   a_P = a_O + omega-dot_l J (P - O) - omega_l^2 (P - O)
// Prismatic pair (guide g, slider s, direction u fixed in g, sliding rates sigma-dot, sigma-ddot;
// docs/conventions.md §C, prismatic pair): the slider point P_s and the guide point P_g coincide now and
//   v_{P_s} = v_{P_g} + sigma-dot u
//   a_{P_s} = a_{P_g} + sigma-ddot u + 2 omega_g sigma-dot J u        (Coriolis term)
// and omega_s = omega_g, omega-dot_s = omega-dot_g.
#pragma once

#include <vector>

#include "core/scalar.h"
#include "linkproof/mechanism/linkage.h"
#include "mechanism/joint_geometry.h"

namespace linkproof {

template <class T>
struct MechanismMotion {
  std::vector<T> omega, omega_dot;        ///< per link, relative to the ground (ground: 0)
  std::vector<T> slide, slide_dot;        ///< per joint: sigma-dot, sigma-ddot (revolute: 0)
  std::vector<Vec2<T>> joint_v, joint_a;  ///< per joint; prismatic: the slider's point
};

/// Fills joint_v / joint_a from omega, omega_dot, slide, slide_dot (already set) by walking the
/// spanning tree out from the ground with the formulas above.
template <class T>
void complete_joint_motion(const Linkage& g, MechanismMotion<T>& m, const JointGeometry<T>& geo = {}) {
  const size_t L = static_cast<size_t>(g.link_count());
  // Per link: a reference point O (a joint position) with its velocity and acceleration.
  std::vector<Vec2<T>> origin(L), v(L), a(L);
  const Vec2<T> zero{from_int<T>(0), from_int<T>(0)};
  for (auto& x : v) x = zero;
  for (auto& x : a) x = zero;
  const auto point_motion = [&](int link, const Vec2<T>& p, Vec2<T>& vp, Vec2<T>& ap) {
    const size_t l = static_cast<size_t>(link);
    const Vec2<T> r = p - origin[l];
    vp = v[l] + m.omega[l] * perp(r);
    ap = a[l] + m.omega_dot[l] * perp(r) - (m.omega[l] * m.omega[l]) * r;
  };
  origin[static_cast<size_t>(g.ground())] = zero;
  for (int link : g.tree_order()) {
    if (link == g.ground()) continue;
    const JointCrossing& c = g.tree_entry(link);
    const LinkageJoint& j = g.joint(c.joint);
    const Vec2<T> p = geo.position(g, c.joint);
    Vec2<T> vp, ap;
    point_motion(c.from, p, vp, ap);
    if (const int s = g.sliding_sign(c); s != 0) {
      const size_t jj = static_cast<size_t>(c.joint);
      const Vec2<T> u = geo.direction(g, c.joint);
      const T w_guide = m.omega[static_cast<size_t>(j.links[0])];
      const Vec2<T> dv = m.slide[jj] * u;
      const Vec2<T> da = m.slide_dot[jj] * u + (from_int<T>(2) * w_guide * m.slide[jj]) * perp(u);
      const T sign = from_int<T>(s);
      vp = vp + sign * dv;
      ap = ap + sign * da;
    }
    origin[static_cast<size_t>(link)] = p;
    v[static_cast<size_t>(link)] = vp;
    a[static_cast<size_t>(link)] = ap;
  }
  m.joint_v.assign(static_cast<size_t>(g.joint_count()), zero);
  m.joint_a.assign(static_cast<size_t>(g.joint_count()), zero);
  for (int jn = 0; jn < g.joint_count(); ++jn) {
    const LinkageJoint& j = g.joint(jn);
    // The revolute point is shared; for a prismatic pair report the slider's point.
    point_motion(j.links[1], geo.position(g, jn), m.joint_v[static_cast<size_t>(jn)],
                 m.joint_a[static_cast<size_t>(jn)]);
  }
}

}  // namespace linkproof
