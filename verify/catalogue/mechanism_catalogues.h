// Paper-specific claim sets for mechanism scenes, selected by a scene's `catalogue` field:
//   dijksman1966_compound  Dijksman (1966) section 3: all relative omega-dot from eq. (22) + companion
//                          per polygon, the triangle relations and the input (conventions §A7)
//   fourbar_polygon        the acceleration-polygon course notes: the four-bar acceleration
//                          polygon and its errata (conventions §B)
//   koshel_class3          Koshel et al.: the class-III mechanism with sliders (conventions §C)
//   dijksman1984_eightbar  Dijksman (1984): the eight-bar's section-3 poles, relocation formulas (1')-(7''),
//                          errata (conventions §D); run by `check` and by `curvature`
#pragma once

#include <string>
#include <vector>

#include "mechanism/mechanism_catalogue.h"

namespace linkproof::catalogues {

MechanismCatalogue dijksman1966_compound();
MechanismCatalogue fourbar_polygon();
MechanismCatalogue koshel_class3();
MechanismCatalogue dijksman1984_eightbar();
/// Koshel et al.'s printed arithmetic chain (2)-(17), one claim per step with the tolerance derived
/// from the printed digits (koshel_printed_chain.cpp); part of koshel_class3.
std::vector<MechanismClaim> koshel_printed_chain();

/// The catalogues named by scene.catalogues; an unknown name is InputError(scene.source,
/// "mechanism.catalogue", ...).
std::vector<MechanismCatalogue> mechanism_catalogues(const MechanismScene& scene);
/// The second-order catalogues among scene.catalogues (what `linkproof curvature` runs).
std::vector<MechanismCatalogue> second_order_catalogues(const MechanismScene& scene);

}  // namespace linkproof::catalogues
