// The claims of mechanism/curvature_analysis.h, on a finished analysis.
#include <fmt/format.h>

#include "mechanism/curvature_analysis.h"
#include "mechanism/mechanism_catalogue.h"

namespace linkproof {

namespace {

using PP = PlanePoint<Rational>;
using Cmp = Comparison<Rational>;

Defined<Rational> coordinate(const PP& p, int axis, const std::string& name) {
  if (p.is_finite()) return axis == 0 ? p.at.x : p.at.y;
  if (p.kind == PP::Kind::AtInfinity) return Defined<Rational>::undefined(name, "at infinity");
  return Defined<Rational>::undefined(p.quantity.empty() ? name : p.quantity, p.reason);
}

// lhs and rhs points compared coordinate by coordinate.
void compare_points(ClaimSides<Rational>& s, const std::string& label, const PP& lhs, const std::string& lhs_name,
                    const PP& rhs, const std::string& rhs_name) {
  for (int axis = 0; axis < 2; ++axis)
    s.instances.push_back(Cmp{fmt::format("{} {}", label, axis == 0 ? "x" : "y"), coordinate(lhs, axis, lhs_name),
                              coordinate(rhs, axis, rhs_name)});
}

Defined<Rational> maybe(const std::optional<Rational>& x, const std::string& name, const std::string& why) {
  if (x) return *x;
  return Defined<Rational>::undefined(name, why);
}

// Every bar of the linkage seen from both ends: (bar, near link m, far link f).
struct BarView {
  int bar, moving, fixed;
  BarEnds ends;
};
std::vector<BarView> all_bars(const Linkage& g) {
  std::vector<BarView> out;
  for (int b = 0; b < g.link_count(); ++b)
    for (int m = 0; m < g.link_count(); ++m)
      if (m != b && bar_problem(g, m, b).empty()) {
        const BarEnds e = bar_ends(g, m, b);
        if (e.far_link != m) out.push_back({b, m, e.far_link, e});
      }
  return out;
}

// f(bar, field of its near link, field of its far link) for every bar seen from both ends.
template <class F>
void for_each_bar(const MechanismContext& c, F f) {
  const auto& fields = c.truth.motion.fields;
  for (const BarView& b : all_bars(c.scene.linkage))
    f(b, fields[static_cast<size_t>(b.moving)], fields[static_cast<size_t>(b.fixed)]);
}

std::string motion_name(const Linkage& g, int m, int f) { return g.link_name(m) + "/" + g.link_name(f); }

// Why the pole of m/f is not a finite point: at infinity (a relative translation, e.g. across a
// prismatic pair, which it names), or undefined (no relative motion).
std::string pole_not_finite(const Linkage& g, const PP& pole, int m, int f) {
  std::string pair;
  for (const LinkageJoint& j : g.joints())
    if (j.type == JointType::Prismatic && ((j.links[0] == m && j.links[1] == f) || (j.links[0] == f && j.links[1] == m)))
      pair = fmt::format(" (the prismatic joint {} between them)", j.name);
  if (pole.kind == PP::Kind::AtInfinity)
    return fmt::format("the pole of {} is at infinity in the direction ({}, {}): the motion is an instantaneous "
                       "translation{}, omega = 0, and Euler-Savary needs a finite pole",
                       motion_name(g, m, f), format_rational(pole.at.x), format_rational(pole.at.y), pair);
  return fmt::format("the pole of {} is undefined: {}{}", motion_name(g, m, f), pole.reason, pair);
}

MechanismClaim make(std::string id, std::string source, std::string statement, Expectation e,
                    std::function<ClaimSides<Rational>(const MechanismContext&)> f,
                    std::function<bool(const MechanismContext&)> applies = {}) {
  return MechanismClaim{ClaimInfo{std::move(id), std::move(source), std::move(statement), e, "", 4, 0}, std::move(f),
                        std::move(applies)};
}

const std::string kSource = "Dijksman (1984), docs/conventions.md §D";

void add_pole_claims(std::vector<MechanismClaim>& out, const std::shared_ptr<const CurvatureAnalysis>& a) {
  out.push_back(make(
      "curvature.joint_poles", kSource + ": poles",
      "the pole P_ij of the two links of every revolute joint is the joint (v_i = v_j there)", Expectation::Holds,
      [a](const MechanismContext& c) {
        ClaimSides<Rational> s;
        const Linkage& g = c.scene.linkage;
        for (const LinkageJoint& j : g.joints())
          if (j.type == JointType::Revolute)
            compare_points(s, "joint " + j.name, a->pole(j.links[0], j.links[1]), "pole", PP::finite(j.at), j.name);
        return s;
      }));
  out.push_back(make(
      "curvature.aronhold_kennedy", kSource + ": Aronhold-Kennedy",
      "for every triple of links i < j < k the poles P_ij, P_jk, P_ik are collinear: det[P_ij; P_jk; P_ik] = 0 in "
      "homogeneous coordinates (a pole at infinity is its direction with w = 0)",
      Expectation::Holds, [a](const MechanismContext& c) {
        ClaimSides<Rational> s;
        const Linkage& g = c.scene.linkage;
        const int L = g.link_count();
        for (int i = 0; i < L; ++i)
          for (int j = i + 1; j < L; ++j)
            for (int k = j + 1; k < L; ++k) {
              const std::string label = fmt::format("{},{},{}", g.link_name(i), g.link_name(j), g.link_name(k));
              const PP* ps[3] = {&a->pole(i, j), &a->pole(j, k), &a->pole(i, k)};
              Defined<Rational> det = Defined<Rational>::pending();
              bool ok = true;
              for (const PP* p : ps)
                if (p->kind == PP::Kind::Undefined && ok) det = Defined<Rational>::undefined(p->quantity, p->reason), ok = false;
              if (ok) det = collinearity(homogeneous(*ps[0]), homogeneous(*ps[1]), homogeneous(*ps[2]));
              s.instances.push_back(Cmp{label, det, Rational(0)});
            }
        return s;
      }));
}

void add_curvature_claims(std::vector<MechanismClaim>& out, const std::shared_ptr<const CurvatureAnalysis>& a) {
  out.push_back(make(
      "curvature.bar_far_joint_is_centre", kSource + ": a bar joins a point and its curvature centre",
      "for every bar (binary link) between links m and f, the far joint is the path curvature centre "
      "X + (|v|^2/(v x a)) J v of the near joint in the motion m/f (Coriolis included), from both ends",
      Expectation::Holds,
      [](const MechanismContext& c) {
        ClaimSides<Rational> s;
        const Linkage& g = c.scene.linkage;
        for_each_bar(c, [&](const BarView& b, const LinkField<Rational>& fm, const LinkField<Rational>& ff) {
          const Vec2<Rational> N = g.joint(b.ends.near_joint).at;
          const PP centre = construct_curvature_centre(N, relative_point_motion(fm, ff, N),
                                                       "centre of " + g.joint(b.ends.near_joint).name);
          compare_points(s, fmt::format("bar {}: {} in {}", g.link_name(b.bar), g.joint(b.ends.near_joint).name,
                                        motion_name(g, b.moving, b.fixed)),
                         centre, "centre", PP::finite(g.joint(b.ends.far_joint).at), g.joint(b.ends.far_joint).name);
        });
        return s;
      },
      [](const MechanismContext& c) { return !all_bars(c.scene.linkage).empty(); }));
  out.push_back(make(
      "curvature.euler_savary.bar_lines", kSource + ": Euler-Savary",
      "on every bar line, from the pole P of the motion m/f of the two links the bar joins: "
      "1/(P S_a) - 1/(P S_b) = 1/(delta sin theta) with S_a the near joint and S_b the far joint "
      "(both sides divided by |u|: 1/((S_a-P).u) - 1/((S_b-P).u) = omega^2/(a_P.u))",
      Expectation::Holds,
      [](const MechanismContext& c) {
        ClaimSides<Rational> s;
        const Linkage& g = c.scene.linkage;
        for_each_bar(c, [&](const BarView& b, const LinkField<Rational>& fm, const LinkField<Rational>& ff) {
          const auto circle = construct_inflection_circle(fm, ff, "pole");
          const Vec2<Rational> N = g.joint(b.ends.near_joint).at, F = g.joint(b.ends.far_joint).at;
          const auto es = euler_savary_sides(circle, F - N, N, PP::finite(F));
          const std::string label = fmt::format("bar {} in {}", g.link_name(b.bar), motion_name(g, b.moving, b.fixed));
          s.instances.push_back(Cmp{label, maybe(es.lhs, "1/(P S_a) - 1/(P S_b)", "a joint is at the pole"),
                                    maybe(es.rhs, "1/(delta sin theta)", "pole at infinity or the bar along the pole tangent")});
        });
        return s;
      },
      [](const MechanismContext& c) { return !all_bars(c.scene.linkage).empty(); }));
  out.push_back(make(
      "curvature.euler_savary.rays", kSource + ": Euler-Savary",
      "for every requested motion m/f, on rays from the pole P in the directions u = (1,0), (0,1), (1,1), (1,-2), "
      "(3,1) with S_a = P + u and S_b its analytic curvature centre: S_b lies on the ray and "
      "1/((S_a-P).u) - 1/((S_b-P).u) = omega^2/(a_P.u)",
      Expectation::Holds,
      [a](const MechanismContext& c) {
        ClaimSides<Rational> s;
        const Linkage& g = c.scene.linkage;
        const auto& fields = c.truth.motion.fields;
        for (const CentreEntry& e : a->centres) {
          const int m = e.request.moving, f = e.request.fixed;
          const std::string name = motion_name(g, m, f);
          if (!e.circle.pole.is_finite()) {
            s.instances.push_back(Cmp{name, Defined<Rational>::undefined("P_" + name, pole_not_finite(g, e.circle.pole, m, f)),
                                      Rational(0)});
            continue;
          }
          const Vec2<Rational> P = e.circle.pole.at;
          const Vec2<Rational> dirs[] = {{1, 0}, {0, 1}, {1, 1}, {1, -2}, {3, 1}};
          for (const auto& u : dirs) {
            const Vec2<Rational> Sa = P + u;
            const PP Sb = construct_curvature_centre(
                Sa, relative_point_motion(fields[static_cast<size_t>(m)], fields[static_cast<size_t>(f)], Sa), "S_b");
            const std::string label = fmt::format("{} u=({},{})", name, format_rational(u.x), format_rational(u.y));
            if (Sb.is_finite()) s.instances.push_back(Cmp{label + " S_b on the ray", cross(Sb.at - P, u), Rational(0)});
            const auto es = euler_savary_sides(e.circle, u, Sa, Sb);
            s.instances.push_back(Cmp{label, maybe(es.lhs, "1/(P S_a) - 1/(P S_b)", "S_b at the pole"),
                                      maybe(es.rhs, "1/(delta sin theta)", "u along the pole tangent")});
          }
        }
        return s;
      },
      [a](const MechanismContext&) { return !a->centres.empty(); }));
}

void add_bobillier_claims(std::vector<MechanismClaim>& out, const std::shared_ptr<const CurvatureAnalysis>& a) {
  for (const bool mirrored : {false, true}) {
    out.push_back(make(
        mirrored ? "curvature.bobillier.mirrored_step_c" : "curvature.bobillier", kSource + ": Bobillier, section 5 (a)-(e)",
        mirrored ? "erratum reading: step (c) with the angle measured in the opposite sense, "
                   "angle(q_AC -> PC) = angle(PB -> PQ_AB), gives the curvature centre"
                 : "steps (a)-(e) by line intersections (angle(PC -> q_AC) = angle(PB -> PQ_AB), directed, same sense) "
                   "give the analytic curvature centre of every requested point",
        mirrored ? Expectation::Fails : Expectation::Holds,
        [a, mirrored](const MechanismContext& c) {
          ClaimSides<Rational> s;
          const Linkage& g = c.scene.linkage;
          for (const CentreEntry& e : a->centres) {
            const auto& b = mirrored ? e.bobillier_mirrored : e.bobillier;
            const std::string label =
                fmt::format("{} in {}", e.request.point, motion_name(g, e.request.moving, e.request.fixed));
            const PP gamma = b ? b->gamma : PP::undefined("Bobillier's gamma of " + label, e.bobillier_pairs);
            compare_points(s, label, gamma, "gamma", e.centre, "analytic centre");
          }
          return s;
        },
        [a](const MechanismContext&) { return !a->centres.empty(); }));
  }
}

// Rates of every link except the step's bars, before and after.
void compare_rates(ClaimSides<Rational>& s, const Linkage& g, const ReductionEntry& e, bool accelerations) {
  const std::string tag = fmt::format("link {} bars {},{}", g.link_name(e.request.link), g.link_name(e.request.bars[0]),
                                      g.link_name(e.request.bars[1]));
  if (!e.solved) {
    s.instances.push_back(Cmp{tag, Defined<Rational>::undefined("reduced linkage of " + tag, e.problem), Rational(0)});
    return;
  }
  const auto& before = accelerations ? e.before.motion.omega_dot : e.before.motion.omega;
  const auto& after = accelerations ? e.after.motion.omega_dot : e.after.motion.omega;
  for (int l = 0; l < g.link_count(); ++l)
    if (l != e.request.bars[0] && l != e.request.bars[1] && l != g.ground())
      s.instances.push_back(Cmp{fmt::format("{}: {}[{}]", tag, accelerations ? "omega_dot" : "omega", g.link_name(l)),
                                after[static_cast<size_t>(l)], before[static_cast<size_t>(l)]});
}

void add_joining_claims(std::vector<MechanismClaim>& out, const std::shared_ptr<const CurvatureAnalysis>& a) {
  for (const int order : {1, 2})
    for (const bool acc : {false, true}) {
      const bool holds = order == 2 || !acc;
      out.push_back(make(
          fmt::format("joint_joining.{}.{}_preserved", order == 1 ? "first_order" : "second_order",
                      acc ? "accelerations" : "velocities"),
          kSource + (order == 1 ? ": sections 2-3" : ": section 4"),
          fmt::format("{}-order joint-joining (near joints of both bars moved to I{}) preserves the {} of every "
                      "other link (the reduced linkage solved again by the same engine){}",
                      order == 1 ? "first" : "second", order == 1 ? ", far joints kept" : ", far joints relocated by (1')",
                      acc ? "angular accelerations" : "angular velocities",
                      holds ? "" : "; expected to fail: first order keeps velocities only"),
          holds ? Expectation::Holds : Expectation::Fails,
          [a, order, acc](const MechanismContext& c) {
            ClaimSides<Rational> s;
            for (const ReductionEntry& e : a->reductions)
              if (e.request.order == order) compare_rates(s, c.scene.linkage, e, acc);
            return s;
          },
          [a, order](const MechanismContext&) {
            for (const ReductionEntry& e : a->reductions)
              if (e.request.order == order) return true;
            return false;
          }));
    }
  const auto has_second = [a](const MechanismContext&) {
    for (const ReductionEntry& e : a->reductions)
      if (e.request.order == 2) return true;
    return false;
  };
  out.push_back(make(
      "joint_joining.second_order.relocation_is_centre", kSource + ": eqs. (1'), (3'), (5'), (7'), (1'')-(7'')",
      "the far joint relocated by 1/(P F') = 1/(P F) + 1/(P I) - 1/(P N) (P the pole of the ternary link and the far "
      "link) is the analytic curvature centre of I in their relative motion",
      Expectation::Holds,
      [a](const MechanismContext& c) {
        ClaimSides<Rational> s;
        const Linkage& g = c.scene.linkage;
        for (const ReductionEntry& e : a->reductions) {
          if (e.request.order != 2) continue;
          for (int b = 0; b < 2; ++b)
            compare_points(s, fmt::format("link {} bar {}", g.link_name(e.request.link), g.link_name(e.request.bars[b])),
                           e.step.new_far[b], "F'", e.step.centre_of_I[b], "centre of I");
        }
        return s;
      },
      has_second));
  out.push_back(make(
      "joint_joining.second_order.any_near_point", kSource + ": section 4 (any point of the bar line)",
      "replacing one bar by a bar from K = 2I - N (another point of its line) to the far joint relocated by the same "
      "formula (K for I) preserves the angular velocities and accelerations of every other link",
      Expectation::Holds,
      [a](const MechanismContext& c) {
        ClaimSides<Rational> s;
        const Linkage& g = c.scene.linkage;
        for (const ReductionEntry& e : a->reductions) {
          if (e.request.order != 2 || !e.solved) continue;
          for (int b = 0; b < 2; ++b) {
            const BarEnds& ends = e.step.ends[b];
            const Vec2<Rational> N = e.linkage_before.joint(ends.near_joint).at;
            const Vec2<Rational> F = e.linkage_before.joint(ends.far_joint).at;
            const Vec2<Rational> K = Rational(2) * e.step.I.at - N;
            const std::string tag = fmt::format("link {} bar {}", g.link_name(e.request.link), g.link_name(e.request.bars[b]));
            const PP Fk = relocate_far_joint(e.step.pole[b].at, N, F, K, "F' for K");
            if (!Fk.is_finite()) {
              s.instances.push_back(Cmp{tag, coordinate(Fk, 0, "F' for K"), Rational(0)});
              continue;
            }
            const auto moved = solve_rigid_body(move_bar(e.linkage_before, ends, K, Fk.at), c.scene.inputs, c.scene.source);
            for (int l = 0; l < g.link_count(); ++l) {
              if (l == e.request.bars[b] || l == g.ground()) continue;
              const size_t k = static_cast<size_t>(l);
              s.instances.push_back(Cmp{fmt::format("{}: omega[{}]", tag, g.link_name(l)), moved.motion.omega[k],
                                        e.before.motion.omega[k]});
              s.instances.push_back(Cmp{fmt::format("{}: omega_dot[{}]", tag, g.link_name(l)), moved.motion.omega_dot[k],
                                        e.before.motion.omega_dot[k]});
            }
          }
        }
        return s;
      },
      has_second));
}

}  // namespace

std::vector<MechanismClaim> curvature_claims(std::shared_ptr<const CurvatureAnalysis> analysis) {
  std::vector<MechanismClaim> out;
  add_pole_claims(out, analysis);
  add_curvature_claims(out, analysis);
  add_bobillier_claims(out, analysis);
  add_joining_claims(out, analysis);
  return out;
}

}  // namespace linkproof
