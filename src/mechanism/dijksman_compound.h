// Dijksman (1966) on a compound mechanism (its section 3, docs/conventions.md §A7): all relative angular
// velocities and accelerations from a few polygons, without solving the mechanism as a whole.
//
// Unknowns: omega_ik and omega-dot_ik for every pair of links i < k (omega_ki = -omega_ik).
// Relations, for the velocities:
//   triangle  omega_ij + omega_jk - omega_ik = 0 for every triple (rank (L-1)(L-2)/2)
//   input     omega_{input, ground} = given
//   polygon   for every loop of the basis, read as Dijksman's polygon with a fixed side n
//             (K_j the joints in loop order, side j the link between K_j and K_{j+1}):
//             eq. (5)  omega_{n-1,n} = sum_j i_{n-1,j} omega_{j,n}
//             eq. (6)  omega_{n-2,n} = sum_j i_{n-2,j} omega_{j,n}
// and for the accelerations the same triangle relations, the input, and per polygon
//   eq. (22)  omega-dot_{n-1,n} = sum_j (lambda_j omega_j^2 + i_{n-1,j} omega-dot_j)
//             - cot phi S_1 - (|r_{n-2}|^2/D) S_2
//   companion omega-dot_{n-2,n} = sum_j (mu_j omega_j^2 + i_{n-2,j} omega-dot_j)
//             + cot phi S_2 + (|r_{n-1}|^2/D) S_1
// (S_1, S_2 over ordered pairs j != l; omega_j = omega_{j,n} from the velocity solve). The
// coefficients are the closed forms of docs/conventions.md §A3 (geometry/closed_forms.h). The fixed side is the
// ground where the loop contains it, else the first side that is not a dead centre.
// Applies to revolute-only linkages of mobility 1 with one link input; polygons need n >= 4.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/scalar.h"
#include "geometry/closed_forms.h"
#include "linkproof/mechanism/linkage.h"
#include "mechanism/linear_system.h"

