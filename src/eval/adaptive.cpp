#include "linkproof/eval/adaptive.h"

#include <cmath>
#include <limits>

#include "linkproof/eval/routes.h"

namespace linkproof {

std::string_view to_string(AdaptiveLevel l) {
  switch (l) {
    case AdaptiveLevel::Double: return "double";
    case AdaptiveLevel::LongDouble: return "long double";
    case AdaptiveLevel::Exact: break;
  }
  return "exact";
}

double round_to_nearest_double(const Rational& q) {
  double best = cln::double_approx(q);
  if (!std::isfinite(best)) return best;
  Rational best_err = cln::abs(q - exact_value_of(best));
  for (double c : {std::nextafter(best, -HUGE_VAL), std::nextafter(best, HUGE_VAL)}) {
    if (!std::isfinite(c)) continue;
    const Rational err = cln::abs(q - exact_value_of(c));
    int mant_exp = 0;
    const bool even = std::fmod(std::ldexp(std::frexp(c, &mant_exp), 53), 2.0) == 0;
    if (err < best_err || (err == best_err && even)) {
      best = c;
      best_err = err;
    }
  }
  return best;
}

namespace {

/// Double upper bound of a nonnegative rational.
double round_up(const Rational& q) {
  double d = cln::double_approx(q);
  if (exact_value_of(d) < q) d = std::nextafter(d, HUGE_VAL);
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
  // e plus the rounding of v to double, rounded up.
  const F total = x.e + std::abs(static_cast<F>(value) - x.v);
  bound = std::nextafter(static_cast<double>(total), HUGE_VAL);
  return bound <= tolerance * std::abs(value) && std::isfinite(bound);
}

template <class F>
bool try_stage(const Polygon<double>& p, const InputRates<double>& in, const AdaptiveOptions& o, AdaptiveResult& r) {
  using T = Tracked<F>;
  // Inputs are exact (radius 0); sides are formed in tracked arithmetic, so their rounding is
  // bounded too. No copies of the polygon: the route reads the doubles in place.
  const auto exact = [](double x) { return T(static_cast<F>(x), 0); };
  const auto side = [&](int j) {
    const Vec2<double>& k0 = p.joint(j);
    const Vec2<double>& k1 = p.joint(j + 1);
    return Vec2<T>{exact(k1.x) - exact(k0.x), exact(k1.y) - exact(k0.y)};
  };
  const auto rates = [&](int k, T& w, T& wd) {
    w = exact(in.omega[static_cast<size_t>(k)]);
    wd = exact(in.omega_dot[static_cast<size_t>(k)]);
  };
  RouteValue<T> v;
  try {
    v = direct_solve_core<T>(p.n(), side, rates);
  } catch (const UndefinedQuantity&) {
    return false;  // a pivot is exactly zero in F: let the exact stage decide
  }
  if (o.relative_tolerance == 0) {
    if (!rounds_uniquely(v.omega_dot_n1, r.omega_dot_n1) || !rounds_uniquely(v.omega_dot_n2, r.omega_dot_n2))
      return false;
    // The exact value lies in [v - e, v + e], which rounds entirely to the returned double.
    r.bound_n1 = std::nextafter(static_cast<double>(v.omega_dot_n1.e + std::abs(v.omega_dot_n1.v - static_cast<F>(r.omega_dot_n1))), HUGE_VAL);
    r.bound_n2 = std::nextafter(static_cast<double>(v.omega_dot_n2.e + std::abs(v.omega_dot_n2.v - static_cast<F>(r.omega_dot_n2))), HUGE_VAL);
    r.correctly_rounded = true;
    return true;
  }
  return certified_bound(v.omega_dot_n1, o.relative_tolerance, r.omega_dot_n1, r.bound_n1) &&
         certified_bound(v.omega_dot_n2, o.relative_tolerance, r.omega_dot_n2, r.bound_n2);
}

}  // namespace

AdaptiveResult compute_omega_dot_adaptive(const Polygon<double>& polygon, const InputRates<double>& rates,
                                          const AdaptiveOptions& options) {
  AdaptiveResult r;
  r.level = AdaptiveLevel::Double;
  if (try_stage<double>(polygon, rates, options, r)) return r;
  r = {};
  r.level = AdaptiveLevel::LongDouble;
  if (try_stage<long double>(polygon, rates, options, r)) return r;
  r = {};
  r.level = AdaptiveLevel::Exact;
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
