#include "numerics/data_check.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <cln/integer.h>
#include <cln/rational.h>

#include "linkproof/core/error.h"
#include "core/scalar.h"
#include "core/tracked.h"
#include "mechanism/mechanism_solve.h"
#include "mechanism/mechanism_vector_route.h"

namespace linkproof {

namespace {

using TD = Tracked<double>;

TD with_uncertainty(const RecordedNumber& n) {
  TD t = ScalarTraits<TD>::from_rational(n.value);
  t.e = t.e + n.uncertainty;
  return t;
}

/// The scene's linkage with this sample's joint positions.
Linkage sample_linkage(const MechanismScene& scene, const MotionSample& s) {
  const Linkage& g = scene.linkage;
  std::vector<LinkageJoint> joints = g.joints();
  for (size_t j = 0; j < joints.size(); ++j) joints[j].at = {s.x[j].value, s.y[j].value};
  return Linkage(g.link_names(), g.ground(), std::move(joints));
}

Rational exact_of(double x) { return ScalarTraits<double>::to_rational(x); }

/// sqrt(q) in double for q >= 0 without overflow of the squares: q scaled by 4^-k first.
double sqrt_of(const Rational& q) {
  if (cln::zerop(q)) return 0;
  const long k = (static_cast<long>(cln::integer_length(cln::numerator(q))) -
                  static_cast<long>(cln::integer_length(cln::denominator(q)))) / 2;
  const Rational scaled = k >= 0 ? q / cln::ash(cln::cl_I(1), 2 * k) : q * cln::ash(cln::cl_I(1), -2 * k);
  return std::ldexp(std::sqrt(ScalarTraits<double>::from_rational(scaled)), static_cast<int>(k));
}

/// | sqrt(a) - sqrt(b) | > t for exact a, b, t >= 0, decided exactly (no square root taken):
/// sqrt(a) > sqrt(b) + t  <=>  a - b - t^2 > 0 and (a - b - t^2)^2 > 4 t^2 b.
bool lengths_differ_by_more_than(const Rational& a, const Rational& b, const Rational& t) {
  const auto longer = [&](const Rational& x, const Rational& y) {
    const Rational d = x - y - t * t;
    return cln::plusp(d) && d * d > Rational(4) * t * t * y;
  };
  return longer(a, b) || longer(b, a);
}

/// |d_sample| - |d_ref| for display: (|d_s|^2 - |d_r|^2) / (|d_s| + |d_r|), the numerator exact.
double length_change(const Rational& a, const Rational& b) {
  const double den = sqrt_of(a) + sqrt_of(b);
  if (den == 0) return 0;
  if (!std::isfinite(den)) return sqrt_of(a) - sqrt_of(b);
  return ScalarTraits<double>::from_rational((a - b) / exact_of(den));
}

/// A tolerance of the closure (a double sum of uncertainties) rounded up: a bound, not an estimate.
double rounded_up(double x) { return x > 0 ? std::nextafter(x, std::numeric_limits<double>::infinity()) : x; }

int sign_of(const Rational& q) { return cln::minusp(q) ? -1 : cln::plusp(q) ? 1 : 0; }

void check_closure(const MechanismScene& scene, const MotionSample& s, SampleCheck& out) {
  const Linkage& g = scene.linkage;
  const auto u_sample = [&](int j) { return std::max(s.x[size_t(j)].uncertainty, s.y[size_t(j)].uncertainty); };
  double scene_scale = 0;
  for (const auto& jt : g.joints())
    scene_scale = std::max({scene_scale, std::abs(ScalarTraits<double>::from_rational(jt.at.x)),
                            std::abs(ScalarTraits<double>::from_rational(jt.at.y))});
  const auto u_scene = [&](int j) {
    return std::max(scene_coordinate_uncertainty(g.joint(j).at.x, scene_scale),
                    scene_coordinate_uncertainty(g.joint(j).at.y, scene_scale));
  };
  const auto at = [&](int j) { return Vec2<Rational>{s.x[size_t(j)].value, s.y[size_t(j)].value}; };
  // Every decision below is exact (rationals); residual and tolerance are doubles for the report.
  // The worst entry: an exceeded one before any other, then the largest residual / tolerance.
  bool worst_exceeds = false;
  double worst_ratio = -1;
  bool any_exceeds = false;
  const auto consider = [&](bool exceeds, double residual, double tolerance, const std::string& what) {
    double ratio = tolerance > 0 ? residual / tolerance : (residual > 0 ? INFINITY : 0);
    if (std::isnan(ratio)) ratio = INFINITY;
    any_exceeds = any_exceeds || exceeds;
    if (exceeds > worst_exceeds || (exceeds == worst_exceeds && ratio > worst_ratio)) {
      worst_exceeds = exceeds;
      worst_ratio = ratio;
      out.closure_residual = residual;
      out.closure_tolerance = tolerance;
      out.closure_worst = what;
    }
  };
  // A tolerance that is not finite cannot be read exactly: the pair cannot be judged, and the
  // sample is not taken as consistent.
  const auto judged_tolerance = [&](double tol, const std::string& what) -> std::optional<Rational> {
    if (std::isfinite(tol)) return exact_of(tol);
    consider(true, INFINITY, tol, what + " (tolerance not finite: cannot be judged)");
    return std::nullopt;
  };
  // Joints fixed in each link: revolute members, and a prismatic pair's point on its slider.
  for (int l = 0; l < g.link_count(); ++l) {
    std::vector<int> fixed;
    for (int j = 0; j < g.joint_count(); ++j) {
      const LinkageJoint& jt = g.joint(j);
      if (jt.type == JointType::Revolute ? (jt.links[0] == l || jt.links[1] == l) : jt.links[1] == l) fixed.push_back(j);
    }
    for (size_t a = 0; a < fixed.size(); ++a)
      for (size_t b = a + 1; b < fixed.size(); ++b) {
        const int ja = fixed[a], jb = fixed[b];
        const Rational ls = norm2(at(jb) - at(ja)), lr = norm2(g.joint(jb).at - g.joint(ja).at);
        const double tol = rounded_up(std::sqrt(2.0) * (u_sample(ja) + u_sample(jb) + u_scene(ja) + u_scene(jb)));
        const std::string what = fmt::format("|{}{}| of link {}", g.joint(ja).name, g.joint(jb).name, g.link_name(l));
        if (const auto t = judged_tolerance(tol, what))
          consider(lengths_differ_by_more_than(ls, lr, *t), std::abs(length_change(ls, lr)), tol, what);
      }
    // Orientation: distances alone accept a mirror image of a link of 3 or more joints.
    // cross(d1 + e1, d2 + e2) - cross(d1, d2) is at most (|d2x| + |d2y|) |e1| + (|d1x| + |d1y|) |e2|
    // + 2 |e1| |e2| with |e1| <= u_a + u_b, |e2| <= u_a + u_c per coordinate: a reversed sign
    // beyond that bound in both the sample and the scene cannot come from rounding.
    const auto flip_bound = [](const Vec2<Rational>& d1, const Vec2<Rational>& d2, const Rational& e1,
                               const Rational& e2) {
      return (cln::abs(d2.x) + cln::abs(d2.y)) * e1 + (cln::abs(d1.x) + cln::abs(d1.y)) * e2 + Rational(2) * e1 * e2;
    };
    for (size_t a = 0; a < fixed.size(); ++a)
      for (size_t b = a + 1; b < fixed.size(); ++b)
        for (size_t c = b + 1; c < fixed.size(); ++c) {
          const int ja = fixed[a], jb = fixed[b], jc = fixed[c];
          const std::string what = fmt::format("orientation of {}, {}, {} in link {} (reversed: a mirror image)",
                                               g.joint(ja).name, g.joint(jb).name, g.joint(jc).name, g.link_name(l));
          const double us = u_sample(ja) + std::max(u_sample(jb), u_sample(jc));
          const double ur = u_scene(ja) + std::max(u_scene(jb), u_scene(jc));
          if (!std::isfinite(us) || !std::isfinite(ur)) {
            consider(true, INFINITY, INFINITY, what + " (uncertainty not finite: cannot be judged)");
            continue;
          }
          const Vec2<Rational> s1 = at(jb) - at(ja), s2 = at(jc) - at(ja);
          const Vec2<Rational> r1 = g.joint(jb).at - g.joint(ja).at, r2 = g.joint(jc).at - g.joint(ja).at;
          const Rational cs = cross(s1, s2), cr = cross(r1, r2);
          const Rational bs = flip_bound(s1, s2, exact_of(us), exact_of(us));
          const Rational br = flip_bound(r1, r2, exact_of(ur), exact_of(ur));
          const bool reversed = sign_of(cs) * sign_of(cr) < 0 && cln::abs(cs) > bs && cln::abs(cr) > br;
          if (reversed)
            consider(true, ScalarTraits<double>::from_rational(cln::abs(cs)), ScalarTraits<double>::from_rational(bs), what);
        }
  }
  for (int j = 0; j < g.joint_count(); ++j) {
    const LinkageJoint& jt = g.joint(j);
    if (jt.type != JointType::Prismatic) continue;
    // Distance from the guide line: |cross(d, axis)| / |axis| > t  <=>  cross^2 > t^2 |axis|^2.
    const Rational off = cross(at(j) - jt.at, jt.axis), axis2 = norm2(jt.axis);
    const double tol = rounded_up(std::sqrt(2.0) * (u_sample(j) + u_scene(j)));
    const std::string what = fmt::format("{} off its guide", jt.name);
    if (const auto t = judged_tolerance(tol, what))
      consider(off * off > *t * *t * axis2, std::abs(ScalarTraits<double>::from_rational(off / exact_of(sqrt_of(axis2)))),
               tol, what);
  }
  out.consistent = !any_exceeds;
}

std::string guide_problem(const MechanismScene& scene) {
  const Linkage& g = scene.linkage;
  for (const auto& j : g.joints())
    if (j.type == JointType::Prismatic && j.links[0] != g.ground())
      return fmt::format("prismatic joint `{}` slides on `{}`, not on the ground: check-data reads the guide's axis from "
                         "the scene, which holds only for a guide fixed in the ground",
                         j.name, g.link_name(j.links[0]));
  return "";
}

void check_sample(const MechanismScene& scene, const MotionSample& s, SampleCheck& out) {
  const Linkage g = sample_linkage(scene, s);
  std::vector<MechanismInput> inputs = scene.inputs;
  std::vector<InputValue<TD>> values;
  for (size_t k = 0; k < inputs.size(); ++k) {
    inputs[k].rate = s.rate[k].value;
    inputs[k].rate_dot = s.rate_dot[k].value;
    values.push_back({with_uncertainty(s.rate[k]), with_uncertainty(s.rate_dot[k])});
  }
  const std::string source = fmt::format("{}: {}", s.label, scene.source);
  const MechanismSolution<Rational> exact = solve_mechanism<Rational>(
      g, inputs, rigid_body_constraint_matrix<Rational>(g),
      [&](const std::vector<Rational>& qd) { return rigid_body_acceleration_rhs<Rational>(g, qd); }, source);
  std::vector<Vec2<TD>> at;
  for (size_t j = 0; j < s.x.size(); ++j) at.push_back({with_uncertainty(s.x[j]), with_uncertainty(s.y[j])});
  std::vector<TD> w_radius, a_radius, v_radius, vd_radius;
  try {
    const MechanismSolution<TD> bounded = solve_mechanism<TD>(
        g, inputs, rigid_body_constraint_matrix<TD>(g, JointGeometry<TD>{&at}),
        [&](const std::vector<TD>& qd) { return rigid_body_acceleration_rhs<TD>(g, qd, true, JointGeometry<TD>{&at}); }, source, &values);
    w_radius = bounded.motion.omega;
    a_radius = bounded.motion.omega_dot;
    v_radius = bounded.motion.slide;
    vd_radius = bounded.motion.slide_dot;
  } catch (const InputError&) {
    // Within the data's precision the mechanism may lock: nothing can be bounded.
    const TD unbounded(0.0, std::numeric_limits<double>::infinity());
    w_radius.assign(exact.motion.omega.size(), unbounded);
    a_radius = w_radius;
    v_radius.assign(exact.motion.slide.size(), unbounded);
    vd_radius = v_radius;
  }
  out.omega = exact.motion.omega;
  out.alpha = exact.motion.omega_dot;
  const auto compare = [&](const std::string& name, RecordedQuantity quantity, const RecordedNumber& user,
                           const Rational& truth, const TD& bound) {
    RecordedRateCheck c;
    c.name = name;
    c.quantity = quantity;
    c.exact = truth;
    c.user_text = user.text;
    c.difference = ScalarTraits<double>::from_rational(user.value - truth);
    // NaN radius (an overflow inside the bounded solve) is as unknown as an infinite one.
    const double radius = std::isnan(bound.e) ? std::numeric_limits<double>::infinity() : bound.e;
    c.tolerance = rounded_up(radius + user.uncertainty);
    c.outcome = compare_recorded(user.value, truth, c.tolerance);
    out.checks.push_back(std::move(c));
  };
  for (int l = 0; l < g.link_count(); ++l) {
    const size_t i = static_cast<size_t>(l);
    if (s.user_omega[i]) compare(g.link_name(l), RecordedQuantity::Omega, *s.user_omega[i], out.omega[i], w_radius[i]);
    if (s.user_alpha[i]) compare(g.link_name(l), RecordedQuantity::Alpha, *s.user_alpha[i], out.alpha[i], a_radius[i]);
  }
  for (int j = 0; j < g.joint_count(); ++j) {
    const size_t i = static_cast<size_t>(j);
    if (s.user_slide[i])
      compare(g.joint(j).name, RecordedQuantity::SlideVelocity, *s.user_slide[i], exact.motion.slide[i], v_radius[i]);
    if (s.user_slide_dot[i])
      compare(g.joint(j).name, RecordedQuantity::SlideAcceleration, *s.user_slide_dot[i], exact.motion.slide_dot[i],
              vd_radius[i]);
  }
}

}  // namespace

RateOutcome compare_recorded(const Rational& user, const Rational& exact, double tolerance) {
  if (!std::isfinite(tolerance)) return RateOutcome::Inconclusive;
  const Rational t = exact_of(tolerance);
  if (cln::abs(user - exact) > t) return RateOutcome::Differs;
  if (cln::zerop(t)) return RateOutcome::Agrees;  // user == exact, exactly
  // The truth within the data's precision spans [exact - t, exact + t]: if that reaches 0 no
  // recorded value is told apart from one of the other sign (near a toggle: exact -5e17, t 3.5e18).
  if (t >= cln::abs(exact)) return RateOutcome::Inconclusive;
  return RateOutcome::Agrees;
}

SampleVerdict SampleCheck::verdict() const {
  if (!error.empty()) return SampleVerdict::Unsolvable;
  if (checks.empty()) return SampleVerdict::NothingCompared;
  bool inconclusive = false;
  for (const auto& c : checks) {
    if (c.outcome == RateOutcome::Differs) return SampleVerdict::Differs;
    inconclusive = inconclusive || c.outcome == RateOutcome::Inconclusive;
  }
  return inconclusive ? SampleVerdict::Inconclusive : SampleVerdict::Agrees;
}

DataCheck check_motion_data(const MechanismScene& scene, const MotionData& data) {
  if (std::string p = guide_problem(scene); !p.empty()) throw InputError(scene.source, "mechanism.joints", p);
  DataCheck out;
  out.scene = scene.source;
  out.data = data.source;
  out.link_names = scene.linkage.link_names();
  for (const MotionSample& s : data.samples) {
    SampleCheck c;
    c.line = s.line;
    c.label = s.label;
    c.t = s.t;
    c.input_angle = s.input_angle;
    check_closure(scene, s, c);
    try {
      check_sample(scene, s, c);
    } catch (const InputError& e) {
      c.error = e.what();
    }
    if (!c.consistent) ++out.inconsistent;
    out.compared += static_cast<int>(c.checks.size());
    switch (c.verdict()) {
      case SampleVerdict::Agrees: ++out.agreeing; break;
      case SampleVerdict::Differs: ++out.differing; break;
      case SampleVerdict::Inconclusive: ++out.inconclusive; break;
      case SampleVerdict::NothingCompared: ++out.nothing_compared; break;
      case SampleVerdict::Unsolvable: ++out.unsolvable; break;
    }
    out.samples.push_back(std::move(c));
  }
  return out;
}

}  // namespace linkproof
