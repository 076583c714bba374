#include "mechanism/sub_mechanism.h"

#include <algorithm>
#include <functional>

#include "mechanism/mechanism_solve.h"
#include "mechanism/mechanism_vector_route.h"

namespace linkproof {

bool inputs_fix_motion(const Linkage& g, const std::vector<MechanismInput>& inputs) {
  const int N = g.unknown_count();
  DenseMatrix<Rational> A = rigid_body_constraint_matrix<Rational>(g);
  const int rank = solve_linear_system<Rational>(A, std::vector<Rational>(A.size(), Rational(0))).rank;
  if (N - rank != static_cast<int>(inputs.size())) return false;
  std::vector<Rational> b(A.size(), Rational(0));
  append_input_rows(g, inputs, A, b, false, "");
  return solve_linear_system<Rational>(A, b).rank == N;
}

namespace {

// The links an input needs: its link, or both links of its prismatic joint.
void add_input_links(const Linkage& g, const MechanismInput& in, std::vector<bool>& keep) {
  if (in.kind == MechanismInput::Kind::Link) {
    keep[static_cast<size_t>(in.index)] = true;
  } else {
    keep[static_cast<size_t>(g.joint(in.index).links[0])] = true;
    keep[static_cast<size_t>(g.joint(in.index).links[1])] = true;
  }
}

bool connected_to_ground(const Linkage& g, const std::vector<bool>& keep) {
  std::vector<bool> seen(keep.size(), false);
  std::vector<int> stack{g.ground()};
  seen[static_cast<size_t>(g.ground())] = true;
  while (!stack.empty()) {
    const int l = stack.back();
    stack.pop_back();
    for (const LinkageJoint& j : g.joints())
      for (int side = 0; side < 2; ++side) {
        const int a = j.links[side], b = j.links[1 - side];
        if (a != l || !keep[static_cast<size_t>(b)] || seen[static_cast<size_t>(b)]) continue;
        seen[static_cast<size_t>(b)] = true;
        stack.push_back(b);
      }
  }
  for (size_t l = 0; l < keep.size(); ++l)
    if (keep[l] && !seen[l]) return false;
  return true;
}

// X connected through joints between its own links.
bool connected_set(const Linkage& g, const std::vector<int>& x) {
  std::vector<int> reached{x.front()};
  for (size_t k = 0; k < reached.size(); ++k)
    for (const LinkageJoint& j : g.joints())
      for (int side = 0; side < 2; ++side) {
        const int a = j.links[side], b = j.links[1 - side];
        if (a != reached[k] || std::find(x.begin(), x.end(), b) == x.end()) continue;
        if (std::find(reached.begin(), reached.end(), b) == reached.end()) reached.push_back(b);
      }
  return reached.size() == x.size();
}

}  // namespace

SubMechanism restrict_mechanism(const MechanismScene& s, std::vector<int> keep_links) {
  const Linkage& g = s.linkage;
  std::sort(keep_links.begin(), keep_links.end());
  std::vector<int> link_at(static_cast<size_t>(g.link_count()), -1), joint_at(static_cast<size_t>(g.joint_count()), -1);
  SubMechanism sub;
  std::vector<std::string> names;
  for (int l : keep_links) {
    link_at[static_cast<size_t>(l)] = static_cast<int>(names.size());
    names.push_back(g.link_name(l));
  }
  sub.kept_links = keep_links;
  std::vector<LinkageJoint> joints;
  for (int j = 0; j < g.joint_count(); ++j) {
    LinkageJoint joint = g.joint(j);
    if (link_at[static_cast<size_t>(joint.links[0])] < 0 || link_at[static_cast<size_t>(joint.links[1])] < 0) continue;
    joint.links[0] = link_at[static_cast<size_t>(joint.links[0])];
    joint.links[1] = link_at[static_cast<size_t>(joint.links[1])];
    joint_at[static_cast<size_t>(j)] = static_cast<int>(joints.size());
    sub.kept_joints.push_back(j);
    joints.push_back(std::move(joint));
  }
  MechanismScene& r = sub.scene;
  r.name = s.name;
  r.source = s.source;
  r.linkage = Linkage(std::move(names), link_at[static_cast<size_t>(g.ground())], std::move(joints));
  for (MechanismInput in : s.inputs) {
    in.index = (in.kind == MechanismInput::Kind::Link ? link_at : joint_at)[static_cast<size_t>(in.index)];
    LINKPROOF_ASSERT(in.index >= 0, "restrict_mechanism: an input's link or joint is left out");
    r.inputs.push_back(in);
  }
  for (MechanismPoint p : s.points)
    if ((p.link = link_at[static_cast<size_t>(p.link)]) >= 0) r.points.push_back(p);
  for (LinkDimension d : s.dimensions) {
    d.joint_a = joint_at[static_cast<size_t>(d.joint_a)], d.joint_b = joint_at[static_cast<size_t>(d.joint_b)];
    if (d.joint_a >= 0 && d.joint_b >= 0) r.dimensions.push_back(d);
  }
  r.tolerance = s.tolerance;
  r.catalogues = s.catalogues;
  for (CurvatureRequest c : s.curvature) {
    c.moving = link_at[static_cast<size_t>(c.moving)], c.fixed = link_at[static_cast<size_t>(c.fixed)];
    if (c.moving >= 0 && c.fixed >= 0) r.curvature.push_back(c);
  }
  for (JointJoiningRequest q : s.joint_joining) {
    q.link = link_at[static_cast<size_t>(q.link)];
    for (int& b : q.bars) b = link_at[static_cast<size_t>(b)];
    if (q.link >= 0 && q.bars[0] >= 0 && q.bars[1] >= 0) r.joint_joining.push_back(q);
  }
  r.dimension_residual = s.dimension_residual;
  // Read by name (joints) and by input index (rates, every input is kept): the bound of a
  // rationalised scene (mechanism/dimensioned_bound.h) needs it on the part solved too.
  r.placement = s.placement;
  return sub;
}

SubMechanism determined_sub_mechanism(const MechanismScene& s, const std::vector<int>& required) {
  const Linkage& g = s.linkage;
  const size_t L = static_cast<size_t>(g.link_count());
  std::vector<bool> fixed(L, false), keep(L, true);
  fixed[static_cast<size_t>(g.ground())] = true;
  for (int l : required) fixed[static_cast<size_t>(l)] = true;
  for (const MechanismInput& in : s.inputs) add_input_links(g, in, fixed);

  const auto kept_indices = [&] {
    std::vector<int> out;
    for (size_t l = 0; l < L; ++l)
      if (keep[l]) out.push_back(static_cast<int>(l));
    return out;
  };
  // Tries to leave out one group of `size` links among the free kept ones; true if it did.
  const auto leave_out_one = [&](int size) {
    std::vector<int> free;
    for (size_t l = 0; l < L; ++l)
      if (keep[l] && !fixed[l]) free.push_back(static_cast<int>(l));
    if (static_cast<int>(free.size()) < size) return false;
    std::vector<int> x;
    const std::function<bool(size_t)> choose = [&](size_t from) -> bool {
      if (static_cast<int>(x.size()) == size) {
        int touching = 0;
        for (const LinkageJoint& j : g.joints()) {
          const bool a = std::find(x.begin(), x.end(), j.links[0]) != x.end();
          const bool b = std::find(x.begin(), x.end(), j.links[1]) != x.end();
          touching += (a || b) && keep[static_cast<size_t>(j.links[0])] && keep[static_cast<size_t>(j.links[1])];
        }
        if (3 * size != 2 * touching || !connected_set(g, x)) return false;
        for (int l : x) keep[static_cast<size_t>(l)] = false;
        if (connected_to_ground(g, keep)) {
          const SubMechanism rest = restrict_mechanism(s, kept_indices());
          if (inputs_fix_motion(rest.scene.linkage, rest.scene.inputs)) return true;
        }
        for (int l : x) keep[static_cast<size_t>(l)] = true;
        return false;
      }
      for (size_t k = from; k < free.size(); ++k) {
        x.push_back(free[k]);
        if (choose(k + 1)) return true;
        x.pop_back();
      }
      return false;
    };
    return choose(0);
  };
  for (bool progress = true; progress;) {
    progress = false;
    for (int size = 2; size <= kMaxGroupLinks && !progress; size += 2) progress = leave_out_one(size);
  }
  return restrict_mechanism(s, kept_indices());
}

}  // namespace linkproof
