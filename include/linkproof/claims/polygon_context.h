// Everything a claim about an n-side polygon may refer to, computed once per configuration in
// scalar type T: the exact ground truth (symbolic engine), the closed forms, the paper's
// construction for every input side, and the ground truth of each four-bar j solved on its
// own (the same engine at n = 4, independent of the construction).
#pragma once

#include <map>
#include <utility>
#include <vector>

#include "linkproof/geometry/closed_forms.h"
#include "linkproof/geometry/construction.h"
#include "linkproof/symbolic/ground_truth.h"

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

template <class T>
struct PolygonContext {
  int n = 0;
  Polygon<T> polygon;
  InputRates<T> rates;
  Defined<PolygonMotion<T>> truth = Defined<PolygonMotion<T>>::undefined("", "");
  Defined<ClosedForms<T>> closed = Defined<ClosedForms<T>>::undefined("", "");
  /// Exact term coefficients of omega-dot_{n-1,n} (first) and omega-dot_{n-2,n} (second).
  Defined<std::pair<TermCoefficients<T>, TermCoefficients<T>>> coefficients =
      Defined<std::pair<TermCoefficients<T>, TermCoefficients<T>>>::undefined("", "");
  /// Coefficients of omega_j in the exact omega_{n-1,n} (first) and omega_{n-2,n} (second),
  /// j = 1..n-3 at [j-1]: the engine's motion for a unit input j.
  Defined<std::pair<std::vector<T>, std::vector<T>>> velocity_coefficients =
      Defined<std::pair<std::vector<T>, std::vector<T>>>::undefined("", "");
  std::vector<FourBarConstruction<T>> construction;  ///< j = 1..n-3 at [j-1], correct reading
  std::vector<FourBarTruth<T>> four_bars;            ///< j = 1..n-3 at [j-1]

  /// The construction under another reading (SPEC A5), built on first use and kept.
  const std::vector<FourBarConstruction<T>>& construction_for(const ConstructionReading& r) const {
    const int key = r.displaced_start | r.beta_towards_p_prime << 1 | r.beta_ccw_positive << 2 | r.signed_ratios << 3;
    if (key == 15) return construction;
    auto it = other_readings_.find(key);
    if (it == other_readings_.end()) {
      std::vector<FourBarConstruction<T>> v;
      for (int j = 1; j <= inputs(); ++j) v.push_back(construct_four_bar(polygon, j, r));
      it = other_readings_.emplace(key, std::move(v)).first;
    }
    return it->second;
  }

  /// Sides and rates by the paper's 1-based indices.
  Vec2<T> r(int j) const { return polygon.side(j); }
  const T& omega_in(int j) const { return rates.omega[static_cast<size_t>(j - 1)]; }
  const T& omega_dot_in(int j) const { return rates.omega_dot[static_cast<size_t>(j - 1)]; }
  int inputs() const { return n - 3; }

 private:
  mutable std::map<int, std::vector<FourBarConstruction<T>>> other_readings_;
};

/// The polygon K'_j, K_{n-2}, K_{n-1}, K_n of four-bar j.
template <class T>
Polygon<T> make_four_bar_polygon(const Polygon<T>& p, int j) {
  const int n = p.n();
  return Polygon<T>({p.joint(n - 2) - p.side(j), p.joint(n - 2), p.joint(n - 1), p.joint(n)});
}

/// Builds the context from a polygon and rates already in scalar type T. `dead_centre` says
/// whether D = 0, decided by the caller (exactly, from the exact input or identically for
/// symbolic coordinates): a rounded D must not turn "does not exist" into a huge number.
template <class T>
PolygonContext<T> build_polygon_context_from(GroundTruthEngine& engine, Polygon<T> polygon, InputRates<T> rates,
                                             bool dead_centre) {
  PolygonContext<T> c;
  c.n = polygon.n();
  c.polygon = std::move(polygon);
  c.rates = std::move(rates);
  // Four-bar j shares r_{n-2} and r_{n-1}, hence D, so it is at its dead centre too.
  const auto unless_dead_centre = [dead_centre](auto&& f) {
    if (dead_centre) throw dead_centre_error();
    return f();
  };
  c.truth = Defined<PolygonMotion<T>>::attempt(
      [&] { return unless_dead_centre([&] { return engine.motion(c.polygon, c.rates); }); });
  c.closed = Defined<ClosedForms<T>>::attempt(
      [&] { return unless_dead_centre([&] { return compute_closed_forms(c.polygon); }); });
  c.coefficients = Defined<std::pair<TermCoefficients<T>, TermCoefficients<T>>>::attempt(
      [&] { return unless_dead_centre([&] { return engine.coefficients(c.polygon); }); });
  const T zero = from_int<T>(0), one = from_int<T>(1);
  c.velocity_coefficients = Defined<std::pair<std::vector<T>, std::vector<T>>>::attempt([&] {
    return unless_dead_centre([&] {
      std::pair<std::vector<T>, std::vector<T>> v;
      for (int j = 1; j <= c.n - 3; ++j) {
        InputRates<T> unit{std::vector<T>(static_cast<size_t>(c.n - 3), zero), std::vector<T>(static_cast<size_t>(c.n - 3), zero)};
        unit.omega[static_cast<size_t>(j - 1)] = one;
        const PolygonMotion<T> m = engine.motion(c.polygon, unit);
        v.first.push_back(m.omega[static_cast<size_t>(c.n - 2)]);
        v.second.push_back(m.omega[static_cast<size_t>(c.n - 3)]);
      }
      return v;
    });
  });
  for (int j = 1; j <= c.n - 3; ++j) {
    c.construction.push_back(construct_four_bar(c.polygon, j));
    const Polygon<T> fb = make_four_bar_polygon(c.polygon, j);
    FourBarTruth<T> t;
    const auto unit = Defined<PolygonMotion<T>>::attempt(
        [&] { return unless_dead_centre([&] { return engine.motion(fb, InputRates<T>{{one}, {zero}}); }); });
    const auto real = Defined<PolygonMotion<T>>::attempt([&] {
      return unless_dead_centre([&] { return engine.motion(fb, InputRates<T>{{c.omega_in(j)}, {c.omega_dot_in(j)}}); });
    });
    t.ratio_out = Defined<T>::attempt([&] { return unit.get().omega[2]; });
    t.ratio_cpl = Defined<T>::attempt([&] { return unit.get().omega[1]; });
    t.omega_out = Defined<T>::attempt([&] { return real.get().omega[2]; });
    t.omega_cpl = Defined<T>::attempt([&] { return real.get().omega[1]; });
    t.omega_dot_out = Defined<T>::attempt([&] { return real.get().omega_dot[2]; });
    t.omega_dot_cpl = Defined<T>::attempt([&] { return real.get().omega_dot[1]; });
    t.coefficients = Defined<std::pair<TermCoefficients<T>, TermCoefficients<T>>>::attempt(
        [&] { return unless_dead_centre([&] { return engine.coefficients(fb); }); });
    c.four_bars.push_back(std::move(t));
  }
  return c;
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
