// Errors as data: how a failed run (exit 2 bad input, exit 3 internal error) is reported.
//
// Text (stderr): "linkproof: bad input: FILE: FIELD: PROBLEM", control characters escaped.
// JSON (stdout, with --json), one object:
//   {"error": {"kind": "input" | "internal", "file": ..., "line": L | null, "column": C | null,
//              "field": ..., "message": ...}, "exit_status": 2 | 3}
// `line`/`column` come from a "FILE:LINE:COLUMN" source (claim expressions) or a
// "(yaml line L, column C)" field (YAML syntax); strings are valid UTF-8 (invalid bytes escaped).
#pragma once

#include <optional>
#include <ostream>
#include <string>

#include "linkproof/core/error.h"

namespace linkproof::cli {

struct ErrorReport {
  std::string kind;  ///< "input" or "internal"
  std::string file;
  std::optional<int> line, column;
  std::string field;
  std::string message;
  int exit_status = 2;
  std::string text;  ///< the one-line message of the text report (the exception's what())
};

/// An InputError split into file, line, column, field and message.
ErrorReport input_error_report(const InputError& e);
/// A bad-input problem of the command line (file "<command line>").
ErrorReport command_line_error_report(const std::string& field, const std::string& message);
/// An internal error (exit 3).
ErrorReport internal_error_report(const std::string& message);

/// Prints the error on `err` as text, and as one JSON object on `out` when `json`; returns
/// report.exit_status.
int print_error(std::ostream& out, std::ostream& err, const ErrorReport& report, bool json);

/// `s` with control characters escaped (\n, \t, \xHH) and invalid UTF-8 bytes as \xHH.
std::string printable(const std::string& s);

}  // namespace linkproof::cli
