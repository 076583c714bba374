// Random rational four-bars and eight-bars for the second-order property tests (RapidCheck).
#pragma once

#include <rapidcheck.h>

#include "mechanism/joint_joining.h"
#include "mechanism/mechanism_catalogue.h"
#include "mechanism/mechanism_test_support.h"

namespace linkproof::testing {

/// A rational in [-range, range] with denominator 1..4.
inline rc::Gen<Rational> small_rational(int range) {
  return rc::gen::mapcat(rc::gen::inRange(1, 5), [range](int d) {
    return rc::gen::map(rc::gen::inRange(-range * d, range * d + 1), [d](int n) { return Rational(n) / Rational(d); });
  });
}

inline rc::Gen<Vec2<Rational>> small_point(int range) {
  return rc::gen::map(rc::gen::pair(small_rational(range), small_rational(range)),
                      [](const std::pair<Rational, Rational>& p) { return Vec2<Rational>{p.first, p.second}; });
}

/// Four-bar O2 A B O4: links "1" (ground), "2" crank, "3" coupler, "4" rocker.
inline Topology fourbar_topology() { return {"fourbar", {"1", "2", "3", "4"}, 0, {{0, 1}, {1, 2}, {2, 3}, {3, 0}}, 1}; }

/// Dijksman's (1984) eight-bar: links "0".."7" (ground 0), joints 01 12 23 34 45 56 67 70 26 04,
/// driven by link 4.
inline Topology eightbar_topology() {
  return {"eightbar", {"0", "1", "2", "3", "4", "5", "6", "7"}, 0,
          {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 6}, {6, 7}, {7, 0}, {2, 6}, {0, 4}}, 4};
}

/// A random scene of topology t: joint positions in [-10, 10]^2, input rates in [-3, 3].
inline MechanismScene random_scene(const Topology& t) {
  std::vector<Vec2<Rational>> at;
  for (size_t j = 0; j < t.joints.size(); ++j) at.push_back(*small_point(10));
  const Rational w = *small_rational(3), wd = *small_rational(3);
  RC_PRE(!cln::zerop(w));
  return make_scene(t, at, w, wd);
}

/// The exact solution of a random scene (the rigid-body route: exact and faster than the GiNaC
/// closure; the two agree by mechanism.routes_agree); discards singular draws (locked, dead centre).
inline MechanismSolution<Rational> solve_or_discard(const MechanismScene& s) {
  MechanismSolution<Rational> truth;
  try {
    truth = solve_rigid_body(s.linkage, s.inputs, s.source);
  } catch (const InputError&) {
    RC_DISCARD("a singular random configuration");
  }
  RC_PRE(truth.mobility == 1);
  return truth;
}

}  // namespace linkproof::testing
