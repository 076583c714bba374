#include "count/integer_families.h"

#include <cln/rational.h>

#include "linkproof/core/error.h"
#include "geometry/closed_forms.h"

namespace linkproof {

namespace {

using cln::cl_I;

cl_I lcm_of_denominators(const std::vector<Rational>& values) {
  cl_I l = 1;
  for (const Rational& v : values) l = cln::lcm(l, cln::denominator(v));
  return l;
}

/// q, an integer by construction (a value times the lcm of the denominators).
cl_I integer_of(const Rational& q) {
  LINKPROOF_ASSERT(cln::denominator(q) == 1, "integer_fixed_side_families: scaling left a fraction");
  return cln::numerator(q);
}

}  // namespace

IntegerFamilies integer_fixed_side_families(const Polygon<Rational>& p, const std::vector<Rational>& omega) {
  const int n = p.n();
  LINKPROOF_ASSERT(n >= 3 && static_cast<int>(omega.size()) == n, "integer_fixed_side_families: bad input");
  std::vector<Rational> coordinates;
  for (int k = 1; k <= n; ++k) {
    coordinates.push_back(p.joint(k).x);
    coordinates.push_back(p.joint(k).y);
  }
  const cl_I s = lcm_of_denominators(coordinates);
  std::vector<Vec2<cl_I>> side;  // side[j - 1] = s r_j
  for (int j = 1; j <= n; ++j) {
    const Vec2<Rational> r = p.side(j);
    side.push_back({integer_of(r.x * s), integer_of(r.y * s)});
  }
  const cl_I L = lcm_of_denominators(omega);
  std::vector<cl_I> w;  // w[body] = L omega_body
  for (const Rational& o : omega) w.push_back(integer_of(o * L));

  IntegerFamilies out;
  for (int f = 1; f <= n; ++f) {
    // The polygon with side f fixed (relative_rates.h, with_fixed_side): its side t is side
    // original(t), the side of body original(t) - 1.
    const auto original = [f, n](int t) { return (f + t - 1) % n + 1; };
    const int fixed = f - 1;
    const Vec2<cl_I>& a = side[static_cast<size_t>(original(n - 2) - 1)];
    const Vec2<cl_I>& b = side[static_cast<size_t>(original(n - 1) - 1)];
    const cl_I D = cross(a, b);
    if (cln::zerop(D)) throw dead_centre_error();
    const cl_I ab = dot(a, b), aa = norm2(a), bb = norm2(b), D2 = D * D, D3 = D2 * D;

    const auto zero_relation = [n] { return IntegerRelation{std::vector<cl_I>(static_cast<size_t>(n - 1), 0), 0}; };
    IntegerRelation v5 = zero_relation(), v6 = zero_relation(), r22 = zero_relation(), rc = zero_relation();
    // c rate(body, fixed) = c y_fixed - c y_body.
    const auto add_term = [fixed](IntegerRelation& r, int body, const cl_I& c) {
      if (fixed > 0) r.row[static_cast<size_t>(fixed - 1)] = r.row[static_cast<size_t>(fixed - 1)] + c;
      if (body > 0) r.row[static_cast<size_t>(body - 1)] = r.row[static_cast<size_t>(body - 1)] - c;
    };
    add_term(v5, original(n - 1) - 1, D);
    add_term(v6, original(n - 2) - 1, D);
    add_term(r22, original(n - 1) - 1, D3);
    add_term(rc, original(n - 2) - 1, D3);
    cl_I sum_lambda = 0, sum_mu = 0, u_sum = 0, v_sum = 0, u_squares = 0, v_squares = 0;
    for (int j = 1; j <= n - 3; ++j) {
      const int body = original(j) - 1;
      const Vec2<cl_I>& r = side[static_cast<size_t>(body)];
      const cl_I I = cross(r, a), K = cross(b, r);
      add_term(v5, body, -I);
      add_term(v6, body, -K);
      add_term(r22, body, -(D2 * I));
      add_term(rc, body, -(D2 * K));
      const cl_I wj = w[static_cast<size_t>(body)] - w[static_cast<size_t>(fixed)];
      const cl_I w2 = wj * wj, I2 = I * I, K2 = K * K;
      sum_lambda = sum_lambda - (D2 * dot(a, r) + K2 * aa + I2 * ab) * w2;
      sum_mu = sum_mu + (D2 * dot(b, r) + K2 * ab + I2 * bb) * w2;
      const cl_I u = I * wj, v = K * wj;
      u_sum = u_sum + u;
      v_sum = v_sum + v;
      u_squares = u_squares + u * u;
      v_squares = v_squares + v * v;
    }
    // Ordered-pair sums, as in relative_rates.cpp: sum_{j != l} u_j u_l = (sum u)^2 - sum u^2.
    const cl_I S1 = u_sum * u_sum - u_squares, S2 = v_sum * v_sum - v_squares;
    r22.rhs = sum_lambda - ab * S1 - aa * S2;
    rc.rhs = sum_mu + ab * S2 + bb * S1;
    out.velocity.push_back(std::move(v5));
    out.velocity.push_back(std::move(v6));
    out.eq22.push_back(std::move(r22));
    out.companion.push_back(std::move(rc));
  }
  return out;
}

}  // namespace linkproof
