// Plane vectors over any scalar type T (see core/scalar.h).
// Conventions (docs/conventions.md, Notation): a x b = a_x b_y - a_y b_x; J a = (-a_y, a_x) turns a by +90 degrees.
#pragma once

#include "linkproof/core/scalar.h"

namespace linkproof {

template <class T>
struct Vec2 {
  T x{}, y{};
};

template <class T> Vec2<T> operator+(const Vec2<T>& a, const Vec2<T>& b) { return {a.x + b.x, a.y + b.y}; }
template <class T> Vec2<T> operator-(const Vec2<T>& a, const Vec2<T>& b) { return {a.x - b.x, a.y - b.y}; }
template <class T> Vec2<T> operator-(const Vec2<T>& a) { return {-a.x, -a.y}; }
template <class T> Vec2<T> operator*(const T& s, const Vec2<T>& a) { return {s * a.x, s * a.y}; }

/// 2-D cross product a x b = a_x b_y - a_y b_x (twice the signed area of (0, a, b)).
template <class T> T cross(const Vec2<T>& a, const Vec2<T>& b) { return a.x * b.y - a.y * b.x; }
template <class T> T dot(const Vec2<T>& a, const Vec2<T>& b) { return a.x * b.x + a.y * b.y; }
template <class T> T norm2(const Vec2<T>& a) { return dot(a, a); }
/// J a: a turned by +90 degrees (counter-clockwise).
template <class T> Vec2<T> perp(const Vec2<T>& a) { return {-a.y, a.x}; }

/// Both components zero. For symbolic coordinates one zero test of |a|^2 (zero over the reals
/// iff a = 0), so that a proof records "these two points coincide", not "one coordinate is 0".
template <class T> bool is_zero_vector(const Vec2<T>& a) {
  if constexpr (requires { ScalarTraits<T>::is_symbolic; })
    return linkproof::is_zero(a.x * a.x + a.y * a.y);
  else
    return linkproof::is_zero(a.x) && linkproof::is_zero(a.y);
}

/// Converts an exact vector to scalar type T.
template <class T> Vec2<T> vec_from_rational(const Vec2<Rational>& a) {
  return {from_rational<T>(a.x), from_rational<T>(a.y)};
}

}  // namespace linkproof
