#include "mechanism/curvature_analysis.h"
#include "geometry/zero_vector.h"
#include "mechanism/mechanism_catalogue.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace linkproof {

namespace {

// Two (point, centre) pairs of the motion m/f for Bobillier: from bars joining m and f when there
// are two (a four-bar: independent of the analytic route), else from the analytic centres of two
// joints of m.
struct BobillierPairs {
  PlanePoint<Rational> A, alpha, B, beta;  ///< finite, or at infinity (docs/mechanisms.md, "Bobillier with sliders")
  std::string from;
};

using PPR = PlanePoint<Rational>;

// The pair a prismatic joint j gives for the motion m/f (docs/mechanisms.md, "Bobillier with
// sliders"): its relative pole P_mk (k the joint's other link) is the point at infinity in the
// direction n = J u. It belongs to m and k alike and, as m and k keep one orientation, moves as a
// point of k: its centre in f is the point of k/f's return circle (the centres of the points at
// infinity: diameter from P_kf to P_kf - a_P / omega^2) on the line through P_kf along n,
//   beta = P_kf + (n . D / |n|^2) n,   D = -a_P / omega_kf^2.
// A guide pinned to f (a rocker) has a_P = 0: beta is its pivot. nullopt with `why` when k/f has
// no finite pole or does not turn.
std::optional<std::pair<PPR, PPR>> prismatic_pair(const Linkage& g, const std::vector<LinkField<Rational>>& fields,
                                                   const LinkageJoint& j, int m, int f, std::string& why) {
  const int k = j.links[0] == m ? j.links[1] : j.links[0];
  if (k == f) {
    why = "its links are the two of the motion: a relative translation";
    return std::nullopt;
  }
  const InflectionCircle<Rational> c = construct_inflection_circle(
      fields[static_cast<size_t>(k)], fields[static_cast<size_t>(f)], fmt::format("P_{},{}", g.link_name(k), g.link_name(f)));
  if (!c.pole.is_finite() || cln::zerop(c.omega)) {
    why = fmt::format("{}/{} has no finite pole: the centre of the point at infinity of the slide is not defined",
                      g.link_name(k), g.link_name(f));
    return std::nullopt;
  }
  const Vec2<Rational> n = perp(j.axis), D = (Rational(-1) / (c.omega * c.omega)) * c.a_pole;
  return std::pair{PPR::infinite(n), PPR::finite(c.pole.at + (dot(n, D) / norm2(n)) * n)};
}

// The pairs, or (nullopt) with `why` saying what was found and what could not be used: a joint
// that is the requested point, an undefined centre, a prismatic pair between the two links of the
// motion (a relative translation) or whose other link has no finite pole relative to f. A centre
// at infinity and a prismatic pair's pole at infinity are pairs (docs/mechanisms.md, "Bobillier
// with sliders").
std::optional<BobillierPairs> bobillier_pairs(const Linkage& g, const std::vector<LinkField<Rational>>& fields,
                                              const CurvatureRequest& r, std::string& why) {
  std::vector<std::pair<PPR, PPR>> pairs;
  std::vector<std::string> names;
  for (int b = 0; b < g.link_count() && pairs.size() < 2; ++b) {
    if (b == r.moving || b == r.fixed || !bar_problem(g, r.moving, b).empty()) continue;
    const BarEnds e = bar_ends(g, r.moving, b);
    if (e.far_link != r.fixed) continue;
    pairs.emplace_back(PPR::finite(g.joint(e.near_joint).at), PPR::finite(g.joint(e.far_joint).at));
    names.push_back(g.link_name(b));
  }
  if (pairs.size() == 2)
    return BobillierPairs{pairs[0].first, pairs[0].second, pairs[1].first, pairs[1].second,
                          fmt::format("bars {} and {} joining links {} and {}", names[0], names[1],
                                      g.link_name(r.moving), g.link_name(r.fixed))};
  const std::string motion = g.link_name(r.moving) + "/" + g.link_name(r.fixed);
  std::vector<std::string> bars = names, unusable;
  pairs.clear();
  names.clear();
  const auto& fm = fields[static_cast<size_t>(r.moving)];
  const auto& ff = fields[static_cast<size_t>(r.fixed)];
  for (const LinkageJoint& j : g.joints()) {
    if (pairs.size() == 2) break;
    if (j.links[0] != r.moving && j.links[1] != r.moving) continue;
    if (j.type == JointType::Prismatic) {
      std::string problem;
      if (const auto p = prismatic_pair(g, fields, j, r.moving, r.fixed, problem)) {
        pairs.push_back(*p);
        names.push_back(j.name + " (its pole at infinity)");
      } else {
        unusable.push_back(fmt::format("prismatic joint {} (links {} and {}: {})", j.name, g.link_name(j.links[0]),
                                       g.link_name(j.links[1]), problem));
      }
      continue;
    }
    if (is_zero_vector(j.at - r.at)) {
      unusable.push_back(fmt::format("joint {} (it is the requested point)", j.name));
      continue;
    }
    const auto c = construct_curvature_centre(j.at, relative_point_motion(fm, ff, j.at), "");
    if (c.kind == PPR::Kind::Undefined) {
      unusable.push_back(fmt::format("joint {} (its centre in {} is {})", j.name, motion, c.reason));
      continue;
    }
    // A centre at infinity (a straight path, e.g. a slider's pin) is a pair too, in its direction.
    pairs.emplace_back(PPR::finite(j.at), c);
    names.push_back(c.is_finite() ? j.name : j.name + " (its centre at infinity)");
  }
  if (pairs.size() < 2) {
    why = fmt::format("Bobillier needs two (point, curvature centre) pairs of {}; bars joining {} and {}: "
                      "{}; joints of {} with a centre: {}{}{}",
                      motion, g.link_name(r.moving), g.link_name(r.fixed), bars.empty() ? "none" : fmt::format("{}", fmt::join(bars, ", ")),
                      g.link_name(r.moving), names.empty() ? "none" : fmt::format("{}", fmt::join(names, ", ")),
                      unusable.empty() ? "" : "; not usable: ", fmt::format("{}", fmt::join(unusable, "; ")));
    return std::nullopt;
  }
  return BobillierPairs{pairs[0].first, pairs[0].second, pairs[1].first, pairs[1].second,
                        fmt::format("analytic centres of joints {} and {} (no two bars join links {} and {})",
                                    names[0], names[1], g.link_name(r.moving), g.link_name(r.fixed))};
}

bool same_rates(const Linkage& g, const std::vector<Rational>& a, const std::vector<Rational>& b, const int skip[2]) {
  for (int l = 0; l < g.link_count(); ++l)
    if (l != skip[0] && l != skip[1] && a[static_cast<size_t>(l)] != b[static_cast<size_t>(l)]) return false;
  return true;
}

}  // namespace

