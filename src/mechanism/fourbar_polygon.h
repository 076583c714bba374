// The acceleration polygon of a four-bar (the acceleration-polygon course notes,
// docs/conventions.md §B), over any scalar type T.
//
// Four-bar O2-A-B-O4: crank 2 (O2 -> A), coupler 3 (A -> B), rocker 4 (O4 -> B), frame 1.
// R_AO2 = A - O2, R_BA = B - A, R_BO4 = B - O4, R-breve = J R.
// Velocity polygon: omega2 J R_AO2 + omega3 J R_BA = omega4 J R_BO4, so
//   omega3 = -omega2 (R_AO2 x R_BO4)/(R_BA x R_BO4),  omega4 = omega2 (R_AO2 x R_BA)/(R_BO4 x R_BA).
// Acceleration polygon (drawn from the acceleration origin O_A):
//   A_A^n = -omega2^2 R_AO2, A_A^t = alpha2 R-breve_AO2, A_BA^n = -omega3^2 R_BA,
//   A_B^n = -omega4^2 R_BO4; the tangential A_BA^t (along R-breve_BA) and A_B^t (along
//   R-breve_BO4) close the polygon A_A^n + A_A^t + A_BA^n + A_BA^t = A_B^n + A_B^t.
//   alpha3 = A_BA^t . R-breve_BA / |R_BA|^2,  alpha4 = A_B^t . R-breve_BO4 / |R_BO4|^2.
// Coupler point P: A_P = A_A^n + A_A^t - omega3^2 R_PA + alpha3 R-breve_PA.
// Path curvature centre of P: P + (|v_P|^2 / (v_P x A_P)) J v_P.
// Undefined (UndefinedQuantity) at the four-bar's dead centre R_BA x R_BO4 = 0.
#pragma once

#include <optional>
#include <vector>

#include "core/scalar.h"
#include "linkproof/core/error.h"
#include "linkproof/mechanism/linkage.h"
#include "linkproof/geometry/vec2.h"

namespace linkproof {

/// The roles of a four-bar's links and joints, found from the linkage and its input.
struct FourBarRoles {
  int frame = 0, crank = 0, coupler = 0, rocker = 0;  ///< link indices
  int O2 = 0, A = 0, B = 0, O4 = 0;                   ///< joint indices
};

/// The roles if g is a revolute four-bar driven by one link adjacent to the frame.
std::optional<FourBarRoles> identify_fourbar(const Linkage& g, const std::vector<MechanismInput>& inputs);

template <class T>
struct FourBarPolygon {
  Vec2<T> R_AO2, R_BA, R_BO4;
  T omega2, alpha2, omega3, omega4;
  Vec2<T> A_A_n, A_A_t, A_BA_n, A_B_n, A_BA_t, A_B_t;  ///< the polygon's vectors
  Vec2<T> A_A, A_B;                                    ///< vertices (from O_A)
  T alpha3, alpha4;
};

template <class T>
FourBarPolygon<T> construct_fourbar_polygon(const Vec2<T>& O2, const Vec2<T>& A, const Vec2<T>& B, const Vec2<T>& O4,
                                            const T& omega2, const T& alpha2) {
  FourBarPolygon<T> p;
  p.R_AO2 = A - O2, p.R_BA = B - A, p.R_BO4 = B - O4;
  const T den = cross(p.R_BA, p.R_BO4);
  if (is_zero(den)) throw UndefinedQuantity("R_BA x R_BO4", "dead centre of the four-bar: coupler and rocker parallel");
  p.omega2 = omega2, p.alpha2 = alpha2;
  p.omega3 = -omega2 * cross(p.R_AO2, p.R_BO4) / den;
  p.omega4 = -omega2 * cross(p.R_AO2, p.R_BA) / den;
  p.A_A_n = -(omega2 * omega2) * p.R_AO2;
  p.A_A_t = alpha2 * perp(p.R_AO2);
  p.A_BA_n = -(p.omega3 * p.omega3) * p.R_BA;
  p.A_B_n = -(p.omega4 * p.omega4) * p.R_BO4;
  // Closing: alpha4 J R_BO4 - alpha3 J R_BA = K; the intersection of the two tangential lines.
  const Vec2<T> K = p.A_A_n + p.A_A_t + p.A_BA_n - p.A_B_n;
  const T a3 = -cross(K, perp(p.R_BO4)) / cross(p.R_BA, p.R_BO4);
  const T a4 = -cross(K, perp(p.R_BA)) / cross(p.R_BA, p.R_BO4);
  p.A_BA_t = a3 * perp(p.R_BA);
  p.A_B_t = a4 * perp(p.R_BO4);
  p.A_A = p.A_A_n + p.A_A_t;
  p.A_B = p.A_B_n + p.A_B_t;
  // The projection formulas of the course notes.
  p.alpha3 = dot(p.A_BA_t, perp(p.R_BA)) / norm2(p.R_BA);
  p.alpha4 = dot(p.A_B_t, perp(p.R_BO4)) / norm2(p.R_BO4);
  return p;
}

/// A_P = -omega2^2 R_AO2 + alpha2 R-breve_AO2 - omega3^2 R_PA + alpha3 R-breve_PA.
template <class T>
Vec2<T> fourbar_coupler_acceleration(const FourBarPolygon<T>& p, const Vec2<T>& R_PA) {
  return p.A_A_n + p.A_A_t - (p.omega3 * p.omega3) * R_PA + p.alpha3 * perp(R_PA);
}

/// P + (|v|^2 / (v x a)) J v; undefined where v x a = 0 (an inflection point or rest).
template <class T>
Vec2<T> path_curvature_centre(const Vec2<T>& P, const Vec2<T>& v, const Vec2<T>& a) {
  const T va = cross(v, a);
  if (is_zero(va)) throw UndefinedQuantity("v x a", "the point's path has no finite curvature centre here");
  return P + (norm2(v) / va) * perp(v);
}

}  // namespace linkproof
