#include "symbolic/polygon_symbols.h"

#include <string>

#include "linkproof/core/error.h"

namespace linkproof {

PolygonSymbols::PolygonSymbols(int n) : n_(n) {
  LINKPROOF_ASSERT(n >= 3, "a polygon has at least 3 sides");
  for (int j = 1; j <= n; ++j) {
    const std::string s = std::to_string(j);
    theta_.emplace_back("theta_" + s, "\\theta_{" + s + "}");
    length_.emplace_back("L_" + s);
    omega_.emplace_back("omega_" + s, "\\omega_{" + s + "}");
    omega_dot_.emplace_back("omega_dot_" + s, "\\dot\\omega_{" + s + "}");
    omega_ddot_.emplace_back("omega_ddot_" + s, "\\ddot\\omega_{" + s + "}");
    x_.emplace_back("x_" + s);
    y_.emplace_back("y_" + s);
  }
}

size_t PolygonSymbols::idx(int j) const {
  LINKPROOF_ASSERT(j >= 1 && j <= n_, "side index out of range");
  return static_cast<size_t>(j - 1);
}

}  // namespace linkproof
