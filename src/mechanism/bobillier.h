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

#include <optional>
#include <string>
#include <utility>

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

/// The line through two points, either of which may lie at infinity (PlanePoint::AtInfinity: `at`
/// is its direction): two finite points on it, or nullopt for two points at infinity (the line at
/// infinity) or an undefined one.
template <class T>
std::optional<std::pair<Vec2<T>, Vec2<T>>> line_through(const PlanePoint<T>& X, const PlanePoint<T>& Y) {
  using PP = PlanePoint<T>;
  if (X.kind == PP::Kind::Undefined || Y.kind == PP::Kind::Undefined) return std::nullopt;
  if (X.is_finite() && Y.is_finite()) return std::pair{X.at, Y.at};
  if (X.is_finite()) return std::pair{X.at, X.at + Y.at};
  if (Y.is_finite()) return std::pair{Y.at + X.at, Y.at};
  return std::nullopt;
}

/// Steps (a)-(e) with A as the base point; the result's gamma is Undefined naming the failing
/// step. `mirrored` takes the erratum reading of step (c).
///
/// A pair's point or centre may lie at infinity (docs/mechanisms.md, "Bobillier with sliders"):
/// every line through it is then the line through the other point in its direction, and in
/// step (c) the ray PB of a point B at infinity is its direction. The theorem is projective in
/// its lines (Bobillier's angle relation compares the directions of lines through P), so it
/// holds in this limit; each finite case is unchanged.
template <class T>
BobillierConstruction<T> construct_bobillier_once(const PlanePoint<T>& A, const PlanePoint<T>& alpha,
                                                  const PlanePoint<T>& B, const PlanePoint<T>& beta, const Vec2<T>& C,
                                                  bool mirrored) {
  using namespace bobillier_detail;
  using PP = PlanePoint<T>;
  BobillierConstruction<T> r;
  const auto meet = [](const auto& l1, const auto& l2, const std::string& name) {
    if (!l1 || !l2) return PP::undefined(name, "a line through two points at infinity (the line at infinity)");
    return intersect_lines(l1->first, l1->second, l2->first, l2->second, name);
  };
  r.P = meet(line_through(alpha, A), line_through(beta, B), "P (step a)");
  r.Q_AB = meet(line_through(alpha, beta), line_through(A, B), "Q_AB (step b)");
  const auto stop = [&](const PP& why, const std::string& step) {
    r.gamma = PP::undefined("gamma", step + (why.kind == PP::Kind::AtInfinity ? " is at infinity" : ": " + why.reason));
    return r;
  };
  if (!r.P.is_finite()) return stop(r.P, "the pole P (step a)");
  if (!r.Q_AB.is_finite()) return stop(r.Q_AB, "the collineation point Q_AB (step b)");
  const Vec2<T> b = B.is_finite() ? B.at - r.P.at : B.at, q = r.Q_AB.at - r.P.at, c = C - r.P.at;
  if (is_zero_vector(c)) return stop(PP::undefined("", "C is the pole"), "step (c)");
  if (is_zero_vector(b) || is_zero_vector(q)) return stop(PP::undefined("", "B or Q_AB is the pole"), "step (c)");
  r.q_AC_direction = mirrored ? complex_mul(complex_mul(c, conj(q)), b) : complex_mul(complex_mul(c, q), conj(b));
  r.Q_AC = meet(line_through(A, PP::finite(C)), std::optional{std::pair{r.P.at, r.P.at + r.q_AC_direction}},
                "Q_AC (step d)");
  if (!r.Q_AC.is_finite()) return stop(r.Q_AC, "the point Q_AC (step d)");
  r.gamma = meet(std::optional{std::pair{r.P.at, C}}, line_through(alpha, r.Q_AC), "gamma (step e)");
  if (r.gamma.kind == PP::Kind::Undefined) r.gamma.quantity = "gamma";
  return r;
}

template <class T>
BobillierConstruction<T> construct_bobillier_once(const Vec2<T>& A, const Vec2<T>& alpha, const Vec2<T>& B,
                                                  const Vec2<T>& beta, const Vec2<T>& C, bool mirrored) {
  using PP = PlanePoint<T>;
  return construct_bobillier_once(PP::finite(A), PP::finite(alpha), PP::finite(B), PP::finite(beta), C, mirrored);
}

/// As drawn; the B/beta version when C lies on the line PA (docs/conventions.md §D). Points and
/// centres may lie at infinity (see construct_bobillier_once).
template <class T>
BobillierConstruction<T> construct_bobillier(const PlanePoint<T>& A, const PlanePoint<T>& alpha, const PlanePoint<T>& B,
                                             const PlanePoint<T>& beta, const Vec2<T>& C, bool mirrored = false) {
  // C on the ray PX: X - P, or X's direction when X is at infinity.
  const auto on_ray = [&](const BobillierConstruction<T>& r, const PlanePoint<T>& X) {
    return r.P.is_finite() && is_zero(cross(C - r.P.at, X.is_finite() ? X.at - r.P.at : X.at));
  };
  BobillierConstruction<T> r = construct_bobillier_once(A, alpha, B, beta, C, mirrored);
  if (on_ray(r, A)) {
    r = construct_bobillier_once(B, beta, A, alpha, C, mirrored);
    r.version = 'B';
    if (on_ray(r, B)) r.gamma = PlanePoint<T>::undefined("gamma", "C lies on both pole rays PA and PB (C is the pole)");
  }
  return r;
}

template <class T>
BobillierConstruction<T> construct_bobillier(const Vec2<T>& A, const Vec2<T>& alpha, const Vec2<T>& B,
                                             const Vec2<T>& beta, const Vec2<T>& C, bool mirrored = false) {
  using PP = PlanePoint<T>;
  return construct_bobillier(PP::finite(A), PP::finite(alpha), PP::finite(B), PP::finite(beta), C, mirrored);
}

}  // namespace linkproof
