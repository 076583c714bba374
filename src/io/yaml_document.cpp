#include "yaml_document.h"

#include <fmt/format.h>
#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/eventhandler.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "linkproof/core/error.h"
#include "io/input_limits.h"

namespace linkproof::yaml_io {

namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// YAML 1.1 booleans (what yaml-cpp's own conversion accepts), only for a clearer message:
// parse_rational would reject them anyway.
bool is_yaml_boolean(std::string_view s) {
  const std::string l = lower(s);
  return l == "true" || l == "false" || l == "yes" || l == "no" || l == "on" || l == "off";
}

bool is_nan_or_infinity(std::string_view s) {
  std::string l = lower(s);
  if (!l.empty() && (l.front() == '+' || l.front() == '-')) l.erase(0, 1);
  return l == ".nan" || l == "nan" || l == ".inf" || l == "inf" || l == "infinity";
}

// Records where each document starts (the mark of its first token); ignores the content.
class DocumentStarts final : public YAML::EventHandler {
 public:
  std::vector<YAML::Mark> marks;
  void OnDocumentStart(const YAML::Mark& mark) override { marks.push_back(mark); }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
  void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t, const std::string&) override {}
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
  void OnMapEnd() override {}
};

// A NUL byte is not text: yaml-cpp would call it an "unknown escape character" or worse.
void refuse_nul_bytes(const std::string& text, const std::string& source) {
  const auto nul = text.find('\0');
  if (nul == std::string::npos) return;
  int line = 1, column = 1;
  for (std::size_t i = 0; i < nul; ++i) {
    if (text[i] == '\n') { ++line; column = 1; } else { ++column; }
  }
  throw InputError(source, fmt::format("(yaml line {}, column {})", line, column),
                   "a NUL byte (\\0) in the file: a scene or claim file is UTF-8 text");
}

// yaml-cpp reports a tab where YAML allows only spaces as "illegal map value" or "end of map
// not found": name the tab when the failing line or the one before holds one.
std::string tab_hint(const std::string& text, const YAML::Mark& mark) {
  if (mark.is_null()) return "";
  std::size_t start = 0;
  for (int line = 0; line < mark.line - 1 && start != std::string::npos; ++line) {
    start = text.find('\n', start);
    if (start != std::string::npos) ++start;
  }
  for (int k = std::max(0, mark.line - 1); k <= mark.line && start != std::string::npos && start < text.size(); ++k) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    if (const auto tab = text.find('\t', start); tab != std::string::npos && tab < end)
      return fmt::format(" (line {}, column {} holds a tab character: YAML indents and separates with spaces only)",
                         k + 1, tab - start + 1);
    start = end + 1;
  }
  return "";
}

}  // namespace

std::string shorten(std::string_view s, std::size_t max) {
  std::string out;
  for (char c : s.substr(0, std::min(s.size(), max)))
    out += std::iscntrl(static_cast<unsigned char>(c)) ? '?' : c;
  if (s.size() > max) out += fmt::format("... ({} characters)", s.size());
  return out;
}

namespace {

// Length of the valid UTF-8 sequence starting at s[i] (1..4), or 0 if the bytes there are not one.
std::size_t utf8_length(std::string_view s, std::size_t i) {
  const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = b(i);
  std::size_t len = 0;
  unsigned lo = 0x80, hi = 0xbf;  // the allowed range of the second byte
  if (c < 0x80) return 1;
  if (c >= 0xc2 && c <= 0xdf) len = 2;
  else if (c >= 0xe0 && c <= 0xef) len = 3, lo = c == 0xe0 ? 0xa0 : 0x80, hi = c == 0xed ? 0x9f : 0xbf;
  else if (c >= 0xf0 && c <= 0xf4) len = 4, lo = c == 0xf0 ? 0x90 : 0x80, hi = c == 0xf4 ? 0x8f : 0xbf;
  else return 0;
  if (i + len > s.size() || b(i + 1) < lo || b(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < len; ++k)
    if (b(i + k) < 0x80 || b(i + k) > 0xbf) return 0;
  return len;
}

}  // namespace

std::string clean_text(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    const std::size_t len = utf8_length(s, i);
    if (len > 1) {
      out.append(s.substr(i, len));
      i += len;
      continue;
    }
    if (c == '\n') out += "\\n";
    else if (c == '\t') out += "\\t";
    else if (c == '\r') out += "\\r";
    else if (len == 0 || c < 0x20 || c == 0x7f) out += fmt::format("\\x{:02x}", c);
    else out += static_cast<char>(c);
    ++i;
  }
  return out;
}

std::string backticked(std::string_view s) { return "`" + shorten(s, kMaxQuoted) + "`"; }

