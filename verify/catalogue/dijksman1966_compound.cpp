// Dijksman (1966) section 3 on compound mechanisms (conventions §A7): the multi-polygon solve
// compared with the mechanism engine, and the rank count.
#include <fmt/format.h>

#include "mechanism/dijksman_compound.h"
#include "mechanism_catalogues.h"
#include "mechanism/mechanism_catalogue.h"

namespace linkproof::catalogues {

namespace {

bool applies(const MechanismContext& c) {
  return dijksman_compound_problem(c.scene.linkage, c.scene.inputs).empty();
}

}  // namespace

MechanismCatalogue dijksman1966_compound() {
  MechanismCatalogue cat;
  cat.name = "dijksman1966_compound";
  cat.claims.push_back(MechanismClaim{
      ClaimInfo{"dijksman1966.compound.omega", "Dijksman (1966) eqs. (5), (6), section 3",
                "every relative omega_ik from eqs. (5), (6) per polygon, the relations omega_ij + omega_jk = "
                "omega_ik and the input equals the engine's omega_i - omega_k",
                Expectation::Holds, "", 4, 0},
      [](const MechanismContext& c) {
        const Linkage& g = c.scene.linkage;
        const auto d = solve_dijksman_compound<Rational>(g, c.scene.inputs[0]);
        ClaimSides<Rational> s;
        for (size_t p = 0; p < d.pairs.size(); ++p) {
          const auto [i, k] = d.pairs[p];
          s.instances.push_back({fmt::format("omega[{},{}]", g.link_name(i), g.link_name(k)), d.omega[p],
                                 c.truth.motion.omega[static_cast<size_t>(i)] - c.truth.motion.omega[static_cast<size_t>(k)]});
        }
        return s;
      },
      applies});
  cat.claims.push_back(MechanismClaim{
      ClaimInfo{"dijksman1966.compound.omega_dot", "Dijksman (1966) eq. (22), companion, section 3",
                "every relative omega-dot_ik from eq. (22) and its companion per polygon, the relations "
                "omega-dot_ij + omega-dot_jk = omega-dot_ik and the input equals the engine's "
                "omega-dot_i - omega-dot_k",
                Expectation::Holds, "", 4, 0},
      [](const MechanismContext& c) {
        const Linkage& g = c.scene.linkage;
        const auto d = solve_dijksman_compound<Rational>(g, c.scene.inputs[0]);
        ClaimSides<Rational> s;
        for (size_t p = 0; p < d.pairs.size(); ++p) {
          const auto [i, k] = d.pairs[p];
          s.instances.push_back({fmt::format("omega_dot[{},{}]", g.link_name(i), g.link_name(k)), d.omega_dot[p],
                                 c.truth.motion.omega_dot[static_cast<size_t>(i)] -
                                     c.truth.motion.omega_dot[static_cast<size_t>(k)]});
        }
        return s;
      },
      applies});
  cat.claims.push_back(MechanismClaim{
      ClaimInfo{"dijksman1966.compound.rank", "Dijksman (1966) section 3, docs/conventions.md §A7",
                "the triangle relations, the input and two relations of (22) per polygon have full rank "
                "L(L-1)/2 (every relative omega-dot is determined)",
                Expectation::Holds, "", 4, 0},
      [](const MechanismContext& c) {
        const Linkage& g = c.scene.linkage;
        const auto d = solve_dijksman_compound<Rational>(g, c.scene.inputs[0]);
        const int L = g.link_count();
        ClaimSides<Rational> s;
        s.instances.push_back({"acceleration rank", Rational(d.acceleration_rank), Rational(L * (L - 1) / 2)});
        s.instances.push_back({"velocity rank", Rational(d.velocity_rank), Rational(L * (L - 1) / 2)});
        return s;
      },
      applies});
  cat.tables = [](const MechanismContext& c) {
    std::vector<ReportTable> out;
    if (!applies(c)) return out;
    std::string problem;
    ReportTable t{"dijksman1966_polygons", {}};
    const auto ps = dijksman_polygons(c.scene.linkage, problem);
    for (size_t q = 0; q < ps.size(); ++q) {
      std::string sides;
      for (int l : ps[q].side_link) sides += (sides.empty() ? "" : "-") + c.scene.linkage.link_name(l);
      t.rows.emplace_back(fmt::format("polygon {}", q + 1), "links " + sides + " (last side fixed)");
    }
    out.push_back(std::move(t));
    return out;
  };
  return cat;
}

std::vector<MechanismCatalogue> mechanism_catalogues(const MechanismScene& scene) {
  std::vector<MechanismCatalogue> out;
  for (const std::string& name : scene.catalogues) {
    if (name == "dijksman1966_compound") out.push_back(dijksman1966_compound());
    else if (name == "fourbar_polygon") out.push_back(fourbar_polygon());
    else if (name == "koshel_class3") out.push_back(koshel_class3());
    else if (name == "dijksman1984_eightbar") out.push_back(dijksman1984_eightbar());
    else
      throw InputError(scene.source, "mechanism.catalogue",
                       "unknown catalogue `" + name +
                           "`; known: dijksman1966_compound, fourbar_polygon, koshel_class3, dijksman1984_eightbar");
  }
  return out;
}

std::vector<MechanismCatalogue> second_order_catalogues(const MechanismScene& scene) {
  std::vector<MechanismCatalogue> out;
  for (MechanismCatalogue& c : mechanism_catalogues(scene))
    if (c.name == "dijksman1984_eightbar") out.push_back(std::move(c));
  return out;
}

}  // namespace linkproof::catalogues
