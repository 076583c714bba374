// The acceleration-polygon course notes (conventions §B): the acceleration polygon of a four-bar, and its errata.
#include <fmt/format.h>

#include "mechanism/fourbar_polygon.h"
#include "mechanism_catalogues.h"
#include "mechanism/mechanism_catalogue.h"

namespace linkproof::catalogues {

namespace {

struct FourBarCase {
  FourBarRoles roles;
  FourBarPolygon<Rational> polygon;
};

FourBarCase make_case(const MechanismContext& c) {
  const Linkage& g = c.scene.linkage;
  const auto roles = identify_fourbar(g, c.scene.inputs);
  if (!roles) throw InternalError("fourbar_polygon: not a four-bar driven by a crank (applies() should have said so)");
  const auto at = [&](int j) { return g.joint(j).at; };
  return {*roles, construct_fourbar_polygon<Rational>(at(roles->O2), at(roles->A), at(roles->B), at(roles->O4),
                                                      c.scene.inputs[0].rate, c.scene.inputs[0].rate_dot)};
}

bool is_fourbar(const MechanismContext& c) { return identify_fourbar(c.scene.linkage, c.scene.inputs).has_value(); }

// Coupler points of the scene (tracer points on the coupler).
std::vector<const MechanismPoint*> coupler_points(const MechanismContext& c, const FourBarRoles& r) {
  std::vector<const MechanismPoint*> out;
  for (const auto& p : c.scene.points)
    if (p.link == r.coupler) out.push_back(&p);
  return out;
}

bool has_coupler_point(const MechanismContext& c) {
  const auto roles = identify_fourbar(c.scene.linkage, c.scene.inputs);
  return roles && !coupler_points(c, *roles).empty();
}

// The engine's acceleration of a coupler point: from joint A by the rigid-body formula.
Vec2<Rational> engine_point_acceleration(const MechanismContext& c, const FourBarRoles& r, const Vec2<Rational>& P) {
  const auto& m = c.truth.motion;
  const Vec2<Rational> d = P - c.scene.linkage.joint(r.A).at;
  const Rational& w = m.omega[static_cast<size_t>(r.coupler)];
  return m.joint_a[static_cast<size_t>(r.A)] + m.omega_dot[static_cast<size_t>(r.coupler)] * perp(d) - (w * w) * d;
}

Vec2<Rational> engine_point_velocity(const MechanismContext& c, const FourBarRoles& r, const Vec2<Rational>& P) {
  const Vec2<Rational> d = P - c.scene.linkage.joint(r.A).at;
  return c.truth.motion.joint_v[static_cast<size_t>(r.A)] + c.truth.motion.omega[static_cast<size_t>(r.coupler)] * perp(d);
}

void compare_vec(ClaimSides<Rational>& s, const std::string& label, const Vec2<Rational>& a, const Vec2<Rational>& b) {
  s.instances.push_back({label + ".x", a.x, b.x});
  s.instances.push_back({label + ".y", a.y, b.y});
}

std::string text(const Vec2<Rational>& v) { return fmt::format("({}, {})", format_rational(v.x), format_rational(v.y)); }

const char* kFourbarPolygonSource = "acceleration-polygon course notes: four-bar acceleration polygon (docs/conventions.md §B)";

}  // namespace

MechanismCatalogue fourbar_polygon() {
  MechanismCatalogue cat;
  cat.name = "fourbar_polygon";
  const auto claim = [&](std::string id, std::string statement, Expectation e, std::string note, auto f,
                         bool (*applies)(const MechanismContext&)) {
    cat.claims.push_back(MechanismClaim{ClaimInfo{std::move(id), kFourbarPolygonSource, std::move(statement), e, std::move(note), 4, 0},
                                        f, applies});
  };
  claim("seed001.velocity_polygon", "omega3, omega4 from the velocity polygon equal the engine's", Expectation::Holds, "",
        [](const MechanismContext& c) {
          const FourBarCase k = make_case(c);
          const auto& w = c.truth.motion.omega;
          ClaimSides<Rational> s;
          s.instances.push_back({"omega3", k.polygon.omega3, w[static_cast<size_t>(k.roles.coupler)]});
          s.instances.push_back({"omega4", k.polygon.omega4, w[static_cast<size_t>(k.roles.rocker)]});
          return s;
        },
        is_fourbar);
  claim("seed001.acceleration_equation",
        "-omega2^2 R_AO2 + alpha2 R'_AO2 - omega3^2 R_BA + alpha3 R'_BA - (-omega4^2 R_BO4) - alpha4 R'_BO4 = 0 "
        "with the engine's rates",
        Expectation::Holds, "",
        [](const MechanismContext& c) {
          const FourBarCase k = make_case(c);
          const auto& m = c.truth.motion;
          const auto& p = k.polygon;
          const Rational w3 = m.omega[static_cast<size_t>(k.roles.coupler)], w4 = m.omega[static_cast<size_t>(k.roles.rocker)];
          const Rational a3 = m.omega_dot[static_cast<size_t>(k.roles.coupler)],
                         a4 = m.omega_dot[static_cast<size_t>(k.roles.rocker)];
          const Vec2<Rational> lhs = -(p.omega2 * p.omega2) * p.R_AO2 + p.alpha2 * perp(p.R_AO2) - (w3 * w3) * p.R_BA +
                                     a3 * perp(p.R_BA) + (w4 * w4) * p.R_BO4 - a4 * perp(p.R_BO4);
          ClaimSides<Rational> s;
          compare_vec(s, "residual", lhs, Vec2<Rational>{0, 0});
          return s;
        },
        is_fourbar);
  claim("seed001.alpha3_alpha4",
        "alpha3 = A^t_BA . R'_BA / |R_BA|^2 and alpha4 = A^t_B . R'_BO4 / |R_BO4|^2 from the closed polygon equal the "
        "engine's",
        Expectation::Holds, "",
        [](const MechanismContext& c) {
          const FourBarCase k = make_case(c);
          const auto& m = c.truth.motion;
          ClaimSides<Rational> s;
          s.instances.push_back({"alpha3", k.polygon.alpha3, m.omega_dot[static_cast<size_t>(k.roles.coupler)]});
          s.instances.push_back({"alpha4", k.polygon.alpha4, m.omega_dot[static_cast<size_t>(k.roles.rocker)]});
          return s;
        },
        is_fourbar);
  claim("seed001.alpha4.printed_R_BO2",
        "the printed alpha4 = A^t_B . R'_BO2 / |R_BO2|^2 (R_BO2 = B - O2) equals the engine's alpha4",
        Expectation::Fails, "erratum: R_BO2 is R_BO4 (docs/conventions.md §B)",
        [](const MechanismContext& c) {
          const FourBarCase k = make_case(c);
          const Linkage& g = c.scene.linkage;
          const Vec2<Rational> R_BO2 = g.joint(k.roles.B).at - g.joint(k.roles.O2).at;
          ClaimSides<Rational> s;
          s.instances.push_back({"alpha4", dot(k.polygon.A_B_t, perp(R_BO2)) / norm2(R_BO2),
                                 c.truth.motion.omega_dot[static_cast<size_t>(k.roles.rocker)]});
          return s;
        },
        is_fourbar);
  claim("seed001.coupler_point",
        "A_P = -omega2^2 R_AO2 + alpha2 R'_AO2 - omega3^2 R_PA + alpha3 R'_PA equals the engine's acceleration of P",
        Expectation::Holds, "",
        [](const MechanismContext& c) {
          const FourBarCase k = make_case(c);
          ClaimSides<Rational> s;
          for (const MechanismPoint* P : coupler_points(c, k.roles)) {
            const Vec2<Rational> R_PA = P->at - c.scene.linkage.joint(k.roles.A).at;
            compare_vec(s, "A_" + P->name, fourbar_coupler_acceleration(k.polygon, R_PA),
                        engine_point_acceleration(c, k.roles, P->at));
          }
          return s;
        },
        has_coupler_point);
  claim("seed001.coupler_point.printed",
        "the printed A_P = -omega2^2 R_AO2 + omega2 R'_AO2 - omega3^2 R_PA + omega3 R'_PA equals the engine's",
        Expectation::Fails, "erratum: omega2, omega3 are printed where alpha2, alpha3 belong (docs/conventions.md §B)",
        [](const MechanismContext& c) {
          const FourBarCase k = make_case(c);
          const auto& p = k.polygon;
          ClaimSides<Rational> s;
          for (const MechanismPoint* P : coupler_points(c, k.roles)) {
            const Vec2<Rational> R_PA = P->at - c.scene.linkage.joint(k.roles.A).at;
            const Vec2<Rational> printed = p.A_A_n + p.omega2 * perp(p.R_AO2) - (p.omega3 * p.omega3) * R_PA +
                                           p.omega3 * perp(R_PA);
            compare_vec(s, "A_" + P->name, printed, engine_point_acceleration(c, k.roles, P->at));
          }
          return s;
        },
        has_coupler_point);
  claim("seed001.curvature_centre",
        "the path curvature centre of P from the polygon (v_P, A_P) equals the one from the engine's motion",
        Expectation::Holds, "",
        [](const MechanismContext& c) {
          const FourBarCase k = make_case(c);
          const auto& p = k.polygon;
          ClaimSides<Rational> s;
          for (const MechanismPoint* P : coupler_points(c, k.roles)) {
            const Vec2<Rational> R_PA = P->at - c.scene.linkage.joint(k.roles.A).at;
            const Vec2<Rational> v = p.omega2 * perp(p.R_AO2) + p.omega3 * perp(R_PA);
            compare_vec(s, "centre_" + P->name,
                        path_curvature_centre(P->at, v, fourbar_coupler_acceleration(p, R_PA)),
                        path_curvature_centre(P->at, engine_point_velocity(c, k.roles, P->at),
                                              engine_point_acceleration(c, k.roles, P->at)));
          }
          return s;
        },
        has_coupler_point);
  cat.tables = [](const MechanismContext& c) {
    std::vector<ReportTable> out;
    if (!is_fourbar(c)) return out;
    const FourBarCase k = make_case(c);
    const auto& p = k.polygon;
    ReportTable t{"fourbar_polygon", {}};
    t.rows = {{"omega3", format_rational(p.omega3)}, {"omega4", format_rational(p.omega4)},
              {"A_A^n", text(p.A_A_n)},             {"A_A^t", text(p.A_A_t)},
              {"A_BA^n", text(p.A_BA_n)},           {"-A_B^n", text(-p.A_B_n)},
              {"A_BA^t", text(p.A_BA_t)},           {"A_B^t", text(p.A_B_t)},
              {"vertex A_A", text(p.A_A)},          {"vertex A_B", text(p.A_B)},
              {"alpha3", format_rational(p.alpha3)}, {"alpha4", format_rational(p.alpha4)}};
    for (const MechanismPoint* P : coupler_points(c, k.roles)) {
      const Vec2<Rational> R_PA = P->at - c.scene.linkage.joint(k.roles.A).at;
      const Vec2<Rational> a = fourbar_coupler_acceleration(p, R_PA);
      const Vec2<Rational> v = p.omega2 * perp(p.R_AO2) + p.omega3 * perp(R_PA);
      t.rows.emplace_back("A_" + P->name, text(a));
      try {
        t.rows.emplace_back("curvature centre of " + P->name, text(path_curvature_centre(P->at, v, a)));
      } catch (const UndefinedQuantity& u) {
        t.rows.emplace_back("curvature centre of " + P->name, "undefined: " + u.quantity());
      }
    }
    out.push_back(std::move(t));
    return out;
  };
  return cat;
}

}  // namespace linkproof::catalogues