std::string kind_of(const YAML::Node& node) {
  if (!node.IsDefined()) return "nothing (the field is missing)";
  switch (node.Type()) {
    case YAML::NodeType::Null: return "null (an empty value)";
    case YAML::NodeType::Sequence: return "a list";
    case YAML::NodeType::Map: return "a map";
    case YAML::NodeType::Scalar: return "the string " + backticked(node.Scalar());
    default: return "nothing";
  }
}

Rational read_exact_number(const YAML::Node& node, const std::string& source, const std::string& field,
                           const std::string& what) {
  const auto fail = [&](const std::string& problem) { throw InputError(source, field, shorten(problem, kMaxProblem)); };
  const std::string expected = "expected an exact number for " + what +
                               " (an integer, a fraction \"p/q\" or a decimal), got ";
  // A missing key of a const map is an invalid node, on which IsScalar() itself throws.
  if (!node.IsDefined()) fail("missing required field: an exact number for " + what);
  if (!node.IsScalar()) fail(expected + kind_of(node));
  const std::string& s = node.Scalar();  // the text as written: never read through a double
  const bool plain = node.Tag() == "?";
  if (plain && is_yaml_boolean(s)) fail(expected + "the boolean " + backticked(s));
  if (is_nan_or_infinity(s))
    fail(expected + backticked(s) + ", which is not finite (NaN and infinities are refused)");
  if (s.size() > kMaxNumberCharacters)
    fail(fmt::format("the number for {} has {} characters; the limit is {} (docs/limits.md)", what, s.size(),
                     kMaxNumberCharacters));
  try {
    return parse_rational(s);
  } catch (const std::invalid_argument& e) {
    fail("invalid number for " + what + ": " + e.what());
  }
  throw InternalError("unreachable");
}

YAML::Node parse_single_document(const std::string& yaml_text, const std::string& source,
                                 const std::string& empty_problem) {
  const auto at = [](const YAML::Mark& m) {
    return m.is_null() ? std::string("(yaml)") : fmt::format("(yaml line {}, column {})", m.line + 1, m.column + 1);
  };
  refuse_nul_bytes(yaml_text, source);
  YAML::Node doc;
  try {
    // A first pass finds the document boundaries. It must not be YAML::LoadAll: on a stray
    // top-level ',' yaml-cpp 0.7 starts an empty document at the same token forever (until
    // memory runs out). Stopping at the third document and comparing starts catches that.
    std::istringstream stream(yaml_text);
    YAML::Parser parser(stream);
    DocumentStarts starts;
    while (starts.marks.size() < 3 && parser.HandleNextDocument(starts)) {
    }
    const auto& m = starts.marks;
    for (std::size_t i = 1; i < m.size(); ++i) {
      if (m[i].pos == m[i - 1].pos) {
        const auto pos = static_cast<std::size_t>(m[i].pos);
        const std::string token = pos < yaml_text.size() ? backticked(yaml_text.substr(pos, 1)) : "end";
        throw InputError(source, at(m[i]), "malformed YAML: unexpected " + token);
      }
    }
    if (m.size() > 1)
      throw InputError(source, "",
                       fmt::format("expected one YAML document, found a second one at line {}",
                                   m[1].line + 1));
    if (!m.empty()) doc = YAML::Load(yaml_text);
  } catch (const YAML::DeepRecursion& e) {
    throw InputError(source, at(e.mark),
                     fmt::format("the YAML is nested too deeply (the parser stops at {} levels)", e.depth()));
  } catch (const YAML::ParserException& e) {
    throw InputError(source, at(e.mark), "malformed YAML: " + e.msg + tab_hint(yaml_text, e.mark));
  } catch (const YAML::Exception& e) {
    throw InputError(source, "(yaml)", std::string("malformed YAML: ") + e.what());
  }
  if (doc.IsNull()) throw InputError(source, "", empty_problem);
  return doc;
}

std::string read_scene_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path, "", "cannot read file: it is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", std::string("cannot read file: ") + std::strerror(errno));
  // Read with a cap, never to EOF: /dev/zero or a huge file is refused after kMaxInputBytes + 1.
  std::string text(kMaxInputBytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  if (in.bad()) throw InputError(path, "", "cannot read file: read error");
  text.resize(static_cast<std::size_t>(in.gcount()));
  if (text.size() > kMaxInputBytes)
    throw InputError(path, "", fmt::format("the file is larger than the limit of {} bytes (docs/limits.md)",
                                           kMaxInputBytes));
  return text;
}

void emit_number(YAML::Emitter& out, const Rational& q) {
  const std::string text = format_rational(q);
  if (text.find('/') == std::string::npos)
    out << text;
  else
    out << YAML::DoubleQuoted << text;
}

}  // namespace linkproof::yaml_io
