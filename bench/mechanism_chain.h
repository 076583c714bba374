// A chain of four-bar loops for the mechanism benchmarks (mechanism_bench.cpp,
// proof_scale_bench.cpp): a four-bar, then dyads pinned to earlier links, one loop each.
#pragma once

#include <random>
#include <string>
#include <utility>
#include <vector>

#include "linkproof/mechanism/mechanism_scene.h"

namespace linkproof {

// A four-bar, then dyads (two new links, three joints) each pinned to two random earlier links:
// mobility stays 1. Coordinates are random rationals (fixed seed), so the chain is generic.
inline MechanismScene random_chain(int links, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> c(-50, 50);
  const auto point = [&] { return Vec2<Rational>{Rational(c(rng)) / 7, Rational(c(rng)) / 7}; };
  std::vector<std::string> names;
  for (int l = 0; l < links; ++l) names.push_back(std::to_string(l));
  std::vector<LinkageJoint> joints;
  const auto add = [&](int a, int b) {
    std::string name = "J";  // appended, not "J" + string: GCC 12 warns falsely on that (-Wstringop-overflow)
    name += std::to_string(joints.size());
    joints.push_back({std::move(name), JointType::Revolute, {a, b}, point(), {}});
  };
  add(0, 1), add(1, 2), add(2, 3), add(3, 0);
  for (int p = 4; p + 1 < links; p += 2) {
    std::uniform_int_distribution<int> earlier(0, p - 1);
    const int e1 = earlier(rng);
    int e2 = earlier(rng);
    while (e2 == e1) e2 = earlier(rng);
    add(e1, p), add(p, p + 1), add(p + 1, e2);
  }
  MechanismScene s;
  s.name = "chain";
  s.source = "chain";
  s.linkage = Linkage(names, 0, joints);
  s.inputs = {MechanismInput{MechanismInput::Kind::Link, 1, Rational(1), Rational(1) / 2}};
  return s;
}

/// The links of a random_chain with `loops` independent loops (a four-bar, then one dyad per loop).
inline int chain_links_for_loops(int loops) { return 2 * loops + 2; }

}  // namespace linkproof
