#include "claims/rate_poly.h"

#include <algorithm>
#include <charconv>

namespace linkproof {

std::string monomial_label(const Monomial& m) {
  if (m.empty()) return "1";
  // Written into one buffer (a label per compared monomial: m^2 of them per claim at n sides).
  std::string s;
  s.reserve(12 * static_cast<size_t>(m.size()));
  char digits[16];
  const auto number = [&](int k) {
    const auto end = std::to_chars(digits, digits + sizeof digits, k).ptr;
    s.append(digits, end);
  };
  for (int i = 0; i < m.size();) {
    int k = i;
    while (k < m.size() && m[k] == m[i]) ++k;
    const RateVariable v = RateVariable::from_id(m[i]);
    if (!s.empty()) s += '*';
    s += v.kind == RateVariable::Omega ? "omega[" : "omega_dot[";
    number(v.index);
    s += ']';
    if (k - i > 1) {
      s += '^';
      number(k - i);
    }
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