namespace linkproof {

/// One loop read as Dijksman's polygon: links of sides 1..n (side n fixed) and the joints K_1..K_n.
struct DijksmanPolygon {
  std::vector<int> side_link;  ///< side_link[j-1]: the link of side j
  std::vector<Vec2<Rational>> vertices;
};

template <class T>
struct DijksmanCompoundSolution {
  std::vector<std::pair<int, int>> pairs;  ///< (i, k), i < k, in the unknowns' order
  std::vector<T> omega, omega_dot;         ///< omega_ik, omega-dot_ik
  int velocity_rank = 0, acceleration_rank = 0;
  std::vector<DijksmanPolygon> polygons;
};

/// The polygons of the loop basis, each rotated so that its fixed side is the ground (if in the
/// loop) or the first side with D != 0. Empty problem text if all is well.
std::vector<DijksmanPolygon> dijksman_polygons(const Linkage& g, std::string& problem);

/// Empty if Dijksman's compound method applies (revolute pairs only, one link input, loops of
/// n >= 4 with distinct links), else why not.
std::string dijksman_compound_problem(const Linkage& g, const std::vector<MechanismInput>& inputs);

template <class T>
DijksmanCompoundSolution<T> solve_dijksman_compound(const Linkage& g, const MechanismInput& input) {
  std::string problem;
  DijksmanCompoundSolution<T> s;
  s.polygons = dijksman_polygons(g, problem);
  LINKPROOF_ASSERT(problem.empty(), problem);
  const int L = g.link_count();
  std::vector<std::vector<int>> index(static_cast<size_t>(L), std::vector<int>(static_cast<size_t>(L), -1));
  for (int i = 0; i < L; ++i)
    for (int k = i + 1; k < L; ++k) {
      index[static_cast<size_t>(i)][static_cast<size_t>(k)] = static_cast<int>(s.pairs.size());
      s.pairs.emplace_back(i, k);
    }
  const size_t P = s.pairs.size();
  const T zero = from_int<T>(0), one = from_int<T>(1);
  // Adds c * x_{ab} (x_{ab} = -x_{ba}) to a row.
  const auto add = [&](std::vector<T>& row, int a, int b, const T& c) {
    if (a == b) return;
    if (a < b) row[static_cast<size_t>(index[static_cast<size_t>(a)][static_cast<size_t>(b)])] += c;
    else row[static_cast<size_t>(index[static_cast<size_t>(b)][static_cast<size_t>(a)])] -= c;
  };
  DenseMatrix<T> base;  // triangle relations and the input row, shared by both systems
  for (int i = 0; i < L; ++i)
    for (int j = i + 1; j < L; ++j)
      for (int k = j + 1; k < L; ++k) {
        std::vector<T> row(P, zero);
        add(row, i, j, one), add(row, j, k, one), add(row, i, k, -one);
        base.push_back(std::move(row));
      }
  std::vector<T> input_row(P, zero);
  add(input_row, input.index, g.ground(), one);
  base.push_back(input_row);
  const size_t input_at = base.size() - 1;

  std::vector<ClosedForms<T>> forms;
  for (const DijksmanPolygon& p : s.polygons) {
    std::vector<Vec2<T>> v;
    for (const auto& k : p.vertices) v.push_back(vec_from_rational<T>(k));
    forms.push_back(compute_closed_forms(Polygon<T>(std::move(v))));
  }
  // Velocities: eqs. (5), (6).
  DenseMatrix<T> A = base;
  std::vector<T> b(A.size(), zero);
  b[input_at] = from_rational<T>(input.rate);
  for (size_t q = 0; q < s.polygons.size(); ++q) {
    const auto& sl = s.polygons[q].side_link;
    const int n = static_cast<int>(sl.size());
    const int fixed = sl[static_cast<size_t>(n - 1)];
    std::vector<T> r5(P, zero), r6(P, zero);
    add(r5, sl[static_cast<size_t>(n - 2)], fixed, one);
    add(r6, sl[static_cast<size_t>(n - 3)], fixed, one);
    for (int j = 1; j <= n - 3; ++j) {
      add(r5, sl[static_cast<size_t>(j - 1)], fixed, -forms[q].i_out[static_cast<size_t>(j - 1)]);
      add(r6, sl[static_cast<size_t>(j - 1)], fixed, -forms[q].i_cpl[static_cast<size_t>(j - 1)]);
    }
    A.push_back(std::move(r5)), A.push_back(std::move(r6));
    b.push_back(zero), b.push_back(zero);
  }
  const LinearSolution<T> vel = solve_linear_system<T>(A, b);
  s.velocity_rank = vel.rank;
  if (vel.x.size() != P) throw UndefinedQuantity("omega_ik", "the polygon relations do not determine every relative omega");
  s.omega = vel.x;
  const auto omega_of = [&](int a, int c) {
    if (a == c) return zero;
    return a < c ? s.omega[static_cast<size_t>(index[static_cast<size_t>(a)][static_cast<size_t>(c)])]
                 : -s.omega[static_cast<size_t>(index[static_cast<size_t>(c)][static_cast<size_t>(a)])];
  };
  // Accelerations: eq. (22) and the companion.
  A = base;
  b.assign(A.size(), zero);
  b[input_at] = from_rational<T>(input.rate_dot);
  for (size_t q = 0; q < s.polygons.size(); ++q) {
    const auto& sl = s.polygons[q].side_link;
    const ClosedForms<T>& f = forms[q];
    const int n = static_cast<int>(sl.size());
    const int fixed = sl[static_cast<size_t>(n - 1)];
    std::vector<T> r22(P, zero), rc(P, zero);
    add(r22, sl[static_cast<size_t>(n - 2)], fixed, one);
    add(rc, sl[static_cast<size_t>(n - 3)], fixed, one);
    T rhs22 = zero, rhsc = zero, S1 = zero, S2 = zero;
    for (int j = 1; j <= n - 3; ++j) {
      const size_t jj = static_cast<size_t>(j - 1);
      const T w = omega_of(sl[jj], fixed);
      add(r22, sl[jj], fixed, -f.i_out[jj]);
      add(rc, sl[jj], fixed, -f.i_cpl[jj]);
      rhs22 += f.lambda[jj] * w * w;
      rhsc += f.mu[jj] * w * w;
      for (int l = 1; l <= n - 3; ++l) {
        if (l == j) continue;
        const size_t ll = static_cast<size_t>(l - 1);
        const T wl = omega_of(sl[ll], fixed);
        S1 += f.i_out[jj] * f.i_out[ll] * w * wl;
        S2 += f.i_cpl[jj] * f.i_cpl[ll] * w * wl;
      }
    }
    rhs22 = rhs22 - f.cot_phi * S1 - f.rho * S2;
    rhsc = rhsc + f.cot_phi * S2 + f.rho_companion * S1;
    A.push_back(std::move(r22)), A.push_back(std::move(rc));
    b.push_back(rhs22), b.push_back(rhsc);
  }
  const LinearSolution<T> acc = solve_linear_system<T>(A, b);
  s.acceleration_rank = acc.rank;
  if (acc.x.size() != P)
    throw UndefinedQuantity("omega-dot_ik", "the polygon relations do not determine every relative omega-dot");
  s.omega_dot = acc.x;
  return s;
}

}  // namespace linkproof
