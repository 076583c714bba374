#include "mechanism/dijksman_compound.h"

#include <fmt/format.h>

#include <algorithm>

namespace linkproof {

std::string dijksman_compound_problem(const Linkage& g, const std::vector<MechanismInput>& inputs) {
  if (g.prismatic_count() > 0) return "the linkage has prismatic pairs (Dijksman's polygons have revolute joints only)";
  if (inputs.size() != 1 || inputs[0].kind != MechanismInput::Kind::Link)
    return "Dijksman's compound method needs exactly one link input";
  for (const LinkageLoop& loop : g.loops()) {
    if (loop.crossings.size() < 4) return fmt::format("a loop has {} sides: polygons need n >= 4", loop.crossings.size());
    std::vector<int> links;
    for (const auto& c : loop.crossings) links.push_back(c.to);
    std::sort(links.begin(), links.end());
    if (std::adjacent_find(links.begin(), links.end()) != links.end()) return "a loop passes a link twice";
  }
  return {};
}

std::vector<DijksmanPolygon> dijksman_polygons(const Linkage& g, std::string& problem) {
  problem.clear();
  std::vector<DijksmanPolygon> out;
  for (const LinkageLoop& loop : g.loops()) {
    const size_t n = loop.crossings.size();
    DijksmanPolygon base;
    // K_j is the joint of crossing j-1; side j runs inside link crossings[j-1].to.
    for (const auto& c : loop.crossings) {
      base.vertices.push_back(g.joint(c.joint).at);
      base.side_link.push_back(c.to);
    }
    // Rotations putting each side last (fixed); the ground first, then the others in order.
    std::vector<size_t> order;
    for (size_t s = 0; s < n; ++s)
      if (base.side_link[s] == g.ground()) order.push_back(s);
    for (size_t s = 0; s < n; ++s)
      if (base.side_link[s] != g.ground()) order.push_back(s);
    bool found = false;
    for (size_t s : order) {
      DijksmanPolygon p;
      for (size_t t = 1; t <= n; ++t) {  // side s becomes side n: start at side s+1
        const size_t k = (s + t) % n;
        p.vertices.push_back(base.vertices[k]);
        p.side_link.push_back(base.side_link[k]);
      }
      if (!cln::zerop(Polygon<Rational>(p.vertices).dead_centre_determinant())) {
        out.push_back(std::move(p));
        found = true;
        break;
      }
    }
    if (!found) problem = "every choice of fixed side of a loop is a dead centre";
  }
  return out;
}

}  // namespace linkproof
