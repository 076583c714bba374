#include "mechanism/joint_joining.h"

#include <fmt/format.h>

#include "mechanism/curvature.h"
#include "mechanism/mechanism_vector_route.h"

namespace linkproof {

std::string bar_problem(const Linkage& g, int t, int bar) {
  std::vector<int> js;
  for (int j = 0; j < g.joint_count(); ++j)
    if (g.joint(j).links[0] == bar || g.joint(j).links[1] == bar) js.push_back(j);
  const std::string name = g.link_name(bar);
  if (bar == t) return fmt::format("link `{}` cannot be a bar of itself", name);
  if (js.size() != 2) return fmt::format("link `{}` is not a bar: it has {} joints (a bar has 2)", name, js.size());
  int on_t = 0;
  for (int j : js) {
    if (g.joint(j).type != JointType::Revolute) return fmt::format("bar `{}` has a prismatic joint `{}`", name, g.joint(j).name);
    if (g.joint(j).links[0] == t || g.joint(j).links[1] == t) ++on_t;
  }
  if (on_t != 1)
    return fmt::format("bar `{}` must have exactly one joint on link `{}` (it has {})", name, g.link_name(t), on_t);
  // The ground does not move: taken as a bar, the reduction would move its ends, and a true
  // claim about the reduced mechanism would fail. It is refused as the driver bar is.
  if (bar == g.ground()) return fmt::format("link `{}` is the ground: the ground cannot be a joined bar", name);
  return {};
}

BarEnds bar_ends(const Linkage& g, int t, int bar) {
  BarEnds e;
  for (int j = 0; j < g.joint_count(); ++j) {
    const LinkageJoint& J = g.joint(j);
    if (J.links[0] != bar && J.links[1] != bar) continue;
    const int other = J.links[0] == bar ? J.links[1] : J.links[0];
    if (other == t) e.near_joint = j;
    else e.far_joint = j, e.far_link = other;
  }
  return e;
}

Linkage move_bar(const Linkage& g, const BarEnds& ends, const Vec2<Rational>& K, const Vec2<Rational>& F) {
  std::vector<LinkageJoint> joints = g.joints();
  joints[static_cast<size_t>(ends.near_joint)].at = K;
  joints[static_cast<size_t>(ends.far_joint)].at = F;
  return Linkage(g.link_names(), g.ground(), std::move(joints));
}

MechanismSolution<Rational> solve_rigid_body(const Linkage& g, const std::vector<MechanismInput>& inputs,
                                             const std::string& source) {
  return solve_mechanism<Rational>(
      g, inputs, rigid_body_constraint_matrix<Rational>(g),
      [&](const std::vector<Rational>& qd) { return rigid_body_acceleration_rhs<Rational>(g, qd); }, source);
}

JointJoiningStep join_joints(const Linkage& g, const MechanismMotion<Rational>& motion, const JointJoiningRequest& r) {
  JointJoiningStep s;
  const std::string t = g.link_name(r.link);
  for (int b = 0; b < 2; ++b) {
    if (std::string p = bar_problem(g, r.link, r.bars[b]); !p.empty()) {
      s.problem = p;
      return s;
    }
    s.ends[b] = bar_ends(g, r.link, r.bars[b]);
  }
  const auto at = [&](int joint) { return g.joint(joint).at; };
  s.I = intersect_lines(at(s.ends[0].near_joint), at(s.ends[0].far_joint), at(s.ends[1].near_joint),
                        at(s.ends[1].far_joint), fmt::format("I (bar lines of {} and {})", g.link_name(r.bars[0]),
                                                             g.link_name(r.bars[1])));
  if (!s.I.is_finite()) {
    s.problem = s.I.kind == PlanePoint<Rational>::Kind::AtInfinity ? "the bar lines are parallel: I is at infinity"
                                                                    : "I is undefined: " + s.I.reason;
    return s;
  }
  const auto& fields = motion.fields;
  std::vector<LinkageJoint> joints = g.joints();
  for (int b = 0; b < 2; ++b) {
    const BarEnds& e = s.ends[b];
    const auto& ft = fields[static_cast<size_t>(r.link)];
    const auto& fx = fields[static_cast<size_t>(e.far_link)];
    const std::string bar = g.link_name(r.bars[b]);
    s.pole[b] = construct_pole(ft, fx, fmt::format("P_{},{}", t, g.link_name(e.far_link)));
    s.centre_of_I[b] = construct_curvature_centre(s.I.at, relative_point_motion(ft, fx, s.I.at),
                                                  fmt::format("centre of I in {}/{}", t, g.link_name(e.far_link)));
    if (r.order == 1) {
      s.new_far[b] = PlanePoint<Rational>::finite(at(e.far_joint));
    } else if (!s.pole[b].is_finite()) {
      s.new_far[b] = PlanePoint<Rational>::undefined("new far joint of " + bar, "the pole is not a finite point");
    } else {
      s.new_far[b] = relocate_far_joint(s.pole[b].at, at(e.near_joint), at(e.far_joint), s.I.at,
                                        "new far joint of " + bar);
    }
    if (!s.new_far[b].is_finite()) {
      s.problem = fmt::format("bar {}: {}", bar,
                              s.new_far[b].kind == PlanePoint<Rational>::Kind::AtInfinity
                                  ? "the relocated far joint is at infinity (the bar would become a slider)"
                                  : s.new_far[b].reason);
      return s;
    }
    joints[static_cast<size_t>(e.near_joint)].at = s.I.at;
    joints[static_cast<size_t>(e.far_joint)].at = s.new_far[b].at;
  }
  s.reduced = Linkage(g.link_names(), g.ground(), std::move(joints));
  return s;
}

}  // namespace linkproof
