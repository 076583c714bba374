#include "numerics/adaptive.h"

#include <cmath>
#include <limits>

#include <optional>
#include <type_traits>
#include <vector>

#include "core/a_priori_bound.h"
#include "numerics/omega_dot_fraction.h"
#include "numerics/routes.h"

namespace linkproof {

std::string_view to_string(AdaptiveLevel l) {
  switch (l) {
    case AdaptiveLevel::Double: return "double";
    case AdaptiveLevel::LongDouble: return "long double";
    case AdaptiveLevel::Exact: break;
  }
  return "exact";
}

std::string_view to_string(AdaptiveStage s) {
  switch (s) {
    case AdaptiveStage::APrioriDouble: return "a priori double";
    case AdaptiveStage::RunningDouble: return "running double";
    case AdaptiveStage::RunningLongDouble: return "running long double";
    case AdaptiveStage::Exact: break;
  }
  return "exact";
}

double round_to_nearest_double(const Rational& q) { return round_rational<double>(q); }

namespace {

/// Double upper bound of a nonnegative rational.
double round_up(const Rational& q) {
  double d = round_rational<double>(q);
  if (std::isfinite(d) && exact_value_of(d) < q) d = std::nextafter(d, HUGE_VAL);
  return d;
}

/// Is every real in [v - e, v + e] rounded to the same double? Then that double is certified.
template <class F>
bool rounds_uniquely(const Tracked<F>& x, double& out) {
  if (!std::isfinite(x.v) || !std::isfinite(x.e)) return false;
  // Widen outwards by one ulp of F to absorb the rounding of v +- e itself.
  const F lo = std::nextafter(x.v - x.e, -std::numeric_limits<F>::infinity());
  const F hi = std::nextafter(x.v + x.e, std::numeric_limits<F>::infinity());
  const double dlo = static_cast<double>(lo), dhi = static_cast<double>(hi);
  if (dlo != dhi) return false;
  out = dlo;
  return true;
}

/// Absolute bound of |exact - double(v)|, from a tracked value in F (>= double).
template <class F>
bool certified_bound(const Tracked<F>& x, double tolerance, double& value, double& bound) {
  if (!std::isfinite(x.v) || !std::isfinite(x.e)) return false;
  value = static_cast<double>(x.v);
  if constexpr (std::is_same_v<F, double>) {
    bound = x.e;  // v is already a double: nothing more to round
  } else {
    // e plus the rounding of v to double, rounded up.
    // |v - double(v)| is exact in F (at most half an ulp of double, a multiple of v's ulp).
    bound = round_up_to_double(TrackedTraits<F>::add_up(x.e, std::abs(static_cast<F>(value) - x.v)));
  }
  return bound <= tolerance * std::abs(value) && std::isfinite(bound);
}

/// The polygon's joints and rates read in place as exact numbers of type T.
template <class T, class Exact>
auto side_reader(const Polygon<double>& p, const Exact& exact) {
  return [&p, exact](int j) {
    const Vec2<double>& k0 = p.joint(j);
    const Vec2<double>& k1 = p.joint(j + 1);
    return Vec2<T>{exact(k1.x) - exact(k0.x), exact(k1.y) - exact(k0.y)};
  };
}
template <class T, class Exact>
auto rates_reader(const InputRates<double>& in, const Exact& exact) {
  return [&in, exact](int k, T& w, T& wd) {
    w = exact(in.omega[static_cast<size_t>(k)]);
    wd = exact(in.omega_dot[static_cast<size_t>(k)]);
  };
}

/// Accepts the stage's two tracked results if they meet the request (see the file comment of
/// adaptive.h); fills r.
template <class F>
bool accept(const Tracked<F>& n1, const Tracked<F>& n2, const AdaptiveOptions& o, AdaptiveResult& r) {
  if (o.relative_tolerance == 0) {
    if (!rounds_uniquely(n1, r.omega_dot_n1) || !rounds_uniquely(n2, r.omega_dot_n2)) return false;
    // The exact value lies in [v - e, v + e], which rounds entirely to the returned double.
    r.bound_n1 = round_up_to_double(TrackedTraits<F>::add_up(n1.e, std::abs(n1.v - static_cast<F>(r.omega_dot_n1))));
    r.bound_n2 = round_up_to_double(TrackedTraits<F>::add_up(n2.e, std::abs(n2.v - static_cast<F>(r.omega_dot_n2))));
    r.correctly_rounded = true;
    return true;
  }
  return certified_bound(n1, o.relative_tolerance, r.omega_dot_n1, r.bound_n1) &&
         certified_bound(n2, o.relative_tolerance, r.omega_dot_n2, r.bound_n2);
}

/// The a priori bound factor 1.001 k u of each part of compute_omega_dot_parts for n sides
/// (core/a_priori_bound.h), from the parts' depths k: data-independent, so one O(n) integer
/// pass per n and arithmetic, cached per thread. Infinite where k u > 2^-20.
template <class F>
const OmegaDotParts<F>& part_bound_factors(int n) {
  thread_local std::vector<std::optional<OmegaDotParts<F>>> cache;
  const auto i = static_cast<size_t>(n);
  if (cache.size() <= i) cache.resize(i + 1);
  if (!cache[i]) {
    // Sides are once-rounded differences of exact joints (depth 1); rates are exact (depth 0).
    const OmegaDotParts<OperationDepth> k = compute_omega_dot_parts<OperationDepth>(
        n, [](int) { return Vec2<OperationDepth>{{1}, {1}}; },
        [](int, OperationDepth& w, OperationDepth& wd) { w = wd = OperationDepth{0}; });
    // The bound of a value with shadow 1 is its factor.
    const auto f = [](OperationDepth d) { return a_priori_error_bound(ShadowedFloat<F>::rounded_once(F(1)), d.k); };
    cache[i] = OmegaDotParts<F>{f(k.d),    f(k.x0),     f(k.x1),     f(k.a_n1),
                                f(k.a_n2), f(k.norm_a), f(k.norm_b), f(k.a_dot_b)};
  }
  return *cache[i];
}

/// Stage 1: the parts of the division-free fraction in ShadowedFloat<F> with a priori bounds,
/// combined and divided in Tracked<F> (see numerics/omega_dot_fraction.h for why the split).
/// A non-finite shadow or factor gives a non-finite radius, which accept() rejects.
template <class F>
bool try_a_priori(const Polygon<double>& p, const InputRates<double>& in, const AdaptiveOptions& o, AdaptiveResult& r) {
  using S = ShadowedFloat<F>;
  const std::vector<Vec2<double>>& k = p.joints();
  // Sides enter as once-rounded differences (depth 1, as part_bound_factors counts them); j + 1
  // <= n - 1 here, so no index wraps around.
  const auto side = [&k](int j) {
    const Vec2<double>& k0 = k[static_cast<size_t>(j - 1)];
    const Vec2<double>& k1 = k[static_cast<size_t>(j)];
    return Vec2<S>{S::rounded_once(static_cast<F>(k1.x) - static_cast<F>(k0.x)),
                   S::rounded_once(static_cast<F>(k1.y) - static_cast<F>(k0.y))};
  };
  const auto exact = [](double x) { return S::exact(static_cast<F>(x)); };
  const OmegaDotParts<S> s = compute_omega_dot_parts<S>(p.n(), side, rates_reader<S>(in, exact));
  const OmegaDotParts<F>& c = part_bound_factors<F>(p.n());
  using T = Tracked<F>;
  const OmegaDotParts<T> t{T(s.d.v, c.d * s.d.m),          T(s.x0.v, c.x0 * s.x0.m),
                           T(s.x1.v, c.x1 * s.x1.m),       T(s.a_n1.v, c.a_n1 * s.a_n1.m),
                           T(s.a_n2.v, c.a_n2 * s.a_n2.m), T(s.norm_a.v, c.norm_a * s.norm_a.m),
                           T(s.norm_b.v, c.norm_b * s.norm_b.m), T(s.a_dot_b.v, c.a_dot_b * s.a_dot_b.m)};
  const OmegaDotFraction<T> f = combine_omega_dot_parts(t);
  const T inverse = T(1) / f.denominator;  // one bounded division for both accelerations
  return accept(f.numerator_n1 * inverse, f.numerator_n2 * inverse, o, r);
}

/// Stages 2 and 3: the direct solve in Tracked<F> (running error bound).
template <class F>
bool try_running(const Polygon<double>& p, const InputRates<double>& in, const AdaptiveOptions& o, AdaptiveResult& r) {
  using T = Tracked<F>;
  const auto exact = [](double x) { return T(static_cast<F>(x), 0); };
  RouteValue<T> v;
  try {
    v = direct_solve_core<T>(p.n(), side_reader<T>(p, exact), rates_reader<T>(in, exact));
  } catch (const UndefinedQuantity&) {
    return false;  // a pivot is exactly zero in F: let the exact stage decide
  }
  return accept(v.omega_dot_n1, v.omega_dot_n2, o, r);
}

}  // namespace

AdaptiveResult compute_omega_dot_adaptive(const Polygon<double>& polygon, const InputRates<double>& rates,
                                          const AdaptiveOptions& options) {
  AdaptiveResult r;
  r.level = AdaptiveLevel::Double;
  r.stage = AdaptiveStage::APrioriDouble;
  if (try_a_priori<double>(polygon, rates, options, r)) return r;
  r = {};
  r.level = AdaptiveLevel::Double;
  r.stage = AdaptiveStage::RunningDouble;
  if (try_running<double>(polygon, rates, options, r)) return r;
  r = {};
  r.level = AdaptiveLevel::LongDouble;
  r.stage = AdaptiveStage::RunningLongDouble;
  if (try_running<long double>(polygon, rates, options, r)) return r;
  r = {};
  r.level = AdaptiveLevel::Exact;
  r.stage = AdaptiveStage::Exact;
  std::vector<Vec2<Rational>> joints;
  for (const auto& k : polygon.joints()) joints.push_back({exact_value_of(k.x), exact_value_of(k.y)});
  InputRates<Rational> in;
  for (double w : rates.omega) in.omega.push_back(exact_value_of(w));
  for (double w : rates.omega_dot) in.omega_dot.push_back(exact_value_of(w));
  try {
    const RouteValue<Rational> v = compute_by_direct_solve(Polygon<Rational>(std::move(joints)), in);
    r.omega_dot_n1 = round_to_nearest_double(v.omega_dot_n1);
    r.omega_dot_n2 = round_to_nearest_double(v.omega_dot_n2);
    r.bound_n1 = round_up(cln::abs(v.omega_dot_n1 - exact_value_of(r.omega_dot_n1)));
    r.bound_n2 = round_up(cln::abs(v.omega_dot_n2 - exact_value_of(r.omega_dot_n2)));
    r.correctly_rounded = std::isfinite(r.omega_dot_n1) && std::isfinite(r.omega_dot_n2);
  } catch (const UndefinedQuantity& u) {
    r.defined = false;
    r.undefined_quantity = u.quantity();
  }
  return r;
}

}  // namespace linkproof
