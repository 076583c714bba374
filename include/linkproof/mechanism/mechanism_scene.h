// What a mechanism scene states about a mechanism: the linkage, its inputs, tracer points, declared
// dimensions (with the allowed tolerance) and the paper catalogues to run. Read from YAML by
// io/mechanism_scene.h; checked by mechanism/mechanism_check.h.
#pragma once

#include <optional>
#include <string>
#include <vector>

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

struct MechanismScene {
  std::string name;
  std::string source;
  Linkage linkage;
  std::vector<MechanismInput> inputs;
  std::vector<MechanismPoint> points;
  std::vector<LinkDimension> dimensions;
  std::optional<Rational> tolerance;
  std::vector<std::string> catalogues;
  /// max over dimensions of | |AB| - length | (an approximation in double; 0 if none).
  double dimension_residual = 0;
};

}  // namespace linkproof
