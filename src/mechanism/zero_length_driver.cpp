#include "mechanism/zero_length_driver.h"

namespace linkproof {

std::optional<ZeroLengthDriver> zero_length_driver(const Linkage& g, const std::vector<MechanismInput>& inputs,
                                                   const std::vector<Vec2<Rational>>& joint_at) {
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const MechanismInput& in = inputs[i];
    if (in.kind != MechanismInput::Kind::Link) continue;
    std::vector<int> on_link;
    for (int j = 0; j < g.joint_count(); ++j)
      if (g.joint(j).links[0] == in.index || g.joint(j).links[1] == in.index) on_link.push_back(j);
    if (on_link.size() < 2) continue;
    const Vec2<Rational>& p = joint_at[static_cast<std::size_t>(on_link.front())];
    bool all_at_p = true;
    for (const int j : on_link) {
      const Vec2<Rational>& q = joint_at[static_cast<std::size_t>(j)];
      all_at_p = all_at_p && g.joint(j).type == JointType::Revolute && q.x == p.x && q.y == p.y;
    }
    if (all_at_p) return ZeroLengthDriver{i, on_link[0], on_link[1], p};
  }
  return std::nullopt;
}

}  // namespace linkproof
