// Reports of how a mechanism scene's positions, axes and rates were given (mechanism_scene.h,
// ScenePlacement): which were placed from dimensions, which are exact, and which the check runs on
// as rationals within a stated bound ("Mechanisms from dimensions", docs/mechanisms.md).
//
// JSON (added to `linkproof check --json` on a mechanism scene, beside the check's own keys):
//   "positions": {"A": {"given_by": "polar", "exact": false, "bound": "1e-60"},
//                 "O2": {"given_by": "at", "exact": true, "bound": "0"},
//                 "D": {..., "axis": {"given_by": "axis angle 30deg", "exact": false, "bound": "1e-62"}}},
//   "input_rates": {"inputs[0].omega": {"given": "1500rpm", "exact": false, "bound": "1e-58"}},
//   "rationalised": "runs on rationalised positions: joints A, B within 1e-60; ..." or null
// A bound is the smallest power of ten at or above the certified bound on |used - given| (each
// coordinate of a position or direction; the value of a rate).
#pragma once

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>

#include "linkproof/mechanism/mechanism_check.h"
#include "linkproof/mechanism/mechanism_scene.h"

namespace linkproof {

/// The keys "positions", "input_rates" and "rationalised" above.
nlohmann::json scene_placement_json(const MechanismScene& scene);

/// One line, "runs on rationalised positions: joints A, B within 1e-60; input rates
/// inputs[0].omega within 1e-58", or "" when every value is exact.
std::string rationalised_statement(const MechanismScene& scene);

/// For a scene given by dimensions (ScenePlacement::is_dimensioned): the statement above, what
/// the results are exact for, and a table of every joint and rate given by dimensions. Nothing
/// otherwise.
/// `bound`: the check's bound on the distance to the results at the dimensioned values
/// (MechanismCheck::dimensioned), one line after the statement; without it (nullptr) the
/// results are said to be exact for the rationals only.
void write_scene_placement_text(std::ostream& out, const MechanismScene& scene, const DimensionedBound* bound = nullptr);

/// The smallest power of ten at or above b, "1e-60"; "0" for b = 0.
std::string format_bound(const Rational& b);

}  // namespace linkproof
