// Everything a claim about an n-side polygon may refer to, computed at most once per
// configuration in scalar type T, on first use: the exact ground truth (symbolic engine), the
// closed forms, the paper's construction for every input side, and the ground truth of each
// four-bar j solved on its own (the same engine at n = 4, independent of the construction).
#pragma once

#include <algorithm>
#include <cstdint>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "core/exact_sum.h"
#include "geometry/closed_forms.h"
#include "geometry/construction.h"
#include "symbolic/ground_truth.h"

namespace linkproof {

/// Four-bar j = K'_j K_{n-2} K_{n-1} K_n solved exactly by the engine.
template <class T>
struct FourBarTruth {
  Defined<T> ratio_out = Defined<T>::undefined("", "");  ///< omega_out / omega_in (unit input): eq. (4)'s i_{n-1,j}
  Defined<T> ratio_cpl = Defined<T>::undefined("", "");  ///< omega_coupler / omega_in: eq. (6)'s i_{n-2,j}
  Defined<T> omega_out = Defined<T>::undefined("", "");  ///< _j omega_{n-1,n}: output with input (omega_j, omega-dot_j)
  Defined<T> omega_cpl = Defined<T>::undefined("", "");  ///< _j omega_{n-2,n}
  Defined<T> omega_dot_out = Defined<T>::undefined("", "");  ///< _j omega-dot_{n-1,n}, eq. (9)
  Defined<T> omega_dot_cpl = Defined<T>::undefined("", "");  ///< _j omega-dot_{n-2,n}, eq. (11)
  /// Term coefficients of _j omega-dot_{n-1,n} (first) and _j omega-dot_{n-2,n} (second): of
  /// omega-dot_j (omega_dot[0]) and omega_j^2 (omega_sq[0]).
  Defined<std::pair<TermCoefficients<T>, TermCoefficients<T>>> coefficients =
      Defined<std::pair<TermCoefficients<T>, TermCoefficients<T>>>::undefined("", "");
};

/// The polygon K'_j, K_{n-2}, K_{n-1}, K_n of four-bar j.
template <class T>
Polygon<T> make_four_bar_polygon(const Polygon<T>& p, int j) {
  const int n = p.n();
  return Polygon<T>({p.joint(n - 2) - p.side(j), p.joint(n - 2), p.joint(n - 1), p.joint(n)});
}

/// Every quantity is computed on first use and kept: a claim that reads only the closed forms
/// never pays for the engine or the construction, and in a symbolic proof it never records
/// their zero tests (which would widen the exceptional set with degeneracies it does not have).
/// The engine passed at construction must outlive the context.
template <class T>
class PolygonContext {
 public:
  /// `dead_centre` says whether D = 0, decided by the caller (exactly, from the exact input or
  /// identically for symbolic coordinates): a rounded D must not turn "does not exist" into a
  /// huge number.
  PolygonContext(GroundTruthEngine& engine, Polygon<T> polygon_in, InputRates<T> rates_in, bool dead_centre)
      : n(polygon_in.n()), polygon(std::move(polygon_in)), rates(std::move(rates_in)), engine_(&engine),
        dead_centre_(dead_centre), four_bars_(static_cast<size_t>(std::max(n - 3, 0))) {}

  int n = 0;
  Polygon<T> polygon;
  InputRates<T> rates;
  /// Set where only verdicts are read (Evidence::Examples): a comparison may then leave values
  /// its verdict does not need to be made on demand (Comparison::same_value).
  bool values_on_demand = false;

  /// The engine's exact motion of the polygon.
  const Defined<PolygonMotion<T>>& truth() const {
    reads_.truth = true;
    return cached(truth_, [&] { return engine_->motion(polygon, rates); });
  }
  /// The closed forms of docs/conventions.md §A3.
  const Defined<ClosedForms<T>>& closed() const {
    reads_.closed_forms = true;
    return cached(closed_, [&] { return compute_closed_forms(polygon); });
  }
  /// Exact term coefficients of omega-dot_{n-1,n} (first) and omega-dot_{n-2,n} (second).
  const Defined<std::pair<TermCoefficients<T>, TermCoefficients<T>>>& coefficients() const {
    reads_.truth = true;
    solve_terms();
    return *coefficients_;
  }
  /// Coefficients of omega_j in the exact omega_{n-1,n} (first) and omega_{n-2,n} (second),
  /// j = 1..n-3 at [j-1].
  const Defined<std::pair<std::vector<T>, std::vector<T>>>& velocity_coefficients() const {
    reads_.truth = true;
    solve_terms();
    return *velocity_coefficients_;
  }
  /// The construction of every four-bar j = 1..n-3 (at [j-1]) under a reading (docs/conventions.md §A5; the
  /// default is the correct reading).
  const std::vector<FourBarConstruction<T>>& construction_for(const ConstructionReading& r = {}) const {
    const int key = r.displaced_start | r.beta_towards_p_prime << 1 | r.beta_ccw_positive << 2 | r.signed_ratios << 3;
    reads_.readings |= static_cast<std::uint16_t>(1u << key);
    auto it = constructions_.find(key);
    if (it == constructions_.end()) {
      // Readings that move the same points share their steps (the arithmetic): e.g. §A5.6's
      // unsigned ratios are the correct reading's values read differently.
      const int steps_key = construction_steps_key(r);
      auto steps = construction_steps_.find(steps_key);
      if (steps == construction_steps_.end()) {
        const FourBarFrame<T> frame = make_four_bar_frame(polygon);
        std::vector<FourBarSteps<T>> v;
        for (int j = 1; j <= inputs(); ++j) v.push_back(construct_four_bar_steps(frame, polygon.joint(j), polygon.side(j), r));
        steps = construction_steps_.emplace(steps_key, std::move(v)).first;
      }
      std::vector<FourBarConstruction<T>> v;
      for (int j = 1; j <= inputs(); ++j) v.push_back(construction_from_steps(steps->second[static_cast<size_t>(j - 1)], j, r));
      it = constructions_.emplace(key, std::move(v)).first;
    }
    return it->second;
  }
  /// Four-bar j (1 <= j <= n-3) solved on its own by the engine.
  const FourBarTruth<T>& four_bar(int j) const {
    reads_.four_bar_truth = true;
    std::optional<FourBarTruth<T>>& slot = four_bars_[static_cast<size_t>(j - 1)];
    if (!slot) slot = solve_four_bar(j);
    return *slot;
  }

