// The motion tape of an n-side polygon built without GiNaC trees: the canonical form
// (canonical_form.h) of the solved loop closure is assembled directly from the closed form of
// its two time derivatives, and compiled. It is the tape that compiling GiNaC's derivation
// (loop_closure.h) gives, instruction for instruction: GiNaC's derivation is the reference, and
// tests compare the two tapes (MotionTape.*).
//
// What GiNaC derives, and what is assembled here (side n fixed, m = n-3 inputs, p = n-2, q = n-1;
// docs/conventions.md §A2):
//   velocity      sum_{j<=q} omega_j (-y_j, x_j) = 0
//   acceleration  sum_{j<=q} omega-dot_j (-y_j, x_j) - omega_j^2 (x_j, y_j) = 0
// both linear in the unknowns of sides p and q with the matrix [a b], a = (-y_p, x_p),
// b = (-y_q, x_q), solved by Cramer's rule written structurally:
//   D = a x b,  c = (sum_{j<=m} omega_j y_j, -sum_{j<=m} omega_j x_j),
//   omega_p = (c x b) / D,  omega_q = (a x c) / D,
//   c' = sum_{j<=m} (omega-dot_j y_j + omega_j^2 x_j, -omega-dot_j x_j + omega_j^2 y_j)
//        + omega_p^2 (x_p, y_p) + omega_q^2 (x_q, y_q),
//   omega-dot_p = (c' x b) / D,  omega-dot_q = (a x c') / D,
// with u x v = u_x v_y - u_y v_x. Every sum, product and power is the one GiNaC's expression
// tree has at that place (after GiNaC's own flattening), so their canonical forms are equal.
#pragma once

#include <string>
#include <vector>

#include "symbolic/tape.h"

namespace linkproof {

/// The tape's input names, in its input order: x_1..x_{n-1}, y_1..y_{n-1}, omega_1..omega_{n-3},
/// omega_dot_1..omega_dot_{n-3} (the names of PolygonSymbols' symbols).
std::vector<std::string> motion_tape_input_names(int n);

/// The motion tape for n >= 4 sides: outputs omega_{n-2}, omega_{n-1}, omega-dot_{n-2},
/// omega-dot_{n-1}. `denominator_name` names D where it is zero.
Tape derive_motion_tape(int n, std::string denominator_name);

}  // namespace linkproof
