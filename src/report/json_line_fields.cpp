#include "report/json_line_fields.h"

#include "linkproof/core/error.h"
#include "report/sweep_lines.h"

namespace linkproof {

using nlohmann::json;

namespace {

constexpr Verdict kVerdicts[] = {Verdict::Holds, Verdict::Fails, Verdict::Undefined, Verdict::Inconclusive,
                                 Verdict::Error};

}  // namespace

json parse_line_object(const std::string& line, const std::string& file, const std::string& where) {
  json j;
  try {
    j = json::parse(line);
  } catch (const json::parse_error& e) {
    throw InputError(file, where, std::string("not JSON: ") + e.what());
  } catch (const json::exception& e) {  // e.g. out_of_range: a number beyond double's range (1e400)
    throw InputError(file, where, std::string("not a result line: ") + e.what());
  }
  if (!j.is_object()) throw InputError(file, where, "must be a JSON object");
  return j;
}

Verdict line_verdict(const json& j, const std::string& file, const std::string& field) {
  if (j.is_string())
    for (Verdict v : kVerdicts)
      if (j.get<std::string>() == to_string(v)) return v;
  throw InputError(file, field, "not a verdict (holds, fails, undefined, inconclusive, error): " + j.dump());
}

const json& line_member(const json& j, const char* key, json::value_t type, const std::string& file,
                        const std::string& where) {
  const auto it = j.find(key);
  if (it == j.end()) throw InputError(file, where + "." + key, "missing");
  const bool ok = type == json::value_t::number_integer ? it->is_number_integer() : it->type() == type;
  if (!ok) throw InputError(file, where + "." + key, "has the wrong type: " + it->dump());
  return *it;
}

void check_line_digest(const json& j, const std::string& line, const std::string& file, const std::string& where) {
  const auto digest = j.find("digest");
  if (digest == j.end() || !digest->is_string())
    throw InputError(file, where + ".digest",
                     "missing: every case line carries the digest of its content (a line of an older linkproof, or "
                     "edited)");
  json content = j;
  content.erase("digest");
  std::string canonical, written;
  try {
    canonical = content.dump();
    written = j.dump();
  } catch (const json::type_error& e) {
    throw InputError(file, where, std::string("not valid UTF-8: ") + e.what());
  }
  if (sweep_line_digest(canonical) != digest->get<std::string>())
    throw InputError(file, where + ".digest",
                     "does not match the line's content: the line was edited or damaged after it was written");
  if (written != line)
    throw InputError(file, where, "is not in the form linkproof writes (keys sorted, no spaces): edited by hand");
}

}  // namespace linkproof
