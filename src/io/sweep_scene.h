// A case of a sweep as a scene file that `linkproof check` reads (the exact polygon and rates
// generated from seed, n and index), so that any failure of a sweep replays on its own.
#pragma once

#include <string>

#include "check/random_polygon.h"

namespace linkproof {

/// "sweep-seed{seed}-n{n}-i{index}": the scene's name, and its file name without ".yaml".
std::string sweep_scene_name(const RandomPolygonCase& rc);
/// The scene in the schema of io/scene.h, numbers exact.
std::string sweep_scene_yaml(const RandomPolygonCase& rc);

}  // namespace linkproof
