#include "mechanism/relative_rates.h"

#include <optional>

#include "linkproof/core/error.h"
#include "geometry/closed_forms.h"

namespace linkproof {

RelativeRates::RelativeRates(int bodies) : m_(bodies) {
  LINKPROOF_ASSERT(bodies >= 2, "RelativeRates needs at least two bodies");
}

int RelativeRates::column(int i, int k) const {
  LINKPROOF_ASSERT(0 <= i && i < k && k < m_, "RelativeRates::column needs 0 <= i < k < m");
  // Rows 0..i-1 of the strict upper triangle hold (m-1) + ... + (m-i) columns.
  return i * m_ - i * (i + 1) / 2 + (k - i - 1);
}

std::pair<int, int> RelativeRates::bodies_of(int col) const {
  int i = 0;
  while (col >= m_ - 1 - i) {
    col -= m_ - 1 - i;
    ++i;
  }
  return {i, i + 1 + col};
}

std::pair<int, Rational> RelativeRates::term(int a, int b, const Rational& c) const {
  LINKPROOF_ASSERT(a != b, "rate of a body relative to itself");
  return a < b ? std::pair<int, Rational>{column(a, b), c} : std::pair<int, Rational>{column(b, a), -c};
}

std::vector<RateRelation> triangle_relations(const RelativeRates& rates) {
  const int m = rates.bodies();
  std::vector<RateRelation> out;
  out.reserve(static_cast<size_t>(m) * (m - 1) * (m - 2) / 6);
  for (int i = 0; i < m; ++i)
    for (int j = i + 1; j < m; ++j)
      for (int k = j + 1; k < m; ++k)
        out.push_back({"", make_sparse_row<Rational>({{rates.column(i, j), 1}, {rates.column(j, k), 1},
                                                      {rates.column(i, k), -1}}),
                       0});
  return out;
}

BodyPolygon with_fixed_side(const BodyPolygon& p, int f) {
  const int n = p.polygon.n();
  LINKPROOF_ASSERT(1 <= f && f <= n && static_cast<int>(p.bodies.size()) == n, "with_fixed_side: bad side");
  BodyPolygon out;
  std::vector<Vec2<Rational>> joints;
  for (int t = 1; t <= n; ++t) {
    const int s = (f + t - 1) % n + 1;  // original side that becomes side t
    joints.push_back(p.polygon.joint(s));
    out.bodies.push_back(p.bodies[static_cast<size_t>(s - 1)]);
  }
  out.polygon = Polygon<Rational>(std::move(joints));
  return out;
}

namespace {

/// The closed forms of p, kept for the next call: velocity_relations and acceleration_relations
/// of one polygon (count_fixed_side_relations asks for both in turn) compute them once.
const ClosedForms<Rational>& closed_forms_of(const Polygon<Rational>& p) {
  thread_local std::optional<Polygon<Rational>> last;
  thread_local ClosedForms<Rational> forms;
  const auto same = [&p] {
    if (!last || last->n() != p.n()) return false;
    for (int k = 1; k <= p.n(); ++k)
      if (last->joint(k).x != p.joint(k).x || last->joint(k).y != p.joint(k).y) return false;
    return true;
  };
  if (!same()) {
    last.reset();
    forms = compute_closed_forms(p);  // throws at a dead centre: nothing is kept then
    last = p;
  }
  return forms;
}

/// rate_{lead,n} - sum_j coeff_j rate_{j,n} as a row.
SparseRow<Rational> polygon_row(const RelativeRates& rates, const BodyPolygon& p, int lead,
                                const std::vector<Rational>& coeff) {
  const int n = p.polygon.n();
  const int fixed = p.bodies[static_cast<size_t>(n - 1)];
  std::vector<std::pair<int, Rational>> e;
  e.push_back(rates.term(p.bodies[static_cast<size_t>(lead - 1)], fixed, 1));
  for (int j = 1; j <= n - 3; ++j)
    e.push_back(rates.term(p.bodies[static_cast<size_t>(j - 1)], fixed, -coeff[static_cast<size_t>(j - 1)]));
  return make_sparse_row(std::move(e));
}

std::string side_label(const BodyPolygon& p) {
  std::string s;
  for (int b : p.bodies) s += (s.empty() ? "" : "-") + std::to_string(b);
  return s;
}

}  // namespace

std::vector<RateRelation> velocity_relations(const RelativeRates& rates, const BodyPolygon& p) {
  const ClosedForms<Rational>& c = closed_forms_of(p.polygon);
  const int n = p.polygon.n();
  const std::string at = " of polygon " + side_label(p);
  return {{"(5)" + at, polygon_row(rates, p, n - 1, c.i_out), 0},
          {"(6)" + at, polygon_row(rates, p, n - 2, c.i_cpl), 0}};
}

std::vector<RateRelation> acceleration_relations(const RelativeRates& rates, const BodyPolygon& p,
                                                 const std::vector<Rational>& omega) {
  const ClosedForms<Rational>& c = closed_forms_of(p.polygon);
  const int n = p.polygon.n();
  const Rational& w_n = omega[static_cast<size_t>(p.bodies[static_cast<size_t>(n - 1)])];
  Rational sum_lambda = 0, sum_mu = 0, a1 = 0, a2 = 0, q1 = 0, q2 = 0;
  for (int j = 1; j <= n - 3; ++j) {
    const size_t k = static_cast<size_t>(j - 1);
    const Rational w = omega[static_cast<size_t>(p.bodies[k])] - w_n;  // omega_{j,n}
    sum_lambda = sum_lambda + c.lambda[k] * w * w;
    sum_mu = sum_mu + c.mu[k] * w * w;
    const Rational u = c.i_out[k] * w, v = c.i_cpl[k] * w;
    a1 = a1 + u;
    a2 = a2 + v;
    q1 = q1 + u * u;
    q2 = q2 + v * v;
  }
  // Ordered-pair sums: sum_{j != l} u_j u_l = (sum u)^2 - sum u^2.
  const Rational s1 = a1 * a1 - q1, s2 = a2 * a2 - q2;
  const std::string at = " of polygon " + side_label(p);
  return {{"(22)" + at, polygon_row(rates, p, n - 1, c.i_out), sum_lambda - c.cot_phi * s1 - c.rho * s2},
          {"companion" + at, polygon_row(rates, p, n - 2, c.i_cpl),
           sum_mu + c.cot_phi * s2 + c.rho_companion * s1}};
}

}  // namespace linkproof
