// The free coordinates of a mechanism scene's topology: what a configuration of it draws afresh
// (proof/mechanism_sampling.h) or makes a symbol (proof/mechanism_proof.h).
//
// A configuration keeps the scene's links, joints, inputs and tracer points, and which joints
// and points coincide: one position per group of coincident joints and points (a slider at its
// pin, a tracer point on a joint), one axis per prismatic joint, a rate and its derivative per
// input.
#pragma once

#include <string>
#include <vector>

#include "linkproof/mechanism/mechanism_scene.h"

namespace linkproof {

struct TopologyLayout {
  std::vector<int> joint_group, point_group;  ///< group of each joint, of each tracer point
  std::vector<std::string> group_name;        ///< the first joint or point of each group, as written
  int groups() const { return static_cast<int>(group_name.size()); }
};

TopologyLayout topology_layout(const MechanismScene& scene);

/// The values of one configuration, in the layout's order.
struct TopologyValues {
  std::vector<Vec2<Rational>> positions;  ///< per group
  std::vector<Vec2<Rational>> axes;       ///< per joint (revolute: unused)
  std::vector<Rational> rate, rate_dot;   ///< per input
};

/// The scene of `topology` at these values, named `name` (source `name`.yaml).
MechanismScene topology_configuration(const MechanismScene& topology, const TopologyLayout& layout,
                                      const TopologyValues& values, const std::string& name);

}  // namespace linkproof
