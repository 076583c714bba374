// The three elementary steps of the paper's graphic construction (Dijksman 1966, sec. 2;
// docs/conventions.md §A3), each written once, generic over the scalar type T:
//   intersect_lines     the point where two lines meet (Q_j, P'_j, P_j)
//   directed_ratio      XA / XB of directed segments on one line (i_{n-1,j}, i_{n-2,j})
//   cot_signed_angle    cot of the signed angle at a vertex (beta_j, gamma_j)
// Each writes its result and returns a StepStatus: no exception, no string, no allocation (the
// hot path of the construction route, numerics/routes.h). The `require_...` functions turn a
// status into an UndefinedQuantity that names the quantity and why (docs/conventions.md §A6);
// they take callables for the names, so that strings are made only when a quantity is
// undefined. compute_directed_ratio is the throwing form of directed_ratio.
// Every step tests its divisors with linkproof::is_zero: exactly for exact and symbolic T (for
// symbolic T each test is recorded as a place where the result may fail, core/symbolic_scalar.h),
// and "exactly zero" for floating-point T.
#pragma once

#include <string>

#include "core/scalar.h"
#include "linkproof/core/error.h"
#include "linkproof/geometry/vec2.h"
#include "geometry/zero_vector.h"

namespace linkproof {

/// Outcome of one construction step.
enum class StepStatus : unsigned char {
  defined,          ///< the result exists and was written
  null_direction,   ///< a line or a ray is spanned by two coincident points
  degenerate,       ///< parallel lines (point at infinity), a zero-length reference segment,
                    ///< or collinear rays (angle 0 or pi)
  pivots_coincide,  ///< K'_j = K_n: the ground line of four-bar j is undefined (docs/conventions.md §A6)
  not_reached,      ///< not run: an input of the step is itself undefined
};

/// Intersection x of line(p, p + u) and line(q, q + v):
///   x = p + t u,  t = ((q - p) x v) / (u x v).
/// null_direction if u or v is null; degenerate if the lines are parallel (x at infinity).
template <class T>
StepStatus intersect_lines(const Vec2<T>& p, const Vec2<T>& u, const Vec2<T>& q, const Vec2<T>& v, Vec2<T>& x) {
  if (is_zero_vector(u) || is_zero_vector(v)) return StepStatus::null_direction;
  const T den = cross(u, v);
  if (linkproof::is_zero(den)) return StepStatus::degenerate;
  const T t = cross(q - p, v) / den;
  x = p + t * u;
  return StepStatus::defined;
}

/// Directed ratio XA / XB of segments on one line through X (A, B collinear with X):
///   r = ((A - X) . (B - X)) / |B - X|^2,
/// positive iff A and B lie on the same side of X. degenerate if B = X.
template <class T>
StepStatus directed_ratio(const Vec2<T>& x, const Vec2<T>& a, const Vec2<T>& b, T& r) {
  const Vec2<T> xb = b - x;
  const T den = norm2(xb);
  if (linkproof::is_zero(den)) return StepStatus::degenerate;
  r = dot(a - x, xb) / den;
  return StepStatus::defined;
}

/// cot of the signed angle at a vertex V between the rays VA and VB: c = (VA . VB) / (VA x VB).
/// The angle is positive iff VA x VB > 0, i.e. iff the triangle B -> V -> A is counter-clockwise.
/// null_direction if a ray is null; degenerate if the rays are collinear (cot infinite).
template <class T>
StepStatus cot_signed_angle(const Vec2<T>& va, const Vec2<T>& vb, T& c) {
  if (is_zero_vector(va) || is_zero_vector(vb)) return StepStatus::null_direction;
  const T s = cross(va, vb);
  if (linkproof::is_zero(s)) return StepStatus::degenerate;
  c = dot(va, vb) / s;
  return StepStatus::defined;
}

/// Throws UndefinedQuantity(name(), why) unless an intersection step is defined; lines() names
/// the two lines, e.g. "K_{n-1}K_n and K'_1K_{n-2}".
template <class NameFn, class LinesFn>
void require_intersection(StepStatus s, const NameFn& name, const LinesFn& lines) {
  if (s == StepStatus::defined) return;
  if (s == StepStatus::null_direction)
    throw UndefinedQuantity(name(), "a line through " + lines() + " has coincident points");
  if (s == StepStatus::degenerate)
    throw UndefinedQuantity(name(), "lines " + lines() + " are parallel: the point is at infinity");
  throw InternalError("require_intersection: " + name() + " was not constructed");
}

/// Throws UndefinedQuantity(name(), why) unless a directed-ratio step is defined.
template <class NameFn>
void require_ratio(StepStatus s, const NameFn& name) {
  if (s == StepStatus::defined) return;
  if (s == StepStatus::degenerate) throw UndefinedQuantity(name(), "the reference segment has zero length");
  throw InternalError("require_ratio: " + name() + " was not computed");
}

/// Throws UndefinedQuantity(name(), why) unless a signed-angle step is defined; rays() names
/// the two rays, e.g. "rays Q_1K_{n-1} and Q_1P'_1".
template <class NameFn, class RaysFn>
void require_angle(StepStatus s, const NameFn& name, const RaysFn& rays) {
  if (s == StepStatus::defined) return;
  if (s == StepStatus::null_direction)
    throw UndefinedQuantity(name(), "a ray of " + rays() + " is null (its end coincides with the vertex)");
  if (s == StepStatus::degenerate)
    throw UndefinedQuantity(name(), rays() + " are collinear: the angle is 0 or pi, its cotangent infinite");
  throw InternalError("require_angle: " + name() + " was not computed");
}

/// directed_ratio, throwing UndefinedQuantity(name(), ...) if B = X.
template <class T, class NameFn>
T compute_directed_ratio_lazy(const Vec2<T>& x, const Vec2<T>& a, const Vec2<T>& b, const NameFn& name) {
  T r{};
  require_ratio(directed_ratio(x, a, b, r), name);
  return r;
}

template <class T>
T compute_directed_ratio(const Vec2<T>& x, const Vec2<T>& a, const Vec2<T>& b, const std::string& name) {
  return compute_directed_ratio_lazy(x, a, b, [&] { return name; });
}

}  // namespace linkproof
