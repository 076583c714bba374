// Names made from user strings (report/escape.h): anchors and file name stems.
#include <fmt/format.h>

#include <cctype>
#include <cstdint>

#include "report/escape.h"

namespace linkproof::report {

namespace {

bool is_ascii_alnum(char c) {
  const auto u = static_cast<unsigned char>(c);
  return u < 0x80 && std::isalnum(u);
}

// FNV-1a, 64 bits: a fixed, platform-independent hash (std::hash is neither).
std::uint64_t fnv1a(const std::string& s) {
  std::uint64_t h = 14695981039346656037ull;
  for (char c : s) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
  return h;
}

}  // namespace

std::string anchor_id(const std::string& id) {
  std::string out;
  out.reserve(id.size());
  for (char c : id) {
    if (is_ascii_alnum(c) || c == '.' || c == '_' || c == ':' || c == '-')
      out += c;
    else
      out += fmt::format("-{:02x}", static_cast<unsigned char>(c));
  }
  return out;
}

std::string file_stem(const std::string& name) {
  std::string out;
  out.reserve(name.size());
  for (std::size_t i = 0; i < name.size();) {
    const char c = name[i];
    if (is_ascii_alnum(c) || c == '.' || c == '_' || c == '+' || c == '-') {
      out += c;
      ++i;
      continue;
    }
    out += '_';  // one per character: a multi-byte UTF-8 character gives one '_'
    ++i;
    if (static_cast<unsigned char>(c) >= 0xC0)
      while (i < name.size() && (static_cast<unsigned char>(name[i]) & 0xC0) == 0x80) ++i;
  }
  // No hidden file, no "." or "..", no name read as an option.
  out.erase(0, out.find_first_not_of(".-"));
  if (out.size() > kMaxFileStemBytes)
    out = out.substr(0, kMaxFileStemBytes - 17) + fmt::format("-{:016x}", fnv1a(name));
  if (out.empty()) out = "unnamed";
  return out;
}

}  // namespace linkproof::report
