// A driven link of zero length: every joint on it revolute and at one point, so its rotation
// moves nothing and a check would run on an input that drives no motion. The scene reader
// refuses such a scene (io/mechanism_scene.cpp); random configurations of a topology that have
// one cannot be written as a scene that replays (proof/topology_configurations.h).
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "linkproof/mechanism/linkage.h"
#include "linkproof/mechanism/mechanism_scene.h"

namespace linkproof {

struct ZeroLengthDriver {
  std::size_t input = 0;        ///< index into the inputs
  int first = 0, second = 0;    ///< two joints of the driven link, both at `at`
  Vec2<Rational> at;
};

/// The first link input whose link has at least two joints, all revolute and all at one point,
/// with joint j at joint_at[j] (the topology's joints and types, another configuration's
/// positions); nullopt if there is none.
std::optional<ZeroLengthDriver> zero_length_driver(const Linkage& g, const std::vector<MechanismInput>& inputs,
                                                   const std::vector<Vec2<Rational>>& joint_at);

}  // namespace linkproof
