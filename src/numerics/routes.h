// The four routes to the angular accelerations of sides n-1 and n-2 of the n-side polygon
// (Dijksman 1966, docs/conventions.md §A2-§A4), each written once, generic over the scalar type T, so that
// every route runs in every arithmetic of the ladder (numerics/ladder.h) through the same code:
//
//   Route::Construction  the paper's way: eq. (22) and the companion formula with i_{n-1,j},
//                        i_{n-2,j}, lambda_j = i(1-i) cot beta_j and mu_j = i(1-i) cot gamma_j
//                        read off the graphic construction of four-bar j (Q_j, P'_j, beta_j,
//                        gamma_j: geometry/construction.h); cot phi and r_{n-2}/(r_{n-1} sin phi)
//                        from the signed angle phi (docs/conventions.md §A3). Undefined where the
//                        construction breaks (Q_j or P'_j at infinity, beta_j = 0, ...: docs/conventions.md §A6),
//                        and loses digits near those places.
//   Route::ClosedForms   eq. (22) and the companion with every coefficient by its closed form of
//                        docs/conventions.md §A3 (rational functions of the side vectors): defined except at the
//                        dead centre D = 0.
//   Route::DirectSolve   the differentiated loop closure (docs/conventions.md §A2) as two 2x2 linear systems
//                          omega_{n-2} J r_{n-2} + omega_{n-1} J r_{n-1} = -sum_j omega_j J r_j
//                          omegadot_{n-2} J r_{n-2} + omegadot_{n-1} J r_{n-1}
//                              = sum_k omega_k^2 r_k - sum_j omegadot_j J r_j   (k over all sides)
//                        solved by LU with partial pivoting (not by Cramer's rule).
//   Route::SymbolicTape  evaluation of the symbolic solution derived by GiNaC and compiled to a
//                        tape (symbolic/ground_truth.h).
// Sums over ordered pairs S = sum_{j != l} a_j a_l are formed in O(n) as (sum a)^2 - sum a^2.
#pragma once

#include <array>
#include <optional>
#include <string_view>

#include "core/scalar.h"
#include "geometry/closed_forms.h"
#include "geometry/construction.h"
#include "symbolic/ground_truth.h"

namespace linkproof {

enum class Route { Construction, ClosedForms, DirectSolve, SymbolicTape };

inline constexpr std::array<Route, 4> kAllRoutes = {Route::Construction, Route::ClosedForms, Route::DirectSolve,
                                                     Route::SymbolicTape};

/// "construction", "closed-forms", "direct-solve", "symbolic-tape".
std::string_view to_string(Route r);
std::optional<Route> parse_route(std::string_view s);

/// omega-dot_{n-1,n} (eq. 22) and omega-dot_{n-2,n} (the companion) by one route.
template <class T>
struct RouteValue {
  T omega_dot_n1;  ///< omega-dot_{n-1,n}
  T omega_dot_n2;  ///< omega-dot_{n-2,n}
};

/// S = sum_{j != l} a_j a_l over ordered pairs (docs/conventions.md §A3), accumulated in O(n).
template <class T>
struct OrderedPairSum {
  T sum = from_int<T>(0), squares = from_int<T>(0);
  void add(const T& a) {
    sum += a;
    squares += a * a;
  }
  T value() const { return sum * sum - squares; }
};

/// Eq. (22) and the companion from per-side coefficients: i_out = i_{n-1,j}, i_cpl = i_{n-2,j},
/// lambda_j, mu_j, and cot phi, rho = |r_{n-2}|^2/D, rho' = |r_{n-1}|^2/D.
///   omegadot_{n-1} = sum_j (lambda_j w_j^2 + i_out_j wd_j) - cot phi S1 - rho S2
///   omegadot_{n-2} = sum_j (mu_j w_j^2 + i_cpl_j wd_j) + cot phi S2 + rho' S1
/// with S1 = sum_{j!=l} i_out_j i_out_l w_j w_l, S2 the same with i_cpl.
template <class T>
class DijksmanAccumulator {
 public:
  void add(const T& w, const T& wd, const T& i_out, const T& i_cpl, const T& lambda, const T& mu) {
    const T w2 = w * w;
    first_n1_ += lambda * w2 + i_out * wd;
    first_n2_ += mu * w2 + i_cpl * wd;
    s1_.add(i_out * w);
    s2_.add(i_cpl * w);
  }
  RouteValue<T> finish(const T& cot_phi, const T& rho, const T& rho_companion) const {
    const T s1 = s1_.value(), s2 = s2_.value();
    return {first_n1_ - cot_phi * s1 - rho * s2, first_n2_ + cot_phi * s2 + rho_companion * s1};
  }

