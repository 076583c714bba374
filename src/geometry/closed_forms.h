// Closed forms of docs/conventions.md §A2, §A3 (rational functions of the side vectors), generic over T.
// They are the second route to every quantity of the construction, defined everywhere except
// at the dead centre D = r_{n-2} x r_{n-1} = 0, where they throw UndefinedQuantity("D").
#pragma once

#include <vector>

#include "core/defined.h"
#include "core/scalar.h"
#include "linkproof/geometry/polygon.h"

namespace linkproof {

/// Closed forms of the construction's ratios and of the mixed-term coefficients (docs/conventions.md §A3, §A4).
template <class T>
struct ClosedForms {
  T D;                 ///< r_{n-2} x r_{n-1}
  T cot_phi;           ///< cot phi = r_{n-2}.r_{n-1} / D  (phi signed, ccw from r_{n-2} to r_{n-1})
  T rho;               ///< r_{n-2} / (r_{n-1} sin phi) = |r_{n-2}|^2 / D
  T rho_companion;     ///< |r_{n-1}|^2 / D (companion formula)
  std::vector<T> i_out;   ///< i_{n-1,j} = (r_j x r_{n-2}) / D
  std::vector<T> i_cpl;   ///< i_{n-2,j} = (r_{n-1} x r_j) / D
  std::vector<T> lambda;  ///< -[r_{n-2}.r_j + i_{n-2,j}^2 |r_{n-2}|^2 + i_{n-1,j}^2 r_{n-2}.r_{n-1}] / D
  std::vector<T> mu;      ///< [r_{n-1}.r_j + i_{n-2,j}^2 r_{n-2}.r_{n-1} + i_{n-1,j}^2 |r_{n-1}|^2] / D
};

inline UndefinedQuantity dead_centre_error() {
  return UndefinedQuantity("D = r_{n-2} x r_{n-1}",
                           "dead centre: sides n-2 and n-1 are parallel, omega ~ 1/D, omega-dot ~ 1/D^3");
}

template <class T>
ClosedForms<T> compute_closed_forms(const Polygon<T>& p) {
  const int n = p.n();
  const Vec2<T> a = p.side(n - 2), b = p.side(n - 1);
  ClosedForms<T> c;
  c.D = cross(a, b);
  if (linkproof::is_zero(c.D)) throw dead_centre_error();
  const T ab = dot(a, b), aa = norm2(a), bb = norm2(b);
  c.cot_phi = ab / c.D;
  c.rho = aa / c.D;
  c.rho_companion = bb / c.D;
  for (int j = 1; j <= n - 3; ++j) {
    const Vec2<T> r = p.side(j);
    const T io = cross(r, a) / c.D, ic = cross(b, r) / c.D;
    c.i_out.push_back(io);
    c.i_cpl.push_back(ic);
    c.lambda.push_back(-(dot(a, r) + ic * ic * aa + io * io * ab) / c.D);
    c.mu.push_back((dot(b, r) + ic * ic * ab + io * io * bb) / c.D);
  }
  return c;
}

/// The ground truth by the closed forms of docs/conventions.md §A2 (route "closed forms"): omega and omega-dot
/// of sides n-2 and n-1 from the inputs. Throws at the dead centre.
template <class T>
PolygonMotion<T> compute_closed_form_motion(const Polygon<T>& p, const InputRates<T>& in) {
  const int n = p.n();
  const Vec2<T> a = p.side(n - 2), b = p.side(n - 1);
  const T D = cross(a, b);
  if (linkproof::is_zero(D)) throw dead_centre_error();
  T w_n1 = from_int<T>(0), w_n2 = from_int<T>(0), acc_n1 = from_int<T>(0), acc_n2 = from_int<T>(0);
  for (int j = 1; j <= n - 3; ++j) {
    const Vec2<T> r = p.side(j);
    const T& w = in.omega[j - 1];
    const T& wd = in.omega_dot[j - 1];
    const T w2 = w * w;
    w_n1 += w * cross(r, a);
    w_n2 += w * cross(b, r);
    acc_n1 += wd * cross(r, a) - w2 * dot(a, r);
    acc_n2 += wd * cross(b, r) + w2 * dot(b, r);
  }
  w_n1 = w_n1 / D;
  w_n2 = w_n2 / D;
  acc_n1 = (acc_n1 - w_n2 * w_n2 * norm2(a) - w_n1 * w_n1 * dot(a, b)) / D;
  acc_n2 = (acc_n2 + w_n2 * w_n2 * dot(a, b) + w_n1 * w_n1 * norm2(b)) / D;
  PolygonMotion<T> m;
  m.omega = in.omega;
  m.omega_dot = in.omega_dot;
  m.omega.push_back(w_n2);
  m.omega.push_back(w_n1);
  m.omega.push_back(from_int<T>(0));
  m.omega_dot.push_back(acc_n2);
  m.omega_dot.push_back(acc_n1);
  m.omega_dot.push_back(from_int<T>(0));
  return m;
}

}  // namespace linkproof
