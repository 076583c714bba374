// Solving a mechanism's velocity and acceleration systems, given its constraint matrix.
//
// The loop closures of a linkage (mechanism/linkage.h), differentiated once and twice in time at
// the current configuration, are linear in the rates q-dot = (omega of every moving link,
// sigma-dot of every prismatic pair) and in q-ddot:
//   velocity      A q-dot  = 0
//   acceleration  A q-ddot = h(q-dot)          (h: the centripetal and Coriolis terms)
// with the same matrix A (constraint_count x unknown_count). The mobility is
// unknown_count - rank(A); the scene must give exactly that many inputs, each fixing one unknown.
// Two routes build A and h: the symbolic loop closure (mechanism/mechanism_closure.h, GiNaC) and
// the rigid-body vector formulas (mechanism/mechanism_vector_route.h); both end here.
//
// Errors are bad input (InputError(source, field, problem)): a locked linkage (mobility 0), a
// number of inputs different from the mobility, inputs that do not fix the motion (dependent
// inputs, or an input on a link that cannot move), inputs that contradict the constraints.
#pragma once

#include <fmt/format.h>

#include <string>
#include <vector>

#include "core/scalar.h"
#include "linkproof/core/error.h"
#include "mechanism/linkage_motion.h"
#include "mechanism/linear_system.h"

