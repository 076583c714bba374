#include "report/curvature_report.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <cmath>

#include "report/json_report.h"
#include "report/mechanism_report.h"
#include "report/number_text.h"

namespace linkproof {

using nlohmann::json;
using PP = PlanePoint<Rational>;

namespace {

json vec_json(const Vec2<Rational>& v) { return json::array({format_rational(v.x), format_rational(v.y)}); }
// The decimals of a point, for the "<key>_decimal" members beside exact points.
json vec_decimal_json(const Vec2<Rational>& v) { return json::array({decimal_text(v.x), decimal_text(v.y)}); }

// A coordinate as people read it (report/number_text.h): "3/2 = 1.5".
std::string coordinate_text(const Rational& x) { return readable_number(x); }

// The radius of a curvature centre as people read it: exact ("5/2 = 2.5", "sqrt(13) ≈ 3.605551275").
std::string radius_readable(const Rational& squared) {
  const std::string exact = exact_radius_text(squared);
  if (exact.find("sqrt") == std::string::npos) return readable_number(parse_rational(exact));
  return fmt::format("{} ≈ {:.10g}", exact, std::sqrt(cln::double_approx(squared)));
}

double radius_double(const Rational& squared) { return std::sqrt(cln::double_approx(squared)); }

json point_json(const PP& p) {
  if (p.is_finite()) return vec_json(p.at);
  if (p.kind == PP::Kind::AtInfinity) return json{{"at_infinity", vec_json(p.at)}};
  return json{{"undefined", p.quantity + ": " + p.reason}};
}

std::string point_text(const PP& p) {
  if (p.is_finite()) return fmt::format("({}, {})", coordinate_text(p.at.x), coordinate_text(p.at.y));
  if (p.kind == PP::Kind::AtInfinity)
    return fmt::format("at infinity, direction ({}, {})", coordinate_text(p.at.x), coordinate_text(p.at.y));
  return "undefined (" + p.reason + ")";
}

const std::string& name(const std::vector<std::string>& names, int i) { return names[static_cast<size_t>(i)]; }

json centre_json(const CentreEntry& e, const std::vector<std::string>& names) {
  json j{{"point", e.request.point}, {"moving", name(names, e.request.moving)}, {"fixed", name(names, e.request.fixed)},
         {"velocity", vec_json(e.motion.v)}, {"acceleration", vec_json(e.motion.a)}};
  if (e.centre.is_finite()) {
    j["at"] = vec_json(e.centre.at);
    j["at_decimal"] = vec_decimal_json(e.centre.at);
    const Rational r2 = norm2(e.centre.at - e.request.at);
    j["radius"] = exact_radius_text(r2);
    j["radius_decimal"] = fmt::format("{:.10g}", radius_double(r2));
    j["radius_squared"] = format_rational(r2);
  } else if (e.centre.kind == PP::Kind::AtInfinity) {
    j["at_infinity"] = vec_json(e.centre.at);
    j["reason"] = "v x a = 0: the point is on the inflection circle (an inflection point of its path)";
  } else {
    j["undefined"] = e.centre.reason;
  }
  j["pole"] = point_json(e.circle.pole);
  if (e.circle.pole.is_finite()) {
    j["inflection_pole"] = point_json(inflection_pole(e.circle));
    j["pole_normal"] = vec_json(e.circle.normal);
    j["pole_tangent"] = vec_json(e.circle.tangent);
  }
  json b{{"pairs", e.bobillier_pairs}};
  if (e.bobillier) {
    const auto& c = *e.bobillier;
    b["version"] = std::string(1, c.version);
    b["P"] = point_json(c.P);
    b["Q_AB"] = point_json(c.Q_AB);
    if (c.P.is_finite() && c.Q_AB.is_finite()) b["q_AC_direction"] = vec_json(c.q_AC_direction);
    b["Q_AC"] = point_json(c.Q_AC);
    b["gamma"] = point_json(c.gamma);
  }
  j["bobillier"] = b;
  return j;
}

json reduction_json(const ReductionEntry& e, const std::vector<std::string>& names) {
  json j{{"link", name(names, e.request.link)},
         {"bars", {name(names, e.request.bars[0]), name(names, e.request.bars[1])}},
         {"order", e.request.order}};
  if (e.step.I.kind != PP::Kind::Undefined || e.step.ends[0].near_joint >= 0) j["I"] = point_json(e.step.I);
  if (!e.problem.empty()) {
    j["problem"] = e.problem;
    return j;
  }
  json far = json::object(), poles = json::object();
  for (int b = 0; b < 2; ++b) {
    far[name(names, e.request.bars[b])] = point_json(e.step.new_far[b]);
    poles[name(names, e.request.bars[b])] = point_json(e.step.pole[b]);
  }
  j["new_far"] = far;
  j["poles"] = poles;
  j["velocities_preserved"] = e.velocities_preserved;
  j["accelerations_preserved"] = e.accelerations_preserved;
  return j;
}

}  // namespace

json curvature_json(const CurvatureAnalysis& a, const std::vector<std::string>& names) {
  json poles = json::array(), centres = json::array(), reductions = json::array();
  for (const PoleEntry& p : a.poles) {
    json j{{"links", {name(names, p.i), name(names, p.k)}}};
    if (p.pole.is_finite()) j["at"] = vec_json(p.pole.at), j["at_decimal"] = vec_decimal_json(p.pole.at);
    else if (p.pole.kind == PP::Kind::AtInfinity) j["at_infinity"] = vec_json(p.pole.at);
    else j["undefined"] = p.pole.reason;
    poles.push_back(j);
  }
  for (const CentreEntry& e : a.centres) centres.push_back(centre_json(e, names));
  for (const ReductionEntry& e : a.reductions) reductions.push_back(reduction_json(e, names));
  return {{"poles", poles}, {"curvature_centres", centres}, {"reductions", reductions}};
}

json to_json(const CurvatureCheck& c, const ClaimsStatus& status) {
  json j = curvature_json(*c.analysis, c.link_names);
  json claims = json::array();
  for (const auto& cl : c.claims) claims.push_back(to_json(cl));
  j["scene"] = c.scene;
  j["claims"] = claims;
  j["not_applicable"] = c.not_applicable;
  j["summary"] = claims_summary_json(c.claims, status);
  j["exit_status"] = status.exit_status;
  return j;
}

void write_curvature_text(std::ostream& out, const CurvatureAnalysis& a, const std::vector<std::string>& names) {
  fmt::print(out, "\npoles\n");
  for (const PoleEntry& p : a.poles)
    fmt::print(out, "  P_{},{:<6} {}\n", name(names, p.i), name(names, p.k), point_text(p.pole));
  if (!a.centres.empty()) fmt::print(out, "\ncurvature centres\n");
  for (const CentreEntry& e : a.centres) {
    fmt::print(out, "  {} in {}/{}: {}", e.request.point, name(names, e.request.moving), name(names, e.request.fixed),
               point_text(e.centre));
    if (e.centre.is_finite()) fmt::print(out, ", radius {}", radius_readable(norm2(e.centre.at - e.request.at)));
    fmt::print(out, "\n    pole {}, inflection pole {}\n", point_text(e.circle.pole), point_text(inflection_pole(e.circle)));
    fmt::print(out, "    Bobillier ({}): {}\n", e.bobillier_pairs,
               e.bobillier ? point_text(e.bobillier->gamma) : std::string("not constructed"));
  }
  if (!a.reductions.empty()) fmt::print(out, "\njoint-joining\n");
  for (const ReductionEntry& e : a.reductions) {
    fmt::print(out, "  link {} bars {},{} order {}: ", name(names, e.request.link), name(names, e.request.bars[0]),
               name(names, e.request.bars[1]), e.request.order);
    if (!e.problem.empty()) {
      fmt::print(out, "not done: {}\n", e.problem);
      continue;
    }
    fmt::print(out, "I {}", point_text(e.step.I));
    for (int b = 0; b < 2; ++b)
      fmt::print(out, ", far joint of {} {}", name(names, e.request.bars[b]), point_text(e.step.new_far[b]));
    fmt::print(out, "\n    velocities preserved {}, accelerations preserved {}\n", e.velocities_preserved,
               e.accelerations_preserved);
  }
}

void write_text(std::ostream& out, const CurvatureCheck& c, const ClaimsStatus& status) {
  fmt::print(out, "scene {} (exact arithmetic)\n", c.scene);
  write_curvature_text(out, *c.analysis, c.link_names);
  write_claim_section(out, c.claims, c.not_applicable, status);
}

}  // namespace linkproof
