#include "linkproof/claims/rate_poly.h"

#include <algorithm>

namespace linkproof {

std::string monomial_label(const Monomial& m) {
  if (m.empty()) return "1";
  std::string s;
  for (int i = 0; i < m.size();) {
    int k = i;
    while (k < m.size() && m[k] == m[i]) ++k;
    const RateVariable v = RateVariable::from_id(m[i]);
    if (!s.empty()) s += "*";
    s += (v.kind == RateVariable::Omega ? "omega[" : "omega_dot[") + std::to_string(v.index) + "]";
    if (k - i > 1) s += "^" + std::to_string(k - i);
    i = k;
  }
  return s;
}

std::vector<int> monomial_indices(const Monomial& m) {
  std::vector<int> v;
  for (int i = 0; i < m.size(); ++i) v.push_back(RateVariable::from_id(m[i]).index);
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

}  // namespace linkproof
