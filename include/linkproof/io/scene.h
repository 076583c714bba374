// Polygon scene files: one closed n-side polygon of Dijksman (1966) and its input rates, read
// from YAML with every number kept exact (docs/conventions.md §A1 for the notation).
//
// Schema (all fields required unless marked optional):
//
//   name: pentagon                 # non-empty string: the scene's name in reports
//   description: docs/conventions.md §A8 ...    # optional string, free text
//   polygon:
//     joints: [[0, 0], [1, 4], [5, 5], [7, 1], [3, -2]]  # K_1..K_n; side n (K_n -> K_1) is fixed
//     omega: [2, -1]               # omega_{j,n},     j = 1..n-3 (rad per unit time, ccw > 0)
//     omega_dot: [1, 3]            # omega-dot_{j,n}, j = 1..n-3
//   ask: [omega_dot(4), claims: [eq22]]   # optional: compute only these (check/ask.h); rates
//                                         # omega(j), omega_dot(j) for sides j = 1..n
//
// - n >= 4 joints, each a list of exactly two numbers [x, y]; omega and omega_dot hold exactly
//   n - 3 numbers each. No two joints may coincide (a coincident adjacent pair is a zero-length
//   side). A dead centre (r_{n-2} parallel to r_{n-1}, D = 0) is valid input: the mechanism is
//   undefined there, and saying so is the checker's job, not the reader's.
// - Any other top-level key, or any key in `polygon` other than the three above, is an error
//   ("unknown field"); so is a repeated key. A top-level `mechanism:` key (a mechanism scene,
//   io/mechanism_scene.h) is refused here with its own message.
//
// Exactness: every number is read from the YAML scalar's text, never through a double, with
// linkproof::parse_rational (core/exact.h). Accepted spellings, quoted or not: integers ("-12"),
// fractions ("7/3", "-1/400"), decimals read as the exact decimal fraction ("0.1" is 1/10,
// "2.5e-3" is 1/400, |exponent| <= 4000). Refused where a number belongs: NaN and infinities
// (".nan", ".inf", "nan", ...), booleans, null or empty values, lists, maps, hexadecimal, a zero
// denominator, anything else that is not one of the spellings above.
//
// Errors: every problem with the input, including an unreadable file and malformed YAML, is
// thrown as linkproof::InputError(source, field, problem) (core/error.h), never as a crash:
//   source   the file path given to load_polygon_scene, or the label given to
//            parse_polygon_scene;
//   field    where: "name", "polygon.joints", "polygon.joints[2][0]" (YAML list indices are
//            0-based; the problem text names the paper's 1-based K_j / omega_{j,n}), "" for the
//            whole document, or "(yaml line L, column C)" (1-based) for a YAML syntax error;
//   problem  what is wrong and what was expected, e.g. "expected 2 values (omega_{j,n} for
//            j = 1..n-3 with n = 5), got 3".
// At most kMaxSceneJoints joints are accepted, so that validation stays fast on any file.
#pragma once

#include <string>

#include "linkproof/check/ask.h"
#include "linkproof/core/exact.h"
#include "linkproof/geometry/polygon.h"

namespace linkproof {

/// A polygon read from a scene file: the geometry, the inputs, and where it came from.
struct PolygonScene {
  std::string name;              ///< field `name`: non-empty
  std::string source;            ///< the file path, or the label given to parse_polygon_scene
  Polygon<Rational> polygon;     ///< K_1..K_n, exact; n >= 4, no coincident joints
  InputRates<Rational> rates;    ///< omega / omega_dot, 0-based (omega[0] = omega_{1,n}), n-3 each
  std::optional<SceneAsk> ask{}; ///< field `ask`: what to compute (nullopt: everything; {}: aggregates may leave it out)
};

/// Upper bound on n: far beyond any linkage, low enough that checking all pairs of joints for
/// coincidence (quadratic) stays well under a second.
inline constexpr int kMaxSceneJoints = 10000;

/// Reads and validates the scene file at `path` (source = path).
/// Throws InputError(path, "", "cannot read file: ...") if the file is missing or unreadable,
/// and InputError for every problem listed above.
PolygonScene load_polygon_scene(const std::string& path);

/// Parses and validates scene text; `source` labels the errors and becomes scene.source.
PolygonScene parse_polygon_scene(const std::string& yaml_text, const std::string& source);

/// Writes the scene in the schema above (without `description`), numbers as exact reduced
/// "p/q" strings (integers plain), the name double-quoted. For every valid scene s,
/// parse_polygon_scene(polygon_scene_to_yaml(s), s.source) equals s exactly.
std::string polygon_scene_to_yaml(const PolygonScene& scene);

}  // namespace linkproof
