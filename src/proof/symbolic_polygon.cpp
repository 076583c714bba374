#include "symbolic_polygon.h"

namespace linkproof::proof_detail {

std::vector<GiNaC::ex> SymbolicPolygon::symbols() const {
  std::vector<GiNaC::ex> s(x.begin(), x.end());
  s.insert(s.end(), y.begin(), y.end());
  s.push_back(px);
  s.push_back(py);
  return s;
}

std::string numbered_side(int side, int) { return std::to_string(side); }

std::string general_side(int side, int n) {
  if (side == n - 1) return "{n-1}";
  if (side == n - 2) return "{n-2}";
  return side == 1 ? "j" : side == 2 ? "l" : std::to_string(side);
}

SymbolicPolygon make_symbolic_polygon(int n, const SideNames& names) {
  SymbolicPolygon s;
  s.n = n;
  for (int k = 1; k <= n - 1; ++k) {
    const std::string name = names(k, n);
    const std::string sep = name.front() == '{' ? "_" : "";
    s.x.emplace_back("x" + sep + name);
    s.y.emplace_back("y" + sep + name);
  }
  std::vector<Vec2<GiNaC::ex>> joints(static_cast<size_t>(n));
  joints[static_cast<size_t>(n - 1)] = {s.px, s.py};
  for (int k = n - 1; k >= 1; --k)
    joints[static_cast<size_t>(k - 1)] = {joints[static_cast<size_t>(k)].x - s.x[static_cast<size_t>(k - 1)],
                                          joints[static_cast<size_t>(k)].y - s.y[static_cast<size_t>(k - 1)]};
  s.polygon = Polygon<GiNaC::ex>(joints);
  return s;
}

}  // namespace linkproof::proof_detail