const PlanePoint<Rational>& CurvatureAnalysis::pole(int i, int k) const {
  if (i > k) std::swap(i, k);
  // `poles` holds every pair i < k in link order (analyse_curvature), so the pair's place is
  // known: a scan per lookup made the Aronhold-Kennedy claim over all triples O(L^5) (a 100-loop
  // chain took 70 s). Another order (built by hand) falls back to the scan.
  const auto m = static_cast<long long>(poles.size());
  long long links = 1;
  while (links * (links - 1) / 2 < m) ++links;
  if (links * (links - 1) / 2 == m && i >= 0 && k < links) {
    const long long at = static_cast<long long>(i) * (2 * links - i - 1) / 2 + (k - i - 1);
    const PoleEntry& e = poles[static_cast<size_t>(at)];
    if (e.i == i && e.k == k) return e.pole;
  }
  for (const auto& p : poles)
    if (p.i == i && p.k == k) return p.pole;
  throw InternalError(fmt::format("no pole of links {} and {}", i, k));
}

// The analysis constructs every pole (L(L-1)/2 exact points) and its claims visit every triple
// of links (L^3/6): 202 links take about 3.5 s, 402 links over 8 GiB. Larger mechanisms are
// refused before the work (docs/limits.md).
constexpr int kMaxCurvatureLinks = 200;

