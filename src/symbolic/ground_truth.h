// The ground truth: exact angular velocities and accelerations of an n-side polygon from its
// differentiated loop closure (loop_closure.h), compiled to tapes (tape.h) and evaluated over
// any scalar type. Derivations are made once per n and cached.
//
// Term by term: the exact omega-dot of sides n-1 and n-2 is linear in the omega-dot_j and
// quadratic in the omega_j (docs/conventions.md §A4). Its coefficients are the derivatives of the solution with
// respect to the input rates,
//   [omega-dot_j] = d E / d omega-dot_j,  [omega_j^2] = (1/2) d^2 E / d omega_j^2,
//   [omega_j omega_l] = d^2 E / d omega_j d omega_l  (j < l),
// taken in forward mode: the motion tape evaluated over rate jets (rate_jet.h), O(n^2) per
// polygon. coefficient_tape() is the same derivatives taken symbolically and compiled (O(n^2)
// outputs, larger than O(n^2) to evaluate): a second route kept for cross-checks.
//
// Not thread-safe (GiNaC is not): use one engine per thread that derives, or derive first.
#pragma once

#include <map>
#include <memory>
#include <vector>

#include "core/scalar.h"
#include "geometry/closed_forms.h"
#include "symbolic/loop_closure.h"
#include "symbolic/rate_jet.h"
#include "symbolic/tape.h"

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

/// The exact omega and omega-dot of sides n-1 and n-2 as polynomials in the input rates.
template <class T>
struct SolutionTerms {
  /// Coefficients of omega_j (j = 1..n-3 at [j-1]) in omega_{n-1,n} and omega_{n-2,n}.
  std::vector<T> velocity_out, velocity_cpl;
  /// Term coefficients of omega-dot_{n-1,n} and omega-dot_{n-2,n}.
  TermCoefficients<T> out, cpl;
};

class GroundTruthEngine {
 public:
  /// What a check evaluates for n sides: the motion tape (outputs omega_{n-2}, omega_{n-1},
  /// omega-dot_{n-2}, omega-dot_{n-1}; inputs x_1..x_{n-1}, y_1..y_{n-1}, omega_j, omega_dot_j),
  /// built directly from the closed form of the solved loop closure (motion_tape.h).
  struct Derivation {
    explicit Derivation(int n);
    Tape motion;
  };
  /// GiNaC's derivation of the same (loop_closure.h): the reference the motion tape is tested
  /// against (it compiles to the same tape), and the expressions a derivation report prints.
  struct SymbolicDerivation {
    explicit SymbolicDerivation(int n);
    /// GiNaC's solution compiled: the same tape as Derivation::motion, instruction for instruction.
    Tape motion_tape() const;
    PolygonSymbols symbols;
    LoopSolution solution;
    std::vector<GiNaC::ex> inputs;      ///< the tape's inputs as symbols
    std::unique_ptr<Tape> coefficients; ///< outputs for side n-1 then n-2: [omega-dot_j], [omega_j^2], [pairs]
  };

  /// The derivation for n sides (n >= 4), made on first use.
  const Derivation& derivation(int n);
  /// GiNaC's derivation for n sides, made on first use.
  const SymbolicDerivation& symbolic_derivation(int n);
  /// The symbolically differentiated coefficient tape for n sides, made on first use (a second
  /// route to terms(): for tests, not used by checks).
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

  /// Every term coefficient of the exact solution, by forward-mode differentiation of the
  /// motion tape with respect to the rates (rate_jet.h): O(n^2). Throws UndefinedQuantity at the
  /// dead centre.
  template <class T>
  SolutionTerms<T> terms(const Polygon<T>& p) {
    const int n = p.n();
    const auto m = static_cast<size_t>(n - 3);
    TapeJetEvaluator<T> eval(derivation(n).motion, 2 * static_cast<size_t>(n - 1));
    std::vector<T> numbers = tape_inputs<T>(p, nullptr);
    numbers.resize(2 * static_cast<size_t>(n - 1));
    const std::vector<RateJet<T>> out = eval(numbers);
    // Rate variables: omega_j is j-1, omega-dot_j is m + j-1 (the tape's input order).
    auto linear = [&](const RateJet<T>& e, size_t first) {
      std::vector<T> v(m, from_int<T>(0));
      for (const auto& [var, c] : e.linear) {
        LINKPROOF_ASSERT(var >= first && var < first + m, "a rate term of the wrong kind in the solution");
        v[var - first] = c;
      }
      return v;
    };
    auto acceleration = [&](const RateJet<T>& e) {
      TermCoefficients<T> c;
      c.omega_dot = linear(e, m);
      c.omega_sq.assign(m, from_int<T>(0));
      c.omega_pair.assign(m * (m - 1) / 2, from_int<T>(0));
      for (const auto& [key, value] : e.quadratic) {
        const auto [v, w] = RateJet<T>::quadratic_vars(key);
        LINKPROOF_ASSERT(w < m, "omega-dot must be linear in omega-dot_j");
        if (v == w)
          c.omega_sq[v] = value;
        else
          c.omega_pair[pair_index(static_cast<int>(v) + 1, static_cast<int>(w) + 1, static_cast<int>(m))] = value;
      }
      return c;
    };
    SolutionTerms<T> t;
    LINKPROOF_ASSERT(out[0].quadratic.empty() && out[1].quadratic.empty(), "omega must be linear in omega_j");
    t.velocity_cpl = linear(out[0], 0);
    t.velocity_out = linear(out[1], 0);
    t.cpl = acceleration(out[2]);
    t.out = acceleration(out[3]);
    return t;
  }

  /// Term coefficients of the exact omega-dot_{n-1,n} (first) and omega-dot_{n-2,n} (second).
  template <class T>
  std::pair<TermCoefficients<T>, TermCoefficients<T>> coefficients(const Polygon<T>& p) {
    SolutionTerms<T> t = terms(p);
    return {std::move(t.out), std::move(t.cpl)};
  }

  /// The same from the symbolically differentiated coefficient tape (coefficient_tape()).
  template <class T>
  std::pair<TermCoefficients<T>, TermCoefficients<T>> coefficients_by_symbolic_derivatives(const Polygon<T>& p) {
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
  std::map<int, std::unique_ptr<SymbolicDerivation>> symbolic_cache_;
};

}  // namespace linkproof
