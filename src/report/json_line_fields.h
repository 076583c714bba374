// Reading back the lines of a result file (report/sweep_lines.h, report/topology_sweep_lines.h):
// typed fields, verdict words and the line's digest, each failure an InputError naming the file,
// the line and the field.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "linkproof/core/verdict.h"

namespace linkproof {

/// Line `where` of `file` parsed as JSON, which must be an object.
nlohmann::json parse_line_object(const std::string& line, const std::string& file, const std::string& where);

/// `j[key]`, which must be present and of `type` (number_integer: any integer).
const nlohmann::json& line_member(const nlohmann::json& j, const char* key, nlohmann::json::value_t type,
                                  const std::string& file, const std::string& where);

/// A verdict word (holds, fails, undefined, inconclusive, error).
Verdict line_verdict(const nlohmann::json& j, const std::string& file, const std::string& field);

/// Checks the digest of case line `line` (parsed as `j`): present, equal to sweep_line_digest of
/// the line without it, and the line in the form linkproof writes (keys sorted, no spaces).
void check_line_digest(const nlohmann::json& j, const std::string& line, const std::string& file,
                       const std::string& where);

}  // namespace linkproof
