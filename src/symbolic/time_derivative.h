// The total time derivative d/dt over a chain of state symbols, e.g. theta -> omega ->
// omega_dot -> omega_ddot: d/dt f = sum_s (df/ds) (ds/dt).
//
// Implemented as a recursive rule set (sum, product, integer power, sin, cos) that visits each
// node once, so its cost is linear in the size of the expression; calling GiNaC's diff() once
// per symbol would cost (number of symbols) x (size), i.e. O(n^2) for a polygon.
#pragma once

#include <ginac/ginac.h>

namespace linkproof {

class TimeDerivative {
 public:
  /// Declares ds/dt = rate. Symbols never declared are constants (d/dt = 0).
  void set_rate(const GiNaC::symbol& s, const GiNaC::ex& rate);
  /// d/dt e. Throws InternalError on a node it has no rule for.
  GiNaC::ex apply(const GiNaC::ex& e) const;

 private:
  GiNaC::exmap rate_;
};

}  // namespace linkproof
