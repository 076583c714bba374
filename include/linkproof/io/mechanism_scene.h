// Mechanism scene files: any planar linkage with revolute and prismatic pairs, its inputs, and
// optional tracer points and declared dimensions, read from YAML with every number exact.
//
// Schema (fields required unless marked optional):
//
//   name: eightbar-fig5
//   description: free text                          # optional
//   mechanism:
//     ground: "0"                                   # the frame's link name
//     links: ["0", "1", ...]                        # optional: when given, every link named
//                                                   # elsewhere must be in it (typos are errors)
//     joints:
//       - {name: "01", type: revolute,  links: ["0", "1"], at: [0, 0]}
//       - {name: "D",  type: prismatic, links: ["0", "4"], at: [117349/1000, -26785/1000], axis: [1, 0]}
//     inputs:                                       # as many as the mobility
//       - {link: "1", omega: 1, omega_dot: 1/2}     # rates relative to the ground
//       - {joint: "D", v: 2, a: 0}                  # a slider: sigma-dot, sigma-ddot along axis
//     points:                                       # optional tracer points (e.g. a coupler point)
//       - {name: P, link: "3", at: [9, 14]}
//     dimensions:                                   # optional declared lengths between two
//       - {joints: ["A", "B"], length: 60}          # joints of one link
//     tolerance: 1/10                               # optional: allowed | |AB| - length |
//     catalogue: [fourbar_polygon]                  # optional: paper-specific claim sets to run
//   curvature:                                      # optional (top level or in `mechanism`):
//     - {point: "23", moving: "2", fixed: "4"}      # path curvature centres (docs/curvature.md)
//   joint_joining:                                  # optional: reductions, in order
//     - {link: "2", bars: ["1", "3"], order: 2}
//   ask: [links: ["5"], claims: [routes_agree]]     # optional: compute only these (check/ask.h);
//                                                   # omega(L), omega_dot(L) of links, points: [joints or points]
//
// - A joint has a unique name, `type` revolute or prismatic, exactly two different links and a
//   point `at`; a prismatic joint also a non-zero `axis` (links[0] is the guide that carries the
//   axis, links[1] the slider: mechanism/linkage.h). Every link must be connected to the ground.
// - Closure: the links are the rigid bodies through their joints, so joint positions close every
//   loop by construction. Declared `dimensions` are what positions read from data can violate:
//   without `tolerance` each must hold exactly, with it within the tolerance; otherwise the
//   scene is refused ("does not close at the given positions") naming the dimension.
// - Mobility and the number of inputs are checked when solving (mechanism/mechanism_solve.h).
// Errors: InputError(source, field, problem), fields like "mechanism.joints[3].axis".
#pragma once

#include <string>

#include "linkproof/mechanism/mechanism_scene.h"

namespace linkproof {

/// True if the file is a YAML map with a top-level `mechanism` key (false for anything else,
/// including unreadable files: the polygon reader then reports the problem).
bool is_mechanism_scene_text(const std::string& yaml_text);

/// The scene at `path` (or in `yaml_text`); a polygon scene is refused naming the field
/// `mechanism`, so that a command that needs a mechanism says so.
MechanismScene load_mechanism_scene(const std::string& path);
MechanismScene parse_mechanism_scene(const std::string& yaml_text, const std::string& source);

/// Writes the scene in the schema above (without `description`; `links` listed in link order,
/// every number exact: integers plain, fractions "p/q"), so that
/// parse_mechanism_scene(mechanism_scene_to_yaml(s), s.source) describes the same mechanism:
/// the same links, joints, inputs, points, dimensions, tolerance and catalogues. Used to print a
/// generated or failing case as a file `linkproof check` reads (linkproof/testing.h).
std::string mechanism_scene_to_yaml(const MechanismScene& scene);

/// The scene read from `path` as text (InputError if unreadable); used to choose the reader.
std::string read_scene_text(const std::string& path);

}  // namespace linkproof
