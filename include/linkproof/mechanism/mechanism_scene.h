// What a mechanism scene states about a mechanism: the linkage, its inputs, tracer points, declared
// dimensions (with the allowed tolerance) and the paper catalogues to run. Read from YAML by
// io/mechanism_scene.h; checked by mechanism/mechanism_check.h.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "linkproof/check/ask.h"
#include "linkproof/mechanism/linkage.h"

namespace linkproof {

struct MechanismPoint {
  std::string name;
  int link = 0;
  Vec2<Rational> at;
};

struct LinkDimension {
  int joint_a = 0, joint_b = 0;
  Rational length;
};

/// A request for the path curvature centre of a point fixed in link `moving`, seen from link
/// `fixed` (scene key `curvature`; mechanism/curvature_analysis.h).
struct CurvatureRequest {
  std::string point;  ///< a joint's or a tracer point's name
  Vec2<Rational> at;
  int moving = 0, fixed = 0;
};

/// A joint-joining request on ternary link `link` with bars `bars` (scene key `joint_joining`;
/// mechanism/joint_joining.h); order 1 or 2.
struct JointJoiningRequest {
  int link = 0;
  int bars[2] = {0, 0};
  int order = 2;
};

/// How one value of the scene was given (io/mechanism_scene.h, "Mechanisms from dimensions"):
/// a joint position `at: [x, y]` or placed by `polar`, `dyad`, `slide` or `at: J`; a prismatic
/// axis given as an angle; an input rate given with pi or rpm. The engine works on exact
/// rationals: a value that is not a rational (or not known to be one) is replaced by a rational
/// within `bound` of it, and everything computed from the scene is exact for that rational.
struct GivenValue {
  std::string subject;   ///< the joint's name, or the input's field ("inputs[0].omega")
  std::string given_by;  ///< "at", "at joint", "polar", "dyad", "slide", "axis angle", or the text ("1500rpm")
  bool exact = true;     ///< the rational used is the given value exactly
  Rational bound = 0;    ///< else |used - given| <= bound, for each coordinate
};

/// The provenance of the scene's positions, axes and rates (all exact for a scene that gives
/// every joint `at: [x, y]` and every rate as a number).
struct ScenePlacement {
  std::vector<GivenValue> joints;  ///< one per joint, in joint order
  std::vector<GivenValue> axes;    ///< prismatic axes given as an angle
  std::vector<GivenValue> rates;   ///< input rates given as an expression (pi, rpm)
  /// Prismatic axes given as `axis: {from: J}` (joint, J): u = P - J follows the two positions,
  /// so it moves with them when they are rationalised (mechanism/dimensioned_bound.h).
  std::vector<std::pair<std::string, std::string>> axes_from;
  /// True when some value is not exact: the check runs on rationalised values.
  bool is_rationalised() const;
  /// True when some joint is placed from dimensions or some value given as an expression.
  bool is_dimensioned() const;
};

struct MechanismScene {
  std::string name;
  std::string source;
  Linkage linkage;
  std::vector<MechanismInput> inputs;
  std::vector<MechanismPoint> points;
  std::vector<LinkDimension> dimensions;
  std::optional<Rational> tolerance;
  std::vector<std::string> catalogues;
  /// Second-order work the scene asks for (empty: none).
  std::vector<CurvatureRequest> curvature;
  std::vector<JointJoiningRequest> joint_joining;
  /// max over dimensions of | |AB| - length | (an approximation in double; 0 if none).
  double dimension_residual = 0;
  /// Top-level `ask` (check/ask.h): the links, points and claims to compute (nullopt: everything).
  std::optional<SceneAsk> ask;
  /// How positions, axes and rates were given, and which were rationalised (io/mechanism_scene.h).
  ScenePlacement placement;
};

inline bool ScenePlacement::is_rationalised() const {
  for (const auto* list : {&joints, &axes, &rates})
    for (const GivenValue& v : *list)
      if (!v.exact) return true;
  return false;
}

inline bool ScenePlacement::is_dimensioned() const {
  if (!axes.empty() || !rates.empty()) return true;
  for (const GivenValue& v : joints)
    if (v.given_by != "at") return true;
  return false;
}

}  // namespace linkproof
