// Route 1 to a mechanism's kinematics (the ground truth): every loop's closure built
// symbolically with GiNaC and differentiated twice in time.
//
// The current configuration is the reference: link l is turned by theta_l from it (theta_l = 0
// now), so a vector r fixed in l is R(theta_l) r, and a prismatic pair adds sigma R(theta_guide) u
// (sigma = 0 now). For each loop of the basis (mechanism/linkage.h):
//   position   sum_i R(theta_{l_i}) r_i + sum (+-) sigma R(theta_guide) u = 0          (2 rows)
// and for each prismatic pair theta_slider - theta_guide = const.                      (1 row)
// The operator d/dt (symbolic/time_derivative.h: theta -> omega -> omega_dot, sigma -> sigma_dot
// -> sigma_ddot) is applied twice, then theta = sigma = 0 is substituted: cos 0 = 1, sin 0 = 0,
// so the result is exact. The velocity rows are linear in q-dot: their coefficients are the
// constraint matrix A; the acceleration rows are A q-ddot - h(q-dot), where h holds the
// centripetal (omega^2 r) and Coriolis (2 omega_guide sigma-dot J u) terms.
// Solved by mechanism/mechanism_solve.h. GiNaC is not thread-safe: one closure per thread.
#pragma once

#include <ginac/ginac.h>

#include <vector>

#include "linkproof/mechanism/linkage.h"
#include "mechanism/linear_system.h"

namespace linkproof {

class MechanismClosure {
 public:
  explicit MechanismClosure(const Linkage& g);

  /// Symbols of the unknowns q-ddot, in Linkage's unknown order.
  const std::vector<GiNaC::symbol>& rate_dot_symbols() const { return rate_dot_; }

  /// A: coefficient of q-dot_c in velocity row r (exact).
  DenseMatrix<Rational> constraint_matrix() const;
  /// A', the coefficients of q-ddot in the acceleration rows: equal to A (a check of the route).
  DenseMatrix<Rational> acceleration_matrix() const;
  /// h(q-dot): minus the acceleration rows at q-ddot = 0 with q-dot substituted.
  std::vector<Rational> acceleration_rhs(const std::vector<Rational>& qdot) const;
  /// The position rows at theta = sigma = 0: the closure residual of the given positions
  /// (exactly 0 when the joints are where the links put them, which the model guarantees).
  std::vector<Rational> position_residual() const;

 private:
  std::vector<GiNaC::symbol> angle_, rate_, rate_dot_;  // per unknown: theta|sigma, its rate, 2nd rate
  std::vector<GiNaC::ex> position_, velocity_, acceleration_;
  GiNaC::exmap at_reference_;  // theta = sigma = 0
};

}  // namespace linkproof
