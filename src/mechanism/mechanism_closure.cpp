#include "mechanism/mechanism_closure.h"

#include <fmt/format.h>

#include "linkproof/core/error.h"
#include "symbolic/time_derivative.h"

namespace linkproof {

using namespace GiNaC;

namespace {

ex exact(const Rational& q) { return numeric(cln::cl_N(q)); }

Rational to_rational(const ex& e) {
  if (!is_a<numeric>(e) || !ex_to<numeric>(e).is_rational())
    throw InternalError("mechanism closure: expected a rational number, got a non-numeric expression");
  return cln::the<cln::cl_RA>(ex_to<numeric>(e).to_cl_N());
}

}  // namespace

MechanismClosure::MechanismClosure(const Linkage& g) {
  const int N = g.unknown_count();
  for (int c = 0; c < N; ++c) {
    angle_.emplace_back(fmt::format("q{}", c));
    rate_.emplace_back(fmt::format("qd{}", c));
    rate_dot_.emplace_back(fmt::format("qdd{}", c));
  }
  std::vector<symbol> third;
  for (int c = 0; c < N; ++c) third.emplace_back(fmt::format("qddd{}", c));
  TimeDerivative d;
  for (int c = 0; c < N; ++c) {
    d.set_rate(angle_[c], rate_[c]);
    d.set_rate(rate_[c], rate_dot_[c]);
    d.set_rate(rate_dot_[c], third[c]);
    at_reference_[angle_[c]] = 0;
  }
  const auto theta = [&](int link) -> ex {
    const int c = g.unknown_of_link(link);
    return c < 0 ? ex(0) : ex(angle_[static_cast<size_t>(c)]);
  };
  // R(theta) v, as the pair (x, y).
  const auto rotate = [](const ex& t, const Vec2<Rational>& v) {
    return std::pair<ex, ex>{cos(t) * exact(v.x) - sin(t) * exact(v.y), sin(t) * exact(v.x) + cos(t) * exact(v.y)};
  };
  for (const LinkageLoop& loop : g.loops()) {
    exvector xs, ys;  // collected, added once (a sum built by += is quadratic)
    const size_t k = loop.crossings.size();
    for (size_t i = 0; i < k; ++i) {
      const JointCrossing& c = loop.crossings[i];
      const JointCrossing& next = loop.crossings[(i + 1) % k];
      const auto [x, y] = rotate(theta(c.to), g.joint(next.joint).at - g.joint(c.joint).at);
      xs.push_back(x);
      ys.push_back(y);
      if (const int s = g.sliding_sign(c); s != 0) {
        const LinkageJoint& j = g.joint(c.joint);
        const ex sigma = s * angle_[static_cast<size_t>(g.unknown_of_joint(c.joint))];
        const auto [ux, uy] = rotate(theta(j.links[0]), j.axis);
        xs.push_back(sigma * ux);
        ys.push_back(sigma * uy);
      }
    }
    position_.push_back(add(xs));
    position_.push_back(add(ys));
  }
  for (const LinkageJoint& j : g.joints())
    if (j.type == JointType::Prismatic) position_.push_back(theta(j.links[1]) - theta(j.links[0]));
  for (const ex& p : position_) {
    const ex v = d.apply(p);
    const ex a = d.apply(v);
    velocity_.push_back(expand(v.subs(at_reference_)));
    acceleration_.push_back(expand(a.subs(at_reference_)));
  }
}

DenseMatrix<Rational> MechanismClosure::constraint_matrix() const {
  DenseMatrix<Rational> A;
  for (const ex& row : velocity_) {
    std::vector<Rational> r;
    for (const symbol& s : rate_) r.push_back(to_rational(row.coeff(s, 1)));
    A.push_back(std::move(r));
  }
  return A;
}

DenseMatrix<Rational> MechanismClosure::acceleration_matrix() const {
  DenseMatrix<Rational> A;
  for (const ex& row : acceleration_) {
    std::vector<Rational> r;
    for (const symbol& s : rate_dot_) r.push_back(to_rational(row.coeff(s, 1)));
    A.push_back(std::move(r));
  }
  return A;
}

std::vector<Rational> MechanismClosure::acceleration_rhs(const std::vector<Rational>& qdot) const {
  LINKPROOF_ASSERT(qdot.size() == rate_.size(), "acceleration_rhs: wrong number of rates");
  exmap values;
  for (size_t c = 0; c < rate_.size(); ++c) {
    values[rate_[c]] = exact(qdot[c]);
    values[rate_dot_[c]] = 0;
  }
  std::vector<Rational> h;
  for (const ex& row : acceleration_) h.push_back(-to_rational(row.subs(values)));
  return h;
}

std::vector<Rational> MechanismClosure::position_residual() const {
  std::vector<Rational> out;
  for (const ex& row : position_) out.push_back(to_rational(row.subs(at_reference_)));
  return out;
}

}  // namespace linkproof
