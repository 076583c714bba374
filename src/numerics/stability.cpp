#include "numerics/stability.h"

#include <cmath>
#include <limits>

#include "numerics/ladder.h"

namespace linkproof {

namespace {

template <class T>
RouteMeasurement measure_route(Route route, GroundTruthEngine& engine, const Polygon<Rational>& polygon,
                               const InputRates<Rational>& rates, const CaseStudy& truth, double budget) {
  RouteMeasurement m;
  m.route = route;
  m.arithmetic = arithmetic_name<T>();
  m.precision_bits = precision_bits<T>();
  if (!truth.exact_n1) {
    m.defined = false;
    m.undefined_quantity = "D = r_{n-2} x r_{n-1}";
    m.reason = truth.truth_undefined_reason;
    return m;
  }
  const Polygon<T> p = polygon.convert<T>();
  const InputRates<T> in = rates.convert<T>();
  try {
    const RouteValue<T> v = compute_by_route(route, engine, p, in);
    m.n1 = measure_error(to_exact(v.omega_dot_n1), *truth.exact_n1, m.precision_bits);
    m.n2 = measure_error(to_exact(v.omega_dot_n2), *truth.exact_n2, m.precision_bits);
    if (budget > 0)
      m.seconds_per_eval = seconds_per_call([&] { return compute_by_route(route, engine, p, in); }, budget);
  } catch (const UndefinedQuantity& u) {
    m.defined = false;
    m.undefined_quantity = u.quantity();
    m.reason = u.reason();
  }
  return m;
}

/// Relative bound e/|v| of a tracked value (infinite if unbounded or v = 0 with e > 0).
template <class F>
double relative_bound(const Tracked<F>& x) {
  if (x.e == 0) return 0;
  if (!std::isfinite(x.e) || !std::isfinite(x.v) || x.v == 0) return std::numeric_limits<double>::infinity();
  return static_cast<double>(x.e / std::abs(x.v));
}

ConditionEstimate estimate_condition(Route route, GroundTruthEngine& engine, const Polygon<Rational>& polygon,
                                     const InputRates<Rational>& rates) {
  ConditionEstimate c;
  c.route = route;
  try {
    const auto d = compute_by_route(route, engine, polygon.convert<Tracked<double>>(), rates.convert<Tracked<double>>());
    const auto ld = compute_by_route(route, engine, polygon.convert<Tracked<long double>>(),
                                     rates.convert<Tracked<long double>>());
    c.bound_double_n1 = relative_bound(d.omega_dot_n1);
    c.bound_double_n2 = relative_bound(d.omega_dot_n2);
    c.bound_long_double_n1 = relative_bound(ld.omega_dot_n1);
    c.bound_long_double_n2 = relative_bound(ld.omega_dot_n2);
    c.condition = std::max(c.bound_double_n1, c.bound_double_n2) / Tracked<double>::unit_roundoff();
  } catch (const UndefinedQuantity& u) {
    c.defined = false;
    c.undefined_quantity = u.quantity();
  }
  return c;
}

}  // namespace

CaseStudy study_case(GroundTruthEngine& engine, const Polygon<Rational>& polygon, const InputRates<Rational>& rates,
                     const StudyOptions& options) {
  CaseStudy s;
  s.n = polygon.n();
  try {
    const PolygonMotion<Rational> m = compute_closed_form_motion(polygon, rates);
    s.exact_n1 = m.omega_dot[static_cast<size_t>(s.n - 2)];
    s.exact_n2 = m.omega_dot[static_cast<size_t>(s.n - 3)];
  } catch (const UndefinedQuantity& u) {
    s.truth_undefined_reason = u.reason();
  }
  for (Route route : kAllRoutes) {
    if (!options.routes.empty() && !options.routes.count(route)) continue;
    for_each_arithmetic([&]<class T>() {
      if (!options.arithmetics.empty() && !options.arithmetics.count(arithmetic_name<T>())) return;
      s.measurements.push_back(measure_route<T>(route, engine, polygon, rates, s, options.time_budget_seconds));
    });
    if (s.exact_n1) s.conditions.push_back(estimate_condition(route, engine, polygon, rates));
  }
  return s;
}

}  // namespace linkproof
