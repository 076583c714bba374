// What a mechanism scene states about a mechanism: the linkage, its inputs, tracer points, declared
// dimensions (with the allowed tolerance) and the paper catalogues to run. Read from YAML by
// io/mechanism_scene.h; checked by mechanism/mechanism_check.h.
#pragma once

#include <optional>
#include <string>
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
};

}  // namespace linkproof
