#include "mechanism/fourbar_polygon.h"

namespace linkproof {

std::optional<FourBarRoles> identify_fourbar(const Linkage& g, const std::vector<MechanismInput>& inputs) {
  if (g.link_count() != 4 || g.joint_count() != 4 || g.prismatic_count() != 0) return std::nullopt;
  if (inputs.size() != 1 || inputs[0].kind != MechanismInput::Kind::Link) return std::nullopt;
  FourBarRoles r;
  r.frame = g.ground();
  r.crank = inputs[0].index;
  // The joint between two links, or -1.
  const auto between = [&](int a, int b) {
    for (int j = 0; j < g.joint_count(); ++j) {
      const auto& x = g.joint(j);
      if ((x.links[0] == a && x.links[1] == b) || (x.links[0] == b && x.links[1] == a)) return j;
    }
    return -1;
  };
  r.O2 = between(r.frame, r.crank);
  if (r.O2 < 0) return std::nullopt;
  for (int l = 0; l < 4; ++l) {
    if (l == r.frame || l == r.crank) continue;
    if (between(r.crank, l) >= 0) r.coupler = l;
    else r.rocker = l;
  }
  r.A = between(r.crank, r.coupler);
  r.B = between(r.coupler, r.rocker);
  r.O4 = between(r.rocker, r.frame);
  if (r.A < 0 || r.B < 0 || r.O4 < 0 || r.coupler == r.rocker) return std::nullopt;
  return r;
}

}  // namespace linkproof
