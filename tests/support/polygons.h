// Test support: the worked examples of conventions §A8 as exact polygons.
#pragma once

#include "linkproof/geometry/polygon.h"

namespace linkproof::test {

struct Example {
  Polygon<Rational> polygon;
  InputRates<Rational> rates;
};

/// The pentagon of conventions §A8: K = (0,0),(1,4),(5,5),(7,1),(3,-2); omega = 2, -1; omega-dot = 1, 3.
inline Example spec_pentagon() {
  return {Polygon<Rational>({{0, 0}, {1, 4}, {5, 5}, {7, 1}, {3, -2}}), {{2, -1}, {1, 3}}};
}

/// The hexagon of conventions §A8: K = (0,0),(0,4),(3,6),(7,5),(8,1),(4,-2); omega = 1,-2,3; omega-dot = 1/2,-1,2.
inline Example spec_hexagon() {
  return {Polygon<Rational>({{0, 0}, {0, 4}, {3, 6}, {7, 5}, {8, 1}, {4, -2}}),
          {{1, -2, 3}, {Rational(1) / 2, -1, 2}}};
}

inline Rational q(long p, long d = 1) { return Rational(p) / Rational(d); }

}  // namespace linkproof::test