namespace linkproof {

template <class T>
struct MechanismSolution {
  MechanismMotion<T> motion;
  int rank = 0;      ///< rank of the constraint matrix A
  int mobility = 0;  ///< unknown_count - rank
  std::vector<T> qdot, qddot;
};

/// An input's rate and its derivative already in T (e.g. with the uncertainty of recorded data).
template <class T>
struct InputValue {
  T rate, rate_dot;
};

/// The inputs' rates (or, second_order, their derivatives) appended to b: the right-hand side of
/// the input rows.
template <class T>
void append_input_rates(const std::vector<MechanismInput>& inputs, std::vector<T>& b, bool second_order,
                        const std::vector<InputValue<T>>* values = nullptr) {
  for (size_t k = 0; k < inputs.size(); ++k) {
    if (values)
      b.push_back(second_order ? (*values)[k].rate_dot : (*values)[k].rate);
    else
      b.push_back(from_rational<T>(second_order ? inputs[k].rate_dot : inputs[k].rate));
  }
}

/// The input rows: one unit row per input, in the unknown's column; the right-hand sides are the
/// inputs' rates, or `values[k]` when given.
template <class T>
void append_input_rows(const Linkage& g, const std::vector<MechanismInput>& inputs, DenseMatrix<T>& A,
                       std::vector<T>& b, bool second_order, const std::string& source,
                       const std::vector<InputValue<T>>* values = nullptr) {
  // A matrix without rows yet (no constraints, or a scratch for the right-hand side) takes the
  // width of the unknowns.
  if (A.empty() && A.cols() == 0) A = DenseMatrix<T>::with_columns(static_cast<size_t>(g.unknown_count()));
  for (size_t k = 0; k < inputs.size(); ++k) {
    const MechanismInput& in = inputs[k];
    const int col = in.kind == MechanismInput::Kind::Link ? g.unknown_of_link(in.index) : g.unknown_of_joint(in.index);
    if (col < 0)
      throw InputError(source, fmt::format("mechanism.inputs[{}]", k),
                       in.kind == MechanismInput::Kind::Link ? "an input on the ground link: its rates are 0 by definition"
                                                             : "a slider input on a revolute joint");
    A.add_row(from_int<T>(0))[static_cast<size_t>(col)] = from_int<T>(1);
  }
  append_input_rates(inputs, b, second_order, values);
}

/// Solves velocity then acceleration. `A` is the constraint matrix; `acceleration_rhs(qdot)`
/// returns h(q-dot) (constraint_count entries). `values`: the inputs' rates in T (optional);
/// `geo`: where the joints are for the joints' velocities (default: the linkage's positions);
/// `joints`: whether joint_v / joint_a are filled (the links' fields always are).
template <class T, class AccelerationRhs>
MechanismSolution<T> solve_mechanism(const Linkage& g, const std::vector<MechanismInput>& inputs, DenseMatrix<T> A,
                                     AccelerationRhs acceleration_rhs, const std::string& source,
                                     const std::vector<InputValue<T>>* values = nullptr,
                                     const JointGeometry<T>& geo = {}, JointMotion joints = JointMotion::Fill) {
  const size_t N = static_cast<size_t>(g.unknown_count());
  const size_t constraints = A.size();
  MechanismSolution<T> s;
  // The rank of A alone (the mobility) is its own elimination: pivoting the constraint rows
  // before the input rows would, in floating point, pivot on a rounding residue where an input
  // row (a unit row) is the better pivot (a crank 100 times shorter than the other links).
  s.rank = LinearSystem<T>::rank_of(A);
  s.mobility = static_cast<int>(N) - s.rank;
  if (s.mobility == 0)
    throw InputError(source, "mechanism.joints",
                     fmt::format("the linkage is locked: mobility 0 (rank of the velocity constraints {} = number "
                                 "of unknowns; Gruebler count {})", s.rank, g.grubler_mobility()));
  if (static_cast<int>(inputs.size()) != s.mobility)
    throw InputError(source, "mechanism.inputs",
                     fmt::format("the mechanism has mobility {} (rank of the velocity constraints {}, {} unknowns; "
                                 "Gruebler count {}) and needs {} input(s), got {}",
                                 s.mobility, s.rank, N, g.grubler_mobility(), s.mobility, inputs.size()));
  std::vector<T> bv;
  bv.reserve(constraints + inputs.size());
  bv.assign(constraints, from_int<T>(0));
  A.reserve(constraints + inputs.size());
  append_input_rows(g, inputs, A, bv, false, source, values);
  // Velocity and acceleration: one matrix (the constraints and the input rows), two right-hand sides.
  const LinearSystem<T> system(std::move(A));
  LinearSolution<T> vel = system.solve(std::move(bv));
  if (vel.rank < static_cast<int>(N))
    throw InputError(source, "mechanism.inputs",
                     "the inputs do not fix the motion: some input is dependent on the others or on the constraints "
                     "(e.g. it drives a link that cannot move), so another part of the mechanism stays free");
  if (!vel.consistent)
    throw InputError(source, "mechanism.inputs", "the inputs contradict the constraints");
  s.qdot = std::move(vel.x);
  std::vector<T> ba = acceleration_rhs(s.qdot);
  LINKPROOF_ASSERT(ba.size() == constraints, "acceleration right-hand side has the wrong size");
  append_input_rates(inputs, ba, true, values);
  LinearSolution<T> acc = system.solve(std::move(ba));
  if (!acc.consistent || acc.x.size() != N)
    throw InputError(source, "mechanism.inputs", "the acceleration inputs contradict the constraints");
  s.qddot = std::move(acc.x);

  MechanismMotion<T>& m = s.motion;
  const T zero = from_int<T>(0);
  m.omega.reserve(static_cast<size_t>(g.link_count()));
  m.omega_dot.reserve(static_cast<size_t>(g.link_count()));
  m.slide.reserve(static_cast<size_t>(g.joint_count()));
  m.slide_dot.reserve(static_cast<size_t>(g.joint_count()));
  for (int l = 0; l < g.link_count(); ++l) {
    const int c = g.unknown_of_link(l);
    m.omega.push_back(c < 0 ? zero : s.qdot[static_cast<size_t>(c)]);
    m.omega_dot.push_back(c < 0 ? zero : s.qddot[static_cast<size_t>(c)]);
  }
  for (int j = 0; j < g.joint_count(); ++j) {
    const int c = g.unknown_of_joint(j);
    m.slide.push_back(c < 0 ? zero : s.qdot[static_cast<size_t>(c)]);
    m.slide_dot.push_back(c < 0 ? zero : s.qddot[static_cast<size_t>(c)]);
  }
  complete_joint_motion(g, m, geo, joints);
  return s;
}

}  // namespace linkproof
