#include "linkproof/io/scene.h"

#include <fmt/format.h>
#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <utility>
#include <vector>

#include "linkproof/core/error.h"
#include "scene_ask.h"
#include "yaml_document.h"

namespace linkproof {

namespace {

using namespace yaml_io;


std::string plural(std::size_t k, const char* one, const char* many) {
  return fmt::format("{} {}", k, k == 1 ? one : many);
}

// Reads one document; every check throws InputError naming source_, a field and the problem.
class SceneReader {
 public:
  explicit SceneReader(std::string source) : source_(std::move(source)) {}

  PolygonScene read(const YAML::Node& doc) {
    if (!doc.IsMap())
      fail("", "expected a map with the fields `name` and `polygon` at the top level, got " +
                   kind_of(doc));
    const auto top = fields(doc, "", {"name", "description", "polygon", "ask"},
                            {"mechanism", "this is a mechanism scene (top-level `mechanism`), and a polygon scene (`name`, `polygon`) is "
                                          "expected here; `linkproof check SCENE` reads both kinds"});

    PolygonScene scene;
    scene.source = source_;
    scene.name = read_name(top);
    if (auto d = find(top, "description"); d && !d->IsScalar())
      fail("description", "expected a string (free text), got " + kind_of(*d));

    const auto poly = find(top, "polygon");
    if (!poly)
      fail("polygon", "missing required field `polygon`: a map with joints, omega and omega_dot");
    if (!poly->IsMap())
      fail("polygon", "expected a map with the fields joints, omega and omega_dot, got " + kind_of(*poly));
    const auto pf = fields(*poly, "polygon.", {"joints", "omega", "omega_dot"}, {});

    scene.polygon = Polygon<Rational>(read_joints(pf));
    const int n = scene.polygon.n();
    scene.rates.omega = read_rates(pf, "omega", "omega", n);
    scene.rates.omega_dot = read_rates(pf, "omega_dot", "omega-dot", n);

    if (std::string problem = polygon_input_problem(scene.polygon); !problem.empty())
      fail("polygon.joints", problem);
    if (auto a = find(top, "ask")) scene.ask = read_ask(*a, n);
    return scene;
  }

 private:
  using Fields = std::vector<std::pair<std::string, YAML::Node>>;
  struct Refused {
    std::string_view key, message;
  };

  [[noreturn]] void fail(const std::string& field, const std::string& problem) const {
    throw InputError(source_, field, shorten(problem, kMaxProblem));
  }

  // The entries of a map, checked: plain keys, no repeats, none outside `allowed`. A `refused`
  // key gets its own message (checked first: it explains more than "unknown field").
  Fields fields(const YAML::Node& map, const std::string& prefix,
                std::initializer_list<std::string_view> allowed, Refused refused) const {
    const std::string where = prefix.empty() ? "" : prefix.substr(0, prefix.size() - 1);
    Fields out;
    for (const auto& kv : map) {
      if (!kv.first.IsScalar())
        fail(where, "a field name must be a plain string, got " + kind_of(kv.first));
      out.emplace_back(kv.first.Scalar(), kv.second);
    }
    for (const auto& [key, value] : out)
      if (!refused.key.empty() && key == refused.key) fail(prefix + key, std::string(refused.message));
    std::string expected;
    for (auto a : allowed) expected += (expected.empty() ? "" : ", ") + std::string(a);
    for (std::size_t i = 0; i < out.size(); ++i) {
      const std::string& key = out[i].first;
      if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())
        fail(prefix + shorten(key, kMaxQuoted),
             "unknown field " + backticked(key) + "; expected only: " + expected);
      for (std::size_t k = 0; k < i; ++k)
        if (out[k].first == key) fail(prefix + key, "field " + backticked(key) + " is given twice");
    }
    return out;
  }

  static std::optional<YAML::Node> find(const Fields& f, std::string_view key) {
    for (const auto& [k, v] : f)
      if (k == key) return v;
    return std::nullopt;
  }

