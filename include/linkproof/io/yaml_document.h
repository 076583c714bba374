// Reading one YAML document safely: the shared front end of every linkproof input file
// (scenes, claim files). Malformed YAML, a second document, too deep nesting and an unreadable
// file become InputError(source, "(yaml line L, column C)", problem); yaml-cpp 0.7's endless
// loop on a stray top-level ',' is avoided (see the .cpp).
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

namespace linkproof {

/// The document in `yaml_text` (a Null node if the text holds none).
YAML::Node parse_yaml_document(const std::string& yaml_text, const std::string& source);

/// The whole file at `path` as text; InputError if it cannot be read (or is a directory).
std::string read_text_file(const std::string& path);

/// "(yaml line L, column C)", 1-based, for a node's or an error's mark.
std::string yaml_position(const YAML::Mark& m);

}  // namespace linkproof
