#include "error_report.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <regex>

#include "report/json_report.h"

namespace linkproof::cli {

std::string printable(const std::string& s) {
  std::string out;
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '\n') out += "\\n";
    else if (c == '\t') out += "\\t";
    else if (c < 0x20 || c == 0x7f) out += fmt::format("\\x{:02x}", c);
    else out += ch;
  }
  // Invalid UTF-8 is escaped by JSON's error handler below; text keeps the bytes it was given,
  // minus the control characters that could forge lines or move the cursor.
  return out;
}

ErrorReport input_error_report(const InputError& e) {
  ErrorReport r;
  r.kind = "input";
  r.file = e.source();
  r.field = e.field();
  r.message = e.problem();
  r.text = e.what();
  std::smatch m;
  static const std::regex file_line_column(R"(^(.*):([0-9]{1,9}):([0-9]{1,9})$)");
  static const std::regex yaml_position(R"(^\(yaml line ([0-9]{1,9}), column ([0-9]{1,9})\)$)");
  if (std::regex_match(r.file, m, file_line_column)) {
    r.line = std::stoi(m[2].str());
    r.column = std::stoi(m[3].str());
    r.file = m[1].str();
  }
  if (std::regex_match(r.field, m, yaml_position)) {
    r.line = std::stoi(m[1].str());
    r.column = std::stoi(m[2].str());
    r.field.clear();
  }
  r.exit_status = 2;
  return r;
}

ErrorReport command_line_error_report(const std::string& field, const std::string& message) {
  return ErrorReport{"input", "<command line>", std::nullopt, std::nullopt, field, message, 2,
                     field.empty() ? message : "<command line>: " + field + ": " + message};
}

ErrorReport internal_error_report(const std::string& message) {
  return ErrorReport{"internal", "", std::nullopt, std::nullopt, "", message, 3, message};
}

int print_error(std::ostream& out, std::ostream& err, const ErrorReport& r, bool json) {
  fmt::print(err, "linkproof: {}: {}\n", r.kind == "input" ? "bad input" : "internal error", printable(r.text));
  if (json) {
    nlohmann::json j;
    j["error"] = {{"kind", r.kind},
                  {"file", r.file},
                  {"line", r.line ? nlohmann::json(*r.line) : nlohmann::json(nullptr)},
                  {"column", r.column ? nlohmann::json(*r.column) : nlohmann::json(nullptr)},
                  {"field", r.field},
                  {"message", r.message}};
    j["exit_status"] = r.exit_status;
    out << json_text(j) << "\n";
  }
  return r.exit_status;
}

}  // namespace linkproof::cli
