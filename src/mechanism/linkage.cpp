#include "linkproof/mechanism/linkage.h"

#include <fmt/format.h>

#include <deque>

#include "linkproof/core/error.h"
#include "geometry/zero_vector.h"

namespace linkproof {

namespace {

// For every link, the joints touching it (adjacency of the link graph; joints are the edges).
std::vector<std::vector<int>> adjacency(int link_count, const std::vector<LinkageJoint>& joints) {
  std::vector<std::vector<int>> adj(static_cast<size_t>(link_count));
  for (size_t j = 0; j < joints.size(); ++j)
    for (int s = 0; s < 2; ++s) adj[static_cast<size_t>(joints[j].links[s])].push_back(static_cast<int>(j));
  return adj;
}

int other_link(const LinkageJoint& j, int link) { return j.links[0] == link ? j.links[1] : j.links[0]; }

}  // namespace

std::string linkage_problem(const std::vector<std::string>& link_names, int ground,
                            const std::vector<LinkageJoint>& joints) {
  const int L = static_cast<int>(link_names.size());
  if (L < 2) return fmt::format("a linkage needs at least 2 links (the ground and one more), got {}", L);
  if (ground < 0 || ground >= L) return "the ground link is not one of the links";
  for (const auto& j : joints) {
    for (int s = 0; s < 2; ++s)
      if (j.links[s] < 0 || j.links[s] >= L) return fmt::format("joint `{}` names a link that does not exist", j.name);
    if (j.links[0] == j.links[1])
      return fmt::format("joint `{}` connects link `{}` to itself: a joint needs two different links", j.name,
                         link_names[static_cast<size_t>(j.links[0])]);
    if (j.type == JointType::Prismatic && is_zero_vector(j.axis))
      return fmt::format("prismatic joint `{}` has a zero axis: the guide direction must be non-zero", j.name);
  }
  const auto adj = adjacency(L, joints);
  std::vector<bool> seen(static_cast<size_t>(L), false);
  std::deque<int> queue{ground};
  seen[static_cast<size_t>(ground)] = true;
  while (!queue.empty()) {
    const int l = queue.front();
    queue.pop_front();
    for (int j : adj[static_cast<size_t>(l)]) {
      const int o = other_link(joints[static_cast<size_t>(j)], l);
      if (!seen[static_cast<size_t>(o)]) seen[static_cast<size_t>(o)] = true, queue.push_back(o);
    }
  }
  for (int l = 0; l < L; ++l)
    if (!seen[static_cast<size_t>(l)])
      return fmt::format("link `{}` is not connected to the ground `{}` through joints",
                         link_names[static_cast<size_t>(l)], link_names[static_cast<size_t>(ground)]);
  return {};
}

Linkage::Linkage(std::vector<std::string> link_names, int ground, std::vector<LinkageJoint> joints)
    : links_(std::move(link_names)), ground_(ground), joints_(std::move(joints)) {
  LINKPROOF_ASSERT(linkage_problem(links_, ground_, joints_).empty(), linkage_problem(links_, ground_, joints_));
  const int L = link_count();
  const auto adj = adjacency(L, joints_);
  // Breadth-first spanning tree from the ground.
  std::vector<int> depth(static_cast<size_t>(L), -1);
  std::vector<bool> in_tree(joints_.size(), false);
  entry_.assign(static_cast<size_t>(L), JointCrossing{});
  depth[static_cast<size_t>(ground_)] = 0;
  order_ = {ground_};
  for (size_t head = 0; head < order_.size(); ++head) {
    const int l = order_[head];
    for (int j : adj[static_cast<size_t>(l)]) {
      const int o = other_link(joints_[static_cast<size_t>(j)], l);
      if (depth[static_cast<size_t>(o)] >= 0) continue;
      depth[static_cast<size_t>(o)] = depth[static_cast<size_t>(l)] + 1;
      entry_[static_cast<size_t>(o)] = JointCrossing{j, l, o};
      in_tree[static_cast<size_t>(j)] = true;
      order_.push_back(o);
    }
  }
  // One loop per chord a -> b: cross the chord into b, then climb the tree from b and from a to
  // their common ancestor, and come down to a.
  for (int j = 0; j < joint_count(); ++j) {
    if (in_tree[static_cast<size_t>(j)]) continue;
    const int a = joints_[static_cast<size_t>(j)].links[0], b = joints_[static_cast<size_t>(j)].links[1];
    std::vector<JointCrossing> up_from_b, up_from_a;  // crossings towards the root
    int x = b, y = a;
    while (x != y) {
      if (depth[static_cast<size_t>(x)] >= depth[static_cast<size_t>(y)]) {
        const auto& e = entry_[static_cast<size_t>(x)];
        up_from_b.push_back(JointCrossing{e.joint, x, e.from});
        x = e.from;
      } else {
        const auto& e = entry_[static_cast<size_t>(y)];
        up_from_a.push_back(e);  // crossing downwards, towards a: parent -> y
        y = e.from;
      }
    }
    LinkageLoop loop;
    loop.crossings.push_back(JointCrossing{j, a, b});
    for (const auto& c : up_from_b) loop.crossings.push_back(c);
    for (auto it = up_from_a.rbegin(); it != up_from_a.rend(); ++it) loop.crossings.push_back(*it);
    loops_.push_back(std::move(loop));
  }
  for (int l = 0; l < L; ++l) link_unknown_.push_back(l == ground_ ? -1 : unknown_count_++);
  for (const auto& j : joints_) joint_unknown_.push_back(j.type == JointType::Prismatic ? unknown_count_++ : -1);
}

std::optional<int> Linkage::find_link(const std::string& name) const {
  for (int i = 0; i < link_count(); ++i)
    if (links_[static_cast<size_t>(i)] == name) return i;
  return std::nullopt;
}

std::optional<int> Linkage::find_joint(const std::string& name) const {
  for (int i = 0; i < joint_count(); ++i)
    if (joints_[static_cast<size_t>(i)].name == name) return i;
  return std::nullopt;
}

int Linkage::prismatic_count() const {
  int k = 0;
  for (const auto& j : joints_) k += j.type == JointType::Prismatic;
  return k;
}

int Linkage::sliding_sign(const JointCrossing& c) const {
  const auto& j = joints_[static_cast<size_t>(c.joint)];
  if (j.type == JointType::Revolute) return 0;
  return c.to == j.links[1] ? 1 : -1;
}

}  // namespace linkproof
