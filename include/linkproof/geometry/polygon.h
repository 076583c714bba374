// The closed n-side polygon of Dijksman (1966), docs/conventions.md §A1.
//
// Joints K_1..K_n; side r_j = K_{j+1} - K_j (K_{n+1} = K_1), so sum r_j = 0 (eq. 1). K_j is the
// start of r_j; side n (K_n -> K_1) is fixed. Indices in this API are the paper's, 1-based.
// Inputs are omega_{j,n} and omega-dot_{j,n} for j = 1..n-3.
#pragma once

#include <string>
#include <vector>

#include "linkproof/geometry/vec2.h"

namespace linkproof {

template <class T>
class Polygon {
 public:
  Polygon() = default;
  explicit Polygon(std::vector<Vec2<T>> joints) : joints_(std::move(joints)) {}

  int n() const { return static_cast<int>(joints_.size()); }
  /// K_j, j = 1..n (K_{n+1} = K_1).
  const Vec2<T>& joint(int j) const { return joints_[static_cast<size_t>((j - 1) % n())]; }
  /// r_j = K_{j+1} - K_j, j = 1..n.
  Vec2<T> side(int j) const { return joint(j + 1) - joint(j); }
  const std::vector<Vec2<T>>& joints() const { return joints_; }

  /// D = r_{n-2} x r_{n-1}; the mechanism's dead centre is D = 0 (docs/conventions.md §A2).
  T dead_centre_determinant() const { return cross(side(n() - 2), side(n() - 1)); }

  template <class U>
  Polygon<U> convert() const {
    std::vector<Vec2<U>> out;
    out.reserve(joints_.size());
    for (const auto& k : joints_) out.push_back(vec_from_rational<U>(k));
    return Polygon<U>(std::move(out));
  }

 private:
  std::vector<Vec2<T>> joints_;
};

/// The state of the n-3 input sides: omega_{j,n} and omega-dot_{j,n}, j = 1..n-3
/// (stored 0-based: omega[0] is omega_{1,n}).
template <class T>
struct InputRates {
  std::vector<T> omega, omega_dot;

  template <class U>
  InputRates<U> convert() const {
    InputRates<U> out;
    for (const auto& w : omega) out.omega.push_back(from_rational<U>(w));
    for (const auto& a : omega_dot) out.omega_dot.push_back(from_rational<U>(a));
    return out;
  }
};

/// omega and omega-dot of every side relative to side n, 0-based (omega[j-1] = omega_{j,n};
/// entry n-1 is side n itself, always 0).
template <class T>
struct PolygonMotion {
  std::vector<T> omega, omega_dot;
};

/// The exact motion of a polygon: omega_{j,n} and omega-dot_{j,n} of every side j = 1..n, from
/// the loop closure differentiated twice (linkproof's ground truth; the rates of the input sides
/// are `rates`'). Throws InputError for a polygon that polygon_input_problem refuses, for rates
/// of the wrong length, and at the dead centre D = r_{n-2} x r_{n-1} = 0 (no motion exists).
/// GiNaC underneath: call it from one thread at a time.
PolygonMotion<Rational> exact_polygon_motion(const Polygon<Rational>& polygon, const InputRates<Rational>& rates);

/// Checks an exact polygon for what makes it unusable as input (n < 4, coincident joints,
/// hence zero-length sides). Returns an empty string if valid, otherwise the problem, naming
/// the joints by the paper's indices.
std::string polygon_input_problem(const Polygon<Rational>& p);

}  // namespace linkproof
