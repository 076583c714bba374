// The n-gon in generic coordinates, for proofs: side r_k = (x_k, y_k) for k = 1..n-1 and
// K_n = (px, py); joints K_n, K_{n-1} = K_n - r_{n-1}, ..., K_1 = K_2 - r_1 (side n closes the
// loop). The 2n symbols are independent, so a rational function of them that is zero is zero
// for every polygon where it is defined. Private to src/proof.
#pragma once

#include <ginac/ginac.h>

#include <functional>
#include <string>
#include <vector>

#include "linkproof/geometry/polygon.h"

namespace linkproof::proof_detail {

struct SymbolicPolygon {
  int n = 0;
  std::vector<GiNaC::realsymbol> x, y;  // [k-1]
  GiNaC::realsymbol px{"px"}, py{"py"};
  Polygon<GiNaC::ex> polygon;
  std::vector<GiNaC::ex> symbols() const;
  /// The symbols of side k (x_k, y_k).
  std::vector<GiNaC::ex> side_symbols(int k) const { return {x[static_cast<size_t>(k - 1)], y[static_cast<size_t>(k - 1)]}; }
};

/// How sides are named in printed polynomials: "1", "2", ... or, for the base of a proof for
/// every n, "j", "l", "{n-2}", "{n-1}".
using SideNames = std::function<std::string(int side, int n)>;
std::string numbered_side(int side, int n);
/// At the base n = 5 of a proof for every n: r_1, r_2 stand for r_j, r_l (any two inputs).
std::string general_side(int side, int n);

SymbolicPolygon make_symbolic_polygon(int n, const SideNames& names = numbered_side);

}  // namespace linkproof::proof_detail
