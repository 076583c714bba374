// Building blocks shared by the claims of Dijksman (1966): the sums of the paper written once,
// generic over the scalar type. Internal to the catalogue.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "dijksman1966.h"

namespace linkproof::dijksman1966::parts {

inline std::string label_j(int j) { return "j=" + std::to_string(j); }

inline bool is_true_reading(const ConstructionReading& r) {
  return r.displaced_start && r.beta_towards_p_prime && r.beta_ccw_positive && r.signed_ratios;
}

/// The construction under a reading (the context's own for the true reading).
template <class T>
std::vector<FourBarConstruction<T>> constructions(const PolygonContext<T>& c, const ConstructionReading& r) {
  if (is_true_reading(r)) return c.construction;
  std::vector<FourBarConstruction<T>> v;
  for (int j = 1; j <= c.inputs(); ++j) v.push_back(construct_four_bar(c.polygon, j, r));
  return v;
}

/// cot phi, r_{n-2}/(r_{n-1} sin phi) = |r_{n-2}|^2/D and |r_{n-1}|^2/D, with phi the signed
/// angle from r_{n-2} to r_{n-1} (SPEC A3), or the unsigned drawn angle |phi| (erratum A5.6):
/// cot|phi| = r_{n-2}.r_{n-1}/|D|, sin|phi| = |sin phi|. Undefined at the dead centre.
template <class T>
struct PhiTerms {
  T cot_phi, rho, rho_companion;
};
template <class T>
PhiTerms<T> phi_terms(const PolygonContext<T>& c, bool signed_phi) {
  const ClosedForms<T>& cf = c.closed.get();
  if (signed_phi) return {cf.cot_phi, cf.rho, cf.rho_companion};
  const T abs_d = abs_value(cf.D);
  const Vec2<T> a = c.r(c.n - 2), b = c.r(c.n - 1);
  return {dot(a, b) / abs_d, norm2(a) / abs_d, norm2(b) / abs_d};
}

/// sum_{j != l} x_j x_l over ordered pairs, in O(n): (sum x)^2 - sum x^2.
template <class T>
T ordered_pair_sum(const std::vector<T>& x) {
  T s = from_int<T>(0), s2 = from_int<T>(0);
  for (const T& v : x) {
    s += v;
    s2 += v * v;
  }
  return s * s - s2;
}

/// _j omega = (ratio_j) omega_j for every input j (contributions of the four-bars, eq. 5/6).
template <class T>
std::vector<T> contributions(const PolygonContext<T>& c, const std::function<T(int)>& ratio) {
  std::vector<T> v;
  for (int j = 1; j <= c.inputs(); ++j) v.push_back(ratio(j) * c.omega_in(j));
  return v;
}

/// A formula of the shape of (22) and the companion:
///   sum_j (square_j omega_j^2 + linear_j omega-dot_j)
///   + (pair_factor / 2) sum_{j != l} (k1 u_j u_l + k2 v_j v_l) omega_j omega_l
/// so that the coefficient of the monomial omega_j omega_l (j < l) is
/// pair_factor (k1 u_j u_l + k2 v_j v_l).
template <class T>
struct QuadraticFormula {
  std::function<T(int)> linear, square, u, v;
  std::function<T()> k1, k2;
  T pair_factor;
};

/// Total (engine truth vs formula) and every term (engine coefficient vs formula coefficient).
template <class T>
ClaimSides<T> quadratic_sides(const PolygonContext<T>& c, const QuadraticFormula<T>& f,
                              const std::function<T()>& truth_total,
                              const std::function<const TermCoefficients<T>&()>& truth_terms) {
  const int m = c.inputs();
  ClaimSides<T> s;
  s.instances.push_back(compare<T>("total", truth_total, [&] {
    T sum = from_int<T>(0);
    for (int j = 1; j <= m; ++j) {
      const T& w = c.omega_in(j);
      sum += f.square(j) * w * w + f.linear(j) * c.omega_dot_in(j);
    }
    const T mixed = f.k1() * ordered_pair_sum(contributions<T>(c, f.u)) +
                    f.k2() * ordered_pair_sum(contributions<T>(c, f.v));
    return sum + f.pair_factor / from_int<T>(2) * mixed;
  }));
  for (int j = 1; j <= m; ++j) {
    const size_t k = static_cast<size_t>(j - 1);
    s.terms.push_back(compare<T>("omega_dot[" + std::to_string(j) + "]",
                                 [&] { return truth_terms().omega_dot[k]; }, [&] { return f.linear(j); }));
    s.terms.push_back(compare<T>("omega[" + std::to_string(j) + "]^2",
                                 [&] { return truth_terms().omega_sq[k]; }, [&] { return f.square(j); }));
  }
  for (int j = 1; j <= m; ++j)
    for (int l = j + 1; l <= m; ++l)
      s.terms.push_back(compare<T>(
          "omega[" + std::to_string(j) + "]*omega[" + std::to_string(l) + "]",
          [&] { return truth_terms().omega_pair[pair_index(j, l, m)]; },
          [&] { return f.pair_factor * (f.k1() * f.u(j) * f.u(l) + f.k2() * f.v(j) * f.v(l)); }));
  return s;
}

}  // namespace linkproof::dijksman1966::parts
