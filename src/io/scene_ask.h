// Reading a scene's `ask` field (check/ask.h), shared by the polygon and mechanism scene
// readers. Private to src/io.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

#include "linkproof/check/ask.h"

namespace linkproof::yaml_io {

/// The `ask` list: its form is checked here (items, keys, spellings, repeats); what the names
/// refer to (a side 1..n, a link, a claim) is checked by the caller, which knows the scene.
SceneAsk read_scene_ask(const YAML::Node& node, const std::string& source);

/// Writes `ask: [...]` (a key and its value, inside an open map) so that read_scene_ask reads
/// the same ask back.
void emit_ask(YAML::Emitter& out, const SceneAsk& ask);

}  // namespace linkproof::yaml_io
