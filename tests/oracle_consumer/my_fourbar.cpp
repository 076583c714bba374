#include "my_fourbar.h"

#include "linkproof/testing/cases.h"

std::vector<double> fourbar_alpha(const linkproof::Linkage& m, const std::vector<linkproof::MechanismInput>& inputs,
                                  bool planted_bug) {
  using linkproof::testing::joint_xy;
  const auto o2 = joint_xy(m, "O2"), a = joint_xy(m, "A"), b = joint_xy(m, "B"), o4 = joint_xy(m, "O4");
  const double w2 = linkproof::nearest_double(inputs[0].rate), al2 = linkproof::nearest_double(inputs[0].rate_dot);
  // Loop O2 -> A -> B -> O4: r2 + r3 - r4 = const, r2 = A - O2, r3 = B - A, r4 = B - O4.
  const double r2x = a[0] - o2[0], r2y = a[1] - o2[1];
  const double r3x = b[0] - a[0], r3y = b[1] - a[1];
  const double r4x = b[0] - o4[0], r4y = b[1] - o4[1];
  // Velocity: J (w2 r2 + w3 r3 - w4 r4) = 0, so w3 r3 - w4 r4 = -w2 r2 (Cramer on [r3, -r4]).
  const double det = -r3x * r4y + r3y * r4x;
  const double w3 = w2 * (r2x * r4y - r2y * r4x) / det;
  const double w4 = w2 * (r2x * r3y - r2y * r3x) / det;
  // Acceleration: J (al2 r2 + al3 r3 - al4 r4) = c with c = w2^2 r2 + w3^2 r3 - w4^2 r4,
  // so al3 r3 - al4 r4 = -J c - al2 r2.
  const double k3 = planted_bug ? 0.0 : w3 * w3;
  const double cx = w2 * w2 * r2x + k3 * r3x - w4 * w4 * r4x;
  const double cy = w2 * w2 * r2y + k3 * r3y - w4 * w4 * r4y;
  const double px = cy - al2 * r2x, py = -cx - al2 * r2y;  // -J c = (c_y, -c_x)
  const double al3 = (-px * r4y + py * r4x) / det;
  const double al4 = (r3x * py - r3y * px) / det;
  return {0.0, al2, al3, al4};
}

std::vector<double> my_fourbar_omega(const linkproof::Linkage& m, const std::vector<linkproof::MechanismInput>& inputs) {
  using linkproof::testing::joint_xy;
  const auto o2 = joint_xy(m, "O2"), a = joint_xy(m, "A"), b = joint_xy(m, "B"), o4 = joint_xy(m, "O4");
  const double w2 = linkproof::nearest_double(inputs[0].rate);
  const double r2x = a[0] - o2[0], r2y = a[1] - o2[1];
  const double r3x = b[0] - a[0], r3y = b[1] - a[1];
  const double r4x = b[0] - o4[0], r4y = b[1] - o4[1];
  const double det = -r3x * r4y + r3y * r4x;  // as in fourbar_alpha
  return {0.0, w2, w2 * (r2x * r4y - r2y * r4x) / det, w2 * (r2x * r3y - r2y * r3x) / det};
}