 private:
  T first_n1_ = from_int<T>(0), first_n2_ = from_int<T>(0);
  OrderedPairSum<T> s1_, s2_;
};

/// Route (a): the paper's construction for every four-bar j. Throws UndefinedQuantity naming
/// the first construction quantity that does not exist (or D at the dead centre).
/// Per polygon, once: D, cot phi, the two rho, and the frame K_{n-2}, K_{n-1}, K_n shared by
/// every four-bar; per j, the construction steps with plain values (construct_four_bar_steps:
/// K'_j, Q_j, P'_j, the directed ratios, cot beta_j, cot gamma_j, lambda_j, mu_j). Only where a
/// step is undefined is construct_four_bar built, to name the quantity.
template <class T>
RouteValue<T> compute_by_construction(const Polygon<T>& p, const InputRates<T>& in) {
  const int n = p.n();
  const Vec2<T> a = p.side(n - 2), b = p.side(n - 1);
  const T D = cross(a, b);
  if (linkproof::is_zero(D)) throw dead_centre_error();
  // Not const: GCC 12 does not split a const aggregate that an inlined callee constructs into
  // registers ("store to a read-only decl"), and the steps would go through memory.
  FourBarFrame<T> frame = make_four_bar_frame(p);
  const std::vector<Vec2<T>>& k = p.joints();  // K_j = k[j-1]; no wrap-around for j <= n-3
  DijksmanAccumulator<T> acc;
  for (int j = 1; j <= n - 3; ++j) {
    const auto i = static_cast<size_t>(j - 1);
    FourBarSteps<T> s = construct_four_bar_steps(frame, k[i], k[i + 1] - k[i]);  // r_j = K_{j+1} - K_j
    // In the order i_{n-1,j}, i_{n-2,j}, lambda_j, mu_j, so that the name is deterministic.
    if (!s.coefficients_defined) throw_first_undefined_coefficient(p, j);
    acc.add(in.omega[i], in.omega_dot[i], s.i_out, s.i_cpl, s.lambda, s.mu);
  }
  return acc.finish(dot(a, b) / D, norm2(a) / D, norm2(b) / D);
}

/// Route (b): eq. (22) and the companion with the closed forms of docs/conventions.md §A3.
template <class T>
RouteValue<T> compute_by_closed_forms(const Polygon<T>& p, const InputRates<T>& in) {
  const ClosedForms<T> cf = compute_closed_forms(p);
  DijksmanAccumulator<T> acc;
  for (size_t k = 0; k < cf.i_out.size(); ++k)
    acc.add(in.omega[k], in.omega_dot[k], cf.i_out[k], cf.i_cpl[k], cf.lambda[k], cf.mu[k]);
  return acc.finish(cf.cot_phi, cf.rho, cf.rho_companion);
}

/// Solves [c0 c1] x = rhs (columns c0, c1) by LU with partial pivoting; throws the dead-centre
/// error if the matrix is singular in T (exactly, for exact T).
template <class T>
std::array<T, 2> solve_2x2_partial_pivoting(const Vec2<T>& c0, const Vec2<T>& c1, const Vec2<T>& rhs) {
  // Rows (c0.x, c1.x | rhs.x) and (c0.y, c1.y | rhs.y); pivot on the larger |first column|.
  const bool swap = is_less(abs_value(c0.x), abs_value(c0.y));
  const T& a00 = swap ? c0.y : c0.x;
  const T& a01 = swap ? c1.y : c1.x;
  const T& b0 = swap ? rhs.y : rhs.x;
  const T& a10 = swap ? c0.x : c0.y;
  const T& a11 = swap ? c1.x : c1.y;
  const T& b1 = swap ? rhs.x : rhs.y;
  if (is_zero(a00)) throw dead_centre_error();
  const T l = a10 / a00;
  const T u11 = a11 - l * a01;
  if (is_zero(u11)) throw dead_centre_error();
  const T x1 = (b1 - l * b0) / u11;
  return {(b0 - a01 * x1) / a00, x1};
}

/// Route (c) on any source of data: side(j) gives r_j (j = 1..n-1) and rates(k, w, wd) sets
/// omega_{k+1,n}, omega-dot_{k+1,n} (k = 0..n-4). compute_by_direct_solve and the adaptive mode
/// (which feeds doubles into tracked arithmetic without copying) share this one algorithm.
template <class T, class SideFn, class RatesFn>
RouteValue<T> direct_solve_core(int n, const SideFn& side, const RatesFn& rates) {
  const Vec2<T> a = side(n - 2), b = side(n - 1);
  Vec2<T> rhs_w{from_int<T>(0), from_int<T>(0)};
  Vec2<T> rhs_wd = rhs_w;
  for (int j = 1; j <= n - 3; ++j) {
    const Vec2<T> r = side(j);
    T w, wd;
    rates(j - 1, w, wd);
    const Vec2<T> jr = perp(r);
    rhs_w = rhs_w - w * jr;
    rhs_wd = rhs_wd + (w * w) * r - wd * jr;
  }
  const Vec2<T> ja = perp(a), jb = perp(b);
  const std::array<T, 2> x = solve_2x2_partial_pivoting(ja, jb, rhs_w);
  rhs_wd = rhs_wd + (x[0] * x[0]) * a + (x[1] * x[1]) * b;
  const std::array<T, 2> xd = solve_2x2_partial_pivoting(ja, jb, rhs_wd);
  return {xd[1], xd[0]};
}

/// Route (c): the differentiated loop closure solved directly (velocities, then accelerations).
template <class T>
RouteValue<T> compute_by_direct_solve(const Polygon<T>& p, const InputRates<T>& in) {
  return direct_solve_core<T>(
      p.n(), [&](int j) { return p.side(j); },
      [&](int k, T& w, T& wd) {
        w = in.omega[static_cast<size_t>(k)];
        wd = in.omega_dot[static_cast<size_t>(k)];
      });
}

/// Route (d): the compiled symbolic solution (derived once per n by `engine`).
template <class T>
RouteValue<T> compute_by_symbolic_tape(GroundTruthEngine& engine, const Polygon<T>& p, const InputRates<T>& in) {
  const int n = p.n();
  const PolygonMotion<T> m = engine.motion(p, in);
  return {m.omega_dot[static_cast<size_t>(n - 2)], m.omega_dot[static_cast<size_t>(n - 3)]};
}

/// Any route by name. `engine` is used by Route::SymbolicTape only.
template <class T>
RouteValue<T> compute_by_route(Route r, GroundTruthEngine& engine, const Polygon<T>& p, const InputRates<T>& in) {
  switch (r) {
    case Route::Construction: return compute_by_construction(p, in);
    case Route::ClosedForms: return compute_by_closed_forms(p, in);
    case Route::DirectSolve: return compute_by_direct_solve(p, in);
    case Route::SymbolicTape: break;
  }
  return compute_by_symbolic_tape(engine, p, in);
}

}  // namespace linkproof
