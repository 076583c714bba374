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

}  // namespace

std::string shorten(std::string_view s, std::size_t max) {
  std::string out;
  for (char c : s.substr(0, std::min(s.size(), max)))
    out += std::iscntrl(static_cast<unsigned char>(c)) ? '?' : c;
  if (s.size() > max) out += fmt::format("... ({} characters)", s.size());
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
  if (!node.IsScalar()) fail(expected + kind_of(node));
  const std::string& s = node.Scalar();  // the text as written: never read through a double
  const bool plain = node.Tag() == "?";
  if (plain && is_yaml_boolean(s)) fail(expected + "the boolean " + backticked(s));
  if (is_nan_or_infinity(s))
    fail(expected + backticked(s) + ", which is not finite (NaN and infinities are refused)");
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
    throw InputError(source, at(e.mark), "malformed YAML: " + e.msg);
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
  std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) throw InputError(path, "", "cannot read file: read error");
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
