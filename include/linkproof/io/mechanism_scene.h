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
//       - {link: "1", omega: 1, omega_dot: 1/2}     # rates relative to the ground (or 1500rpm)
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
// - `type: slot`, links [slotted link, pin link]: a pin in a straight slot, read as a prismatic
//   pair P [slotted link, P.block] plus a revolute pair P.pin [P.block, pin link] at the same
//   point, with the block link P.block added (a link or joint already so named is an error).
//   An `axis` (prismatic or slot) may be `{from: J}`: the direction from joint J to this joint.
// - Mechanisms from dimensions: instead of `at: [x, y]` a joint may be placed from joints
//   placed before it (in any order of the list that allows it; a cycle or an unknown name is an
//   InputError naming the joint):
//     at: J                                          the position of joint J (a slider at a pin)
//     polar: {from: J, length: L, angle: A}          J + L (cos A, sin A), A from +x counter-clockwise
//     dyad: {from: [J1, L1], to: [J2, L2], side: left}   the circles about J1 and J2 meet on the
//                                                    left (or right) of the directed line J1 -> J2
//     slide: {line: [J, A], from: [J2, L], pick: ahead}   the line through J at angle A meets the
//                                                    circle about J2: farther along the line
//                                                    (ahead) or nearer (behind)
//   and an `axis` may be an angle. Angles: `30deg`, `1.2rad`, `pi/6` or plain radians (numbers,
//   `pi`, `*`, `/`, a leading minus, a unit); an input's omega takes `1500rpm` (signed), its
//   omega_dot `rpm/s`. Circles that do not meet, or a line that misses its circle, are refused
//   naming the joint and the distance by which they miss. Exact data stay exact (a rational
//   cos/sin, a rational intersection); a position, direction or rate that is not a rational is
//   computed as a certified enclosure (io/joint_placement.h) and replaced by a rational within
//   a stated bound, 60 digits below the scene's scale: `placement` in the scene records which
//   values are exact and which are rationalised, and within what. An axis given as an angle is
//   an exactly unit rational direction. Declared `dimensions` between rationalised joints hold
//   within the tolerance plus the bounds.
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
/// every number exact: integers plain, fractions "p/q"; every joint `at: [x, y]`, the rationals
/// used for a scene given by dimensions, so its `placement` is not written), so that
/// parse_mechanism_scene(mechanism_scene_to_yaml(s), s.source) describes the same mechanism:
/// the same links, joints, inputs, points, dimensions, tolerance and catalogues. Used to print a
/// generated or failing case as a file `linkproof check` reads (linkproof/testing.h).
std::string mechanism_scene_to_yaml(const MechanismScene& scene);

/// The scene read from `path` as text (InputError if unreadable); used to choose the reader.
std::string read_scene_text(const std::string& path);

}  // namespace linkproof
