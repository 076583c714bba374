#include "linkproof/numerics/data_check.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "linkproof/core/error.h"
#include "linkproof/core/scalar.h"
#include "linkproof/core/tracked.h"
#include "linkproof/mechanism/mechanism_solve.h"
#include "linkproof/mechanism/mechanism_vector_route.h"

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

double length(const Vec2<Rational>& d) { return std::sqrt(ScalarTraits<double>::from_rational(norm2(d))); }

/// |d_sample| - |d_ref| without cancellation: (|d_s|^2 - |d_r|^2) / (|d_s| + |d_r|), the
/// numerator exact.
double length_change(const Vec2<Rational>& ds, const Vec2<Rational>& dr) {
  const double den = length(ds) + length(dr);
  return den == 0 ? 0 : ScalarTraits<double>::from_rational(norm2(ds) - norm2(dr)) / den;
}

void check_closure(const MechanismScene& scene, const MotionSample& s, SampleCheck& out) {
  const Linkage& g = scene.linkage;
  const auto u_sample = [&](int j) { return std::max(s.x[size_t(j)].uncertainty, s.y[size_t(j)].uncertainty); };
  double scene_scale = 0;
  for (const auto& jt : g.joints())
    scene_scale = std::max({scene_scale, std::abs(ScalarTraits<double>::from_rational(jt.at.x)),
                            std::abs(ScalarTraits<double>::from_rational(jt.at.y))});
  const auto u_scene = [&](int j) {
    return std::max(rational_uncertainty(g.joint(j).at.x, scene_scale), rational_uncertainty(g.joint(j).at.y, scene_scale));
  };
  const auto at = [&](int j) { return Vec2<Rational>{s.x[size_t(j)].value, s.y[size_t(j)].value}; };
  double worst_ratio = -1;
  const auto consider = [&](double residual, double tolerance, const std::string& what) {
    const double ratio = tolerance > 0 ? residual / tolerance : (residual > 0 ? INFINITY : 0);
    if (ratio > worst_ratio) {
      worst_ratio = ratio;
      out.closure_residual = residual;
      out.closure_tolerance = tolerance;
      out.closure_worst = what;
    }
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
        const double r = std::abs(length_change(at(jb) - at(ja), g.joint(jb).at - g.joint(ja).at));
        const double tol = std::sqrt(2.0) * (u_sample(ja) + u_sample(jb) + u_scene(ja) + u_scene(jb));
        consider(r, tol, fmt::format("|{}{}| of link {}", g.joint(ja).name, g.joint(jb).name, g.link_name(l)));
      }
  }
  for (int j = 0; j < g.joint_count(); ++j) {
    const LinkageJoint& jt = g.joint(j);
    if (jt.type != JointType::Prismatic) continue;
    const Vec2<Rational> d = at(j) - jt.at;
    const double off = std::abs(ScalarTraits<double>::from_rational(cross(d, jt.axis))) / length(jt.axis);
    consider(off, std::sqrt(2.0) * (u_sample(j) + u_scene(j)), fmt::format("{} off its guide", jt.name));
  }
  out.consistent = worst_ratio <= 1;
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
  std::vector<TD> w_radius, a_radius;
  try {
    const MechanismSolution<TD> bounded = solve_mechanism<TD>(
        g, inputs, rigid_body_constraint_matrix<TD>(g, &at),
        [&](const std::vector<TD>& qd) { return rigid_body_acceleration_rhs<TD>(g, qd, true, &at); }, source, &values);
    w_radius = bounded.motion.omega;
    a_radius = bounded.motion.omega_dot;
  } catch (const InputError&) {
    // Within the data's precision the mechanism may lock: nothing can be bounded.
    const TD unbounded(0.0, std::numeric_limits<double>::infinity());
    w_radius.assign(exact.motion.omega.size(), unbounded);
    a_radius = w_radius;
  }
  out.omega = exact.motion.omega;
  out.alpha = exact.motion.omega_dot;
  for (int l = 0; l < g.link_count(); ++l) {
    const size_t i = static_cast<size_t>(l);
    for (int q = 0; q < 2; ++q) {
      const auto& user = q == 0 ? s.user_omega[i] : s.user_alpha[i];
      if (!user) continue;
      RecordedRateCheck c;
      c.link = g.link_name(l);
      c.quantity = q == 0 ? "omega" : "alpha";
      c.exact = q == 0 ? exact.motion.omega[i] : exact.motion.omega_dot[i];
      c.user_text = user->text;
      const Rational diff = user->value - c.exact;
      c.difference = ScalarTraits<double>::from_rational(diff);
      const double radius = (q == 0 ? w_radius[i] : a_radius[i]).e;
      c.tolerance = (std::isfinite(radius) ? radius : std::numeric_limits<double>::infinity()) + user->uncertainty;
      c.agrees = std::abs(c.difference) <= c.tolerance;
      out.checks.push_back(std::move(c));
    }
  }
}

}  // namespace

bool SampleCheck::agrees() const {
  if (!error.empty()) return false;
  for (const auto& c : checks)
    if (!c.agrees) return false;
  return true;
}

DataCheck check_motion_data(const MechanismScene& scene, const MotionData& data) {
  if (std::string p = guide_problem(scene); !p.empty()) throw InputError(scene.source, "mechanism.joints", p);
  DataCheck out;
  out.scene = scene.source;
  out.data = data.source;
  out.link_names = scene.linkage.link_names();
  out.tolerance_rule =
      "agrees iff |user - exact| <= radius of the Tracked<double> solve started from the data's digit uncertainties "
      "(positions and input rates) + the uncertainty of the user's digits; digits: half a unit of the last digit, one "
      "ulp for 16+ significant digits (a printed double), integers and fractions exact";
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
    if (!c.error.empty())
      ++out.unsolvable;
    else if (c.agrees())
      ++out.agreeing;
    else
      ++out.differing;
    out.samples.push_back(std::move(c));
  }
  return out;
}

int exit_status(const DataCheck& check) {
  return check.differing + check.inconsistent + check.unsolvable == 0 ? 0 : 1;
}

}  // namespace linkproof
