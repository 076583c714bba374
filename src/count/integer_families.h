// The relation families of count_fixed_side_relations (counting.h) as integer rows on the free
// rates: the same relations, each multiplied by a nonzero constant, so that their ranks can be
// computed without fractions (core/fraction_free_echelon.h).
//
// What is scaled, and why no rank changes (docs/conventions.md §A7):
//  * the polygon by the lcm s of its coordinates' denominators: every closed form is a ratio of
//    products of side vectors of equal degree (i = cross/cross, lambda = dot/D + ...), unchanged;
//  * every side velocity by the lcm L of their denominators: the acceleration constants are
//    quadratic forms in the velocities, so every right-hand side of every family is multiplied
//    by L^2: the column b of [A | b] is scaled, which keeps the rank of A and of [A | b];
//  * each relation by D (velocity) or D^3 (acceleration), D = r_{n-2} x r_{n-1} of its choice of
//    the fixed side (nonzero: D = 0 is the dead centre, which throws): one row of [A | b] scaled.
// With I_j = D i_{n-1,j} = r_j x r_{n-2}, K_j = D i_{n-2,j} = r_{n-1} x r_j and the integer
// velocities w_j = L (omega_j - omega_fixed), the (22) relation times D^3 reads
//     D^3 w_{n-1,n} - sum_j D^2 I_j w_{j,n}
//        = sum_j Lambda_j w_j^2 - (r_{n-2}.r_{n-1}) S_1 - |r_{n-2}|^2 S_2,
//     Lambda_j = -(D^2 r_{n-2}.r_j + K_j^2 |r_{n-2}|^2 + I_j^2 r_{n-2}.r_{n-1}),
//     S_1 = (sum_j I_j w_j)^2 - sum_j (I_j w_j)^2,  S_2 = the same with K_j,
// which is D^3 times relative_rates.cpp's (22) with lambda_j = Lambda_j / D^3, cot phi, rho; the
// companion likewise with M_j = D^2 r_{n-1}.r_j + K_j^2 r_{n-2}.r_{n-1} + I_j^2 |r_{n-1}|^2.
//
// A rate of body a relative to body b is y_b - y_a on the free rates y_1 .. y_{n-1} (y_0 = 0):
// a relation's term c rate(a, fixed) adds c to column fixed - 1 and -c to column a - 1.
#pragma once

#include <cln/integer.h>

#include <vector>

#include "linkproof/geometry/polygon.h"

namespace linkproof {

/// sum_k row[k] y_{k+1} = rhs, y_1 .. y_{n-1} the free rates.
struct IntegerRelation {
  std::vector<cln::cl_I> row;
  cln::cl_I rhs;
};

/// The three families over all n choices of the fixed side f = 1..n, in that order of f.
struct IntegerFamilies {
  std::vector<IntegerRelation> velocity;   ///< (5), (6) of each f (2n)
  std::vector<IntegerRelation> eq22;       ///< (22) of each f (n)
  std::vector<IntegerRelation> companion;  ///< the companion of each f (n)
};

/// The families of polygon `p` (n >= 3, side j is body j-1) with side velocities `omega` (one
/// per side, any common reference). Throws UndefinedQuantity (dead_centre_error) if some choice
/// of the fixed side is a dead centre.
IntegerFamilies integer_fixed_side_families(const Polygon<Rational>& p, const std::vector<Rational>& omega);

}  // namespace linkproof
