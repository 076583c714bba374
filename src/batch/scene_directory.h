// The scene directory of a sweep (`--scenes DIR`): scene files written into it, one file a
// scene. A polygon sweep writes its cases with an unexpected outcome (batch/batch_sweep.h), a
// sweep of a topology the shrunk counterexamples of its disproved claims
// (write_counterexample_scenes). Errors name the field "scene directory" (the command line
// names its option).
#pragma once

#include <string>

#include "linkproof/core/error.h"
#include "proof/topology_sweep.h"

namespace linkproof {

/// Creates `dir` (and its parents) if needed: InputError naming it when it cannot be created.
void create_scene_directory(const std::string& dir);

/// Writes `yaml` to `<dir>/<name>.yaml` (replacing it), creating `dir` if needed; InputError
/// naming the file when it cannot be written.
void write_scene_file(const std::string& dir, const std::string& name, const std::string& yaml);

/// Writes the counterexample of each disproved claim of `report` (expected to fail or not) to
/// `<dir>/counterexample-<claim id>.yaml` (the scene's name): the scene `check-claim CLAIMS
/// --scene FILE` re-fails the claim on. Returns the number of files written.
int write_counterexample_scenes(const std::string& dir, const TopologySweepReport& report);

}  // namespace linkproof
