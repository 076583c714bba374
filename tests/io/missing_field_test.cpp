// Every field left out of a bundled scene is either optional or bad input that names the field:
// never yaml-cpp's own "invalid node" (which names no field), never another exception. The
// scenes are walked as YAML trees and each map key, at any depth, is removed in turn (an input
// without `omega_dot` once gave "invalid node; ..." and no field path).
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "linkproof/core/error.h"
#include "linkproof/io/mechanism_scene.h"
#include "linkproof/io/scene.h"

namespace linkproof {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& p) {
  std::ifstream f(p);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

// Calls `visit` with the text of the document with one map key removed, once per key of every
// map in the tree, and a description of which key it was.
void for_each_key_removed(const std::string& text,
                          const std::function<void(const std::string& yaml, const std::string& removed)>& visit) {
  // Count the map keys in document order; then, for each k, remove the k-th.
  const std::function<int(YAML::Node, int&, int, std::string&, std::string)> walk =
      [&](YAML::Node n, int& counter, int target, std::string& removed, std::string path) -> int {
    if (n.IsMap()) {
      std::vector<std::string> keys;
      for (const auto& kv : n) keys.push_back(kv.first.Scalar());
      for (const std::string& key : keys) {
        if (counter++ == target) {
          n.remove(key);
          removed = path + (path.empty() ? "" : ".") + key;
          return 1;
        }
        if (walk(n[key], counter, target, removed, path + (path.empty() ? "" : ".") + key)) return 1;
      }
    } else if (n.IsSequence()) {
      for (std::size_t i = 0; i < n.size(); ++i)
        if (walk(n[i], counter, target, removed, path + "[" + std::to_string(i) + "]")) return 1;
    }
    return 0;
  };
  for (int target = 0;; ++target) {
    YAML::Node doc = YAML::Load(text);
    int counter = 0;
    std::string removed;
    if (!walk(doc, counter, target, removed, "")) break;
    YAML::Emitter out;
    out << doc;
    visit(out.c_str(), removed);
  }
}

template <class Parse>
void expect_named_or_accepted(const fs::path& dir, Parse parse, int min_variants) {
  int variants = 0, refused = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() != ".yaml") continue;
    for_each_key_removed(read_text(e.path()), [&](const std::string& yaml, const std::string& removed) {
      SCOPED_TRACE(e.path().filename().string() + " without " + removed);
      ++variants;
      try {
        parse(yaml);
      } catch (const InputError& err) {
        ++refused;
        EXPECT_FALSE(err.field().empty()) << err.what();
        EXPECT_EQ(std::string(err.what()).find("invalid node"), std::string::npos) << err.what();
      } catch (const std::exception& other) {
        ADD_FAILURE() << "not an InputError: " << other.what();
      }
    });
  }
  EXPECT_GE(variants, min_variants);
  EXPECT_GT(refused, min_variants / 4);
}

TEST(MissingField, EveryKeyLeftOutOfABundledMechanismSceneIsOptionalOrNamed) {
  expect_named_or_accepted(fs::path(LINKPROOF_SOURCE_DIR) / "verify/scenes/mechanisms",
                           [](const std::string& yaml) { parse_mechanism_scene(yaml, "m.yaml"); }, 100);
}

TEST(MissingField, EveryKeyLeftOutOfABundledPolygonSceneIsOptionalOrNamed) {
  expect_named_or_accepted(fs::path(LINKPROOF_SOURCE_DIR) / "verify/scenes",
                           [](const std::string& yaml) { parse_polygon_scene(yaml, "p.yaml"); }, 10);
}

TEST(MissingField, AnInputWithoutOmegaDotNamesTheField) {
  const std::string scene = "name: m\nmechanism:\n  ground: \"0\"\n  joints:\n"
                            "    - {name: A, type: revolute, links: [\"0\", \"1\"], at: [0, 0]}\n"
                            "    - {name: B, type: revolute, links: [\"1\", \"2\"], at: [1, 2]}\n"
                            "    - {name: C, type: revolute, links: [\"2\", \"3\"], at: [4, 3]}\n"
                            "    - {name: D, type: revolute, links: [\"3\", \"0\"], at: [5, 0]}\n"
                            "  inputs:\n    - {link: \"1\", omega: 1}\n";
  try {
    parse_mechanism_scene(scene, "m.yaml");
    FAIL() << "accepted an input without omega_dot";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "mechanism.inputs[0].omega_dot");
    EXPECT_NE(e.problem().find("missing"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace linkproof
