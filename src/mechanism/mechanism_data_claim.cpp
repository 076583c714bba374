#include "mechanism/mechanism_data_claim.h"

#include <cln/rational.h>
#include <fmt/format.h>

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "check/arithmetic_types.h"
#include "core/symbolic_scalar.h"
#include "mechanism/curvature.h"

namespace linkproof {

namespace {

using Node = MechanismNode;
using V = Vec2<Rational>;

std::string list_names(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

void bind(Node& n, const MechanismScene& s, const std::string& field) {
  for (Node& c : n.children) bind(c, s, field);
  if (n.op != Node::Op::Name) return;
  const Linkage& g = s.linkage;
  const auto fail = [&](const std::string& problem) { throw InputError(n.where, field, problem); };
  std::vector<std::string> joints, points;
  for (const LinkageJoint& j : g.joints()) joints.push_back(j.name);
  for (const MechanismPoint& p : s.points) points.push_back(p.name);
  switch (n.kind) {
    case ClaimKind::Link: {
      const auto l = g.find_link(n.name);
      if (!l) fail(fmt::format("unknown link '{}' (the scene's links: {})", n.name, list_names(g.link_names())));
      n.index = *l;
      return;
    }
    case ClaimKind::Point: {
      if (const auto j = g.find_joint(n.name)) {
        n.index = *j;
        return;
      }
      const auto p = std::find(points.begin(), points.end(), n.name);
      if (p == points.end())
        fail(fmt::format("unknown joint or point '{}' (joints: {}; points: {})", n.name, list_names(joints),
                         points.empty() ? "none" : list_names(points)));
      n.index = static_cast<int>(p - points.begin());
      n.is_tracer_point = true;
      return;
    }
    case ClaimKind::Slider: {
      const auto j = g.find_joint(n.name);
      if (!j) fail(fmt::format("unknown joint '{}' (joints: {})", n.name, list_names(joints)));
      if (g.joint(*j).type != JointType::Prismatic)
        fail(fmt::format("joint '{}' is revolute: sliding rates need a prismatic joint", n.name));
      n.index = *j;
      return;
    }
    default: LINKPROOF_ASSERT(false, "a name node of a value kind");
  }
}

template <class T>
using Value = MechanismValueOf<T>;

template <class T>
Value<T> number(T x) {
  return {false, std::move(x), from_int<T>(0)};
}
template <class T>
Value<T> vector_value(const Vec2<T>& v) {
  return {true, v.x, v.y};
}
template <class T>
Vec2<T> as_vector(const Value<T>& v) {
  return {v.x, v.y};
}

template <class T>
const Vec2<T>& position(const Node& n, const MechanismFrameOf<T>& f) {
  return n.is_tracer_point ? f.point_at[static_cast<size_t>(n.index)] : f.joint_at[static_cast<size_t>(n.index)];
}

template <class T>
const LinkField<T>& field_of(const Node& n, const MechanismFrameOf<T>& f) {
  return f.fields[static_cast<size_t>(n.index)];
}

[[noreturn]] void undefined(const Node& n, const std::string& reason) { throw UndefinedQuantity(n.text, reason); }

// |u| of a prismatic axis: 1 where the frame's axes are unit by construction, else the exact
// length when it is rational (a unit or Pythagorean direction).
template <class T>
T axis_length(const Node& n, const MechanismFrameOf<T>& f) {
  if (f.unit_axes) return from_int<T>(1);
  if constexpr (std::is_same_v<T, GiNaC::ex>) {
    undefined(n, "the axis length of a symbolic axis that is not a unit vector");
  } else {
    // The scene's exact axis: its length is rational or the quantity is undefined, in every
    // arithmetic alike (a floating run never rounds an irrational |u| into a value).
    const V& u = f.scene.linkage.joint(n.index).axis;
    cln::cl_RA root;
    if (!cln::sqrtp(norm2(u), &root))
      undefined(n, fmt::format("the axis ({}, {}) of joint '{}' has an irrational length: give it as a rational unit "
                               "direction (e.g. [3/5, 4/5] or an angle) or compare dot(vel(J, slider, guide), axis)",
                               format_rational(u.x), format_rational(u.y), n.name));
    return from_rational<T>(root);
  }
}

// b^e for an integer e (b != 0 when e < 0), by squaring.
template <class T>
T integer_power(const T& b, int e) {
  T result = from_int<T>(1), base = b;
  for (unsigned k = static_cast<unsigned>(e < 0 ? -e : e); k > 0; k >>= 1) {
    if (k & 1u) result = result * base;
    if (k > 1) base = base * base;
  }
  return e < 0 ? from_int<T>(1) / result : result;
}

// The largest magnitude of a summand met while evaluating a claim in floating point: the scale a
// derived error bound is judged against (check/judge.h), so that a claim whose sides are exactly 0
// (a closed polygon: sum of terms = 0) is confirmed to the accuracy of its terms.
struct SummandScale {
  double largest = 0;
  template <class T>
  void add(const Value<T>& v) {
    if constexpr (ScalarTraits<T>::has_error_bound)
      for (const T* c : {&v.x, &v.y}) largest = std::max(largest, std::min(std::abs(ScalarTraits<T>::to_double(*c)), DBL_MAX));
  }
};

template <class T>
Value<T> evaluate_node(const Node& n, const MechanismFrameOf<T>& f, SummandScale* scale);

template <class T>
Value<T> call(const Node& n, const MechanismFrameOf<T>& f, SummandScale* scale) {
  using Q = Evaluation;
  using P = PlanePoint<T>;
  const auto& a = n.children;
  const auto value = [&](size_t k) { return evaluate_node(a[k], f, scale); };
  const auto relative_motion = [&] { return relative_point_motion(field_of(a[1], f), field_of(a[2], f), position(a[0], f)); };
  const auto slide = [&](const std::vector<T>& rates) { return rates[static_cast<size_t>(a[0].index)] * axis_length(a[0], f); };
  switch (n.word->evaluation) {
    case Q::Omega: return number(field_of(a[0], f).omega);
    case Q::OmegaRelative: return number(field_of(a[0], f).omega - field_of(a[1], f).omega);
    case Q::Alpha: return number(field_of(a[0], f).omega_dot);
    case Q::AlphaRelative: return number(field_of(a[0], f).omega_dot - field_of(a[1], f).omega_dot);
    case Q::Position: return vector_value(position(a[0], f));
    case Q::Velocity: return vector_value(field_of(a[1], f).velocity(position(a[0], f)));
    case Q::VelocityRelative: return vector_value(relative_motion().v);
    case Q::Acceleration: return vector_value(field_of(a[1], f).acceleration(position(a[0], f)));
    case Q::AccelerationRelative: return vector_value(relative_motion().a);
    case Q::Pole: {
      const P p = construct_pole(field_of(a[0], f), field_of(a[1], f), n.text);
      if (p.kind == P::Kind::AtInfinity) undefined(n, "the pole is at infinity: omega(L) = omega(M), a relative translation");
      if (!p.is_finite()) undefined(n, p.reason);
      return vector_value(p.at);
    }
    case Q::Centre:
    case Q::CentreAt: {
      // centre_at: the point of L at a constructed position (a vector argument), not a named one.
      const Vec2<T> X = n.word->evaluation == Q::Centre ? position(a[0], f) : as_vector(value(0));
      const P c = construct_curvature_centre(X, relative_point_motion(field_of(a[1], f), field_of(a[2], f), X), n.text);
      if (c.kind == P::Kind::AtInfinity)
        undefined(n, "the centre is at infinity: the point is on the inflection circle (v x a = 0)");
      if (!c.is_finite()) undefined(n, c.reason);
      return vector_value(c.at);
    }
    case Q::SlidingV: return number(slide(f.motion.slide));
    case Q::SlidingA: return number(slide(f.motion.slide_dot));
    case Q::Axis: {
      // Unit, like the axis the sliding rates are measured along: a value independent of how
      // long the scene writes the axis (a proof's axes are unit by construction).
      const T length = axis_length(a[0], f);
      const Vec2<T>& u = f.axis[static_cast<size_t>(a[0].index)];
      return vector_value(Vec2<T>{u.x / length, u.y / length});
    }
    case Q::Dot: return number(dot(as_vector(value(0)), as_vector(value(1))));
    case Q::Cross: return number(cross(as_vector(value(0)), as_vector(value(1))));
    case Q::Perp: return vector_value(perp(as_vector(value(0))));
    case Q::Norm2: return number(norm2(as_vector(value(0))));
    case Q::Vx: return number(value(0).x);
    case Q::Vy: return number(value(0).y);
    case Q::Vec: return vector_value(Vec2<T>{value(0).x, value(1).x});
    case Q::Meet: {
      const P p = intersect_lines(as_vector(value(0)), as_vector(value(1)), as_vector(value(2)), as_vector(value(3)), n.text);
      if (p.kind == P::Kind::AtInfinity) undefined(n, "the two lines are parallel");
      if (!p.is_finite()) undefined(n, p.reason);
      return vector_value(p.at);
    }
    default: break;  // a word of the polygon language alone
  }
  LINKPROOF_ASSERT(false, "a mechanism word without an evaluation");
  return {};
}

template <class T>
std::vector<Vec2<T>> exact_points(const std::vector<MechanismPoint>& points) {
  std::vector<Vec2<T>> out;
  for (const MechanismPoint& p : points) out.push_back(vec_from_rational<T>(p.at));
  return out;
}

template <class T>
std::vector<Vec2<T>> exact_joints(const Linkage& g, bool axes) {
  std::vector<Vec2<T>> out;
  for (const LinkageJoint& j : g.joints()) out.push_back(vec_from_rational<T>(axes ? j.axis : j.at));
  return out;
}

}  // namespace

template <class T>
MechanismFrameOf<T>::MechanismFrameOf(const MechanismScene& s, const MechanismMotion<T>& m)
    : MechanismFrameOf(s, m, exact_joints<T>(s.linkage, false), exact_points<T>(s.points), exact_joints<T>(s.linkage, true),
                       false) {}

template <class T>
MechanismFrameOf<T>::MechanismFrameOf(const MechanismScene& s, const MechanismMotion<T>& m, std::vector<Vec2<T>> joints,
                                      std::vector<Vec2<T>> points, std::vector<Vec2<T>> axes, bool unit)
    : scene(s), motion(m), joint_at(std::move(joints)), point_at(std::move(points)), axis(std::move(axes)), unit_axes(unit),
      fields(m.fields) {
  LINKPROOF_ASSERT(fields.size() == static_cast<size_t>(s.linkage.link_count()), "a motion without its links' fields");
}

void bind_mechanism_claim(MechanismDataClaim& claim, const MechanismScene& scene) {
  bind(claim.lhs.root(), scene, claim.lhs.field());
  bind(claim.rhs.root(), scene, claim.rhs.field());
}

namespace {

template <class T>
Value<T> evaluate_node(const Node& n, const MechanismFrameOf<T>& f, SummandScale* scale) {
  switch (n.op) {
    case Node::Op::Constant: return number(from_rational<T>(n.constant));
    case Node::Op::Name: LINKPROOF_ASSERT(false, "a name evaluated as a value"); return {};
    case Node::Op::Call: return call(n, f, scale);
    case Node::Op::Negate: {
      Value<T> v = evaluate_node(n.children[0], f, scale);
      v.x = -v.x, v.y = -v.y;
      return v;
    }
    case Node::Op::Power: {
      const T b = evaluate_node(n.children[0], f, scale).x;
      if (n.exponent < 0 && is_zero(b)) throw UndefinedQuantity(n.children[0].text, "a negative power of 0 (it is 0 here)");
      return number(integer_power(b, n.exponent));
    }
    default: break;
  }
  const Value<T> a = evaluate_node(n.children[0], f, scale);
  const Value<T> b = evaluate_node(n.children[1], f, scale);
  if (scale && (n.op == Node::Op::Add || n.op == Node::Op::Subtract)) scale->add(a), scale->add(b);
  switch (n.op) {
    case Node::Op::Add: return {a.is_vector, a.x + b.x, a.y + b.y};
    case Node::Op::Subtract: return {a.is_vector, a.x - b.x, a.y - b.y};
    case Node::Op::Multiply:
      if (a.is_vector) return {true, a.x * b.x, a.y * b.x};
      if (b.is_vector) return {true, a.x * b.x, a.x * b.y};
      return number(a.x * b.x);
    case Node::Op::Divide:
      if (is_zero(b.x)) throw UndefinedQuantity(n.children[1].text, "a divisor that is 0 here");
      return {a.is_vector, a.x / b.x, a.is_vector ? a.y / b.x : from_int<T>(0)};
    default: break;
  }
  LINKPROOF_ASSERT(false, "an unknown mechanism expression node");
  return {};
}

}  // namespace

template <class T>
MechanismValueOf<T> evaluate_mechanism_expression(const Node& n, const MechanismFrameOf<T>& f) {
  return evaluate_node(n, f, nullptr);
}

template <class T>
ClaimSides<T> evaluate_mechanism_claim(const MechanismDataClaim& claim, const MechanismFrameOf<T>& f) {
  SummandScale scale;
  const auto side = [&](const MechanismExpression& e) {
    return Defined<Value<T>>::attempt([&] {
      const Value<T> v = evaluate_node(e.root(), f, &scale);
      scale.add(v);  // a vector's components are judged against its larger one
      return v;
    });
  };
  const Defined<Value<T>> l = side(claim.lhs), r = side(claim.rhs);
  const auto component = [](const Defined<Value<T>>& v, bool y) {
    if (!v.has_value()) return Defined<T>::undefined(v.quantity(), v.reason());
    return Defined<T>(y ? v.get().y : v.get().x);
  };
  ClaimSides<T> s;
  s.instances.reserve(2);
  if (claim.lhs.kind() == ClaimKind::Vector) {
    s.instances.push_back({"x", component(l, false), component(r, false), scale.largest});
    s.instances.push_back({"y", component(l, true), component(r, true), scale.largest});
  } else {
    s.instances.push_back({"total", component(l, false), component(r, false), scale.largest});
  }
  return s;
}

// Every arithmetic (exact and the floating ones with their error bounds: a sample of a
// topology in `--arith A`), and GiNaC expressions for the proof over a topology.
#define LINKPROOF_INSTANTIATE_MECHANISM_CLAIM(enumerator, name, type)                                       \
  template struct MechanismFrameOf<type>;                                                                  \
  template MechanismValueOf<type> evaluate_mechanism_expression(const Node&, const MechanismFrameOf<type>&); \
  template ClaimSides<type> evaluate_mechanism_claim(const MechanismDataClaim&, const MechanismFrameOf<type>&);
LINKPROOF_FOR_EACH_ARITHMETIC(LINKPROOF_INSTANTIATE_MECHANISM_CLAIM)
// The exact mechanism check (MechanismFrame, mechanism_check.cpp) computes in CLN rationals.
LINKPROOF_INSTANTIATE_MECHANISM_CLAIM(Exact, "exact", ::linkproof::Rational)
template struct MechanismFrameOf<GiNaC::ex>;
template MechanismValueOf<GiNaC::ex> evaluate_mechanism_expression(const Node&, const MechanismFrameOf<GiNaC::ex>&);
#undef LINKPROOF_INSTANTIATE_MECHANISM_CLAIM

MechanismClaim to_mechanism_claim(const MechanismDataClaim& claim) {
  MechanismClaim c;
  c.info = claim.info;
  c.evaluate = [claim](const MechanismContext& ctx) {
    const MechanismFrame frame(ctx.scene, ctx.truth.motion);
    return evaluate_mechanism_claim(claim, frame);
  };
  return c;
}

}  // namespace linkproof
