#include "symbolic/loop_closure.h"

#include "linkproof/core/error.h"
#include "symbolic/time_derivative.h"

namespace linkproof {

using namespace GiNaC;

namespace {

ex cross2(const ex& ax, const ex& ay, const ex& bx, const ex& by) { return ax * by - ay * bx; }

}  // namespace

namespace {
/// One traversal (e.has(x) per symbol would cost O(n) traversals).
bool has_any_of(const ex& e, const exset& symbols) {
  if (is_a<symbol>(e)) return symbols.count(e) > 0;
  for (size_t i = 0; i < e.nops(); ++i)
    if (has_any_of(e.op(i), symbols)) return true;
  return false;
}
}  // namespace

size_t expression_tree_size(const ex& e) {
  size_t s = 1;
  for (size_t i = 0; i < e.nops(); ++i) s += expression_tree_size(e.op(i));
  return s;
}

LoopSolution derive_loop_solution(const PolygonSymbols& s) {
  const int n = s.n();
  LINKPROOF_ASSERT(n >= 4, "the loop solution needs n >= 4 (n-3 inputs)");
  LoopSolution sol;

  // Eq. (1): sum of the side vectors in polar form.
  exvector cx, cy;
  for (int j = 1; j <= n; ++j) {
    cx.push_back(s.length(j) * cos(s.theta(j)));
    cy.push_back(s.length(j) * sin(s.theta(j)));
  }
  sol.closure[0] = dynallocate<add>(cx);
  sol.closure[1] = dynallocate<add>(cy);

  // d/dt: theta_j -> omega_j -> omega_dot_j -> omega_ddot_j for the moving sides; side n is
  // fixed (theta_n constant), which is what makes every rate relative to side n.
  TimeDerivative d;
  for (int j = 1; j <= n - 1; ++j) {
    d.set_rate(s.theta(j), s.omega(j));
    d.set_rate(s.omega(j), s.omega_dot(j));
    d.set_rate(s.omega_dot(j), s.omega_ddot(j));
  }

  // L_j cos(theta_j) = x_j, L_j sin(theta_j) = y_j: the trigonometric form becomes polynomial.
  exset lengths;
  for (int j = 1; j <= n; ++j) lengths.insert(s.length(j));
  exmap to_components;
  for (int j = 1; j <= n; ++j) {
    to_components[cos(s.theta(j))] = s.x(j) / s.length(j);
    to_components[sin(s.theta(j))] = s.y(j) / s.length(j);
  }
  for (int c = 0; c < 2; ++c) {
    const ex v = d.apply(sol.closure[c]);
    const ex a = d.apply(v);
    sol.velocity[c] = v.subs(to_components, subs_options::no_pattern).expand();
    sol.acceleration[c] = a.subs(to_components, subs_options::no_pattern).expand();
    LINKPROOF_ASSERT(!has_any_of(sol.velocity[c], lengths) && !has_any_of(sol.acceleration[c], lengths),
                     "side lengths must cancel after the substitution");
  }

  // Velocity: a*omega_{n-2} + b*omega_{n-1} = c, solved by Cramer's rule.
  const symbol& u = s.omega(n - 2);
  const symbol& v = s.omega(n - 1);
  ex a[2], b[2], c[2];
  exmap unknowns_zero{{u, 0}, {v, 0}};
  for (int k = 0; k < 2; ++k) {
    a[k] = sol.velocity[k].coeff(u, 1);
    b[k] = sol.velocity[k].coeff(v, 1);
    c[k] = -sol.velocity[k].subs(unknowns_zero, subs_options::no_pattern);
  }
  sol.determinant = cross2(a[0], a[1], b[0], b[1]);
  sol.omega_n2 = cross2(c[0], c[1], b[0], b[1]) / sol.determinant;
  sol.omega_n1 = cross2(a[0], a[1], c[0], c[1]) / sol.determinant;

  // Acceleration: same matrix for the unknown omega-dots; the right-hand side contains
  // omega_{n-2}^2 and omega_{n-1}^2, into which the velocity solution is substituted as is.
  const symbol& ud = s.omega_dot(n - 2);
  const symbol& vd = s.omega_dot(n - 1);
  exmap acc_unknowns_zero{{ud, 0}, {vd, 0}};
  exmap velocity_solution{{u, sol.omega_n2}, {v, sol.omega_n1}};
  ex ac[2];
  for (int k = 0; k < 2; ++k) {
    LINKPROOF_ASSERT((sol.acceleration[k].coeff(ud, 1) - a[k]).is_zero() &&
                         (sol.acceleration[k].coeff(vd, 1) - b[k]).is_zero(),
                     "velocity and acceleration equations share their matrix");
    ac[k] = -sol.acceleration[k]
                 .subs(acc_unknowns_zero, subs_options::no_pattern)
                 .subs(velocity_solution, subs_options::no_pattern);
  }
  sol.omega_dot_n2 = cross2(ac[0], ac[1], b[0], b[1]) / sol.determinant;
  sol.omega_dot_n1 = cross2(a[0], a[1], ac[0], ac[1]) / sol.determinant;
  return sol;
}

}  // namespace linkproof
