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
#include "mechanism/joint_geometry.h"
#include "mechanism/mechanism_solve.h"

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

/// The same values in a scalar type T, where the kinematics read them (a JointGeometry and the
/// inputs' rates): a configuration solved and judged without building its scene.
template <class T>
struct TopologyValuesIn {
  std::vector<Vec2<T>> joint_at, point_at, axis;  ///< per joint, per tracer point, per joint
  std::vector<InputValue<T>> inputs;
  JointGeometry<T> geometry() const { return {&joint_at, &axis}; }
};

template <class T>
TopologyValuesIn<T> topology_values_in(const MechanismScene& topology, const TopologyLayout& layout,
                                       const TopologyValues& c) {
  std::vector<Vec2<T>> groups;
  for (const Vec2<Rational>& p : c.positions) groups.push_back(vec_from_rational<T>(p));
  TopologyValuesIn<T> out;
  for (size_t j = 0; j < layout.joint_group.size(); ++j) {
    out.joint_at.push_back(groups[static_cast<size_t>(layout.joint_group[j])]);
    out.axis.push_back(topology.linkage.joint(static_cast<int>(j)).type == JointType::Prismatic
                           ? vec_from_rational<T>(c.axes[j])
                           : Vec2<T>{from_int<T>(0), from_int<T>(0)});
  }
  for (const int g : layout.point_group) out.point_at.push_back(groups[static_cast<size_t>(g)]);
  for (size_t k = 0; k < c.rate.size(); ++k) out.inputs.push_back({from_rational<T>(c.rate[k]), from_rational<T>(c.rate_dot[k])});
  return out;
}

}  // namespace linkproof
