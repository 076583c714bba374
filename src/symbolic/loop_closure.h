// The loop-closure equations of an n-side polygon, differentiated twice in time and solved
// exactly for the two dependent sides: the ground truth of linkproof (docs/conventions.md §A2).
//
//   closure       sum_{j=1..n} L_j (cos theta_j, sin theta_j) = 0                (eq. 1)
//   velocity      d/dt closure,   side n fixed (omega_n = 0)
//   acceleration  d^2/dt^2 closure
// After differentiating, cos theta_j and sin theta_j are replaced by x_j / L_j, y_j / L_j, so
// every equation is polynomial in the side components x_j, y_j (GiNaC's normal() knows no
// trigonometry). Both equations are linear in the unknowns of sides n-2 and n-1 with the same
// 2x2 matrix [a b] (columns: coefficients of the two unknowns); they are solved by Cramer's rule
// written structurally, u = (c x b)/(a x b), v = (a x c)/(a x b), and the velocity solution is
// substituted into the acceleration right-hand side without expanding. No global simplifier
// is called, so the result has size O(n).
#pragma once

#include <ginac/ginac.h>

#include "symbolic/polygon_symbols.h"

namespace linkproof {

struct LoopSolution {
  GiNaC::ex closure[2];        ///< x and y components of eq. (1), in L_j and theta_j
  GiNaC::ex velocity[2];       ///< d/dt closure, in x_j, y_j, omega_j
  GiNaC::ex acceleration[2];   ///< d^2/dt^2 closure, in x_j, y_j, omega_j, omega_dot_j
  GiNaC::ex determinant;       ///< a x b: equals D = r_{n-2} x r_{n-1}
  GiNaC::ex omega_n2, omega_n1;          ///< omega_{n-2,n}, omega_{n-1,n} in the inputs
  GiNaC::ex omega_dot_n2, omega_dot_n1;  ///< omega-dot_{n-2,n}, omega-dot_{n-1,n} in the inputs
};

/// Derives the closure, its two time derivatives and their exact solution.
LoopSolution derive_loop_solution(const PolygonSymbols& s);

/// Number of nodes of the expression tree (shared subtrees counted at every use).
size_t expression_tree_size(const GiNaC::ex& e);

}  // namespace linkproof
