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

/// A small fraction p/d (d > 0), as random configurations draw their values: converted to any
/// scalar type without exact arithmetic where the type allows (from_fraction, core/scalar.h).
struct SmallFraction {
  long p = 0, d = 1;
  Rational exact() const { return Rational(p) / Rational(d); }
};

/// The values of one drawn configuration as small fractions, in the layout's order.
struct TopologyDraw {
  std::vector<Vec2<SmallFraction>> positions, axes;
  std::vector<SmallFraction> rate, rate_dot;
  TopologyValues exact() const;
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
                                       const TopologyDraw& c) {
  const auto in_t = [](const SmallFraction& f) { return from_fraction<T>(f.p, f.d); };
  const auto vec_in_t = [&](const Vec2<SmallFraction>& v) { return Vec2<T>{in_t(v.x), in_t(v.y)}; };
  std::vector<Vec2<T>> groups;
  groups.reserve(c.positions.size());
  for (const Vec2<SmallFraction>& p : c.positions) groups.push_back(vec_in_t(p));
  TopologyValuesIn<T> out;
  out.joint_at.reserve(layout.joint_group.size());
  out.axis.reserve(layout.joint_group.size());
  for (size_t j = 0; j < layout.joint_group.size(); ++j) {
    out.joint_at.push_back(groups[static_cast<size_t>(layout.joint_group[j])]);
    out.axis.push_back(topology.linkage.joint(static_cast<int>(j)).type == JointType::Prismatic
                           ? vec_in_t(c.axes[j])
                           : Vec2<T>{from_int<T>(0), from_int<T>(0)});
  }
  for (const int g : layout.point_group) out.point_at.push_back(groups[static_cast<size_t>(g)]);
  for (size_t k = 0; k < c.rate.size(); ++k) out.inputs.push_back({in_t(c.rate[k]), in_t(c.rate_dot[k])});
  return out;
}

}  // namespace linkproof