  /// Sides and rates by the paper's 1-based indices.
  Vec2<T> r(int j) const { return polygon.side(j); }
  const T& omega_in(int j) const { return rates.omega[static_cast<size_t>(j - 1)]; }
  const T& omega_dot_in(int j) const { return rates.omega_dot[static_cast<size_t>(j - 1)]; }
  int inputs() const { return n - 3; }

  /// What has been computed so far, without computing anything.
  bool has_truth() const { return truth_.has_value() || velocity_coefficients_.has_value() || coefficients_.has_value(); }
  bool has_closed_forms() const { return closed_.has_value(); }
  bool has_four_bar_truth() const {
    return std::any_of(four_bars_.begin(), four_bars_.end(), [](const auto& f) { return f.has_value(); });
  }
  /// The constructions computed so far, by reading.
  const std::map<int, std::vector<FourBarConstruction<T>>>& computed_constructions() const { return constructions_; }

  /// What was read since the last clear_reads(), whether computed then or before: which
  /// quantities one claim reads on a context that other claims share (check/inconclusive_cause.h
  /// names among them the one that made a comparison inconclusive). Reading a quantity records it,
  /// also when its computation ends in an exception.
  struct Reads {
    bool truth = false;           ///< the engine's motion or its term coefficients
    bool closed_forms = false;
    bool four_bar_truth = false;  ///< some four-bar j solved on its own
    std::uint16_t readings = 0;   ///< bit k: the construction under reading k (construction_for's key)
  };
  const Reads& reads() const { return reads_; }
  void clear_reads() const { reads_ = Reads{}; }

 private:
  /// f() unless at the dead centre, as a Defined (an UndefinedQuantity becomes undefined).
  template <class V, class F>
  Defined<V> attempt_unless_dead_centre(const F& f) const {
    return Defined<V>::attempt([&]() -> V {
      if (dead_centre_) throw dead_centre_error();
      return f();
    });
  }
  template <class V, class F>
  const Defined<V>& cached(std::optional<Defined<V>>& slot, const F& f) const {
    if (!slot) slot = attempt_unless_dead_centre<V>(f);
    return *slot;
  }

  /// Both coefficient sets from one forward-mode differentiation of the engine's solution
  /// (GroundTruthEngine::terms, O(n^2)).
  void solve_terms() const {
    if (coefficients_) return;
    const Defined<SolutionTerms<T>> t = attempt_unless_dead_centre<SolutionTerms<T>>([&] { return engine_->terms(polygon); });
    if (t.has_value()) {
      coefficients_ = std::pair(t.get().out, t.get().cpl);
      velocity_coefficients_ = std::pair(t.get().velocity_out, t.get().velocity_cpl);
    } else {
      coefficients_ = Defined<std::pair<TermCoefficients<T>, TermCoefficients<T>>>::undefined(t.quantity(), t.reason());
      velocity_coefficients_ = Defined<std::pair<std::vector<T>, std::vector<T>>>::undefined(t.quantity(), t.reason());
    }
  }

  // Four-bar j shares r_{n-2} and r_{n-1}, hence D, so it is at its dead centre too.
  FourBarTruth<T> solve_four_bar(int j) const {
    const Polygon<T> fb = make_four_bar_polygon(polygon, j);
    if constexpr (GrowingExactNumber<T>)
      return solve_four_bar_from_terms(fb, j);
    else
      return solve_four_bar_by_motion(fb, j);
  }

