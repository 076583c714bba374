// The ground truth: exact angular velocities and accelerations of an n-side polygon from its
// differentiated loop closure (loop_closure.h), compiled to tapes (tape.h) and evaluated over
// any scalar type. Derivations are made once per n and cached.
//
// Term by term: the exact omega-dot of sides n-1 and n-2 is linear in the omega-dot_j and
// quadratic in the omega_j (SPEC A4). Its coefficients are derived symbolically by
// differentiating the solution with respect to the input rates,
//   [omega-dot_j] = d E / d omega-dot_j,  [omega_j^2] = (1/2) d^2 E / d omega_j^2,
//   [omega_j omega_l] = d^2 E / d omega_j d omega_l  (j < l),
// and compiled into a second tape (built on first use: it has O(n^2) outputs).
//
// Not thread-safe (GiNaC is not): use one engine per thread that derives, or derive first.
#pragma once

#include <map>
#include <memory>
#include <vector>

#include "linkproof/geometry/closed_forms.h"
#include "linkproof/symbolic/loop_closure.h"
#include "linkproof/symbolic/tape.h"

namespace linkproof {

/// Index of the unordered input pair (j, l), 1 <= j < l <= m, in row-major order.
inline size_t pair_index(int j, int l, int m) {
  // pairs with first index < j: sum_{a=1}^{j-1} (m - a)
  return static_cast<size_t>((j - 1) * m - (j - 1) * j / 2 + (l - j - 1));
}

/// Coefficients of one exact omega-dot as a polynomial in the input rates.
template <class T>
struct TermCoefficients {
  std::vector<T> omega_dot;   ///< of omega-dot_j, j = 1..n-3 (0-based)
  std::vector<T> omega_sq;    ///< of omega_j^2
  std::vector<T> omega_pair;  ///< of omega_j omega_l, j < l, at pair_index(j, l, n-3)
};

class GroundTruthEngine {
 public:
  struct Derivation {
    explicit Derivation(int n);
    PolygonSymbols symbols;
    LoopSolution solution;
    std::vector<GiNaC::ex> inputs;    ///< tape inputs: x_1..x_{n-1}, y_1..y_{n-1}, omega_j, omega_dot_j
    Tape motion;                        ///< outputs omega_{n-2}, omega_{n-1}, omega-dot_{n-2}, omega-dot_{n-1}
    std::unique_ptr<Tape> coefficients; ///< outputs for side n-1 then n-2: [omega-dot_j], [omega_j^2], [pairs]
  };

  /// The derivation for n sides (n >= 4), made on first use.
  const Derivation& derivation(int n);
  /// The coefficient tape for n sides, made on first use.
  const Tape& coefficient_tape(int n);

  /// omega and omega-dot of all n sides relative to side n (side n itself 0).
  /// Throws UndefinedQuantity at the dead centre.
  template <class T>
  PolygonMotion<T> motion(const Polygon<T>& p, const InputRates<T>& in) {
    const int n = p.n();
    const Derivation& d = derivation(n);
    TapeEvaluator<T> eval(d.motion);
    const std::vector<T> out = eval(tape_inputs(p, &in));
    PolygonMotion<T> m{in.omega, in.omega_dot};
    m.omega.push_back(out[0]);
    m.omega.push_back(out[1]);
    m.omega.push_back(from_int<T>(0));
    m.omega_dot.push_back(out[2]);
    m.omega_dot.push_back(out[3]);
    m.omega_dot.push_back(from_int<T>(0));
    return m;
  }

  /// Term coefficients of the exact omega-dot_{n-1,n} (first) and omega-dot_{n-2,n} (second).
  template <class T>
  std::pair<TermCoefficients<T>, TermCoefficients<T>> coefficients(const Polygon<T>& p) {
    const int n = p.n(), m = n - 3;
    TapeEvaluator<T> eval(coefficient_tape(n));
    const std::vector<T> out = eval(tape_inputs<T>(p, nullptr));
    const size_t pairs = static_cast<size_t>(m * (m - 1) / 2), block = 2 * static_cast<size_t>(m) + pairs;
    auto slice = [&](size_t base) {
      TermCoefficients<T> c;
      c.omega_dot.assign(out.begin() + base, out.begin() + base + m);
      c.omega_sq.assign(out.begin() + base + m, out.begin() + base + 2 * m);
      c.omega_pair.assign(out.begin() + base + 2 * m, out.begin() + base + block);
      return c;
    };
    return {slice(0), slice(block)};
  }

 private:
  template <class T>
  static std::vector<T> tape_inputs(const Polygon<T>& p, const InputRates<T>* in) {
    const int n = p.n();
    std::vector<T> v;
    v.reserve(static_cast<size_t>(2 * (n - 1) + 2 * (n - 3)));
    for (int j = 1; j <= n - 1; ++j) v.push_back(p.side(j).x);
    for (int j = 1; j <= n - 1; ++j) v.push_back(p.side(j).y);
    for (int j = 0; j < n - 3; ++j) v.push_back(in ? in->omega[j] : from_int<T>(0));
    for (int j = 0; j < n - 3; ++j) v.push_back(in ? in->omega_dot[j] : from_int<T>(0));
    return v;
  }

  std::map<int, std::unique_ptr<Derivation>> cache_;
};

}  // namespace linkproof
