// Plane vectors over any scalar type T (double, long double, exact Rational, ...).
// Conventions (docs/conventions.md, Notation): a x b = a_x b_y - a_y b_x; J a = (-a_y, a_x) turns a by +90 degrees.
#pragma once

#include "linkproof/core/exact.h"

namespace linkproof {

/// The conversion of an exact value to scalar type T (defined with the scalar traits inside the
/// library; instantiated there for double, long double and Rational).
template <class T>
T from_rational(const Rational& q);

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

/// Converts an exact vector to scalar type T.
template <class T> Vec2<T> vec_from_rational(const Vec2<Rational>& a) {
  return {from_rational<T>(a.x), from_rational<T>(a.y)};
}

}  // namespace linkproof
