// Consumer of the installed package: computes the pentagon of conventions §A8 exactly through the public
// API and checks omega-dot of side 4 against the known answer 3755/1331.
// Exit code 0 iff it matches.
#include <iostream>

#include "linkproof/geometry/polygon.h"

int main() {
  linkproof::Polygon<linkproof::Rational> p({{0, 0}, {1, 4}, {5, 5}, {7, 1}, {3, -2}});
  linkproof::InputRates<linkproof::Rational> in{{2, -1}, {1, 3}};
  const auto m = linkproof::exact_polygon_motion(p, in);

  const linkproof::Rational expected = linkproof::Rational(3755) / 1331;
  const linkproof::Rational& got = m.omega_dot[3];
  std::cout << "omega_dot_4 = " << linkproof::format_rational(got)
            << " (expected " << linkproof::format_rational(expected) << ")\n";
  if (got != expected) {
    std::cout << "FAIL: the installed linkproof computes a wrong omega_dot_4\n";
    return 1;
  }
  std::cout << "OK: find_package(linkproof) consumer\n";
  return 0;
}
