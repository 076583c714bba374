// Bobillier's construction of a curvature centre (Dijksman 1984, section 5, Fig. 6; docs/conventions.md §D),
// by line intersections only, over any scalar type T.
//
// Given two points A, B of the moving plane with their curvature centres alpha, beta in the
// fixed plane (a four-bar alpha A B beta) and a third point C of the moving plane:
//   (a) P    = line(alpha, A) x line(beta, B)             the pole
//   (b) Q_AB = line(alpha, beta) x line(A, B)             the collineation point
//   (c) q_AC: the line through P with  angle(PC -> q_AC) = angle(PB -> PQ_AB), both angles
//       directed and in the same sense. As complex numbers the direction of q_AC is
//       (C - P)(Q_AB - P) conj(B - P): rotating PC by the angle from PB to PQ_AB, exactly.
//   (d) Q_AC = line(A, C) x q_AC
//   (e) gamma = line(P, C) x line(alpha, Q_AC)            the centre sought
// The mirrored reading of (c) (the angle measured in the opposite sense, direction
// (C - P) conj(Q_AB - P)(B - P)) is an erratum reading: it gives a wrong gamma (docs/conventions.md §D).
// Degenerate cases are values, not exceptions: C on the line PA (step (d) intersects a line with
// itself) -> the B/beta version (the roles of A and B exchanged); C on both PA and PB, the pole
// or Q_AB at infinity or undefined -> Undefined naming the step; gamma at infinity (C on the
// inflection circle) -> AtInfinity.
#pragma once

#include <string>

#include "core/scalar.h"
#include "mechanism/poles.h"
#include "geometry/zero_vector.h"

namespace linkproof {

template <class T>
struct BobillierConstruction {
  PlanePoint<T> P, Q_AB, Q_AC, gamma;
  Vec2<T> q_AC_direction;
  char version = 'A';  ///< 'A': as drawn; 'B': roles of (A, alpha) and (B, beta) exchanged
};

namespace bobillier_detail {
template <class T>
Vec2<T> complex_mul(const Vec2<T>& a, const Vec2<T>& b) { return {a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x}; }
template <class T>
Vec2<T> conj(const Vec2<T>& a) { return {a.x, -a.y}; }
}  // namespace bobillier_detail

/// Steps (a)-(e) with A as the base point; the result's gamma is Undefined naming the failing
/// step. `mirrored` takes the erratum reading of step (c).
template <class T>
BobillierConstruction<T> construct_bobillier_once(const Vec2<T>& A, const Vec2<T>& alpha, const Vec2<T>& B,
                                                  const Vec2<T>& beta, const Vec2<T>& C, bool mirrored) {
  using namespace bobillier_detail;
  using PP = PlanePoint<T>;
  BobillierConstruction<T> r;
  r.P = intersect_lines(alpha, A, beta, B, "P (step a)");
  r.Q_AB = intersect_lines(alpha, beta, A, B, "Q_AB (step b)");
  const auto stop = [&](const PP& why, const std::string& step) {
    r.gamma = PP::undefined("gamma", step + (why.kind == PP::Kind::AtInfinity ? " is at infinity" : ": " + why.reason));
    return r;
  };
  if (!r.P.is_finite()) return stop(r.P, "the pole P (step a)");
  if (!r.Q_AB.is_finite()) return stop(r.Q_AB, "the collineation point Q_AB (step b)");
  const Vec2<T> b = B - r.P.at, q = r.Q_AB.at - r.P.at, c = C - r.P.at;
  if (is_zero_vector(c)) return stop(PP::undefined("", "C is the pole"), "step (c)");
  if (is_zero_vector(b) || is_zero_vector(q)) return stop(PP::undefined("", "B or Q_AB is the pole"), "step (c)");
  r.q_AC_direction = mirrored ? complex_mul(complex_mul(c, conj(q)), b) : complex_mul(complex_mul(c, q), conj(b));
  r.Q_AC = intersect_lines(A, C, r.P.at, r.P.at + r.q_AC_direction, "Q_AC (step d)");
  if (!r.Q_AC.is_finite()) return stop(r.Q_AC, "the point Q_AC (step d)");
  r.gamma = intersect_lines(r.P.at, C, alpha, r.Q_AC.at, "gamma (step e)");
  if (r.gamma.kind == PP::Kind::Undefined) r.gamma.quantity = "gamma";
  return r;
}

/// As drawn; the B/beta version when C lies on the line PA (docs/conventions.md §D).
template <class T>
BobillierConstruction<T> construct_bobillier(const Vec2<T>& A, const Vec2<T>& alpha, const Vec2<T>& B,
                                             const Vec2<T>& beta, const Vec2<T>& C, bool mirrored = false) {
  BobillierConstruction<T> r = construct_bobillier_once(A, alpha, B, beta, C, mirrored);
  if (r.P.is_finite() && is_zero(cross(C - r.P.at, A - r.P.at))) {
    r = construct_bobillier_once(B, beta, A, alpha, C, mirrored);
    r.version = 'B';
    if (r.P.is_finite() && is_zero(cross(C - r.P.at, B - r.P.at)))
      r.gamma = PlanePoint<T>::undefined("gamma", "C lies on both pole rays PA and PB (C is the pole)");
  }
  return r;
}

}  // namespace linkproof
