#include "symbolic/motion_tape.h"

#include "linkproof/core/error.h"

namespace linkproof {

namespace {

using Split = CanonicalForm::Split;

Split negated(const Split& s) { return {-s.content, s.primitive}; }

}  // namespace

std::vector<std::string> motion_tape_input_names(int n) {
  std::vector<std::string> names;
  names.reserve(static_cast<size_t>(4 * n - 8));
  for (const char* word : {"x_", "y_"})
    for (int j = 1; j <= n - 1; ++j) names.push_back(word + std::to_string(j));
  for (const char* word : {"omega_", "omega_dot_"})
    for (int j = 1; j <= n - 3; ++j) names.push_back(word + std::to_string(j));
  return names;
}

Tape derive_motion_tape(int n, std::string denominator_name) {
  LINKPROOF_ASSERT(n >= 4, "the motion tape needs n >= 4 (n-3 inputs)");
  const int m = n - 3, p = n - 2, q = n - 1;
  CanonicalForm f(motion_tape_input_names(n));
  // Input indices follow motion_tape_input_names.
  auto x = [&](int j) { return f.input(static_cast<std::uint32_t>(j - 1)); };
  auto y = [&](int j) { return f.input(static_cast<std::uint32_t>(q + j - 1)); };
  auto omega = [&](int j) { return f.input(static_cast<std::uint32_t>(2 * q + j - 1)); };
  auto omega_dot = [&](int j) { return f.input(static_cast<std::uint32_t>(2 * q + m + j - 1)); };
  // u x v = u_x v_y - u_y v_x, as GiNaC's ax*by - ay*bx.
  auto cross = [&](const Split& ux, const Split& uy, const Split& vx, const Split& vy) {
    return f.sum({f.product({ux, vy}), negated(f.product({uy, vx}))});
  };
  auto over_d = [&](const Split& numerator, const Split& d) { return f.product({numerator, f.power(d, -1)}); };

  const Split ax = negated(y(p)), ay = x(p), bx = negated(y(q)), by = x(q);
  const Split d = cross(ax, ay, bx, by);

  // Velocity: c = minus the input rates' part of the velocity equation.
  std::vector<Split> cx, cy;
  for (int j = 1; j <= m; ++j) {
    cx.push_back(f.product({omega(j), y(j)}));
    cy.push_back(negated(f.product({omega(j), x(j)})));
  }
  const Split c_x = f.sum(cx), c_y = f.sum(cy);
  const Split omega_p = over_d(cross(c_x, c_y, bx, by), d);
  const Split omega_q = over_d(cross(ax, ay, c_x, c_y), d);

  // Acceleration: the same matrix; the solved sides' omega^2 are the velocity solution squared.
  std::vector<Split> ex_terms, ey_terms;
  for (int j = 1; j <= m; ++j) {
    const Split omega_sq = f.power(omega(j), 2);
    ex_terms.push_back(f.product({omega_dot(j), y(j)}));
    ex_terms.push_back(f.product({omega_sq, x(j)}));
    ey_terms.push_back(negated(f.product({omega_dot(j), x(j)})));
    ey_terms.push_back(f.product({omega_sq, y(j)}));
  }
  const Split omega_p_sq = f.power(omega_p, 2), omega_q_sq = f.power(omega_q, 2);
  ex_terms.push_back(f.product({omega_p_sq, x(p)}));
  ex_terms.push_back(f.product({omega_q_sq, x(q)}));
  ey_terms.push_back(f.product({omega_p_sq, y(p)}));
  ey_terms.push_back(f.product({omega_q_sq, y(q)}));
  const Split e_x = f.sum(ex_terms), e_y = f.sum(ey_terms);
  const Split omega_dot_p = over_d(cross(e_x, e_y, bx, by), d);
  const Split omega_dot_q = over_d(cross(ax, ay, e_x, e_y), d);

  return Tape(std::move(f), {omega_p, omega_q, omega_dot_p, omega_dot_q}, std::move(denominator_name));
}

}  // namespace linkproof
