// Second-order geometry of a relative plane motion (docs/conventions.md §D), over any scalar type T: the
// path curvature centre of a point, the inflection circle, the pole normal and tangent, and the
// two sides of Euler-Savary's equation on a ray from the pole.
//
// Curvature centre of the path of X (velocity v, acceleration a, relative to the frame):
//   C = X + (|v|^2 / (v x a)) J v,       squared radius |C - X|^2 = |v|^6 / (v x a)^2.
//   v = 0      X is at the pole: a cusp of its path, the centre is undefined;
//   v x a = 0  X is on the inflection circle: the centre is at infinity (direction J v).
// Motion m/f with pole P (finite), omega = omega_m - omega_f != 0 and pole acceleration a_P:
//   inflection pole W = P + a_P / omega^2 (the inflection circle has diameter PW),
//   delta = |a_P| / omega^2, pole normal n = a_P / |a_P| = J t, pole tangent t = -J n.
// Euler-Savary on the ray from P in direction u (S_a a point of the ray, S_b its centre; signed
// distances along u; theta the angle from t to u):
//   1/(P S_a) - 1/(P S_b) = 1/(delta sin theta).
// Both sides divided by |u| are rational: with PS = (S - P).u / |u| and
// delta sin theta = (t x u)/|u| * |a_P|/omega^2 = (a_P . u) / (omega^2 |u|),
//   lhs / |u| = 1/((S_a - P).u) - 1/((S_b - P).u),      rhs / |u| = omega^2 / (a_P . u).
// A centre at infinity contributes 1/(P S_b) = 0. This is the form compared exactly.
#pragma once

#include <optional>

#include "core/scalar.h"
#include "mechanism/poles.h"
#include "geometry/zero_vector.h"

namespace linkproof {

/// The path curvature centre of X, or why it does not exist / is at infinity.
template <class T>
PlanePoint<T> construct_curvature_centre(const Vec2<T>& X, const RelativePointMotion<T>& m, const std::string& quantity) {
  if (is_zero_vector(m.v)) return PlanePoint<T>::undefined(quantity, "the point is at the pole (v = 0): a cusp of its path");
  const T vxa = cross(m.v, m.a);
  if (is_zero(vxa)) return PlanePoint<T>::infinite(perp(m.v));
  return PlanePoint<T>::finite(X + (norm2(m.v) / vxa) * perp(m.v));
}

/// The instantaneous second-order data of the relative motion m/f.
template <class T>
struct InflectionCircle {
  PlanePoint<T> pole;
  T omega;              ///< omega_m - omega_f
  Vec2<T> a_pole;       ///< acceleration of the pole point of m relative to f
  Vec2<T> inflection;   ///< the inflection pole W = P + a_P / omega^2 (P finite, omega != 0)
  Vec2<T> normal, tangent;  ///< a_P and -J a_P (directions of n and t, not normalised)
};

/// Undefined (named) when the pole is not a finite point or the relative motion is a pure
/// rotation about the pole (a_P = 0: no inflection circle).
template <class T>
PlanePoint<T> inflection_pole(const InflectionCircle<T>& c) {
  if (!c.pole.is_finite()) return PlanePoint<T>::undefined("inflection pole", "the pole is at infinity or undefined");
  if (is_zero_vector(c.a_pole)) return PlanePoint<T>::undefined("inflection pole", "the pole has zero acceleration (a_P = 0)");
  return PlanePoint<T>::finite(c.inflection);
}

template <class T>
InflectionCircle<T> construct_inflection_circle(const LinkField<T>& m, const LinkField<T>& f, const std::string& pole_name) {
  InflectionCircle<T> c;
  c.pole = construct_pole(m, f, pole_name);
  c.omega = m.omega - f.omega;
  const Vec2<T> zero{from_int<T>(0), from_int<T>(0)};
  c.a_pole = c.inflection = c.normal = c.tangent = zero;
  if (!c.pole.is_finite()) return c;
  c.a_pole = relative_point_motion(m, f, c.pole.at).a;  // v = 0 at the pole: no Coriolis term
  c.inflection = c.pole.at + (from_int<T>(1) / (c.omega * c.omega)) * c.a_pole;
  c.normal = c.a_pole;
  c.tangent = -perp(c.a_pole);
  return c;
}

/// The two sides of Euler-Savary divided by |u| (see the header comment). nullopt where a side
/// does not exist: S_a at the pole, or u along the pole tangent (sin theta = 0).
template <class T>
struct EulerSavarySides {
  std::optional<T> lhs, rhs;
};

template <class T>
EulerSavarySides<T> euler_savary_sides(const InflectionCircle<T>& c, const Vec2<T>& u, const Vec2<T>& S_a,
                                       const PlanePoint<T>& S_b) {
  EulerSavarySides<T> s;
  if (!c.pole.is_finite()) return s;
  const T apu = dot(c.a_pole, u);
  if (!is_zero(apu)) s.rhs = c.omega * c.omega / apu;
  const T da = dot(S_a - c.pole.at, u);
  if (is_zero(da)) return s;
  if (S_b.kind == PlanePoint<T>::Kind::AtInfinity) {
    s.lhs = from_int<T>(1) / da;
  } else if (S_b.is_finite()) {
    const T db = dot(S_b.at - c.pole.at, u);
    if (!is_zero(db)) s.lhs = from_int<T>(1) / da - from_int<T>(1) / db;
  }
  return s;
}

}  // namespace linkproof
