// Shared by the scene readers (scene.cpp: polygons, mechanism_scene.cpp: mechanisms): safe
// loading of one YAML document and exact numbers, every problem as InputError(source, field, ...).
// Private to src/io.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>
#include <string_view>

#include "linkproof/core/exact.h"

namespace linkproof::yaml_io {

/// Quoted values in messages are cut so that a megabyte-long scalar gives a readable message.
inline constexpr std::size_t kMaxQuoted = 60;
inline constexpr std::size_t kMaxProblem = 400;

std::string shorten(std::string_view s, std::size_t max);
std::string backticked(std::string_view s);
/// Free text from a file (names, statements, notes) as the program keeps it: control
/// characters escaped (\n, \t, \r, \xHH) so that a name cannot forge report lines, and bytes
/// that are not valid UTF-8 escaped as \xHH so that JSON output stays valid. Valid UTF-8
/// without control characters is returned unchanged.
std::string clean_text(std::string_view s);

/// "null (an empty value)", "a list", "a map", "the string `...`".
std::string kind_of(const YAML::Node& node);

/// One exact number read from the scalar's text (never through a double); `what` names the
/// quantity in messages. Refuses booleans, NaN/infinities, lists, maps, null, bad spellings.
Rational read_exact_number(const YAML::Node& node, const std::string& source, const std::string& field,
                           const std::string& what);

/// The one YAML document of `text`; `empty_problem` is the message for an empty document.
/// Malformed YAML, several documents and too deep nesting are InputError naming the position.
YAML::Node parse_single_document(const std::string& text, const std::string& source,
                                 const std::string& empty_problem);

/// Writes q exactly: integers plain, fractions as a double-quoted "p/q" (read back exactly).
void emit_number(YAML::Emitter& out, const Rational& q);

/// The contents of the file at `path`, or InputError(path, "", "cannot read file: ...").
std::string read_scene_file(const std::string& path);

}  // namespace linkproof::yaml_io
