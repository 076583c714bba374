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

/// The motion field of one link (mechanism/poles.h): v0, a0 are the velocity and acceleration
/// of the point of the link now at the world origin, so that
///   v(X) = v0 + omega J X,      a(X) = a0 + omega-dot J X - omega^2 X.
template <class T>
struct LinkField {
  T omega, omega_dot;
  Vec2<T> v0, a0;
  Vec2<T> velocity(const Vec2<T>& X) const { return v0 + omega * perp(X); }
  Vec2<T> acceleration(const Vec2<T>& X) const { return a0 + omega_dot * perp(X) - (omega * omega) * X; }
};

template <class T>
struct MechanismMotion {
  std::vector<T> omega, omega_dot;        ///< per link, relative to the ground (ground: 0)
  std::vector<T> slide, slide_dot;        ///< per joint: sigma-dot, sigma-ddot (revolute: 0)
  std::vector<LinkField<T>> fields;       ///< per link (ground: 0)
  std::vector<Vec2<T>> joint_v, joint_a;  ///< per joint; prismatic: the slider's point (JointMotion::Skip: empty)
};

/// Whether complete_joint_motion fills joint_v / joint_a (a sampled configuration reads the
/// links' fields alone).
enum class JointMotion { Fill, Skip };

/// Fills the links' fields and joint_v / joint_a from omega, omega_dot, slide, slide_dot
/// (already set) by walking the spanning tree out from the ground with the formulas above: a
/// link's field from its tree joint's point, moved with the field of the link it is entered
/// from (and the sliding terms where that joint is prismatic).
template <class T>
void complete_joint_motion(const Linkage& g, MechanismMotion<T>& m, const JointGeometry<T>& geo = {},
                           JointMotion joints = JointMotion::Fill) {
  const Vec2<T> zero{from_int<T>(0), from_int<T>(0)};
  m.fields.assign(static_cast<size_t>(g.link_count()), LinkField<T>{from_int<T>(0), from_int<T>(0), zero, zero});
  for (int link : g.tree_order()) {
    if (link == g.ground()) continue;
    const JointCrossing& c = g.tree_entry(link);
    const LinkageJoint& j = g.joint(c.joint);
    const Vec2<T> p = geo.position(g, c.joint);
    const LinkField<T>& from = m.fields[static_cast<size_t>(c.from)];
    Vec2<T> vp = from.velocity(p), ap = from.acceleration(p);
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
    LinkField<T>& f = m.fields[static_cast<size_t>(link)];
    f.omega = m.omega[static_cast<size_t>(link)];
    f.omega_dot = m.omega_dot[static_cast<size_t>(link)];
    f.v0 = vp - f.omega * perp(p);
    f.a0 = ap - f.omega_dot * perp(p) + (f.omega * f.omega) * p;
  }
  if (joints == JointMotion::Skip) return;
  m.joint_v.resize(static_cast<size_t>(g.joint_count()));
  m.joint_a.resize(static_cast<size_t>(g.joint_count()));
  for (int jn = 0; jn < g.joint_count(); ++jn) {
    // The revolute point is shared; for a prismatic pair report the slider's point.
    const LinkField<T>& f = m.fields[static_cast<size_t>(g.joint(jn).links[1])];
    const Vec2<T> X = geo.position(g, jn);
    m.joint_v[static_cast<size_t>(jn)] = f.velocity(X);
    m.joint_a[static_cast<size_t>(jn)] = f.acceleration(X);
  }
}

}  // namespace linkproof
