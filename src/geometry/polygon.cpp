#include "linkproof/geometry/polygon.h"

#include <fmt/format.h>

namespace linkproof {

std::string polygon_input_problem(const Polygon<Rational>& p) {
  const int n = p.n();
  if (n < 4) return fmt::format("a polygon needs at least 4 joints (n >= 4), got {}", n);
  for (int a = 1; a <= n; ++a) {
    for (int b = a + 1; b <= n; ++b) {
      if (p.joint(a).x == p.joint(b).x && p.joint(a).y == p.joint(b).y) {
        const bool adjacent = b == a + 1 || (a == 1 && b == n);
        return fmt::format("joints K_{} and K_{} coincide at ({}, {}){}", a, b,
                           format_rational(p.joint(a).x), format_rational(p.joint(a).y),
                           adjacent ? fmt::format(": side r_{} has zero length", b == a + 1 ? a : n)
                                    : std::string());
      }
    }
  }
  return {};
}

}  // namespace linkproof
