#include "proof/topology_layout.h"

namespace linkproof {

TopologyLayout topology_layout(const MechanismScene& s) {
  TopologyLayout out;
  std::vector<Vec2<Rational>> seen;
  const auto group = [&](const Vec2<Rational>& p, const std::string& name) {
    for (size_t k = 0; k < seen.size(); ++k)
      if (seen[k].x == p.x && seen[k].y == p.y) return static_cast<int>(k);
    seen.push_back(p);
    out.group_name.push_back(name);
    return static_cast<int>(seen.size() - 1);
  };
  for (const LinkageJoint& j : s.linkage.joints()) out.joint_group.push_back(group(j.at, j.name));
  for (const MechanismPoint& p : s.points) out.point_group.push_back(group(p.at, p.name));
  return out;
}

TopologyValues TopologyDraw::exact() const {
  TopologyValues out;
  const auto vec = [](const Vec2<SmallFraction>& v) { return Vec2<Rational>{v.x.exact(), v.y.exact()}; };
  for (const auto& v : positions) out.positions.push_back(vec(v));
  for (const auto& v : axes) out.axes.push_back(vec(v));
  for (const SmallFraction& f : rate) out.rate.push_back(f.exact());
  for (const SmallFraction& f : rate_dot) out.rate_dot.push_back(f.exact());
  return out;
}

MechanismScene topology_configuration(const MechanismScene& topology, const TopologyLayout& layout,
                                      const TopologyValues& c, const std::string& name) {
  MechanismScene s;
  s.name = name;
  s.source = name + ".yaml";
  std::vector<LinkageJoint> joints = topology.linkage.joints();
  for (size_t j = 0; j < joints.size(); ++j) {
    joints[j].at = c.positions[static_cast<size_t>(layout.joint_group[j])];
    if (joints[j].type == JointType::Prismatic) joints[j].axis = c.axes[j];
  }
  s.linkage = Linkage(topology.linkage.link_names(), topology.linkage.ground(), std::move(joints));
  s.inputs = topology.inputs;
  for (size_t k = 0; k < s.inputs.size(); ++k) s.inputs[k].rate = c.rate[k], s.inputs[k].rate_dot = c.rate_dot[k];
  s.points = topology.points;
  for (size_t p = 0; p < s.points.size(); ++p) s.points[p].at = c.positions[static_cast<size_t>(layout.point_group[p])];
  return s;
}

}  // namespace linkproof
