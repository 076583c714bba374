#include "linkproof/io/yaml_document.h"

#include <fmt/format.h>
#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/eventhandler.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

#include "linkproof/core/error.h"

namespace linkproof {

namespace {

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

std::string yaml_position(const YAML::Mark& m) {
  return m.is_null() ? std::string("(yaml)") : fmt::format("(yaml line {}, column {})", m.line + 1, m.column + 1);
}

YAML::Node parse_yaml_document(const std::string& yaml_text, const std::string& source) {
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
        const std::string token = pos < yaml_text.size() ? "`" + yaml_text.substr(pos, 1) + "`" : "end";
        throw InputError(source, yaml_position(m[i]), "malformed YAML: unexpected " + token);
      }
    }
    if (m.size() > 1)
      throw InputError(source, "", fmt::format("expected one YAML document, found a second one at line {}", m[1].line + 1));
    if (m.empty()) return YAML::Node();
    return YAML::Load(yaml_text);
  } catch (const YAML::DeepRecursion& e) {
    throw InputError(source, yaml_position(e.mark),
                     fmt::format("the YAML is nested too deeply (the parser stops at {} levels)", e.depth()));
  } catch (const YAML::ParserException& e) {
    throw InputError(source, yaml_position(e.mark), "malformed YAML: " + e.msg);
  } catch (const YAML::Exception& e) {
    throw InputError(source, "(yaml)", std::string("malformed YAML: ") + e.what());
  }
}

std::string read_text_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(path, "", "cannot read file: it is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", std::string("cannot read file: ") + std::strerror(errno));
  std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) throw InputError(path, "", "cannot read file: read error");
  return text;
}

}  // namespace linkproof