  // The motion at unit input rates (the ratios), at the polygon's rates, and the term
  // coefficients: three evaluations of the engine, whose bits and bounds floating point prints.
  FourBarTruth<T> solve_four_bar_by_motion(const Polygon<T>& fb, int j) const {
    const T zero = from_int<T>(0), one = from_int<T>(1);
    FourBarTruth<T> t;
    const auto unit = attempt_unless_dead_centre<PolygonMotion<T>>(
        [&] { return engine_->motion(fb, InputRates<T>{{one}, {zero}}); });
    const auto real = attempt_unless_dead_centre<PolygonMotion<T>>(
        [&] { return engine_->motion(fb, InputRates<T>{{omega_in(j)}, {omega_dot_in(j)}}); });
    t.ratio_out = Defined<T>::attempt([&] { return unit.get().omega[2]; });
    t.ratio_cpl = Defined<T>::attempt([&] { return unit.get().omega[1]; });
    t.omega_out = Defined<T>::attempt([&] { return real.get().omega[2]; });
    t.omega_cpl = Defined<T>::attempt([&] { return real.get().omega[1]; });
    t.omega_dot_out = Defined<T>::attempt([&] { return real.get().omega_dot[2]; });
    t.omega_dot_cpl = Defined<T>::attempt([&] { return real.get().omega_dot[1]; });
    t.coefficients = attempt_unless_dead_centre<std::pair<TermCoefficients<T>, TermCoefficients<T>>>(
        [&] { return engine_->coefficients(fb); });
    return t;
  }

  // Exact values are unique, so the four-bar's motion follows from one differentiation of its
  // solution (GroundTruthEngine::terms) in place of two more evaluations of the motion (the
  // four-bars were a tenth of an exact pentagon check, a third less now; callgrind, docs/
  // performance.md): omega_out = i omega_j with the velocity coefficient
  // i, and omega-dot_out = c_dot omega-dot_j + c_sq omega_j^2 (a one-input four-bar has no other
  // term). Floating point keeps the three evaluations, whose bits and bounds its outputs print.
  FourBarTruth<T> solve_four_bar_from_terms(const Polygon<T>& fb, int j) const {
    const Defined<SolutionTerms<T>> terms = attempt_unless_dead_centre<SolutionTerms<T>>([&] { return engine_->terms(fb); });
    const T& w = omega_in(j);
    const T& wd = omega_dot_in(j);
    const auto omega_dot = [&](const TermCoefficients<T>& c) { return c.omega_dot[0] * wd + c.omega_sq[0] * (w * w); };
    FourBarTruth<T> t;
    t.ratio_out = Defined<T>::attempt([&] { return terms.get().velocity_out[0]; });
    t.ratio_cpl = Defined<T>::attempt([&] { return terms.get().velocity_cpl[0]; });
    t.omega_out = Defined<T>::attempt([&] { return terms.get().velocity_out[0] * w; });
    t.omega_cpl = Defined<T>::attempt([&] { return terms.get().velocity_cpl[0] * w; });
    t.omega_dot_out = Defined<T>::attempt([&] { return omega_dot(terms.get().out); });
    t.omega_dot_cpl = Defined<T>::attempt([&] { return omega_dot(terms.get().cpl); });
    t.coefficients = Defined<std::pair<TermCoefficients<T>, TermCoefficients<T>>>::attempt(
        [&] { return std::pair(terms.get().out, terms.get().cpl); });
    return t;
  }

  GroundTruthEngine* engine_;
  bool dead_centre_ = false;
  mutable std::optional<Defined<PolygonMotion<T>>> truth_;
  mutable std::optional<Defined<ClosedForms<T>>> closed_;
  mutable std::optional<Defined<std::pair<TermCoefficients<T>, TermCoefficients<T>>>> coefficients_;
  mutable std::optional<Defined<std::pair<std::vector<T>, std::vector<T>>>> velocity_coefficients_;
  mutable std::map<int, std::vector<FourBarConstruction<T>>> constructions_;
  /// construct_four_bar_steps of every four-bar, by construction_steps_key (construction_for).
  mutable std::map<int, std::vector<FourBarSteps<T>>> construction_steps_;
  mutable std::vector<std::optional<FourBarTruth<T>>> four_bars_;
  mutable Reads reads_;
};

/// Builds the context from a polygon and rates already in scalar type T (see the constructor).
template <class T>
PolygonContext<T> build_polygon_context_from(GroundTruthEngine& engine, Polygon<T> polygon, InputRates<T> rates,
                                             bool dead_centre) {
  return PolygonContext<T>(engine, std::move(polygon), std::move(rates), dead_centre);
}

/// Builds the context in scalar type T from exact input (each exact number is converted once;
/// the dead centre is decided exactly, whatever T is).
template <class T>
PolygonContext<T> build_polygon_context(GroundTruthEngine& engine, const Polygon<Rational>& exact,
                                        const InputRates<Rational>& exact_rates) {
  return build_polygon_context_from<T>(engine, exact.convert<T>(), exact_rates.convert<T>(),
                                       cln::zerop(exact.dead_centre_determinant()));
}

}  // namespace linkproof
