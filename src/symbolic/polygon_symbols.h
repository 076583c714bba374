// The symbol table of an n-side polygon: one owner for every GiNaC symbol (GiNaC identifies
// symbols by a hidden serial, not by name, so symbols must never be re-created by name).
//
//   theta_j, L_j        angle and length of side j (j = 1..n); side n is fixed
//   omega_j, omega_dot_j, omega_ddot_j   first, second, third time derivatives of theta_j
//   x_j, y_j            components of r_j = L_j (cos theta_j, sin theta_j)
// Indices are the paper's (1-based); vectors below are 0-based (theta[j-1] is theta_j).
#pragma once

#include <ginac/ginac.h>

#include <vector>

namespace linkproof {

class PolygonSymbols {
 public:
  explicit PolygonSymbols(int n);

  int n() const { return n_; }
  const GiNaC::realsymbol& theta(int j) const { return theta_[idx(j)]; }
  const GiNaC::realsymbol& length(int j) const { return length_[idx(j)]; }
  const GiNaC::realsymbol& omega(int j) const { return omega_[idx(j)]; }
  const GiNaC::realsymbol& omega_dot(int j) const { return omega_dot_[idx(j)]; }
  const GiNaC::realsymbol& omega_ddot(int j) const { return omega_ddot_[idx(j)]; }
  const GiNaC::realsymbol& x(int j) const { return x_[idx(j)]; }
  const GiNaC::realsymbol& y(int j) const { return y_[idx(j)]; }

 private:
  size_t idx(int j) const;
  int n_;
  std::vector<GiNaC::realsymbol> theta_, length_, omega_, omega_dot_, omega_ddot_, x_, y_;
};

}  // namespace linkproof