  std::string read_name(const Fields& top) const {
    const auto node = find(top, "name");
    if (!node) fail("name", "missing required field `name`: the scene's name, a non-empty string");
    if (!node->IsScalar()) fail("name", "expected a non-empty string, got " + kind_of(*node));
    const std::string& s = node->Scalar();
    if (std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isspace(c); }))
      fail("name", "expected a non-empty string, got an empty one");
    return clean_text(s);
  }

  Rational read_number(const YAML::Node& node, const std::string& field, const std::string& what) const {
    return read_exact_number(node, source_, field, what);
  }

  std::vector<Vec2<Rational>> read_joints(const Fields& pf) const {
    const std::string field = "polygon.joints";
    const auto node = find(pf, "joints");
    if (!node)
      fail(field, "missing required field `joints`: the list [[x, y], ...] of K_1..K_n, n >= 4");
    if (!node->IsSequence())
      fail(field, "expected a list of joints [[x, y], ...] (K_1..K_n), got " + kind_of(*node));
    const std::size_t n = node->size();
    if (n < 4) fail(field, fmt::format("expected at least 4 joints K_1..K_n (n >= 4), got {}", n));
    if (n > static_cast<std::size_t>(kMaxSceneJoints))
      fail(field, fmt::format("expected at most {} joints, got {}", kMaxSceneJoints, n));

    std::vector<Vec2<Rational>> joints;
    joints.reserve(n);
    std::size_t i = 0;
    for (const auto& joint : *node) {
      const std::string jf = fmt::format("{}[{}]", field, i);
      const std::string name = fmt::format("K_{}", i + 1);
      if (!joint.IsSequence())
        fail(jf, "expected joint " + name + " as a list of 2 numbers [x, y], got " + kind_of(joint));
      if (joint.size() != 2)
        fail(jf, fmt::format("expected 2 coordinates [x, y] for joint {}, got {}", name, joint.size()));
      Vec2<Rational> k;
      k.x = read_number(joint[0], jf + "[0]", "the x coordinate of " + name);
      k.y = read_number(joint[1], jf + "[1]", "the y coordinate of " + name);
      joints.push_back(k);
      ++i;
    }
    return joints;
  }

  // omega or omega_dot: n-3 numbers, symbol_{j,n} for j = 1..n-3.
  std::vector<Rational> read_rates(const Fields& pf, const std::string& key, const std::string& symbol,
                                   int n) const {
    const std::string field = "polygon." + key;
    const std::size_t count = static_cast<std::size_t>(n - 3);
    const std::string meaning = fmt::format("{}_{{j,n}} for j = 1..n-3 with n = {}", symbol, n);
    const auto node = find(pf, key);
    if (!node)
      fail(field, fmt::format("missing required field `{}`: {} ({})", key,
                              plural(count, "value", "values"), meaning));
    if (!node->IsSequence())
      fail(field, fmt::format("expected a list of {} ({}), got {}", plural(count, "number", "numbers"),
                              meaning, kind_of(*node)));
    if (node->size() != count)
      fail(field, fmt::format("expected {} ({}), got {}", plural(count, "value", "values"), meaning,
                              node->size()));
    std::vector<Rational> out;
    out.reserve(count);
    std::size_t j = 0;
    for (const auto& value : *node) {
      out.push_back(read_number(value, fmt::format("{}[{}]", field, j),
                                fmt::format("{}_{{{},{}}}", symbol, j + 1, n)));
      ++j;
    }
    return out;
  }

  // The polygon's ask: rates of sides 1..n; links and points belong to mechanism scenes.
  SceneAsk read_ask(const YAML::Node& node, int n) const {
    SceneAsk ask = read_scene_ask(node, source_);
    for (const AskedRate& r : ask.rates) {
      const std::string& s = r.subject.name;
      const bool digits = !s.empty() && s.size() <= 6 && std::all_of(s.begin(), s.end(), [](unsigned char c) {
        return std::isdigit(c);
      });
      const int side = digits ? std::stoi(s) : 0;
      if (side < 1 || side > n)
        fail(r.subject.field, fmt::format("{}: expected a side 1..{} of this polygon (relative to side {}), got {}",
                                          r.text(), n, n, backticked(shorten(s, kMaxQuoted))));
    }
    // A side is a number: `omega_dot(04)` is `omega_dot(4)`, written as such, and asked once.
    for (std::size_t i = 0; i < ask.rates.size(); ++i) {
      AskedRate& r = ask.rates[i];
      r.subject.name = std::to_string(std::stoi(r.subject.name));
      for (std::size_t k = 0; k < i; ++k)
        if (ask.rates[k].dot == r.dot && ask.rates[k].subject.name == r.subject.name)
          fail(r.subject.field, backticked(r.text()) + " is asked twice");
    }
    const auto refuse = [&](const std::vector<AskedName>& names, const char* key) {
      if (!names.empty())
        fail(names.front().field, fmt::format("`{}` belongs to mechanism scenes; a polygon scene asks for omega(j), "
                                              "omega_dot(j), claims and arithmetic",
                                              key));
    };
    refuse(ask.links, "links");
    refuse(ask.points, "points");
    return ask;
  }

  std::string source_;
};

// Integers plain; fractions double-quoted so that no YAML reader takes "3/2" for anything else.
void emit_list(YAML::Emitter& out, const std::vector<Rational>& values) {
  out << YAML::Flow << YAML::BeginSeq;
  for (const auto& v : values) emit_number(out, v);
  out << YAML::EndSeq;
}

}  // namespace

PolygonScene parse_polygon_scene(const std::string& yaml_text, const std::string& source) {
  const YAML::Node doc = parse_single_document(
      yaml_text, source, "empty document: expected a map with the fields `name` and `polygon`");
  try {
    return SceneReader(source).read(doc);
  } catch (const YAML::Exception& e) {  // a safety net: the reader only uses non-throwing calls
    throw InputError(source, "", std::string("cannot read the YAML: ") + e.what());
  }
}

PolygonScene load_polygon_scene(const std::string& path) {
  return parse_polygon_scene(read_scene_file(path), path);
}

std::string polygon_scene_to_yaml(const PolygonScene& scene) {
  YAML::Emitter out;
  out << YAML::BeginMap;
  out << YAML::Key << "name" << YAML::Value << YAML::DoubleQuoted << scene.name;
  out << YAML::Key << "polygon" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "joints" << YAML::Value << YAML::Flow << YAML::BeginSeq;
  for (const auto& k : scene.polygon.joints()) {
    out << YAML::Flow << YAML::BeginSeq;
    emit_number(out, k.x);
    emit_number(out, k.y);
    out << YAML::EndSeq;
  }
  out << YAML::EndSeq;
  out << YAML::Key << "omega" << YAML::Value;
  emit_list(out, scene.rates.omega);
  out << YAML::Key << "omega_dot" << YAML::Value;
  emit_list(out, scene.rates.omega_dot);
  out << YAML::EndMap;
  if (scene.ask) emit_ask(out, *scene.ask);
  out << YAML::EndMap;
  LINKPROOF_ASSERT(out.good(), "YAML emitter failed: " + out.GetLastError());
  return std::string(out.c_str()) + "\n";
}

}  // namespace linkproof
