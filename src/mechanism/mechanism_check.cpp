#include "mechanism/mechanism_catalogue.h"

#include <Eigen/SVD>
#include <cln/float.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <new>
#include <optional>
#include <stdexcept>
#include <type_traits>

#include "core/tracked.h"
#include "mechanism/axis_length.h"
#include "mechanism/dimensioned_bound.h"
#include "mechanism/mechanism_vector_route.h"
#include "mechanism/mechanism_closure.h"
#include "mechanism/sub_mechanism.h"
#include "check/arithmetic_types.h"

namespace linkproof {

namespace {

// 2-norm condition of [A; input rows] in double (Eigen's SVD): sigma_max / sigma_min.
double velocity_condition(const MechanismScene& s) {
  DenseMatrix<double> A = rigid_body_constraint_matrix<double>(s.linkage);
  std::vector<double> b(A.size(), 0.0);
  append_input_rows(s.linkage, s.inputs, A, b, false, s.source);
  Eigen::MatrixXd M(static_cast<Eigen::Index>(A.size()), static_cast<Eigen::Index>(s.linkage.unknown_count()));
  for (size_t r = 0; r < A.size(); ++r)
    for (size_t c = 0; c < A[r].size(); ++c) {
      // Coordinates beyond double's range: the coefficients overflow and no SVD of them means
      // anything (joints at 1e400 gave "condition 1.0002"). Not computable: inf (JSON null).
      if (!std::isfinite(A[r][c])) return INFINITY;
      M(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = A[r][c];
    }
  // Singular values only. BDCSVD is Jacobi's for small matrices (below 16 columns Eigen uses
  // JacobiSVD itself) and divide and conquer above: a 599-loop chain took 120 s, 80 % of it in
  // a JacobiSVD of this matrix.
  const Eigen::BDCSVD<Eigen::MatrixXd> svd(M);
  const auto& sv = svd.singularValues();
  if (sv.size() == 0 || sv(sv.size() - 1) == 0) return INFINITY;
  return sv(0) / sv(sv.size() - 1);
}

// A floating arithmetic that cannot represent the problem (its coefficients overflow).
struct ArithmeticLimit : std::runtime_error {
  using std::runtime_error::runtime_error;
};

template <class T>
MechanismSolution<T> solve_by_vector_route(const MechanismScene& s, const Linkage& g,
                                           const std::vector<MechanismInput>& inputs) {
  return solve_mechanism<T>(
      g, inputs, rigid_body_constraint_matrix<T>(g),
      [&](const std::vector<T>& qd) { return rigid_body_acceleration_rhs<T>(g, qd); }, s.source);
}

// IEEE values can be inf or NaN; CLN long floats throw instead (caught by the caller). A
// Tracked value is finite when its midpoint is (an unbounded radius is a bound, reported).
template <class F>
bool is_finite_value(const F& x) {
  if constexpr (std::is_floating_point_v<F>) return std::isfinite(x);
  else if constexpr (requires { x.v; x.e; }) return is_finite_value(x.v);
  return true;
}

// The bound reported beside a value: none for an exact one, the running error bound (the radius)
// of a Tracked one.
std::optional<ResultRadius> bound_of(const Rational&) { return std::nullopt; }
template <class F>
std::optional<ResultRadius> bound_of(const Tracked<F>& x) {
  return ResultRadius(x.e);
}

template <class F>
bool all_finite(const MechanismMotion<F>& m) {
  const auto finite = [](const std::vector<F>& xs) { return std::all_of(xs.begin(), xs.end(), is_finite_value<F>); };
  const auto finite_vectors = [](const std::vector<Vec2<F>>& vs) {
    return std::all_of(vs.begin(), vs.end(), [](const Vec2<F>& v) { return is_finite_value(v.x) && is_finite_value(v.y); });
  };
  return finite(m.omega) && finite(m.omega_dot) && finite(m.slide) && finite(m.slide_dot) && finite_vectors(m.joint_v) &&
         finite_vectors(m.joint_a);
}

// A prismatic joint's rates along the unit axis and its Coriolis term (MechanismCheck::Sliding).
template <class T>
MechanismCheck::Sliding sliding_motion(const Linkage& g, int joint, const MechanismMotion<T>& m) {
  const LinkageJoint& j = g.joint(joint);
  const T& sd = m.slide[static_cast<size_t>(joint)];
  const T& sdd = m.slide_dot[static_cast<size_t>(joint)];
  MechanismCheck::Sliding out;
  out.guide = g.link_name(j.links[0]), out.slider = g.link_name(j.links[1]);
  out.axis = j.axis;
  const SquareRootForm length = construct_square_root(norm2(j.axis));
  out.axis_length = length.coefficient, out.axis_radicand = length.radicand;
  // sigma-dot |u|: exact as the coefficient of sqrt(radicand); in floating point |u| enclosed.
  T unit_length;
  if constexpr (ScalarTraits<T>::is_exact) {
    unit_length = length.coefficient;
    out.rate_radicand = length.radicand;
  } else {
    unit_length = square_root_value<T>(norm2(j.axis));
  }
  const T v = sd * unit_length, a = sdd * unit_length;
  out.v_unit = result_number(v), out.a_unit = result_number(a);
  out.v_unit_bound = bound_of(v), out.a_unit_bound = bound_of(a);
  // 2 omega_guide J v_rel with v_rel = sigma-dot u (linkage_motion.h).
  const Vec2<T> coriolis =
      (from_int<T>(2) * m.omega[static_cast<size_t>(j.links[0])] * sd) * perp(vec_from_rational<T>(j.axis));
  out.coriolis[0] = result_number(coriolis.x), out.coriolis[1] = result_number(coriolis.y);
  out.coriolis_bound[0] = bound_of(coriolis.x), out.coriolis_bound[1] = bound_of(coriolis.y);
  return out;
}

// The slots of `g`: the reader writes a slot P as the prismatic pair P [slotted, P.block] and the
// revolute pair P.pin [P.block, pin link] (io/mechanism_scene.h), and refuses any other link or
// joint of those names, so the names and this shape identify a slot.
std::vector<MechanismCheck::Slot> find_slots(const Linkage& g) {
  std::vector<MechanismCheck::Slot> out;
  for (const LinkageJoint& j : g.joints()) {
    if (j.type != JointType::Prismatic || g.link_name(j.links[1]) != j.name + ".block") continue;
    const std::optional<int> pin = g.find_joint(j.name + ".pin");
    if (!pin) continue;
    const LinkageJoint& p = g.joint(*pin);
    if (p.type != JointType::Revolute || (p.links[0] != j.links[1] && p.links[1] != j.links[1])) continue;
    const int pin_link = p.links[0] == j.links[1] ? p.links[1] : p.links[0];
    out.push_back({j.name, g.link_name(j.links[1]), p.name, g.link_name(j.links[0]), g.link_name(pin_link)});
  }
  return out;
}

template <class T>
void fill_motion(MechanismCheck& r, const MechanismScene& s, const MechanismMotion<T>& m) {
  const Linkage& g = s.linkage;
  for (int l = 0; l < g.link_count(); ++l) {
    const T& w = m.omega[static_cast<size_t>(l)];
    const T& wd = m.omega_dot[static_cast<size_t>(l)];
    r.omega.push_back(result_number(w)), r.omega_bound.push_back(bound_of(w));
    r.omega_dot.push_back(result_number(wd)), r.omega_dot_bound.push_back(bound_of(wd));
  }
  for (int i = 0; i < g.link_count(); ++i)
    for (int k = i + 1; k < g.link_count(); ++k) {
      const T w = m.omega[static_cast<size_t>(i)] - m.omega[static_cast<size_t>(k)];
      const T wd = m.omega_dot[static_cast<size_t>(i)] - m.omega_dot[static_cast<size_t>(k)];
      r.relative.push_back({g.link_name(i), g.link_name(k), result_number(w), result_number(wd), bound_of(w), bound_of(wd)});
    }
  // The values of a point's velocity and acceleration and their bounds.
  const auto set_point = [](MechanismCheck::PointMotion& p, const Vec2<T>& v, const Vec2<T>& a) {
    p.v[0] = result_number(v.x), p.v[1] = result_number(v.y), p.a[0] = result_number(a.x), p.a[1] = result_number(a.y);
    p.v_bound[0] = bound_of(v.x), p.v_bound[1] = bound_of(v.y), p.a_bound[0] = bound_of(a.x), p.a_bound[1] = bound_of(a.y);
  };
  for (int j = 0; j < g.joint_count(); ++j) {
    MechanismCheck::PointMotion p;
    p.name = g.joint(j).name;
    set_point(p, m.joint_v[static_cast<size_t>(j)], m.joint_a[static_cast<size_t>(j)]);
    if (g.joint(j).type == JointType::Prismatic) {
      const T& sd = m.slide[static_cast<size_t>(j)];
      const T& sdd = m.slide_dot[static_cast<size_t>(j)];
      p.slide = result_number(sd), p.slide_dot = result_number(sdd);
      p.slide_bound = bound_of(sd), p.slide_dot_bound = bound_of(sdd);
      p.sliding = sliding_motion(g, j, m);
    }
    r.joints.push_back(std::move(p));
  }
  for (const MechanismPoint& pt : s.points) {
    // A tracer point moves with its link: from the link's first joint by the rigid-body formulas.
    int j0 = 0;
    while (g.joint(j0).links[0] != pt.link && g.joint(j0).links[1] != pt.link) ++j0;
    const LinkageJoint& j = g.joint(j0);
    const size_t l = static_cast<size_t>(pt.link);
    Vec2<T> v0 = m.joint_v[static_cast<size_t>(j0)], a0 = m.joint_a[static_cast<size_t>(j0)];
    if (j.type == JointType::Prismatic && pt.link == j.links[0]) {
      // joint_v/a are the slider's point; the guide's point differs by the sliding motion.
      const Vec2<T> u = vec_from_rational<T>(j.axis);
      const T w = m.omega[l], sd = m.slide[static_cast<size_t>(j0)];
      v0 = v0 - sd * u;
      a0 = a0 - (m.slide_dot[static_cast<size_t>(j0)] * u + (from_int<T>(2) * w * sd) * perp(u));
    }
    const Vec2<T> d = vec_from_rational<T>(pt.at - j.at);
    const Vec2<T> v = v0 + m.omega[l] * perp(d);
    const Vec2<T> a = a0 + m.omega_dot[l] * perp(d) - (m.omega[l] * m.omega[l]) * d;
    MechanismCheck::PointMotion p;
    p.name = pt.name;
    set_point(p, v, a);
    r.points.push_back(std::move(p));
  }
}

}  // namespace

ClaimOutcome run_mechanism_claim(const MechanismClaim& claim, const MechanismContext& ctx) {
  ClaimOutcome out;
  out.info = claim.info;
  try {
    const ClaimSides<Rational> sides = claim.evaluate(ctx);
    if (sides.instances.empty() && sides.terms.empty()) {  // nothing compared is no pass
      out.verdict = Verdict::Error;
      out.error = "the claim produced no comparison";
      return out;
    }
    Verdict v = Verdict::Holds;
    for (const auto& c : sides.instances) out.instances.push_back(judge(c));
    for (const auto& c : sides.terms) out.terms.push_back(judge(c));
    for (const auto& o : out.instances) v = combine(v, o.verdict);
    for (const auto& o : out.terms) v = combine(v, o.verdict);
    out.verdict = v;
    for (const auto* list : {&out.instances, &out.terms})
      for (const auto& o : *list)
        if (o.verdict == v && out.headline.label.empty()) out.headline = o;
  } catch (const UndefinedQuantity& u) {
    out.mark_undefined(u.quantity(), u.reason());
  } catch (const std::bad_alloc&) {
    throw;  // out of memory (--max-memory-mb) ends the run: not an evaluation's error
  } catch (const std::exception& e) {
    out.verdict = Verdict::Error;
    out.error = e.what();
  }
  return out;
}

void run_mechanism_claims(const std::vector<MechanismClaim>& claims, const MechanismContext& ctx,
                          std::vector<ClaimOutcome>& outcomes, std::vector<std::string>& not_applicable) {
  for (const MechanismClaim& c : claims) {
    if (c.applies && !c.applies(ctx)) {
      not_applicable.push_back(c.info.id);
      continue;
    }
    outcomes.push_back(run_mechanism_claim(c, ctx));
  }
}

MechanismSolution<Rational> solve_mechanism_exact(const MechanismScene& s) {
  const MechanismClosure closure(s.linkage);
  return solve_mechanism<Rational>(
      s.linkage, s.inputs, closure.constraint_matrix(),
      [&](const std::vector<Rational>& qd) { return closure.acceleration_rhs(qd); }, s.source);
}

std::vector<MechanismClaim> builtin_mechanism_claims() {
  std::vector<MechanismClaim> out;
  out.push_back(MechanismClaim{
      ClaimInfo{"mechanism.routes_agree", "linkproof (issue 4): two derivations of the kinematics",
                "the GiNaC loop closure differentiated twice and the rigid-body vector formulas "
                "(omega J r, omega-dot J r - omega^2 r, Coriolis 2 omega_guide sigma-dot J u) give the same "
                "q-dot and q-ddot",
                Expectation::Holds, "", 4, 0},
      [](const MechanismContext& c) {
        const auto other = solve_by_vector_route<Rational>(c.scene, c.scene.linkage, c.scene.inputs);
        ClaimSides<Rational> sides;
        for (size_t k = 0; k < other.qdot.size(); ++k) {
          sides.instances.push_back({fmt::format("q_dot[{}]", k), c.truth.qdot[k], other.qdot[k]});
          sides.instances.push_back({fmt::format("q_ddot[{}]", k), c.truth.qddot[k], other.qddot[k]});
        }
        return sides;
      },
      {}});
  out.push_back(MechanismClaim{
      ClaimInfo{"mechanism.driver_inversion", "Koshel et al., docs/conventions.md §C: central claim",
                "taking another moving link as the driver, with its omega and omega-dot from the solution, "
                "gives the same omega and omega-dot for every link",
                Expectation::Holds, "", 4, 0},
      [](const MechanismContext& c) {
        const Linkage& g = c.scene.linkage;
        ClaimSides<Rational> sides;
        for (int l = 0; l < g.link_count(); ++l) {
          const Rational& w = c.truth.motion.omega[static_cast<size_t>(l)];
          const bool is_input = c.scene.inputs[0].kind == MechanismInput::Kind::Link && c.scene.inputs[0].index == l;
          if (l == g.ground() || is_input || cln::zerop(w)) continue;  // a link at rest cannot drive
          MechanismInput in{MechanismInput::Kind::Link, l, w, c.truth.motion.omega_dot[static_cast<size_t>(l)]};
          const auto inv = solve_by_vector_route<Rational>(c.scene, g, {in});
          for (int k = 0; k < g.link_count(); ++k) {
            sides.instances.push_back({fmt::format("driver {}: omega[{}]", g.link_name(l), g.link_name(k)),
                                       c.truth.motion.omega[static_cast<size_t>(k)], inv.motion.omega[static_cast<size_t>(k)]});
            sides.instances.push_back({fmt::format("driver {}: omega_dot[{}]", g.link_name(l), g.link_name(k)),
                                       c.truth.motion.omega_dot[static_cast<size_t>(k)],
                                       inv.motion.omega_dot[static_cast<size_t>(k)]});
          }
        }
        return sides;
      },
      // Applies only where some moving link other than the input turns: a link at rest cannot
      // drive, and with none to drive the claim would compare nothing.
      [](const MechanismContext& c) {
        if (c.truth.mobility != 1) return false;
        const Linkage& g = c.scene.linkage;
        for (int l = 0; l < g.link_count(); ++l) {
          const bool is_input = c.scene.inputs[0].kind == MechanismInput::Kind::Link && c.scene.inputs[0].index == l;
          if (l != g.ground() && !is_input && !cln::zerop(c.truth.motion.omega[static_cast<size_t>(l)])) return true;
        }
        return false;
      }});
  return out;
}

namespace {

// The whole check of `s` with `claims` and the tables of `table_catalogues`.
MechanismCheck check_solved(const MechanismScene& s, const std::vector<MechanismClaim>& claims,
                            const std::vector<const MechanismCatalogue*>& table_catalogues, Arithmetic a) {
  const Linkage& g = s.linkage;
  MechanismCheck r;
  r.scene = s.name;
  r.arithmetic = a;
  r.grubler = g.grubler_mobility();
  r.loops = static_cast<int>(g.loops().size());
  r.unknowns = g.unknown_count();
  r.link_names = g.link_names();
  r.slots = find_slots(g);
  const MechanismClosure closure(g);
  const MechanismSolution<Rational> truth = solve_mechanism<Rational>(
      g, s.inputs, closure.constraint_matrix(),
      [&](const std::vector<Rational>& qd) { return closure.acceleration_rhs(qd); }, s.source);
  r.mobility = truth.mobility;
  r.rank = truth.rank;
  r.condition = velocity_condition(s);
  Rational residual = 0;
  for (const Rational& x : closure.position_residual()) residual = cln::max(residual, cln::abs(x));
  r.closure_residual = residual;
  r.dimension_residual = s.dimension_residual;
  if (a == Arithmetic::Exact) {
    fill_motion(r, s, truth.motion);
  } else {
    with_scalar_type(a, [&]<class T>() {
      if constexpr (!ScalarTraits<T>::is_exact) {
        using F = decltype(T{}.v);  // the plain floating type of the arithmetic; T = Tracked<F>
        // The exact solve above has accepted mobility and inputs: a floating route that fails
        // (a rank decided wrongly, an overflow) is a limit of the arithmetic, not bad input.
        std::string failure;
        try {
          // Overflowing coefficients are named as such: solved anyway, they give a rank of 0
          // and a message about the mechanism's mobility, which is not what went wrong.
          for (const auto& row : rigid_body_constraint_matrix<F>(g))
            if (!std::all_of(row.begin(), row.end(), is_finite_value<F>))
              throw ArithmeticLimit("a coefficient of the velocity constraints overflows (joint coordinates beyond "
                                    "the range of " + std::string(to_string(a)) + ")");
          // Solved in Tracked<F>: the midpoints are F's own solve (the same operations, pivots
          // and rank decisions), each with its running error bound.
          const auto floating = solve_by_vector_route<T>(s, g, s.inputs);
          if (floating.mobility == truth.mobility && floating.rank == truth.rank && all_finite(floating.motion))
            fill_motion(r, s, floating.motion);
          else
            failure = fmt::format("rank {} and mobility {} in floating point (exact: rank {}, mobility {}), or a "
                                  "non-finite value",
                                  floating.rank, floating.mobility, truth.rank, truth.mobility);
        } catch (const ArithmeticLimit& e) {
          failure = e.what();
        } catch (const InputError& e) {
          // The exact solve accepted mobility and inputs: the floating one decided otherwise.
          failure = "its rounded solve disagrees with the exact one: " + e.problem();
        } catch (const Error& e) {
          failure = e.what();
        } catch (const cln::floating_point_exception& e) {
          failure = e.what();
        }
        if (!failure.empty()) {
          r.arithmetic_note = std::string(to_string(a)) + " could not solve this configuration (" + failure +
                              "); the motion shown is the exact one";
          fill_motion(r, s, truth.motion);
        }
      }
    });
  }
  // Rationalised positions, axes or rates: how far the results may be from those at the
  // dimensioned values (mechanism/dimensioned_bound.h), whatever the arithmetic.
  if (s.placement.is_rationalised()) r.dimensioned = compute_dimensioned_bound(s, construct_starting_radii(s));
  const MechanismContext ctx{s, truth};
  for (const MechanismCatalogue* cat : table_catalogues) {
    if (!cat->tables) continue;
    try {
      for (auto& t : cat->tables(ctx)) r.tables.push_back(std::move(t));
    } catch (const UndefinedQuantity& u) {  // e.g. a four-bar at its dead centre
      r.tables.push_back(ReportTable{cat->name, {{"undefined", u.quantity() + ": " + u.reason()}}});
    }
  }
  run_mechanism_claims(claims, ctx, r.claims, r.not_applicable);
  r.all_links = g.link_count();
  r.all_loops = r.loops;
  return r;
}

// The links an ask needs: the asked links, those of asked rates, the link of each asked tracer
// point, and for an asked joint one of its links (both for a prismatic joint: its sliding rates).
std::vector<int> asked_links(const MechanismScene& s) {
  const Linkage& g = s.linkage;
  std::vector<int> out;
  for (const AskedRate& r : s.ask->rates) out.push_back(*g.find_link(r.subject.name));
  for (const AskedName& n : s.ask->links) out.push_back(*g.find_link(n.name));
  for (const AskedName& n : s.ask->points) {
    const auto p = std::find_if(s.points.begin(), s.points.end(), [&](const MechanismPoint& q) { return q.name == n.name; });
    if (p != s.points.end()) {
      out.push_back(p->link);
      continue;
    }
    const LinkageJoint& j = g.joint(*g.find_joint(n.name));
    out.push_back(j.links[0]);
    if (j.type == JointType::Prismatic) out.push_back(j.links[1]);
  }
  return out;
}

// Only the asked rows of a check made on the sub-mechanism.
void keep_asked_rows(MechanismCheck& r, const SceneAsk& ask) {
  std::vector<std::string> names;
  std::vector<ResultNumber> omega, omega_dot;
  std::vector<std::optional<ResultRadius>> omega_bound, omega_dot_bound;
  const auto add_link = [&](const std::string& name) {
    if (std::find(names.begin(), names.end(), name) != names.end()) return;
    const auto k = static_cast<size_t>(std::find(r.link_names.begin(), r.link_names.end(), name) - r.link_names.begin());
    names.push_back(name), omega.push_back(r.omega[k]), omega_dot.push_back(r.omega_dot[k]);
    omega_bound.push_back(r.omega_bound[k]), omega_dot_bound.push_back(r.omega_dot_bound[k]);
  };
  for (const AskedRate& x : ask.rates) add_link(x.subject.name);
  for (const AskedName& x : ask.links) add_link(x.name);
  const auto asked_point = [&](const MechanismCheck::PointMotion& p) {
    return std::any_of(ask.points.begin(), ask.points.end(), [&](const AskedName& n) { return n.name == p.name; });
  };
  std::erase_if(r.joints, [&](const auto& p) { return !asked_point(p); });
  std::erase_if(r.points, [&](const auto& p) { return !asked_point(p); });
  r.computed_links = r.link_names;
  r.link_names = std::move(names), r.omega = std::move(omega), r.omega_dot = std::move(omega_dot);
  r.omega_bound = std::move(omega_bound), r.omega_dot_bound = std::move(omega_dot_bound);
  r.relative.clear();
  if (r.dimensioned) {
    const auto listed = [](const std::vector<std::string>& kept, const std::string& name) {
      return std::find(kept.begin(), kept.end(), name) != kept.end();
    };
    std::erase_if(r.dimensioned->links, [&](const auto& b) { return !listed(r.link_names, b.name); });
    const auto not_asked = [&](const DimensionedBound::Point& b) {
      return std::none_of(ask.points.begin(), ask.points.end(), [&](const AskedName& n) { return n.name == b.name; });
    };
    std::erase_if(r.dimensioned->joints, not_asked);
    std::erase_if(r.dimensioned->points, not_asked);
  }
}

}  // namespace

MechanismCheck check_mechanism(const MechanismScene& s, const std::vector<MechanismCatalogue>& catalogues,
                               Arithmetic a) {
  std::vector<MechanismClaim> all = builtin_mechanism_claims();
  std::vector<const MechanismCatalogue*> tables;
  for (const MechanismCatalogue& cat : catalogues) {
    all.insert(all.end(), cat.claims.begin(), cat.claims.end());
    tables.push_back(&cat);
  }
  // A scene whose inputs do not fix its motion gets the whole check's error.
  if (!s.ask || !s.ask->restricts() || !inputs_fix_motion(s.linkage, s.inputs)) return check_solved(s, all, tables, a);
  const std::vector<MechanismClaim> chosen = asked_claims(all, s.ask, s.source);
  std::erase_if(tables, [&](const MechanismCatalogue* cat) {
    return std::none_of(cat->claims.begin(), cat->claims.end(), [&](const MechanismClaim& c) {
      return std::any_of(chosen.begin(), chosen.end(), [&](const MechanismClaim& k) { return k.info.id == c.info.id; });
    });
  });
  // A claim speaks of the whole mechanism (its ranks, its loops, any of its links), so asked
  // claims are evaluated on the whole mechanism; only asked rates, links and points alone are
  // computed on the smallest sub-mechanism that determines them (a claim of rank on a
  // sub-mechanism once gave "holds" where the whole mechanism's ranks were compared).
  std::optional<SubMechanism> sub;
  if (chosen.empty()) sub = determined_sub_mechanism(s, asked_links(s));
  const MechanismScene& solved = sub ? sub->scene : s;
  MechanismCheck r = check_solved(solved, chosen, tables, a);
  r.all_links = s.linkage.link_count();
  r.all_loops = static_cast<int>(s.linkage.loops().size());
  r.ask = s.ask;
  keep_asked_rows(r, *s.ask);
  return r;
}

MechanismCheck check_mechanism_claims(const MechanismScene& s, const std::vector<MechanismClaim>& claims) {
  return check_solved(s, claims, {}, Arithmetic::Exact);
}

MechanismCheck check_mechanism(const MechanismScene& s, Arithmetic a) { return check_mechanism(s, {}, a); }

}  // namespace linkproof
