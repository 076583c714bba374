// Helpers for the mechanism tests: building linkages from a topology and solving them.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <cln/real.h>

#include <type_traits>
#include <variant>

#include "core/scalar.h"
#include "linkproof/core/result_number.h"
#include "mechanism/mechanism_catalogue.h"

namespace linkproof::testing {

inline std::string mechanism_scene_path(const std::string& name) {
  return std::string(LINKPROOF_SOURCE_DIR) + "/verify/scenes/mechanisms/" + name;
}

/// A revolute-only topology: link names, the ground, and joints as pairs of link indices.
struct Topology {
  std::string name;
  std::vector<std::string> links;
  int ground = 0;
  std::vector<std::pair<int, int>> joints;
  int input = 1;  ///< a link adjacent to the ground
};

inline MechanismScene make_scene(const Topology& t, const std::vector<Vec2<Rational>>& at, const Rational& w,
                                 const Rational& wd) {
  std::vector<LinkageJoint> joints;
  for (size_t j = 0; j < t.joints.size(); ++j) {
    LinkageJoint x;
    x.name = "J" + std::to_string(j);
    x.links[0] = t.joints[j].first, x.links[1] = t.joints[j].second;
    x.at = at[j];
    joints.push_back(x);
  }
  MechanismScene s;
  s.name = t.name;
  s.source = t.name;
  s.linkage = Linkage(t.links, t.ground, std::move(joints));
  s.inputs = {MechanismInput{MechanismInput::Kind::Link, t.input, w, wd}};
  return s;
}

/// The exact rational value of a result: the rational itself, or a float's (midpoint's) value.
inline Rational exact_value_of_result(const ResultNumber& x) {
  return std::visit(
      [](const auto& v) -> Rational {
        using V = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<V, Rational>) return v;
        else if constexpr (std::is_same_v<V, cln::cl_F>) return cln::rational(v);
        else return exact_value_of(v);
      },
      x);
}

}  // namespace linkproof::testing