CurvatureAnalysis analyse_curvature(const MechanismScene& s, const MechanismSolution<Rational>& truth) {
  const Linkage& g = s.linkage;
  if (g.link_count() > kMaxCurvatureLinks)
    throw InputError(s.source, "mechanism.links",
                     fmt::format("the curvature analysis (every pole, every triple of links) accepts at most {} links "
                                 "(docs/limits.md), this mechanism has {}",
                                 kMaxCurvatureLinks, g.link_count()));
  CurvatureAnalysis a;
  const auto& fields = truth.motion.fields;
  for (int i = 0; i < g.link_count(); ++i)
    for (int k = i + 1; k < g.link_count(); ++k)
      a.poles.push_back({i, k, construct_pole(fields[static_cast<size_t>(i)], fields[static_cast<size_t>(k)],
                                              fmt::format("P_{},{}", g.link_name(i), g.link_name(k)))});
  for (const CurvatureRequest& r : s.curvature) {
    CentreEntry c;
    c.request = r;
    const auto& fm = fields[static_cast<size_t>(r.moving)];
    const auto& ff = fields[static_cast<size_t>(r.fixed)];
    c.motion = relative_point_motion(fm, ff, r.at);
    c.centre = construct_curvature_centre(
        r.at, c.motion, fmt::format("centre of {} in {}/{}", r.point, g.link_name(r.moving), g.link_name(r.fixed)));
    c.circle = construct_inflection_circle(fm, ff, fmt::format("P_{},{}", g.link_name(r.moving), g.link_name(r.fixed)));
    std::string why;
    if (const auto p = bobillier_pairs(g, fields, r, why)) {
      c.bobillier = construct_bobillier(p->A, p->alpha, p->B, p->beta, r.at, false);
      c.bobillier_mirrored = construct_bobillier(p->A, p->alpha, p->B, p->beta, r.at, true);
      c.bobillier_pairs = p->from;
    } else {
      c.bobillier_pairs = why;
    }
    a.centres.push_back(std::move(c));
  }
  Linkage current = g;
  for (const JointJoiningRequest& r : s.joint_joining) {
    ReductionEntry e;
    e.request = r;
    e.linkage_before = current;
    try {
      e.before = solve_rigid_body(current, s.inputs, s.source);
      e.step = join_joints(current, e.before.motion, r);
      e.problem = e.step.problem;
      if (e.problem.empty()) {
        e.after = solve_rigid_body(e.step.reduced, s.inputs, s.source);
        e.solved = true;
        e.velocities_preserved = same_rates(g, e.before.motion.omega, e.after.motion.omega, r.bars);
        e.accelerations_preserved = same_rates(g, e.before.motion.omega_dot, e.after.motion.omega_dot, r.bars);
        current = e.step.reduced;
      }
    } catch (const InputError& err) {
      e.problem = std::string("the reduced linkage cannot be solved: ") + err.what();
    }
    a.reductions.push_back(std::move(e));
  }
  return a;
}

CurvatureCheck check_curvature(const MechanismScene& s, const std::vector<MechanismCatalogue>& catalogues) {
  CurvatureCheck r;
  r.scene = s.name;
  r.link_names = s.linkage.link_names();
  const MechanismSolution<Rational> truth = solve_mechanism_exact(s);
  r.analysis = std::make_shared<const CurvatureAnalysis>(analyse_curvature(s, truth));
  const MechanismContext ctx{s, truth};
  std::vector<MechanismClaim> all = curvature_claims(r.analysis);
  for (const MechanismCatalogue& cat : catalogues) all.insert(all.end(), cat.claims.begin(), cat.claims.end());
  run_mechanism_claims(all, ctx, r.claims, r.not_applicable);
  return r;
}

std::string exact_radius_text(const Rational& squared) {
  Rational root;
  if (cln::sqrtp(squared, &root)) return format_rational(root);
  return "sqrt(" + format_rational(squared) + ")";
}

}  // namespace linkproof
