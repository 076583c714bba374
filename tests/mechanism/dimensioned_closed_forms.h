// Closed forms of the two worked examples given by dimensions (verify/scenes/mechanisms/
// dimensions_fourbar.yaml, dimensions_slider_crank.yaml), computed by a route independent of the
// engine: each loop written as complex numbers and solved by hand (law of cosines for the
// position, 2x2 Cramer for the rates), in CLN long floats of 150 digits (good to about 1e-145).
// Shared by tests/mechanism/dimensioned_worked_examples_test.cpp and dimensioned_bound_test.cpp.
#pragma once

#include <cln/float.h>
#include <cln/real.h>

#include "linkproof/core/exact.h"

namespace linkproof::testing {

inline const cln::float_format_t kClosedFormDigits = cln::float_format(150);
inline cln::cl_F lf(const Rational& q) { return cln::cl_float(q, kClosedFormDigits); }
inline cln::cl_F lf(long n) { return cln::cl_float(cln::cl_I(n), kClosedFormDigits); }

/// Four-bar a e2 + b e3 - c e4 - d = 0 (e_k = (cos th_k, sin th_k)), the open assembly (B left
/// of A -> O4), crank angle th2, omega2 = w2, alpha2 = 0.
struct FourBarClosedForm {
  cln::cl_F bx, by, w3, w4, al3, al4;
};
inline FourBarClosedForm fourbar_closed_form(const cln::cl_F& a, const cln::cl_F& b, const cln::cl_F& c,
                                             const cln::cl_F& d, const cln::cl_F& th2, const cln::cl_F& w2) {
  const cln::cl_F ax = a * cln::cos(th2), ay = a * cln::sin(th2), fx = d - ax, fy = -ay;
  const cln::cl_F f = cln::sqrt(fx * fx + fy * fy);
  const cln::cl_F cos_beta = (b * b + f * f - c * c) / (lf(2) * b * f);  // law of cosines at A
  const cln::cl_F th3 = cln::atan(fx, fy) + cln::atan(cos_beta, cln::sqrt(lf(1) - cos_beta * cos_beta));
  const cln::cl_F bx = ax + b * cln::cos(th3), by = ay + b * cln::sin(th3);
  const cln::cl_F th4 = cln::atan(bx - d, by);
  // Velocities: w3 b J e3 - w4 c J e4 = -w2 a J e2 (J e = (-sin, cos)); Cramer on
  // [[-b s3, c s4], [b c3, -c c4]].
  const cln::cl_F s2 = cln::sin(th2), c2 = cln::cos(th2), s3 = cln::sin(th3), c3 = cln::cos(th3),
                  s4 = cln::sin(th4), c4 = cln::cos(th4);
  const cln::cl_F det = (-b * s3) * (-c * c4) - (c * s4) * (b * c3);
  const cln::cl_F r1 = w2 * a * s2, r2 = -w2 * a * c2;
  const cln::cl_F w3 = (r1 * (-c * c4) - (c * s4) * r2) / det, w4 = ((-b * s3) * r2 - (b * c3) * r1) / det;
  // Accelerations (alpha2 = 0): al3 b J e3 - al4 c J e4 = a w2^2 e2 + b w3^2 e3 - c w4^2 e4.
  const cln::cl_F q1 = a * w2 * w2 * c2 + b * w3 * w3 * c3 - c * w4 * w4 * c4,
                  q2 = a * w2 * w2 * s2 + b * w3 * w3 * s3 - c * w4 * w4 * s4;
  const cln::cl_F al3 = (q1 * (-c * c4) - (c * s4) * q2) / det, al4 = ((-b * s3) * q2 - (b * c3) * q1) / det;
  return {bx, by, w3, w4, al3, al4};
}

/// In-line slider-crank: crank r at angle th turning at w (alpha = 0), rod l, the slider on the
/// line through O2 along +x. x_B = r cos th + S, S = sqrt(l^2 - r^2 sin^2 th); v_B = w x',
/// a_B = w^2 x'' with x' = -r sin th - r^2 sin th cos th / S and
/// x'' = -r cos th - r^2 (cos 2th / S + r^2 sin^2 th cos^2 th / S^3); the rod: l sin phi =
/// -r sin th, so w3 = -r w cos th / S and al3 = r sin th (w^2 - w3^2) / S.
struct SliderCrankClosedForm {
  cln::cl_F x, v, a, w3, al3;
};
inline SliderCrankClosedForm slider_crank_closed_form(const cln::cl_F& r, const cln::cl_F& l, const cln::cl_F& th,
                                                      const cln::cl_F& w) {
  const cln::cl_F s = cln::sin(th), c = cln::cos(th), S = cln::sqrt(l * l - r * r * s * s);
  const cln::cl_F x = r * c + S, x1 = -r * s - r * r * s * c / S;
  const cln::cl_F x2 = -r * c - r * r * ((c * c - s * s) / S + r * r * s * s * c * c / (S * S * S));
  const cln::cl_F w3 = -r * w * c / S;
  return {x, w * x1, w * w * x2, w3, r * s * (w * w - w3 * w3) / S};
}

}  // namespace linkproof::testing
