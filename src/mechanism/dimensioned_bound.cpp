#include "mechanism/dimensioned_bound.h"

#include <cln/exception.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/multiprecision.h"
#include "core/scalar.h"
#include "core/tracked.h"
#include "linkproof/core/error.h"
#include "mechanism/axis_length.h"
#include "mechanism/mechanism_solve.h"
#include "mechanism/mechanism_vector_route.h"

namespace linkproof {

namespace {

using BoundFloat = MpFloat<kDimensionedBoundDigits>;
using T = Tracked<BoundFloat>;
using Traits = TrackedTraits<BoundFloat>;

constexpr double kUnbounded = std::numeric_limits<double>::infinity();

/// q with `radius` added to its rounding error: every value within radius of q is in the enclosure.
T widened(const Rational& q, const Rational& radius) {
  T x = from_rational<T>(q);
  x.e = Traits::add_up(x.e, Traits::radius_up(radius));
  return x;
}

/// The width 2e of an enclosure, rounded up to a double (+inf when unbounded).
double width(const T& x) {
  if (Traits::is_unbounded(x.e)) return kUnbounded;
  return (x.e + x.e).to_double_up();
}
double width(const Vec2<T>& x) { return std::max(width(x.x), width(x.y)); }

/// sqrt of an enclosure whose lower end is positive: sqrt is increasing, so [sqrt(lo), sqrt(hi)]
/// (each end enclosed in rationals, enclose_square_root) holds it; unbounded otherwise.
T enclosed_sqrt(const T& q) {
  const Rational mid = to_exact(q);
  if (Traits::is_unbounded(q.e)) return {BoundFloat(mid), Traits::unbounded()};
  const Rational e = q.e.to_rational(), lo = mid - e, hi = mid + e;
  if (!cln::plusp(lo)) return {BoundFloat(mid), Traits::unbounded()};
  constexpr int kBits = 512;  // beyond the 100 digits (333 bits) of the solve
  const RationalEnclosure a = enclose_square_root(lo, kBits), b = enclose_square_root(hi, kBits);
  const Rational low = a.midpoint - a.half_width, high = b.midpoint + b.half_width;
  return widened((low + high) / 2, (high - low) / 2);
}

int joint_index(const Linkage& g, const std::string& name) {
  const std::optional<int> j = g.find_joint(name);
  return j ? *j : -1;
}

}  // namespace

StartingRadii construct_starting_radii(const MechanismScene& s) {
  const Linkage& g = s.linkage;
  const size_t J = static_cast<size_t>(g.joint_count());
  StartingRadii r;
  r.position.assign(J, Rational(0));
  r.axis.assign(J, Rational(0));
  r.input.assign(s.inputs.size(), {Rational(0), Rational(0)});
  // By name: a sub-mechanism (mechanism/sub_mechanism.h) keeps the whole scene's placement.
  for (const GivenValue& v : s.placement.joints)
    if (const int j = joint_index(g, v.subject); j >= 0 && !v.exact) r.position[static_cast<size_t>(j)] = v.bound;
  for (const GivenValue& v : s.placement.axes)
    if (const int j = joint_index(g, v.subject); j >= 0 && !v.exact) r.axis[static_cast<size_t>(j)] = v.bound;
  // u = P - J moves with both positions: each coordinate by at most the sum of their bounds.
  for (const auto& entry : s.placement.axes_from) {
    const int p = joint_index(g, entry.first), from = joint_index(g, entry.second);
    if (p >= 0 && from >= 0)
      r.axis[static_cast<size_t>(p)] = r.position[static_cast<size_t>(p)] + r.position[static_cast<size_t>(from)];
  }
  for (const GivenValue& v : s.placement.rates) {
    if (v.exact) continue;
    for (size_t k = 0; k < s.inputs.size(); ++k) {
      const bool link = s.inputs[k].kind == MechanismInput::Kind::Link;
      if (v.subject == fmt::format("inputs[{}].{}", k, link ? "omega" : "v")) r.input[k].first = v.bound;
      if (v.subject == fmt::format("inputs[{}].{}", k, link ? "omega_dot" : "a")) r.input[k].second = v.bound;
    }
  }
  return r;
}

DimensionedBound compute_dimensioned_bound(const MechanismScene& s, const StartingRadii& radii) {
  const Linkage& g = s.linkage;
  DimensionedBound out;
  out.digits = kDimensionedBoundDigits;
  std::vector<Vec2<T>> at, axis;
  for (int j = 0; j < g.joint_count(); ++j) {
    const LinkageJoint& jt = g.joint(j);
    const Rational& rp = radii.position[static_cast<size_t>(j)];
    const Rational& ra = radii.axis[static_cast<size_t>(j)];
    at.push_back({widened(jt.at.x, rp), widened(jt.at.y, rp)});
    axis.push_back({widened(jt.axis.x, ra), widened(jt.axis.y, ra)});
  }
  std::vector<InputValue<T>> values;
  for (size_t k = 0; k < s.inputs.size(); ++k)
    values.push_back({widened(s.inputs[k].rate, radii.input[k].first), widened(s.inputs[k].rate_dot, radii.input[k].second)});
  const JointGeometry<T> geo{&at, &axis};
  // Nothing is bounded: every summary bound +inf (the per-quantity lists stay empty).
  const auto unbounded = [&](std::string reason) {
    out.reason = std::move(reason);
    out.omega = out.omega_dot = out.v = out.a = out.sliding_v = out.sliding_a = kUnbounded;
    return out;
  };
  MechanismSolution<T> sol;
  try {
    sol = solve_mechanism<T>(
        g, s.inputs, rigid_body_constraint_matrix<T>(g, geo),
        [&](const std::vector<T>& qd) { return rigid_body_acceleration_rhs<T>(g, qd, true, geo); }, s.source, &values,
        geo);
  } catch (const InputError& e) {
    return unbounded("the solve over every configuration within the rationalisation bounds failed (" + e.problem() +
                     "): some of them may be singular, e.g. at a dead centre");
  } catch (const cln::floating_point_exception& e) {
    return unbounded(std::string("the bounding solve left the range of its arithmetic (") + e.what() + ")");
  }
  const MechanismMotion<T>& m = sol.motion;
  // The first quantity without a bound names the reason.
  const auto note = [&](double b, const std::string& what) {
    if (std::isinf(b) && out.reason.empty())
      out.reason = what + ": the solve divided by an enclosure containing 0 (within the rationalisation bounds the "
                          "mechanism may be at a singular position, e.g. a dead centre)";
    return b;
  };
  for (int l = 0; l < g.link_count(); ++l) {
    if (l == g.ground()) continue;
    const size_t i = static_cast<size_t>(l);
    DimensionedBound::Link b{g.link_name(l), note(width(m.omega[i]), "omega of " + g.link_name(l)),
                             note(width(m.omega_dot[i]), "omega-dot of " + g.link_name(l))};
    out.omega = std::max(out.omega, b.omega), out.omega_dot = std::max(out.omega_dot, b.omega_dot);
    out.links.push_back(std::move(b));
  }
  const auto point = [&](const std::string& name, const Vec2<T>& v, const Vec2<T>& a) {
    DimensionedBound::Point p{name, note(width(v), "velocity of " + name), note(width(a), "acceleration of " + name),
                              {}, {}, {}, {}, {}};
    out.v = std::max(out.v, p.v), out.a = std::max(out.a, p.a);
    return p;
  };
  for (int j = 0; j < g.joint_count(); ++j) {
    const size_t i = static_cast<size_t>(j);
    const LinkageJoint& jt = g.joint(j);
    DimensionedBound::Point p = point(jt.name, m.joint_v[i], m.joint_a[i]);
    if (jt.type == JointType::Prismatic) {
      // As MechanismCheck::Sliding: sigma-dot |u|, sigma-ddot |u|, 2 omega_guide sigma-dot J u,
      // with u (and so |u|) enclosed over the box too.
      const T len = enclosed_sqrt(axis[i].x * axis[i].x + axis[i].y * axis[i].y);
      p.slide = note(width(m.slide[i]), "sliding velocity of " + jt.name);
      p.slide_dot = note(width(m.slide_dot[i]), "sliding acceleration of " + jt.name);
      p.v_unit = note(width(m.slide[i] * len), "sliding velocity of " + jt.name);
      p.a_unit = note(width(m.slide_dot[i] * len), "sliding acceleration of " + jt.name);
      const T w2 = from_int<T>(2) * m.omega[static_cast<size_t>(jt.links[0])] * m.slide[i];
      p.coriolis = note(width(w2 * perp(axis[i])), "Coriolis term of " + jt.name);
      out.sliding_v = std::max(out.sliding_v, *p.v_unit), out.sliding_a = std::max(out.sliding_a, *p.a_unit);
    }
    out.joints.push_back(std::move(p));
  }
  for (const MechanismPoint& pt : s.points) {
    // As in mechanism_check.cpp: from the link's first joint by the rigid-body formulas.
    int j0 = 0;
    while (g.joint(j0).links[0] != pt.link && g.joint(j0).links[1] != pt.link) ++j0;
    const LinkageJoint& j = g.joint(j0);
    const size_t l = static_cast<size_t>(pt.link), i0 = static_cast<size_t>(j0);
    Vec2<T> v0 = m.joint_v[i0], a0 = m.joint_a[i0];
    if (j.type == JointType::Prismatic && pt.link == j.links[0]) {
      const Vec2<T>& u = axis[i0];
      const T sd = m.slide[i0];
      v0 = v0 - sd * u;
      a0 = a0 - (m.slide_dot[i0] * u + (from_int<T>(2) * m.omega[l] * sd) * perp(u));
    }
    const Vec2<T> d = vec_from_rational<T>(pt.at) - at[i0];
    const Vec2<T> v = v0 + m.omega[l] * perp(d);
    const Vec2<T> a = a0 + m.omega_dot[l] * perp(d) - (m.omega[l] * m.omega[l]) * d;
    out.points.push_back(point(pt.name, v, a));
  }
  out.bounded = out.reason.empty();
  return out;
}

}  // namespace linkproof
